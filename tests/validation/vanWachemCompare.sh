#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# benchmarks/vanWachemValidation/compare.py on synthetic records whose
# figures are known in closed form: an "experiment" of sines (pressure
# 80 sqrt2 sin(2 pi 2 t) over 3-6 s, bed height 0.12 + 0.02 sin(2 pi 2.5 t)
# over 2-4 s) and a "run" of sines (probe p_rgh 500 + 88 sqrt2 sin(2 pi 2.5 t)
# every 1e-4 s over 0-8 s, restarted at 5 s after a first run killed at
# 5.5 s in the middle of a row; 200 particles with their tops
# at 0.13 + 0.012 sin(2 pi 2.5 t), one with its top at 0.3 m, every 0.01 s).
# Expected after the 2-s transient (whole periods, so exact up to the
# grids): rms A/sqrt2 (88 and 80 Pa; 0.5 %), dominant frequencies 2.5 and
# 2 Hz (the 0.01-Hz grid), the 99 % bed height's mean 0.13 m and rms
# 0.012/sqrt2 m (0.5 %), the highest particle's top 0.3 m; the verdicts
# +10 % within (pressure rms), +25 % OUTSIDE (pressure frequency), +8 %
# within (mean bed height), -40 % OUTSIDE (bed height rms), +0 % within
# (its frequency). Over windows of 2 s (--window 2, 2-8 s: five windows,
# whole periods) every window has the same figures: median and range the
# whole record's (0.5 %). Bad input refused in one line naming the file or
# entry.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
compare=$testsDir/../benchmarks/vanWachemValidation/compare.py
py() { /usr/bin/python3 "$@"; }

cd "$workDir" || fail "work directory"
py - <<'PY' || fail "synthetic records"
import os, sys
import numpy as np
from dpmfoam2d import particles as pio, tables
two_pi = 2 * np.pi
os.makedirs("experiment")
t = np.arange(3.0, 6.0 + 1e-9, 1e-3)
np.savetxt("experiment/relative_pressure.csv", np.column_stack([t, 80 * 2**0.5 * np.sin(two_pi * 2 * t)]),
           delimiter=",", header="t,p", comments="")
t = np.arange(2.0, 4.0 + 1e-9, 1e-3)
np.savetxt("experiment/height.csv", np.column_stack([t, 0.12 + 0.02 * np.sin(two_pi * 2.5 * t)]),
           delimiter=",", header="t,h", comments="")
os.makedirs("run/system"); open("run/system/controlDict", "w").close()
def probe(start, t, p):
    d = "run/postProcessing/pressureProbe/%s" % start
    os.makedirs(d)
    with open(d + "/p_rgh", "w") as f:
        f.write("# Probe 0 (0.045 0.045 0.004)\n#  Probe  0\n#  Time\n")
        f.writelines("%.10g %.17g\n" % r for r in zip(t, p))
p = lambda t: 500 + 88 * 2**0.5 * np.sin(two_pi * 2.5 * t)
t = np.arange(1, 55001) * 1e-4                   # a first run to 5.5 s ...
probe("0", t, np.where(t < 5 - 1e-9, p(t), 1e6))  # ... whose rows past the restart are dropped
with open("run/postProcessing/pressureProbe/0/p_rgh", "a") as f:
    f.write("5.5001 12")                         # killed while writing a row
t = 5 + np.arange(1, 30001) * 1e-4
probe("5", t, p(t))
d = np.full(200, 1.545e-3)
for k in range(801):
    t = 0.01 * k
    y = np.full(200, 0.13 + 0.012 * np.sin(two_pi * 2.5 * t)) - d / 2
    y[7] = 0.3 - d[7] / 2
    pio.write_particles("run", t, np.column_stack([np.linspace(0.01, 0.08, 200), y]), d,
                        np.zeros(200, np.int8))
PY

py "$compare" --run synthetic=run --reference experiment --figures figures \
    --table table.md > log.compare 2>&1 || { cat log.compare; fail "compare.py"; }
cat log.compare
[ -s figures/timeSeries.png ] && [ -s figures/spectra.png ] || fail "no figures"

py - <<'PY' || fail "the figures of the synthetic records"
import sys
rows = {}
for line in open("table.md"):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) > 4:
        rows[cells[0]] = cells
def num(label, col):
    return float(rows[label][col])
