#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmBedStatistics on a synthetic bed (makeCase.py): voidage 0.40 in the
# bed (cell centres below 0.12 m), 1 above, a bubble of voidage 0.9 (radius
# 20 mm, centre 30 mm up at t = 1.5 s, 50 mm at 1.6 s). Expected from that
# construction: bed height 0.12 m (half-way between the rows centred at
# 116.25 and 123.75 mm), emulsion voidage 0.40, bubble fraction = cells of
# the bed whose centre lies in the bubble / 320 bed cells. Particle speeds
# set here: small ones alternately 0.3 m/s and 0.004 m/s, large ones 0.1
# m/s, so speedRmsSmall = sqrt((0.3^2 + 0.004^2)/2), stillSmall = 0.5
# (threshold 0.01 m/s), speedRmsLarge = 0.1, stillLarge = 0. Tolerance 1e-6
# relative (velocities are stored in float32). Then on the files the solver
# wrote (the test column, 0.02 s): each class's rms speed (in the plane), still fraction
# and mean voidage at its particles as computed here from the solver's HDF5
# datasets (read with h5py), to 1e-6 relative. Bad options and a missing
# case give errors naming them.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/pictures/pictureFunctions"
. "$testsDir/solver/testFunctions"

makeParticleCase "$workDir/bed" 1.5 1.6
/usr/bin/python3 - "$workDir/bed" <<'PY' || fail "setting particle velocities"
import sys, numpy as np
from dpmfoam2d import particles as pio, tables
case = sys.argv[1]
for t, path in pio.list_times(case):
    p = pio.read_particles(path)
    n = len(p["class"])
    v = np.zeros((n, 3))
    small = np.nonzero(p["class"] == 0)[0]
    v[small[0::2], :2] = (0.18, 0.24)          # 0.3 m/s
    v[small[1::2], :2] = (0.0, -0.004)
    v[p["class"] == 1, :2] = (0.06, -0.08)     # 0.1 m/s
    pio.write_particles(case, t, p["position"], p["diameter"], p["class"], velocity=v,
                        omega=p["omega"], ids=p.get("id"))
PY
dpmBedStatistics "$workDir/bed" -report >log.dpmBedStatistics 2>&1 \
    || { cat log.dpmBedStatistics; fail "dpmBedStatistics failed"; }
cat log.dpmBedStatistics
/usr/bin/python3 - "$workDir/bed" <<'PY' || fail "bed statistics"
import sys, numpy as np
from dpmfoam2d import particles as pio, tables
case = sys.argv[1]
bed = tables.read_postprocessing(case, "bedStatistics", "bed.dat")
par = tables.read_postprocessing(case, "bedStatistics", "particles.dat")
assert list(bed["Time"]) == [1.5, 1.6], bed["Time"]
assert list(par["Time"]) == [1.5, 1.6], par["Time"]
dx = 0.0075
xc = (np.arange(20) + 0.5) * dx
yc = (np.arange(16) + 0.5) * dx                # the 16 rows below 0.12 m
X, Y = np.meshgrid(xc, yc)
for k, t in enumerate((1.5, 1.6)):
    inside = ((X - 0.075) ** 2 + (Y - 0.03 - 0.02 * k) ** 2 < 0.02 ** 2).sum()
    expected = inside / 320.0
    print("t = %g: bubble cells %d, fraction %.6f (expected %.6f)"
          % (t, inside, bed["bubbleFraction"][k], expected))
    assert abs(bed["bubbleFraction"][k] - expected) < 1e-12
assert np.all(np.abs(bed["bedHeight"] - 0.12) < 1e-12), bed["bedHeight"]
assert np.all(np.abs(bed["emulsionVoidage"] - 0.40) < 1e-9), bed["emulsionVoidage"]
def close(a, b):
    assert np.all(np.abs(a - b) <= 1e-6 * b), (a, b)
close(par["speedRmsSmall"], np.sqrt((0.3 ** 2 + 0.004 ** 2) / 2))
close(par["stillSmall"], 0.5)
close(par["speedRmsLarge"], 0.1)
assert np.all(par["stillLarge"] == 0.0), par["stillLarge"]
assert np.all(np.isnan(par["voidageSmall"])), "no voidage in the files: nan expected"
PY
# The solver's own files
makeCase "$workDir/column"
(cd "$workDir/column" && runSolver) || fail "the test column"
dpmBedStatistics "$workDir/column" -every 0.01 >log.column 2>&1 \
    || { cat log.column; fail "dpmBedStatistics on the solver's files"; }
/usr/bin/python3 - "$workDir/column" <<'PY' || fail "bed statistics of the solver's files"
import glob, os, sys
import h5py, numpy as np
from dpmfoam2d import tables
case = sys.argv[1]
par = tables.read_postprocessing(case, "bedStatistics", "particles.dat")
files = sorted(glob.glob(os.path.join(case, "particles", "*.h5")),
               key=lambda f: float(os.path.basename(f)[:-3]))
assert len(par["Time"]) == len(files), (par["Time"], files)
for k, path in enumerate(files):
    with h5py.File(path, "r") as f:
        cls = f["class"][()].reshape(-1)
        speed = np.linalg.norm(f["velocity"][()][:, :2].astype(float), axis=1)  # in the plane
        eps = f["voidage"][()].astype(float).reshape(-1)
    for c, name in ((0, "Small"), (1, "Large")):
        want = {"speedRms": np.sqrt(np.mean(speed[cls == c] ** 2)),
                "still": np.mean(speed[cls == c] < 0.01),
                "voidage": np.mean(eps[cls == c])}
        for q, w in want.items():
            got = par[q + name][k]
            print("%s: %s%s %.6g (from the file %.6g)" % (os.path.basename(path), q, name, got, w))
            assert abs(got - w) <= 1e-6 * max(abs(w), 1e-12), (q + name, got, w)
PY

# Bad input
dpmBedStatistics "$workDir/bed" -bubbleVoidage 1.2 >log.bad 2>&1 && fail "-bubbleVoidage 1.2 accepted"
grep -q "bubbleVoidage 1.2 is outside (0, 1)" log.bad || { cat log.bad; fail "bubbleVoidage message"; }
dpmBedStatistics "$workDir/nothing" >log.missing 2>&1 && fail "missing case accepted"
grep -q "no case directory .*nothing" log.missing || { cat log.missing; fail "missing case message"; }
pass "bed height, bubble fraction, emulsion voidage and particle speeds as constructed"
