// Blunt projectile: a cylinder with a hemispherical nose, structured throughout. The cylinder is
// an O-grid (a square core + 4 annulus blocks, as taylor_bar.geo); the nose is half a cubed
// sphere (as sphere.geo): a half cube continuing the cylinder's core, the shell block below it
// and four half shell blocks around it, which meet the annulus blocks node for node at the
// junction (the nose's equator, a section of the O-grid).
//
//   gsph-preproc projectile_hemispherical_nose.geo -o projectile.h5
//   gsph-preproc projectile_hemispherical_nose.geo -o projectile.h5 --set refine=2
//
// Axis along z, nose pointing to -z with its tip at z = 0, the sphere's centre (the junction)
// at z = R, the flat rear end at z = R + L. The blocks meet three at an edge around the half
// cube and the core, so they cannot all glue into one generalized space: gsph-preproc glues the
// core, the half cube and the shell block below it (a column along the axis) and the annulus
// and half shell blocks into a ring periodic around it, and couples the two spaces by the
// overset method (docs/formats.md). Every parameter can be overridden with
// `gmsh -setnumber NAME VALUE` or `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "projectile". Sets: "nose" (the hemisphere), "rear" (z = R + L).

DefineConstant[
  R = {5e-3, Name "Parameters/R"},        // radius of the cylinder and of the nose [m]
  L = {20e-3, Name "Parameters/L"},       // length of the cylinder [m]
  core = {0.35, Name "Parameters/core"},  // the core's half-side as a fraction of R (< 1/√3)
  n = {8, Name "Parameters/n"},           // cells along a core side = per quarter of arc
  nr = {5, Name "Parameters/nr"},         // cells from the core to the outer surface
  nz = {40, Name "Parameters/nz"},        // cells along the cylinder
  refine = {1, Name "Parameters/refine"}  // multiplies every cell count (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (R <= 0 || L <= 0 || core <= 0 || core * Sqrt(3) >= 1 || n < 1 || nr < 1 || nz < 1 || refine < 1)
  Error("projectile_hemispherical_nose.geo: needs R, L > 0, 0 < core < 1/sqrt(3), n, nr, nz, refine >= 1 (got R = %g, L = %g, core = %g, n = %g, nr = %g, nz = %g, refine = %g)", R, L, core, n, nr, nz, refine);
EndIf
zc = R;           // the sphere's centre: the junction's plane
c = core * R;     // half-side of the core, and height of the half cube below the junction
s3 = R / Sqrt(3);  // the sphere's points above the half cube's lower corners
s2 = R / Sqrt(2);  // and above its upper corners, on the equator (the O-grid's rim)
nh = Ceil(n * refine / 2);  // cells along the half cube's height: cubic cells

Point(1) = {0, 0, zc};  // centre of the great circles
For i In {0:7}  // corner i at (±, ±, ±) with the x, y, z signs from the bits of i
  sx = 2 * (i % 2) - 1;  sy = 2 * (Floor(i / 2) % 2) - 1;  sz = 2 * Floor(i / 4) - 1;
  inner[i] = newp;  outer[i] = newp + 1;
  If (sz < 0)
    Point(inner[i]) = {sx * c, sy * c, zc - c};  Point(outer[i]) = {sx * s3, sy * s3, zc - s3};
  Else
    Point(inner[i]) = {sx * c, sy * c, zc};      Point(outer[i]) = {sx * s2, sy * s2, zc};
  EndIf
EndFor
// The 12 edges of the half cube as corner pairs: 4 along x, 4 along y, 4 along z.
from[] = {0, 2, 4, 6,  0, 1, 4, 5,  0, 1, 2, 3};
to[] = {1, 3, 5, 7,  2, 3, 6, 7,  4, 5, 6, 7};
For e In {0:11}
  cube[e] = newl;  Line(cube[e]) = {inner[from[e]], inner[to[e]]};
  arc[e] = newl;   Circle(arc[e]) = {outer[from[e]], 1, outer[to[e]]};  // a great-circle arc
EndFor
For i In {0:7}
  spoke[i] = newl;  Line(spoke[i]) = {inner[i], outer[i]};
EndFor
Transfinite Curve{cube[{0:7}], arc[{0:7}]} = n * refine + 1;
Transfinite Curve{cube[{8:11}], arc[{8:11}]} = nh + 1;
Transfinite Curve{spoke[]} = nr * refine + 1;

// Between a cube edge and the arc above it: the side shared by two shell blocks; the four
// along the top (edges 2, 3, 6, 7) are the annulus blocks' sections at the junction.
For e In {0:11}
  loop = newll;  Curve Loop(loop) = {cube[e], spoke[to[e]], -arc[e], -spoke[from[e]]};
  side[e] = news;  Surface(side[e]) = {loop};
EndFor
// The six faces (-x, +x, -y, +y, -z, +z) as four edges each, walked round with their signs;
// the +z face (the core's section at the junction) has no shell block.
faceEdge[] = {4, 10, 6, 8,  5, 11, 7, 9,  0, 9, 2, 8,  1, 11, 3, 10,  0, 5, 1, 4,  2, 7, 3, 6};
For f In {0:5}
  innerLoop[] = {};  outerLoop[] = {};
  For k In {0:3}
    sign = (k < 2) ? 1 : -1;
    innerLoop[] += sign * cube[faceEdge[4 * f + k]];
    outerLoop[] += sign * arc[faceEdge[4 * f + k]];
  EndFor
  loop = newll;  Curve Loop(loop) = innerLoop[];  face[f] = news;  Plane Surface(face[f]) = {loop};
  If (f < 5)
    loop = newll;  Curve Loop(loop) = outerLoop[];  cap[f] = news;  Surface(cap[f]) = {loop} In Sphere{1};
  EndIf
EndFor
Transfinite Surface{side[], face[], cap[]};
Recombine Surface{side[], face[], cap[]};

shell = newsl;  Surface Loop(shell) = {face[]};
block[0] = newv;  Volume(block[0]) = {shell};  // the half cube
For f In {0:4}
  bounding[] = {face[f], cap[f]};
  For k In {0:3}
    bounding[] += side[faceEdge[4 * f + k]];
  EndFor
  shell = newsl;  Surface Loop(shell) = bounding[];
  block[f + 1] = newv;  Volume(block[f + 1]) = {shell};
EndFor
Transfinite Volume{block[]};

// The cylinder: the junction's O-grid section (core + 4 annulus blocks) extruded along z.
Extrude {0, 0, L} { Surface{face[5], side[{2, 3, 6, 7}]}; Layers{nz * refine}; Recombine; }

e = 1e-6 * R;  // tolerance of the bounding box below
Physical Volume("projectile") = Volume{:};
Physical Surface("nose") = {cap[]};
Physical Surface("rear") = Surface In BoundingBox{-R - e, -R - e, zc + L - e, R + e, R + e, zc + L + e};
