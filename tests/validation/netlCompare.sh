#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# benchmarks/netlSegregationValidation/compare.py on synthetic rise times
# whose statistics are known, and dpmfoam2d.statistics under it
# (netlStatistics.py: Welch, TOST, the one-sided tests and V&V 20's u_val
# against values computed independently). The synthetic repeats and seeds
# are P = (-1.5, -1, -0.5, 0, 0, 0.5, 1, 1.5), of standard deviation 1,
# scaled and shifted: 8 repeats of sd 1 (the margin Delta = 2 sd = 2 s) against
# 8 seeds of sd 0.5. Each row's expected cells are computed here from the
# formulas (Welch-Satterthwaite by hand, quantiles from scipy.stats.t).
# Checked: equal means met; 1.5 margins apart not met; 1.8 s apart undecided;
# a censored seed not met when even the bound lies above the margin,
# censored where its run ended (a bed at rest ends it before its end time),
# undecided otherwise; the same seeds as a met condition, but 3, too few
# (no verdict); the trends met, the reverse shown (not met), undecided
# with a censored seed on the side that could undo it; V&V 20's u_val with
# both tables' terms, one, or none (u_D alone), from the run folder's
# uncertainty/ or -uncertainty; a bad uncertainty table refused; the
# spread ratio; the count line; the per-seed record; the experiment's
# means and intervals from its own files against the published table.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
compare=$testsDir/../benchmarks/netlSegregationValidation/compare.py
reference=$testsDir/../../shared/reference/netlSegregation2022/measurements
py() { /usr/bin/python3 "$@"; }

py "$testsDir/validation/netlStatistics.py" || fail "dpmfoam2d.statistics against independent values"

cd "$workDir" || fail "work directory"
py - <<'PY' || fail "synthetic rise times"
import os
nan = float("nan")
P = [-1.5, -1, -0.5, 0, 0, 0.5, 1, 1.5]          # sd 1
os.makedirs("experiment")
def table(path, rows):
    with open(path, "w") as f:
        f.writelines("\t".join("%g" % v for v in r) + "\n" for r in rows)
def repeats(*bases):
    return [[b + p for b in bases] for p in P]
table("experiment/U183_M177_1L.txt", repeats(8))
table("experiment/U183_M227_1L.txt", repeats(12))
table("experiment/U214_M177_4L.txt", repeats(5, 6, 7, 8))
table("experiment/U214_M177_2L.txt", repeats(5, 6))
table("experiment/U214_M177_2S.txt", repeats(9, 10))
table("experiment/U183_M177_4L.txt", repeats(8, 9, 10, 11))
def seed(run, name, end, rows, rest=None):
    """rows: [t(q 0.95), t(0.99), t(0.999)] for each rank, as dpmRiseTime writes them;
    the run ended at its end time, or at rest (the bedAtRest line in its log)."""
    os.makedirs(os.path.join(run, name, "system"))
    with open(os.path.join(run, name, "system", "controlDict"), "w") as f:
        f.write("startTime 0;\nendTime         %g;\n" % end)
    for t in ("0", "%g" % ((rest or end) / 2), "%g" % (rest or end)):
        os.makedirs(os.path.join(run, name, t), exist_ok=True)
    if rest:
        with open(os.path.join(run, name, "log.dpmFoam2D"), "w") as f:
            f.write("bedAtRest bedAtRest: the bed has been at rest (its speed below 0.01 m/s)"
                    " since t = %g, for 2 s by t = %g; ending the run after one more step\n"
                    % (rest - 2, rest))
    out = os.path.join(run, name, "postProcessing", "riseTime", "0")
    os.makedirs(out)
    with open(os.path.join(out, "riseOrder.dat"), "w") as f:
        f.write("# rank\triseTime_q0.95\triseTime_q0.99\triseTime_q0.999\n")
        f.writelines("%d\t%g\t%g\t%g\n" % ((k + 1,) + tuple(r)) for k, r in enumerate(rows))
def bracket(*t99):
    """[t95, t99, t999] of each rank: the surface's bracket 0.5 s earlier, 1 s later."""
    return [[t - 0.5, t, t + 1] for t in t99]
def same(*t):
    return [[v, v, v] for v in t]
