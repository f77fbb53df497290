#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# benchmarks/netlSegregationValidation/compare.py on synthetic rise times
# whose statistics are known in closed form: three seeds and three repeats
# per condition, so each 95 % interval is t(0.975, 2) s / sqrt(3) with
# Student's t(0.975, 2) = 4.302653 (Welch's difference of two such sets of
# spread 1: 2.776445 sqrt(2/3), its t at 4 degrees of freedom). Checked: the
# means and intervals, each overlap verdict (yes; no; no for a censored
# seed whose lower bound lies above; undecided for one whose bound does
# not), the surface's bracket with its censored bound, the trends (holds,
# not shown, undecided with a censored seed in either condition where it
# would not hold, or in the faster one where it would; the held-out
# conditions' two), the count of criteria met and the per-seed record.
# Then the experiment's means and intervals from its own files, all eight
# conditions, against the table of LaMarche et al. (2022) in the reference
# folder's SOURCES.md.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
compare=$testsDir/../benchmarks/netlSegregationValidation/compare.py
reference=$testsDir/../../shared/reference/netlSegregation2022/measurements
py() { /usr/bin/python3 "$@"; }

cd "$workDir" || fail "work directory"
py - <<'PY' || fail "synthetic rise times"
import os
nan = float("nan")
os.makedirs("experiment")
def table(path, rows):
    with open(path, "w") as f:
        f.writelines("\t".join("%g" % v for v in r) + "\n" for r in rows)
table("experiment/U214_M177_4L.txt", [[4, 7.1, 8, 9], [5, 8.1, 9, 10], [6, 9.1, 10, 11]])
table("experiment/U183_M177_1L.txt", [[7], [8], [9]])
table("experiment/U183_M227_1L.txt", [[11], [12], [13]])
def seed(run, name, end, rows):
    """rows: [t(q 0.95), t(0.99), t(0.999)] for each rank, as dpmRiseTime writes them."""
    os.makedirs(os.path.join(run, name, "system"))
    with open(os.path.join(run, name, "system", "controlDict"), "w") as f:
        f.write("startTime 0;\nendTime         %g;\n" % end)
    out = os.path.join(run, name, "postProcessing", "riseTime", "0")
    os.makedirs(out)
    with open(os.path.join(out, "riseOrder.dat"), "w") as f:
        f.write("# rank\triseTime_q0.95\triseTime_q0.99\triseTime_q0.999\n")
        f.writelines("%d\t%g\t%g\t%g\n" % ((k + 1,) + tuple(r)) for k, r in enumerate(rows))
# four intruders; the third seed's last two not risen by 24 s at q 0.99 and 0.999
for k, t99 in enumerate(([9, 11, 12, 23], [10, 12, 13, 23.5], [11, 13, nan, nan])):
    t95 = [10.5, 12.5, 20, 22] if k == 2 else [t - 0.5 for t in t99]
    seed("run", "U214_M177_4L_seed%d" % (k + 1), 24,
         [[a, b, b + 1] for a, b in zip(t95, t99)])
for k, t in enumerate((7, 8, 9)):
    seed("run", "U183_M177_1L_seed%d" % (k + 1), 24, [[t - 0.5, t, t + 1]])
for k, t in enumerate((12, 13, 14)):
    seed("run", "U183_M227_1L_seed%d" % (k + 1), 36, [[t - 0.5, t, t + 1]])
# a second run: the heavier bed's third seed not risen by 36 s
for k, t in enumerate((7, 8, 9)):
    seed("censored", "U183_M177_1L_seed%d" % (k + 1), 24, [[t, t, t]])
for k, t in enumerate((8, 9, nan)):
    seed("censored", "U183_M227_1L_seed%d" % (k + 1), 36, [[t, t, t]])
