#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks a snapshot's class colours against the particles drawn.

  countClassPixels.py <png> <particles.h5> <relTol>

Counts the pixels of each class colour (dpmfoam2d.pictures.tools.CLASS_COLOURS,
within 2/255 per channel: the discs are drawn unlit, so they are exact).
Expected ratio small/large pixels = sum over small of d^2 / sum over large
of d^2 (areas of the discs drawn, none overlapping or cut in the test data).
Passes when |measured/expected - 1| <= relTol; prints both.
"""

import sys

import numpy as np
import matplotlib.image as mpimg

from dpmfoam2d import particles as pio
from dpmfoam2d.pictures.tools import CLASS_COLOURS

png, h5, relTol = sys.argv[1], sys.argv[2], float(sys.argv[3])
img = mpimg.imread(png)[:, :, :3]
counts = {}
for c, colour in CLASS_COLOURS.items():
    counts[c] = int(np.all(np.abs(img - np.array(colour)) <= 2.0 / 255, axis=2).sum())
p = pio.read_particles(h5)
d2 = p["diameter"].astype(float) ** 2
expected = d2[p["class"] == 0].sum() / d2[p["class"] == 1].sum()
measured = counts[0] / max(counts[1], 1)
print("pixels: small %d, large %d; ratio %.4f, expected %.4f (areas), relTol %g"
      % (counts[0], counts[1], measured, expected, relTol))
if min(counts.values()) < 1000 or abs(measured / expected - 1) > relTol:
    sys.exit("FAIL: class colours not in the expected proportion")
