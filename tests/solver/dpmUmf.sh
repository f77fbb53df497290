#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmUmf: the minimum fluidization velocities of the case's drag model.
# With ErgunWenYu below its switch voidage the drag is Ergun's (1952), so
# the bed's Umf at voidage eps solves sum_k x_k Ergun(eps, d_k, U) =
# (1 - eps)(rho_p - rho_g) g (x_k: the classes' shares of the solid volume;
# each class alone: x_k = 1, and in the mixture the same, all densities
# being equal), a quadratic in U solved here independently of the code.
# The test column's 600 + 130 particles at 1 and 64 bar, eps 0.4 and 0.45:
# every velocity within 1e-6 relative (printed to 8 digits, bisected to
# 1e-12); the Wen-Yu Umf and U0 (U0byUmf 1.25) within 1e-6; a voidage
# outside (0, 1) stops it naming the option and the range.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/case"
cd "$workDir/case" || fail "cd"
for bar in 1 64
do
    setEntry constant/gasProperties operatingPressure $bar
    dpmUmf -voidage '(0.4 0.45)' > log.dpmUmf.$bar 2>&1 \
        || { tail -20 log.dpmUmf.$bar; fail "dpmUmf failed at $bar bar"; }
    sed -n '/^Drag model/,/^Terminal/p' log.dpmUmf.$bar
    py - "$testsDir/solver" log.dpmUmf.$bar $bar <<'PY' || fail "dpmUmf at $bar bar"
import re, sys
import numpy as np
sys.path.insert(0, sys.argv[1])
from foamData import wen_yu_umf
text = open(sys.argv[2]).read()
rho_g, rho_p, mu, g = 1.204 * float(sys.argv[3]), 2525.0, 1.75e-5, 9.81
d = np.array([1.5e-3, 2.5e-3])
n = np.array([600, 130])
x = n * d**3 / (n * d**3).sum()          # shares of the solid volume


def ergun_umf(eps, shares):
    # sum_k x_k [150 (1-e)^2 mu U/(e^3 d^2) + 1.75 (1-e) rho U^2/(e^3 d)]
    a = 1.75 * (1 - eps) * rho_g / eps**3 * (shares / d).sum()
    b = 150 * (1 - eps)**2 * mu / eps**3 * (shares / d**2).sum()
    c = (1 - eps) * (rho_p - rho_g) * g
    return (-b + np.sqrt(b * b + 4 * a * c)) / (2 * a)


def close(name, got, want, tol=1e-6):
    ok = abs(got - want) <= tol * abs(want)
    print("%-28s %.8g, expected %.8g (%.1e)%s" % (name, got, want,
          abs(got / want - 1), "" if ok else "  FAIL"))
    return ok


ok = True
wmass = n * d**3 / (n * d**3).sum()
umf_wy = wen_yu_umf(1 / (wmass / d).sum(), rho_p, rho_g)
m = re.search(r"Wen-Yu Umf (\S+) m/s .*; U0 (\S+) m/s", text)
ok &= close("Wen-Yu Umf", float(m.group(1)), umf_wy)
ok &= close("U0", float(m.group(2)), 1.25 * umf_wy)
rows = re.findall(r"^(0\.\d+)((?:\s+\S+){6})\s*$", text, re.M)
assert [float(r[0]) for r in rows] == [0.4, 0.45], rows
for eps, rest in rows:
    eps = float(eps)
    v = [float(s) for s in rest.split()]
    umf = ergun_umf(eps, x)
    ok &= close("eps %g mixture Umf" % eps, v[0], umf)
    ok &= close("eps %g U0/Umf" % eps, v[1], 1.25 * umf_wy / umf)
    for k, name in enumerate(["small", "large"]):
        alone = ergun_umf(eps, np.eye(2)[k])
        ok &= close("eps %g %s in mixture" % (eps, name), v[2 + k], alone)
        ok &= close("eps %g %s alone" % (eps, name), v[4 + k], alone)
sys.exit(0 if ok else 1)
PY
done

dpmUmf -voidage '(0.4 1.2)' > log.dpmUmf.bad 2>&1 && fail "dpmUmf took voidage 1.2"
grep -q "Option -voidage: '1.2' is outside (0, 1); allowed: one or more voidages, each in (0, 1)" log.dpmUmf.bad \
    || { cat log.dpmUmf.bad; fail "no clear error for -voidage 1.2"; }
echo "voidage 1.2 refused: $(grep -m1 'Option -voidage' log.dpmUmf.bad)"
pass "dpmUmf: Ergun's Umf for every class and the mixture, Wen-Yu's U0, a bad voidage refused"
