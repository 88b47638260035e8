// Ductile plate perforation: a circular Weldox 460E plate, clamped at its rim, struck
// at its centre by a blunt hardened-steel cylinder (Børvik et al. 1999: 12 mm plate, 20 mm ×
// 80 mm projectile of 197 g).
//
//   gsph-preproc plate_perforation.geo -o perforation.h5        (GSPH, shear-zone layout: the default)
//   gsph-preproc plate_perforation.geo -o plain.h5 --set hs=0   (GSPH, plain ring of cells h)
//   gsph-preproc plate_perforation.geo -o uniform.h5 --set hs=0 --lattice 2e-3  (uniform, same h)
//
// Plate: z in [-Tp, 0], axis z, radius R (the clamped rim; the experiment's frame: r = 250 mm;
// a smaller R keeps the run cheap, docs/theory.md "Plate perforation"). It is an O-grid:
//   * a square Cartesian core [-c, c]² (fine cells, ≈ h),
//   * ring 1 from the core's sides to the circle r1 (fine radial cells; the projectile's edge,
//     r = Rp, lies inside it, so the plug's shear zone is in one space, away from the core's
//     overset band),
//   * ring 2 from r1 to the rim R, radial cells growing by `grading` outward.
// With hs < h (the shear-zone layout) ring 1 is split at the circle r = Rp, where the plug
// shears off: its radial cells shrink by `sgrading` per cell from the core towards Rp, to hs
// at Rp, and grow again by `sgrading` outward until they reach h (r1 then follows from hs, h
// and sgrading). The angular cells at Rp stay ≈ h and the core shrinks to 0.3 Rp (its corners
// well inside Rp, so the ring's radial lines are nearly as long on the diagonals as on the
// axes); the plate's smallest cells are then hs, radially, in the band where it fails.
// The rings glue into one generalized space, periodic in the angle; the core is a space of its
// own, coupled to the rings by the overset method. Through the thickness ntp uniform layers.
// Projectile: an O-grid like taylor_bar.geo (core + annulus), nose at z = gap, cells about the
// plate's at the nose and growing along the axis.
// Body 0 is the plate, body 1 the projectile. Every parameter can be overridden with
// `gsph-preproc --set NAME=VALUE`. Units: SI (m).
// Bodies: Physical Volumes "plate" and "projectile". Sets: "plate_rim" (the plate's cylindrical
// outer face, to clamp), "nose" (the projectile's flat face).

DefineConstant[
  R = {0.05, Name "Parameters/R"},            // plate radius: the clamped rim [m]
  Tp = {0.012, Name "Parameters/Tp"},         // plate thickness [m]
  h = {0.002, Name "Parameters/h"},           // fine cell size of the plate [m]
  hs = {0.00067, Name "Parameters/hs"},       // radial cell at r = Rp [m]; 0 (or ≥ h): h
  sgrading = {1.15, Name "Parameters/sgrading"},  // radial cell ratio towards hs at Rp
  c = {0.006, Name "Parameters/c"},           // half-side of the plate's core square [m]
  r1 = {0.014, Name "Parameters/r1"},         // outer radius of the fine ring [m] (hs = 0)
  grading = {1.1, Name "Parameters/grading"}, // ratio of successive radial cells in ring 2
  Rp = {0.01, Name "Parameters/Rp"},          // projectile radius [m]
  Lp = {0.08, Name "Parameters/Lp"},          // projectile length [m]
  gap = {0.0005, Name "Parameters/gap"},      // distance from the plate to the nose [m]
  pcore = {0.4, Name "Parameters/pcore"},     // projectile core half-side / Rp
  pgrading = {1.08, Name "Parameters/pgrading"}  // ratio of successive axial cells from the nose
];
// Parameter ranges: a clear error (gsph-preproc reports it) instead of a degenerate mesh
// or a crash inside gmsh.
If (R <= 0 || Tp <= 0 || h <= 0 || hs < 0)
  Error("plate_perforation.geo: needs R, Tp, h > 0; hs ≥ 0 (got R = %g, Tp = %g, h = %g, hs = %g)", R, Tp, h, hs);
EndIf

// Cell counts of the plate from the fine size h (and hs).
shear = (hs > 0 && hs < h);
ntp = Ceil(Tp / h - 0.5);                // through the thickness
If (shear)
  cs = 0.3 * Rp;                          // core half-side
  n = Ceil(Pi * Rp / (2 * h) - 0.5);      // angular cells per quarter: ≈ h at Rp
  La = Rp - cs * Sqrt(2);                 // ring 1a along its diagonals (its shortest lines)
  nra = Ceil(Log(1 + La * (sgrading - 1) / hs) / Log(sgrading) - 0.5);
  nrb = Ceil(Log(h / hs) / Log(sgrading));  // ring 1b: from hs up to ≈ h
  rf = Rp + hs * (sgrading^nrb - 1) / (sgrading - 1);  // its outer radius
  first = hs * sgrading^nrb;              // ring 2 goes on from ring 1b's grading
