#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Threads: 200 CFD steps (2000 DEM steps, with particles renumbered by cell)
# on 1 and on 2 threads give the same particles and gas, bit for bit: the
# DEM and the coupling loops sum in an order that does not depend on the
# thread count. Correct on a busy machine too (only slower).
# In the slab mode the spheres' z, vz and spin vector too.
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
(cd two && setEntry constant/particleProperties nThreads 2)

(cd one && runSolver)
(cd two && runSolver)

py - <<'PY' || fail "1 and 2 threads differ"
import sys, h5py, numpy as np
ok = True
names = ["position", "velocity", "omega", "id"]
with h5py.File("one/particles/0.02.h5") as a:
    names += ["spin"] if "spin" in a else []
for name in names:
    with h5py.File("one/particles/0.02.h5") as a, h5py.File("two/particles/0.02.h5") as b:
        same = np.array_equal(a[name][()], b[name][()])
        print(f"particles {name}: {'identical' if same else 'DIFFERENT'}")
        ok &= same
for field in ("U", "p_rgh", "voidage"):
    same = open(f"one/0.02/{field}", "rb").read() == open(f"two/0.02/{field}", "rb").read()
    print(f"gas {field}: {'identical' if same else 'DIFFERENT'}")
    ok &= same
sys.exit(0 if ok else 1)
PY
pass "1 and 2 threads give the same bits"
