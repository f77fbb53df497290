#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# tutorials/UmfSweep's mechanism on two short steps: dpmFoam2D reads U0/Umf
# only at start, so each velocity step is a restart with constant/sweepStep
# changed. Steps of 0.1 s at U0/Umf 0.5 then 1.5 (0.05 s of settling).
# Expected:
#   1. the second step's log starts from the first step's end (t = 0.1) and
#      gives U0 = 1.5 Umf (three times the first step's U0, same Umf);
#   2. the written inlet velocity at the end of the step is that U0;
#   3. the bed's pressure drop over the second half of each step (the
#      inletPressure function object) is below the bed's weight per unit
#      area W/A at 0.5 Umf and grows by more than 30 % at 1.5 Umf (the new
#      U0 acts; 0.1 s is too short for the fluidized bed's mean, which the
#      full sweep measures: the bed first lifts as a slug);
#   4. plotSweep makes sweep.dat and sweep.png from the two steps.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

cp -r "$testsDir/../tutorials/UmfSweep" "$workDir/case" || fail "copy"
cd "$workDir/case" && ./Allclean >/dev/null || fail "Allclean"
setEntry constant/particleProperties initialBed/settleTime 0.05
./Allrun 0.1 0.5 1.5 || fail "Allrun"
cat log.plotSweep

u1=$(sed -n 's/.*U0 \(\S*\) m\/s at patch.*/\1/p' log.dpmFoam2D.step1)
u2=$(sed -n 's/.*U0 \(\S*\) m\/s at patch.*/\1/p' log.dpmFoam2D.step2)
grep -q "U0/Umf 1.5," log.dpmFoam2D.step2 || fail "step 2 does not run at U0/Umf 1.5"
grep -q "^Particles: .* read from .*/0.1/uniform/dem.state" log.dpmFoam2D.step2 \
    || fail "step 2 did not continue from t = 0.1"
py - "$u1" "$u2" <<'PY' || fail "U0 of the steps / inlet velocity / pressure drop"
import sys, re
import numpy as np
u1, u2 = float(sys.argv[1]), float(sys.argv[2])
assert abs(u2 / u1 - 3) < 1e-6, (u1, u2)
# 2. inlet velocity written at t = 0.2 (binary file, uniform value is text)
text = open("0.2/U", "rb").read().decode("latin-1")
block = text[text.index("inlet"):]
m = re.search(r"value\s+uniform\s+\(([^)]*)\)", block)
uy = float(m.group(1).split()[1])
assert abs(uy - u2) < 1e-6 * u2, (uy, u2)     # the log has 8 digits
# 3. pressure drop against the weight
head = open("sweep.dat").readline()
W = float(re.search(r"W/A = (\S+) Pa", head).group(1))
data = [l.split() for l in open("sweep.dat") if not l.startswith("#")]
dp1, dp2 = float(data[0][3]), float(data[1][3])
print("U0 %.4f -> %.4f m/s; inlet Uy %.4f; dp %.1f, %.1f Pa; W/A %.1f Pa" % (u1, u2, uy, dp1, dp2, W))
assert dp1 < 0.8 * W and dp2 > 1.3 * dp1
PY
[ -s sweep.png ] || fail "no sweep.png"
pass "a velocity step is a restart with the new U0"
