// Sphere as a "cubed sphere": a cube core and six shell blocks, each shell block between a face
// of the cube and the sphere's sixth above it. The standard structured sphere: no coordinate
// singularity anywhere, every cell close to a cube.
//
//   gsph-preproc sphere.geo -o sphere.h5
//   gsph-preproc sphere.geo -o sphere.h5 --set refine=2
//
// The blocks meet three at an edge (around each edge of the cube), so their indices cannot all
// glue into one generalized space: gsph-preproc glues the core with two opposite shell blocks
// (a column) and the four others into a ring periodic around the column's axis, and couples the
// two spaces by the overset method, continuing each space's lattice across the faces they
// share (docs/formats.md). Every parameter can be overridden with `gmsh -setnumber NAME VALUE`
// or `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "ball". Set: "surface" (r = R).

DefineConstant[
  R = {5e-3, Name "Parameters/R"},        // radius [m]
  core = {0.35, Name "Parameters/core"},  // the cube's half-side as a fraction of R (< 1/√3)
  n = {8, Name "Parameters/n"},           // cells along an edge of the cube
  nr = {5, Name "Parameters/nr"},         // cells from the cube to the sphere
  refine = {1, Name "Parameters/refine"}  // multiplies every cell count (convergence studies)
];
If (R <= 0 || core <= 0 || core * Sqrt(3) >= 1 || n < 1 || nr < 1 || refine < 1)
  Error("sphere.geo: needs R > 0, 0 < core < 1/sqrt(3), n, nr, refine >= 1 (got R = %g, core = %g, n = %g, nr = %g, refine = %g)", R, core, n, nr, refine);
EndIf
c = core * R;     // half-side of the cube
s = R / Sqrt(3);  // the sphere's points above the cube's corners

Point(1) = {0, 0, 0};  // centre of the great circles
For i In {0:7}  // corner i at (±, ±, ±) with the x, y, z signs from the bits of i
  sx = 2 * (i % 2) - 1;  sy = 2 * (Floor(i / 2) % 2) - 1;  sz = 2 * Floor(i / 4) - 1;
  inner[i] = newp;  Point(inner[i]) = {sx * c, sy * c, sz * c};
  outer[i] = newp;  Point(outer[i]) = {sx * s, sy * s, sz * s};
EndFor
// The 12 edges of a cube as corner pairs: 4 along x, 4 along y, 4 along z.
from[] = {0, 2, 4, 6,  0, 1, 4, 5,  0, 1, 2, 3};
to[] = {1, 3, 5, 7,  2, 3, 6, 7,  4, 5, 6, 7};
For e In {0:11}
  cube[e] = newl;  Line(cube[e]) = {inner[from[e]], inner[to[e]]};
  arc[e] = newl;   Circle(arc[e]) = {outer[from[e]], 1, outer[to[e]]};  // a great-circle arc
EndFor
For i In {0:7}
  spoke[i] = newl;  Line(spoke[i]) = {inner[i], outer[i]};
EndFor
Transfinite Curve{cube[], arc[]} = n * refine + 1;
Transfinite Curve{spoke[]} = nr * refine + 1;

// Between a cube edge and the arc above it: the side shared by two shell blocks.
For e In {0:11}
  loop = newll;  Curve Loop(loop) = {cube[e], spoke[to[e]], -arc[e], -spoke[from[e]]};
  side[e] = news;  Surface(side[e]) = {loop};
EndFor
// The six faces (-x, +x, -y, +y, -z, +z) as four edges each, walked round with their signs.
faceEdge[] = {4, 10, 6, 8,  5, 11, 7, 9,  0, 9, 2, 8,  1, 11, 3, 10,  0, 5, 1, 4,  2, 7, 3, 6};
For f In {0:5}
  innerLoop[] = {};  outerLoop[] = {};
  For k In {0:3}
    sign = (k < 2) ? 1 : -1;
    innerLoop[] += sign * cube[faceEdge[4 * f + k]];
    outerLoop[] += sign * arc[faceEdge[4 * f + k]];
  EndFor
  loop = newll;  Curve Loop(loop) = innerLoop[];  face[f] = news;  Plane Surface(face[f]) = {loop};
  loop = newll;  Curve Loop(loop) = outerLoop[];  cap[f] = news;  Surface(cap[f]) = {loop} In Sphere{1};
EndFor
Transfinite Surface{side[], face[], cap[]};
Recombine Surface{side[], face[], cap[]};

shell = newsl;  Surface Loop(shell) = {face[]};
block[0] = newv;  Volume(block[0]) = {shell};  // the cube core
For f In {0:5}
  bounding[] = {face[f], cap[f]};
  For k In {0:3}
    bounding[] += side[faceEdge[4 * f + k]];
  EndFor
  shell = newsl;  Surface Loop(shell) = bounding[];
  block[f + 1] = newv;  Volume(block[f + 1]) = {shell};
EndFor
Transfinite Volume{block[]};

Physical Volume("ball") = {block[]};
Physical Surface("surface") = {cap[]};
