"""How to run:   python3 examples/python/specimen.py <path to PeriStep.so>
                 (needs numpy; the library is build/component/fmi/PeriStep.so)
What it shows:   your own specimen through the FMU: a picture (a numpy array of characters) becomes the
                 material maps of the "specimen" scene ('.' matrix, '#' an inclusion ten times as stiff and
                 as tough, ' ' a hole: Young's modulus 0, Void), an inclined pre-crack is one segment, the
                 bottom is held and the top pulled up by loadFactor * 1e-5 m. Every step raises loadFactor
                 and prints the reaction of the top grip; at the end the damage field as a picture
                 ('X' cracked). Exit status 0 when the crack has grown from the notch.
"""
import ctypes as C
import sys

import numpy as np

from embed import PeriStep, get_float64, refs, set_float64

# Value references and enumeration values, from api/peristep.h.
VR_NX, VR_NY, VR_NCRACKS, VR_SCENE, VR_LX, VR_LY = 1, 2, 4, 10, 11, 12
VR_LOAD_FACTOR, VR_DAMAGE = 30, 42
VR_MATERIAL_E, VR_MATERIAL_G = 80, 82
VR_CRACK_X0, VR_CRACK_Y0, VR_CRACK_X1, VR_CRACK_Y1 = 83, 84, 85, 86
VR_GRIP_TOP_UY, VR_REACTION_TOP_Y = 98, 107
SCENE_SPECIMEN = 9

# The plate as a picture, top row first; h = 0.1 m, so 33 x 17 points span 3.2 x 1.6 m.
PICTURE = [
    ".................................",
    ".................................",
    ".................................",
    ".................................",
    "...........................   ...",
    "..........................     ..",
    "...................###.....   ...",
    "..................#####..........",
    ".................#######.........",
    "..................#####..........",
    "...................###...........",
    ".................................",
    ".................................",
    ".................................",
    ".................................",
    ".................................",
    ".................................",
]
H = 0.1
NOTCH = (-1.6, -0.3, -1.0, 0.1)  # x0, y0, x1, y1 [m]: from the left edge, rising


def material_maps(picture):
    """E [Pa] and G [J/m^2] images [ny][nx], row 0 at the bottom (y = -Ly/2) as the FMU stores them."""
    chars = np.array([list(row) for row in reversed(picture)])
    E = np.select([chars == "#", chars == " "], [1e10, 0.0], default=1e9)
    G = np.where(chars == "#", 10.0, 1.0)
    return E, G


def main(path):
    fmu = PeriStep(path)
    E, G = material_maps(PICTURE)
    ny, nx = E.shape
    instance = fmu.instantiate(b"specimen.py")
    try:
        # 1. The grid and the number of pre-cracks are structural parameters.
        fmu.EnterConfigurationMode(instance)
        fmu.SetUInt64(instance, refs(VR_NX, VR_NY, VR_NCRACKS), 3, (C.c_uint64 * 3)(nx, ny, 1), 3)
        fmu.ExitConfigurationMode(instance)
        # 2. The scene, the plate, the maps, the notch and the pull of the top grip.
        fmu.SetInt64(instance, refs(VR_SCENE), 1, (C.c_int64 * 1)(SCENE_SPECIMEN), 1)
        set_float64(fmu, instance, VR_LX, [H * (nx - 1)])
        set_float64(fmu, instance, VR_LY, [H * (ny - 1)])
        set_float64(fmu, instance, VR_MATERIAL_E, E)
        set_float64(fmu, instance, VR_MATERIAL_G, G)
        for vr, value in zip((VR_CRACK_X0, VR_CRACK_Y0, VR_CRACK_X1, VR_CRACK_Y1), NOTCH):
            set_float64(fmu, instance, vr, [value])
        set_float64(fmu, instance, VR_GRIP_TOP_UY, [1e-5])
        fmu.EnterInitializationMode(instance, False, 0.0, 0.0, True, 40.0)
        fmu.ExitInitializationMode(instance)
        # 3. Raise the load step by step: each step breaks bonds until equilibrium.
        for step, load in enumerate(np.arange(2.0, 12.01, 0.5)):
            set_float64(fmu, instance, VR_LOAD_FACTOR, [load])
            fmu.step(instance, float(step), 1.0)
            damage = get_float64(fmu, instance, VR_DAMAGE, (ny, nx))
            reaction = get_float64(fmu, instance, VR_REACTION_TOP_Y, (1,))[0]
            cracked = damage > 0.3
            front = (np.nonzero(cracked.any(axis=0))[0].max() * H - H * (nx - 1) / 2) if cracked.any() else -np.inf
            print(f"loadFactor {load:5.2f}: top reaction {reaction:10.4g} N/m, crack front x = {front:5.2f} m")
            if front >= 1.0:
                break
        # 4. The damage picture, top row first.
        for j in reversed(range(ny)):
            print("".join("X" if cracked[j, i] else PICTURE[ny - 1 - j][i] for i in range(nx)))
        fmu.Terminate(instance)
    finally:
        fmu.FreeInstance(instance)
    if front <= NOTCH[2] + H:
        sys.exit("the crack did not grow from the notch")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(f"usage: {sys.argv[0]} <path to PeriStep.so>")
    main(sys.argv[1])