# run: equal means (met), 1.5 margins apart (not met), and four intruders:
# k 1 1.8 s late (undecided), k 2 on the experiment's (met), k 3 and 4 with
# the 8th seed not risen by 24 s (at q 0.99 and 0.999; risen at 0.95 by 20
# and 22 s): k 3's bound near the experiment's (undecided), k 4's 13 s late
for i, p in enumerate(P):
    seed("run", "U183_M177_1L_seed%d" % (i + 1), 24, bracket(8 + 0.5 * p))
    seed("run", "U183_M227_1L_seed%d" % (i + 1), 36, bracket(15 + 0.5 * p))
    rows = bracket(6.8 + 0.5 * p, 6 + 0.5 * p, 7 + 0.5 * p, 20 + 0.5 * p)
    if i == 7:
        rows[2:] = [[20, nan, nan], [22, nan, nan]]
    seed("run", "U214_M177_4L_seed%d" % (i + 1), 24, rows)
os.makedirs("run/uncertainty")
with open("run/uncertainty/U183_M177_1L.dat", "w") as f:
    f.write("# rank u_input u_num\n1 0.4 0.3\n")
with open("run/uncertainty/U183_M227_1L.dat", "w") as f:
    f.write("# rank u_num\n1 0.5\n")
# fewSeeds: the first three of run's equal means: too few for a verdict
for i, p in enumerate((-1, 0, 1)):
    seed("fewSeeds", "U183_M177_1L_seed%d" % (i + 1), 24, bracket(8 + 0.5 * p))
    seed("fewSeeds", "U183_M227_1L_seed%d" % (i + 1), 36, bracket(15 + 0.5 * p))
# censored: the heavier bed's 8th seed not risen when its bed came to rest
# at 9 s (its end time 36 s), the others 3 s early: the reverse of the trend
# shown, but on a bound taken where the run ended
for i, p in enumerate(P):
    seed("censored", "U183_M177_1L_seed%d" % (i + 1), 24, same(8 + 0.5 * p))
    seed("censored", "U183_M227_1L_seed%d" % (i + 1), 36,
         same(nan if i == 7 else 5 + 0.2 * p), rest=9 if i == 7 else None)
# fasterCensored: the trend shown, but the faster condition's 8th seed not
# risen by 24 s: its bound may understate its mean
for i, p in enumerate(P):
    seed("fasterCensored", "U183_M177_1L_seed%d" % (i + 1), 24, same(nan if i == 7 else 8 + 0.5 * p))
    seed("fasterCensored", "U183_M227_1L_seed%d" % (i + 1), 72, same(60 + p))
# heldOut: small intruders 1 s earlier than large (the reverse shown), four
# at 1.83 m/s 3 s later than at 2.134 (shown), all of sd 1
for i, p in enumerate(P):
    seed("heldOut", "U214_M177_2L_seed%d" % (i + 1), 24, same(5 + p, 6 + p))
    seed("heldOut", "U214_M177_2S_seed%d" % (i + 1), 36, same(4 + p, 5 + p))
    seed("heldOut", "U214_M177_4L_seed%d" % (i + 1), 24, same(9 + p, 10 + p, 11 + p, 12 + p))
    seed("heldOut", "U183_M177_4L_seed%d" % (i + 1), 30, same(12 + p, 13 + p, 14 + p, 15 + p))
PY

py "$compare" run -reference experiment -figure rise.png > log.compare 2>&1 \
    || { cat log.compare; fail "compare.py"; }
cat log.compare
[ -s rise.png ] || fail "no figure"
py - <<'PY' || fail "the statistics and verdicts of the synthetic rise times"
import math, sys
import numpy as np
from scipy import stats
P = np.array([-1.5, -1, -0.5, 0, 0, 0.5, 1, 1.5])
def ci(x):
    x = np.asarray(x, float)
    return "%.2f +- %.2f" % (x.mean(), stats.t.ppf(0.975, len(x) - 1) * x.std(ddof=1) / math.sqrt(len(x)))
def welch(a, b):
    """difference, 90 % interval by hand (Welch-Satterthwaite), TOST p at margin 2 sd(b)"""
    a, b = np.asarray(a, float), np.asarray(b, float)
    qa, qb = a.var(ddof=1) / len(a), b.var(ddof=1) / len(b)
    dof = (qa + qb)**2 / (qa**2 / (len(a) - 1) + qb**2 / (len(b) - 1))
    se, d, margin = math.sqrt(qa + qb), a.mean() - b.mean(), 2 * b.std(ddof=1)
    h = stats.t.ppf(0.95, dof) * se
    p = max(stats.t.sf((d + margin) / se, dof), stats.t.cdf((d - margin) / se, dof))
    return d, d - h, d + h, margin, p