# a third: the lighter bed's third seed not risen by 24 s, the heavier one's
# far later (a run of 72 s): the difference would hold, but the lighter
# bed's bound may understate its mean
for k, t in enumerate((7, 8, nan)):
    seed("fasterCensored", "U183_M177_1L_seed%d" % (k + 1), 24, [[t, t, t]])
for k, t in enumerate((60, 61, 62)):
    seed("fasterCensored", "U183_M227_1L_seed%d" % (k + 1), 72, [[t, t, t]])
# the held-out conditions' trends: small intruders 1 s later than large (not
# shown by three seeds of spread 1), four at 1.83 m/s 3 s later than at 2.134
table("experiment/U214_M177_2L.txt", [[5, 6], [6, 7], [7, 8]])
table("experiment/U214_M177_2S.txt", [[9, 10], [10, 11], [11, 12]])
table("experiment/U183_M177_4L.txt", [[7, 8, 9, 10], [8, 9, 10, 11], [9, 10, 11, 12]])
for k, t in enumerate((5, 6, 7)):
    seed("heldOut", "U214_M177_2L_seed%d" % (k + 1), 24, [[t, t, t], [t + 1, t + 1, t + 1]])
    seed("heldOut", "U214_M177_2S_seed%d" % (k + 1), 36, [[t + 1, t + 1, t + 1], [t + 2, t + 2, t + 2]])
for k, t in enumerate((9, 10, 11)):
    seed("heldOut", "U214_M177_4L_seed%d" % (k + 1), 24, [[t + j, t + j, t + j] for j in range(4)])
    seed("heldOut", "U183_M177_4L_seed%d" % (k + 1), 30, [[t + 3 + j] * 3 for j in range(4)])
PY

py "$compare" run -reference experiment -figure rise.png > log.compare 2>&1 \
    || { cat log.compare; fail "compare.py"; }
cat log.compare
[ -s rise.png ] || fail "no figure"
py - <<'PY' || fail "the statistics of the synthetic rise times"
import math, sys
t2, t4 = 4.302653, 2.776445          # Student's t(0.975, 2) and t(0.975, 4)
def ci(x):
    m = sum(x) / len(x)
    s = math.sqrt(sum((v - m)**2 for v in x) / (len(x) - 1))
    return "%.2f +- %.2f" % (m, t2 * s / math.sqrt(len(x)))
rows = {}
for line in open("log.compare"):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) == 8 and cells[0].startswith("U"):
        rows[(cells[0], int(cells[1]))] = cells
# condition, k: simulated (censored at their end time), experiment, overlap,
# surface 95 % / 99.9 %, not risen
expected = {
    ("U214_M177_4L", 1): (ci([9, 10, 11]), ci([4, 5, 6]), "no", "9.50 / 11.00", "0"),
    ("U214_M177_4L", 2): (ci([11, 12, 13]), ci([7.1, 8.1, 9.1]), "yes", "11.50 / 13.00", "0"),
    ("U214_M177_4L", 3): (">=" + ci([12, 13, 24]), ci([8, 9, 10]), "-", "14.67 / >=17.00", "1"),
    ("U214_M177_4L", 4): (">=" + ci([23, 23.5, 24]), ci([9, 10, 11]), "no", "22.50 / >=24.17", "1"),
    ("U183_M177_1L", 1): (ci([7, 8, 9]), ci([7, 8, 9]), "yes", "7.50 / 9.00", "0"),
    ("U183_M227_1L", 1): (ci([12, 13, 14]), ci([11, 12, 13]), "yes", "12.50 / 14.00", "0"),
}
ok = len(rows) == len(expected)
for key, (sim, exp, overlap, surfaces, censored) in expected.items():
    got = rows.get(key, [""] * 8)
    good = got[2] == "3" and got[3] == sim and got[4] == exp and got[5] == overlap \
        and got[6] == surfaces and got[7] == censored
    ok &= good
    print("%s k %d: %s | %s | %s | %s | %s (expected %s | %s | %s | %s | %s): %s"
          % (key + tuple(got[3:8]) + (sim, exp, overlap, surfaces, censored,
                                      "ok" if good else "WRONG")))
