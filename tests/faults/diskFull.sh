#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# A full disk at each kind of write (particle file, index update, particle
# state, gas fields), the case on a small tmpfs this test mounts: the run
# pauses at the write (DPMFOAM2D_FAULT=<point>:<n>:stop), the test fills the
# disk and lets it go on. It must stop with a message naming the file and
# "No space left on device", a non-zero exit without a signal, every file
# written before still whole and unchanged; after the space is freed a plain
# restart continues from the last complete time and ends bit for bit as an
# uninterrupted run. Needs root (mount).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
. "$testsDir/faults/faultFunctions"

[ "$(id -u)" = 0 ] || fail "needs root to mount a tmpfs"
cd "$workDir" || fail "cd"
disk="$workDir/disk"
mkdir -p "$disk"
mount -t tmpfs -o size=16m tmpfs "$disk" || fail "cannot mount a tmpfs on $disk"
cleanUp()
{
    cd / && umount "$disk"
}
trap cleanUp EXIT

makeFaultCase template
cp -r template reference
(cd reference && runSolver)

# One kind of write: in a subshell that ends the paused run if it fails
fullDiskAt()
{
    local fault=$1 name=${1%%:*} case=$disk/${1%%:*} pid= status file
    trap '[ -n "${pid:-}" ] && kill -9 $pid 2>/dev/null' EXIT
    cp -r template "$case"
    (cd "$case" && DPMFOAM2D_FAULT=$fault:stop exec dpmFoam2D) >log.$name 2>&1 &
    pid=$!
    waitStopped $pid || fail "$name: the run did not pause at DPMFOAM2D_FAULT=$fault:stop"

    # What is there now must come out unchanged
    (cd "$case" && find . -type f | sort | xargs md5sum) >sums.$name
    dd if=/dev/zero of="$disk/filler.$name" bs=64k >/dev/null 2>&1
    kill -CONT $pid
    wait $pid
    status=$?
    pid=
    [ "$status" != 0 ] || fail "$name: ran on a full disk"
    [ "$status" -lt 128 ] || { tail -20 log.$name; fail "$name: died of signal $((status - 128)) on a full disk"; }
    case $name in
        particleWrite) file="particles/0.02.h5" ;;
        xdmfWrite)     file="particles/particles.xdmf" ;;
        stateWrite)    file="0.02/uniform/dem.state" ;;
        fieldWrite)    file="0.02/" ;;
    esac
    grep -E "$file.*: .*No space left on device" log.$name \
        || { tail -20 log.$name; rm -rf "$case" "$disk/filler.$name"; fail "$name: no message naming $file and 'No space left on device'"; }
    (cd "$case" && md5sum --quiet -c "$workDir/sums.$name") || fail "$name: a file written before the full disk changed"
    checkWhole "$case" || fail "$name: a file is damaged after the full disk"

    rm "$disk/filler.$name"
    (cd "$case" && dpmFoam2D) >log.$name.restart 2>&1 \
        || { tail -20 log.$name.restart; fail "$name: no restart after the space was freed"; }
    grep -q "read from .*0.01/uniform/dem.state" log.$name.restart || fail "$name: did not restart from 0.01"
    compareRuns reference "$case" || fail "$name: the restarted run differs"
    rm -rf "$case"
    echo "ok   full disk at $name: stopped with the file and the reason, restarted bit for bit"
}

failed=
for fault in $faultPoints
do
    (fullDiskAt $fault) || failed="$failed ${fault%%:*}"
    rm -rf "$disk"/* 2>/dev/null
done

# A read-only disk (as no permission, which root does not meet) at the gas
# fields' write: the run stops naming them and the reason, restarts after
readOnlyAt()
{
    local name=readOnly case=$disk/readOnly pid= status
    trap '[ -n "${pid:-}" ] && kill -9 $pid 2>/dev/null; mount -o remount,rw "$disk"' EXIT
    cp -r template "$case"
    (cd "$case" && DPMFOAM2D_FAULT=fieldWrite:2:stop exec dpmFoam2D) >log.$name 2>&1 &
    pid=$!
    waitStopped $pid || fail "$name: the run did not pause"
    (cd "$case" && find . -type f | sort | xargs md5sum) >sums.$name
    mount -o remount,ro "$disk" || fail "cannot remount $disk read-only"
    kill -CONT $pid
    wait $pid
    status=$?
    pid=
    mount -o remount,rw "$disk"
    [ "$status" != 0 ] && [ "$status" -lt 128 ] || { tail -20 log.$name; fail "$name: exit $status on a read-only disk"; }
    grep -E "Cannot write .*0.02.*: Read-only file system" log.$name \
        || { tail -20 log.$name; fail "$name: no message naming 0.02 and 'Read-only file system'"; }
    (cd "$case" && md5sum --quiet -c "$workDir/sums.$name") || fail "$name: a file written before changed"
    (cd "$case" && dpmFoam2D) >log.$name.restart 2>&1 || { tail -20 log.$name.restart; fail "$name: no restart"; }
    compareRuns reference "$case" || fail "$name: the restarted run differs"
    echo "ok   read-only disk at the gas fields: stopped with the reason, restarted bit for bit"
}
(readOnlyAt) || failed="$failed readOnly"
[ -z "$failed" ] || fail "full disk not handled at:$failed"
pass "a full or read-only disk at each kind of write stops the run cleanly, nothing lost, and it restarts"
