// Taylor bar: a full cylinder meshed as an O-grid (a square Cartesian core + 4 annulus blocks).
//
//   gmsh -3 taylor_bar.geo                          -> taylor_bar.msh
//   gsph-preproc taylor_bar.geo -o taylor.h5        (meshes in-process)
//   gsph-preproc taylor_bar.geo -o taylor.h5 --set refine=2
//
// Copper rod of the Taylor impact test: length 25.4 mm, diameter 7.6 mm, axis along z, impact
// face at z = 0. The square core [-c, c]² covers the axis (no coordinate singularity); four
// annulus blocks run from the core's sides to the outer surface. The annulus blocks glue into
// one generalized space, periodic in its angular index; the core is a space of its own (its
// indices cannot glue consistently to the annulus's radial/angular ones), coupled to the
// annulus by the overset method. Cells are graded along z, finest at the impact face; `lip`
// grades them radially towards the surface, `centre` across the core towards the axis (the
// impact zone's resolution at ≤ 10k particles: --set n=12 --set nr=3 --set nz=34
// --set grading=1.08 --set centre=10 --set lip=0.7, docs/validation.md).
// Every parameter can be overridden with `gmsh -setnumber NAME VALUE` or
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Body: Physical Volume "rod". Sets: "impact" (z = 0), "free_end" (z = L), "lateral" (r = R).

DefineConstant[
  R = {3.8e-3, Name "Parameters/R"},          // radius [m]
  L = {25.4e-3, Name "Parameters/L"},         // length [m]
  core = {0.4, Name "Parameters/core"},       // core half-side c as a fraction of R
  n = {8, Name "Parameters/n"},               // cells along a core side = per quarter of arc
  nr = {4, Name "Parameters/nr"},             // cells from the core to the outer surface
  nz = {40, Name "Parameters/nz"},            // cells along the axis
  grading = {1.03, Name "Parameters/grading"},  // ratio of successive cell lengths from z = 0
  lip = {1, Name "Parameters/lip"},           // ratio of successive radial cells from the core
                                              // to the surface (below 1: finer at the lip)
  centre = {1, Name "Parameters/centre"},     // gmsh Bump on the core's sides: above 1, cells
                                              // finer at the axis (10: about 6 times finer
                                              // there than at the core's corners)
  refine = {1, Name "Parameters/refine"}      // multiplies every cell count (convergence studies)
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (R <= 0 || L <= 0 || core <= 0 || grading <= 0 || lip <= 0 || centre <= 0 || n < 1 || nr < 1 || nz < 1 || refine < 1)
  Error("taylor_bar.geo: needs R, L, core, grading, lip, centre > 0; n, nr, nz, refine ≥ 1 (got R = %g, L = %g, core = %g, grading = %g, lip = %g, centre = %g, n = %g, nr = %g, nz = %g, refine = %g)", R, L, core, grading, lip, centre, n, nr, nz, refine);
EndIf
c = core * R;
s = R / Sqrt(2);

Point(1) = {0, 0, 0};  // centre of the arcs
core_[] = {newp, newp + 1, newp + 2, newp + 3};
Point(core_[0]) = {c, -c, 0};  Point(core_[1]) = {c, c, 0};
Point(core_[2]) = {-c, c, 0};  Point(core_[3]) = {-c, -c, 0};
rim[] = {newp, newp + 1, newp + 2, newp + 3};
Point(rim[0]) = {s, -s, 0};  Point(rim[1]) = {s, s, 0};
Point(rim[2]) = {-s, s, 0};  Point(rim[3]) = {-s, -s, 0};

For k In {0:3}
  side[k] = newl;   Line(side[k]) = {core_[k], core_[(k + 1) % 4]};   // core square
  spoke[k] = newl;  Line(spoke[k]) = {core_[k], rim[k]};             // core corner -> rim
  arc[k] = newl;    Circle(arc[k]) = {rim[k], 1, rim[(k + 1) % 4]};  // a quarter of the rim
EndFor
If (centre == 1)
  Transfinite Curve{side[], arc[]} = n * refine + 1;
Else
  Transfinite Curve{side[]} = n * refine + 1 Using Bump centre;
  Transfinite Curve{arc[]} = n * refine + 1;
EndIf
If (lip == 1)
  Transfinite Curve{spoke[]} = nr * refine + 1;
Else
  Transfinite Curve{spoke[]} = nr * refine + 1 Using Progression lip^(1 / refine);
EndIf

loop = newll; Curve Loop(loop) = {side[]};
section[0] = news; Plane Surface(section[0]) = {loop};  // core
For k In {0:3}  // annulus block k: between core side k and arc k
  loop = newll; Curve Loop(loop) = {spoke[k], arc[k], -spoke[(k + 1) % 4], -side[k]};
  section[k + 1] = news; Plane Surface(section[k + 1]) = {loop};
EndFor
Transfinite Surface{section[]};
Recombine Surface{section[]};

// Structured along z: graded layers, cumulative heights of a geometric progression.
layers = nz * refine;
ratio = grading^(1 / refine);
For m In {1:layers}
  one[m - 1] = 1;
  If (ratio == 1)  // (gmsh evaluates both branches of ?:, so 0/0 would stop it)
    height[m - 1] = m / layers;
  Else
    height[m - 1] = (ratio^m - 1) / (ratio^layers - 1);
  EndIf
EndFor
Extrude {0, 0, L} { Surface{section[]}; Layers{one[], height[]}; Recombine; }

e = 1e-6 * R;  // tolerance of the bounding boxes below
Physical Volume("rod") = Volume{:};
Physical Surface("impact") = Surface In BoundingBox{-R - e, -R - e, -e, R + e, R + e, e};
Physical Surface("free_end") = Surface In BoundingBox{-R - e, -R - e, L - e, R + e, R + e, L + e};
// The outer surface: the lateral surfaces that reach |x| = R or |y| = R (spokes stop at R/√2).
Physical Surface("lateral") = {};
all[] = Surface{:};
For k In {0:#all[] - 1}
  bb[] = BoundingBox Surface{all[k]};  // {xmin, ymin, zmin, xmax, ymax, zmax}
  If (bb[5] - bb[2] > L - e && (bb[3] > 0.9 * R || bb[4] > 0.9 * R || bb[0] < -0.9 * R || bb[1] < -0.9 * R))
    Physical Surface("lateral") += {all[k]};
  EndIf
EndFor
