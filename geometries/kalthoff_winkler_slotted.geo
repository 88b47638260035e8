// Kalthoff–Winkler edge-cracked plate impact with the notches cut as slots (structured hex
// blocks in four generalized spaces, overset). Superseded for the case by kalthoff_winkler.geo
// (one space, sharp notches as [[precrack]]s: docs/theory.md "Initial cracks"); kept as the
// overset conversion test of a plate with fine cells far from the origin
// (Geometries.KalthoffWinklerConvertsWithFineCellsFarFromTheOrigin).
//
//   gmsh -3 kalthoff_winkler_slotted.geo                   -> kalthoff_winkler_slotted.msh
//   gsph-preproc kalthoff_winkler.geo -o kw.h5             (GSPH: graded, one particle per hex)
//   gsph-preproc kalthoff_winkler.geo -o kw_u.h5 --lattice 0.002   (uniform layout, same geometry)
//
// A plate W x H x T (x: the impact direction, y: along the impacted edge, z: thickness), the
// impacted edge at x = 0, y in [-H/2, H/2]. Two notches (slots of width s) run from x = 0 to
// the notch tips at x = c, centred on y = -d/2 and y = +d/2; the edge between them (the
// "impact" set) is struck. The cracks start at the notch tips and run at about 70° to the
// notch direction (+x), away from the struck middle: the upper one towards +y and the far
// corner (W, H/2), the lower one its mirror image. Four blocks, each its own generalized space:
//   * "ligament" [c, W] x [-H/2, H/2]: both crack paths, one Cartesian block whose left side is
//     made of six faces (lower arm, lower notch tip, the middle arm's two halves, upper notch
//     tip, upper arm);
//   * the lower arm [0, c] x [-H/2, -d/2 - s/2], the middle arm [0, c] x [-d/2 + s/2, d/2 - s/2]
//     (struck on its x = 0 face), the upper arm [0, c] x [d/2 + s/2, H/2].
// Grading: cells are h (divided by refine) where the cracks run, i.e. over the whole ligament
// in x and over the outer bands |y| > d/2 - s/2 in y (the cracks reach the edges y = ±H/2);
// they grow towards the struck edge x = 0 (in x, up to `coarsen` h at x = 0) and towards the
// plate's middle line y = 0 (in y, up to `coarsen` h at y = 0), where no crack runs. The
// plate is not cut at y = 0 for symmetry: both cracks are computed.
// The notch width s must keep the slot open for the SPH pairs (support 2κ spacings, κ = 1.2):
// the uniform layout (`--lattice H`) needs at least two lattice rows inside the slot, s ≳ 2.25 H;
// the GSPH layout needs s + h > 2κ h (the rows either side are paired through the overset
// coupling of the blocks otherwise), s > 1.4 h. The default 4.5 mm serves h, H ≤ 2 mm;
// scripts/validate_kalthoff sets s = 2.25 Δx.
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "plate". Sets: "impact" (x = 0 between the notches), "notch_tips"
// (the faces x = c inside both slots).

