#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# One run a case (src/dpmCoupling/caseLock): while a solver runs in a case,
# a second dpmFoam2D and a dpmPackBed there are refused at once (exit 1,
# within 10 s) with one line naming the holder's pid, host and start and
# the lock file, leaving the case as it was; -postProcess needs no lock;
# a holder killed by SIGKILL leaves no stale lock: the next start continues
# from its last complete time. A bed that two cases share, outside both,
# is locked while a solver packs it: the second case's solver is refused
# naming the first. A lock path that is a link, a FIFO or a directory is
# refused, and nothing is written through a link.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

cd "$workDir" || fail "cd"
makeCase case
cd case || fail "cd case"
setEntry system/controlDict endTime 5          # runs until killed
dpmFoam2D > log.holder 2>&1 &
holder=$!
trap 'kill -9 $holder 2>/dev/null' EXIT
for i in $(seq 1 300)
do
    grep -q "pid $holder " .dpmLock 2>/dev/null && [ -d 0.01 ] && break
    kill -0 $holder 2>/dev/null || { tail -20 log.holder; fail "the first solver ended"; }
    sleep 0.2
done
grep -q "pid $holder " .dpmLock || fail "the first solver wrote no holder line into .dpmLock"
holderLine="in use by dpmFoam2D \(pid $holder on $(hostname), started [0-9-]+ [0-9:]+ UTC\), which holds the lock \"$PWD/.dpmLock\""

refused()
{
    local app="$1"; shift
    local start=$SECONDS
    timeout 30 "$app" "$@" > log.$app 2>&1
    local status=$?
    [ "$status" = 1 ] || { tail -5 log.$app; fail "a second $app in a running case: exit $status, not 1"; }
    [ $((SECONDS - start)) -le 10 ] || fail "the second $app took $((SECONDS - start)) s to be refused"
    grep -qE "^$app: the directory \"$PWD\" is $holderLine" log.$app \
        || { cat log.$app; fail "$app: no message naming the holder and the lock"; }
    echo "ok   $app refused: $(grep -m1 "is in use" log.$app)"
}
cp -r system system.before
refused dpmFoam2D
refused dpmPackBed
diff -r system system.before > /dev/null || fail "a refused run changed system/"
ls constant/packedBed.state >/dev/null 2>&1 && fail "a refused dpmPackBed wrote a bed"
dpmFoam2D -postProcess -func writeCellCentres -latestTime > log.postProcess 2>&1 \
    || { tail -10 log.postProcess; fail "-postProcess refused while a run holds the case"; }
echo "ok   -postProcess runs beside the solver"

kill -9 $holder
wait $holder 2>/dev/null
trap - EXIT
latest=$(foamListTimes -latestTime 2>/dev/null | tail -1)
[ -n "$latest" ] || fail "no time written before the kill"
next=$(py -c "print(round($latest + 0.01, 6))")
setEntry system/controlDict endTime "$next"
runSolver
grep -q "read from .*/uniform/dem.state" log.dpmFoam2D || fail "the run after the kill did not restart"
[ -f "$next/uniform/dem.state" ] || fail "the run after the kill did not reach $next"
grep -q "pid [0-9]* " .dpmLock || fail "no holder line after the restart"
echo "ok   after kill -9 of the holder the next run started (restarted from $latest, ended at $next)"

# A shared bed outside the cases, missing: the first solver packs it (3 s of
# settling) holding its directory's lock; the second is refused meanwhile
cd "$workDir" || fail "cd"
mkdir -p sharedBed
for c in caseA caseB
do
    makeCase $c
    setEntry $c/constant/particleProperties initialBed/settleTime 3
    setEntry $c/constant/particleProperties initialBed/file "\"$workDir/sharedBed/bed.state\""
done
(cd caseA && exec dpmFoam2D > log.packer 2>&1) &
packer=$!
trap 'kill -9 $packer 2>/dev/null' EXIT
for i in $(seq 1 300)
do
    grep -q "pid $packer " sharedBed/.dpmLock 2>/dev/null && break
    kill -0 $packer 2>/dev/null || { tail -20 caseA/log.packer; fail "the packing solver ended"; }
    sleep 0.1
done
grep -q "pid $packer " sharedBed/.dpmLock || fail "the packing solver did not lock the shared bed's directory"
[ -f sharedBed/bed.state ] && fail "the bed was saved before the second solver could be tried (packing too fast)"
(cd caseB && timeout 30 dpmFoam2D > log.second 2>&1)
status=$?
[ "$status" = 1 ] || { tail -5 caseB/log.second; fail "a second solver packing the shared bed: exit $status, not 1"; }
grep -qE "the directory \"$workDir/sharedBed\" is in use by dpmFoam2D \(pid $packer " caseB/log.second \
    || { tail -8 caseB/log.second; fail "the second solver's refusal does not name the packer"; }
echo "ok   a shared bed being packed is refused to a second case: $(grep -m1 "is in use" caseB/log.second | cut -c1-160)"
kill -9 $packer; wait $packer 2>/dev/null
trap - EXIT
# A lock path that is a link (to a file outside the case) or not a regular
# file is refused by the solver and the packer, and nothing is written
# through it: the link's target keeps its bytes
cd "$workDir" || fail "cd"
makeCase linked
printf 'not the lock\n' > victim
cp victim victim.before
ln -s ../victim linked/.dpmLock
notRegular()
{
    local what="$1" app="$2"; shift 2
    (cd linked && timeout 30 "$app" "$@" > log.$app 2>&1)
    local status=$?
    [ "$status" = 1 ] || { tail -5 linked/log.$app; fail "$app with a lock that is $what: exit $status, not 1"; }
    grep -qE "^The lock file \"$workDir/linked/.dpmLock\" is $what; a lock must be a regular file" linked/log.$app \
        || { tail -8 linked/log.$app; fail "$app: no message naming the lock that is $what"; }
    cmp -s victim victim.before || fail "$app wrote through the lock link into the file it names"
    echo "ok   $app refused a lock that is $what: $(grep -m1 "The lock file" linked/log.$app | cut -c1-140)"
}
notRegular "a symbolic link" dpmFoam2D
notRegular "a symbolic link" dpmPackBed
rm linked/.dpmLock && mkfifo linked/.dpmLock
notRegular "not a regular file" dpmFoam2D
rm linked/.dpmLock && mkdir linked/.dpmLock
notRegular "not a regular file" dpmPackBed
rmdir linked/.dpmLock
# The same for a shared bed's directory outside the case
mkdir -p linkedBed && ln -s ../victim linkedBed/.dpmLock
setEntry linked/constant/particleProperties initialBed/file "\"$workDir/linkedBed/bed.state\""
(cd linked && timeout 30 dpmFoam2D > log.bed 2>&1)
grep -qE "The lock file \"$workDir/linkedBed/.dpmLock\" is a symbolic link" linked/log.bed \
    || { tail -8 linked/log.bed; fail "the shared bed's lock link was not refused"; }
cmp -s victim victim.before || fail "the packer wrote through the shared bed's lock link"
echo "ok   a shared bed's lock link is refused"

pass "a second solver or packer in a running case is refused naming the holder; kill -9 leaves no stale lock; a shared bed is locked while packed; a lock that is a link or not a regular file is refused and nothing is written through it"
