#!/bin/bash
# Restart: 2N CFD steps in one go equal N steps, a restart from the written
# time, and N more (N = 1000 DEM steps: the particles are renumbered by cell
# every 200, at the restart step too). The particles (positions, velocities, spins) and the gas
# fields must be identical bit for bit (gas written in binary).
#   restart.sh <workDir> [dragModel]
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
cd .. && cp -r once twice || fail "copy"

(cd once && runSolver)
cd twice || fail "cd"
setEntry system/controlDict endTime 0.01
runSolver
mv log.dpmFoam2D log.dpmFoam2D.1
setEntry system/controlDict endTime 0.02
runSolver
grep -q "read from .*0.01/uniform/dem.state" log.dpmFoam2D || fail "the second run did not restart from 0.01"
cd ..

py - <<'PY' || fail "restart is not bit for bit"
import sys, h5py, numpy as np
ok = True
for name in ("position", "velocity", "omega"):
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

# A time directory without its particle state (a run killed while writing
# it) must stop the restart with a message, not start a new bed there
rm twice/0.02/uniform/dem.state
(cd twice && dpmFoam2D >log.incomplete 2>&1) && fail "restarted from an incomplete time"
grep -q "The time directory is incomplete" twice/log.incomplete || fail "no message for an incomplete time"
pass "restart continues bit for bit; an incomplete time is refused"
