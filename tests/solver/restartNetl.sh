#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Restart of the NETL tutorial itself (4507 glass beads of 3.1 mm and four
# intruders of 9.43 mm, the gas resolved in 3D): its intruders are searched
# apart from the beads' grid, and the particles are renumbered by cell every
# 200 DEM steps, at the restart step too. 0.04 s in one go must equal 0.02 s,
# a stop, and 0.02 s more, bit for bit: the particle files, the gas fields
# and the DEM state (their md5 sums).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

cp -r "$DPMFOAM2D_PROJECT/tutorials/netlSegregationBed" "$workDir/once" || fail "copy the tutorial"
cd "$workDir/once" || fail "cd"
cp -r 0.orig 0
blockMesh >log.blockMesh 2>&1 || fail "blockMesh"
dpmPackBed >log.dpmPackBed 2>&1 || { tail -20 log.dpmPackBed; fail "dpmPackBed"; }
setEntry system/controlDict endTime 0.04
setEntry system/controlDict writeInterval 0.02
setEntry constant/particleProperties writeInterval 0.02
cd .. && cp -r once twice || fail "copy"

(cd once && runSolver)
cd twice || fail "cd"
setEntry system/controlDict endTime 0.02
runSolver
mv log.dpmFoam2D log.dpmFoam2D.1
rm particles/0.02.h5     # the restart writes its start time's file anew
setEntry system/controlDict endTime 0.04
runSolver
grep -q "read from .*0.02/uniform/dem.state" log.dpmFoam2D || fail "the second run did not restart from 0.02"
cd ..

# The gas and the DEM state by their md5 sums; the particle file dataset by
# dataset (an HDF5 file's bytes hold more than its data)
different=0
for f in 0.04/U 0.04/p_rgh 0.04/uniform/dem.state
do
    a=$(md5sum < once/$f) b=$(md5sum < twice/$f)
    if [ "$a" = "$b" ]
    then
        echo "$f: identical (${a%% *})"
    else
        echo "$f: DIFFERENT (${a%% *} against ${b%% *})"
        different=$((different + 1))
    fi
done
py - <<'PY' || different=$((different + 1))
import hashlib, sys, h5py
ok = True
with h5py.File("once/particles/0.04.h5") as a, h5py.File("twice/particles/0.04.h5") as b:
    for name in sorted(a):
        sa = hashlib.md5(a[name][()].tobytes()).hexdigest()
        sb = hashlib.md5(b[name][()].tobytes()).hexdigest() if name in b else "missing"
        print(f"particles/0.04.h5 {name}: {'identical' if sa == sb else 'DIFFERENT'} ({sa})")
        ok &= sa == sb
sys.exit(0 if ok else 1)
PY
[ "$different" = 0 ] || fail "the restarted NETL bed parts from the uninterrupted run"
pass "the NETL tutorial stopped at 0.02 s and continued equals the run through 0.04 s, bit for bit"
