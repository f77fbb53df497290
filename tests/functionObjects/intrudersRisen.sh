#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The intrudersRisen function object ends a run at the first particle file
# in which every particle of a class lies at or above the bed's surface
# (dpmRiseTime's: the height below which the fraction q of the other
# particles' centres lie), after one more step that writes the end.
#
# A run of the test column (730 particles, 0.1 s of gas, particle files
# every 0.01 s) with two instances on the 130 large particles:
#   counted  q 0.1, endRun false: one row per particle file after the start
#   ended    q 0.01 from 0.015 s (timeStart), endRun true
# Expected, against numpy's quantile of the particle files' heights
# (dpmfoam2d.rise_time.surface_heights), file by file:
#   1. each row's surface equal to the bit, its count equal;
#   2. the run ends one CFD step after the first file from 0.015 s in which
#      `ended` finds all 130 at or above its surface, with that time written
#      (gas fields, restart state, particle file), or at the end time if
#      there is none;
# and bad entries (fraction 1, an unknown class, executeControl) stop the
# run naming the dictionary, the entry and what is allowed.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
export WM_PROJECT_SITE="${WM_PROJECT_SITE:-$DPMFOAM2D_PROJECT}"

makeCase "$workDir/case"
cd "$workDir/case" || fail "cd"
setEntry system/controlDict endTime 0.1
setEntry system/controlDict writeInterval 0.05
setEntry system/controlDict writePrecision 17       # the surfaces to the bit
cp system/controlDict controlDict.base
cat >>system/controlDict <<'EOF2'
functions
{
    ended
    {
        #includeEtc "caseDicts/postProcessing/segregation/intrudersRisen"
        class       large;
        fraction    0.01;
        timeStart   0.015;
    }
    counted
    {
        #includeEtc "caseDicts/postProcessing/segregation/intrudersRisen"
        class       large;
        fraction    0.1;
        endRun      false;
    }
}
EOF2
runSolver
grep -q "^intrudersRisen counted: t = 0.01, [0-9]* of 130 large at or above the surface" log.dpmFoam2D \
    || fail "no sample line in log.dpmFoam2D"

py - . <<'PY' || fail "the samples and the end differ from the particle files (above)"
import glob
import os
import sys

import numpy as np
from dpmfoam2d import particles, rise_time

case = sys.argv[1]
dt, end, start = 1e-4, 0.1, 0.015
files = [(t, p) for t, p in particles.list_times(case) if t > 0]
errors = []


def rows(name):
    table = os.path.join(case, "postProcessing", name, "0", "intrudersRisen.dat")
    return {round(float(r[0]), 9): (float(r[1]), int(r[2]), int(r[3]))
            for r in (line.split() for line in open(table) if not line.startswith("#"))}


counted, ended = rows("counted"), rows("ended")
ending = None
for t, path in files:
    p = particles.read_particles(path)
    y, mine = p["position"][:, 1], p["class"] == 1
    for name, table, q in (("counted", counted, 0.1), ("ended", ended, 0.01)):
        if name == "ended" and t < start - 1e-9:
            if round(t, 9) in table:
                errors.append("ended sampled %g s, before its timeStart" % t)
            continue
        surface = rise_time.surface_heights(y, ~mine, [q])[0]
        at = int((y[mine] >= surface).sum())
        got = table.get(round(t, 9))
        if got is None:
            if ending is None or t <= ending:
                errors.append("%s: no row at %g s" % (name, t))
            continue
        if got != (float(surface), at, int(mine.sum())):
            errors.append("%s at %g s: %r, the files give %r" % (name, t, got, (float(surface), at, int(mine.sum()))))
        if name == "ended" and at == mine.sum() and ending is None:
            ending = t
last = max(float(d) for d in os.listdir(case) if d.replace(".", "").replace("e-", "").isdigit())
expected = ending + dt if ending is not None else end
print("all 130 large at or above the q 0.01 surface from 0.015 s: %s; the run's last time %g s, expected %g s"
      % ("at %g s" % ending if ending is not None else "never", last, expected))
if abs(last - expected) > 1e-9:
    errors.append("the run ended at %g s, expected %g s" % (last, expected))
for what in ("uniform/dem.state", "U", "p_rgh"):
    if not os.path.isfile(os.path.join(case, "%g" % last, what)):
        errors.append("the last time %g s lacks %s" % (last, what))
if ending is not None and max(t for t, _ in particles.list_times(case)) != last:
    errors.append("no particle file of the last time %g s" % last)
print("%d rows of counted and %d of ended checked" % (len(counted), len(ended)))
for e in errors:
    print(e)
sys.exit(1 if errors else 0)
PY
grep -q "^intrudersRisen ended: every large has risen to the surface (q 0.01)" log.dpmFoam2D \
    || echo "(the run was not ended: its class never all at the surface)"

# expectFailure <name> <entries> <pattern>...: the run fails, its log holds each pattern
expectFailure()
{
    local name="$1" entries="$2"
    shift 2
    rm -rf postProcessing 0.* [1-9]*
    cp controlDict.base system/controlDict
    setEntry system/controlDict endTime 0.02
    cat >>system/controlDict <<EOF2
functions
{
    risen
    {
        #includeEtc "caseDicts/postProcessing/segregation/intrudersRisen"
        $entries
    }
}
EOF2
    dpmFoam2D >"log.$name" 2>&1 && fail "$name: dpmFoam2D ran; expected an error"
    for pattern in "$@"
    do
        grep -q -- "$pattern" "log.$name" \
            || { sed -n '/FOAM FATAL/,$p' "log.$name"; fail "$name: no '$pattern' in log.$name"; }
    done
    echo "  $name: $(grep -m1 -A3 'FOAM FATAL' "log.$name" | sed -n 2p)"
}
expectFailure fraction "class large; fraction 1;" \
    "Entry 'fraction' = 1" "controlDict.functions.risen" "allowed: .* in (0, 1)"
expectFailure class "class intruder;" \
    "Entry 'class' = intruder" "not a class of cloud 'particles'" "(small large)"
expectFailure executeControl "class large; executeControl timeStep; executeInterval 5;" \
    "executeControl" "type intrudersRisen"

pass "intrudersRisen samples the particle files as numpy does and ends the run when all have risen"