def row(c, k, sim, exp, verdict, u_terms, surfaces, censored, lower=""):
    """The expected cells: u_terms are (u_input, u_num), None where not estimated."""
    d, lo, hi, margin, p = welch(sim, exp)
    u_D = np.std(exp, ddof=1) / math.sqrt(len(exp))
    u = math.sqrt(u_D**2 + sum(v**2 for v in u_terms if v is not None))
    note = " (u_D alone)" if u_terms == (None, None) else \
        " (without u_input)" if u_terms[0] is None else " (without u_num)" if u_terms[1] is None else ""
    e = np.mean(sim) - np.mean(exp)
    return [c, str(k), str(len(sim)), lower + ci(sim), ci(exp), "%s%.2f" % (lower, d),
            "%.2f to %.2f" % (lo, hi), "%.2f" % margin, "%.3f" % p, verdict, "%.2f%s" % (u, note),
            "%.2f %s %.2f" % (abs(e), "<=" if abs(e) <= 2 * u else ">", 2 * u),
            "%.2f" % (np.std(sim, ddof=1) / np.std(exp, ddof=1)), surfaces, str(censored)]
rows = {}
for line in open("log.compare"):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) == 15 and cells[0].startswith("U"):
        rows[(cells[0], int(cells[1]))] = cells
k3 = np.r_[7 + 0.5 * P[:7], 24]          # the 8th seed at its end time
k4 = np.r_[20 + 0.5 * P[:7], 24]
expected = {
    ("U183_M177_1L", 1): row("U183_M177_1L", 1, 8 + 0.5 * P, 8 + P, "met", (0.4, 0.3),
                             "7.50 / 9.00", 0),
    ("U183_M227_1L", 1): row("U183_M227_1L", 1, 15 + 0.5 * P, 12 + P, "not met", (None, 0.5),
                             "14.50 / 16.00", 0),
    ("U214_M177_4L", 1): row("U214_M177_4L", 1, 6.8 + 0.5 * P, 5 + P, "undecided", (None, None),
                             "6.30 / 7.80", 0),
    ("U214_M177_4L", 2): row("U214_M177_4L", 2, 6 + 0.5 * P, 6 + P, "met", (None, None),
                             "5.50 / 7.00", 0),
    ("U214_M177_4L", 3): row("U214_M177_4L", 3, k3, 7 + P, "undecided (censored seeds)",
                             (None, None), "%.2f / >=%.2f" % (np.r_[k3[:7] - 0.5, 20].mean(),
                                                             np.r_[k3[:7] + 1, 24].mean()), 1, ">="),
    ("U214_M177_4L", 4): row("U214_M177_4L", 4, k4, 8 + P, "not met", (None, None),
                             "%.2f / >=%.2f" % (np.r_[k4[:7] - 0.5, 22].mean(),
                                                np.r_[k4[:7] + 1, 24].mean()), 1, ">="),
}
ok = len(rows) == len(expected)
for key, want in expected.items():
    got = rows.get(key, [""] * 15)
    good = got == want
    ok &= good
    print("%s k %d: %s\n  expected %s: %s" % (key + (" | ".join(got), " | ".join(want),
                                                   "ok" if good else "WRONG")))
text = open("log.compare").read()
def trend(name, a, b, tail):
    a, b = np.asarray(a, float), np.asarray(b, float)
    qa, qb = a.var(ddof=1) / len(a), b.var(ddof=1) / len(b)
    dof = (qa + qb)**2 / (qa**2 / (len(a) - 1) + qb**2 / (len(b) - 1))
    d, se = a.mean() - b.mean(), math.sqrt(qa + qb)
    h = stats.t.ppf(0.95, dof) * se
    return "%s = %.2f s, 90 %% interval %.2f to %.2f, one-sided p %.3f: %s" \
        % (name, d, d - h, d + h, stats.t.sf(d / se, dof), tail)
