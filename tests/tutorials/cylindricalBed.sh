#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# tutorials/cylindricalBed, reduced (1500 small and 324 large spheres, the
# paper's mixture at equal masses; the tutorial's sphere quadrature; 0.2 s
# of settling, 0.5 s of gas at U0 = 2 Umf), run by its Allrun: the gas on
# the O-grid, the spheres inside the cylinder fitted to the mesh's wall.
# Expected:
# - the bubbling bed's time-averaged pressure drop over 0.2-0.5 s equals
#   the particles' weight less their buoyancy over the gas's cross-section
#   (the inlet patch's area), corrected as in the box's balance
#   (solver/fluidizedPressureDrop.sh) by the particles' momentum gain over
#   the window and the distributor's share (kn x overlap with y = 0):
#   within 5 %;
# - at every write the gas carries exactly the particles' force and their
#   volume is mapped in full (relative 1e-10);
# - every particle file: each sphere's centre inside the cylinder of the
#   mesh's wall (radius 15 mm about x = 0, z = 15 mm), the sphere reaching
#   beyond it by less than half its radius: a contact's overlap, v
#   sqrt(m/kn) for a head-on impact at v, 4 % of a large sphere's radius
#   at 0.3 m/s, half of it at 3.9 m/s (the floor's deepest, the same law on
#   a plane, is printed beside);
# - the analyses work on the O-grid: the Lacey index written at every
#   gas write, in [0, 1]; dpmBedStatistics' bed height at the first gas
#   write (from the voidage of the cells' rows) within a row's height
#   (5 mm) of the height below which 99 % of the particles' tops lie;
#   dpmRiseTime writes its tables;
# - a restart from 0.3 s writes the same bits at 0.5 s (the particle state
#   and the gas fields).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

cp -r "$testsDir/../tutorials/cylindricalBed" "$workDir/case" || fail "copy"
cd "$workDir/case" || fail "cd"
./Allclean >/dev/null
setEntry constant/particleProperties classes.small.count 1500
setEntry constant/particleProperties classes.large.count 324
setEntry constant/particleProperties initialBed.settleTime 0.2
setEntry system/controlDict endTime 0.5
setEntry system/controlDict writeInterval 0.1
cat >>system/controlDict <<'EOF2'
functions
{
    #includeFunc inletPressure
    inletPressure { writeInterval 1; writeArea true; }  // every step
    #includeFunc exchangeBalance
}
EOF2
./Allrun >/dev/null 2>&1 || { tail -20 log.*; fail "Allrun"; }
grep -q "^End" log.dpmFoam2D || { tail -20 log.dpmFoam2D; fail "dpmFoam2D did not end"; }

kn=$(foamDictionary -entry contact.kn -value constant/particleProperties) \
    || fail "contact.kn"
py - "$kn" "$testsDir/solver" <<'PY' || fail "the cylindrical bed's balance, containment or exchange"
import sys, glob, re
import numpy as np
import h5py
sys.path.insert(0, sys.argv[2])
from foamData import exchange_balance
kn = float(sys.argv[1])
rho_g, g, rho_p, R, zc = 1.204, 9.81, 2525, 0.015, 0.015
d = np.array([1.5e-3, 2.5e-3]); n = np.array([1500, 324])
V = np.sum(n * np.pi * d**3 / 6)

path = glob.glob("postProcessing/inletPressure/*/surfaceFieldValue.dat")[0]
text = open(path).read()
m = re.search(r"Area\s*:\s*(\S+)", text)
if not m:
    sys.exit("no Area in " + path)
A = float(m.group(1))
data = np.loadtxt(path)
t, p = data[:, 0], data[:, -1]
t0, t1 = 0.2, 0.5
expected = (rho_p - rho_g) * V * g / A
mean = p[t >= t0].mean()

def particles(time):
    with h5py.File(f"particles/{time:g}.h5", "r") as f:
        return (f["position"][:].astype(float), f["velocity"][:].astype(float),
                f["diameter"][:].reshape(-1).astype(float))

def momentum(time):
    x, v, dp = particles(time)
    return np.sum(rho_p * np.pi * dp**3 / 6 * v[:, 1])
dPdt = (momentum(t1) - momentum(t0)) / (t1 - t0) / A

