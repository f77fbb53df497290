#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# kill -9 at chosen moments of the writes of 0.02 s in a short run: the run
# stops itself at a fault point (DPMFOAM2D_FAULT=<point>:<n>:stop,
# src/dpmCoupling/faultInjection) and this test kills it there, so the files
# left are what a kill at that moment leaves. Points (killPoints): within
# and at the end of the particle file, of the index update and of the
# particle state; during the gas fields; between them and the state; after
# the state. What the kill leaves is checked against the uninterrupted run
# (a temporary with half its file, a prefix of it or all of it); then a
# plain restart must continue from the last complete time, 0.01 s (0.02 s
# once its state is renamed), setting an incomplete 0.02 aside, and end bit
# for bit as the uninterrupted run, every file whole. The point's self-kill
# form (no :stop) is checked once, at the start's particle file.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
. "$testsDir/faults/faultFunctions"

cd "$workDir" || fail "cd"
makeFaultCase template
cp -r template reference
(cd reference && runSolver)

# <point>:<n>, the file it leaves, what that holds (checkLeft), the restart
killPoints="
particleWrite.part:3   particles/0.02.h5.partial         half   0.01
particleWrite.rename:3 particles/0.02.h5.partial         whole  0.01
xdmfWrite.part:3       particles/particles.xdmf.partial  prefix 0.01
xdmfWrite.rename:3     particles/particles.xdmf.partial  index  0.01
fieldWrite:2           0.02                              some   0.01
stateWrite:3           0.02/U                            whole  0.01
stateWrite.part:3      0.02/uniform/dem.state.tmp        prefix 0.01
stateWrite.rename:3    0.02/uniform/dem.state.tmp        whole  0.01
stateWrite.done:3      0.02/uniform/dem.state            whole  0.02
"

# checkLeft <reference case> <file left> <holds>: the file against the
# uninterrupted run's (its name without .partial or .tmp). half: half its
# bytes; prefix: a strict prefix of it; whole: all of it (particle files by
# size: their HDF5 headers hold their creation time); index: the index of
# 0.02 s, valid and listing 0 to 0.02; some: a time directory with some of
# its gas fields, not all
checkLeft()
{
    py - "$@" <<'PY'
import os, sys
import xml.etree.ElementTree as ET
ref, left, holds = sys.argv[1:]
final = os.path.join(ref, left.replace(".partial", "").replace(".tmp", ""))
if holds == "some":
    have = [f for f in ("U", "p_rgh", "phi") if os.path.isfile(os.path.join(left, f))]
    print(f"gas fields in {left}:", " ".join(have) or "none")
    sys.exit(0 if os.path.isdir(left) and len(have) < 3 else 1)
b = open(left, "rb").read()
if holds == "index":
    listed = {i.text.split(":")[0] for i in ET.fromstring(b).iter("DataItem")}
    print(f"{left} lists", " ".join(sorted(listed)))
    sys.exit(0 if listed == {"0.h5", "0.01.h5", "0.02.h5"} else 1)
a = open(final, "rb").read()
ok = {
    "half": len(b) == len(a)//2,
    "prefix": 0 < len(b) < len(a) and a.startswith(b),
    "whole": len(b) == len(a) and (final.endswith(".h5") or a == b),
}[holds]
print(f"{left}: {len(b)} of the {len(a)} bytes of the uninterrupted run's file")
sys.exit(0 if ok else 1)
PY
}

# Without :stop the run kills itself there: at the start's particle file
cp -r template selfKill
cd selfKill || fail "cd selfKill"
DPMFOAM2D_FAULT=particleWrite.part:1 dpmFoam2D >log.killed 2>&1
status=$?
[ "$status" = 137 ] || { tail -5 log.killed; fail "DPMFOAM2D_FAULT=particleWrite.part:1 did not kill the run ($status)"; }
checkLeft ../reference particles/0.h5.partial half || fail "selfKill: particles/0.h5.partial is not half its file"
cd ..
echo "ok   a run killed itself at particleWrite.part:1, half of particles/0.h5 left"

while read -r fault left holds restart
do
    [ -n "$fault" ] || continue
    name=${fault%%:*}
    cp -r template "$name"
    cd "$name" || fail "cd $name"
    (DPMFOAM2D_FAULT=$fault:stop exec dpmFoam2D) >log.killed 2>&1 &
    pid=$!
    waitStopped $pid || { kill -9 $pid 2>/dev/null; tail -5 log.killed; fail "$name: the run did not stop at DPMFOAM2D_FAULT=$fault:stop"; }
    kill -KILL $pid
    wait $pid
    status=$?
    [ "$status" = 137 ] || { tail -5 log.killed; fail "$name: the run stopped at $fault was not killed ($status)"; }
    [ -e "$left" ] || fail "$name: killed, but no $left"
    checkLeft ../reference "$left" "$holds" || fail "$name: $left does not hold $holds of its file"
    checkWhole . || fail "$name: a file is damaged after the kill"
    runSolver
    case $name in
        fieldWrite|stateWrite|stateWrite.part|stateWrite.rename)
            grep -q "Restart: time 0.02 is incomplete .*set aside as 0.02.incomplete" log.dpmFoam2D \
                || fail "$name: the incomplete time 0.02 was not set aside" ;;
    esac
    grep -q "read from .*$restart/uniform/dem.state" log.dpmFoam2D || fail "$name: did not restart from $restart"
    cd ..
    compareRuns reference "$name" || fail "$name: the restarted run differs"
    echo "ok   killed at $name, restarted from $restart, bit for bit"
done <<< "$killPoints"
pass "a run killed at each moment of each kind of write restarts and ends bit for bit"
