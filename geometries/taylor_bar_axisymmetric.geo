// Taylor bar, axisymmetric: the half-plane (r, z) cross-section of the copper rod of
// taylor_bar.geo as one structured block of quadrangles, for a 2-D axisymmetric run.
//
//   gmsh -2 taylor_bar_axisymmetric.geo                        -> taylor_bar_axisymmetric.msh
//   gsph-preproc taylor_bar_axisymmetric.geo -o taylor_rz.h5   (meshes in 2-D in-process)
//   gsph-preproc taylor_bar_axisymmetric.geo -o taylor_rz.h5 --set refine=2
//
// The section is the rectangle 0 <= x <= R, 0 <= y <= L: x is the radius r, y runs along the
// bar's axis, the impact face is y = 0. Length 25.4 mm, diameter 7.6 mm (taylor_bar.geo). The
// cells are uniform and roughly square: nr * refine across the radius, as many along the axis
// as keep them square. A 2-D particle file's volumes are per metre of depth (the cells' areas):
// the axisymmetric run turns them into rings (docs/formats.md).
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Surface "rod". Sets (physical curves), named as taylor_bar.geo's: "impact"
// (y = 0), "lateral" (x = R), "free_end" (y = L), and "axis" (x = 0).

DefineConstant[
  R = {3.8e-3, Name "Parameters/R"},      // radius [m]
  L = {25.4e-3, Name "Parameters/L"},     // length [m]
  nr = {8, Name "Parameters/nr"},         // cells across the radius
  nz = {0, Name "Parameters/nz"},         // cells along the axis (0: as many as keep them square)
  grading = {1, Name "Parameters/grading"},  // ratio of successive cell lengths from the impact face
  lip = {1, Name "Parameters/lip"},       // ratio of successive cell widths from the axis to x = R
                                          // (below 1: finer towards the lip)
  refine = {1, Name "Parameters/refine"}  // multiplies every cell count (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (R <= 0 || L <= 0 || nr < 1 || nz < 0 || grading <= 0 || lip <= 0 || refine < 1)
  Error("taylor_bar_axisymmetric.geo: needs R, L, grading, lip > 0; nr, refine ≥ 1; nz ≥ 0 (got R = %g, L = %g, nr = %g, nz = %g, grading = %g, lip = %g, refine = %g)", R, L, nr, nz, grading, lip, refine);
EndIf
cells_r = Round(nr * refine);
cells_z = nz > 0 ? Round(nz * refine) : Round(cells_r * L / R);  // default: square cells

Point(1) = {0, 0, 0};  Point(2) = {R, 0, 0};  Point(3) = {R, L, 0};  Point(4) = {0, L, 0};
Line(1) = {1, 2};  // y = 0: the impact face
Line(2) = {2, 3};  // x = R: the side
Line(3) = {4, 3};  // y = L: the top
Line(4) = {1, 4};  // x = 0: the axis
Curve Loop(1) = {1, 2, -3, -4};
Plane Surface(1) = {1};

// Refined, the same layout with every cell `refine` times smaller: the ratios of successive
// cells become their refine-th roots, as in taylor_bar.geo.
Transfinite Curve{1, 3} = cells_r + 1 Using Progression lip^(1 / refine);  // from the axis outwards
Transfinite Curve{2, 4} = cells_z + 1 Using Progression grading^(1 / refine);  // from the impact face up
Transfinite Surface{1};
Recombine Surface{1};

Physical Surface("rod") = {1};
Physical Curve("impact") = {1};
Physical Curve("axis") = {4};
Physical Curve("lateral") = {2};
Physical Curve("free_end") = {3};
