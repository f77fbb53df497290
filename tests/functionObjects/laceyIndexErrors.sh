#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The laceyIndex function object stops a run with a FatalIOError that names
# the dictionary, the entry and the allowed values for:
#   an unknown varianceBasis, cellSize 0, an empty box, and a cloud with
#   three size classes (the Lacey index here is for binary mixtures).
# Each case is a run of a few steps (0.001 s of settling) that must fail
# with its message in the log.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/case"
cd "$workDir/case" || fail "cd"
setEntry constant/particleProperties initialBed/settleTime 0.001
setEntry system/controlDict endTime 0.0003
cp system/controlDict controlDict.base

# expectFailure <case name> <function entries> <pattern>...: the run fails
# and its log holds every pattern
expectFailure()
{
    local name="$1" entries="$2"
    shift 2
    cp controlDict.base system/controlDict
    cat >>system/controlDict <<EOF2
functions
{
    #include "\$DPMFOAM2D_PROJECT/etc/caseDicts/laceyIndex"
    laceyIndex { $entries }
}
EOF2
    rm -rf postProcessing
    if dpmFoam2D >"log.$name" 2>&1
    then
        fail "$name: dpmFoam2D ran; expected an error"
    fi
    for pattern in "$@"
    do
        grep -q -- "$pattern" "log.$name" \
            || { sed -n '/FOAM FATAL/,$p' "log.$name"; fail "$name: no '$pattern' in log.$name"; }
    done
    echo "  $name: $(grep -m1 -A3 'FOAM FATAL' "log.$name" | sed -n 2p)"
}

expectFailure basis "varianceBasis lacey;" \
    "Unknown varianceBasis 'lacey'" "controlDict.functions.laceyIndex" \
    "allowed: wholeBed" "perSample"
expectFailure cellSize "cellSize 0;" \
    "Entry 'cellSize' = 0" "controlDict.functions.laceyIndex" "allowed: a sampling cell size > 0"
expectFailure box "box (0.05 0) (0.01 0.1);" \
    "Entry 'box'" "is empty" "allowed: box (xMin yMin) (xMax yMax)"

rm -rf 0/uniform        # the saved state has two classes
setEntry constant/particleProperties classes/medium "{ diameter 2e-3; density 2525; count 50; }"
expectFailure threeClasses "" \
    "needs exactly two particle size classes" "has 3" "(small medium large)\|(small large medium)" \
    "controlDict.functions.laceyIndex"

pass "laceyIndex stops with its message for each bad input"
