// Kalthoff–Winkler edge-cracked plate impact: the full plate as ONE generalized space, graded
// so that the cells are finest where the cracks run. The notches are not in the mesh: they are
// sharp initial cracks of the case ([[precrack]] in cases/kalthoff_winkler/case.toml, bonds
// crossing the notch planes start broken).
//
//   gmsh -3 kalthoff_winkler.geo                                  -> kalthoff_winkler.msh
//   gsph-preproc kalthoff_winkler.geo -o kw.h5                     (GSPH: graded, one space)
//   gsph-preproc kalthoff_winkler.geo -o kw_u.h5 --lattice 0.002   (uniform layout, same plate)
//
// A plate W x H x T (x: the impact direction, y: along the impacted edge, z: thickness), the
// impacted edge at x = 0, y in [-H/2, H/2]. The notches run along y = ±d/2 from x = 0 to the
// notch tips at x = c; the edge between them (the "impact" set) is struck. The cracks start at
// the tips and run at about 70° to +x, away from the struck middle, to the edges y = ±H/2.
//
// The plate is a tensor product of 1-D gradings, cut into 3 x 6 transfinite blocks that share
// edges with matching node counts, so gsph-preproc glues them into one index space (no overset
// band anywhere):
//   x: [0, x1] graded from `coarsen` h at the struck edge to h at x1 = c - a; [x1, c] and
//      [c, W] cells of about h (the notch tips x = c lie on a mesh line);
//   y: [-H/2, -d/2] and [d/2, H/2] (where the cracks run) and [-d/2, -y1], [y1, d/2]
//      (a band a below the notch lines) cells of about h (the notch lines y = ±d/2 lie on mesh
//      lines, so no particle sits on a notch plane); [-y1, 0] and [0, y1] graded from h at
//      ±y1 to `coarsenY` h (2) at the middle line y = 0, where no crack runs (graded to 3 h,
//      the far edge's reflected tension breaks bonds along two bands where the fine cells meet
//      the coarse ones, within the tips' crack paths' reach: docs/theory.md "Softening bonds");
//   z: nz cells through the thickness (default: T/h rounded, as the uniform layout has).
// `coarsenX`, `coarsenY` (0: `coarsen`) set one direction's grading on its own (docs/theory.md:
// the crack path's sensitivity to the grading).
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "plate". Set: "impact" (x = 0, |y| ≤ d/2).

