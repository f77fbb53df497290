#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The bedAtRest function object ends a run once the bed's speed
# sqrt(2 E_k/M) has stayed below `speed` in every particle file for
# `duration`, after one more step that writes the end; since when the bed
# has been at rest survives a restart.
#
# Runs of the test column (730 particles, particle files every 0.01 s,
# speed 0.01 m/s, duration 0.1 s):
#   packed     U0 half the mixture's Umf (Wen-Yu): the bed stays packed
#   fluidized  U0 1.25 Umf, 0.3 s: the bed bubbles
# Expected, against the particle files (solid spheres: E_k the sum of
# m v^2/2 + I w^2/2 with I = m d^2/10, m of the class's density):
#   1. each row's speed equal to the files' within 1e-5 (single-precision
#      velocities), restSince the first of the latest unbroken run of
#      files below 0.01 m/s;
#   2. packed: the run ends one CFD step after the first file 0.1 s after
#      restSince, with that time written (gas fields, restart state,
#      particle file); fluidized: faster than 0.01 m/s from 0.05 s on and
#      not ended before its end time;
#   3. packed, stopped half way through its rest and restarted: the same
#      rows after the stop and the same end (restSince read back from the
#      restart time's functionObjectProperties);
# and bad entries (speed 0, duration -1, an unknown entry) stop the run
# naming the dictionary, the entry and what is allowed.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
. "$testsDir/functionObjects/testFunctions"
export WM_PROJECT_SITE="${WM_PROJECT_SITE:-$DPMFOAM2D_PROJECT}"

atRest()     # <dir> <U0byUmf> <endTime>: a case with bedAtRest
{
    makeCase "$1"
    (
        cd "$1" || exit 1
        setEntry constant/gasProperties U0byUmf "$2"
        setEntry system/controlDict endTime "$3"
        setEntry system/controlDict writeInterval 0.05
        setEntry system/controlDict writePrecision 17
        cp system/controlDict controlDict.base
        cat >>system/controlDict <<'EOF2'
functions
{
    rest
    {
        #includeEtc "caseDicts/postProcessing/segregation/bedAtRest"
        duration    0.1;
    }
}
EOF2
    ) || fail "case $1"
}

check()      # <case> <rows only after this time> <end time> <expect the end: yes|no>
{
    py - "$@" <<'PY'
import math
import os
import sys

import numpy as np
from dpmfoam2d import particles

case, after, end, ends = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4] == "yes"
dt, limit, duration = 1e-4, 0.01, 0.1
density = 2525.0        # both classes of the test column
errors = []

rows = {}
folder = os.path.join(case, "postProcessing", "rest")
for d in sorted(os.listdir(folder)):
    for line in open(os.path.join(folder, d, "bedAtRest.dat")):
        if not line.startswith("#"):
            r = line.split()
            rows[round(float(r[0]), 9)] = (float(r[1]), float(r[2]))

since, ending, speeds = -1.0, None, []
for t, path in particles.list_times(case):
    p = particles.read_particles(path)
    d = p["diameter"].astype(float)
    m = density * math.pi / 6 * d**3
    v2 = (p["velocity"].astype(float)**2).sum(axis=1)
    w2 = p["omega"].astype(float)**2
    speed = math.sqrt(np.sum(m * (v2 + w2 * d**2 / 10)) / m.sum())
    speeds.append((t, speed))
    since = (-1.0 if speed >= limit else (t if since < 0 else since))
    if ending is None and since >= 0 and t - since >= duration - dt / 2:
        ending = t
    if t <= after + 1e-9:
        continue
    got = rows.get(round(t, 9))
    if got is None:
        if ending is None or t <= ending:
            errors.append("no row at %g s" % t)
        continue
    if abs(got[0] - speed) > 1e-5 * max(speed, 1e-9) or abs(got[1] - since) > 1e-9:
        errors.append("at %g s: speed %.9g, restSince %g; the files give %.9g, %g"
                      % (t, got[0], got[1], speed, since))
