#!/usr/bin/env python3
"""A run split over MPI processes gives the serial run's state, bit for bit.

    split_runs.py --mpi-solve BUILD-MPI/solver/gsph-solve --preproc .../gsph-preproc
                  --serial-solve BUILD/solver/gsph-solve --source SOURCE_DIR --out DIR

The Taylor bar on the quick start's coarse O-grid without its lip grading (overset band, rigid
wall, Johnson-Cook) to its end time (80 us): with the serial gsph-solve on 2 threads, then with `mpirun -np N` for
N = 2, 3, 4 (oversubscribed on a small machine, one thread each; one process under mpirun is
the restart below). Asserts
  - every snapshot: every dataset byte for byte equal to the serial run's;
  - the final checkpoint byte for byte in every dataset: the state arrays and the energy
    ledger's scalars (exactly rounded sums over the processes);
  - history.csv byte for byte: the columns the state gives (time, step, kinetic and elastic
    energy, ...), the ledger's and the walls' forces;
  - probes.csv byte for byte (probes on the first and the last particle, and at the impact
    face's centre: each read where its particle is owned);
  - contact between bodies: the plate-and-projectile sample on 3 processes, its final snapshot
    and its history (contact forces between the bodies included) byte for byte the serial run's;
  - bonds that break across the cuts: Kalthoff-Winkler at its coarsest spacing (h = 2.5 mm;
    initial cracks, bonds broken by stretch, softening bonds) to its end time (90 us), and the
    plate perforation at 300 m/s (failed particles cutting the bonds through their cells,
    detached particles, contact between the plug and the projectile; the plate's damage
    nonlocal, its average over the particles within the material length a halo of its own) to
    24 us, on 2, 3 and 4 processes: every snapshot and the checkpoint's state as above, the
    run.log's bond count equal, and some damage driver accumulated; the perforation with
    self-contact on 3 processes likewise;
  - restarts across process counts: Kalthoff-Winkler stopped on 4 processes and continued on
    2, stopped on 3 and continued on 1: the final snapshot byte for byte the straight run's;
  - a local damage (the perforation's plate without its material length) to 10 us on 2 and 3
    processes: as above.
Exit status 0 when all hold, 1 otherwise.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import time

import h5py
import numpy as np


START = time.monotonic()


def elapsed():
    return f"{time.monotonic() - START:.0f} s"


def run(cmd, log):
    with open(log, "w") as out:
        code = subprocess.call(cmd, stdout=out, stderr=subprocess.STDOUT)
    return code


def mpirun(n, args):
    return ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
            "-x", "OMP_NUM_THREADS=1", "-np", str(n)] + args


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                out[name] = obj[()]
        f.visititems(visit)
    return out


def compare_files(a, b):
    """Differences between two HDF5 files' datasets, byte for byte."""
    da, db = datasets(a), datasets(b)
    faults = []
    for name in sorted(set(da) | set(db)):
        if name not in da or name not in db:
            faults.append(f"{name}: only in one file")
            continue
        x, y = np.asarray(da[name]), np.asarray(db[name])
        if name.startswith("run/texts/history") or name.startswith("provenance"):
            continue  # the history text is checked as history.csv
        if x.dtype.kind == "O":  # strings
            if x.tolist() != y.tolist():
                faults.append(f"{name}: differs")
        elif x.shape != y.shape or x.dtype != y.dtype or x.tobytes() != y.tobytes():
            faults.append(f"{name}: differs")
    return faults


def history(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(v) for v in r] for r in rows[1:]])


def compare_history(a, b):
    """history.csv byte for byte; on a difference, the columns that differ and by how much."""
    with open(a, "rb") as fa, open(b, "rb") as fb:
        if fa.read() == fb.read():
            return []
    ha, va = history(a)
    hb, vb = history(b)
    if ha != hb or va.shape != vb.shape:
        return [f"{b}: columns or rows differ"]
    return [f"{b}: column {name} differs by up to {np.max(np.abs(va[:, k] - vb[:, k])):.3e}"
            for k, name in enumerate(ha) if not np.array_equal(va[:, k], vb[:, k])] or \
        [f"{b}: differs in its text"]


def bond_line(folder):
    with open(os.path.join(folder, "run.log")) as f:
        return [line for line in f if line.startswith("bonds:")]


