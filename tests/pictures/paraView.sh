#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmParaView -screenshot on a case the solver wrote (the test column, 600
# small and 130 large discs, 0.02 s): the scene renders off-screen at the
# asked height, both classes in their colours in the ratio of their drawn
# areas, 600*1.5^2/(130*2.5^2) = 1.66, within 10 % (the spheres are lit:
# their rims darken, and a rim pixel may fall out of either hue), and the
# gas voidage behind them in grey (dark in the bed, white above it). The
# layout: the bed fills the frame (its particles span at least 80 % of the
# picture's height and 90 % of the bed's part of its width), the legends
# stand beside it and inside the picture (nothing drawn in the picture's
# outer 3 pixels on the right and at the bottom, nor at the top of the
# legends' part), and they name the classes by the case's names and the
# particles' diameters. A case without particle files is refused naming
# the file.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/column"
cd "$workDir/column" || fail "cd"
runSolver
dpmParaView . -screenshot "$workDir/scene.png" -height 2400 >log.dpmParaView 2>&1 \
    || { tail -20 log.dpmParaView; fail "dpmParaView -screenshot failed"; }
grep -q "time 0.02 written" log.dpmParaView || fail "not the latest time (0.02)"
grep -q "^dpmParaView: classes small 1.5 mm, large 2.5 mm;" log.dpmParaView \
    || { cat log.dpmParaView; fail "the legend does not name the classes by name and diameter"; }
bedWidth=$(sed -n 's/^dpmParaView: .*the bed in columns 0-\([0-9]*\) of .*/\1/p' log.dpmParaView)
[ -n "$bedWidth" ] || fail "no layout line in the log"
py - "$workDir/scene.png" "$bedWidth" <<'PY' || fail "the scene's picture"
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
# the colour bars (beside the bed) hold class colours too
bedWidth = int(sys.argv[2])
bed = slice(0, bedWidth)
# the bed's box (rows and columns holding particles)
rows = np.where((red | blue)[:, bed].any(axis=1))[0]
cols = np.where((red | blue)[:, bed].any(axis=0))[0]
# the packed bed's rows (a fifth of the row or more in particles): a particle
# still falling after the packing is framed, but it is no bed
dense = np.where((red | blue)[:, bed].mean(axis=1) > 0.2)[0]
inBed = np.zeros_like(grey)
inBed[dense.min():dense.max() + 1, cols.min():cols.max() + 1] = True
above = np.zeros_like(grey)
above[:max(dense.min() - 20, 1), cols.min():cols.max() + 1] = True
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
# the layout: the bed fills the frame, the legends beside it inside the picture
drawn = im.min(axis=2) < 0.9
legend = drawn[:, bedWidth:]
fills = (rows.max() - rows.min() + 1) / h, (cols.max() - cols.min() + 1) / bedWidth
inside = not drawn[:, -3:].any() and not drawn[-3:, :].any() and not legend[:3, :].any()
print("the particles span %.2f of the height and %.2f of the bed's width; legends drawn: %s,"
      " inside the picture: %s" % (fills[0], fills[1], legend.any(), inside))
sys.exit(0 if h == 2400 and abs(ratio / 1.66 - 1) < 0.10 and bedGrey < 0.6
         and freeGrey > 0.95 and fills[0] >= 0.8 and fills[1] >= 0.9 and legend.any()
         and inside else 1)
PY
cat log.dpmParaView | grep -v "^\s*$" | tail -1

mkdir -p "$workDir/empty"
dpmParaView "$workDir/empty" -screenshot "$workDir/none.png" >log.empty 2>&1 \
    && fail "dpmParaView ran on a case without particles"
grep -q "particles.xdmf not found: run dpmFoam2D" log.empty \
    || { cat log.empty; fail "no message naming particles.xdmf"; }
pass "dpmParaView shows the gas and both classes of particles at their sizes"
