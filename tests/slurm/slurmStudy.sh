#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmStudy on a real single-node Slurm cluster (Debian's slurmctld, slurmd,
# munge, started here as root and stopped at the end). A tiny study: w 0.5
# at 1 and 64 bar, 5 % of Table 3's particles, 0.1 s of settling.
# Expected:
#   1. bad input: no sbatch on PATH, an sbatch error (no such partition),
#      a local dpmStudy running in the study: a clear message, nothing
#      submitted;
#   2. `submit -- --cpus-per-task=1` submits the beds, the cases (after the
#      beds) and results/ (after the cases); the jobs show the case names;
#      a second submission while they are queued submits nothing; every
#      case finishes; results/summary.csv equals a local run's to the last
#      digit (same inputs, one thread: the same bits);
#   3. a case task cancelled (scancel) mid-run shows as stopped in
#      status and is completed by a second submission, which submits only
#      that case; it ends as the uninterrupted local run;
#   4. no daemon is left behind.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
. "$testsDir/slurm/slurmFunctions"
cd "$workDir" || fail "cd"

tiny=(-w 0.5 -p 1 64 -scale 0.05 -settleTime 0.1 -writeInterval 0.01 -mean 0.01
      -noPictures)

echo "0. a local run of the tiny study (the reference)"
dpmStudy run local "${tiny[@]}" -endTime 0.04 -j 2 -interval 5 > log.local 2>&1 || { cat log.local; fail "local run"; }

startSlurm "$workDir/slurm"
sinfo

echo "1. bad input"
env PATH="$FOAM_USER_APPBIN:$DPMFOAM2D_PROJECT/bin" dpmStudy submit nosbatch "${tiny[@]}" \
    > log.nosbatch 2>&1 && fail "submit without sbatch went on"
grep -q "no sbatch on PATH" log.nosbatch || { cat log.nosbatch; fail "no message without sbatch"; }
[ -e nosbatch ] && fail "submit without sbatch made the study directory"
dpmStudy submit badPartition "${tiny[@]}" -endTime 0.04 -- --partition=nosuch > log.badPartition 2>&1 \
    && fail "an sbatch error went unnoticed"
grep -q "sbatch refused the beds: .*[Pp]artition" log.badPartition \
    || { cat log.badPartition; fail "no message on an sbatch error"; }
[ -z "$(squeue -h)" ] || fail "something was submitted after an sbatch error"
dpmStudy run busy "${tiny[@]}" -p 1 -endTime 5 -j 1 -interval 5 > log.busyLocal 2>&1 &
busyPid=$!
# the local run holds the study's lock (shared) while it runs
for i in $(seq 1 300); do [ -e busy/.dpmStudy.lock ] && ! flock -n -x busy/.dpmStudy.lock true && break; sleep 0.2; done
dpmStudy submit busy "${tiny[@]}" -p 1 -endTime 5 > log.busy 2>&1 && fail "submit beside a local dpmStudy went on"
kill -TERM $busyPid; wait $busyPid
grep -q "a local dpmStudy (process $busyPid) runs this study" log.busy || { cat log.busy; fail "no message on a local run"; }
[ -z "$(squeue -h)" ] || fail "something was submitted beside a local run"

echo "2. the study through Slurm"
dpmStudy submit cluster "${tiny[@]}" -endTime 0.04 -- --cpus-per-task=1 > log.submit 2>&1 \
    || { cat log.submit; fail "dpmStudy submit"; }
