#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmStudy on a reduced study: w_small 0.5 at 1 and 64 bar with 5 % of
# Table 3's particles (331 small + 72 large), 0.1 s of settling, 0.1 s of
# gas, restart states every 0.02 s, two cases at once.
# Expected:
#   1. its solvers (two at once) wait passively (OMP_WAIT_POLICY);
#      a second dpmStudy started meanwhile skips the running case (and
#      leaves its time directories alone); killed (SIGTERM) while the first
#      case runs, it stops its solvers;
#   2. run again, it continues that case from its last written time (the
#      new log starts from the saved state, the old one is kept as
#      log.dpmFoam2D.1) and runs the rest; one packed bed serves both
#      pressures (dpmPackBed ran once);
#   3. results/: summary.csv with both cases at t = 0.1 (and the bed
#      statistics of dpmBedStatistics), windows.csv (M in windows of -mean
#      s, checked against the function object's rows), the M(t) figures per pressure and
#      per mass fraction, indices.png, hydrodynamics.png, snapshots.png;
#   4. a third run finds everything finished and runs nothing; status
#      shows the bed and both cases done at 0.1 s, and takes a running
#      case's time and ETA from the last Progress line of a log read from
#      its end (checked on a 4.5-MB log); two results at once
#      (two copies of a work queue finishing together) both succeed, the
#      second waiting for the first, and make the same summary.csv;
#   5. -excessVelocity 0.2 gives a case with U0 = Umf + 0.2 m/s;
#   6. -seeds 2: a bed per seed (packed from seeds 1 and 2: different
#      beds), each case started from its own seed's bed, an ensemble row
#      of two in results/ensemble.csv;
#   7. -variant upwind: the case's fvSchemes edited, the edits recorded in
#      constant/variant and results/variants.md; a rerun from that record
#      makes the same case; a changed variant file, an unknown variant and
#      a variant naming an entry the template lacks are refused; upwind (the
#      gas's numerics) starts from the template's bed, a variant of the
#      particles' friction from a bed of its own packed with its edit;
#   8. a case that a second dpmStudy started while the first was busy is
#      skipped by the first when its turn comes (not run twice).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
export WM_PROJECT_SITE="${WM_PROJECT_SITE:-$DPMFOAM2D_PROJECT}"
cd "$workDir" || fail "cd"

studyArgs=(-w 0.5 -p 1 64 -j 2 -scale 0.05 -settleTime 0.1
           -endTime 0.1 -writeInterval 0.02 -mean 0.05 -interval 2)
study() { dpmStudy run study "${studyArgs[@]}" "$@"; }
case1=study/w0.50_1bar

echo "1. start, then kill while $case1 runs"
# dpmStudy itself in the background (not a function's subshell), so that
# the signal reaches it
# (its cases share the cores: it makes their OpenMP threads wait passively)
env -u OMP_WAIT_POLICY dpmStudy run study "${studyArgs[@]}" > log.study1 2>&1 &
pid=$!
for i in $(seq 1 600)
do
    [ -f "$case1/0.04/uniform/dem.state" ] && break
    kill -0 $pid 2>/dev/null || { cat log.study1; fail "dpmStudy ended before it was killed"; }
    sleep 0.2
done
[ -f "$case1/0.04/uniform/dem.state" ] || { kill $pid; fail "no 0.04 written in 120 s"; }
# A second dpmStudy leaves the running case alone (its solver paused meanwhile,
# so that it is still running when the second one has looked)
solver=
for p in $(pgrep -x -P $pid dpmFoam2D)
do
    [ "$(readlink /proc/$p/cwd)" = "$(cd $case1 && pwd -P)" ] && solver=$p
done
[ -n "$solver" ] || { kill $pid; fail "no solver of $case1 running"; }
tr '\0' '\n' < /proc/$solver/environ | grep -qx OMP_WAIT_POLICY=passive \
    || { kill $pid; fail "dpmStudy -j 2 did not give its solvers OMP_WAIT_POLICY=passive"; }
kill -STOP $solver
study -p 1 -noPictures > log.studyTwice 2>&1 || { kill -CONT $solver; cat log.studyTwice; fail "second dpmStudy failed"; }
kill -CONT $solver
cat log.studyTwice
grep -q "^w0.50_1bar *skipped: process [0-9]* runs in it" log.studyTwice \
    || fail "a second dpmStudy did not skip the running case"
