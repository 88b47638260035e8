#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Kalthoff–Winkler's crack angle at two resolutions (label validation): runs
scripts/validate_kalthoff at Δx = 2.5 and 1.79 mm, GSPH and uniform layouts (the case as it is:
sharp initial cracks, softening bonds), and asserts what docs/validation.md states:

* the path fitted to the broken bonds and the damage map (particles that lost 0.3 of their
  bonds) agree within 3° on each crack (measured: 2.1° and 0.9° at 2.5 mm, 0.3° at 1.79 mm);
* the two cracks' mean angle lies within 5° of the experiment's 70°, by both measures
  (measured: path fit 66.6° and 70.8°, damage map 66.1° and 70.5°);
* GSPH and the uniform layout agree within 5 % by both measures (measured: +0.1 % and +2.3 %
  at 2.5 mm, −4.5 % and −4.3 % at 1.79 mm);
* the energy ledger closes within 0.2 % of the external work (measured −0.05 to −0.08 %).

    kalthoff_angles.py --source DIR --build DIR --out DIR
Exit status 0 when every assertion holds, 1 otherwise.
"""
import argparse
import json
import os
import subprocess
import sys

SPACINGS = "0.0025,0.00178571"
EXPERIMENT = 70.0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--source", required=True)
    ap.add_argument("--build", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    figures = os.path.join(args.out, "kalthoff.json")
    r = subprocess.run([sys.executable, os.path.join(args.source, "scripts", "validate_kalthoff"),
                        args.out, "--spacings", SPACINGS, "--build", args.build,
                        "--threads", "2", "--json", figures])
    if r.returncode != 0:
        print(f"kalthoff_angles: scripts/validate_kalthoff exited with {r.returncode}")
        return 1
    with open(figures) as f:
        runs = {(x["layout"], x["dx"]): x for x in json.load(f)}
    faults = []

    def check(ok, text):
        print(("ok    " if ok else "FAIL  ") + text)
        if not ok:
            faults.append(text)

    for dx in sorted({dx for _, dx in runs}, reverse=True):
        g, u = runs[("GSPH", dx)], runs[("uniform", dx)]
        at = f"Δx = {dx * 1e3:.3g} mm"
        for side, name in (("u", "upper"), ("l", "lower")):
            gap = abs(g["angle_" + side] - g["crack_" + side])
            check(gap <= 3.0, f"{at}, GSPH {name} crack: path fit {g['angle_' + side]:.1f}° and "
                  f"damage map {g['crack_' + side]:.1f}° within 3° ({gap:.1f}°)")
        for key, measure in (("mean", "path fit"), ("crack", "damage map")):
            off = g[key] - EXPERIMENT
            check(abs(off) <= 5.0, f"{at}, GSPH {measure} {g[key]:.1f}° within 5° of "
                  f"{EXPERIMENT:g}° ({off:+.1f}°)")
            rel = 100 * (g[key] - u[key]) / u[key]
            check(abs(rel) <= 5.0, f"{at}, {measure}: GSPH {g[key]:.1f}° and uniform "
                  f"{u[key]:.1f}° within 5 % ({rel:+.1f} %)")
        for layout, run in (("GSPH", g), ("uniform", u)):
            drift = 100 * run["drift"] / run["external"]
            check(abs(drift) <= 0.2, f"{at}, {layout}: energy drift {drift:+.3f} % of the "
                  "external work within 0.2 %")
    print(f"kalthoff_angles: {len(faults)} of the assertions failed" if faults
          else "kalthoff_angles: every assertion holds")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
