#!/usr/bin/env python3
"""Projected wall time of the glass-ceramic toughness study at a finer grid on a cluster.

Reads the per-sample wall times that `bench/glass_ceramic_study.sh` left in OUT_DIR's sample stores
(one thread per MPI rank), scales each by the measured cost ratio of one specimen at the target grid to
one at the study's grid (per crystal fraction, interpolated linearly in f), adds each rank's PCA set-up
once per fraction it works on, and hands the samples to RANKS one-thread ranks in the order
`peristep sample` does: the next sample to the first rank that is free (rank 0's dynamic queue).

  bench/glass_ceramic_projection.py OUT_DIR --ranks 128 --scale 0.2:50.1 --scale 0.8:32.1 --pca-setup 712
"""
import argparse
import glob
import heapq
import os
import struct


def sample_seconds(store):
    """Per-sample wall times of a store, in the order the samples were finished."""
    files = sorted(glob.glob(os.path.join(store, "sample-*.bin")), key=os.path.getmtime)
    return [struct.unpack_from("<d", open(f, "rb").read(16), 8)[0] for f in files]


def scale_at(f, points):
    """The cost ratio at fraction f, linear between the measured fractions, constant beyond them."""
    points = sorted(points)
    if f <= points[0][0]:
        return points[0][1]
    for (f0, s0), (f1, s1) in zip(points, points[1:]):
        if f <= f1:
            return s0 + (s1 - s0) * (f - f0) / (f1 - f0)
    return points[-1][1]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out_dir")
    ap.add_argument("--ranks", type=int, default=128, help="one-thread ranks (64 two-core nodes: 128)")
    ap.add_argument("--scale", action="append", required=True, metavar="F:RATIO",
                    help="cost of one specimen at the target grid over one at the study's grid, at fraction F")
    ap.add_argument("--pca-setup", type=float, default=0.0, help="seconds of one rank's PCA at the target grid")
    a = ap.parse_args()
    points = [tuple(map(float, s.split(":"))) for s in a.scale]

    jobs = []  # (fraction, method, seconds at the target grid), in the study's order
    for tag in (20, 40, 60, 80):
        f = tag / 100
        for method in ("pca", "mc"):
            t = sample_seconds(os.path.join(a.out_dir, f"{method}_f{tag}.samples"))
            jobs += [(f, method, s * scale_at(f, points)) for s in t]
    if not jobs:
        raise SystemExit(f"no sample store in {a.out_dir}")

    free = [(0.0, r, None) for r in range(a.ranks)]  # (time the rank is free, rank, its last study)
    heapq.heapify(free)
    for f, method, seconds in jobs:
        t, r, last = heapq.heappop(free)
        setup = a.pca_setup if method == "pca" and last != (f, method) else 0.0
        heapq.heappush(free, (t + setup + seconds, r, (f, method)))
    wall = max(t for t, _, _ in free)
    total = sum(s for _, _, s in jobs)
    print(f"{len(jobs)} samples, {total / 3600:.1f} core-hours at the target grid, longest sample "
          f"{max(s for _, _, s in jobs) / 3600:.2f} h; on {a.ranks} one-thread ranks: {wall / 3600:.2f} h wall")


if __name__ == "__main__":
    main()