ls -d "$case1"/*.incomplete 2>/dev/null && fail "a second dpmStudy set aside a time being written"
kill -TERM $pid
wait $pid
sleep 1
kill -0 $pid 2>/dev/null && fail "dpmStudy still runs after SIGTERM"
for p in $(pgrep -x dpmFoam2D)
do
    [ "$(readlink /proc/$p/cwd)" = "$(cd $case1 && pwd -P)" ] && fail "a solver of the study still runs"
done
grep -q "End" "$case1/log.dpmFoam2D" && fail "$case1 finished before the kill (make it longer)"

echo "2. run again"
study > log.study2 2>&1 || { cat log.study2; fail "dpmStudy (second run)"; }
cat log.study2
[ -f "$case1/log.dpmFoam2D.1" ] || fail "no log.dpmFoam2D.1 (the first run's log)"
grep -q "^Particles: 403 read from .*/0\.0[2-9]*/uniform/dem.state" "$case1/log.dpmFoam2D" \
    || fail "$case1 did not continue from its last written time"
[ $(ls study/beds/w0.50/log.dpmPackBed* | wc -l) = 1 ] || fail "the bed was packed twice"
for c in study/w0.50_1bar study/w0.50_64bar
do
    grep -q "read from .*beds/w0.50/constant/packedBed.state" $c/log.dpmFoam2D* \
        || fail "$c did not start from the shared bed"
done

echo "3. results"
py - <<'PY' || fail "summary.csv"
import csv
rows = list(csv.DictReader(open("study/results/summary.csv")))
print(rows)
assert [r["case"] for r in rows] == ["w0.50_1bar", "w0.50_64bar"], rows
for r in rows:
    assert abs(float(r["time"]) - 0.1) < 1e-9, r
    assert 0 <= float(r["Mfinal"]) <= 1.2, r
    # dpmBedStatistics read the solver's binary voidage fields: a bed of
    # 403 particles (940 mm^2 of discs, about 10 mm deep in the 150 mm
    # wide column) fills one or two 7.5-mm cell rows; its emulsion lies
    # between close packing (0.26) and the bubble threshold (0.8)
    assert min(abs(float(r["bedHeight"]) - h) for h in (0.0075, 0.015)) < 1e-12, r
    assert 0.0 <= float(r["bubbleFraction"]) <= 1.0, r
    assert 0.26 < float(r["emulsionVoidage"]) <= 0.8, r
    assert float(r["speedRmsSmall"]) > 0 and float(r["speedRmsLarge"]) > 0, r
# windows.csv: -mean 0.05 over 0.1 s of gas = two windows per case; the
# 64-bar case ran once (one start-time directory): its window means are
# those of the function object's rows with 0 < t <= 0.05 and 0.05 < t <= 0.1
import glob
import numpy as np
win = list(csv.DictReader(open("study/results/windows.csv")))
assert [(r["case"], float(r["tStart"]), float(r["tEnd"])) for r in win] == \
    [(c, a, b) for c in ("w0.50_1bar", "w0.50_64bar") for a, b in ((0, 0.05), (0.05, 0.1))], win
dat = glob.glob("study/w0.50_64bar/postProcessing/laceyIndex/*/laceyIndex.dat")
assert len(dat) == 1, dat
t, M = np.loadtxt(dat[0], usecols=(0, 1), unpack=True)
for r, (a, b) in zip(win[2:], ((0, 0.05), (0.05, 0.1))):
    sel = (t > a + 1e-9) & (t <= b + 1e-9)
    assert sel.sum() == 5, t
    assert abs(float(r["M"]) - M[sel].mean()) < 1e-12, (r, M[sel].mean())
PY
grep -q "^| w0.50_64bar | [0-9.]* | [0-9.]* |$" study/results/summary.md \
    || fail "no row of window means in summary.md"
for f in summary.md mixing_1bar.png mixing_64bar.png mixing_w0.50.png indices.png \
         hydrodynamics.png snapshots.png snapshots/w0.50_1bar.png
do
    [ -s "study/results/$f" ] || fail "no results/$f"
done

echo "4. nothing left to run"
study -noPictures > log.study3 2>&1 || fail "dpmStudy (third run)"
cp study/results/summary.csv summary.before
# the second is started while the first holds the lock (held for the test by flock)
exec 8>study/results/.lock && flock 8 || fail "flock"
dpmStudy results study -noPictures -mean 0.05 > log.results1 2>&1 & first=$!
dpmStudy results study -noPictures -mean 0.05 > log.results2 2>&1 & second=$!
# released once both wait (or after 60 s), however slowly they start
for i in $(seq 1 300)
do
    [ "$(cat log.results1 log.results2 | grep -c "^results: waiting for another dpmStudy")" = 2 ] && break
    sleep 0.2
done
flock -u 8; exec 8>&-
wait $first || { cat log.results1; fail "the first of two results failed"; }
wait $second || { cat log.results2; fail "the second of two results failed"; }
[ $(cat log.results1 log.results2 | grep -c "^results: waiting for another dpmStudy") = 2 ] \
    || fail "results did not wait for the lock's holder"
