#!/usr/bin/env python3
"""Molecular-dynamics data of 003 Sec. 5 with Debian's LAMMPS, then coarse-grained HDF5 for the learning.

Runs outside CI (needs `apt-get install lammps lammps-data`, see scripts/optional-packages.txt):
    python3 scripts/md/generate.py [--cache DIR] [--jobs 2] [--train 70] [--out data/learning/graphene_md.h5]
Each LAMMPS run is cached under --cache by the SHA-256 of its input files and variables; a run whose hash is
present is not repeated. Data sets (003 Sec. 5; choices not given in 003 are marked CHOSEN):
  lattice:    relaxed bond length and 2D elastic constants C11, C12, C66 of the potential (lattice_constants.lmp)
  train (I):  periodic sheet 23 x 40 cells (100.78 x 101.19 A, 3680 atoms), static body force
              b = e_c A cos(k1 x1) cos(k2 x2), k_i = 2 pi n_i / L_i, n_i = 0..5, (n1, n2) != 0, c = 1, 2: 70 samples.
              CHOSEN: A = 0.005 C66 |k| / (atoms per area), a strain of about 0.5% (003: below 2%).
  validation (II): 003:(44)-(45) with Table 1 (L = half the box side); CHOSEN: C_k = 10 x Table 1 in eV/A.
  fracture_train (III): [-50, 50]^2 A, 25 A slit at x1 = 0 from the lower edge; CHOSEN: the sheet is first
              stretched by eps0 = 10% in x1 and relaxed with the vertical edges (|x1| > 47 A) held, then the edges
              move at +-v(x2) = +-v0 (50 - x2)/100, v0 = 2 A/ps, the interior started on the matching linear
              profile (crack starts near frame 10 and grows to frame 40). --eps0 0 --v0 V runs 003's loading
              without the stretch: the crack starts at frame 9, 7, 6, 5, 4 for V = 20, 30, 40, 50, 60 A/ps.
  fracture_test (IV): same sheet, free edges, body-force pulse of 003 Sec. 5 (IV); CHOSEN: b0 = 0.8 eV/A,
              tr = 0.5 ps (crack starts near frame 9 and grows to frame 40; b0 = 2 fragments the sheet).
  Frames of III and IV every 99 MD steps of 0.5 fs (003); --frame-steps N records every N steps over the same time.
"""
import argparse
import hashlib
import math
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

BOND = 1.460601            # relaxed bond of SiC.tersoff carbon (lattice_constants.lmp prints it)
NX, NY = 23, 40            # periodic cells: 3 a nx by sqrt(3) a ny
ATOMS_PER_AREA = 4.0 / (3.0 * BOND * math.sqrt(3.0) * BOND)
C66_EV_A2 = 241.89 / 16.0218  # N/m -> eV/A^2 (measured, lattice_constants.lmp)
STRAIN = 0.005
EPS0, V0 = 0.10, 2.0       # fracture_train: stretch before the run, edge speed [A/ps] at the lower edge
PULSE_B0, PULSE_TR = 0.8, 0.5  # eV/A, ps: fracture_test pulse
FRAMES, FRAME_STEPS = 40, 99  # fracture sets: frames of 99 steps of 0.5 fs (4.95e-14 s, 003 Sec. 5)
TABLE1 = [(0.001, 0, 0, 25), (0, 0.001, 0, 25), (0.001, 0, 0, 15), (0, 0.001, 0, 15), (0.001, 0, 0, 10),
          (0.001, 0, 1, 25), (0, 0.001, 1, 25), (0.001, 0, 1, 15), (0, 0.001, 1, 15), (0.001, 0, 1, 10)]


def run_key(inp, variables):
    h = hashlib.sha256()
    for f in (inp, "graphene_sheet.lmp"):
        with open(os.path.join(HERE, f), "rb") as fh:
            h.update(fh.read())
    for k in sorted(variables):
        h.update(f"{k}={variables[k]}\n".encode())
    return h.hexdigest()[:20]


def lammps(cache, inp, variables, output_name):
    """Runs one input (cwd = scripts/md for its include) unless cached; returns (output path, seconds or None)."""
    key = run_key(inp, variables)
    d = os.path.join(cache, key)
    out = os.path.join(d, output_name)
    if os.path.exists(os.path.join(d, "done")):
        return out, None
    os.makedirs(d, exist_ok=True)
    cmd = ["lmp", "-log", os.path.join(d, "log.lammps"), "-screen", os.path.join(d, "screen.txt"), "-in", inp]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    if output_name:
        cmd += ["-var", "out", out]
    with open(os.path.join(d, "command.txt"), "w") as fh:
        fh.write(" ".join(f"'{c}'" for c in cmd) + "\n")
    t0 = time.time()
    subprocess.run(cmd, cwd=HERE, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(d, "done"), "w") as fh:
        fh.write(f"{time.time() - t0:.2f}\n")
    return out, time.time() - t0