DefineConstant[
  W = {0.1, Name "Parameters/W"},           // length along the impact direction x [m]
  H = {0.2, Name "Parameters/H"},           // width of the impacted edge, along y [m]
  T = {0.009, Name "Parameters/T"},         // thickness along z [m]
  c = {0.05, Name "Parameters/c"},          // notch length from x = 0 [m]
  d = {0.05, Name "Parameters/d"},          // distance between the notches' centre lines [m]
  s = {0.0045, Name "Parameters/s"},        // notch (slot) width [m]
  h = {0.002, Name "Parameters/h"},         // cell size where the cracks run [m]
  coarsen = {2.5, Name "Parameters/coarsen"},  // cell size at x = 0 and at y = 0, in h
  nz = {3, Name "Parameters/nz"},           // cells through the thickness (not refined)
  refine = {1, Name "Parameters/refine"}    // divides h (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (W <= 0 || H <= 0 || T <= 0 || c <= 0 || d <= 0 || s <= 0 || h <= 0 || coarsen <= 0 || nz < 1 || refine < 1)
  Error("kalthoff_winkler_slotted.geo: needs W, H, T, c, d, s, h, coarsen > 0; nz, refine ≥ 1 (got W = %g, H = %g, T = %g, c = %g, d = %g, s = %g, h = %g, coarsen = %g, nz = %g, refine = %g)", W, H, T, c, d, s, h, coarsen, nz, refine);
EndIf
y1 = d / 2 - s / 2;  // the middle arm's half height (a slot's inner face)
y2 = d / 2 + s / 2;  // a slot's outer face
Y = H / 2;

// x = 0 (the struck edge; the slots open there)
Point(1) = {0, -Y, 0};  Point(2) = {0, -y2, 0};  Point(3) = {0, -y1, 0};  Point(4) = {0, 0, 0};
Point(5) = {0, y1, 0};  Point(6) = {0, y2, 0};   Point(7) = {0, Y, 0};
// x = c (the notch tips)
Point(11) = {c, -Y, 0};  Point(12) = {c, -y2, 0};  Point(13) = {c, -y1, 0};  Point(14) = {c, 0, 0};
Point(15) = {c, y1, 0};  Point(16) = {c, y2, 0};   Point(17) = {c, Y, 0};
// x = W (the far edge)
Point(21) = {W, -Y, 0};  Point(22) = {W, -y2, 0};  Point(23) = {W, -y1, 0};  Point(24) = {W, 0, 0};
Point(25) = {W, y1, 0};  Point(26) = {W, y2, 0};   Point(27) = {W, Y, 0};

// Along x over the arms, from x = 0 to x = c (slot faces at ±y1, ±y2)
Line(1) = {1, 11};  Line(2) = {2, 12};  Line(3) = {3, 13};
Line(4) = {5, 15};  Line(5) = {6, 16};  Line(6) = {7, 17};
// Along x over the ligament, from x = c to x = W
Line(7) = {11, 21};  Line(8) = {17, 27};
// Along y, upwards, at x = 0 (no line across the slots' mouths), x = c and x = W
Line(31) = {1, 2};  Line(32) = {3, 4};  Line(33) = {4, 5};  Line(34) = {6, 7};
Line(41) = {11, 12};  Line(42) = {12, 13};  Line(43) = {13, 14};
Line(44) = {14, 15};  Line(45) = {15, 16};  Line(46) = {16, 17};
Line(51) = {21, 22};  Line(52) = {22, 23};  Line(53) = {23, 24};
Line(54) = {24, 25};  Line(55) = {25, 26};  Line(56) = {26, 27};

Curve Loop(1) = {1, 41, -2, -31};         Plane Surface(1) = {1};  // lower arm
Curve Loop(2) = {3, 43, 44, -4, -33, -32};  Plane Surface(2) = {2};  // middle arm (struck)
Curve Loop(3) = {5, 46, -6, -34};         Plane Surface(3) = {3};  // upper arm
Curve Loop(4) = {7, 51, 52, 53, 54, 55, 56, -8, -46, -45, -44, -43, -42, -41};
Plane Surface(4) = {4};                                              // ligament

hr = h / refine;
// A graded run of n cells from hr to coarsen hr: n from the mean cell, ratio per cell.
nxArm = Max(2, Round(2 * c / (hr * (1 + coarsen))));
rxArm = coarsen^(1 / (nxArm - 1));
nyMid = Max(2, Round(2 * y1 / (hr * (1 + coarsen))));
ryMid = coarsen^(1 / (nyMid - 1));
nxLig = Round((W - c) / hr);
nyOut = Round((Y - y2) / hr);
ns = Max(1, Round(s / hr));

// Lines from x = 0 towards the tips: cells shrink towards the tips (ratio < 1).
Transfinite Curve{1, 2, 3, 4, 5, 6} = nxArm + 1 Using Progression 1 / rxArm;
Transfinite Curve{7, 8} = nxLig + 1;
Transfinite Curve{31, 34, 41, 46, 51, 56} = nyOut + 1;
Transfinite Curve{42, 45, 52, 55} = ns + 1;
// The middle band's halves: fine at the slots, coarse at y = 0 (y runs upwards: the lower
// half's cells grow along it, the upper half's shrink).
Transfinite Curve{32, 43, 53} = nyMid + 1 Using Progression ryMid;
Transfinite Curve{33, 44, 54} = nyMid + 1 Using Progression 1 / ryMid;
Transfinite Surface{1, 3};
Transfinite Surface{2} = {3, 13, 15, 5};
Transfinite Surface{4} = {11, 21, 27, 17};  // the left side runs 11 -> 12 -> ... -> 17
Recombine Surface{1, 2, 3, 4};

Extrude {0, 0, T} { Surface{1, 2, 3, 4}; Layers{nz}; Recombine; }

e = 1e-6 * W;  // tolerance of the bounding boxes below
Physical Volume("plate") = Volume{:};
Physical Surface("impact") = Surface In BoundingBox{-e, -y1 - e, -e, e, y1 + e, T + e};
tipLower() = Surface In BoundingBox{c - e, -y2 - e, -e, c + e, -y1 + e, T + e};
tipUpper() = Surface In BoundingBox{c - e, y1 - e, -e, c + e, y2 + e, T + e};
Physical Surface("notch_tips") = {tipLower(), tipUpper()};