cat log.submit
grep -q "beds submitted as Slurm job array [0-9]* (1 tasks)" log.submit || fail "beds not submitted"
grep -q "cases submitted as Slurm job array [0-9]* (2 tasks, after [0-9]*)" log.submit || fail "cases not submitted"
grep -q "results/ submitted as Slurm job [0-9]*" log.submit || fail "results not submitted"
squeue -o "%i %j %T %r"
dpmStudy submit cluster "${tiny[@]}" -endTime 0.04 > log.submitTwice 2>&1 || { cat log.submitTwice; fail "second submission"; }
cat log.submitTwice
grep -q "nothing to submit" log.submitTwice || fail "a second submission submitted again"
waitQueueEmpty 300
# finished jobs stay known to the controller for MinJobAge (600 s)
scontrol -o show job > log.jobs
grep -o "JobName=[^ ]*" log.jobs
for c in w0.50_1bar w0.50_64bar
do
    grep -q "JobName=$c " log.jobs || fail "no job named $c"
    grep -q "^End" cluster/$c/log.dpmFoam2D || { tail cluster/$c/log.dpmFoam2D; fail "$c did not finish"; }
    grep -q "task [0-9]*_[0-9]*: exit 0" cluster/$c/log.slurm || fail "no task log in $c"
done
dpmStudy status cluster > log.status 2>&1
cat log.status
[ $(grep -c " done " log.status) = 3 ] || fail "status does not show the bed and both cases done"
py - <<'PY' || fail "the Slurm run differs from the local run"
import csv
def rows(d):
    out = {}
    for r in csv.DictReader(open(d + "/results/summary.csv")):
        out[r["case"]] = r
    return out
L, C = rows("local"), rows("cluster")
assert sorted(L) == sorted(C) == ["w0.50_1bar", "w0.50_64bar"], (L, C)
for case in L:
    for k in ("time", "M0", "Mfinal", "Mmean", "vertical", "horizontal", "U0",
              "bedHeight", "emulsionVoidage", "speedRmsSmall"):
        assert L[case][k] == C[case][k], (case, k, L[case][k], C[case][k])
print("same as the local run")
PY

echo "3. a cancelled task, completed by a second submission"
dpmStudy submit cancel "${tiny[@]}" -endTime 0.04 > log.cancel1 2>&1 || { cat log.cancel1; fail "submit"; }
victim=cancel/w0.50_64bar
for i in $(seq 1 600)
do
    [ -f $victim/0.01/uniform/dem.state ] && break
    sleep 0.2
done
[ -f $victim/0.01/uniform/dem.state ] || fail "no 0.01 written"
task="$(cat $victim/.dpmStudy.slurm)"
scancel "$task" || fail "scancel $task"
waitQueueEmpty 300
grep -q "^End" $victim/log.dpmFoam2D && fail "the case ended before it was cancelled (make it longer)"
dpmStudy status cancel > log.status2 2>&1
cat log.status2
grep -q "^w0.50_64bar *stopped" log.status2 || fail "status does not show the cancelled case stopped"
dpmStudy submit cancel "${tiny[@]}" -endTime 0.04 > log.cancel2 2>&1 || { cat log.cancel2; fail "resubmit"; }
cat log.cancel2
grep -q "cases submitted as Slurm job array [0-9]* (1 tasks)" log.cancel2 \
    || fail "the second submission did not submit just the cancelled case"
waitQueueEmpty 300
grep -q "^End" $victim/log.dpmFoam2D || fail "the cancelled case was not completed"
py - <<'PY' || fail "the completed case differs from the uninterrupted run"
import csv
L = {r["case"]: r for r in csv.DictReader(open("local/results/summary.csv"))}
C = {r["case"]: r for r in csv.DictReader(open("cancel/results/summary.csv"))}
for k in ("time", "Mfinal", "Mmean", "vertical", "horizontal"):
    assert L["w0.50_64bar"][k] == C["w0.50_64bar"][k], (k, L["w0.50_64bar"][k], C["w0.50_64bar"][k])
print("completed as the uninterrupted run")
PY

echo "4. no daemon left"
pids="$(cat slurm/slurmd.pid slurm/slurmctld.pid slurm/munged.pid)"
stopSlurm
for p in $pids; do kill -0 $p 2>/dev/null && fail "daemon $p still runs"; done
pass "dpmStudy through Slurm: submits, refuses bad input, resumes a cancelled case, equals a local run"
