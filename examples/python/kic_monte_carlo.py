"""How to run:   /usr/bin/python3 examples/python/kic_monte_carlo.py [samples] [picture.png]
                 (the peristep package installed, or PYTHONPATH=python; the picture needs matplotlib,
                 Debian's python3-matplotlib)
What it shows:   a Monte Carlo study of the fracture toughness K_IC of the glass-ceramic plate (000 Sec. 5)
                 over its microstructure: sample k is the microstructure of seed 1 + k, each opened by
                 loadDisplacement to 0.3 um in 30 steps on a coarse 26 x 14 grid (h = 32 um), in worker
                 processes. Prints mean, standard deviation and the standard error of the mean, and draws
                 the histogram of K_IC (a text one without matplotlib).
"""
import sys

import peristep
import numpy as np

samples = int(sys.argv[1]) if len(sys.argv) > 1 else 8
picture = sys.argv[2] if len(sys.argv) > 2 else "kic_monte_carlo.png"
plate = dict(scene="glassCeramic", nx=26, ny=14, Lx=800e-6, Ly=416e-6, poissonRatio=0.25, crystalFraction=0.2)
result = peristep.sample(plate, rule="mc", samples=samples, seed=1, load=(0.0, 0.3e-6), steps=30)

kic = result.samples["toughnessKIC"] / 1e6  # MPa m^0.5
print(f"K_IC over {samples} microstructures: mean {result.mean['toughnessKIC'] / 1e6:.3f} MPa m^0.5 "
      f"(+- {result.se_mean['toughnessKIC'] / 1e6:.3f} standard error), std {result.std['toughnessKIC'] / 1e6:.3f}")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    counts, edges = np.histogram(kic, bins=5)
    for n, lo, hi in zip(counts, edges, edges[1:]):
        print(f"  {lo:6.3f} - {hi:6.3f}  {'#' * n}")
else:
    plt.hist(kic, bins="auto", edgecolor="black")
    plt.xlabel("K_IC [MPa m$^{0.5}$]")
    plt.ylabel("microstructures")
    plt.title(f"Glass-ceramic plate, crystal fraction 0.2: {samples} Monte Carlo samples")
    plt.savefig(picture, dpi=100)
    print(f"wrote {picture}")
if not (np.all(np.isfinite(kic)) and np.all(kic > 0) and not result.failures):
    sys.exit("a sample gave no toughness")
