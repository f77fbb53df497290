#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# kill -9 at chosen moments of a short run (tests/faults/faultFunctions:
# during a particle file, an index update, a particle state, the gas
# fields' write), each at the write of 0.02 s, then a plain restart: the run
# must continue from the last complete time and end bit for bit as an
# uninterrupted one, every file whole.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
. "$testsDir/faults/faultFunctions"

cd "$workDir" || fail "cd"
makeFaultCase template
cp -r template reference
(cd reference && runSolver)

for fault in $faultPoints
do
    name=${fault%%:*}
    cp -r template "$name"
    cd "$name" || fail "cd $name"
    DPMFOAM2D_FAULT=$fault dpmFoam2D >log.killed 2>&1
    status=$?
    [ "$status" = 137 ] || { tail -5 log.killed; fail "$name: DPMFOAM2D_FAULT=$fault did not kill the run ($status)"; }
    case $name in
        particleWrite) leftover=particles/0.02.h5.partial ;;
        xdmfWrite)     leftover=particles/particles.xdmf.partial ;;
        stateWrite)    leftover=0.02/uniform/dem.state.tmp ;;
        fieldWrite)    leftover=0.02/p_rgh ;;
    esac
    [ -f "$leftover" ] || fail "$name: killed, but no part-written $leftover"
    checkWhole . || fail "$name: a file is damaged after the kill"
    runSolver
    case $name in
        stateWrite|fieldWrite)
            grep -q "Restart: time 0.02 is incomplete .*set aside as 0.02.incomplete" log.dpmFoam2D \
                || fail "$name: the incomplete time 0.02 was not set aside" ;;
    esac
    grep -q "read from .*0.01/uniform/dem.state" log.dpmFoam2D || fail "$name: did not restart from 0.01"
    cd ..
    compareRuns reference "$name" || fail "$name: the restarted run differs"
    echo "ok   killed during $name, restarted from 0.01, bit for bit"
done
pass "a run killed during each kind of write restarts and ends bit for bit"
