#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# tutorials/netlSegregationBed as a user runs it (Allrun: blockMesh,
# dpmPackBed, dpmFoam2D), on a fifth of its glass, 0.1 s of settling and
# 0.02 s of gas. Expected, from the column's geometry and the tutorial's
# README: the gas resolved in 4 x 24 x 4 cells; every sphere between the
# front and back walls (r - 1 % d <= z <= depth - r + 1 % d, the DEM's
# overlap allowance) and spread over the depth; the intruders on the
# distributor when the gas starts (each centre within 2 % of its radius of
# the height r: resting on the floor); the force on the particles and the reaction on
# the gas equal in every component, and the particles' volume mapped in
# full (1e-10); the gas at U0 = 2.134 m/s (0.5 %).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

cp -r "$testsDir/../tutorials/netlSegregationBed" "$workDir/case" || fail "copy"
cd "$workDir/case" && ./Allclean >/dev/null || fail "Allclean"
setEntry constant/particleProperties classes.glass.count 900
setEntry constant/particleProperties initialBed.settleTime 0.1
setEntry system/controlDict endTime 0.02
setEntry system/controlDict writeInterval 0.01
setEntry constant/particleProperties writeInterval 0.01
./Allrun || fail "Allrun"
for app in blockMesh dpmPackBed dpmFoam2D
do
    [ -f log.$app ] || fail "no log.$app"
done
grep -q "gas cells 9.525 x 9.525 x 9.525 mm (4 x 24 x 4)" log.dpmFoam2D \
    || fail "dpmFoam2D did not resolve the gas in 4 x 24 x 4 cells"
grep -q "^Coupling: voidage model spheres3D" log.dpmFoam2D \
    || fail "dpmFoam2D did not run voidage model spheres3D"

py - "$testsDir/solver" <<'PY' || fail "the segregating-bed tutorial"
import re, sys
import h5py, numpy as np
D, u0 = 0.0381, 2.134
ok = True
with h5py.File("particles/0.h5") as f:
    y0 = f["position"][:, 1].astype(float)
    c0 = f["class"][:].reshape(-1)
with h5py.File("particles/0.02.h5") as f:
    z = f["position"][:, 2].astype(float)
    d = f["diameter"][:].reshape(-1).astype(float)
inside = np.all((z >= d / 2 - 0.01 * d) & (z <= D - d / 2 + 0.01 * d))
print(f"{len(z)} spheres, z in [{z.min()*1e3:.3f}, {z.max()*1e3:.3f}] mm, std {z.std()*1e3:.3f} mm")
ok &= bool(inside) and z.std() > 3.1e-3 and len(z) == 904
r = 0.5 * 9.43e-3
yi = np.sort(y0[c0 == 1])
print(f"intruders' heights at the start {np.round(yi*1e3, 3)} mm; on the floor: {r*1e3:.3f} mm")
ok &= len(yi) == 4 and bool(np.all(np.abs(yi - r) <= 0.02 * r))
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
pass "the segregating-bed tutorial packs its intruders under the glass and runs the gas in depth"
