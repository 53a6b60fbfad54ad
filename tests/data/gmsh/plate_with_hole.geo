// A quarter of a square plate [0, L]^2 with a circular hole of radius r at the origin, meshed
// into quadrilaterals of about h (frontal-Delaunay triangles recombined, full-quad Blossom).
// The curve loop runs clockwise, so Gmsh's quadrilaterals come out clockwise too: the reader
// must turn them. Area: L^2 - pi r^2 / 4 (less the circular segments cut by the mesh).
DefineConstant[ L = 1, r = 0.4, h = 0.05 ];
Point(1) = {0, 0, 0, h};  // centre of the hole, not in the body
Point(2) = {r, 0, 0, h};
Point(3) = {L, 0, 0, h};
Point(4) = {L, L, 0, h};
Point(5) = {0, L, 0, h};
Point(6) = {0, r, 0, h};
Line(1) = {2, 3};
Line(2) = {3, 4};
Line(3) = {4, 5};
Line(4) = {5, 6};
Circle(5) = {6, 1, 2};
Curve Loop(1) = {-5, -4, -3, -2, -1};
Plane Surface(1) = {1};
Recombine Surface{1};
Mesh.RecombinationAlgorithm = 3;
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Curve("hole") = {5};
Physical Surface("body") = {1};