for line in (trend("heavier bed rises slower, simulated: t_r(1) U183_M227_1L - U183_M177_1L",
                   15 + 0.5 * P, 8 + 0.5 * P, "met"),
             trend("heavier bed rises slower, experiment: t_r(1) U183_M227_1L - U183_M177_1L",
                   12 + P, 8 + P, "shown"),
             trend("slower gas rises slower, simulated: t_r(1) U183_M177_1L - U214_M177_4L",
                   8 + 0.5 * P, 6.8 + 0.5 * P, "met"),
             "u_input not estimated (no table run/uncertainty/<condition>.dat, or nan there) "
             "for U183_M227_1L k 1",
             "u_num, u_input not estimated (no table run/uncertainty/<condition>.dat, or nan "
             "there) for U214_M177_4L k 1, U214_M177_4L k 2, U214_M177_4L k 3, U214_M177_4L k 4",
             "criteria: met 4 of 8, not met 2, undecided 2, too few seeds 0"):
    good = line in text
    ok &= good
    print("%s: %s" % (line, "ok" if good else "MISSING"))
sys.exit(0 if ok else 1)
PY

# The uncertainty tables from another folder; one that is not a table of
# uncertainties refused, naming it
mkdir elsewhere || fail "work directory"
printf '# rank u_input u_num\n1 0.1 0.1\n2 0.1 0.1\n3 0.1 0.1\n4 0.1 0.1\n' > elsewhere/U214_M177_4L.dat
py "$compare" run -reference experiment -uncertainty elsewhere > log.elsewhere 2>&1 \
    || { cat log.elsewhere; fail "compare.py -uncertainty"; }
u=$(py -c "import math; print('%.2f' % math.sqrt(0.02 + 1 / 8))")
grep -q "| U214_M177_4L | 1 | 8 | .* | $u | " log.elsewhere \
    || fail "-uncertainty: u_val $u of U214_M177_4L k 1 not in $(cat log.elsewhere)"
grep -q "| U183_M177_1L | 1 | 8 | .* (u_D alone) |" log.elsewhere \
    || fail "-uncertainty: run/uncertainty read although another folder was given"
printf '# rank u_input u_num\n1 -0.4 0.3\n' > elsewhere/U183_M177_1L.dat
py "$compare" run -reference experiment -uncertainty elsewhere > log.badTable 2>&1 \
    && fail "a negative uncertainty accepted: $(cat log.badTable)"
grep -q "elsewhere/U183_M177_1L.dat: rank 1, u_input = -0.4" log.badTable \
    || fail "a bad uncertainty table not named: $(cat log.badTable)"
printf '# rank u_numerical\n1 0.3\n' > elsewhere/U183_M177_1L.dat
py "$compare" run -reference experiment -uncertainty elsewhere > log.badTable 2>&1 \
    && fail "an unknown column accepted: $(cat log.badTable)"
grep -q "elsewhere/U183_M177_1L.dat: columns rank u_numerical" log.badTable \
    || fail "an unknown column not named: $(cat log.badTable)"

# Each seed's record, the censored at their end time as bounds
py "$compare" run -reference experiment -perSeed > log.perSeed 2>&1 \
    || { cat log.perSeed; fail "compare.py -perSeed"; }
for row in "| U214_M177_4L | 1 | 6.05, 5.25, 6.25, 19.25 |" \
           "| U214_M177_4L | 8 | 7.55, 6.75, >=24.00, >=24.00 |" \
           "| U183_M227_1L | 2 | 14.50 |"
do
    grep -qF "$row" log.perSeed || fail "-perSeed: '$row' not in $(cat log.perSeed)"
done

# The same seeds as run's met condition, three of them: no verdict
py "$compare" fewSeeds -reference experiment > log.fewSeeds 2>&1 \
    || { cat log.fewSeeds; fail "compare.py on three seeds"; }
grep -q "| U183_M177_1L | 1 | 3 | .* | too few seeds (n < 8) |" log.fewSeeds \
    || fail "three seeds given a verdict: $(cat log.fewSeeds)"
grep -q "heavier bed rises slower, simulated: .*: too few seeds (n < 8)" log.fewSeeds \
    || fail "a trend on three seeds given a verdict: $(cat log.fewSeeds)"
grep -q "criteria: met 0 of 3, not met 0, undecided 0, too few seeds 3" log.fewSeeds \
    || fail "the count with too few seeds: $(cat log.fewSeeds)"

