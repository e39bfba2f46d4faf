"""How to run:   python3 examples/python/effective_modulus.py <path to PeriStep.so>
                 (needs numpy; the library is build/component/fmi/PeriStep.so)
What it shows:   homogenization with the specimen's elastic model: a glass-ceramic plate (000 Sec. 5's phases,
                 generated at crystal fraction f from a seed) held on every side, whose collars carry the
                 uniaxial strain u = (0, eps y) (collarDuyDy). One solve gives the top grip's reaction F; the
                 effective plane-strain modulus M = F / (Lx eps) is printed for several f beside the Voigt and
                 Reuss averages of the phases' M = lambda + 2 mu. The pure glass plate calibrates the
                 boundary (the top collar's corners also pull: its M comes out 2% above the glass's), and the
                 last column divides that out (the averages are those of the target f, which the generated
                 microstructure meets only approximately). Exit status 0 when M grows with f and the glass plate gives the
                 glass's M to 3%.
"""
import ctypes as C
import sys

import numpy as np

from embed import PeriStep, get_float64, refs, set_float64

# Value references and enumeration values, from api/peristep.h.
VR_NX, VR_NY, VR_SCENE, VR_LX, VR_LY, VR_POISSON_RATIO, VR_SEED, VR_CRYSTAL_FRACTION = 1, 2, 10, 11, 12, 14, 17, 24
VR_MATERIAL_FIELD, VR_SPECIMEN_MODEL, VR_COLLAR_DUY_DY, VR_REACTION_TOP_Y = 79, 99, 147, 107
VR_GRIPS = (87, 88, 89, 90)  # left, right, bottom, top
VR_GRIP_TOP_UY = 98
SCENE_SPECIMEN, MATERIAL_GLASS_CERAMIC, SPECIMEN_ELASTIC, GRIP_HELD = 9, 3, 3, 2

N, L, NU, EPS = 51, 400e-6, 0.25, 1e-3  # 51 x 51 points on a 400 um square (h = 8 um), strain 0.1%
GLASS_E, CRYSTAL_E = 80e9, 133e9        # 000 Table 1 (the FMU's start values)


def plane_strain_m(E, nu=NU):
    """lambda + 2 mu of plane strain."""
    return E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))


def effective_m(fmu, f):
    instance = fmu.instantiate(b"effective_modulus.py")
    try:
        fmu.EnterConfigurationMode(instance)
        fmu.SetUInt64(instance, refs(VR_NX, VR_NY), 2, (C.c_uint64 * 2)(N, N), 2)
        fmu.ExitConfigurationMode(instance)
        enums = (VR_SCENE, VR_MATERIAL_FIELD, VR_SPECIMEN_MODEL) + VR_GRIPS
        values = (SCENE_SPECIMEN, MATERIAL_GLASS_CERAMIC, SPECIMEN_ELASTIC) + (GRIP_HELD,) * 4
        fmu.SetInt64(instance, refs(*enums), len(enums), (C.c_int64 * len(values))(*values), len(values))
        set_float64(fmu, instance, VR_LX, [L])
        set_float64(fmu, instance, VR_LY, [L])
        set_float64(fmu, instance, VR_POISSON_RATIO, [NU])
        set_float64(fmu, instance, VR_CRYSTAL_FRACTION, [f])
        set_float64(fmu, instance, VR_GRIP_TOP_UY, [0.0])  # no rigid pull: the collar gradient alone
        set_float64(fmu, instance, VR_COLLAR_DUY_DY, [EPS])
        fmu.EnterInitializationMode(instance, False, 0.0, 0.0, True, 1.0)
        fmu.ExitInitializationMode(instance)
        fmu.step(instance, 0.0, 1.0)
        reaction = get_float64(fmu, instance, VR_REACTION_TOP_Y, (1,))[0]
        fmu.Terminate(instance)
    finally:
        fmu.FreeInstance(instance)
    return reaction / (L * EPS)


def main(path):
    fmu = PeriStep(path)
    mg, mc = plane_strain_m(GLASS_E), plane_strain_m(CRYSTAL_E)
    print(f"{'f':>4} {'M effective GPa':>16} {'Reuss':>8} {'Voigt':>8} {'M calibrated':>13}")
    moduli = []
    for f in (0.0, 0.2, 0.4, 0.6, 0.8):
        m = effective_m(fmu, f)
        moduli.append(m)
        voigt, reuss = (1 - f) * mg + f * mc, 1 / ((1 - f) / mg + f / mc)
        calibrated = m * mg / moduli[0]
        print(f"{f:4.1f} {m / 1e9:16.2f} {reuss / 1e9:8.2f} {voigt / 1e9:8.2f} {calibrated / 1e9:13.2f}")
    if not all(b > a for a, b in zip(moduli, moduli[1:])):
        sys.exit("the effective modulus does not grow with the crystal fraction")
    if abs(moduli[0] / mg - 1) > 0.03:
        sys.exit(f"the glass plate gives M = {moduli[0] / 1e9:.2f} GPa, not the glass's {mg / 1e9:.2f} GPa")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(f"usage: {sys.argv[0]} <path to PeriStep.so>")
    main(sys.argv[1])