def split_like_serial(a, name, case, args, env, bonds=False, counts=(2, 3, 4)):
    """Runs `case` with the serial gsph-solve and on `counts` processes: the faults and the
    serial run's folder (None when it failed). `bonds`: run.log's bond count must match too."""
    serial = os.path.join(a.out, f"{name}_serial")
    with open(serial + ".log", "w") as out:
        if subprocess.call([a.serial_solve, case, "-o", serial, "--overwrite"] + args, stdout=out,
                           stderr=subprocess.STDOUT, env=env) != 0:
            return [f"{name}: the serial run failed ({serial}.log)"], None
    snapshots = sorted(f for f in os.listdir(serial) if f.startswith("snapshot_"))
    faults = []
    for n in counts:
        folder = os.path.join(a.out, f"{name}_np{n}")
        if run(mpirun(n, [a.mpi_solve, case, "-o", folder, "--overwrite"] + args),
               folder + ".log") != 0:
            faults.append(f"{name} on {n} processes: the run failed ({folder}.log)")
            continue
        for s in snapshots:
            faults += [f"{name} on {n} processes, {s}: {x}"
                       for x in compare_files(os.path.join(serial, s), os.path.join(folder, s))]
        if os.path.exists(os.path.join(serial, "checkpoint.h5")):
            faults += [f"{name} on {n} processes, checkpoint.h5: {x}"
                       for x in compare_files(os.path.join(serial, "checkpoint.h5"),
                                              os.path.join(folder, "checkpoint.h5"))]
        faults += compare_history(os.path.join(serial, "history.csv"),
                                  os.path.join(folder, "history.csv"))
        if os.path.exists(os.path.join(serial, "probes.csv")):
            faults += compare_history(os.path.join(serial, "probes.csv"),
                                      os.path.join(folder, "probes.csv"))
        said = ""
        if bonds:
            if bond_line(folder) != bond_line(serial) or not bond_line(serial):
                faults.append(f"{name} on {n} processes: run.log's bond count differs")
            said = "; " + "".join(bond_line(serial)).strip()
        print(f"{name} on {n} processes: {len(snapshots)} snapshots compared{said}"
              f" ({elapsed()})")
    return faults, serial