py "$compare" censored -reference experiment > log.censored 2>&1 \
    || { cat log.censored; fail "compare.py on censored seeds"; }
grep -q "heavier bed rises slower, simulated: .*: undecided (censored seeds)" log.censored \
    || fail "a reverse trend on a censored slower condition: $(cat log.censored)"
grep -q "| U183_M227_1L | 1 | 8 | >=.* | undecided (censored seeds) |" log.censored \
    || fail "a censored mean below the margin not undecided, or not a bound: $(cat log.censored)"
grep -q "criteria: met 1 of 3, not met 0, undecided 2, too few seeds 0" log.censored \
    || fail "the count with undecided criteria: $(cat log.censored)"
# the seed whose bed came to rest censored where its run ended (9 s), not at
# its end time (36 s): the bound's mean (7 seeds of 5 + 0.2 P and 9) 5.46 s
grep -q "| U183_M227_1L | 1 | 8 | >=5.46 " log.censored \
    || fail "a seed at rest not censored where its run ended: $(cat log.censored)"
py "$compare" censored -reference experiment -perSeed > log.censoredSeeds 2>&1 \
    || { cat log.censoredSeeds; fail "compare.py -perSeed on censored seeds"; }
grep -qF "| U183_M227_1L | 8 | >=9.00 (at rest) |" log.censoredSeeds \
    || fail "-perSeed: the seed at rest not marked: $(cat log.censoredSeeds)"
py "$compare" fasterCensored -reference experiment > log.fasterCensored 2>&1 \
    || { cat log.fasterCensored; fail "compare.py on a censored faster condition"; }
grep -q "heavier bed rises slower, simulated: .*: undecided (censored seeds)" \
    log.fasterCensored || fail "a trend whose faster condition is censored: $(cat log.fasterCensored)"
py "$compare" heldOut -reference experiment > log.heldOut 2>&1 \
    || { cat log.heldOut; fail "compare.py on the held-out conditions"; }
# two sets of 8 of sd 1: se 0.5, dof 14
read -r h p1 p2 <<< "$(py -c "
from scipy import stats
print('%.2f %.3f %.3f' % (stats.t.ppf(0.95, 14) * 0.5, stats.t.sf(-2, 14), stats.t.sf(6, 14)))")"
lo1=$(awk -v h=$h 'BEGIN { printf "%.2f to %.2f", -1 - h, -1 + h }')
lo2=$(awk -v h=$h 'BEGIN { printf "%.2f to %.2f", 3 - h, 3 + h }')
lo3=$(awk -v h=$h 'BEGIN { printf "%.2f to %.2f", 4 - h, 4 + h }')
p3=$(py -c "from scipy import stats; print('%.3f' % stats.t.sf(8, 14))")
for line in "small intruders rise slower, simulated: t_r(1) U214_M177_2S - U214_M177_2L = -1.00 s, 90 % interval $lo1, one-sided p $p1: not met (the reverse shown)" \
            "small intruders rise slower, experiment: t_r(1) U214_M177_2S - U214_M177_2L = 4.00 s, 90 % interval $lo3, one-sided p $p3: shown" \
            "slower gas rises slower, four intruders, simulated: t_r(1) U183_M177_4L - U214_M177_4L = 3.00 s, 90 % interval $lo2, one-sided p $p2: met" \
            "criteria: met 3 of 14, not met 11, undecided 0, too few seeds 0"
do
    grep -qF "$line" log.heldOut || fail "held-out trend: '$line' not in $(cat log.heldOut)"
done

# heights.py on particle files with known heights: 100 glass centres at
# 1..100 mm (99 % below 99.01 mm, numpy's linear quantile), two intruders
# listed in the reverse order of their ids, rising 1 mm per second
BENCH=$testsDir/../benchmarks/netlSegregationValidation py - <<'PY' || fail "heights.py's series"
import sys
import numpy as np
from dpmfoam2d import particles as pio
import importlib.util, os
spec = importlib.util.spec_from_file_location("heights", os.environ["BENCH"] + "/heights.py")
heights = importlib.util.module_from_spec(spec); spec.loader.exec_module(heights)
for k in range(5):
    t = 0.5 * k
    y = np.concatenate([np.arange(1, 101) * 1e-3, [0.020 + 1e-3 * t, 0.010 + 1e-3 * t]])
    pos = np.column_stack([np.full(102, 0.01), y, np.full(102, 0.01)])
    pio.write_particles("heights", t, pos, np.full(102, 3e-3), np.r_[np.zeros(100, np.int8), [1, 1]],
                        ids=np.r_[np.arange(100), [101, 100]])
