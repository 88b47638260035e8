// The O-grid cross-section of geometries/taylor_bar.geo in 2-D: a square Cartesian core and
// four annulus blocks (one space, periodic in its angular index) around it, abutting along
// the core's sides: an overset body of two spaces in the plane. Body: "disc"; sets: "rim",
// and an unnamed group (tag 77) on one quarter of it.
R = 3.8e-3;  // radius [m]
c = 0.4 * R;
s = R / Sqrt(2);
n = 8;
nr = 4;
Point(1) = {0, 0, 0};
core_[] = {newp, newp + 1, newp + 2, newp + 3};
Point(core_[0]) = {c, -c, 0};  Point(core_[1]) = {c, c, 0};
Point(core_[2]) = {-c, c, 0};  Point(core_[3]) = {-c, -c, 0};
rim[] = {newp, newp + 1, newp + 2, newp + 3};
Point(rim[0]) = {s, -s, 0};  Point(rim[1]) = {s, s, 0};
Point(rim[2]) = {-s, s, 0};  Point(rim[3]) = {-s, -s, 0};
For k In {0:3}
  side[k] = newl;   Line(side[k]) = {core_[k], core_[(k + 1) % 4]};
  spoke[k] = newl;  Line(spoke[k]) = {core_[k], rim[k]};
  arc[k] = newl;    Circle(arc[k]) = {rim[k], 1, rim[(k + 1) % 4]};
EndFor
Transfinite Curve{side[], arc[]} = n + 1;
Transfinite Curve{spoke[]} = nr + 1;
loop = newll; Curve Loop(loop) = {side[]};
section[0] = news; Plane Surface(section[0]) = {loop};
For k In {0:3}
  loop = newll; Curve Loop(loop) = {spoke[k], arc[k], -spoke[(k + 1) % 4], -side[k]};
  section[k + 1] = news; Plane Surface(section[k + 1]) = {loop};
EndFor
Transfinite Surface{section[]};
Recombine Surface{section[]};
Physical Surface("disc") = {section[]};
Physical Curve("rim") = {arc[]};
Physical Curve(77) = {arc[0]};
