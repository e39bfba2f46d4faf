"""How to run:   /usr/bin/python3 examples/python/effective_modulus.py     (the peristep package installed,
                 or PYTHONPATH=python)
What it shows:   homogenization with the specimen's elastic model: a glass-ceramic plate (000 Sec. 5's phases,
                 generated at crystal fraction f from a seed) held on every side, whose collars carry the
                 uniaxial strain u = (0, eps y) (collarDuyDy). One solve gives the top grip's reaction F; the
                 effective plane-strain modulus M = F / (Lx eps) is printed for several f beside the Voigt and
                 Reuss averages of the phases' M = lambda + 2 mu. The pure glass plate calibrates the
                 boundary (the top collar's corners also pull: its M comes out 2% above the glass's), and the
                 last column divides that out (the averages are those of the target f, which the generated
                 microstructure meets only approximately). Exit status 0 when M grows with f and the glass
                 plate gives the glass's M to 3%.
"""
import sys

import peristep

N, L, NU, EPS = 51, 400e-6, 0.25, 1e-3  # 51 x 51 points on a 400 um square (h = 8 um), strain 0.1%


def plane_strain_m(E, nu=NU):
    """lambda + 2 mu of plane strain."""
    return E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))


def effective_m(f):
    held = dict.fromkeys(("gripLeft", "gripRight", "gripBottom", "gripTop"), "held")
    with peristep.Simulation("specimen", nx=N, ny=N, materialField="glassCeramic", specimenModel="elastic",
                             Lx=L, Ly=L, poissonRatio=NU, crystalFraction=f, gripTopUy=0.0,  # no rigid pull
                             collarDuyDy=EPS, **held) as sim:
        sim.step()
        return sim.reactionTopY / (L * EPS)


# The phases' Young's moduli are the FMU's start values (000 Table 1).
start = {v.name: float(v.start) for v in peristep.variables() if v.name in ("glassYoungsModulus", "crystalYoungsModulus")}
mg, mc = plane_strain_m(start["glassYoungsModulus"]), plane_strain_m(start["crystalYoungsModulus"])
print(f"{'f':>4} {'M effective GPa':>16} {'Reuss':>8} {'Voigt':>8} {'M calibrated':>13}")
moduli = []
for f in (0.0, 0.2, 0.4, 0.6, 0.8):
    moduli.append(effective_m(f))
    voigt, reuss = (1 - f) * mg + f * mc, 1 / ((1 - f) / mg + f / mc)
    print(f"{f:4.1f} {moduli[-1] / 1e9:16.2f} {reuss / 1e9:8.2f} {voigt / 1e9:8.2f} {moduli[-1] * mg / moduli[0] / 1e9:13.2f}")
if not all(b > a for a, b in zip(moduli, moduli[1:])):
    sys.exit("the effective modulus does not grow with the crystal fraction")
if abs(moduli[0] / mg - 1) > 0.03:
    sys.exit(f"the glass plate gives M = {moduli[0] / 1e9:.2f} GPa, not the glass's {mg / 1e9:.2f} GPa")
