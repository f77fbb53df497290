# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The fixed bed of largeParticleForce.sh: 3.1-mm spheres laid alike in
every 9.525-mm gas cell, wall cells too, and one 9.43-mm intruder.

In x and z each cell column holds the sphere centres in the square
[r, h - r]^2 (no sphere crosses a cell face, so a wall cell holds what an
inner one does): layers of 3 x 3 and 2 x 2 spheres alternate in y every
h/4, so the bed repeats every h/2 in y and every h in x and z, and every
cell away from the bed's ends holds 26 spheres (voidage 0.5307). The
spheres the intruder would overlap are left out.

    largeParticleBed.py <nx> <ny> <nz> <x> <y> <z>    (class x y z lines)
"""
import itertools
import sys
import numpy as np

h = 9.525e-3
d_glass = 3.1e-3
d_intruder = 9.43e-3


def bed(nx, ny, nz):
    r = d_glass / 2
    L = h - d_glass
    big = [(r + i * L / 2, r + k * L / 2) for i in range(3) for k in range(3)]
    small = [(r + L / 4 + i * L / 2, r + L / 4 + k * L / 2) for i in range(2) for k in range(2)]
    points = []
    for ci, ck in itertools.product(range(nx), range(nz)):
        for m in itertools.count():
            y = r + m * h / 4
            if y > ny * h - r:
                break
            for (x, z) in (big if m % 2 == 0 else small):
                points.append((ci * h + x, y, ck * h + z))
    return np.array(points)


def spheres_per_cell():
    return 2 * 9 + 2 * 4


def bed_voidage():
    return 1 - spheres_per_cell() * np.pi * d_glass**3 / 6 / h**3


if __name__ == "__main__":
    nx, ny, nz = (int(a) for a in sys.argv[1:4])
    P = np.array([float(a) for a in sys.argv[4:7]])
    glass = bed(nx, ny, nz)
    keep = np.linalg.norm(glass - P, axis=1) >= (d_glass + d_intruder) / 2
    for p in glass[keep]:
        print(0, *(f"{c:.9g}" for c in p))
    print(1, *(f"{c:.9g}" for c in P))
    print(f"# {len(glass) - keep.sum()} spheres left out around the intruder", file=sys.stderr)
