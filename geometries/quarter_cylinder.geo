// The paper's quarter cylinder: a Cartesian core block and a cylindrical outer block.
//
//   gmsh -3 quarter_cylinder.geo                      -> quarter_cylinder.msh
//   gsph-preproc quarter_cylinder.geo -o qc.h5        (meshes in-process)
//
// A quarter of a cylinder of radius R (x, y >= 0), length Lz along z. A cylindrical index
// space alone would be singular on the axis; here the axis is covered by a Cartesian core
// block [0, c]², and the rest by one outer block whose indices run radially (from the core's
// two outer sides to the arc) and around the arc. The outer block's inner side is made of two
// core sides, so the two blocks share no whole face: they are two generalized spaces (space 0:
// core, space 1: outer), the layout of the paper's overset example. By default the slab is one
// cell thick, the paper's 2-D case; raise Lz and nz for a 3-D quarter cylinder.
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "quarter_cylinder". Sets: "symmetry_x" (x = 0), "symmetry_y" (y = 0),
// "outer" (r = R), "bottom" (z = 0), "top" (z = Lz).

DefineConstant[
  R = {0.01, Name "Parameters/R"},          // radius [m]
  core = {0.5, Name "Parameters/core"},     // core side c as a fraction of R
  Lz = {0.001, Name "Parameters/Lz"},       // length along z [m]
  n = {8, Name "Parameters/n"},             // cells along each core side (2n around the arc)
  nr = {6, Name "Parameters/nr"},           // cells from the core to the arc
  nz = {1, Name "Parameters/nz"},           // cells along z
  refine = {1, Name "Parameters/refine"}    // multiplies every cell count (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (R <= 0 || core <= 0 || Lz <= 0 || n < 1 || nr < 1 || nz < 1 || refine < 1)
  Error("quarter_cylinder.geo: needs R, core, Lz > 0; n, nr, nz, refine ≥ 1 (got R = %g, core = %g, Lz = %g, n = %g, nr = %g, nz = %g, refine = %g)", R, core, Lz, n, nr, nz, refine);
EndIf
c = core * R;

Point(1) = {0, 0, 0};  Point(2) = {c, 0, 0};  Point(3) = {c, c, 0};  Point(4) = {0, c, 0};
Point(5) = {R, 0, 0};  Point(6) = {0, R, 0};  Point(7) = {R / Sqrt(2), R / Sqrt(2), 0};

Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};  Line(4) = {4, 1};  // core square
// Outer block: the arc is cut at 45° (two arcs: gmsh reparametrises extruded 90° arcs poorly
// and warns on fine meshes).
Line(5) = {2, 5};  Circle(6) = {5, 1, 7};  Circle(8) = {7, 1, 6};  Line(7) = {6, 4};

Curve Loop(1) = {1, 2, 3, 4};       Plane Surface(1) = {1};  // core
Curve Loop(2) = {5, 6, 8, 7, -3, -2};  Plane Surface(2) = {2};  // outer: inner and outer
                                                                // sides of 2 curves each

Transfinite Curve{1, 2, 3, 4} = n * refine + 1;
Transfinite Curve{6, 8} = n * refine + 1;
Transfinite Curve{5, 7} = nr * refine + 1;
Transfinite Surface{1};
Transfinite Surface{2} = {2, 5, 6, 4};  // corners: the inner side runs 2 -> 3 -> 4
Recombine Surface{1, 2};

// Structured along z: extrude the structured section, layers recombined into hexes.
Extrude {0, 0, Lz} { Surface{1, 2}; Layers{nz * refine}; Recombine; }

e = 1e-6 * R;  // tolerance of the bounding boxes below
Physical Volume("quarter_cylinder") = Volume{:};
Physical Surface("symmetry_x") = Surface In BoundingBox{-e, -e, -e, e, R + e, Lz + e};
Physical Surface("symmetry_y") = Surface In BoundingBox{-e, -e, -e, R + e, e, Lz + e};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, R + e, R + e, e};
Physical Surface("top") = Surface In BoundingBox{-e, -e, Lz - e, R + e, R + e, Lz + e};
// The arc: the lateral surfaces (full length) that reach x = R or y = R, leaving out the faces
// in the symmetry planes (whose bounding boxes are flat in x or in y).
Physical Surface("outer") = {};
all[] = Surface{:};
For k In {0:#all[] - 1}
  bb[] = BoundingBox Surface{all[k]};  // {xmin, ymin, zmin, xmax, ymax, zmax}
  lateral = bb[5] - bb[2] > Lz - e;
  If (lateral && (bb[3] > R - e || bb[4] > R - e) && bb[3] > e && bb[4] > e)
    Physical Surface("outer") += {all[k]};
  EndIf
EndFor
