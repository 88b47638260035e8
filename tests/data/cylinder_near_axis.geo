// A cylinder meshed as one cylindrical space (four quarter-annulus blocks that glue into one
// space, periodic in the angle) whose inner radius is 1e-4 of the outer: it avoids the axis
// itself, but near it the cells are 6000 times longer radially than around, so dX/dtheta is
// ill-conditioned there. gsph-preproc converts it and warns, naming the space.
R = 1e-3;  r0 = 1e-4 * R;  L = 2.5e-4;  n = 4;  nr = 4;
Point(1) = {0, 0, 0};
For q In {0:3}
  inner[q] = newp;  Point(inner[q]) = {r0 * Cos(q * Pi / 2), r0 * Sin(q * Pi / 2), 0};
  outer[q] = newp;  Point(outer[q]) = {R * Cos(q * Pi / 2), R * Sin(q * Pi / 2), 0};
EndFor
For q In {0:3}
  spoke[q] = newl;  Line(spoke[q]) = {inner[q], outer[q]};
  arcIn[q] = newl;  Circle(arcIn[q]) = {inner[q], 1, inner[(q + 1) % 4]};
  arcOut[q] = newl;  Circle(arcOut[q]) = {outer[q], 1, outer[(q + 1) % 4]};
EndFor
For q In {0:3}
  loop = newll;
  Curve Loop(loop) = {spoke[q], arcOut[q], -spoke[(q + 1) % 4], -arcIn[q]};
  section[q] = news;  Plane Surface(section[q]) = {loop};
EndFor
Transfinite Curve{spoke[]} = nr + 1;
Transfinite Curve{arcIn[], arcOut[]} = n + 1;
Transfinite Surface{section[]};
Recombine Surface{section[]};
Extrude {0, 0, L} { Surface{section[]}; Layers{1}; Recombine; }
Physical Volume("rod") = Volume{:};
