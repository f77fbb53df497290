#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# NETL's segregating bed in the slab (LaMarche et al. 2022): glass beads of a
# normal diameter distribution (3101 um, standard deviation 187 um, cut to
# 2.6-3.6 mm) given by massFraction, a class drawn from a file of measured
# diameters in micrometres (scale 1e-6), and two large HDPE intruders
# (9.43 mm, 941 kg/m3) laid first, one at the centre of the floor and one at
# random. The bed as packed (settleTime 0, particles/0.h5):
#   - the glass count is massFraction totalMass over rho pi/6 E[d^3], E[d^3] of
#     the truncated normal by quadrature here; the log's Sauter mean and the
#     class summary's number mean likewise;
#   - the glass diameters lie within the bounds, their mean within 3 standard
#     errors of the truncated normal's (quadrature); the sampled class's are
#     the file's values alone;
#   - the placed intruder is where it was asked, the random one on the floor
#     within the column, and no two particles overlap.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

case="$workDir/netl"
makeCase "$case"
cd "$case" || fail "no case"
for kv in "width 0.038" "height 0.152" "depth 0.038" "nx 4" "ny 16"
do
    set -- $kv
    setEntry system/bedGeometry "$1" "$2"
done
blockMesh >log.blockMesh 2>&1 || fail "blockMesh"
printf '# diameters, um\n3122.9 3401.6\n3231.2 # a comment\n3022.6\n2991.8\n' >dp_beads.txt
/usr/bin/python3 - <<'PY' || fail "cannot write particleProperties"
p = "constant/particleProperties"
s = open(p).read()
s = s.replace("""    small { diameter 1.5e-3; density 2525; count 600; }
    large { diameter 2.5e-3; density 2525; count 130; }""", """    glass
    {
        diameter
        {
            distribution normal; mean 3.101e-3; standardDeviation 1.87e-4;
            min 2.6e-3; max 3.6e-3;
        }
        density 2522; massFraction 1;
    }
    beads { diameter { distribution samples; file "dp_beads.txt"; scale 1e-6; } density 2522; count 100; }
    large { diameter 9.43e-3; density 941; count 2; }""")
s = s.replace("""    seed        1;
    settleTime  0.3;""", """    seed        1;
    settleTime  0;
    place { large { positions ((0.019 0.005 0.019)); random 1; } }""")
s = s.replace("nThreads        1;", "nThreads        1;\nvoidageModel    slab3D;\ntotalMass       0.05;")
open(p, "w").write(s)
PY
setEntry system/controlDict endTime 1e-4
runSolver

/usr/bin/python3 - "$case" <<'PY' || fail "the packed bed is not as asked (above)"
import sys, math
import numpy as np
from dpmfoam2d import read_particles
case = sys.argv[1]
p = read_particles(case + "/particles/0.h5")
x, d, c = p["position"].astype(float), p["diameter"].astype(float), p["class"]
bad = []
# The truncated normal's moments by quadrature of its density
mu, s, a, b = 3.101e-3, 1.87e-4, 2.6e-3, 3.6e-3
t = np.linspace(a, b, 200001)
w = np.exp(-0.5 * ((t - mu) / s) ** 2)
m = [np.trapz(w * t ** k, t) / np.trapz(w, t) for k in range(4)]
count = round(1.0 * 0.05 / (2522 * math.pi / 6 * m[3]))
glass, beads, large = d[c == 0], d[c == 1], np.where(c == 2)[0]
if len(glass) != count:
    bad.append("glass count %d, expected %d" % (len(glass), count))
if glass.min() < a * (1 - 1e-6) or glass.max() > b * (1 + 1e-6):
    bad.append("glass diameters outside [%g, %g]: %g..%g" % (a, b, glass.min(), glass.max()))
se = math.sqrt((m[2] - m[1] ** 2) / len(glass))
if abs(glass.mean() - m[1]) > 3 * se:
    bad.append("glass mean %.7g, expected %.7g +- %.2g" % (glass.mean(), m[1], 3 * se))
listed = np.array([3122.9, 3401.6, 3231.2, 3022.6, 2991.8]) * 1e-6
if len(beads) != 100 or not all(np.min(abs(listed - v)) < 1e-6 * v for v in beads):
    bad.append("the sampled class's diameters are not the file's")
log = open(case + "/log.dpmFoam2D").read()
sauter = float(log.split("class glass diameters")[1].split("Sauter mean ")[1].split()[0])
if abs(sauter / (m[3] / m[2]) - 1) > 1e-6:
    bad.append("Sauter mean %.8g in the log, %.8g expected" % (sauter, m[3] / m[2]))
number = float(log.split("    glass: ")[1].split(" d = ")[1].split()[0]) * 1e-3
if abs(number / m[1] - 1) > 1e-6 or "(the number mean of its distribution)" not in log:
    bad.append("the class summary's d %.8g m is not the number mean %.8g m" % (number, m[1]))
r = 0.5 * 9.43e-3
if len(large) != 2:
    bad.append("%d intruders" % len(large))
else:
    at = [i for i in large if np.allclose(x[i], [0.019, 0.005, 0.019], atol=1e-8)]
    if len(at) != 1:
        bad.append("no intruder at (0.019 0.005 0.019): %s" % x[large])
    other = [i for i in large if i not in at]
    for i in other:
        if abs(x[i][1] - r) > 1e-8 or not (r <= x[i][0] <= 0.038 - r) or not (r <= x[i][2] <= 0.038 - r):
            bad.append("the random intruder at %s is not on the floor within the column" % x[i])
for i in range(len(d)):
    gap = np.linalg.norm(x[i + 1:] - x[i], axis=1) - 0.5 * (d[i + 1:] + d[i])
    if len(gap) and gap.min() < -1e-5 * d[i]:
        bad.append("particle %d overlaps another by %g m" % (i, -gap.min()))
        break
print("\n".join(bad) if bad else "bed as asked: %d glass (expected %d), mean %.6g m" % (len(glass), count, glass.mean()))
sys.exit(1 if bad else 0)
PY
pass "diameter distributions and placed intruders packed as asked (counts, bounds, means, samples, positions, no overlaps)"
