#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmBedStatistics on a slab run (voidageModel slab3D): dpmFoam2D runs
# hand-placed 3D spheres for 2 ms and dpmBedStatistics reads what it wrote.
# The column: 8 x 40 cells of 7.5 mm, a slab 3 mm deep (one cell thick). In
# each cell of the 10 bottom rows but a 2 x 2 block (columns 3-4, rows 4-5,
# the "bubble"): 4 large spheres (2.5 mm, local x, y = 1.875 or 5.625 mm,
# z 1.5 mm) and a small one (1.5 mm) at the cell's centre, at z 0.9 or
# 2.1 mm (the column through the depth counts it either way). No sphere
# touches another, a wall or a cell face, and none gets nearer than 0.6 mm
# to one in 2 ms of fall (g t^2 / 2 = 0.02 mm), so from outside the code:
#   voidage of a bed cell  1 - (4 pi/6 2.5^3 + pi/6 1.5^3) / (7.5 7.5 3) mm3
#                          = 0.795599 (emulsionVoidage; 1 in the bubble)
#   bedHeight  75 mm (rows 0-9 below -surfaceVoidage 0.9, row 10 empty)
#   bubbleFraction  4 / 80 = 0.05 (-bubbleVoidage 0.95)
#   speedRms of both classes  g t (1 - rho_g/rho_p) = 0.0196107 m/s at
#   t = 2 ms: free fall from rest in a closed column (the drag of the gas
#   the falling bed pushes up through it, Ergun's at that slip, is below
#   0.1 % of the weight); still 0 (-stillSpeed 0.01), 1 (-stillSpeed 0.03)
# Tolerances: 1e-6 relative on the geometry (fields written with 8
# digits), 1 % on the speeds (the drag bound with a margin).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/slab"
cd "$workDir/slab" || fail "cd"
setSlab slab3D 3e-3
setEntry constant/gasProperties inletPatch none
setEntry 0/U boundaryField.inlet "{ type noSlip; }"
setEntry system/controlDict endTime 0.002
setEntry system/controlDict writeInterval 0.002
setEntry constant/particleProperties writeInterval 0.002
setEntry constant/particleProperties classes.small.count 76
setEntry constant/particleProperties classes.large.count 304
setEntry constant/particleProperties initialBed \
    '{ positions "$FOAM_CASE/constant/spheres"; }'
py - <<'PY' || fail "placing the spheres"
with open("constant/spheres", "w") as f:
    f.write("# class x y z (m): 4 large and 1 small per bed cell\n")
    for row in range(10):
        for col in range(8):
            if col in (3, 4) and row in (4, 5):
                continue                                # the bubble
            x0, y0 = 7.5e-3 * col, 7.5e-3 * row
            for dx in (1.875e-3, 5.625e-3):
                for dy in (1.875e-3, 5.625e-3):
                    f.write("1 %.6e %.6e 1.5e-3\n" % (x0 + dx, y0 + dy))
            z = 0.9e-3 if (row + col) % 2 else 2.1e-3
            f.write("0 %.6e %.6e %.6e\n" % (x0 + 3.75e-3, y0 + 3.75e-3, z))
PY
runSolver
grep -q "^Particles: 380 placed from " log.dpmFoam2D \
    || { grep "^Particles" log.dpmFoam2D; fail "380 placed spheres expected"; }

for still in 0.01 0.03
do
    dpmBedStatistics . -surfaceVoidage 0.9 -bubbleVoidage 0.95 -stillSpeed $still \
        -every 0.001 >log.dpmBedStatistics.$still 2>&1 \
        || { cat log.dpmBedStatistics.$still; fail "dpmBedStatistics failed"; }
    cp postProcessing/bedStatistics/0/particles.dat particles.$still.dat
done
cat log.dpmBedStatistics.0.03 postProcessing/bedStatistics/0/*.dat

py - <<'PY' || fail "slab bed statistics"
import sys, numpy as np
from dpmfoam2d import particles as pio, tables
bed = tables.read_postprocessing(".", "bedStatistics", "bed.dat")
t = np.atleast_1d(bed["Time"])
k = int(np.argmin(np.abs(t - 0.002)))
assert abs(t[k] - 0.002) < 1e-12, t
eps = 1 - (4 * 2.5 ** 3 + 1.5 ** 3) * np.pi / 6 / (7.5 * 7.5 * 3)
checks = [("bedHeight", np.atleast_1d(bed["bedHeight"])[k], 0.075, 1e-6),
          ("bubbleFraction", np.atleast_1d(bed["bubbleFraction"])[k], 0.05, 1e-6),
          ("emulsionVoidage", np.atleast_1d(bed["emulsionVoidage"])[k], eps, 1e-6)]
v = 9.81 * 0.002 * (1 - 1.204 / 2525)
for still, expected in ((0.01, 0.0), (0.03, 1.0)):
    par = np.loadtxt("particles.%s.dat" % still, ndmin=2)
    rows = par[np.abs(par[:, 0] - 0.002) < 1e-12]
    assert len(rows) == 1, par[:, 0]
    r = rows[0]          # Time speedRmsSmall stillSmall speedRmsLarge stillLarge ...
    checks += [("speedRmsSmall", r[1], v, 1e-2), ("speedRmsLarge", r[3], v, 1e-2),
               ("stillSmall -stillSpeed %s" % still, r[2], expected, 0),
               ("stillLarge -stillSpeed %s" % still, r[4], expected, 0)]
bad = 0
for name, got, want, tol in checks:
    ok = abs(got - want) <= tol * abs(want)
    bad += not ok
    print("%-28s %.7g  expected %.7g  tolerance %g  %s"
          % (name, got, want, tol, "ok" if ok else "WRONG"))
sys.exit(bad)
PY
pass "bed height, bubble fraction, voidage and speeds of a slab run as placed"
