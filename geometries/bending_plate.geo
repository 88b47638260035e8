// Thin plate for three-point bending, graded through its thickness.
//
//   gmsh -3 bending_plate.geo                        -> bending_plate.msh
//   gsph-preproc bending_plate.geo -o plate.h5       (meshes in-process)
//
// The plate spans x in [0, L], y in [0, B], z in [0, T]. It rests on two supports at
// x = a and x = L - a on its bottom face and is loaded along x = L/2 on its top face. To give
// those lines their own particle sets, the plate is cut along x into 7 blocks (strips of width
// w under the supports and the load); the blocks glue into one generalized space. Cells are
// graded through the thickness (finer at the top and bottom faces, where the bending stress is
// largest) with a symmetric bump.
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "plate". Sets: "support_left", "support_right" (bottom strips),
// "load" (top strip at mid-span).

DefineConstant[
  L = {0.2, Name "Parameters/L"},        // length along x [m]
  B = {0.04, Name "Parameters/B"},       // width along y [m]
  T = {0.005, Name "Parameters/T"},      // thickness along z [m]
  a = {0.02, Name "Parameters/a"},       // support position from each end [m]
  w = {0.004, Name "Parameters/w"},      // width of the support and load strips [m]
  h = {0.002, Name "Parameters/h"},      // in-plane cell size [m]
  nz = {6, Name "Parameters/nz"},        // cells through the thickness
  bump = {0.25, Name "Parameters/bump"}, // < 1: finer at both faces (gmsh "Using Bump")
  refine = {1, Name "Parameters/refine"} // multiplies every cell count (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (L <= 0 || B <= 0 || T <= 0 || a <= 0 || w <= 0 || h <= 0 || bump <= 0 || nz < 1 || refine < 1)
  Error("bending_plate.geo: needs L, B, T, a, w, h, bump > 0; nz, refine ≥ 1 (got L = %g, B = %g, T = %g, a = %g, w = %g, h = %g, bump = %g, nz = %g, refine = %g)", L, B, T, a, w, h, bump, nz, refine);
EndIf

// Block boundaries along x: end, support strip, mid-span load strip, support strip, end.
xs[] = {0, a - w/2, a + w/2, L/2 - w/2, L/2 + w/2, L - a - w/2, L - a + w/2, L};

// Cross-section in the x-z plane (y = 0): points at the bottom (z = 0) and top (z = T).
For m In {0:7}
  bottom[m] = newp; Point(bottom[m]) = {xs[m], 0, 0};
  top[m] = newp;    Point(top[m]) = {xs[m], 0, T};
  up[m] = newl;     Line(up[m]) = {bottom[m], top[m]};     // through the thickness
EndFor
Transfinite Curve{up[]} = nz * refine + 1 Using Bump bump;

For m In {0:6}
  lower[m] = newl; Line(lower[m]) = {bottom[m], bottom[m + 1]};
  upper[m] = newl; Line(upper[m]) = {top[m], top[m + 1]};
  cells = Round((xs[m + 1] - xs[m]) / h) * refine;
  If (cells < 1)
    cells = 1;
  EndIf
  Transfinite Curve{lower[m], upper[m]} = cells + 1;
  loop = newll; Curve Loop(loop) = {lower[m], up[m + 1], -upper[m], -up[m]};
  section[m] = news; Plane Surface(section[m]) = {loop};
  Transfinite Surface{section[m]};
  Recombine Surface{section[m]};
EndFor

// Structured through the width: one extrusion of the whole section, layers recombined to hexes.
Extrude {0, B, 0} { Surface{section[]}; Layers{Round(B / h) * refine}; Recombine; }

e = 1e-6 * L;  // tolerance of the bounding boxes below
Physical Volume("plate") = Volume{:};
Physical Surface("support_left") = Surface In BoundingBox{xs[1] - e, -e, -e, xs[2] + e, B + e, e};
Physical Surface("support_right") = Surface In BoundingBox{xs[5] - e, -e, -e, xs[6] + e, B + e, e};
Physical Surface("load") = Surface In BoundingBox{xs[3] - e, -e, T - e, xs[4] + e, B + e, T + e};