last = max(float(n) for n in os.listdir(case) if n.replace(".", "").replace("e-", "").isdigit())
expected = ending + dt if ending is not None else end
print("%s: speeds %s m/s; at rest from %s; the run's last time %g s, expected %g s"
      % (case, " ".join("%.3g" % s for _, s in speeds[:12]) + (" ..." if len(speeds) > 12 else ""),
         "%g s" % since if since >= 0 else "never", last, expected))
if ends != (ending is not None):
    errors.append("the bed %s at rest for %g s, expected %s" % ("was" if ending is not None
                  else "was not", duration, "so" if ends else "not"))
if abs(last - expected) > 1e-9:
    errors.append("the run ended at %g s, expected %g s" % (last, expected))
for what in ("uniform/dem.state", "U", "p_rgh"):
    if not os.path.isfile(os.path.join(case, "%g" % last, what)):
        errors.append("the last time %g s lacks %s" % (last, what))
if max(t for t, _ in particles.list_times(case)) != last:
    errors.append("no particle file of the last time %g s" % last)
for e in errors:
    print(e)
sys.exit(1 if errors else 0)
PY
}

echo "1. packed: U0 half of Umf"
atRest "$workDir/packed" 0.5 1
cd "$workDir/packed" || fail "cd"
runSolver
grep -q "^bedAtRest rest: the bed has been at rest (its speed below 0.01 m/s) since t = " \
    log.dpmFoam2D || fail "the packed bed's run not ended at rest: $(grep '^bedAtRest' log.dpmFoam2D | tail -3)"
check . -1 1 yes || fail "the packed bed's rows or end differ from the particle files (above)"

echo "2. fluidized: U0 1.25 Umf, 0.3 s"
atRest "$workDir/fluidized" 1.25 0.3
cd "$workDir/fluidized" || fail "cd"
runSolver
check . -1 0.3 no || fail "the fluidized bed's rows or end differ from the particle files (above)"
py - <<'PY' || fail "the fluidized bed not moving faster than 0.01 m/s from 0.05 s"
import glob
rows = [l.split() for f in glob.glob("postProcessing/rest/*/bedAtRest.dat")
        for l in open(f) if not l.startswith("#")]
slow = [r for r in rows if float(r[0]) >= 0.05 - 1e-9 and float(r[1]) < 0.01]
print("fluidized: %d rows, the slowest from 0.05 s %.3g m/s" % (len(rows), min(
    float(r[1]) for r in rows if float(r[0]) >= 0.05 - 1e-9)))
raise SystemExit(1 if slow else 0)
PY

echo "3. packed, stopped half way through its rest and restarted"
rest=$(awk '!/^#/ && $3 >= 0 { print $3; exit }' "$workDir"/packed/postProcessing/rest/0/bedAtRest.dat)
stop=$(awk -v s="$rest" 'BEGIN { printf "%.2f", s + 0.05 }')
atRest "$workDir/restarted" 0.5 "$stop"
cd "$workDir/restarted" || fail "cd"
runSolver
setEntry system/controlDict endTime 1
runSolver
since=$(sed -n "s/^bedAtRest rest: t = $stop, .* since t = \([^ ]*\)$/\1/p" log.dpmFoam2D | head -1)
awk -v a="$since" -v b="$rest" 'BEGIN { exit !(a != "" && (a - b)^2 < 1e-18) }' \
    || fail "the restart does not know since when the bed was at rest ($rest s): $(grep '^bedAtRest' log.dpmFoam2D | head -3)"
check . "$stop" 1 yes || fail "the restarted run's rows or end differ (above)"
[ "$(ls -d "$workDir"/packed/[0-9]* | xargs -n1 basename | sort -g | tail -1)" \
  = "$(ls -d [0-9]* | sort -g | tail -1)" ] || fail "the restarted run ends elsewhere than the uninterrupted one"

expectFailure speed segregation/bedAtRest rest "speed 0;" \
    "Entry 'speed' = 0" "controlDict.functions.rest" "allowed: .* > 0"
expectFailure duration segregation/bedAtRest rest "duration -1;" \
    "Entry 'duration' = -1" "allowed: .* > 0"
expectFailure unknown segregation/bedAtRest rest "durration 1;" "durration" "duration"

pass "bedAtRest measures the bed's speed as the particle files give it, ends a packed bed's run after its rest, not a bubbling one's, and restarts knowing since when"
