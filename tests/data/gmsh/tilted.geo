// A square of quadrilaterals in the plane z = x (not z = 0): read_gmsh_body must refuse it.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 1};
Point(3) = {1, 1, 1};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
