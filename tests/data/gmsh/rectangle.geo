// The box [x0, x1] x [y0, y1] as a structured grid of nx x ny nodes (transfinite, recombined into
// quadrilaterals): the body make_grid_particles and make_grid_mesh build. The OpenCASCADE kernel
// places the nodes of straight transfinite curves to the last bit (the built-in kernel's are
// off by about 1e-12). Parameters: gmsh -setnumber nx 10 ...
SetFactory("OpenCASCADE");
DefineConstant[ x0 = 0, y0 = 0, x1 = 1, y1 = 1, nx = 3, ny = 3 ];
Rectangle(1) = {x0, y0, 0, x1 - x0, y1 - y0};  // curves 1 bottom, 2 right, 3 top, 4 left
Transfinite Curve{1, 3} = nx;
Transfinite Curve{2, 4} = ny;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("body") = {1};
