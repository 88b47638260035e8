// A sphere striking a plate: the cubed sphere of sphere.geo above a square plate, two bodies.
//
//   gsph-preproc sphere_impact.geo -o particles.h5
//   gsph-preproc sphere_impact.geo -o uniform.h5 --lattice 2.9e-4   # standard SPH, same spacing
//
// The sphere (radius R, centre at the origin; sphere.geo's parameters) falls along −z onto a
// plate P × P × T whose impact face lies at z = −R − gap. The plate is one block, its cells
// along x and y graded (Bump) finest under the sphere, its layers finest at the impact face
// (each `ratio` times the one above): under the sphere the cells match the sphere's smallest
// (0.39 mm), and they coarsen where the plate barely deforms. Every
// parameter can be overridden with `gmsh -setnumber NAME VALUE` or `gsph-preproc --set
// NAME=VALUE`. Units: SI (m).
// Bodies: Physical Volumes "ball" and "plate". Sets: "surface" (the sphere's), "plate_rim" (the
// plate's four side faces, to clamp), "impact_face" (the plate's face towards the sphere).

Include "sphere.geo";

DefineConstant[
  P = {20e-3, Name "Parameters/P"},        // plate side [m]
  T = {12e-3, Name "Parameters/T"},        // plate thickness [m]
  np = {31, Name "Parameters/np"},         // plate cells along x and along y
  bump = {4, Name "Parameters/bump"},      // > 1: plate cells finer at its centre
  nt = {18, Name "Parameters/nt"},         // plate cells through the thickness
  ratio = {1.058, Name "Parameters/ratio"}, // layer thickness ratio, from the impact face down
  gap = {0.2e-3, Name "Parameters/gap"}    // distance from the sphere to the plate [m]
];
If (P <= 2 * R || T <= 0 || bump <= 0 || ratio <= 0 || np < 1 || nt < 1 || gap < 0)
  Error("sphere_impact.geo: needs P > 2 R, T, bump, ratio > 0, np, nt >= 1, gap >= 0 (got P = %g, R = %g, T = %g, bump = %g, ratio = %g, np = %g, nt = %g, gap = %g)", P, R, T, bump, ratio, np, nt, gap);
EndIf
top = -R - gap;
corner[] = {newp, newp + 1, newp + 2, newp + 3};
Point(corner[0]) = {-P / 2, -P / 2, top - T};  Point(corner[1]) = {P / 2, -P / 2, top - T};
Point(corner[2]) = {P / 2, P / 2, top - T};    Point(corner[3]) = {-P / 2, P / 2, top - T};
For k In {0:3}
  edge[k] = newl;  Line(edge[k]) = {corner[k], corner[(k + 1) % 4]};
EndFor
Transfinite Curve{edge[]} = np * refine + 1 Using Bump bump;
loop = newll;  Curve Loop(loop) = {edge[]};
bottom = news;  Plane Surface(bottom) = {loop};
Transfinite Surface{bottom};  Recombine Surface{bottom};
// Layers from the bottom up, the thickest first: cumulative heights of a geometric progression.
layers = nt * refine;
q = ratio^(1 / refine);
count[] = {};  height[] = {};
total = 0;
For k In {0:layers - 1}
  total += q^(layers - 1 - k);
EndFor
sum = 0;
For k In {0:layers - 1}
  sum += q^(layers - 1 - k);
  count[] += 1;
  height[] += sum / total;
EndFor
plate[] = Extrude {0, 0, T} { Surface{bottom}; Layers{count[], height[]}; Recombine; };

e = 1e-6 * P;  // tolerance of the bounding boxes below
Physical Volume("plate") = {plate[1]};
Physical Surface("impact_face") = {plate[0]};
Physical Surface("plate_rim") = {plate[{2:5}]};
