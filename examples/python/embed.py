"""How to run:   /usr/bin/python3 examples/python/embed.py     (the peristep package installed, or
                 PYTHONPATH=python; the FMU is build/PeriStep.fmu, or PERISTEP_FMU)
What it shows:   PeriStep driven from Python with the peristep package: a small loop over the random
                 coordinate xi of Test 1 of 000 on a 17 x 17 grid, one Simulation per sample, reading the
                 fields damage and ux as 2D numpy arrays [ny][nx] and the L2 error against the
                 manufactured solution. The skeleton of a sampling loop in a script.
"""
import sys

import peristep  # before numpy: it sets the environment OpenBLAS reads when numpy loads it
import numpy as np

print(f"{'xi':>6} {'errorL2 [m]':>12} {'max |ux| [m]':>13} {'max damage':>11}")
for xi in (-2.0, -1.0, 0.0, 1.0, 2.0):
    # 1. The grid (structural parameters) and the parameters by name; 2. one step at full load.
    with peristep.Simulation("smooth", nx=17, ny=17, poissonRatio=0.3, xi=[xi]) as sim:
        sim.step(loadFactor=1.0)
        # 3. Fields as 2D arrays: row j is y_j (row 0 at y = -Ly/2), column i is x_i.
        ux, damage, error = sim.ux, sim.damage, sim.errorL2
    print(f"{xi:6.1f} {error:12.4e} {np.abs(ux).max():13.4e} {damage.max():11.3g}")
    if not (np.isfinite(error) and error > 0 and ux.shape == (17, 17)):
        sys.exit(f"unexpected outputs at xi = {xi}")
