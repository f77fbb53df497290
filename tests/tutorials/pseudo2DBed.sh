#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# tutorials/pseudo2DBed as a user runs it (Allrun: blockMesh, dpmPackBed,
# dpmFoam2D), on a twentieth of its spheres (the same mix, w = 0.5), 0.1 s
# of settling and 0.02 s of gas. Expected, from the slab's geometry and the
# tutorial's README: every sphere between the front and back walls
# (r - 1 % d <= z <= depth - r + 1 % d, the DEM's overlap allowance) and
# spread over the depth (not one plane: std(z) > d_small/4); the particles'
# volume mapped to the cells in full (1e-10); the gas at U0 = 1.875 m/s
# (the DPMFoam Goldschmidt tutorial's, 0.5 %).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

cp -r "$testsDir/../tutorials/pseudo2DBed" "$workDir/case" || fail "copy"
cd "$workDir/case" && ./Allclean >/dev/null || fail "Allclean"
setEntry constant/particleProperties classes.small.count 2865
setEntry constant/particleProperties classes.large.count 619
setEntry constant/particleProperties initialBed.settleTime 0.1
setEntry constant/particleProperties nThreads 1
setEntry system/controlDict endTime 0.02
setEntry system/controlDict writeInterval 0.01
./Allrun || fail "Allrun"
for app in blockMesh dpmPackBed dpmFoam2D
do
    [ -f log.$app ] || fail "no log.$app"
done
grep -q "slab mode: 3D spheres between walls z = 0 and z = 0.015 m" log.dpmFoam2D \
    || fail "dpmFoam2D did not run the slab"

py - "$testsDir/solver" <<'PY' || fail "the slab tutorial"
import re, sys
import h5py, numpy as np
D, u0 = 15e-3, 1.875
ok = True
with h5py.File("particles/0.02.h5") as f:
    z = f["position"][:, 2].astype(float)
    d = f["diameter"][:].reshape(-1).astype(float)
inside = np.all((z >= d / 2 - 0.01 * d) & (z <= D - d / 2 + 0.01 * d))
spread = z.std()
print(f"{len(z)} spheres, z in [{z.min()*1e3:.3f}, {z.max()*1e3:.3f}] mm, std {spread*1e3:.3f} mm")
ok &= bool(inside) and spread > 1.5e-3 / 4 and len(z) == 2865 + 619
sys.path.insert(0, sys.argv[1])
from foamData import exchange_balance
writes, worst = exchange_balance()
print(f"force and volume balance: {writes} writes, worst {worst:.2e}")
ok &= writes >= 1 and worst < 1e-10
log = open("log.dpmFoam2D").read()
m = re.search(r"U0 (\S+) m/s at patch", log)
u = float(m.group(1)) if m else float("nan")
print(f"U0 {u} m/s, the tutorial's {u0} m/s")
ok &= abs(u - u0) < 0.005 * u0
sys.exit(0 if ok else 1)
PY
pass "the slab tutorial packs and runs its spheres in the slab"
