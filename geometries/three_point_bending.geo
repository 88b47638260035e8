// Thin plate (a narrow strip) for three-point bending (cases/three_point_bending/case.toml):
// one structured hex block, cells anisotropic — fine through the thickness, coarse in-plane.
//
//   gsph-preproc three_point_bending.geo -o gsph.h5                  (GSPH layout: cells 3:1)
//   gsph-preproc three_point_bending.geo -o uniform.h5 --set aspect=1 (uniform: cubic cells)
//   gmsh -3 three_point_bending.geo                                   -> three_point_bending.msh
//
// The plate spans x in [-L/2, L/2], y in [-W/2, W/2], z in [0, T]; it bends about y over
// supports at x = ±S/2 under its bottom face (the case's cylinders; the plate needs no sets).
// Why anisotropic cells, not a grading towards the faces: in bending the stress varies through
// the thickness (linearly while elastic, then an elastic core between plastic layers) and only
// slowly along the span (the moment is linear in x), so the thickness needs the particles and
// the plane does not. Uniform thin layers keep the smallest spacing — which sets the stable
// step — at T/nz; a grading towards the faces would shrink it and lengthen every run.
// Defaults: nz = 6 cells of T/6 through the thickness, in-plane cells aspect × T/nz = 1 mm
// (31 × 3 × 6 = 558 particles); aspect = 1 gives cubic cells of the same thickness spacing
// (93 × 9 × 6 = 5022 particles, 9×). L = 31 mm and an odd cell count put a particle column
// under the indenter (x = 0) and over each support (x = ±10 mm) in both layouts.
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m). Body: Physical Volume "plate".

DefineConstant[
  L = {0.031, Name "Parameters/L"},        // length along x [m] (span S = 0.02 + overhangs)
  W = {0.003, Name "Parameters/W"},        // width along y [m]
  T = {0.002, Name "Parameters/T"},        // thickness along z [m]
  nz = {6, Name "Parameters/nz"},          // cells through the thickness
  aspect = {3, Name "Parameters/aspect"},  // in-plane cell size / thickness spacing T/nz
  refine = {1, Name "Parameters/refine"}   // multiplies every cell count (convergence studies)
];

h = aspect * T / nz;  // in-plane cell size [m]
nx = Round(L / h);
ny = Round(W / h);
If (ny < 1)
  ny = 1;
EndIf

Point(1) = {-L/2, -W/2, 0};  Point(2) = {L/2, -W/2, 0};
Point(3) = {L/2, W/2, 0};    Point(4) = {-L/2, W/2, 0};
Point(5) = {-L/2, -W/2, T};  Point(6) = {L/2, -W/2, T};
Point(7) = {L/2, W/2, T};    Point(8) = {-L/2, W/2, T};

Line(1) = {1, 2};  Line(2) = {4, 3};  Line(3) = {5, 6};  Line(4) = {8, 7};  // along x
Line(5) = {1, 4};  Line(6) = {2, 3};  Line(7) = {5, 8};  Line(8) = {6, 7};  // along y
Line(9) = {1, 5};  Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8}; // along z

Curve Loop(1) = {1, 6, -2, -5};   Plane Surface(1) = {1};  // z = 0 (on the supports)
Curve Loop(2) = {3, 8, -4, -7};   Plane Surface(2) = {2};  // z = T (under the indenter)
Curve Loop(3) = {1, 10, -3, -9};  Plane Surface(3) = {3};  // y = -W/2
Curve Loop(4) = {2, 11, -4, -12}; Plane Surface(4) = {4};  // y = W/2
Curve Loop(5) = {5, 12, -7, -9};  Plane Surface(5) = {5};  // x = -L/2
Curve Loop(6) = {6, 11, -8, -10}; Plane Surface(6) = {6};  // x = L/2
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};

Transfinite Curve{1, 2, 3, 4} = nx * refine + 1;
Transfinite Curve{5, 6, 7, 8} = ny * refine + 1;
Transfinite Curve{9, 10, 11, 12} = nz * refine + 1;
Transfinite Surface{1:6};
Recombine Surface{1:6};
Transfinite Volume{1};

Physical Volume("plate") = {1};
