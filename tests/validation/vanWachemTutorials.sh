#!/bin/bash
# tutorials/vanWachemBed (slab) and tutorials/vanWachemBed2D (discs) as a
# user runs them (Allrun), cut to 0.05 s (slab) and 0.1 s (discs) of
# settling and 0.12 s of gas, then benchmarks/vanWachemValidation/compare.py
# on both runs and on the experiment's digitized curves (../shared/reference/
# vanWachem2001 beside the repository, or VANWACHEM_REFERENCE; left out with
# compare.py's note when absent). The machinery, not the physics: the
# experiment's particles (17,562 spheres; 3392 discs, README.md of the 2D
# tutorial), U0 0.9 m/s (the experiment's), the probe every CFD step
# (1200 rows) inside the mesh, and a table with every figure of both runs.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
py() { /usr/bin/python3 "$@"; }
top=$testsDir/..
compare=$top/benchmarks/vanWachemValidation/compare.py

setEntry() { foamDictionary -entry "$2" -set "$3" "$1" >/dev/null 2>&1 || fail "cannot set $2 in $1"; }

run()   # <tutorial> <case> <settle time> <count> <voidage line>
{
    cp -r "$top/tutorials/$1" "$workDir/$2" || fail "copy $1"
    ( cd "$workDir/$2" && ./Allclean >/dev/null ) || fail "Allclean $1"
    setEntry "$workDir/$2/constant/particleProperties" initialBed.settleTime "$3"
    setEntry "$workDir/$2/system/controlDict" endTime 0.12
    setEntry "$workDir/$2/system/controlDict" writeInterval 0.06
    "$workDir/$2/Allrun" >/dev/null || fail "Allrun of $1"
    cd "$workDir/$2" || fail "$2"
    grep -q "packing $4 particles" log.dpmPackBed || fail "$1: not $4 particles"
    grep -q "$5" log.dpmFoam2D || fail "$1: not '$5'"
    grep -q "U0 0.9 m/s at patch inlet (set by U0 0.9 m/s)" log.dpmFoam2D || fail "$1: U0"
    rows=$(grep -vc '^#' postProcessing/pressureProbe/0/p_rgh)
    [ "$rows" -eq 1200 ] || fail "$1: $rows probe rows, 1200 expected (0.12 s every 1e-4 s)"
    cd "$workDir" || fail "work directory"
}
run vanWachemBed slab 0.05 17562 "voidage model slab3D"
run vanWachemBed2D discs 0.1 3392 "voidage model discs2D"

ref=${VANWACHEM_REFERENCE:-$top/../shared/reference/vanWachem2001}
args=(--run slab=slab --run 2D=discs --transient 0.02 --figures figures --table table.md)
if [ -d "$ref" ]; then
    args+=(--reference "$ref")
    echo "reference: $ref"
else
    echo "reference: no $ref: the comparison runs without the experiment's column"
fi
py "$compare" "${args[@]}" > log.compare 2>&1 || { cat log.compare; fail "compare.py"; }
cat log.compare
[ -s figures/timeSeries.png ] && [ -s figures/spectra.png ] || fail "no figures"
[ -d "$ref" ] || grep -q "note: no reference folder" log.compare || fail "no note of the missing reference"

REFERENCE_PRESENT=$([ -d "$ref" ] && echo 1 || echo 0) py - <<'PY' || fail "the comparison's table"
import os, sys
rows = [[c.strip() for c in l.strip().strip("|").split("|")] for l in open("table.md") if l.startswith("|")]
ok = True
for r in rows[2:]:
    # every figure of both runs is a number; the experiment's where it has one
    values = [r[3], r[5]] + ([r[2]] if os.environ["REFERENCE_PRESENT"] == "1" and not r[0].startswith("highest") else [])
    try:
        [float(v) for v in values]
    except ValueError:
        ok = False
        print("not a number in row '%s': %s" % (r[0], values))
print("%d rows of figures" % (len(rows) - 2))
sys.exit(0 if ok and len(rows) == 13 else 1)
PY
pass "both van Wachem tutorials run and compare.py tabulates them"
