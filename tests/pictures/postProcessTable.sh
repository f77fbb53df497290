#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# A -postProcess table next to the run's: `dpmFoam2D -postProcess -func
# laceyIndex` after a run writes postProcessing/laceyIndex/<latest time>/
# (OpenFOAM's <startTime> directory) with rows from time 0 at the saved
# times. The reader of bin/ (dpmPlotMixing, dpmStudy, dpmPictures) must not
# join it with the run's table (times would repeat, M(t) loop back): it keeps
# it apart with a note naming it, and gives it on request; a later restart,
# whose table OpenFOAM then names laceyIndex_<t>.dat in that directory, joins
# the run's tables into strictly increasing times.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

cd "$workDir" || fail "cd"
makeCase case
cd case || fail "cd"
# the run's rows every 0.005 s, the saved times every 0.01 s
foamDictionary -entry functions -set \
    '{ laceyIndex { #includeEtc "caseDicts/postProcessing/mixing/laceyIndex" writeInterval 0.005; } }' \
    system/controlDict >/dev/null 2>&1 || fail "set functions"
setEntry system/controlDict endTime 0.02
runSolver
dpmFoam2D -postProcess -func laceyIndex >log.postProcess 2>&1 || { tail -20 log.postProcess; fail "-postProcess"; }
[ -f postProcessing/laceyIndex/0.02/laceyIndex.dat ] || fail "no -postProcess table in postProcessing/laceyIndex/0.02"

check()     # <expected run times> <expected -postProcess times>
{
    py - "$1" "$2" <<'PY'
import sys, os
import numpy as np
from dpmfoam2d import particles as pio, tables
run = [float(t) for t in sys.argv[1].split()]
pp = [float(t) for t in sys.argv[2].split()]
for fname in ("laceyIndex.dat", "segregation.dat"):
    t = tables.read_postprocessing(".", "laceyIndex", fname)["Time"]
    print(fname, "run:", " ".join("%g" % v for v in t))
    assert np.allclose(t, run) and np.all(np.diff(t) > 0), (t, run)
    t = tables.read_postprocessing(".", "laceyIndex", fname, postprocess=True)["Time"]
    print(fname, "-postProcess:", " ".join("%g" % v for v in t))
    assert np.allclose(t, pp), (t, pp)
PY
}
check "0 0.005 0.01 0.015 0.02" "0 0.01 0.02" 2>log.check || { cat log.check; fail "the run's table is not the run's alone"; }
grep -q "note: .*laceyIndex/0.02/laceyIndex.dat.*not joined .* -postProcess" log.check \
    || { cat log.check; fail "no note naming the -postProcess table left out"; }

dpmPlotMixing . -o mixing.png -report >report.json 2>log.dpmPlotMixing || { cat log.dpmPlotMixing; fail "dpmPlotMixing"; }
py -c 'import json, sys; r = json.load(open("report.json")); c = r["cases"][0]
sys.exit(0 if (c["laceyRows"], c["segregationRows"]) == (5, 5) else "rows %s" % c)' \
    || fail "dpmPlotMixing joined the -postProcess table"
grep -q "not joined" log.dpmPlotMixing || fail "dpmPlotMixing gave no note"

# A restart from 0.02: its table is 0.02/laceyIndex_0.02.dat (the -postProcess
# one has the name); the run's tables join, the -postProcess one stays apart
setEntry system/controlDict endTime 0.03
runSolver
[ -f postProcessing/laceyIndex/0.02/laceyIndex_0.02.dat ] || fail "no laceyIndex_0.02.dat after the restart"
check "0 0.005 0.01 0.015 0.02 0.025 0.03" "0 0.01 0.02" 2>log.check2 \
    || { cat log.check2; fail "the restarted run's tables are not joined"; }
pass "a -postProcess table is kept apart from the run's (noted), restarts still join"
