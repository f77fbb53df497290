#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Restart: 2N CFD steps in one go equal N steps, a restart from the written
# time, and N more (N = 1000 DEM steps: the particles are renumbered by cell
# every 200, at the restart step too). The particles (positions, velocities, spins) and the gas
# fields must be identical bit for bit (gas written in binary).
# In the slab mode the spheres' z, vz and spin vector too.
#   restart.sh <workDir> [dragModel] [slab3D <depth> | spheres3D:<nz> <depth>]
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
model="${2:-ErgunWenYu}"     # drag model (Beetstra: the cell mixture too)

makeCase "$workDir/once"
cd "$workDir/once" || fail "cd"
setEntry system/controlDict writeFormat binary
setEntry system/controlDict writePrecision 17
setEntry system/controlDict endTime 0.02
setEntry system/controlDict writeInterval 0.01
setEntry constant/gasProperties U0byUmf 2
setEntry constant/particleProperties dragModel "$model"
setMomentum
setSlab "${3:-}" "${4:-}"
cd .. && cp -r once twice || fail "copy"

(cd once && runSolver)
cd twice || fail "cd"
setEntry system/controlDict endTime 0.01
runSolver
mv log.dpmFoam2D log.dpmFoam2D.1
rm particles/0.01.h5     # the restart writes its start time's file anew
setEntry system/controlDict endTime 0.02
runSolver
grep -q "read from .*0.01/uniform/dem.state" log.dpmFoam2D || fail "the second run did not restart from 0.01"
cd ..

py - <<'PY' || fail "restart is not bit for bit"
import sys, h5py, numpy as np
ok = True
names = ["position", "velocity", "omega"]
with h5py.File("once/particles/0.02.h5") as a:
    names += ["spin"] if "spin" in a else []
for name in names:
    with h5py.File("once/particles/0.02.h5") as a, h5py.File("twice/particles/0.02.h5") as b:
        same = np.array_equal(a[name][()], b[name][()])
        print(f"particles {name}: {'identical' if same else 'DIFFERENT'}")
        ok &= same
for field in ("U", "p_rgh"):
    same = open(f"once/0.02/{field}", "rb").read() == open(f"twice/0.02/{field}", "rb").read()
    print(f"gas {field}: {'identical' if same else 'DIFFERENT'}")
    ok &= same
sys.exit(0 if ok else 1)
PY
cmp -s once/0.02/uniform/dem.state twice/0.02/uniform/dem.state || fail "DEM states differ"

# The start files carry the gas at the particles like every other file:
# 0.h5 the initial gas (0.orig/U: uniform (0 0 0), exactly), and the
# restart's 0.01.h5 a voidage in [voidageMin 0.1, 1] whose bed mean is
# within 0.01 of the uninterrupted run's file (one CFD step apart)
py - <<'PY' || fail "the start times' particle files lack the gas at the particles"
import sys, h5py, numpy as np
with h5py.File("once/particles/0.h5") as a:
    ok = "voidage" in a and "gasVelocity" in a
    ok = ok and np.all(a["gasVelocity"][()] == 0) and np.all((a["voidage"][()] >= 0.1) & (a["voidage"][()] <= 1))
    print(f"0.h5: voidage and gasVelocity {'as the initial gas' if ok else 'MISSING or wrong'}")
with h5py.File("twice/particles/0.01.h5") as b, h5py.File("once/particles/0.01.h5") as a:
    fine = "voidage" in b and "gasVelocity" in b
    if fine:
        e, u = b["voidage"][()], b["gasVelocity"][()]
        fine = np.all(np.isfinite(u)) and np.all((e >= 0.1) & (e <= 1)) \
            and abs(e.mean() - a["voidage"][()].mean()) < 0.01
        print(f"restart's 0.01.h5: mean voidage {e.mean():.4f} (run through: {a['voidage'][()].mean():.4f})")
    print(f"restart's 0.01.h5: voidage and gasVelocity {'present' if fine else 'MISSING or wrong'}")
sys.exit(0 if ok and fine else 1)
PY

# A time directory without its particle state (a run killed while writing
# it) is set aside as <time>.incomplete, said in the log, and the run
# continues from the last complete time, again bit for bit
rm twice/0.02/uniform/dem.state
(cd twice && dpmFoam2D >log.incomplete 2>&1) || { tail -20 twice/log.incomplete; fail "no restart after an incomplete time"; }
grep -q "Restart: time 0.02 is incomplete .*set aside as 0.02.incomplete" twice/log.incomplete \
    || fail "no message for the incomplete time set aside"
[ -d twice/0.02.incomplete ] || fail "0.02 not set aside as 0.02.incomplete"
grep -q "read from .*0.01/uniform/dem.state" twice/log.incomplete || fail "did not restart from 0.01"
for f in U p_rgh uniform/dem.state
do
    cmp -s once/0.02/$f twice/0.02/$f || fail "0.02/$f differs after the restart from the incomplete time"
done

# startFrom startTime naming an incomplete time: refused, the time named
rm twice/0.02/uniform/dem.state
setEntry twice/system/controlDict startFrom startTime
setEntry twice/system/controlDict startTime 0.02
(cd twice && dpmFoam2D >log.startTime 2>&1) && fail "started from an incomplete startTime"
grep -qE "Start time 0.02 \(startTime in .*controlDict\"?\) is incomplete" twice/log.startTime \
    || { tail -20 twice/log.startTime; fail "no message naming the incomplete start time"; }
pass "restart continues bit for bit; an incomplete latest time is set aside, an incomplete startTime refused"
