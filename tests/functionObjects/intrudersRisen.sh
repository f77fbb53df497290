#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The intrudersRisen function object ends a run at the first particle file
# by which every particle of a class has been at or above the bed's surface
# in a file (dpmRiseTime's surface: the height below which the fraction q
# of the other particles' centres lie), after one more step that writes
# the end; who has risen survives a restart.
#
# A run of the test column (730 particles, up to 0.3 s of gas, particle
# files every 0.01 s) with two instances on the 130 large particles:
#   counted  q 0.1, endRun false: one row per particle file from the start
#            (some rise and sink back: risen so far exceeds those above)
#   ended    q 0.03 from 0.185 s (timeStart), endRun true
# Expected, against numpy's quantile of the particle files' heights
# (dpmfoam2d.rise_time.surface_heights), file by file:
#   1. each row's surface equal to the bit, the count at or above it and
#      the count risen so far (in this file or an earlier one) equal;
#   2. the run ends one CFD step after the first file from 0.185 s by
#      which `ended` has all 130 risen, with that time written (gas
#      fields, restart state, particle file), or at the end time if none;
#   3. the same run stopped at 0.15 s and restarted gives the same rows
#      after 0.15 s (the risen so far read back from the restart time's
#      functionObjectProperties) and ends at the same time;
# and bad entries (fraction 1, an unknown class, executeControl) stop the
# run naming the dictionary, the entry and what is allowed.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
. "$testsDir/functionObjects/testFunctions"
export WM_PROJECT_SITE="${WM_PROJECT_SITE:-$DPMFOAM2D_PROJECT}"

makeCase "$workDir/case"
cd "$workDir/case" || fail "cd"
setEntry system/controlDict endTime 0.3
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
        fraction    0.03;
        timeStart   0.185;
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
grep -q "^intrudersRisen ended: t = 0.19, [0-9]* of 130 large at or above the surface .* risen so far" log.dpmFoam2D \
    || fail "no sample line in log.dpmFoam2D"

check()      # <case> <rows only after this time>: the rows against the files
{
    py - "$@" <<'PY'
import os
import sys

import numpy as np
from dpmfoam2d import particles, rise_time

case, after = sys.argv[1], float(sys.argv[2])
dt, end, start = 1e-4, 0.3, 0.185
errors = []


def rows(name):
    found = {}
    for table in sorted(os.path.join(case, "postProcessing", name, d, "intrudersRisen.dat")
                        for d in os.listdir(os.path.join(case, "postProcessing", name))):
        for line in open(table):
            if not line.startswith("#"):
                r = line.split()
                found[round(float(r[0]), 9)] = (float(r[1]), int(r[2]), int(r[3]), int(r[4]))
    return found


tables = {"counted": rows("counted"), "ended": rows("ended")}
fractions = {"counted": 0.1, "ended": 0.03}
classes = {"counted": 1, "ended": 1}
risen = {"counted": set(), "ended": set()}
ending = None
for t, path in particles.list_times(case):
    p = particles.read_particles(path)
    y, ids = p["position"][:, 1], p["id"]
    for name, table in tables.items():
        mine = p["class"] == classes[name]
        if name == "ended" and t < start - 1e-9:
            if round(t, 9) in table:
                errors.append("ended sampled %g s, before its timeStart" % t)
            continue
        surface = rise_time.surface_heights(y, ~mine, [fractions[name]])[0]
        above = mine & (y >= surface)
        risen[name].update(ids[above].tolist())
        expected = (float(surface), int(above.sum()), len(risen[name]), int(mine.sum()))
        if name == "ended" and len(risen[name]) == mine.sum() and ending is None:
            ending = t
        if t <= after + 1e-9:
            continue
        got = table.get(round(t, 9))
        if got is None:
            if ending is None or t <= ending:
                errors.append("%s: no row at %g s" % (name, t))
        elif got != expected:
            errors.append("%s at %g s: %r, the files give %r" % (name, t, got, expected))
last = max(float(d) for d in os.listdir(case) if d.replace(".", "").replace("e-", "").isdigit())
expected = ending + dt if ending is not None else end
print("%s: all 130 large risen to the q 0.03 surface from 0.185 s: %s; the run's last time %g s,"
      " expected %g s" % (case, "by %g s" % ending if ending is not None else "never", last, expected))
if abs(last - expected) > 1e-9:
    errors.append("the run ended at %g s, expected %g s" % (last, expected))
for what in ("uniform/dem.state", "U", "p_rgh"):
    if not os.path.isfile(os.path.join(case, "%g" % last, what)):
        errors.append("the last time %g s lacks %s" % (last, what))
if ending is not None and max(t for t, _ in particles.list_times(case)) != last:
    errors.append("no particle file of the last time %g s" % last)
print("%d rows of counted and %d of ended checked after %g s, counted's risen %d"
      % (sum(t > after for t in tables["counted"]), sum(t > after for t in tables["ended"]), after,
         len(risen["counted"])))
for e in errors:
    print(e)
sys.exit(1 if errors else 0)
PY
}
check . -1 || fail "the samples and the end differ from the particle files (above)"
grep -q "^intrudersRisen ended: every large has risen to the surface (q 0.03)" log.dpmFoam2D \
    || echo "(the run was not ended: its class never all risen)"

echo "3. stopped at 0.15 s, restarted"
cd .. && makeCase "$workDir/restarted" && cd restarted || fail "cd"
cp ../case/system/controlDict ../case/controlDict.base system/
setEntry system/controlDict endTime 0.15
runSolver
setEntry system/controlDict endTime 0.3
runSolver
grep -q "^intrudersRisen counted: t = 0.15, .* risen so far" log.dpmFoam2D \
    || fail "the restart does not sample its start's particle file"
check . 0.15 || fail "the restarted run's rows or end differ (above)"

expectFailure fraction segregation/intrudersRisen risen "class large; fraction 1;" \
    "Entry 'fraction' = 1" "controlDict.functions.risen" "allowed: .* in (0, 1)"
expectFailure class segregation/intrudersRisen risen "class intruder;" \
    "Entry 'class' = intruder" "not a class of cloud 'particles'" "(small large)"
expectFailure executeControl segregation/intrudersRisen risen "class large; executeControl timeStep; executeInterval 5;" \
    "executeControl" "type intrudersRisen"

pass "intrudersRisen samples the particle files as numpy does, ends the run when all have risen, and restarts knowing who had"
