// A box meshed with hexahedra that form no structured grid (tetrahedra split into 4 hexahedra
// each): gsph-preproc must refuse it.
Mesh.MeshSizeMax = 0.6;
Mesh.SubdivisionAlgorithm = 2;
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Extrude {0, 0, 1} { Surface{1}; }