def cosine_loads(count):
    loads = []
    for c in range(2):
        for n1 in range(6):
            for n2 in range(6):
                if n1 == 0 and n2 == 0:
                    continue
                k = 2 * math.pi * math.hypot(n1 / (3 * BOND * NX), n2 / (math.sqrt(3) * BOND * NY))
                amp = STRAIN * C66_EV_A2 * k / ATOMS_PER_AREA
                f = f"{amp:.10g}*cos(2*PI*{n1}*v_X/lx)*cos(2*PI*{n2}*v_Y/ly)"
                loads.append((f"c{c}_k{n1}{n2}", f if c == 0 else "0.0", f if c == 1 else "0.0"))
    # Fewer samples (--train) keep every (n1, n2) pattern in both components as long as possible: stride.
    if count < len(loads):
        step = len(loads) / count
        loads = [loads[int(i * step)] for i in range(count)]
    return loads


def disk_loads():
    loads = []
    for i, (c1, c2, p, R) in enumerate(TABLE1):
        L = "(lx/2)" if p == 0 else "(ly/2)"
        terms = []
        for j in (-1, 0, 1):
            r = f"sqrt((v_X-({(1 - p) * j})*{L})^2+(v_Y-({p * j})*{L})^2)"
            q = f"({r}/{R})"  # min(1, q) without min(), which this LAMMPS lacks in atom-style formulas
            terms.append(f"({1 if j == 0 else -1})*cos(PI/2*({q}+(1.0-{q})*({q}>1.0)))")
        s = "(" + "+".join(terms) + ")"
        loads.append((f"k{i + 1}", f"{10 * c1:g}*{s}" if c1 else "0.0", f"{10 * c2:g}*{s}" if c2 else "0.0"))
    return loads


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cache", default=os.path.join(REPO, "build", "md_cache"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--train", type=int, default=70, help="number of training samples (<= 70)")
    ap.add_argument("--out", default=os.path.join(REPO, "data", "learning", "graphene_md.h5"))
    ap.add_argument("--eps0", type=float, default=EPS0, help="fracture_train: stretch in x1 before the run")
    ap.add_argument("--v0", type=float, default=V0, help="fracture_train: edge speed at the lower edge [A/ps]")
    ap.add_argument("--frame-steps", type=int, default=FRAME_STEPS,
                    help="fracture sets: MD steps of 0.5 fs per frame (003: 99); the frames cover the same time")
    ap.add_argument("--coarse-grain", default=os.path.join(REPO, "build", "bench", "learn_coarse_grain"))
    a = ap.parse_args()
    os.makedirs(a.cache, exist_ok=True)

    jobs = [("lattice", "lattice", "lattice_constants.lmp", {"bond": BOND}, "")]
    base = {"bond": BOND, "nx": NX, "ny": NY}
    for name, fx, fy in cosine_loads(a.train):
        jobs.append(("train", name, "quasi_static.lmp", dict(base, fx=fx, fy=fy), "sample.txt"))
    for name, fx, fy in disk_loads():
        jobs.append(("validation", name, "quasi_static.lmp", dict(base, fx=fx, fy=fy), "sample.txt"))
    frames = FRAMES * FRAME_STEPS // a.frame_steps
    frac = {"bond": BOND, "frames": frames, "every": a.frame_steps, "eps0": 0.0, "v0": 0.0, "b0": 0.0, "tr": 1.0}
    jobs.append(("fracture_train", "edges", "fracture.lmp", dict(frac, case="edges", eps0=a.eps0, v0=a.v0),
                 "frames.txt"))
    jobs.append(("fracture_test", "pulse", "fracture.lmp", dict(frac, case="pulse", b0=PULSE_B0, tr=PULSE_TR),
                 "frames.txt"))

    t0 = time.time()
    with ThreadPoolExecutor(max_workers=a.jobs) as pool:
        results = list(pool.map(lambda j: lammps(a.cache, j[2], j[3], j[4]), jobs))
    ran = [s for _, s in results if s is not None]
    print(f"LAMMPS: {len(jobs)} runs, {len(ran)} new, {sum(ran):.1f} s of run time, {time.time() - t0:.1f} s wall "
          f"with {a.jobs} jobs")

    constants = {}
    with open(os.path.join(a.cache, run_key(jobs[0][2], jobs[0][3]), "screen.txt")) as fh:
        for line in fh:
            if line.startswith("RESULT"):
                _, k, v = line.split()
                constants[k] = v
    print("lattice constants:", constants)

    manifest = os.path.join(a.cache, "manifest.txt")
    with open(manifest, "w") as fh:
        for k, v in constants.items():
            fh.write(f"constant {k} {v}\n")
        for (group, name, _, _, _), (out, _) in zip(jobs[1:], results[1:]):
            fh.write(f"{group} {name} {out}\n")
    os.makedirs(os.path.dirname(a.out), exist_ok=True)
    subprocess.run([a.coarse_grain, "--manifest", manifest, "--out", a.out, "--frame-steps", str(a.frame_steps)],
                   check=True)


if __name__ == "__main__":
    sys.exit(main())