t, y, surface, mean = heights.series("heights", "1", 1.0)
ok = np.allclose(t, [0, 1, 2]) and np.allclose(y[:, 0], [0.010, 0.011, 0.012]) \
    and np.allclose(y[:, 1], [0.020, 0.021, 0.022]) and np.allclose(surface, 0.09901) \
    and np.allclose(mean, 0.0505)
print("heights.py series: t %s, intruders %s, surface %s, mean %s: %s"
      % (t, y.tolist(), surface, mean, "ok" if ok else "WRONG"))
sys.exit(0 if ok else 1)
PY
# The experiment's own files against its published means and intervals
if [ -d "$reference" ]
then
    rm -rf published && mkdir published || fail "work directory"
    for c in U214_M177_4L U183_M177_1L U183_M227_1L
    do
        cp -r run/${c}_seed1 published/ || fail "copy"
    done
    # a seed of each condition's intruder count (compare.py refuses others)
    for c in U183_M177_4L U183_M227_4L
    do
        cp -r heldOut/U214_M177_4L_seed1 published/${c}_seed1 || fail "copy"
    done
    for c in U199_M177_2L U214_M177_2L U214_M177_2S
    do
        cp -r heldOut/U214_M177_2L_seed1 published/${c}_seed1 || fail "copy"
    done
    py "$compare" published -reference "$reference" > log.published 2>&1 \
        || { cat log.published; fail "compare.py with the experiment's files"; }
    for row in "U214_M177_4L | 1 | .* | 5.15 +- 0.31" "U214_M177_4L | 2 | .* | 5.54 +- 0.49" \
               "U214_M177_4L | 3 | .* | 6.12 +- 0.61" "U214_M177_4L | 4 | .* | 7.04 +- 0.81" \
               "U183_M177_1L | 1 | .* | 7.50 +- 0.88" "U183_M227_1L | 1 | .* | 11.92 +- 0.94" \
               "U183_M177_4L | 1 | .* | 7.19 +- 1.04" "U183_M177_4L | 4 | .* | 9.38 +- 1.88" \
               "U183_M227_4L | 1 | .* | 9.21 +- 3.01" "U183_M227_4L | 4 | .* | 15.41 +- 1.80" \
               "U199_M177_2L | 1 | .* | 5.87 +- 0.50" "U199_M177_2L | 2 | .* | 6.76 +- 0.49" \
               "U214_M177_2L | 1 | .* | 5.49 +- 0.75" "U214_M177_2L | 2 | .* | 6.67 +- 0.84" \
               "U214_M177_2S | 1 | .* | 9.64 +- 1.47" "U214_M177_2S | 2 | .* | 11.18 +- 1.18"
    do
        grep -q "$row |" log.published || fail "the experiment's table: '$row' not in $(cat log.published)"
    done
    # the margins, twice the repeats' standard deviations: the published
    # half-widths (rounded to 0.001 s) times 2 sqrt(n) / t(0.975, n - 1), to
    # the last digit either way; one seed: too few for a verdict
    read -r m1 m2 <<< "$(py -c "
from scipy import stats
def margin(h, n):
    m = 2 * h * n**0.5 / stats.t.ppf(0.975, n - 1)
    return r'\(%.2f\|%.2f\)' % (m - 0.005, m + 0.005)
print(margin(0.312, 9), margin(0.939, 12))")"
    for row in "U214_M177_4L | 1 | 1 | .* | 5.15 +- 0.31 | .* | - | $m1 | - | too few seeds (n < 8) |" \
               "U183_M227_1L | 1 | 1 | .* | 11.92 +- 0.94 | .* | - | $m2 | - | too few seeds (n < 8) |"
    do
        grep -q "$row" log.published || fail "the experiment's margin: '$row' not in $(cat log.published)"
    done
elif [ -n "${DPMFOAM2D_REQUIRE_REFERENCE:-}" ]
then
    fail "no reference folder $reference"
else
    echo "no reference folder $reference: the published table is not checked"
fi
pass "the rise-time comparison's statistics (Welch, TOST, V&V 20) and verdicts on synthetic seeds"
