// Thick hollow spherical shell: the six shell blocks of a cubed sphere (sphere.geo) without its
// core, each between a sixth of the inner sphere and the sixth of the outer sphere above it.
// Both surfaces are spherical; every cell is close to a cube, with no coordinate singularity.
//
//   gsph-preproc spherical_shell.geo -o shell.h5
//   gsph-preproc spherical_shell.geo -o shell.h5 --set refine=2
//
// The blocks meet three at an edge (along the radial edges above the cube's corners), so they
// cannot all glue into one generalized space: gsph-preproc glues four of them into a ring
// periodic around an axis, the two others (the caps on that axis) are spaces of their own, and
// couples the spaces by the overset method (docs/formats.md). Every parameter can be
// overridden with `gmsh -setnumber NAME VALUE` or `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "shell". Sets: "inner" (r = Ri), "outer" (r = Ro).

DefineConstant[
  Ri = {3e-3, Name "Parameters/Ri"},      // inner radius [m]
  Ro = {5e-3, Name "Parameters/Ro"},      // outer radius [m]
  n = {8, Name "Parameters/n"},           // cells along an edge of a sixth
  nr = {4, Name "Parameters/nr"},         // cells through the wall
  refine = {1, Name "Parameters/refine"}  // multiplies every cell count (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (Ri <= 0 || Ro <= Ri || n < 1 || nr < 1 || refine < 1)
  Error("spherical_shell.geo: needs 0 < Ri < Ro, n, nr, refine >= 1 (got Ri = %g, Ro = %g, n = %g, nr = %g, refine = %g)", Ri, Ro, n, nr, refine);
EndIf
si = Ri / Sqrt(3);  // the spheres' points on the cube's diagonals
so = Ro / Sqrt(3);

Point(1) = {0, 0, 0};  // centre of the great circles
For i In {0:7}  // corner i at (±, ±, ±) with the x, y, z signs from the bits of i
  sx = 2 * (i % 2) - 1;  sy = 2 * (Floor(i / 2) % 2) - 1;  sz = 2 * Floor(i / 4) - 1;
  inner[i] = newp;  Point(inner[i]) = {sx * si, sy * si, sz * si};
  outer[i] = newp;  Point(outer[i]) = {sx * so, sy * so, sz * so};
EndFor
// The 12 edges of a cube as corner pairs: 4 along x, 4 along y, 4 along z.
from[] = {0, 2, 4, 6,  0, 1, 4, 5,  0, 1, 2, 3};
to[] = {1, 3, 5, 7,  2, 3, 6, 7,  4, 5, 6, 7};
For e In {0:11}  // great-circle arcs on both spheres
  innerArc[e] = newl;  Circle(innerArc[e]) = {inner[from[e]], 1, inner[to[e]]};
  outerArc[e] = newl;  Circle(outerArc[e]) = {outer[from[e]], 1, outer[to[e]]};
EndFor
For i In {0:7}
  spoke[i] = newl;  Line(spoke[i]) = {inner[i], outer[i]};
EndFor
Transfinite Curve{innerArc[], outerArc[]} = n * refine + 1;
Transfinite Curve{spoke[]} = nr * refine + 1;

// Between the two arcs of an edge: the side shared by two shell blocks.
For e In {0:11}
  loop = newll;  Curve Loop(loop) = {innerArc[e], spoke[to[e]], -outerArc[e], -spoke[from[e]]};
  side[e] = news;  Surface(side[e]) = {loop};
EndFor
// The six sixths (-x, +x, -y, +y, -z, +z) as four edges each, walked round with their signs.
faceEdge[] = {4, 10, 6, 8,  5, 11, 7, 9,  0, 9, 2, 8,  1, 11, 3, 10,  0, 5, 1, 4,  2, 7, 3, 6};
For f In {0:5}
  innerLoop[] = {};  outerLoop[] = {};
  For k In {0:3}
    sign = (k < 2) ? 1 : -1;
    innerLoop[] += sign * innerArc[faceEdge[4 * f + k]];
    outerLoop[] += sign * outerArc[faceEdge[4 * f + k]];
  EndFor
  loop = newll;  Curve Loop(loop) = innerLoop[];  innerCap[f] = news;  Surface(innerCap[f]) = {loop} In Sphere{1};
  loop = newll;  Curve Loop(loop) = outerLoop[];  outerCap[f] = news;  Surface(outerCap[f]) = {loop} In Sphere{1};
EndFor
Transfinite Surface{side[], innerCap[], outerCap[]};
Recombine Surface{side[], innerCap[], outerCap[]};

For f In {0:5}
  bounding[] = {innerCap[f], outerCap[f]};
  For k In {0:3}
    bounding[] += side[faceEdge[4 * f + k]];
  EndFor
  shell = newsl;  Surface Loop(shell) = bounding[];
  block[f] = newv;  Volume(block[f]) = {shell};
EndFor
Transfinite Volume{block[]};

Physical Volume("shell") = {block[]};
Physical Surface("inner") = {innerCap[]};
Physical Surface("outer") = {outerCap[]};
