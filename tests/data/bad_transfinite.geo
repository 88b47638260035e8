// A box whose opposite edges get different node counts: gmsh cannot mesh the transfinite
// surfaces (it reports the error from inside a parallel loop, which must not abort the tool).
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 4} = 3; Transfinite Curve{3} = 5;
Transfinite Surface{1}; Recombine Surface{1};
Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; }
