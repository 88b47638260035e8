// A plate and a blunt cylindrical projectile: two bodies (two physical volumes).
//
//   gmsh -3 plate_projectile.geo                       -> plate_projectile.msh
//   gsph-preproc plate_projectile.geo -o impact.h5     (meshes in-process)
//
// Ballistic perforation set-up: a square plate P x P x Tp in z in [-Tp, 0], struck at its
// centre by a blunt (flat-nosed) cylinder of radius Rp and length Lp, axis along z, nose at
// z = gap above the plate. The plate is one block graded in x and y, finest under the
// projectile. The projectile is an O-grid like taylor_bar.geo: a square core block and four
// annulus blocks that glue into one space periodic around the axis. Body 0 is the plate, body 1
// the projectile (bodies follow the physical volumes' tags); particles come body by body.
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Bodies: Physical Volumes "plate" and "projectile". Sets: "plate_rim" (the plate's four side
// faces, to clamp), "nose" (the projectile's flat face).

DefineConstant[
  P = {0.1, Name "Parameters/P"},             // plate side [m]
  Tp = {0.012, Name "Parameters/Tp"},         // plate thickness [m]
  np = {40, Name "Parameters/np"},            // plate cells along x and along y
  bump = {3, Name "Parameters/bump"},         // > 1: plate cells finer at its centre
  ntp = {6, Name "Parameters/ntp"},           // plate cells through the thickness
  Rp = {0.01, Name "Parameters/Rp"},          // projectile radius [m]
  Lp = {0.08, Name "Parameters/Lp"},          // projectile length [m]
  gap = {0.001, Name "Parameters/gap"},       // distance from the plate to the nose [m]
  core = {0.4, Name "Parameters/core"},       // projectile core half-side / Rp
  n = {6, Name "Parameters/n"},               // projectile cells per core side (per quarter)
  nr = {3, Name "Parameters/nr"},             // projectile cells from core to surface
  nz = {24, Name "Parameters/nz"},            // projectile cells along its axis
  refine = {1, Name "Parameters/refine"}      // multiplies every cell count
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (P <= 0 || Tp <= 0 || bump <= 0 || Rp <= 0 || Lp <= 0 || core <= 0 || np < 1 || ntp < 1 || n < 1 || nr < 1 || nz < 1 || refine < 1 || gap < 0)
  Error("plate_projectile.geo: needs P, Tp, bump, Rp, Lp, core > 0; np, ntp, n, nr, nz, refine ≥ 1; gap ≥ 0 (got P = %g, Tp = %g, bump = %g, Rp = %g, Lp = %g, core = %g, np = %g, ntp = %g, n = %g, nr = %g, nz = %g, refine = %g, gap = %g)", P, Tp, bump, Rp, Lp, core, np, ntp, n, nr, nz, refine, gap);
EndIf

// --- Plate: one block, a structured square extruded through the thickness. ---------------------
Point(1) = {-P/2, -P/2, -Tp};  Point(2) = {P/2, -P/2, -Tp};
Point(3) = {P/2, P/2, -Tp};    Point(4) = {-P/2, P/2, -Tp};
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};
Transfinite Curve{1:4} = np * refine + 1 Using Bump bump;
Curve Loop(1) = {1:4};  Plane Surface(1) = {1};
Transfinite Surface{1};  Recombine Surface{1};
plate[] = Extrude {0, 0, Tp} { Surface{1}; Layers{ntp * refine}; Recombine; };

// --- Projectile: O-grid section at z = gap, extruded along the axis. ---------------------------
c = core * Rp;
s = Rp / Sqrt(2);
centre = newp;  Point(centre) = {0, 0, gap};
corner[] = {newp, newp + 1, newp + 2, newp + 3};
Point(corner[0]) = {c, -c, gap};  Point(corner[1]) = {c, c, gap};
Point(corner[2]) = {-c, c, gap};  Point(corner[3]) = {-c, -c, gap};
rim[] = {newp, newp + 1, newp + 2, newp + 3};
Point(rim[0]) = {s, -s, gap};  Point(rim[1]) = {s, s, gap};
Point(rim[2]) = {-s, s, gap};  Point(rim[3]) = {-s, -s, gap};
For k In {0:3}
  side[k] = newl;   Line(side[k]) = {corner[k], corner[(k + 1) % 4]};
  spoke[k] = newl;  Line(spoke[k]) = {corner[k], rim[k]};
  arc[k] = newl;    Circle(arc[k]) = {rim[k], centre, rim[(k + 1) % 4]};
EndFor
Transfinite Curve{side[], arc[]} = n * refine + 1;
Transfinite Curve{spoke[]} = nr * refine + 1;
loop = newll;  Curve Loop(loop) = {side[]};
section[0] = news;  Plane Surface(section[0]) = {loop};
For k In {0:3}
  loop = newll;  Curve Loop(loop) = {spoke[k], arc[k], -spoke[(k + 1) % 4], -side[k]};
  section[k + 1] = news;  Plane Surface(section[k + 1]) = {loop};
EndFor
Transfinite Surface{section[]};
Recombine Surface{section[]};
Extrude {0, 0, Lp} { Surface{section[]}; Layers{nz * refine}; Recombine; }

e = 1e-6 * P;  // tolerance of the bounding boxes below
Physical Volume("plate") = {plate[1]};
Physical Volume("projectile") = Volume In BoundingBox{-Rp - e, -Rp - e, gap - e, Rp + e, Rp + e, gap + Lp + e};
Physical Surface("nose") = Surface In BoundingBox{-Rp - e, -Rp - e, gap - e, Rp + e, Rp + e, gap + e};
rimFaces[] = Surface In BoundingBox{-P/2 - e, -P/2 - e, -Tp - e, -P/2 + e, P/2 + e, e};
rimFaces[] += Surface In BoundingBox{P/2 - e, -P/2 - e, -Tp - e, P/2 + e, P/2 + e, e};
rimFaces[] += Surface In BoundingBox{-P/2 - e, -P/2 - e, -Tp - e, P/2 + e, -P/2 + e, e};
rimFaces[] += Surface In BoundingBox{-P/2 - e, P/2 - e, -Tp - e, P/2 + e, P/2 + e, e};
Physical Surface("plate_rim") = {rimFaces[]};
