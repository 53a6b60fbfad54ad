// A plane-strain projectile with a rounded nose (SI units: metres), for
// cases/projectile/projectile.json and tutorials/09_your_own_problem. Half of the section is
// modelled: x >= 0, with the symmetry line x = 0. Width 2 R, straight part L above the nose of
// radius R; the nose tip is at the origin.
R = 5e-3;
L = 20e-3;
h = 1e-3;  // target cell size before the all-quad subdivision halves it (0.5 mm cells)

Point(1) = {0, 0, 0, h};      // nose tip
Point(2) = {0, R, 0, h};      // centre of the nose arc
Point(3) = {R, R, 0, h};
Point(4) = {R, R + L, 0, h};
Point(5) = {0, R + L, 0, h};
Circle(1) = {1, 2, 3};
Line(2) = {3, 4};
Line(3) = {4, 5};
Line(4) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// The names a case file uses for constraints and contact surfaces.
Physical Curve("nose") = {1};
Physical Curve("side") = {2};
Physical Curve("back") = {3};
Physical Curve("symmetry") = {4};
Physical Surface("projectile") = {1};

// Quadrilaterals only: frontal-Delaunay triangles recombined, then every cell split into four
// quadrilaterals (no triangle is left). Gmsh 4.8's quad algorithm (8) crashes; 6 does not.
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.SubdivisionAlgorithm = 1;
