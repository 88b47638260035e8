// Graded bar: one structured hex block, cells graded along the length.
//
//   gmsh -3 graded_bar.geo                       -> graded_bar.msh
//   gsph-preproc graded_bar.geo -o bar.h5        (meshes in-process)
//   gsph-preproc graded_bar.geo -o bar.h5 --set refine=2 --set grading=1.05
//
// Every parameter below can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Bodies and sets: Physical Volume "bar"; Physical Surfaces "clamp" (x = 0) and "load" (x = L).

DefineConstant[
  L = {0.1, Name "Parameters/L"},          // length along x [m]
  W = {0.01, Name "Parameters/W"},         // width along y [m]
  H = {0.01, Name "Parameters/H"},         // height along z [m]
  nx = {20, Name "Parameters/nx"},         // cells along x
  ny = {4, Name "Parameters/ny"},          // cells along y
  nz = {4, Name "Parameters/nz"},          // cells along z
  grading = {1.1, Name "Parameters/grading"},  // ratio of successive cell lengths from x = 0
  refine = {1, Name "Parameters/refine"}   // multiplies every cell count (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (L <= 0 || W <= 0 || H <= 0 || grading <= 0 || nx < 1 || ny < 1 || nz < 1 || refine < 1)
  Error("graded_bar.geo: needs L, W, H, grading > 0; nx, ny, nz, refine ≥ 1 (got L = %g, W = %g, H = %g, grading = %g, nx = %g, ny = %g, nz = %g, refine = %g)", L, W, H, grading, nx, ny, nz, refine);
EndIf

// Keep the same geometric grading when refining: the ratio per cell is grading^(1/refine).
ratio = grading^(1 / refine);

Point(1) = {0, 0, 0};  Point(2) = {L, 0, 0};  Point(3) = {L, W, 0};  Point(4) = {0, W, 0};
Point(5) = {0, 0, H};  Point(6) = {L, 0, H};  Point(7) = {L, W, H};  Point(8) = {0, W, H};

Line(1) = {1, 2};  Line(2) = {4, 3};  Line(3) = {5, 6};  Line(4) = {8, 7};  // along x, from x = 0
Line(5) = {1, 4};  Line(6) = {2, 3};  Line(7) = {5, 8};  Line(8) = {6, 7};  // along y
Line(9) = {1, 5};  Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8}; // along z

Curve Loop(1) = {1, 6, -2, -5};   Plane Surface(1) = {1};  // z = 0
Curve Loop(2) = {3, 8, -4, -7};   Plane Surface(2) = {2};  // z = H
Curve Loop(3) = {1, 10, -3, -9};  Plane Surface(3) = {3};  // y = 0
Curve Loop(4) = {2, 11, -4, -12}; Plane Surface(4) = {4};  // y = W
Curve Loop(5) = {5, 12, -7, -9};  Plane Surface(5) = {5};  // x = 0
Curve Loop(6) = {6, 11, -8, -10}; Plane Surface(6) = {6};  // x = L
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};

// Structured hex block: transfinite curves, surfaces and volume, quads recombined into hexes.
Transfinite Curve{1, 2, 3, 4} = nx * refine + 1 Using Progression ratio;
Transfinite Curve{5, 6, 7, 8} = ny * refine + 1;
Transfinite Curve{9, 10, 11, 12} = nz * refine + 1;
Transfinite Surface{1:6};
Recombine Surface{1:6};
Transfinite Volume{1};

Physical Volume("bar") = {1};
Physical Surface("clamp") = {5};
Physical Surface("load") = {6};
