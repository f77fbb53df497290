#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmParaView -screenshot on a case the solver wrote (the test column, 600
# small and 130 large discs, 0.02 s): the scene renders off-screen at the
# asked height, both classes in their colours in the ratio of their drawn
# areas, 600*1.5^2/(130*2.5^2) = 1.66, within 10 % (the spheres are lit:
# their rims darken, and a rim pixel may fall out of either hue), and the
# gas voidage behind them in grey (dark in the bed, white above it). A case without particle files is refused
# naming the file.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/column"
cd "$workDir/column" || fail "cd"
runSolver
dpmParaView . -screenshot "$workDir/scene.png" -height 2400 >log.dpmParaView 2>&1 \
    || { tail -20 log.dpmParaView; fail "dpmParaView -screenshot failed"; }
grep -q "time 0.02 written" log.dpmParaView || fail "not the latest time (0.02)"
py - "$workDir/scene.png" <<'PY' || fail "the scene's picture"
import sys
import numpy as np
import matplotlib.image as m
im = m.imread(sys.argv[1])[..., :3]
h, w = im.shape[:2]
r, g, b = im[..., 0], im[..., 1], im[..., 2]
# by hue, which the lighting's shading keeps: red (0.89, 0.10, 0.11),
# blue (0.22, 0.49, 0.72) at any brightness
red = (r > 2 * np.maximum(g, b)) & (r > 0.05)
blue = (b > 1.3 * np.maximum(r, g)) & (b > 0.05)
grey = (np.ptp(im, axis=2) < 0.02) & ~red & ~blue
# the colour bars (from 0.78 of the width) hold class colours too
bed = slice(0, int(0.75 * w))
# the bed's box (rows and columns holding particles)
rows = np.where((red | blue)[:, bed].any(axis=1))[0]
cols = np.where((red | blue)[:, bed].any(axis=0))[0]
inBed = np.zeros_like(grey)
inBed[rows.min():rows.max() + 1, cols.min():cols.max() + 1] = True
above = np.zeros_like(grey)
above[:max(rows.min() - 20, 1), cols.min():cols.max() + 1] = True
# the voidage drawn grey from black (0.35) to white (1): between the discs
# the bed's voidage (below 0.74 anywhere at 0.02 s) is darker than 0.6; the
# freeboard's (1) is white
bedGrey = np.median(r[inBed & grey])
freeGrey = np.median(r[above & grey])
nRed, nBlue = red[:, bed].sum(), blue[:, bed].sum()
ratio = nRed / max(nBlue, 1)
print("picture %d x %d px, red %d, blue %d px: ratio %.3f (expected 1.66);"
      " grey between the discs %.2f (< 0.6), above the bed %.2f (> 0.95)"
      % (w, h, nRed, nBlue, ratio, bedGrey, freeGrey))
sys.exit(0 if h == 2400 and abs(ratio / 1.66 - 1) < 0.10 and bedGrey < 0.6
         and freeGrey > 0.95 else 1)
PY
cat log.dpmParaView | grep -v "^\s*$" | tail -1

mkdir -p "$workDir/empty"
dpmParaView "$workDir/empty" -screenshot "$workDir/none.png" >log.empty 2>&1 \
    && fail "dpmParaView ran on a case without particles"
grep -q "particles.xdmf not found: run dpmFoam2D" log.empty \
    || { cat log.empty; fail "no message naming particles.xdmf"; }
pass "dpmParaView shows the gas and both classes of particles at their sizes"
