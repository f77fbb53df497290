#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmPlotMixing on three synthetic cases (makeCase.py mixing; the second
# split over start times 0 and 2.5 as after a restart, the first directory
# holding rows up to 3.0 that the restart replaces; the third as the second
# but its run from 2.5 killed at 3.5 s and run again from 2.5, whose rows
# are in laceyIndex_2.5.dat). Expected: one M(t)
# curve per case and two segregation curves per case (-report), 51 rows
# per case (t = 0..5 s every 0.1 s, no duplicates after the join), and in
# the PNG the first three matplotlib cycle colours (C0 C1 C2) each on at
# least 300 pixels while the fourth (C3) is absent.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/pictures/pictureFunctions"

make="$testsDir/pictures/makeCase.py"
mkdir -p p1 p16 p64 || fail "mkdir"
/usr/bin/python3 "$make" mixing p1 1.0 0.3 3 || fail "makeCase mixing"
/usr/bin/python3 "$make" mixing p16 1.0 0.6 2 restart || fail "makeCase mixing"
/usr/bin/python3 "$make" mixing p64 0.9 0.8 1 rerun || fail "makeCase mixing"
dpmPlotMixing p1 p16 p64 -labels "1 bar" "16 bar" "64 bar" -o plot.png -report \
    >report.json 2>log.dpmPlotMixing || { cat log.dpmPlotMixing; fail "dpmPlotMixing failed"; }
cat report.json
/usr/bin/python3 - report.json plot.png <<'PY' || fail "curves"
import json, sys
import numpy as np, matplotlib.image as m
r = json.load(open(sys.argv[1]))
assert r["mixingCurves"] == 3, r["mixingCurves"]
assert r["segregationCurves"] == 6, r["segregationCurves"]
assert [c["laceyRows"] for c in r["cases"]] == [51] * 3
assert [c["segregationRows"] for c in r["cases"]] == [51] * 3
# p16: M(5) = 0.6 + 0.4 exp(-2.5) from the second start-time directory
assert abs(r["cases"][1]["finalM"] - (0.6 + 0.4 * np.exp(-2.5))) < 1e-5
# p64: M(5) = 0.8 + 0.1 exp(-5) from the second run from 2.5
assert abs(r["cases"][2]["finalM"] - (0.8 + 0.1 * np.exp(-5))) < 1e-5
img = (m.imread(sys.argv[2])[:, :, :3] * 255).round()
def count(hexc):
    c = np.array([int(hexc[i:i + 2], 16) for i in (1, 3, 5)])
    return int(np.all(np.abs(img - c) <= 2, axis=2).sum())
n = {k: count(v) for k, v in
     {"C0": "#1f77b4", "C1": "#ff7f0e", "C2": "#2ca02c", "C3": "#d62728"}.items()}
print("pixels per curve colour", n)
assert min(n["C0"], n["C1"], n["C2"]) >= 300 and n["C3"] == 0, n
PY
pass "one M(t) curve per case, restart directories and reruns joined"