text = open("log.compare").read()
welch = t4 * math.sqrt(2.0 / 3.0)     # two sets of spread 1, three values each
for line in ("heavier bed rises slower, simulated: t_r(1) U183_M227_1L - U183_M177_1L"
             " = 5.00 +- %.2f s: holds" % welch,
             "heavier bed rises slower, experiment: t_r(1) U183_M227_1L - U183_M177_1L"
             " = 4.00 +- %.2f s: holds" % welch,
             "slower gas rises slower, simulated: t_r(1) U183_M177_1L - U214_M177_4L"
             " = -2.00 +- %.2f s: not shown" % welch,
             "slower gas rises slower, experiment: t_r(1) U183_M177_1L - U214_M177_4L"
             " = 3.00 +- %.2f s: holds" % welch,
             "criteria met: 4 of 7 decided (1 undecided)"):
    good = line in text
    ok &= good
    print("%s: %s" % (line, "ok" if good else "MISSING"))
sys.exit(0 if ok else 1)
PY

# Each seed's record, the censored at their end time as bounds
py "$compare" run -reference experiment -perSeed > log.perSeed 2>&1 \
    || { cat log.perSeed; fail "compare.py -perSeed"; }
for row in "| U214_M177_4L | 1 | 9.00, 11.00, 12.00, 23.00 |" \
           "| U214_M177_4L | 3 | 11.00, 13.00, >=24.00, >=24.00 |" \
           "| U183_M227_1L | 2 | 13.00 |"
do
    grep -qF "$row" log.perSeed || fail "-perSeed: '$row' not in $(cat log.perSeed)"
done

py "$compare" censored -reference experiment > log.censored 2>&1 \
    || { cat log.censored; fail "compare.py on censored seeds"; }
grep -q "heavier bed rises slower, simulated: .*: undecided (censored seeds)" log.censored \
    || fail "a trend with a censored seed: $(cat log.censored)"
grep -q "| U183_M227_1L | 1 | 3 | >=" log.censored \
    || fail "a censored mean not given as a bound: $(cat log.censored)"
grep -q "criteria met: 1 of 1 decided (2 undecided)" log.censored \
    || fail "the count with undecided criteria: $(cat log.censored)"
py "$compare" fasterCensored -reference experiment > log.fasterCensored 2>&1 \
    || { cat log.fasterCensored; fail "compare.py on a censored faster condition"; }
grep -q "heavier bed rises slower, simulated: .* = 48.00 +- .*: undecided (censored seeds)" \
    log.fasterCensored || fail "a trend whose faster condition is censored: $(cat log.fasterCensored)"
py "$compare" heldOut -reference experiment > log.heldOut 2>&1 \
    || { cat log.heldOut; fail "compare.py on the held-out conditions"; }
welch=$(awk 'BEGIN { printf "%.2f", 2.776445 * sqrt(2 / 3) }')
for line in "small intruders rise slower, simulated: t_r(1) U214_M177_2S - U214_M177_2L = 1.00 +- $welch s: not shown" \
            "small intruders rise slower, experiment: t_r(1) U214_M177_2S - U214_M177_2L = 4.00 +- $welch s: holds" \
            "slower gas rises slower, four intruders, simulated: t_r(1) U183_M177_4L - U214_M177_4L = 3.00 +- $welch s: holds" \
            "slower gas rises slower, four intruders, experiment: t_r(1) U183_M177_4L - U214_M177_4L = 3.00 +- $welch s: holds"
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
elif [ -n "${DPMFOAM2D_REQUIRE_REFERENCE:-}" ]
then
    fail "no reference folder $reference"
else
    echo "no reference folder $reference: the published table is not checked"
fi
pass "the rise-time comparison's statistics and verdicts on synthetic seeds"
