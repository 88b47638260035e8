// Pipe elbow: a thick-walled tube with a straight leg, a 90° bend and a second straight leg.
// The wall's section is an annulus of four blocks (quarters between the inner and the outer
// circle, no core), swept along the pipe's axis: extruded along the first leg, rotated about the
// bend's axis, extruded along the second leg.
//
//   gsph-preproc pipe_elbow.geo -o elbow.h5
//   gsph-preproc pipe_elbow.geo -o elbow.h5 --set refine=2
//
// Inlet at z = 0, the first leg along +z up to z = L1, the bend about the axis through
// (Rb, 0, L1) along y, the second leg along +x from x = Rb to x = Rb + L2 (at z = L1 + Rb).
// All twelve blocks glue into one generalized space, periodic in its angular index: no
// overset. Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "pipe". Sets: "inlet" (z = 0), "outlet" (x = Rb + L2),
// "inner" (the bore), "outer" (the outside).

DefineConstant[
  Ri = {3.5e-3, Name "Parameters/Ri"},    // inner radius [m]
  Ro = {5e-3, Name "Parameters/Ro"},      // outer radius [m]
  Rb = {15e-3, Name "Parameters/Rb"},     // bend radius, of the pipe's axis [m]
  L1 = {20e-3, Name "Parameters/L1"},     // length of the first leg [m]
  L2 = {20e-3, Name "Parameters/L2"},     // length of the second leg [m]
  n = {8, Name "Parameters/n"},           // cells per quarter of the circumference
  nr = {3, Name "Parameters/nr"},         // cells through the wall
  n1 = {24, Name "Parameters/n1"},        // cells along the first leg
  nb = {28, Name "Parameters/nb"},        // cells along the bend
  n2 = {24, Name "Parameters/n2"},        // cells along the second leg
  refine = {1, Name "Parameters/refine"}  // multiplies every cell count (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh. The bend folds onto itself unless Rb > Ro.
If (Ri <= 0 || Ro <= Ri || Rb <= Ro || L1 <= 0 || L2 <= 0 || n < 1 || nr < 1 || n1 < 1 || nb < 1 || n2 < 1 || refine < 1)
  Error("pipe_elbow.geo: needs 0 < Ri < Ro < Rb, L1, L2 > 0, n, nr, n1, nb, n2, refine >= 1 (got Ri = %g, Ro = %g, Rb = %g, L1 = %g, L2 = %g, n = %g, nr = %g, n1 = %g, nb = %g, n2 = %g, refine = %g)", Ri, Ro, Rb, L1, L2, n, nr, n1, nb, n2, refine);
EndIf

Point(1) = {0, 0, 0};  // centre of the arcs
For k In {0:3}  // the quarters' corners at 45°, 135°, 225°, 315°
  a = Pi / 4 + k * Pi / 2;
  inner[k] = newp;  Point(inner[k]) = {Ri * Cos(a), Ri * Sin(a), 0};
  outer[k] = newp;  Point(outer[k]) = {Ro * Cos(a), Ro * Sin(a), 0};
EndFor
For k In {0:3}
  spoke[k] = newl;     Line(spoke[k]) = {inner[k], outer[k]};
  innerArc[k] = newl;  Circle(innerArc[k]) = {inner[k], 1, inner[(k + 1) % 4]};
  outerArc[k] = newl;  Circle(outerArc[k]) = {outer[k], 1, outer[(k + 1) % 4]};
EndFor
Transfinite Curve{innerArc[], outerArc[]} = n * refine + 1;
Transfinite Curve{spoke[]} = nr * refine + 1;
For k In {0:3}  // quarter k: between spokes k and k + 1
  loop = newll;  Curve Loop(loop) = {spoke[k], outerArc[k], -spoke[(k + 1) % 4], -innerArc[k]};
  section[k] = news;  Plane Surface(section[k]) = {loop};
EndFor
Transfinite Surface{section[]};
Recombine Surface{section[]};

// Each Extrude gives, per quarter, its far section, its volume and its four lateral surfaces
// in the order of the quarter's curve loop: the outer arc's second, the inner arc's fourth.
leg1[] = Extrude {0, 0, L1} { Surface{section[]}; Layers{n1 * refine}; Recombine; };
For k In {0:3}
  bent[k] = leg1[6 * k];
EndFor
bend[] = Extrude { {0, 1, 0}, {Rb, 0, L1}, Pi / 2 } { Surface{bent[]}; Layers{nb * refine}; Recombine; };
For k In {0:3}
  bent[k] = bend[6 * k];
EndFor
leg2[] = Extrude {L2, 0, 0} { Surface{bent[]}; Layers{n2 * refine}; Recombine; };

Physical Volume("pipe") = Volume{:};
Physical Surface("inlet") = {section[]};
Physical Surface("outlet") = {};
Physical Surface("inner") = {};
Physical Surface("outer") = {};
For k In {0:3}
  Physical Surface("outlet") += {leg2[6 * k]};
  Physical Surface("outer") += {leg1[6 * k + 3], bend[6 * k + 3], leg2[6 * k + 3]};
  Physical Surface("inner") += {leg1[6 * k + 5], bend[6 * k + 5], leg2[6 * k + 5]};
EndFor
