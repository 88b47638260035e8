// A 2-D mesh of quadrangles that is not transfinite (an L-shaped surface recombined by the
// quad mesher): no structured grid, refused.
Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 1, 0};
Point(4) = {1, 1, 0}; Point(5) = {1, 2, 0}; Point(6) = {0, 2, 0};
For k In {1:6}
  Line(k) = {k, k % 6 + 1};
EndFor
Curve Loop(1) = {1:6}; Plane Surface(1) = {1};
Mesh.MeshSizeMax = 0.3;
Mesh.SubdivisionAlgorithm = 1;  // every triangle split into quads: an all-quad, unstructured mesh
Recombine Surface{1};
