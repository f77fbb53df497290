#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# A bubbling bed's time-averaged pressure drop equals the particles' weight
# less their buoyancy over the bed's cross-section (width x depth), plus
# the rate at which the particles gained upward momentum over the window:
#   dp = ((M - rho_g V_p,total) g - F_floor + (P(t1) - P(t0))/(t1 - t0)) / (W D)
# (momentum balance of the particles, P = sum m v_y from the saved states;
# p_rgh already excludes the gas's own hydrostatic head). Tolerance 5 %.
# The binary mix of the paper at w_small ~ 0.5, at U0/Umf = 2
# so that the large particles are fluidized too, averaged over the last
# 1.5 s of 2 s of gas. The momentum term is not small in this narrow,
# slugging bed: over 1.5 s it moves the balance by up to 2.3 % of the
# weight, over 0.5 s by up to 6 %, with a sign set by the slug's phase at
# the window's ends (docs/theory/numerics.md, "The fluidized bed's pressure balance", DiFelice). Less the
# floor's share: some particles rest on the distributor (about 7 % of the
# weight at 1 bar), its mean force kn x overlap over the saved states
# (linear springs; the damping averages out). The distributor's pressure
# counts the bottom row's drag once (docs/theory/numerics.md, "The
# gas-side excess").
# The same run checks, at every write, that the gas carries exactly the
# force the particles feel and that the particles' area is mapped to cells
# in full (round-off: relative 1e-10; the exchangeBalance table).
# Every drag model must pass it (the weight does not depend on the drag).
# In the slab mode (slab3D <depth>: 3D spheres between walls <depth> apart,
# the mesh that thick) the same balance with D the slab's depth, and the
# spheres' volume mapped in full; with the gas resolved in depth
# (spheres3D:<nz> <depth>, nz cells between no-slip walls) the same.
#   fluidizedPressureDrop.sh <workDir> <pressure in bar> [dragModel] [slab3D <depth> | spheres3D:<nz> <depth>]
# The formulation (A or B, default B) from the environment: FORMULATION=A.
# The packed bed from SHARED_BED=<file> when set (initialBed/file: the bed
# does not depend on the gas, the drag, the formulation or the schedule);
# with PACK_BED=1 the script only packs that bed, with dpmPackBed (ctest's
# fixture for the runs that share it).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
bar="${2:?pressure in bar}"
model="${3:-ErgunWenYu}"

makeCase "$workDir/case"
cd "$workDir/case" || fail "cd"

setEntry constant/gasProperties operatingPressure "$bar"
setEntry constant/particleProperties dragModel "$model"
setEntry constant/gasProperties U0byUmf 2
setEntry constant/particleProperties classes.small.count 1200
setEntry constant/particleProperties classes.large.count 260
setEntry system/controlDict endTime 2
setEntry system/controlDict writeInterval 0.5
setFormulation
setMomentum
setSlab "${4:-}" "${5:-}"
if [ -n "${SHARED_BED:-}" ]
then
    setEntry constant/particleProperties initialBed.file "\"$SHARED_BED\""
    if [ "${PACK_BED:-}" = 1 ]
    then
        mkdir -p "$(dirname "$SHARED_BED")" && rm -f "$SHARED_BED" \
            && dpmPackBed >log.dpmPackBed 2>&1 && [ -s "$SHARED_BED" ] \
            || { tail -20 log.dpmPackBed; fail "dpmPackBed: the shared bed $SHARED_BED"; }
        pass "the bed packed for the fluidized runs: $SHARED_BED"
        exit 0
    fi
    [ -s "$SHARED_BED" ] || fail "no shared bed $SHARED_BED (its fixture test packs it)"
fi
cat >>system/controlDict <<'EOF2'
functions
{
    #includeFunc inletPressure
    inletPressure { writeInterval 1; }      // every step
    #includeFunc exchangeBalance
}
EOF2
runSolver
grep -q "drag model $model" log.dpmFoam2D || fail "the log does not name the drag model $model"

kn=$(foamDictionary -entry contact.kn -value constant/particleProperties) \
    || fail "contact.kn"
py - "$bar" "$model" "$kn" "${slabDepth:-2.5e-3}" "$testsDir/solver" <<'PY' || fail "fluidized bed pressure drop at $bar bar ($model)"
import sys, glob
import numpy as np
import h5py
sys.path.insert(0, sys.argv[5])
from foamData import exchange_balance
bar = float(sys.argv[1])
rho_g, g, W, D = 1.204 * bar, 9.81, 0.06, float(sys.argv[4])
d = np.array([1.5e-3, 2.5e-3]); n = np.array([1200, 260]); rho_p = 2525
V = np.sum(n * np.pi * d**3 / 6)
expected = (rho_p - rho_g) * V * g / (W * D)

data = np.loadtxt(glob.glob("postProcessing/inletPressure/*/surfaceFieldValue.dat")[0])
t, p = data[:, 0], data[:, 1]
t0, t1 = 0.5, 2.0
mean = p[t >= t0].mean()

# The particles' upward momentum at the window's ends (particles/<t>.h5)
def momentum(time):
    with h5py.File(f"particles/{time:g}.h5", "r") as f:
        dp = f["diameter"][:].reshape(-1).astype(float)
        vy = f["velocity"][:, 1].astype(float)
    return np.sum(rho_p * np.pi * dp**3 / 6 * vy)
dPdt = (momentum(t1) - momentum(t0)) / (t1 - t0) / (W * D)

# The floor's mean force over the saved states in the window (floor y = 0)
def floor_force(path):
    with h5py.File(path, "r") as f:
        r = f["diameter"][:].reshape(-1).astype(float) / 2
        y = f["position"][:, 1].astype(float)
    return float(sys.argv[3]) * np.clip(r - y, 0, None).sum()
states = [s for s in glob.glob("particles/*.h5")
          if t0 <= float(s[len("particles/"):-len(".h5")]) <= t1]
floor = np.mean([floor_force(s) for s in states]) / (W * D)
err = abs(mean - (expected - floor + dPdt)) / expected
print(f"{sys.argv[2]}, {bar:g} bar: mean inlet p_rgh over {t0:g}-{t1:g} s {mean:.1f} Pa, "
      f"(W - B)/A {expected:.1f} Pa, particles' momentum gain {dPdt:+.1f} Pa "
      f"({100*dPdt/expected:+.2f} %), floor {floor:.1f} Pa ({100*floor/expected:.2f} %, "
      f"{len(states)} states), error {100*err:.2f} % (without the floor "
      f"{100*abs(mean - expected - dPdt)/expected:.2f} %, without both "
      f"{100*abs(mean - expected)/expected:.2f} %)")

# Exchange balance at each write
writes, worst = exchange_balance()
print(f"exchange balance: {writes} writes, worst relative mismatch {worst:.2e}")
ok = err < 0.05 and writes >= 4 and worst < 1e-10 and len(states) > 100
sys.exit(0 if ok else 1)
PY
pass "pressure drop of the fluidized bed at $bar bar ($model)"