Else
  cs = c;
  n = Ceil(2 * c / h - 0.5);              // core cells per side (= per quarter of arc)
  nr1 = Ceil((r1 - c) / h - 0.5);         // ring 1, radial (along the axes; shorter on diagonals)
  rf = r1;
  first = 2 * Pi * r1 / (4 * n);          // ring 2's first radial cell ≈ the angular cell at r1
EndIf
nr2 = Ceil(Log(1 + (R - rf) * (grading - 1) / first) / Log(grading) - 0.5);
If (nr2 < 1)
  nr2 = 1;
EndIf
// Projectile: cells of about h at its nose (core, radial, first axial layer), the axial ones
// growing by pgrading towards its back.
pn = Ceil(2 * pcore * Rp / h - 0.5);     // per core side (per quarter of arc)
pnr = Ceil((1 - pcore) * Rp / h - 0.5);  // from the core to the surface
pnz = Ceil(Log(1 + Lp * (pgrading - 1) / h) / Log(pgrading) - 0.5);  // along the axis

// --- Plate section at z = -Tp -----------------------------------------------------------------
z0 = -Tp;
centre = newp;  Point(centre) = {0, 0, z0};
sq[] = {newp, newp + 1, newp + 2, newp + 3};
Point(sq[0]) = {cs, -cs, z0};  Point(sq[1]) = {cs, cs, z0};
Point(sq[2]) = {-cs, cs, z0};  Point(sq[3]) = {-cs, -cs, z0};
s1 = rf / Sqrt(2);
ra[] = {newp, newp + 1, newp + 2, newp + 3};
Point(ra[0]) = {s1, -s1, z0};  Point(ra[1]) = {s1, s1, z0};
Point(ra[2]) = {-s1, s1, z0};  Point(ra[3]) = {-s1, -s1, z0};
s2 = R / Sqrt(2);
rb[] = {newp, newp + 1, newp + 2, newp + 3};
Point(rb[0]) = {s2, -s2, z0};  Point(rb[1]) = {s2, s2, z0};
Point(rb[2]) = {-s2, s2, z0};  Point(rb[3]) = {-s2, -s2, z0};
If (shear)
  sm = Rp / Sqrt(2);
  rm[] = {newp, newp + 1, newp + 2, newp + 3};
  Point(rm[0]) = {sm, -sm, z0};  Point(rm[1]) = {sm, sm, z0};
  Point(rm[2]) = {-sm, sm, z0};  Point(rm[3]) = {-sm, -sm, z0};
EndIf
For k In {0:3}
  side[k] = newl;    Line(side[k]) = {sq[k], sq[(k + 1) % 4]};
  If (shear)
    spokea[k] = newl;  Line(spokea[k]) = {sq[k], rm[k]};
    spokeb[k] = newl;  Line(spokeb[k]) = {rm[k], ra[k]};
    arcm[k] = newl;    Circle(arcm[k]) = {rm[k], centre, rm[(k + 1) % 4]};
  Else
    spoke1[k] = newl;  Line(spoke1[k]) = {sq[k], ra[k]};
  EndIf
  arc1[k] = newl;    Circle(arc1[k]) = {ra[k], centre, ra[(k + 1) % 4]};
  spoke2[k] = newl;  Line(spoke2[k]) = {ra[k], rb[k]};
  arc2[k] = newl;    Circle(arc2[k]) = {rb[k], centre, rb[(k + 1) % 4]};
EndFor
Transfinite Curve{side[], arc1[], arc2[]} = n + 1;
If (shear)
  Transfinite Curve{arcm[]} = n + 1;
  Transfinite Curve{spokea[]} = nra + 1 Using Progression 1 / sgrading;  // finest at Rp
  Transfinite Curve{spokeb[]} = nrb + 1 Using Progression sgrading;
Else
  Transfinite Curve{spoke1[]} = nr1 + 1;
