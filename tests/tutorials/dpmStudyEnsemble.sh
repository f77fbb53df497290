#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmStudy's ensemble arithmetic on synthetic tables with known answers (no
# solver run): a study directory of hand-made cases whose laceyIndex and
# segregation tables hold constants, summed up by `dpmStudy results`.
# Expected, against Student-t quantiles from a printed table (NIST/SEMATECH
# e-Handbook, Table of Upper Critical Values of the t Distribution:
# t(0.975; 2) = 4.303, t(0.975; 4) = 2.776; more digits: 4.302653, 2.776445):
#   - mean and 95 % half-width of M over three seeds (0.3, 0.4, 0.5):
#     0.4 +- 4.302653 x 0.1 / sqrt(3) = 0.248414;
#   - Welch's interval of a difference of two ensembles with equal
#     spreads (dof 4) and with one spread zero (dof 2);
#   - the signs and verdicts of findings 2-4, a one-seed variant screened
#     without an interval, what a variant does to each finding against the
#     baseline's seeds (the shift's interval, a one-seed case taking the
#     baseline's scatter; a three-seed variant that turns findings 3, 4 round), a case without a seed suffix counted alone, a
#     case that has not reached its end time left out of the ensemble;
#   - a template of one's own with its studyDict: its allowed mass
#     fractions and its findings.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
cd "$workDir" || fail "cd"

py - <<'PY' || fail "make the synthetic study"
import os
import numpy as np
def case(name, w, p, seed, M, horizontal=0.0, variant=None, tEnd=2.0):
    d = os.path.join("study", name)
    os.makedirs(os.path.join(d, "constant"))
    os.makedirs(os.path.join(d, "postProcessing", "laceyIndex", "0"))
    with open(os.path.join(d, "constant", "caseSettings"), "w") as f:
        f.write("wSmall %g;\npressure %g;\nseed %d;\nendTime 2;\n" % (w, p, seed))
    if variant:
        with open(os.path.join(d, "constant", "variant"), "w") as f:
            f.write("# variant %s\nsystem/fvSchemes divSchemes/div(voidagePhi,U) Gauss upwind\n"
                    % variant)
    t = np.round(np.arange(0, tEnd + 1e-4, 0.1), 6)
    Mt = np.where(t == 0, 0.8, M)       # M(0) = 0.8, then constant
    with open(os.path.join(d, "postProcessing", "laceyIndex", "0", "laceyIndex.dat"), "w") as f:
        f.write("# Lacey index\n# Time M\n")
        for a, b in zip(t, Mt):
            f.write("%g %.10g\n" % (a, b))
    with open(os.path.join(d, "postProcessing", "laceyIndex", "0", "segregation.dat"), "w") as f:
        f.write("# Time vertical horizontal hSmall hLarge rSmall rLarge\n")
        for a in t:
            f.write("%g 0.5 %.10g 0.1 0.05 0.04 0.03\n" % (a, horizontal))
for k, (m1, m64, h64, m25, m75) in enumerate(zip((0.3, 0.4, 0.5), (0.6, 0.7, 0.8),
                                                  (0.1, 0.2, 0.3), (0.5, 0.5, 0.5),
                                                  (0.2, 0.22, 0.24)), 1):
    case("w0.50_1bar_seed%d" % k, 0.5, 1, k, m1)
    case("w0.50_64bar_seed%d" % k, 0.5, 64, k, m64, horizontal=h64)
    case("w0.25_1bar_seed%d" % k, 0.25, 1, k, m25)
    case("w0.75_1bar_seed%d" % k, 0.75, 1, k, m75)
case("w0.50_8bar", 0.5, 8, 1, 0.33)                 # an unseeded case
case("w0.50_1bar_seed4", 0.5, 1, 4, 0.9, tEnd=1.0)  # still running: left out
case("w0.50_1bar_upwind", 0.5, 1, 1, 0.45, variant="upwind")
case("w0.50_64bar_upwind", 0.5, 64, 1, 0.35, variant="upwind")
for k, m75 in enumerate((0.6, 0.62, 0.64), 1):     # a variant over three seeds
    case("w0.25_1bar_drag_seed%d" % k, 0.25, 1, k, 0.5, variant="drag")
    case("w0.75_1bar_drag_seed%d" % k, 0.75, 1, k, m75, variant="drag")
