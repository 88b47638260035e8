// Single-edge notched plate for brittle cracking (structured hex blocks around the notch).
//
//   gmsh -3 notched_plate.geo                        -> notched_plate.msh
//   gsph-preproc notched_plate.geo -o notched.h5     (meshes in-process)
//
// A plate W x H x T (x, y, z) with a slot of width s cut from its left edge (x = 0) to the
// notch tip at x = c, centred on y = H/2. Pulled apart at its bottom and top edges, it cracks
// from the notch tip along y = H/2. Three blocks:
//   * "ligament" [c, W] x [0, H]: the whole crack path, one Cartesian block whose left side is
//     made of three faces (the lower arm's side, the notch tip, the upper arm's side);
//   * the lower arm [0, c] x [0, H/2 - s/2] and the upper arm [0, c] x [H/2 + s/2, H].
// The arms share only part of the ligament's side, so each block is its own generalized space,
// and the crack path lies inside one of them. Cells are graded in y, finest along the notch.
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "plate". Sets: "grip_bottom" (y = 0), "grip_top" (y = H),
// "notch_tip" (the face at x = c inside the slot).

DefineConstant[
  W = {0.1, Name "Parameters/W"},           // width along x [m]
  H = {0.1, Name "Parameters/H"},           // height along y [m]
  T = {0.004, Name "Parameters/T"},         // thickness along z [m]
  c = {0.05, Name "Parameters/c"},          // notch length from x = 0 [m]
  s = {0.002, Name "Parameters/s"},         // notch (slot) width [m]
  h = {0.002, Name "Parameters/h"},         // cell size away from the notch [m]
  nz = {2, Name "Parameters/nz"},           // cells through the thickness
  grading = {1.05, Name "Parameters/grading"},  // growth of cell height away from the notch
  refine = {1, Name "Parameters/refine"}    // multiplies every cell count (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (W <= 0 || H <= 0 || T <= 0 || c <= 0 || s <= 0 || h <= 0 || grading <= 0 || nz < 1 || refine < 1)
  Error("notched_plate.geo: needs W, H, T, c, s, h, grading > 0; nz, refine ≥ 1 (got W = %g, H = %g, T = %g, c = %g, s = %g, h = %g, grading = %g, nz = %g, refine = %g)", W, H, T, c, s, h, grading, nz, refine);
EndIf
y1 = H / 2 - s / 2;  // slot bottom
y2 = H / 2 + s / 2;  // slot top

Point(1) = {0, 0, 0};   Point(2) = {c, 0, 0};   Point(3) = {W, 0, 0};
Point(4) = {0, y1, 0};  Point(5) = {c, y1, 0};  Point(11) = {W, y1, 0};
Point(6) = {0, y2, 0};  Point(7) = {c, y2, 0};  Point(12) = {W, y2, 0};
Point(8) = {0, H, 0};   Point(9) = {c, H, 0};   Point(10) = {W, H, 0};

Line(1) = {1, 2};  Line(2) = {2, 3};    // bottom edge
Line(3) = {4, 5};                       // slot bottom face
Line(4) = {6, 7};                       // slot top face
Line(5) = {8, 9};  Line(6) = {9, 10};   // top edge
Line(7) = {1, 4};  Line(8) = {2, 5};  Line(12) = {3, 11};   // lower part, up towards the slot
Line(10) = {8, 6}; Line(9) = {9, 7};  Line(14) = {10, 12};  // upper part, down towards the slot
Line(11) = {5, 7}; Line(13) = {11, 12};                     // notch tip face; its right twin

Curve Loop(1) = {1, 8, -3, -7};                    Plane Surface(1) = {1};  // lower arm
Curve Loop(2) = {-5, 10, 4, -9};                   Plane Surface(2) = {2};  // upper arm
Curve Loop(3) = {2, 12, 13, -14, -6, 9, -11, -8};  Plane Surface(3) = {3};  // ligament

nx1 = Round(c / h) * refine;         // cells along the arms
nx2 = Round((W - c) / h) * refine;   // cells across the ligament
ny = Round(y1 / h) * refine;         // cells over each arm's height (graded)
ns = Max(1, Round(s / h)) * refine;  // cells across the notch tip
ratio = grading^(1 / refine);
Transfinite Curve{1, 3, 4, 5} = nx1 + 1;
Transfinite Curve{2, 6} = nx2 + 1;
// Vertical lines run towards the slot's height, so cells shrink towards it (ratio < 1).
Transfinite Curve{7, 8, 9, 10, 12, 14} = ny + 1 Using Progression 1 / ratio;
Transfinite Curve{11, 13} = ns + 1;
Transfinite Surface{1, 2};
Transfinite Surface{3} = {2, 3, 10, 9};  // corners: the left side runs 2 -> 5 -> 7 -> 9
Recombine Surface{1, 2, 3};

Extrude {0, 0, T} { Surface{1, 2, 3}; Layers{nz * refine}; Recombine; }

e = 1e-6 * W;  // tolerance of the bounding boxes below
Physical Volume("plate") = Volume{:};
Physical Surface("grip_bottom") = Surface In BoundingBox{-e, -e, -e, W + e, e, T + e};
Physical Surface("grip_top") = Surface In BoundingBox{-e, H - e, -e, W + e, H + e, T + e};
Physical Surface("notch_tip") = Surface In BoundingBox{c - e, y1 - e, -e, c + e, y2 + e, T + e};
