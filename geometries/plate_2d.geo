// Plate, plane strain: a rectangle of structured quadrangles, cells graded towards the loaded
// edge y = 0, for a 2-D plane-strain run.
//
//   gmsh -2 plate_2d.geo                         -> plate_2d.msh
//   gsph-preproc plate_2d.geo -o plate.h5        (meshes in 2-D in-process)
//   gsph-preproc plate_2d.geo -o plate.h5 --set refine=2 --set grading=1.05
//
// A 2-D particle file's volumes and set areas are per metre of depth (docs/formats.md).
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Surface "plate". Sets (physical curves): "bottom" (y = 0), "right" (x = W),
// "top" (y = H), "left" (x = 0).

DefineConstant[
  W = {0.04, Name "Parameters/W"},            // width along x [m]
  H = {0.02, Name "Parameters/H"},            // height along y [m]
  nx = {20, Name "Parameters/nx"},            // cells along x
  ny = {12, Name "Parameters/ny"},            // cells along y
  grading = {1.1, Name "Parameters/grading"},  // ratio of successive cell heights from y = 0
  refine = {1, Name "Parameters/refine"}      // multiplies every cell count (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (W <= 0 || H <= 0 || grading <= 0 || nx < 1 || ny < 1 || refine < 1)
  Error("plate_2d.geo: needs W, H, grading > 0; nx, ny, refine ≥ 1 (got W = %g, H = %g, grading = %g, nx = %g, ny = %g, refine = %g)", W, H, grading, nx, ny, refine);
EndIf
// Keep the same geometric grading when refining: the ratio per cell is grading^(1/refine).
ratio = grading^(1 / refine);

Point(1) = {0, 0, 0};  Point(2) = {W, 0, 0};  Point(3) = {W, H, 0};  Point(4) = {0, H, 0};
Line(1) = {1, 2};  // y = 0
Line(2) = {2, 3};  // x = W, from y = 0
Line(3) = {4, 3};  // y = H
Line(4) = {1, 4};  // x = 0, from y = 0
Curve Loop(1) = {1, 2, -3, -4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = nx * refine + 1;
Transfinite Curve{2, 4} = ny * refine + 1 Using Progression ratio;
Transfinite Surface{1};
Recombine Surface{1};

Physical Surface("plate") = {1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