DefineConstant[
  W = {0.1, Name "Parameters/W"},           // length along the impact direction x [m]
  H = {0.2, Name "Parameters/H"},           // width of the impacted edge, along y [m]
  T = {0.009, Name "Parameters/T"},         // thickness along z [m]
  c = {0.05, Name "Parameters/c"},          // notch length from x = 0 [m]
  d = {0.05, Name "Parameters/d"},          // distance between the notch lines [m]
  h = {0.002, Name "Parameters/h"},         // cell size where the cracks run [m]
  a = {0.005, Name "Parameters/a"},         // fine band before the tips and below the notches [m],
                                            // rounded to whole cells of h
  coarsen = {3, Name "Parameters/coarsen"}, // cell size at x = 0 and at y = 0, in h
  coarsenX = {0, Name "Parameters/coarsenX"}, // cell size at x = 0 only (0: coarsen)
  coarsenY = {2, Name "Parameters/coarsenY"}, // cell size at y = 0 only (0: coarsen)
  nz = {0, Name "Parameters/nz"},           // cells through the thickness (0: Round(T/h))
  refine = {1, Name "Parameters/refine"}    // divides h (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (W <= 0 || H <= 0 || T <= 0 || c <= 0 || d <= 0 || h <= 0 || a <= 0 || coarsen <= 0 || refine < 1 || coarsenX < 0 || coarsenY < 0 || nz < 0)
  Error("kalthoff_winkler.geo: needs W, H, T, c, d, h, a, coarsen > 0; refine ≥ 1; coarsenX, coarsenY, nz ≥ 0 (got W = %g, H = %g, T = %g, c = %g, d = %g, h = %g, a = %g, coarsen = %g, refine = %g, coarsenX = %g, coarsenY = %g, nz = %g)", W, H, T, c, d, h, a, coarsen, refine, coarsenX, coarsenY, nz);
EndIf
hr = h / refine;
Y = H / 2;
na = Max(1, Round(a / hr));  // the fine bands hold whole cells of hr
x1 = c - na * hr;
y1 = d / 2 - na * hr;
xs[] = {0, x1, c, W};
ys[] = {-Y, -d / 2, -y1, 0, y1, d / 2, Y};

// Cells per segment: graded runs of n cells from hr to coarsen hr (n from the mean cell, a
// geometric progression of ratio r per cell); the others as close to hr as a whole number allows.
cx = coarsenX > 0 ? coarsenX : coarsen;
cy = coarsenY > 0 ? coarsenY : coarsen;
nGraded = Max(2, Round(2 * x1 / (hr * (1 + cx))));
rGradedX = cx^(1 / (nGraded - 1));
nGradedY = Max(2, Round(2 * y1 / (hr * (1 + cy))));
rGradedY = cy^(1 / (nGradedY - 1));
nxs[] = {nGraded, na, Max(1, Round((W - c) / hr))};
nys[] = {Max(1, Round((Y - d / 2) / hr)), na, nGradedY,
         nGradedY, na, Max(1, Round((Y - d / 2) / hr))};
nzCells = nz > 0 ? nz : Max(1, Round(T / hr));

// Points p(i, j) = 1000 + 10 i + j at (xs[i], ys[j]).
For i In {0 : 3}
  For j In {0 : 6}
    Point(1000 + 10 * i + j) = {xs[i], ys[j], 0};
  EndFor
EndFor
// Lines along x: 2000 + 10 i + j from p(i, j) to p(i+1, j); along y: 3000 + 10 i + j from
// p(i, j) to p(i, j+1).
For i In {0 : 2}
  For j In {0 : 6}
    Line(2000 + 10 * i + j) = {1000 + 10 * i + j, 1000 + 10 * (i + 1) + j};
    If (i == 0)
      Transfinite Curve{2000 + j} = nxs[0] + 1 Using Progression 1 / rGradedX;  // fine at x1
    Else
      Transfinite Curve{2000 + 10 * i + j} = nxs[i] + 1;
    EndIf
  EndFor
EndFor
For i In {0 : 3}
  For j In {0 : 5}
    Line(3000 + 10 * i + j) = {1000 + 10 * i + j, 1000 + 10 * i + j + 1};
    If (j == 2)
      Transfinite Curve{3000 + 10 * i + j} = nys[j] + 1 Using Progression rGradedY;  // coarse at 0
    ElseIf (j == 3)
      Transfinite Curve{3000 + 10 * i + j} = nys[j] + 1 Using Progression 1 / rGradedY;
    Else
      Transfinite Curve{3000 + 10 * i + j} = nys[j] + 1;
    EndIf
  EndFor
EndFor
// Surfaces s(i, j) = 4000 + 10 i + j over [xs[i], xs[i+1]] x [ys[j], ys[j+1]].
For i In {0 : 2}
  For j In {0 : 5}
    Curve Loop(4000 + 10 * i + j) = {2000 + 10 * i + j, 3000 + 10 * (i + 1) + j,
                                     -(2000 + 10 * i + j + 1), -(3000 + 10 * i + j)};
    Plane Surface(4000 + 10 * i + j) = {4000 + 10 * i + j};
    Transfinite Surface{4000 + 10 * i + j};
    Recombine Surface{4000 + 10 * i + j};
  EndFor
EndFor

Extrude {0, 0, T} { Surface{4000 : 4005, 4010 : 4015, 4020 : 4025}; Layers{nzCells}; Recombine; }

e = 1e-6 * W;  // tolerance of the bounding boxes below
Physical Volume("plate") = Volume{:};
Physical Surface("impact") = Surface In BoundingBox{-e, -d / 2 - e, -e, e, d / 2 + e, T + e};
