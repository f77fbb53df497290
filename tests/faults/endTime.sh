#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Every end time saved: endTime 0.025 with writeInterval 0.01 (gas and
# particle files) leaves a complete, restartable 0.025 (gas fields,
# uniform/dem.state, particles/0.025.h5 listed in particles.xdmf); a rerun
# computes nothing; raised to 0.03, the run continues from 0.025 and ends
# bit for bit as a run from 0 to 0.03 with 0.025 as its last write but one
# (the DEM state and the gas fields at 0.03 identical).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
. "$testsDir/faults/faultFunctions"

cd "$workDir" || fail "cd"
makeFaultCase template
cp -r template reference
(cd reference && runSolver)

cp -r template case
cd case || fail "cd case"
setEntry system/controlDict endTime 0.025
runSolver
for f in U p_rgh phi uniform/dem.state
do
    [ -f 0.025/$f ] || fail "endTime 0.025 with writeInterval 0.01: no 0.025/$f"
done
[ -f particles/0.025.h5 ] || fail "no particles/0.025.h5"
grep -q '0.025.h5' particles/particles.xdmf || fail "particles.xdmf does not list 0.025.h5"
checkWhole . || fail "a file of the case is damaged"
echo "ok   0.025 written though not a multiple of the write interval"

runSolver
grep -q "^Time = " log.dpmFoam2D && fail "a rerun at the end time computed steps"
grep -q "read from .*0.025/uniform/dem.state" log.dpmFoam2D || fail "the rerun did not read 0.025"
echo "ok   a rerun computes nothing"

setEntry system/controlDict endTime 0.03
runSolver
grep -q "read from .*0.025/uniform/dem.state" log.dpmFoam2D || fail "did not continue from 0.025"
cd ..
py - reference case <<'PY' || fail "the continued run differs from the uninterrupted one at 0.03"
import sys
ref, case = sys.argv[1:]
bad = [f for f in ("U", "p_rgh", "phi", "uniform/dem.state")
       if open(f"{ref}/0.03/{f}", "rb").read() != open(f"{case}/0.03/{f}", "rb").read()]
print("differ at 0.03:", " ".join(bad) if bad else "nothing")
sys.exit(1 if bad else 0)
PY
pass "the end time is saved whatever the write interval, and a run continues from it bit for bit"