cmp -s summary.before study/results/summary.csv || fail "two results at once changed summary.csv"
[ $(grep -c "finished (t = 0.1 s)" log.study3) = 2 ] || { cat log.study3; fail "third run ran something"; }
dpmStudy status study > log.status 2>&1 || { cat log.status; fail "dpmStudy status"; }
cat log.status
grep -q "^beds/w0.50 *done" log.status || fail "status: the bed not done"
for c in w0.50_1bar w0.50_64bar
do
    grep -q "^$c *done *- *0.1 of 0.1 s$" log.status || fail "status: $c not done at 0.1 s"
done
# A running case's time and ETA come from the last Progress line, read from
# the log's end (a 60-s case's log holds ~200 MB)
py - <<PY || fail "status: the last Progress line of a log"
import sys
from dpmfoam2d.study.slurm import last_progress
with open("fake.log", "w") as f:
    f.write("Progress: t = 1 s (2%), 40 wall s per simulated s, ETA 2360 s\n")
    f.write(("x" * 99 + "\n") * 30000)
    f.write("Progress: t = 2.5 s (4%), 41 wall s per simulated s, ETA 2357 s\n")
    f.write(("x" * 99 + "\n") * 15000)    # 1.5 MB: beyond the first tail read
assert last_progress("fake.log") == ("2.5", 2357.0), last_progress("fake.log")
open("none.log", "w").write("Time = 1\n" * 10)
assert last_progress("none.log") == (None, None), last_progress("none.log")
PY
echo "5. a variant study at a given U0 - Umf"
dpmStudy run variant -w 0.5 -p 64 -j 1 -scale 0.05 -settleTime 0.1 -endTime 0.02 \
    -writeInterval 0.02 -mean 0.01 -excessVelocity 0.2 -noPictures > log.variant 2>&1 \
    || { cat log.variant; fail "dpmStudy -excessVelocity"; }
grep -q "(set by U0 - Umf 0.2 m/s)" variant/w0.50_64bar/log.dpmFoam2D \
    || fail "the variant case's U0 was not set by -excessVelocity"
py - <<'PY' || fail "variant summary.csv"
import csv
r = list(csv.DictReader(open("variant/results/summary.csv")))[0]
print("Umf", r["Umf"], "U0", r["U0"])
assert abs(float(r["U0"]) - float(r["Umf"]) - 0.2) < 1e-6, r
PY
echo "6. seeds"
short=(-w 0.5 -p 64 -scale 0.05 -settleTime 0.1 -endTime 0.02 -writeInterval 0.02
       -mean 0.01 -noPictures)
dpmStudy run seeds "${short[@]}" -seeds 2 -j 2 > log.seeds 2>&1 || { cat log.seeds; fail "dpmStudy -seeds 2"; }
for k in 1 2
do
    grep -q "at random in .* (seed $k)" seeds/beds/w0.50_seed$k/log.dpmPackBed \
        || fail "bed w0.50_seed$k was not packed with seed $k"
    grep -q "read from .*beds/w0.50_seed$k/constant/packedBed.state" \
        seeds/w0.50_64bar_seed$k/log.dpmFoam2D || fail "case seed $k did not start from its bed"
done
cmp -s seeds/beds/w0.50_seed1/constant/packedBed.state seeds/beds/w0.50_seed2/constant/packedBed.state \
    && fail "the two seeds gave the same bed"
py - <<'PY' || fail "ensemble of two seeds"
import csv
r = list(csv.DictReader(open("seeds/results/ensemble.csv")))
assert len(r) == 1 and r[0]["n"] == "2" and r[0]["seeds"] == "1 2", r
PY

echo "7. variants"
dpmStudy run variants "${short[@]}" -j 1 -variant upwind > log.variants 2>&1 \
    || { cat log.variants; fail "dpmStudy -variant upwind"; }
vcase=variants/w0.50_64bar_upwind
grep -q "div(voidagePhi,U) *Gauss upwind;" $vcase/system/fvSchemes || fail "upwind not applied"
head -1 $vcase/constant/variant | grep -q "^# variant upwind$" || fail "no record of the variant"
grep -q "^## upwind" variants/results/variants.md || fail "results/variants.md lacks upwind"
grep -q ",upwind," variants/results/summary.csv || fail "summary.csv lacks the variant"
dpmStudy run rerun "${short[@]}" -j 1 -variant "$PWD/$vcase/constant/variant" > log.rerun 2>&1 \
    || { cat log.rerun; fail "rerun from the record"; }