files = sorted(glob.glob("particles/*.h5"), key=lambda s: float(s[10:-3]))
window = [s for s in files if t0 <= float(s[10:-3]) <= t1]
floor, worstOut, worstFloor = [], -np.inf, -np.inf
for s in files:
    x, v, dp = particles(float(s[10:-3]))
    r = dp / 2
    # how far each sphere reaches beyond the cylinder and the floor, in its radii
    reach = (np.hypot(x[:, 0], x[:, 2] - zc) + r - R) / r
    worstOut = max(worstOut, reach.max())
    worstFloor = max(worstFloor, ((r - x[:, 1]) / r).max())
    if s in window:
        floor.append(kn * np.clip(r - x[:, 1], 0, None).sum())
floorP = np.mean(floor) / A
err = abs(mean - (expected - floorP + dPdt)) / expected
print(f"inlet area {A*1e6:.2f} mm2 (pi R^2 {np.pi*R*R*1e6:.2f}), mean inlet p_rgh "
      f"{t0:g}-{t1:g} s {mean:.1f} Pa, (W - B)/A {expected:.1f} Pa, momentum gain "
      f"{dPdt:+.1f} Pa, floor {floorP:.1f} Pa ({len(window)} files): error {100*err:.2f} %")
print(f"containment: {len(files)} particle files, the deepest reach into the wall "
      f"{100*max(worstOut, 0):.2f} % of a radius (into the floor {100*max(worstFloor, 0):.2f} %)")

writes, worst = exchange_balance()
print(f"exchange balance: {writes} writes, worst relative mismatch {worst:.2e}")
ok = (err < 0.05 and worstOut < 0.5 and len(files) > 40 and writes >= 5
      and worst < 1e-10)
sys.exit(0 if ok else 1)
PY

# A restart from 0.3 s ends at 0.5 s with the same bits: the walls fitted
# to the mesh again, the unstructured grid's stencils from scratch
rm -rf "$workDir/restarted" && cp -r "$workDir/case" "$workDir/restarted" || fail "copy for the restart"
(
    cd "$workDir/restarted" || exit 1
    rm -rf 0.4 0.5 postProcessing log.dpmFoam2D
    find particles -name '*.h5' | while read -r f
    do
        t=$(basename "$f" .h5)
        py -c "import sys; sys.exit(0 if float('$t') > 0.3 + 1e-9 else 1)" && rm "$f"
    done
    dpmFoam2D >log.dpmFoam2D 2>&1
) || { tail -20 "$workDir/restarted/log.dpmFoam2D"; fail "the restart from 0.3 s"; }
for f in uniform/dem.state U p_rgh voidage
do
    cmp -s "0.5/$f" "$workDir/restarted/0.5/$f" || fail "0.5/$f differs after the restart from 0.3 s"
done

# The analyses on the O-grid
lacey=$(ls postProcessing/laceyIndex/*/laceyIndex.dat 2>/dev/null | head -1)
[ -n "$lacey" ] || fail "no postProcessing/laceyIndex"
dpmBedStatistics . >log.dpmBedStatistics 2>&1 \
    || { cat log.dpmBedStatistics; fail "dpmBedStatistics on the O-grid"; }
dpmRiseTime . -class large >log.dpmRiseTime 2>&1 \
    || { cat log.dpmRiseTime; fail "dpmRiseTime on the O-grid"; }
[ -s postProcessing/riseTime/0/riseTime.dat ] || fail "no riseTime.dat"
py - "$lacey" <<'PY' || fail "the Lacey index or the bed height on the O-grid"
import sys
import numpy as np
import h5py
lacey = np.loadtxt(sys.argv[1], ndmin=2)
M = lacey[:, 1]
bed = np.loadtxt("postProcessing/bedStatistics/0/bed.dat", ndmin=2)
t0, h0 = bed[0, 0], bed[0, 1]
with h5py.File(f"particles/{t0:g}.h5", "r") as f:
    y = f["position"][:, 1].astype(float)
    top = np.quantile(y + f["diameter"][:].reshape(-1) / 2, 0.99)
print(f"Lacey index: {len(M)} rows, in [{M.min():.3f}, {M.max():.3f}]; bed height at {t0:g} s "
      f"{1e3*h0:.1f} mm from the voidage's rows, the particles' 99 % top {1e3*top:.1f} mm")
ok = len(M) >= 5 and M.min() >= 0 and M.max() <= 1 and abs(h0 - top) <= 5e-3
sys.exit(0 if ok else 1)
PY
pass "the cylindrical bed: its weight on the distributor, every sphere inside the cylinder, the restart bit for bit, the analyses on the O-grid"
