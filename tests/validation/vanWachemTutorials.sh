#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# benchmarks/vanWachemValidation/Allrun on tutorials/vanWachemBed (slab),
# tutorials/vanWachemBed2D (discs) and the bracket 2D:DiFelice, cut to
# 0.05 s of settling and 0.12 s of gas, then its compare.py on the three
# runs and on the experiment's digitized curves (the folder
# ../shared/reference/vanWachem2001 beside the repository, or VANWACHEM_REFERENCE; left out with
# compare.py's note when absent). The machinery, not the physics: the
# experiment's particles (17,562 spheres; 3392 discs, README.md of the 2D
# tutorial), U0 0.9 m/s (the experiment's), the probe every CFD step
# (1200 rows) inside the mesh, the bracket's drag on its base's settled bed,
# a table with every figure of the three runs, and an unknown bracket
# refused before anything runs.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
py() { /usr/bin/python3 "$@"; }
bench=$testsDir/../benchmarks/vanWachemValidation

out=$(RUN="$workDir/bad" "$bench/Allrun" 0.12 slab 2D:DiFelise 2>&1) && fail "an unknown bracket accepted"
grep -q "run '2D:DiFelise': no bracket brackets/DiFelise; the brackets: DiFelice" <<<"$out" \
    || fail "an unknown bracket: $out"
[ -d "$workDir/bad/slab" ] && fail "a case set up before the unknown bracket was refused"

ref=${VANWACHEM_REFERENCE:-$testsDir/../../shared/reference/vanWachem2001}
if [ -d "$ref" ]; then
    echo "reference: $ref"
    export REFERENCE=$ref
else
    echo "reference: no $ref: the comparison runs without the experiment's column"
fi
RUN="$workDir/run" SETTLE_TIME=0.05 TRANSIENT=0.02 "$bench/Allrun" 0.12 slab 2D 2D:DiFelice \
    > "$workDir/log.Allrun" 2>&1 || { cat "$workDir/log.Allrun"; fail "Allrun"; }
cat "$workDir/log.Allrun"
cd "$workDir/run" || fail "no run directory"

check()   # <case> <count> <voidage line> <drag model>
{
    grep -q "packing $2 particles" $1/log.dpmPackBed || fail "$1: not $2 particles"
    grep -q "$3" $1/log.dpmFoam2D || fail "$1: not '$3'"
    grep -q "Selecting drag model $4" $1/log.dpmFoam2D || fail "$1: not drag $4"
    grep -q "U0 0.9 m/s at patch inlet (set by U0 0.9 m/s)" $1/log.dpmFoam2D || fail "$1: U0"
    rows=$(grep -vc '^#' $1/postProcessing/pressureProbe/0/p_rgh)
    [ "$rows" -eq 1200 ] || fail "$1: $rows probe rows, 1200 expected (0.12 s every 1e-4 s)"
}
check slab 17562 "voidage model slab3D" ErgunWenYu
check 2D 3392 "voidage model discs2D" ErgunWenYu
grep -q "Kept the bed of 3392 particles" 2D.DiFelice/log.dpmPackBed \
    && cmp -s 2D/constant/packedBed.state 2D.DiFelice/constant/packedBed.state \
    || fail "2D.DiFelice did not start from 2D's settled bed"
grep -q "Selecting drag model DiFelice" 2D.DiFelice/log.dpmFoam2D || fail "2D.DiFelice: not DiFelice"
[ -s figures/timeSeries.png ] && [ -s figures/spectra.png ] || fail "no figures"
[ -d "$ref" ] || grep -q "note: no reference folder" "$workDir/log.Allrun" || fail "no note of the missing reference"

REFERENCE_PRESENT=$([ -d "$ref" ] && echo 1 || echo 0) py - <<'PY' || fail "the comparison's table"
import os, sys
rows = [[c.strip() for c in l.strip().strip("|").split("|")] for l in open("table.md") if l.startswith("|")]
ok = rows[0][3:9:2] == ["slab", "2D", "2D.DiFelice"]
for r in rows[2:]:
    # every figure of the three runs is a number; the experiment's where it has one
    values = r[3:9:2] + ([r[2]] if os.environ["REFERENCE_PRESENT"] == "1" and not r[0].startswith("highest") else [])
    try:
        [float(v) for v in values]
    except ValueError:
        ok = False
        print("not a number in row '%s': %s" % (r[0], values))
print("%d rows of figures, runs %s" % (len(rows) - 2, rows[0][3:9:2]))
sys.exit(0 if ok and len(rows) == 13 else 1)
PY
pass "both van Wachem tutorials and a bracket run and compare.py tabulates them"