diff -r -q $vcase/system rerun/w0.50_64bar_upwind/system || fail "the rerun's dictionaries differ"
cmp $vcase/constant/variant rerun/w0.50_64bar_upwind/constant/variant || fail "the rerun's record differs"
grep -q '/beds/w0.50/constant/packedBed.state' $vcase/constant/packedBed \
    || fail "the gas-only variant upwind did not start from the template's bed"
mkdir -p changed && echo "constant/particleProperties contact/frictionParticle 0.3" > changed/friction
dpmStudy run variants "${short[@]}" -j 1 -variant "$PWD/changed/friction" > log.friction 2>&1 \
    || { cat log.friction; fail "dpmStudy -variant friction"; }
fbed=variants/beds/w0.50_friction
[ -f $fbed/constant/packedBed.state ] || fail "a variant of the particles packed no bed of its own"
[ "$(foamDictionary -entry contact/frictionParticle -value $fbed/constant/particleProperties)" = 0.3 ] \
    || fail "the variant's own bed was packed without its edit"
grep -q '/beds/w0.50_friction/constant/packedBed.state' variants/w0.50_64bar_friction/constant/packedBed \
    || fail "the variant's case does not start from its own bed"
grep -q "Particles: packing" variants/w0.50_64bar_friction/log.dpmFoam2D \
    && fail "the variant's case packed a bed instead of loading its own (an edit of particleProperties dropped the packedBed include)"
sed 's/Gauss upwind/Gauss linearUpwind grad(U)/' \
    "$DPMFOAM2D_PROJECT/tutorials/paperStudy/variants/upwind" > changed/upwind
dpmStudy run variants "${short[@]}" -variant "$PWD/changed/upwind" > log.changed 2>&1 \
    && fail "a changed variant file was accepted"
grep -q "the edits differ" log.changed || { cat log.changed; fail "no message on a changed variant"; }
dpmStudy run variants "${short[@]}" -variant upwnid > log.unknown 2>&1 && fail "an unknown variant ran"
grep -q "no variant 'upwnid' .*the template's variants: .*upwind" log.unknown \
    || { cat log.unknown; fail "no message on an unknown variant"; }
echo "system/fvSchemes divSchemes/div(phi,U) Gauss upwind" > changed/wrongEntry
dpmStudy run wrong "${short[@]}" -variant "$PWD/changed/wrongEntry" > log.wrong 2>&1 && fail "a wrong entry ran"
grep -q "has no entry 'divSchemes/div(phi,U)'" log.wrong || { cat log.wrong; fail "no message on a wrong entry"; }
echo "8. a case another dpmStudy started meanwhile is skipped when its turn comes"
ov=(-w 0.5 -scale 0.05 -settleTime 0.1 -endTime 0.04 -writeInterval 0.02 -mean 0.02
    -noPictures -interval 1 -j 1)
solverIn() { for p in $(pgrep -x dpmFoam2D); do [ "$(readlink /proc/$p/cwd)" = "$(cd "$1" && pwd -P)" ] && echo $p; done; }
waitSolver()
{
    local s=
    for i in $(seq 1 600); do [ -d "$1" ] && s="$(solverIn "$1")"; [ -n "$s" ] && break; sleep 0.2; done
    [ -n "$s" ] || fail "no solver started in $1"
    echo $s
}
dpmStudy run overlap "${ov[@]}" -p 1 64 > log.overlapA 2>&1 &
pidA=$!
soA="$(waitSolver overlap/w0.50_1bar)"
kill -STOP $soA                         # holds the first study at its 1-bar case
dpmStudy run overlap "${ov[@]}" -p 64 > log.overlapB 2>&1 &
pidB=$!
soB="$(waitSolver overlap/w0.50_64bar)"
kill -STOP $soB                         # the 64-bar case is running, in the second study
kill -CONT $soA
for i in $(seq 1 600); do grep -q "skipped (process $soB runs in it)" log.overlapA && break; sleep 0.2; done
kill -CONT $soB
wait $pidA || { cat log.overlapA; fail "the first study failed"; }
wait $pidB || { cat log.overlapB; fail "the second study failed"; }
grep -q "^w0.50_64bar *skipped (process $soB runs in it)" log.overlapA \
    || { cat log.overlapA; fail "the first study did not skip the case the second had started"; }
[ -e overlap/w0.50_64bar/log.dpmFoam2D.1 ] && fail "the 64-bar case was started twice"
grep -q "^End" overlap/w0.50_64bar/log.dpmFoam2D || fail "the 64-bar case did not finish"
pass "dpmStudy runs, resumes after a kill, shares the bed, sums up, sets U0 - Umf, seeds, variants, skips a case started meanwhile"
