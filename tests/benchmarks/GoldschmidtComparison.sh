#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# benchmarks/GoldschmidtComparison on the tutorial's bed cut to 5 lattice
# columns and 2 layers, 0.01 s in both codes. The cut must give what the
# tutorial's lattice implies (spheres 3 mm apart, 5 across the depth: 5 x 5 x
# 2 = 50 spheres in a box 15 mm wide, weighing less buoyancy 45.03 Pa over
# its 15 x 15 mm floor: 50 pi/6 (2.5 mm)^3 (2526 - 1.2) 9.81 / 2.25e-4),
# compare.py must read that bed from the run, a cut that does not fit 5-mm
# cells must be refused, and voidageSeen.py's own quadrature of the slab's
# columns must agree with dpmFoam2D's voidage (the drag's input) in every
# cell to 1e-3 (the 0.1-mm pixels' own error is a few 1e-4).
#   GoldschmidtComparison.sh <work dir>
set -u
work=${1:?work directory}
. "$(cd "$(dirname "$0")/../.." && pwd)/etc/bashrc" || exit 1
bench=$DPMFOAM2D_PROJECT/benchmarks/GoldschmidtComparison
rm -rf "$work" && mkdir -p "$work" || exit 1
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAILED: $1"; fail=1; fi; }

# A cut that does not fit the cells: refused before anything is set up
out=$(RUN="$work/bad" LATTICE_COLUMNS=7 "$bench/Allrun" 0.01 2>&1); rc=$?
check "LATTICE_COLUMNS=7 refused, naming the entry and the allowed values" \
    '[ $rc -ne 0 ] && grep -q "LATTICE_COLUMNS=7 must be 5, 10, ... 50" <<<"$out" && [ ! -d "$work/bad/DPMFoam" ]'

out=$(RUN="$work/cut" LATTICE_COLUMNS=5 LATTICE_LAYERS=2 TRANSIENT=0 "$bench/Allrun" 0.01 2>&1)
rc=$?
echo "$out"
check "both codes ran" '[ $rc -eq 0 ]'
check "DPMFoam's lattice and box cut to 50 spheres, 15 mm" \
    'grep -q "the tutorial cut to 5 x 5 x 2 = 50 spheres, 15 mm wide" <<<"$out"'
check "dpmFoam2D's the same" 'grep -q "^dpmFoam2D: 50 spheres" <<<"$out" \
    && grep -q "count 50;" "$work/cut/dpmFoam2D/constant/particleProperties"'
check "compare.py reads 50 spheres, 15 mm, W/A 45.0 Pa" \
    'grep -q "50 spheres of 2.5 mm, 15 mm wide, W/A (weight less buoyancy per area) 45.0 Pa" <<<"$out"'

seen=$(/usr/bin/python3 "$bench/voidageSeen.py" "$work/cut" -transient 0 2>&1)
echo "$seen"
worst=$(sed -n 's/.*against the quadrature: largest difference in a cell //p' <<<"$seen")
check "dpmFoam2D's voidage field = the quadrature's in every cell to 1e-3 (${worst:-none})" \
    '[ -n "$worst" ] && awk -v d="$worst" "BEGIN { exit !(d < 1e-3) }"'
check "DPMFoam's spheres read" 'grep -q "DPMFoam   field" <<<"$seen"'

# START=settled: one bed packed and settled by dpmFoam2D, its centres given
# to both codes (DPMFoam's in the tutorial's axes: (x, y, z) = (z - 7.5 mm,
# x - 75 mm, y) of ours); a start that is neither is refused
out=$(RUN="$work/bad" START=settle "$bench/Allrun" 0.01 2>&1); rc=$?
check "START=settle refused" '[ $rc -ne 0 ] && grep -q "START=settle must be lattice or settled" <<<"$out"'
out=$(RUN="$work/settled" LATTICE_COLUMNS=5 LATTICE_LAYERS=2 START=settled \
      SOLVERS=DPMFoam "$bench/Allrun" 0.001 2>&1); rc=$?
echo "$out" | head -5
check "the settled start set up and ran" '[ $rc -eq 0 ] && grep -q "50 spheres from the settled bed" <<<"$out"'
same=$(/usr/bin/python3 - "$work/settled" <<'PY'
import re, sys
run = sys.argv[1]
ours = [[float(v) for v in l.split()[1:]] for l in open(run + '/settledPositions')
        if not l.startswith('#')]
text = open(run + '/DPMFoam/constant/kinematicCloudPositions').read()
theirs = [[float(v) for v in m] for m in
          re.findall(r'^\((\S+) (\S+) (\S+)\)$', text.split('\n(\n', 1)[1], re.M)]
ok = len(ours) == len(theirs) == 50 and all(
    abs(a[2] - 0.0075 - b[0]) < 1e-6 and abs(a[0] - 0.075 - b[1]) < 1e-6 and abs(a[1] - b[2]) < 1e-6
    for a, b in zip(ours, theirs))
print('same' if ok else 'different: %d and %d spheres' % (len(ours), len(theirs)))
PY
)
check "DPMFoam starts from the settled bed's centres ($same)" '[ "$same" = same ]'
exit $fail
