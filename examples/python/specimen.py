"""How to run:   /usr/bin/python3 examples/python/specimen.py     (the peristep package installed, or
                 PYTHONPATH=python)
What it shows:   your own specimen: a picture (an array of characters) becomes the material maps of the
                 "specimen" scene ('.' matrix, '#' an inclusion ten times as stiff and as tough, ' ' a hole:
                 Young's modulus 0, Void), an inclined pre-crack is one segment, the bottom is held and the
                 top pulled up by loadFactor * 1e-5 m. Every step raises loadFactor and prints the reaction
                 of the top grip; at the end the damage field as a picture ('X' cracked). Exit status 0
                 when the crack has grown from the notch.
"""
import sys

import peristep
import numpy as np

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

# 1. The maps as images [ny][nx], row 0 at the bottom (y = -Ly/2): the picture upside down. Their shape
#    gives nx and ny; the notch's one segment gives nCracks = 1.
chars = np.array([list(row) for row in reversed(PICTURE)])
E = np.select([chars == "#", chars == " "], [1e10, 0.0], default=1e9)
G = np.where(chars == "#", 10.0, 1.0)
ny, nx = E.shape
x0, y0, x1, y1 = NOTCH
with peristep.Simulation("specimen", materialYoungsModulus=E, materialFractureEnergy=G, Lx=H * (nx - 1),
                         Ly=H * (ny - 1), crackX0=[x0], crackY0=[y0], crackX1=[x1], crackY1=[y1],
                         gripTopUy=1e-5) as sim:
    # 2. Raise the load step by step: each step breaks bonds until equilibrium at its load.
    for load in np.arange(2.0, 12.01, 0.5):
        sim.step(loadFactor=load)
        cracked = sim.damage > 0.3
        front = np.nonzero(cracked.any(axis=0))[0].max() * H - H * (nx - 1) / 2 if cracked.any() else -np.inf
        print(f"loadFactor {load:5.2f}: top reaction {sim.reactionTopY:10.4g} N/m, crack front x = {front:5.2f} m")
        if front >= 1.0:
            break
# 3. The damage picture, top row first.
for j in reversed(range(ny)):
    print("".join("X" if cracked[j, i] else PICTURE[ny - 1 - j][i] for i in range(nx)))
if front <= x1 + H:
    sys.exit("the crack did not grow from the notch")
print("the crack grew from the notch")