checks = [  # label, column (2 experiment, 3 run), expected, relative tolerance
    ("pressure: rms fluctuation", 2, 80.0, 5e-3),
    ("pressure: rms fluctuation", 3, 88.0, 5e-3),
    ("pressure: mean (exp.: removed)", 3, 500.0, 1e-3),
    ("pressure: peak-to-peak", 3, 2 * 88 * 2**0.5, 1e-2),
    ("pressure: dominant frequency", 2, 2.0, 0.0051),
    ("pressure: dominant frequency", 3, 2.5, 0.0041),
    ("bed height (99 %): mean", 2, 120.0, 1e-3),
    ("bed height (99 %): mean", 3, 130.0, 1e-3),
    ("bed height: rms (amplitude)", 3, 12 / 2**0.5, 5e-3),
    ("bed height: dominant frequency", 3, 2.5, 0.0041),
    ("highest particle: mean", 3, 300.0, 1e-3),
]
ok = True
for label, col, expected, tol in checks:
    got = num(label, col)
    good = abs(got - expected) <= tol * abs(expected)
    ok &= good
    print("%-32s %s %10.5g expected %10.5g (%.1e): %s" % (label, "exp" if col == 2 else "run",
          got, expected, tol, "ok" if good else "WRONG"))
verdicts = [("pressure: rms fluctuation", "+10 % within"),
            ("pressure: dominant frequency", "+25 % OUTSIDE"),
            ("bed height (99 %): mean", "+8 % within"),
            ("bed height: rms (amplitude)", "-40 % OUTSIDE"),
            ("bed height: dominant frequency", "+0 % within")]
for label, expected in verdicts:
    good = rows[label][4] == expected
    ok &= good
    print("%-32s verdict '%s', expected '%s'" % (label, rows[label][4], expected))
sys.exit(0 if ok else 1)
PY

py "$compare" --run synthetic=run --reference experiment --figures figures \
    --window 2 --until 8 --table windows.md > log.windows 2>&1 \
    || { cat log.windows; fail "compare.py --window"; }
grep -q "median (range) of 5 windows of 2 s" log.windows || fail "--window: $(cat log.windows)"
py - <<'PY' || fail "the figures of the synthetic records over windows"
import re, sys
rows = {}
for line in open("windows.md"):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) > 4:
        rows[cells[0]] = cells
ok = True
for label, expected in [("pressure: rms fluctuation", 88.0),
                        ("pressure: dominant frequency", 2.5),
                        ("bed height: rms (amplitude)", 12 / 2**0.5)]:
    m = re.match(r"(\S+) \((\S+)-(\S+)\)$", rows[label][3])
    values = [float(v) for v in m.groups()] if m else []
    good = len(values) == 3 and all(abs(v - expected) <= 5e-3 * expected for v in values)
    ok &= good
    print("%-32s windows '%s' expected %.5g: %s" % (label, rows[label][3], expected,
                                                  "ok" if good else "WRONG"))
sys.exit(0 if ok else 1)
PY

# Bad input: one line naming the entry or the file
out=$(py "$compare" --run synthetic=run --reference experiment --until 9 2>&1) \
    && fail "--until past the run's end accepted"
grep -q "until 9 s: the run ends at 8 s" <<<"$out" || fail "--until past the end: $out"
out=$(py "$compare" --run synthetic=run --reference experiment --window 4 --transient 4 2>&1) \
    && fail "a window longer than half the record accepted"
grep -q "fewer than two windows" <<<"$out" || fail "--window too long: $out"
out=$(py "$compare" --run synthetic 2>&1) && fail "--run without '=' accepted"
grep -q "expected <label>=<case directory>" <<<"$out" || fail "--run without '=': $out"
out=$(py "$compare" run --reference missing 2>&1) && fail "a missing reference folder accepted"
grep -q "missing/relative_pressure.csv: missing" <<<"$out" || fail "missing reference: $out"
mkdir -p empty/system && touch empty/system/controlDict
out=$(py "$compare" empty --reference experiment 2>&1) && fail "a case without the probe accepted"
[ "$(wc -l <<<"$out")" -eq 1 ] && grep -q "pressureProbe/<startTime>/p_rgh" <<<"$out" \
    || fail "a case without the probe: $out"
pass "the comparison's figures and verdicts of synthetic records"