PY
dpmStudy results study -noPictures -mean 1 > log.results 2>&1 || { cat log.results; fail "dpmStudy results"; }
cat log.results
cat study/results/findings.md

py - <<'PY' || fail "ensemble numbers"
import csv
from math import sqrt
T2, T4 = 4.302653, 2.776445          # t(0.975; 2), t(0.975; 4), printed tables
def close(a, b, tol=1e-5):
    assert abs(float(a) - b) < tol, (a, b)
E = {(r["variant"], float(r["wSmall"]), float(r["pressure"])): r
     for r in csv.DictReader(open("study/results/ensemble.csv"))}
r = E["baseline", 0.5, 1]
assert r["n"] == "3" and r["running"] == "1" and r["seeds"] == "1 2 3", r
close(r["Mmean"], 0.4); close(r["MmeanCI"], T2 * 0.1 / sqrt(3))
close(r["M0"], 0.8); close(r["M0CI"], 0.0)
close(r["Mrate"], 0.5)                           # M/M(0) over (0, 1]
r = E["baseline", 0.5, 64]
close(r["horizontal"], 0.2); close(r["horizontalCI"], T2 * 0.1 / sqrt(3))
r = E["baseline", 0.5, 8]
assert r["n"] == "1" and r["MmeanCI"] == "nan", r   # one run: no interval
close(r["Mmean"], 0.33)
r = E["upwind", 0.5, 1]
assert r["n"] == "1", r
F = {(r["variant"], r["comparison"]): r for r in csv.DictReader(open("study/results/findings.csv"))}
f = F["baseline", "final M, 64 - 1 bar, w 0.5"]
close(f["difference"], 0.3); close(f["CI"], T4 * sqrt(0.01 / 3 + 0.01 / 3))
assert f["sign"] == "+" and f["verdict"] == "as the paper", f
f = F["baseline", "horizontal index at 64 bar, w 0.5"]
assert f["sign"] == "none" and f["verdict"] == "no difference resolved", f
f = F["baseline", "final M, w 0.75 - w 0.25, 1 bar"]      # one spread zero: dof 2
close(f["difference"], -0.28); close(f["CI"], T2 * sqrt(0.0004 / 3))
assert f["sign"] == "-" and f["verdict"] == "reversed", f
f = F["baseline", "M/M(0) in the rate window, w 0.75 - w 0.25, 1 bar"]
close(f["difference"], 0.275 - 0.625); close(f["CI"], T2 * sqrt(0.000625 / 3))
assert f["verdict"] == "reversed", f
f = F["upwind", "final M, 64 - 1 bar, w 0.5"]
close(f["difference"], -0.10)
assert f["sign"] == "-?" and f["verdict"].startswith("one seed: against"), f
# Variants against the baseline's seeds (verdicts.csv): the shift of a
# contrast, its interval by Welch-Satterthwaite over the independent
# variances; a one-seed case borrows the baseline case's (weight 1 + 1/3).
V = {(r["variant"], r["comparison"]): r for r in csv.DictReader(open("study/results/verdicts.csv"))}
v = V["upwind", "final M, 64 - 1 bar, w 0.5"]     # two borrowed variances 0.01: dof 4
close(v["shift"], -0.40); close(v["shiftCI"], T4 * sqrt(2 * 0.01 * (1 + 1 / 3)))
assert v["borrowed"] == "True" and v["effect"] == "within the packings' scatter", v
v = V["upwind", "horizontal index at 64 bar, w 0.5"]   # one borrowed variance: dof 2
close(v["shift"], -0.2); close(v["shiftCI"], T2 * sqrt(0.01 * (1 + 1 / 3)))
assert v["effect"] == "within the packings' scatter", v
v = V["drag", "final M, w 0.75 - w 0.25, 1 bar"]   # own spreads 0.0004 and 0 each: dof 4
close(v["value"], 0.12); close(v["CI"], T2 * sqrt(0.0004 / 3))
close(v["shift"], 0.40); close(v["shiftCI"], T4 * sqrt(2 * 0.0004 / 3))
assert v["borrowed"] == "False" and v["effect"] == "turns it round", v
v = V["drag", "M/M(0) in the rate window, w 0.75 - w 0.25, 1 bar"]
close(v["shift"], 0.15 + 0.35)
assert v["effect"] == "turns it round", v
assert ("drag", "final M, 64 - 1 bar, w 0.5") not in V     # drag has no 64-bar case
rows = list(csv.DictReader(open("study/results/summary.csv")))
assert len(rows) == 22, len(rows)      # the running case is in the summary
assert {r["case"]: r["seed"] for r in rows}["w0.50_8bar"] == "", rows
PY
grep -q "^| baseline | 0.50 | 1 | 3 | 1 | 2.00 | 0.800 +- 0.000 | 0.400 +- 0.248 |" study/results/ensemble.md \
    || fail "ensemble.md row"
