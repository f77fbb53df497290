#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The paper's case template (tutorials/paperStudy) makes the particles and
# the gas of a (wSmall, pressure) pair set in constant/caseSettings.
# Expected, from the paper's Table 3: 0.25 -> 3945 small / 2555 large,
# 0.5 -> 6610 / 1440, 0.75 -> 8955 / 645; gas density 1.204 x p/bar
# (docs/theory/paper-model.md, "The case"); U0/Umf 1.25; end time and particle interval as set.
#   1. for all 15 pairs: the dictionaries as the solver reads them
#      (foamDictionary -expand), counts as dpmCloud computes them from
#      massFraction and totalMass: round(w M / m);
#   2. one pair (0.25, 16 bar) through dpmFoam2D (endTime 0, no settling):
#      the log's counts and gas density.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
export WM_PROJECT_SITE="${WM_PROJECT_SITE:-$DPMFOAM2D_PROJECT}"

template="$testsDir/../tutorials/paperStudy"
case="$workDir/case"
cp -r "$template" "$case" || fail "copy the template"
(cd "$case" && rm -rf 0 [1-9]* particles postProcessing log.* constant/polyMesh \
    constant/packedBed*)
cd "$case" || fail "cd"

expand() { foamDictionary -expand "$1" 2>/dev/null; }
for w in 0.25 0.5 0.75
do
    for p in 1 8 16 32 64
    do
        setEntry constant/caseSettings wSmall $w
        setEntry constant/caseSettings pressure $p
        expand constant/particleProperties > pp.txt || fail "expand particleProperties"
        expand constant/gasProperties > gp.txt || fail "expand gasProperties"
        py - $w $p <<'PY' || fail "w $w, $p bar"
import math, re, sys
w, p = float(sys.argv[1]), float(sys.argv[2])
table3 = {0.25: (3945, 2555), 0.5: (6610, 1440), 0.75: (8955, 645)}
pp, gp = open("pp.txt").read(), open("gp.txt").read()
def num(text, pattern):
    return float(re.search(pattern, text, re.S).group(1))
M = num(pp, r"\ntotalMass\s+(\S+);")
counts = []
for name, d in (("small", 1.5e-3), ("large", 2.5e-3)):
    wk = num(pp, name + r"\s*\{[^}]*massFraction\s+(\S+);")
    counts.append(round(wk*M/(2525*math.pi*d**3/6)))
ok = tuple(counts) == table3[w]
pressure = num(gp, r"operatingPressure\s+(\S+);")
ok &= pressure == p and num(gp, r"U0byUmf\s+(\S+);") == 1.25
ok &= num(gp, r"densityAtOneBar\s+(\S+);") == 1.204
print("w %.2f %2g bar: counts %s (Table 3 %s), pressure %g bar: %s"
      % (w, p, counts, table3[w], pressure, "ok" if ok else "WRONG"))
sys.exit(0 if ok else 1)
PY
    done
done
expand system/controlDict > cd.txt
grep -q "^endTime *60;" cd.txt || fail "endTime is not 60 s"
grep -q "^writeInterval *0.01;" <(expand constant/particleProperties) \
    || fail "particle files not every 0.01 s"
grep -q "laceyIndex" cd.txt || fail "no laceyIndex function object"

echo "2. dpmFoam2D on (0.25, 16 bar)"
setEntry constant/caseSettings wSmall 0.25
setEntry constant/caseSettings pressure 16
setEntry constant/caseSettings endTime 0
setEntry constant/caseSettings settleTime 0
cp -r 0.orig 0 && blockMesh >log.blockMesh 2>&1 || fail "blockMesh"
runSolver
grep -q "small: 3945 particles" log.dpmFoam2D || fail "log: not 3945 small"
grep -q "large: 2555 particles" log.dpmFoam2D || fail "log: not 2555 large"
grep -q "operating pressure 16 bar, density 19.264 kg/m3" log.dpmFoam2D \
    || fail "log: not 16 bar, 19.264 kg/m3"
grep -q "U0/Umf 1.25" log.dpmFoam2D || fail "log: U0/Umf not 1.25"
pass "the template makes Table 3's particles and the set pressure"
