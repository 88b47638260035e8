// Two Cartesian blocks of spacings 2:1 side by side along x: an overset interface (DESIGN §6).
//
//   gsph-preproc two_blocks.geo -o blocks.h5                          (abutting, 3-D)
//   gsph-preproc two_blocks.geo -o blocks.h5 --set overlap=2          (fine block overlaps 2 cells)
//   gsph-preproc two_blocks.geo -o blocks.h5 --set plane=1            (one layer: plane strain)
//   gsph-preproc two_blocks.geo -o blocks.h5 --set overlap=2 --priority 1=1   (coarse keeps)
//
// A coarse block [0, Lc] x [0, W] x [0, T] with cells of side h, and a fine block with cells of
// side h/2 from x = Lc - overlap*h to x = Lc - overlap*h + Lf. The blocks share no nodes (their
// sides do not match node for node), so each is a generalized space of its own: space 0 the
// coarse block (gmsh volume 1), space 1 the fine one (volume 2). With overlap > 0 the fine block (finer, so it outranks
// the coarse one by default) keeps its particles and the coarse particles whose centres lie
// inside it are cut; an integer overlap is aligned with the coarse cells, and the kept volume
// is then exactly the union's. With plane = 1 both blocks are one layer of thickness T = h
// (the 2-D, plane-strain layout); otherwise T = W and the fine block has twice the layers.
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "plate". Sets: "left" (x = 0), "right" (the fine block's far end).

DefineConstant[
  h = {1e-3, Name "Parameters/h"},              // coarse cell side [m]; the fine side is h/2
  Lc = {8e-3, Name "Parameters/Lc"},            // coarse block length [m] (a multiple of h)
  Lf = {8e-3, Name "Parameters/Lf"},            // fine block length [m] (a multiple of h/2)
  W = {4e-3, Name "Parameters/W"},              // width along y [m] (a multiple of h)
  overlap = {0, Name "Parameters/overlap"},     // overlap of the blocks, in coarse cells
  plane = {0, Name "Parameters/plane"},         // 1: one layer thick (2-D); 0: 3-D
  refine = {1, Name "Parameters/refine"}        // multiplies every cell count
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (h <= 0)
  Error("two_blocks.geo: needs h > 0 (got h = %g)", h);
EndIf
// The blocks touch or overlap without sharing points: keep gmsh from merging the coincident
// points of their sides (which would make a non-conforming face it cannot mesh).
Geometry.AutoCoherence = 0;

T = plane ? h : W;
x0 = Lc - overlap * h;  // where the fine block starts

// Volume `tag`: a structured block [xa, xb] x [0, W] x [0, T] with cells of side d (layers:
// T / d, or 1 with plane = 1),
// built entity by entity (an extrusion would rely on the point merging switched off above).
Macro StructuredBlock
  p = newp;
  For c In {0:7}  // corner c = (bit 0: x, bit 1: y, bit 2: z)
    Point(p + c) = {(c & 1) ? xb : xa, (c & 2) ? W : 0, (c & 4) ? T : 0};
  EndFor
  l = newl;
  For c In {0:7}  // the edges from corner c along each axis it can go up
    If (!(c & 1))
      Line(l + c) = {p + c, p + c + 1};  // along x
    EndIf
    If (!(c & 2))
      Line(l + 8 + c) = {p + c, p + c + 2};  // along y
    EndIf
    If (!(c & 4))
      Line(l + 16 + c) = {p + c, p + c + 4};  // along z
    EndIf
  EndFor
  Transfinite Curve{l + 0, l + 2, l + 4, l + 6} = Round((xb - xa) / d) * refine + 1;
  Transfinite Curve{l + 8, l + 9, l + 12, l + 13} = Round(W / d) * refine + 1;
  Transfinite Curve{l + 16, l + 17, l + 18, l + 19} = (plane ? 1 : Round(T / d) * refine) + 1;
  ll = newll;  s = news;
  Curve Loop(ll) = {l + 0, l + 9, -(l + 2), -(l + 8)};  Plane Surface(s) = {ll};          // z = 0
  Curve Loop(ll + 1) = {l + 4, l + 13, -(l + 6), -(l + 12)};  Plane Surface(s + 1) = {ll + 1};  // z = T
  Curve Loop(ll + 2) = {l + 0, l + 17, -(l + 4), -(l + 16)};  Plane Surface(s + 2) = {ll + 2};  // y = 0
  Curve Loop(ll + 3) = {l + 2, l + 19, -(l + 6), -(l + 18)};  Plane Surface(s + 3) = {ll + 3};  // y = W
  Curve Loop(ll + 4) = {l + 8, l + 18, -(l + 12), -(l + 16)};  Plane Surface(s + 4) = {ll + 4};  // x = xa
  Curve Loop(ll + 5) = {l + 9, l + 19, -(l + 13), -(l + 17)};  Plane Surface(s + 5) = {ll + 5};  // x = xb
  Transfinite Surface{s:s + 5};
  Recombine Surface{s:s + 5};
  sl = newsl;  Surface Loop(sl) = {s:s + 5};
  Volume(tag) = {sl};
  Transfinite Volume{tag};
Return

tag = 1;  xa = 0;  xb = Lc;  d = h;  Call StructuredBlock;            // coarse
tag = 2;  xa = x0;  xb = x0 + Lf;  d = h / 2;  Call StructuredBlock;  // fine

e = 1e-6 * h;  // tolerance of the bounding boxes below
Physical Volume("plate") = Volume{:};
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, W + e, T + e};
Physical Surface("right") = Surface In BoundingBox{x0 + Lf - e, -e, -e, x0 + Lf + e, W + e, T + e};