grep -q "^## upwind" study/results/variants.md || fail "variants.md lacks the variant"
grep -q "^| 3 | final M, w 0.75 - w 0.25, 1 bar | + | -0.280 +- 0.050 | turns it round | drag |" \
    study/results/verdicts.md || fail "verdicts.md lacks finding 3 turned round by drag"
for f in mixing_1bar.png mixing_upwind_1bar.png indices.png upwind_indices.png hydrodynamics.png
do
    [ -s "study/results/$f" ] || fail "no results/$f"
done
# A template of one's own brings its own study: its studyDict's matrix
# limits -w (with its note), its findings are the ones findings.csv tests
# (here one: w 0.75 - w 0.25 of the final M at each pressure, sign -: the
# hand-made values give 0.22 - 0.5 = -0.28 at 1 bar, as above), and the
# study directory's copy of a studyDict is the one results follows
cp -r "$testsDir/../tutorials/paperStudy" mine || fail "copy the template"
cat > mine/studyDict <<'DICT'
massFractions { values (0.25 0.75); allowed (0.25 0.75); allowedNote "my bed has 0.25 and 0.75"; }
pressures { values (1); }
findingsTitle "My finding";
findingsNotes { A "fewer small particles mix better at {rateWindow}"; }
findings
{
    fractions
    {
        each pressure;
        contrasts { m { finding A; comparison "final M, w 0.75 - w 0.25, {pressure} bar"; quantity Mmean; a 0.75; b 0.25; sign -; } }
    }
}
DICT
mkdir mystudy && cp -r study/w0.25_1bar_seed? study/w0.75_1bar_seed? mystudy/ || fail "copy the cases"
dpmStudy run mystudy -w 0.5 -template mine > log.mineW 2>&1 && fail "-w 0.5 ran against the template's allowed values"
grep -q "error: -w 0.5: my bed has 0.25 and 0.75" log.mineW || { cat log.mineW; fail "no message with the template's note"; }
# the study directory's copy (as dpmStudy makes it) wins over -template's default
cp mine/studyDict mystudy/studyDict
dpmStudy results mystudy -noPictures -mean 1 > log.mine 2>&1 \
    || { cat log.mine; fail "dpmStudy results on a study with its own studyDict"; }
py - <<'PY' || fail "the template's own findings"
import csv
rows = list(csv.DictReader(open("mystudy/results/findings.csv")))
base = [r for r in rows if r["variant"] == "baseline"]
assert [(r["finding"], r["comparison"], r["paperSign"]) for r in base] == \
    [("A", "final M, w 0.75 - w 0.25, 1 bar", "-")], base
assert abs(float(base[0]["difference"]) + 0.28) < 1e-9 and base[0]["verdict"] == "as the paper", base
text = open("mystudy/results/findings.md").read()
assert text.startswith("My finding as differences") and \
    "Finding A: fewer small particles mix better at 0 < t <= 1 s." in text, text[:400]
print("findings of the study's own studyDict:", [(r["variant"], r["finding"], r["comparison"]) for r in rows])
import dpmfoam2d as dpm                 # the package's reader of results/ tables
table = dpm.study_table("mystudy", "findings")
assert list(table["finding"]) == ["A"] and abs(table["difference"][0] + 0.28) < 1e-9, table
assert sorted(dpm.study_table("mystudy", "summary")["case"]) == sorted(
    "w0.%d_1bar_seed%d" % (w, k) for w in (25, 75) for k in (1, 2, 3))
PY
pass "ensemble means, Student-t and Welch intervals, findings' signs as computed by hand; a template's own studyDict"
