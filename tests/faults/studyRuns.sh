#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmStudy's runs and resumes on a reduced study (w 0.5 at 1 bar, 5 % of
# Table 3's particles, 0.1 s of settling):
#   1. -endTime 0.02, below the template's write interval (1 s): the case
#      ends with 0.02 on disk (complete restart state), status says done
#      at 0.02 of 0.02 s, the same command again runs nothing;
#   2. -endTime 0.04: the case continues from 0.02 and ends at 0.04;
#   3. a dpmStudy killed by SIGKILL while its solver runs: the solver holds
#      the case's lock on (dpmStudy hands it down), status shows it
#      running and counts 1 running, a new dpmStudy skips the case naming
#      the solver's pid; the solver killed too, the next dpmStudy continues
#      the case from its last complete time and finishes it.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
export WM_PROJECT_SITE="${WM_PROJECT_SITE:-$DPMFOAM2D_PROJECT}"
cd "$workDir" || fail "cd"

args=(-w 0.5 -p 1 -j 1 -scale 0.05 -settleTime 0.1 -mean 0.01 -noPictures -interval 1)
case1=study/w0.50_1bar
complete() { [ -f "$1/U" ] && [ -f "$1/p_rgh" ] && [ -f "$1/uniform/dem.state" ]; }

echo "1. -endTime 0.02, the template writing every 1 s"
dpmStudy run study "${args[@]}" -endTime 0.02 > log.study1 2>&1 || { cat log.study1; fail "dpmStudy -endTime 0.02"; }
complete $case1/0.02 || fail "-endTime 0.02: no complete 0.02 in $case1"
dpmStudy status study > log.status1 2>&1 || { cat log.status1; fail "status"; }
cat log.status1
grep -q "^w0.50_1bar *done *- *0.02 of 0.02 s$" log.status1 || fail "status: the case not done at 0.02 s"
dpmStudy run study "${args[@]}" -endTime 0.02 > log.study2 2>&1 || { cat log.study2; fail "dpmStudy again"; }
grep -q "^w0.50_1bar *finished (t = 0.02 s)" log.study2 || { cat log.study2; fail "the rerun did not find the case finished"; }
[ -e $case1/log.dpmFoam2D.1 ] && fail "the rerun ran the finished case again"
echo "ok   ended at 0.02 on disk, done, not run again"

echo "2. -endTime 0.04 continues"
dpmStudy run study "${args[@]}" -endTime 0.04 > log.study3 2>&1 || { cat log.study3; fail "dpmStudy -endTime 0.04"; }
grep -q "read from .*/0.02/uniform/dem.state" $case1/log.dpmFoam2D || fail "did not continue from 0.02"
complete $case1/0.04 || fail "-endTime 0.04: no complete 0.04"
echo "ok   continued from 0.02 to 0.04"

echo "3. dpmStudy killed by SIGKILL while its solver runs"
dpmStudy run study "${args[@]}" -endTime 2 > log.study4 2>&1 &
study=$!
solver=
for i in $(seq 1 600)
do
    solver=$(pgrep -x -P $study dpmFoam2D)
    [ -n "$solver" ] && grep -q "pid $solver " $case1/.dpmLock 2>/dev/null && break
    kill -0 $study 2>/dev/null || { cat log.study4; fail "dpmStudy ended before it was killed"; }
    sleep 0.2
done
[ -n "$solver" ] || { kill $study; fail "no solver started"; }
trap 'kill -9 $solver 2>/dev/null' EXIT
kill -9 $study
wait $study 2>/dev/null
kill -0 $solver || fail "the solver ended with its dpmStudy"
dpmStudy status study > log.status2 2>&1 || { cat log.status2; fail "status"; }
cat log.status2
grep -q "^w0.50_1bar *running *local pid $solver " log.status2 || fail "status: the case not running under pid $solver"
grep -q "in 1 case(s), 1 running" log.status2 || fail "status did not count the running case"
dpmStudy run study "${args[@]}" -endTime 2 > log.study5 2>&1 || { cat log.study5; fail "dpmStudy beside the solver"; }
grep -q "^w0.50_1bar *skipped: process $solver runs in it" log.study5 \
    || { cat log.study5; fail "a new dpmStudy did not skip the running case"; }
dpmFoam2D -case "$PWD/$case1" > log.byHand 2>&1 && fail "a solver started by hand in the running case ran"
grep -q "is in use by dpmFoam2D (pid $solver " log.byHand || { tail -5 log.byHand; fail "no message naming the holder"; }
kill -9 $solver
wait $solver 2>/dev/null
trap - EXIT
dpmStudy run study "${args[@]}" -endTime 0.06 > log.study6 2>&1 || { cat log.study6; fail "dpmStudy after the kill"; }
grep -q "read from .*/0.0[4-9]*/uniform/dem.state" $case1/log.dpmFoam2D || fail "did not continue after the kill"
complete $case1/0.06 || fail "no complete 0.06 after the kill"
dpmStudy status study > log.status3 2>&1 || { cat log.status3; fail "status"; }
grep -q "^w0.50_1bar *done *- *0.06 of 0.06 s$" log.status3 || { cat log.status3; fail "status: not done at 0.06"; }
echo "ok   the orphaned solver kept the lock; after its kill the study continued and finished"
pass "dpmStudy saves and records end times below the write interval, resumes, and keeps one run a case"