def restart_across(a, name, case, particles, serial, first, then, stop):
    """Stopped on `first` processes after step `stop`, continued on `then`: the final snapshot
    byte for byte the serial run's (in folder `serial`). The faults."""
    folder = os.path.join(a.out, f"{name}_restart_{first}_{then}")
    if run(mpirun(first, [a.mpi_solve, case, "--particles", particles, "-o", folder,
                          "--overwrite", "--stop-after-steps", str(stop)]),
           folder + ".first.log") != 3:
        return [f"{name} restart {first} -> {then}: the first part did not stop with a checkpoint"]
    if run(mpirun(then, [a.mpi_solve, case, "--particles", particles, "--restart",
                         os.path.join(folder, "checkpoint.h5")]), folder + ".then.log") != 0:
        return [f"{name} restart {first} -> {then}: the restart failed ({folder}.then.log)"]
    last = sorted(f for f in os.listdir(serial) if f.startswith("snapshot_"))[-1]
    print(f"{name} stopped on {first} processes after step {stop}, continued on {then}: compared"
          f" ({elapsed()})")
    return [f"{name} restart {first} -> {then}: {x}"
            for x in compare_files(os.path.join(serial, last), os.path.join(folder, last))]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--mpi-solve", required=True)
    p.add_argument("--serial-solve", required=True)
    p.add_argument("--preproc", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    case = os.path.join(a.source, "cases/taylor_bar/case.toml")
    particles = os.path.join(a.out, "particles.h5")
    if run([a.preproc, os.path.join(a.source, "geometries/taylor_bar.geo"), "--set", "n=6",
            "--set", "nr=3", "--set", "nz=30", "--set", "grading=1.08", "-o", particles],
           os.path.join(a.out, "preproc.log")) != 0:
        sys.exit("split_runs: gsph-preproc failed")
    # With probes on the first and the last particle (on the first and the last process) and
    # at the impact face's centre: probes.csv byte for byte too.
    with open(case) as f:
        text = f.read()
    taylor = os.path.join(a.out, "taylor_probes.toml")
    with open(taylor, "w") as f:
        f.write(text.replace('file = "../../materials/',
                             f'file = "{os.path.join(a.source, "materials")}/', 1))
        with h5py.File(particles, "r") as p:
            last = len(p["particles/X"]) - 1
        f.write(f'\n[[probe]]\nname = "first"\nparticle = 0\n\n[[probe]]\nname = "last"\n'
                f'particle = {last}\n\n[[probe]]\nname = "centre"\npoint = [0.0, 0.0, 0.0]\n')
    # The serial runs: the threaded serial build.
    env = dict(os.environ, OMP_NUM_THREADS="2")
    faults, serial = split_like_serial(a, "taylor_ogrid", taylor, ["--particles", particles], env)
    if serial is None:
        sys.exit("split_runs: " + faults[0])
    # Contact between bodies (a search in the current configuration over every particle): the
    # plate-and-projectile sample (two bodies, a clamped rim, a wall with friction, gravity).
    plate = os.path.join(a.source, "cases/plate_projectile/case.toml")
    plate_particles = os.path.join(a.out, "plate_projectile.h5")
    run([a.preproc, os.path.join(a.source, "geometries/plate_projectile.geo"), "-o",
         plate_particles], os.path.join(a.out, "plate_projectile.preproc.log"))
    plate_run = ["--particles", plate_particles, "--overwrite"]
    plate_serial = os.path.join(a.out, "plate_serial")
    with open(plate_serial + ".log", "w") as out:
        if subprocess.call([a.serial_solve, plate, "-o", plate_serial] + plate_run, stdout=out,
                           stderr=subprocess.STDOUT, env=env) != 0:
            sys.exit("split_runs: the serial plate run failed: " + plate_serial + ".log")
    plate_split = os.path.join(a.out, "plate_np3")
    if run(mpirun(3, [a.mpi_solve, plate, "-o", plate_split] + plate_run),
           plate_split + ".log") != 0:
        faults.append(f"plate and projectile on 3 processes: the run failed ({plate_split}.log)")
    else:
        names, rows = history(os.path.join(plate_serial, "history.csv"))
        if not np.max(np.abs(rows[:, names.index("contact_plate_projectile_fz")])) > 0.0:
            faults.append("plate and projectile: the bodies never touched")
        last = sorted(f for f in os.listdir(plate_serial) if f.startswith("snapshot_"))[-1]
        faults += [f"plate and projectile on 3 processes, {last}: {x}"
                   for x in compare_files(os.path.join(plate_serial, last),
                                          os.path.join(plate_split, last))]
        faults += compare_history(os.path.join(plate_serial, "history.csv"),
                                  os.path.join(plate_split, "history.csv"))
        print(f"plate and projectile on 3 processes: {last} compared ({elapsed()})")
    # Bonds that break across the cuts.
    kw_case = os.path.join(a.source, "cases/kalthoff_winkler/case.toml")
    kw = os.path.join(a.out, "kalthoff_winkler.h5")
    run([a.preproc, os.path.join(a.source, "geometries/kalthoff_winkler.geo"), "--set",
         "h=0.0025", "-o", kw], os.path.join(a.out, "kalthoff_winkler.preproc.log"))
    found, kw_serial = split_like_serial(a, "kalthoff_winkler", kw_case, ["--particles", kw], env,
                                         bonds=True)
    faults += found
    if kw_serial is not None:
        # Restarts on another process count.
        for first, then, stop in ((4, 2, 400), (3, 1, 250)):
            faults += restart_across(a, "kalthoff_winkler", kw_case, kw, kw_serial, first, then,
                                     stop)
    perforation = os.path.join(a.source, "cases/plate_perforation/case.toml")
    pf = os.path.join(a.out, "plate_perforation.h5")
    run([a.preproc, os.path.join(a.source, "geometries/plate_perforation.geo"), "-o", pf],
        os.path.join(a.out, "plate_perforation.preproc.log"))
    found, pf_serial = split_like_serial(a, "plate_perforation", perforation,
                                         ["--particles", pf, "--end-time", "2.4e-5"], env,
                                         bonds=True)
    faults += found
    # Self-contact (the plug and the plate it leaves, the detached particles between them): the
    # perforation again, on 3 processes.
    with open(perforation) as f:
        text = f.read()
    self_contact = os.path.join(a.out, "self_contact.toml")
    with open(self_contact, "w") as f:
        f.write(text.replace("between_bodies = true", "between_bodies = true\nself_contact = true",
                             1))
    found, sc_serial = split_like_serial(a, "self_contact", self_contact,
                                         ["--particles", pf, "--end-time", "2.4e-5"], env,
                                         bonds=True, counts=(3,))
    faults += found
    # The self-contact acted within that time: its state is not the plain perforation's.
    if pf_serial is not None and sc_serial is not None:
        last = sorted(f for f in os.listdir(sc_serial) if f.startswith("snapshot_"))[-1]
        with h5py.File(os.path.join(pf_serial, last)) as f, \
                h5py.File(os.path.join(sc_serial, last)) as g:
            moved = float(np.max(np.abs(f["particles/x"][()] - g["particles/x"][()])))
        if not moved > 0.0:
            faults.append("self-contact: the positions are the plain perforation's")
        print(f"self-contact: positions differ from the plain perforation's by up to"
              f" {moved:.3g} m at {last}")
    # The case's nonlocal damage (ℓ = 2 mm) reads the drivers of the particles within ℓ, a halo
    # of its own (a split run that did not exchange them moved apart by 1.9 m/s at 5 µs on 3
    # processes, measured): some driver must have accumulated for the runs above to show it.
    if pf_serial is not None:
        last = sorted(f for f in os.listdir(pf_serial) if f.startswith("snapshot_"))[-1]
        with h5py.File(os.path.join(pf_serial, last)) as f:
            driver = f["particles/damage_driver"][()]
        if not np.max(driver) > 0.0:
            faults.append("nonlocal damage: no driver accumulated, the average is idle")
        print(f"nonlocal damage: largest driver {np.max(driver):.3g} at {last}")
    # Local damage (the case without its material length), to 10 µs.
    local_case = os.path.join(a.out, "local_damage.toml")
    with open(local_case, "w") as f:
        local_text, n = re.subn(r"(?m)^damage_length = .*\n", "", text)
        if n != 1:
            faults.append(f"{perforation}: expected one damage_length line")
        f.write(local_text)
    found, _ = split_like_serial(a, "local_damage", local_case,
                                 ["--particles", pf, "--end-time", "1.0e-5"], env,
                                 counts=(2, 3))
    faults += found
    for f in faults:
        print("FAIL", f)
    print("split runs: " + ("all equal" if not faults else f"{len(faults)} faults"))
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
