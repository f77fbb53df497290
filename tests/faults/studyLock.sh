#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmStudy's locks and the paths it writes, on a reduced study (w 0.5 at
# 1 bar, 5 % of Table 3's particles; nothing is packed or run):
#   1. a bed's, a case's or results/' lock that is a symbolic link to a file
#      outside the study: refused naming the link, the file unchanged; so
#      is a results/ that is a link to a directory outside, left empty;
#   2. a case's lock that is a directory or a FIFO: refused naming it (the
#      FIFO at once, not waited on);
#   3. the study on a read-only file system (a read-only bind mount in a
#      mount namespace of its own; left out where unshare cannot make one):
#      refused naming a path, no traceback;
#   4. submit beside the pid file of a local dpmStudy killed by SIGKILL,
#      whose pid another process has since: not refused (sbatch is reached,
#      a stub here that refuses everything); a process that does hold the
#      study's lock as a local run does still refuses it, named.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
cd "$workDir" || fail "cd"

args=(-w 0.5 -p 1 -scale 0.05 -settleTime 0.1 -noPictures -endTime 0.02)    # run's and submit's
case1=w0.50_1bar
noTraceback() { ! grep -q "Traceback" "$1" || { cat "$1"; fail "$2: a traceback"; }; }

echo "1. a lock that is a symbolic link"
n=0
for lock in beds/w0.50/.dpmLock $case1/.dpmLock results/.lock
do
    n=$((n + 1))
    study=link$n
    echo "precious $n" > outside$n
    mkdir -p "$study/$(dirname "$lock")"
    ln -s "$PWD/outside$n" "$study/$lock"
    if [ "$lock" = results/.lock ]
    then
        dpmStudy results $study -noPictures > log.link$n 2>&1 && fail "results/ made beside a linked lock"
    else
        dpmStudy run $study "${args[@]}" -j 1 > log.link$n 2>&1 && fail "a study ran beside a linked lock $lock"
    fi
    noTraceback log.link$n "a linked $lock"
    grep -q "$study/$lock is a symbolic link" log.link$n || { cat log.link$n; fail "no message naming the link $lock"; }
    [ "$(cat outside$n)" = "precious $n" ] || fail "the file $lock points to was written: $(cat outside$n)"
    echo "ok   $lock: $(tail -1 log.link$n | cut -c1-160)"
done

mkdir -p outsideDir linkDir
ln -s "$PWD/outsideDir" linkDir/results
dpmStudy results linkDir -noPictures > log.linkDir 2>&1 && fail "results/ made in a linked directory"
noTraceback log.linkDir "a linked results/"
grep -q "linkDir/results: a symbolic link, not a directory of its own" log.linkDir \
    || { cat log.linkDir; fail "no message naming the linked results/"; }
[ -z "$(ls -A outsideDir)" ] || fail "results/ written where its link points: $(ls -A outsideDir)"
echo "ok   results/ a link: $(tail -1 log.linkDir | cut -c1-160)"

echo "2. a case's lock that is a directory or a FIFO"
mkdir -p lockDir/$case1/.dpmLock lockFifo/$case1
mkfifo lockFifo/$case1/.dpmLock
for kind in Dir Fifo
do
    timeout 60 dpmStudy run lock$kind "${args[@]}" -j 1 > log.lock$kind 2>&1 && fail "a study ran beside a lock $kind"
    noTraceback log.lock$kind "a lock $kind"
    grep -q "lock$kind/$case1/.dpmLock is \(a directory\|not a regular file\)" log.lock$kind \
        || { cat log.lock$kind; fail "no message naming the lock $kind"; }
    echo "ok   $(tail -1 log.lock$kind | cut -c1-160)"
done

echo "3. the study on a read-only file system"
mkdir -p readOnly/$case1
if unshare -rm true 2>/dev/null
then
    for what in run results
    do
        if [ $what = run ]; then options=("${args[@]}" -j 1); else options=(-noPictures); fi
        unshare -rm bash -c 'mount --bind readOnly readOnly && mount -o remount,bind,ro readOnly &&
            exec dpmStudy "$@"' bash $what readOnly "${options[@]}" > log.readOnly$what 2>&1 \
            && fail "dpmStudy $what ran on a read-only file system"
        noTraceback log.readOnly$what "a read-only file system"
        grep -q "readOnly/.*: Read-only file system\|readOnly/.*read-only file system" log.readOnly$what \
            || { cat log.readOnly$what; fail "no message naming the read-only path"; }
        echo "ok   $what: $(tail -1 log.readOnly$what | cut -c1-160)"
    done
else
    echo "--   left out: unshare cannot make a mount namespace here"
fi

echo "4. submit beside a killed local run's pid file"
mkdir -p stub
printf '#!/bin/sh\necho "sbatch: error: the stub submits nothing" >&2\nexit 1\n' > stub/sbatch
chmod +x stub/sbatch
sleep 300 </dev/null >/dev/null 2>&1 &
other=$!
trap 'kill $other 2>/dev/null' EXIT
mkdir -p pidFile/.dpmStudy.running
touch pidFile/.dpmStudy.running/$other
PATH="$PWD/stub:$PATH" dpmStudy submit pidFile "${args[@]}" > log.pidFile 2>&1 && fail "the stub sbatch submitted"
noTraceback log.pidFile "submit"
grep -q "a local dpmStudy .*process $other" log.pidFile && { cat log.pidFile; fail "refused for process $other, which holds no lock"; }
grep -q "sbatch refused the beds: sbatch: error: the stub" log.pidFile \
    || { cat log.pidFile; fail "submit did not reach sbatch"; }
echo "ok   the leftover pid file ignored: $(grep -m1 "sbatch refused" log.pidFile | cut -c1-120)"
# a local run's hold: the study's lock shared, as dpmStudy takes it
/usr/bin/python3 -c 'import fcntl, os, sys, time
fd = os.open(sys.argv[1], os.O_RDONLY | os.O_CREAT, 0o644)
fcntl.flock(fd, fcntl.LOCK_SH)
time.sleep(300)' pidFile/.dpmStudy.lock </dev/null >/dev/null 2>&1 &
holder=$!
trap 'kill $other $holder 2>/dev/null' EXIT
for i in $(seq 1 50); do flock -n -x pidFile/.dpmStudy.lock true || break; sleep 0.1; done
PATH="$PWD/stub:$PATH" dpmStudy submit pidFile "${args[@]}" > log.held 2>&1 && fail "submit went on beside a local run"
grep -q "a local dpmStudy (process $holder) runs this study (it holds .*pidFile/.dpmStudy.lock)" log.held \
    || { cat log.held; fail "submit beside a local run's lock: no refusal naming the lock"; }
grep -q "sbatch refused" log.held && fail "submit beside a local run reached sbatch"
echo "ok   a held lock refuses: $(tail -1 log.held | cut -c1-160)"
pass "dpmStudy writes through no link, names the lock paths it refuses, and lets the lock decide"
