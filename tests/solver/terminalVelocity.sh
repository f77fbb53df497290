#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# One 1.5 mm glass sphere falls through gas at rest at 64 bar in a closed
# column. At its terminal velocity the drag balances weight less buoyancy:
#   K(s, eps) s = (rho_p - rho_g) V_p g,
# with K from the paper's drag law (Wen-Yu branch; docs/theory/paper-model.md,
# "Gas": K = V_p 3/4 C_D rho_g s/d eps^-2.65, C_D = 24(1 + 0.15 Re^0.687)/Re,
# Re = rho_g d eps s/mu) at the voidage the particle sees, solved here
# independently by bisection. The slip s is the particle's velocity
# relative to the gas it sees (the particle drags its cell's gas along).
# Tolerance 2 %. Gas cells of 15 mm keep the voidage near 1.
# An isolated sphere has the same terminal velocity in formulations A and
# B (Zhou et al. 2010): A's drag eps_g K_B (eps_g = 1 - phiP) and the
# pressure-gradient force of the particle's own wake differ from B's by
# the order of the particle's volume fraction in its cell, V_p/V_cell =
# 0.3 % here, far inside the tolerance.
# In the slab mode (slab3D <depth>) the sphere falls in the slab's
# mid-plane between the front and back walls, the voidage its sphere-column
# volume: the same balance. With the gas resolved in depth (spheres3D:<nz>
# <depth>, nz cells between no-slip walls) the sphere falls on the plane
# between two cells, the gas it sees interpolated trilinearly from both.
#   terminalVelocity.sh <workDir> [A|B] [slab3D <depth> | spheres3D:<nz> <depth>]    (default B, 2D)
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/case"
cd "$workDir/case" || fail "cd"
setEntry system/bedGeometry width 0.06
setEntry system/bedGeometry height 0.9
setEntry system/bedGeometry nx 4
setEntry system/bedGeometry ny 60
blockMesh >log.blockMesh 2>&1 || fail "blockMesh"

# A closed column: no distributor, the bottom is a wall
setEntry constant/gasProperties operatingPressure 64
setEntry constant/gasProperties inletPatch none
setEntry 0/U boundaryField.inlet "{ type noSlip; }"
echo "0 0.03 0.85" >positions.txt
setEntry constant/particleProperties classes "{ small { diameter 1.5e-3; density 2525; } }"
setEntry constant/particleProperties initialBed "{ positions \"\$FOAM_CASE/positions.txt\"; }"
setEntry system/controlDict endTime 0.4
setEntry system/controlDict writeInterval 0.4
setFormulation "${2:-}"
setMomentum
setSlab "${3:-}" "${4:-}"
runSolver

py - <<'PY' || fail "terminal velocity"
import sys, glob
import h5py, numpy as np
rho_p, rho_g, mu, g, d = 2525.0, 1.204 * 64, 1.75e-5, 9.81, 1.5e-3
Vp = np.pi * d**3 / 6

def drag_force(s, eps):
    Re = rho_g * d * eps * s / mu
    cd_s = 24 * mu / (rho_g * d * eps) * (1 + 0.15 * Re**0.687) if Re < 1000 else 0.44 * s
    return Vp * 0.75 * cd_s * rho_g / d * eps**-2.65 * s

frames = sorted(glob.glob("particles/*.h5"), key=lambda f: float(f.split("/")[-1][:-3]))
rows = []
for f in frames[-10:]:
    with h5py.File(f) as h:
        rows.append((h.attrs["time"], h["position"][0, 1], h["velocity"][0, 1],
                     h["gasVelocity"][0, 1], h["voidage"][0]))
rows = np.array(rows)
slip = np.mean(rows[:, 3] - rows[:, 2])          # gas minus particle, upward > 0
eps = np.mean(rows[:, 4])
weight = (rho_p - rho_g) * Vp * g
lo, hi = 1e-6, 50.0
for _ in range(200):
    mid = 0.5 * (lo + hi)
    lo, hi = (mid, hi) if drag_force(mid, eps) < weight else (lo, mid)
expected = 0.5 * (lo + hi)
accel = np.polyfit(rows[:, 0], rows[:, 2], 1)[0]
err = abs(slip - expected) / expected
print(f"height {rows[-1,1]:.3f} m, voidage {eps:.5f}, particle {rows[-1,2]:.4f} m/s, "
      f"slip {slip:.4f} m/s, analytic {expected:.4f} m/s, error {100*err:.2f} %, "
      f"acceleration {accel:.3f} m/s2")
sys.exit(0 if err < 0.02 and rows[-1, 1] > 0.05 else 1)
PY
pass "terminal velocity of a single particle"
