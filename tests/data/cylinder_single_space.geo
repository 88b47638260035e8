// A full cylinder meshed as ONE cylindrical block: a rectangle in the (r, z) plane revolved about
// the z axis in four quarter turns. Its inner side lies on the axis, so the structured grid
// collapses there (gmsh makes prisms of the hexahedra on the axis): a single cylindrical index
// space is singular on its axis. gsph-preproc must refuse it and name the axis.
R = 1e-3;  L = 2e-3;
Point(1) = {0, 0, 0};  Point(2) = {R, 0, 0};  Point(3) = {R, 0, L};  Point(4) = {0, 0, L};
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};  Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 4;  Transfinite Curve{2, 4} = 3;
Transfinite Surface{1};  Recombine Surface{1};
section = 1;
For q In {0:3}
  out[] = Extrude {{0, 0, 1}, {0, 0, 0}, Pi / 2} { Surface{section}; Layers{4}; Recombine; };
  section = out[0];
EndFor
Physical Volume("rod") = Volume{:};
