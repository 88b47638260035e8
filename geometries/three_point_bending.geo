// Thin plate (a narrow strip) for three-point bending (cases/three_point_bending/case.toml):
// one structured hex block (an extrusion along x), graded along x — cubic cells under the
// indenter and over the supports, up to `aspect` times longer in between — with uniform layers
// through the thickness.
//
//   gsph-preproc three_point_bending.geo -o gsph.h5                  (GSPH layout, graded)
//   gsph-preproc three_point_bending.geo -o uniform.h5 --set aspect=1 (uniform: cubic cells)
//   gmsh -3 three_point_bending.geo                                   -> three_point_bending.msh
//
// The plate spans x in [-L/2, L/2], y in [-W/2, W/2], z in [0, T]; it bends about y over
// supports at x = ±S/2 under its bottom face (the case's cylinders; the plate needs no sets).
// Why this layout: in bending the stress varies through the thickness (linearly while elastic,
// then an elastic core between plastic layers), so every section keeps nz uniform layers of
// h = T/nz (uniform layers also keep the smallest spacing — which sets the stable step — at
// T/nz). Along the span the moment is linear and the plate needs few particles, except where
// it touches a cylinder: under the indenter the plastic hinge forms and the plate then wraps
// the cylinder, and over the supports it bends round them; a contact that steps from one
// particle column to the next makes the force jump by the column's share. So the cells are h
// long in |x| < band (the hinge and the arc wrapped by δ = T) and `support`·h long within
// support_band of x = ±S/2, `aspect`·h elsewhere, the cell length changing by at most the
// factor `ratio` between neighbours (a steeper change, or a gmsh Bump, chatters); the graded
// part is then stretched or shrunk (by 2 % here) to fit L. Across the width (nothing varies
// along y) the cells are `across`·h wide (4 across, across = 2.25, did worse: docs/theory.md).
// Defaults: 6 layers of 1/3 mm, 3 across, 67 along x (21 under the indenter, 7 over each
// support): 1206 particles; aspect = 1 gives the uniform layout of cubic 1/3 mm cells,
// 93 × 9 × 6 = 5022 (4.2×). A particle column sits under the indenter (an odd band).
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m). Body: Physical Volume "plate".

DefineConstant[
  L = {0.031, Name "Parameters/L"},                // length along x [m]
  W = {0.003, Name "Parameters/W"},                // width along y [m]
  T = {0.002, Name "Parameters/T"},                // thickness along z [m]
  S = {0.02, Name "Parameters/S"},                 // span: supports at x = ±S/2 [m]
  nz = {6, Name "Parameters/nz"},                  // cells through the thickness
  aspect = {3, Name "Parameters/aspect"},          // coarse cell length / (T/nz); 1: uniform
  band = {0.0035, Name "Parameters/band"},         // half-width of the cubic cells at x = 0 [m]
  support = {1, Name "Parameters/support"},        // cell length / (T/nz) at the supports
  support_band = {0.001, Name "Parameters/support_band"},  // half-width of that zone [m]
  across = {3, Name "Parameters/across"},          // cell width / (T/nz) (at most aspect)
  ratio = {1.25, Name "Parameters/ratio"},         // largest length ratio of neighbouring cells
  refine = {1, Name "Parameters/refine"}           // divides h (the ramps keep their ratio)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (L <= 0 || W <= 0 || T <= 0 || S <= 0 || aspect <= 0 || band <= 0 || support <= 0 || support_band <= 0 || across <= 0 || ratio <= 0 || nz < 1 || refine < 1)
  Error("three_point_bending.geo: needs L, W, T, S, aspect, band, support, support_band, across, ratio > 0; nz, refine ≥ 1 (got L = %g, W = %g, T = %g, S = %g, aspect = %g, band = %g, support = %g, support_band = %g, across = %g, ratio = %g, nz = %g, refine = %g)", L, W, T, S, aspect, band, support, support_band, across, ratio, nz, refine);
EndIf

h = T / (nz * refine);               // layer thickness = the finest cell length [m]
h_coarse = aspect * h;
h_support = Min(support * h, h_coarse);
slope = ratio - 1;                   // d(cell length)/dx of the ramps: ratio between neighbours
ny = Round(W / (Min(across, aspect) * h));
If (ny < 1)
  ny = 1;
EndIf

// Cell edges along x >= 0, marched from the centre cell [-h/2, h/2] and the band: the size
// field is min(coarse, indenter ramp, support ramp), the ramps of slope ratio − 1.
nband = Round((band - h / 2) / h);  // cells of length h right of the centre cell
edge[0] = h / 2;
For k In {1:nband}
  edge[k] = h / 2 + k * h;
EndFor
n = nband;
For k In {0:1000}
  If (edge[n] < L / 2 - 1e-9 * L)
    x = edge[n];
    // The size field at the cell's left edge, then no more than the field at its right edge
    // (twice: a fixed point), so that a cell before a finer zone is not too long either.
    ramp_support = h_support + slope * (Fabs(x - S / 2) - support_band);
    size_left = Min(h_coarse, Min(h + slope * (x - edge[nband]), Max(h_support, ramp_support)));
    size = size_left;
    For pass In {1:2}
      xr = x + size;
      size = Min(size_left, Min(h_coarse, Min(h + slope * (xr - edge[nband]),
                 Max(h_support, h_support + slope * (Fabs(xr - S / 2) - support_band)))));
    EndFor
    edge[n + 1] = x + size;
    n = n + 1;
  EndIf
EndFor
If (n > nband + 1 && L / 2 - edge[n - 1] < edge[n] - L / 2)
  n = n - 1;  // the nearer of the last two edges meets the end
EndIf
// Stretch (or shrink) the graded part to end at L/2 exactly; the band is kept.
stretch = (L / 2 - edge[nband]) / (edge[n] - edge[nband]);
For k In {nband + 1:n}
  edge[k] = edge[nband] + (edge[k] - edge[nband]) * stretch;
EndFor
// Extrusion heights (each layer's far edge, from x = -L/2, normalised by L): the mirrored
// edges, then the edges.
m = 0;
For k In {n - 1:0:-1}
  one[m] = 1;
  height[m] = (L / 2 - edge[k]) / L;
  m = m + 1;
EndFor
For k In {0:n}
  one[m] = 1;
  height[m] = (L / 2 + edge[k]) / L;
  m = m + 1;
EndFor
height[m - 1] = 1;

// The end section x = -L/2 (ny × nz structured), extruded along x through the layers above.
Point(1) = {-L/2, -W/2, 0};  Point(2) = {-L/2, W/2, 0};
Point(3) = {-L/2, W/2, T};   Point(4) = {-L/2, -W/2, T};
Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = ny + 1;  // (h, hence ny, includes refine)
Transfinite Curve{2, 4} = nz * refine + 1;
Transfinite Surface{1};
Recombine Surface{1};
Extrude {L, 0, 0} { Surface{1}; Layers{one[], height[]}; Recombine; }

Physical Volume("plate") = Volume{:};
