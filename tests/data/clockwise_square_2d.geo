// A unit square whose curve loop runs clockwise, so gmsh's quadrangles do too (normal -z): they
// convert as the counter-clockwise ones do. Body "square"; set "bottom" (y = 0).
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 4}; Line(2) = {4, 3}; Line(3) = {3, 2}; Line(4) = {2, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1:4} = 4;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("square") = {1};
Physical Curve("bottom") = {4};