EndIf
Transfinite Curve{spoke2[]} = nr2 + 1 Using Progression grading;
loop = newll;  Curve Loop(loop) = {side[]};
sec[] = {news};  Plane Surface(sec[0]) = {loop};
For k In {0:3}  // ring 1 (1a and 1b with hs < h)
  If (shear)
    loop = newll;  Curve Loop(loop) = {spokea[k], arcm[k], -spokea[(k + 1) % 4], -side[k]};
    sec[] += {news};  Plane Surface(sec[#sec[] - 1]) = {loop};
    loop = newll;  Curve Loop(loop) = {spokeb[k], arc1[k], -spokeb[(k + 1) % 4], -arcm[k]};
    sec[] += {news};  Plane Surface(sec[#sec[] - 1]) = {loop};
  Else
    loop = newll;  Curve Loop(loop) = {spoke1[k], arc1[k], -spoke1[(k + 1) % 4], -side[k]};
    sec[] += {news};  Plane Surface(sec[#sec[] - 1]) = {loop};
  EndIf
EndFor
For k In {0:3}  // ring 2
  loop = newll;  Curve Loop(loop) = {spoke2[k], arc2[k], -spoke2[(k + 1) % 4], -arc1[k]};
  sec[] += {news};  Plane Surface(sec[#sec[] - 1]) = {loop};
EndFor
Transfinite Surface{sec[]};
Recombine Surface{sec[]};
plate[] = Extrude {0, 0, Tp} { Surface{sec[]}; Layers{ntp}; Recombine; };

// --- Projectile: O-grid section at z = gap, extruded along the axis ----------------------------
pc = pcore * Rp;
ps = Rp / Sqrt(2);
pcentre = newp;  Point(pcentre) = {0, 0, gap};
pq[] = {newp, newp + 1, newp + 2, newp + 3};
Point(pq[0]) = {pc, -pc, gap};  Point(pq[1]) = {pc, pc, gap};
Point(pq[2]) = {-pc, pc, gap};  Point(pq[3]) = {-pc, -pc, gap};
pr[] = {newp, newp + 1, newp + 2, newp + 3};
Point(pr[0]) = {ps, -ps, gap};  Point(pr[1]) = {ps, ps, gap};
Point(pr[2]) = {-ps, ps, gap};  Point(pr[3]) = {-ps, -ps, gap};
For k In {0:3}
  pside[k] = newl;   Line(pside[k]) = {pq[k], pq[(k + 1) % 4]};
  pspoke[k] = newl;  Line(pspoke[k]) = {pq[k], pr[k]};
  parc[k] = newl;    Circle(parc[k]) = {pr[k], pcentre, pr[(k + 1) % 4]};
EndFor
Transfinite Curve{pside[], parc[]} = pn + 1;
Transfinite Curve{pspoke[]} = pnr + 1;
loop = newll;  Curve Loop(loop) = {pside[]};
psec[0] = news;  Plane Surface(psec[0]) = {loop};
For k In {0:3}
  loop = newll;  Curve Loop(loop) = {pspoke[k], parc[k], -pspoke[(k + 1) % 4], -pside[k]};
  psec[k + 1] = news;  Plane Surface(psec[k + 1]) = {loop};
EndFor
Transfinite Surface{psec[]};
Recombine Surface{psec[]};
// Axial layers graded from the nose (cumulative heights of a geometric progression): at the
// nose the projectile's cells are about the plate's, so the contact pushes the plate's face
// evenly (a coarse nose hammers the face particle by particle).
For m In {1:pnz}
  one[m - 1] = 1;
  If (pgrading == 1)  // (gmsh evaluates both branches of ?:, so 0/0 would stop it)
    height[m - 1] = m / pnz;
  Else
    height[m - 1] = (pgrading^m - 1) / (pgrading^pnz - 1);
  EndIf
EndFor
Extrude {0, 0, Lp} { Surface{psec[]}; Layers{one[], height[]}; Recombine; }

e = 1e-6 * R;  // tolerance of the bounding boxes below
Physical Volume("plate") = Volume In BoundingBox{-R - e, -R - e, -Tp - e, R + e, R + e, e};
Physical Volume("projectile") = Volume In BoundingBox{-Rp - e, -Rp - e, gap - e, Rp + e, Rp + e, gap + Lp + e};
Physical Surface("nose") = Surface In BoundingBox{-Rp - e, -Rp - e, gap - e, Rp + e, Rp + e, gap + e};
// The rim: the plate's lateral surfaces that reach |x| = R or |y| = R (spokes stop at R/√2).
Physical Surface("plate_rim") = {};
all[] = Surface In BoundingBox{-R - e, -R - e, -Tp - e, R + e, R + e, e};
For k In {0:#all[] - 1}
  bb[] = BoundingBox Surface{all[k]};  // {xmin, ymin, zmin, xmax, ymax, zmax}
  If (bb[5] - bb[2] > Tp - e && (bb[3] > 0.9 * R || bb[4] > 0.9 * R || bb[0] < -0.9 * R || bb[1] < -0.9 * R))
    Physical Surface("plate_rim") += {all[k]};
  EndIf
EndFor
