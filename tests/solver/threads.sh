#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Threads: 200 CFD steps (2000 DEM steps, with particles renumbered by cell)
# on 1 and on 2 threads give the same particles and gas, bit for bit: the
# DEM and the coupling loops sum in an order that does not depend on the
# thread count. Correct on a busy machine too (only slower).
# In the slab mode the spheres' z, vz and spin vector too. Two threads fixed
# (threadChoice fixed); in the 2D mode with the default drag also measured
# (threadChoice measured: each CFD step on one thread or two, as timed), the
# same bits again and the log's count of the steps on each.
#   threads.sh <workDir> [dragModel] [slab3D <depth> | spheres3D:<nz> <depth>]
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
model="${2:-ErgunWenYu}"     # drag model (Beetstra: the cell mixture too)

makeCase "$workDir/one"
cd "$workDir/one" || fail "cd"
setEntry system/controlDict writeFormat binary
setEntry system/controlDict endTime 0.02
setEntry system/controlDict writeInterval 0.02
setEntry constant/gasProperties U0byUmf 2
setEntry constant/particleProperties nThreads 1
setEntry constant/particleProperties dragModel "$model"
setMomentum
setSlab "${3:-}" "${4:-}"
cd .. && cp -r one two || fail "copy"
(cd two && setEntry constant/particleProperties nThreads 2 \
        && setEntry constant/particleProperties threadChoice fixed)
runs="one two"
if [ -z "${3:-}" ] && [ "$model" = ErgunWenYu ]
then
    cp -r one measured || fail "copy"
    (cd measured && setEntry constant/particleProperties nThreads 2 \
                 && setEntry constant/particleProperties threadChoice measured)
    runs="$runs measured"
fi
for run in $runs
do
    (cd $run && runSolver)
done
if [ -d measured ]
then
    grep -q "DEM threads: 2, or one where the run's own timing finds one faster" \
        measured/log.dpmFoam2D || fail "the set-up does not name the measured choice"
    line=$(grep "^DEM threads (threadChoice measured): 2 in" measured/log.dpmFoam2D) \
        || fail "no count of the steps on each team"
    read -r all one <<<"$(sed -E 's/.* 2 in ([0-9]+) CFD steps, one in ([0-9]+) .*/\1 \2/' <<<"$line")"
    # The first trial runs on both teams whatever the load: its 2 untimed
    # steps and at least 2 timed on all threads (ThreadChooser), its 23 on one
    [ $((all + one)) -eq 200 ] && [ "$all" -ge 4 ] && [ "$one" -ge 23 ] \
        || fail "steps on each team ($line): 200 in all, at least a trial's 4 on all threads and 23 on one"
    grep -q "DEM threads (threadChoice" two/log.dpmFoam2D && fail "a fixed choice counted"
    echo "$line"
fi

RUNS="$runs" py - <<'PY' || fail "1 and 2 threads differ"
import os, sys, h5py, numpy as np
ok = True
with h5py.File("one/particles/0.02.h5") as a:
    names = ["position", "velocity", "omega", "id"] + (["spin"] if "spin" in a else [])
for other in os.environ["RUNS"].split()[1:]:
    for name in names:
        with h5py.File("one/particles/0.02.h5") as a, h5py.File(f"{other}/particles/0.02.h5") as b:
            same = np.array_equal(a[name][()], b[name][()])
            print(f"{other}: particles {name}: {'identical' if same else 'DIFFERENT'}")
            ok &= same
    for field in ("U", "p_rgh", "voidage"):
        same = open(f"one/0.02/{field}", "rb").read() == open(f"{other}/0.02/{field}", "rb").read()
        print(f"{other}: gas {field}: {'identical' if same else 'DIFFERENT'}")
        ok &= same
sys.exit(0 if ok else 1)
PY
pass "1 and 2 threads give the same bits"
