#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmSnapshot on a synthetic bed (makeCase.py): 2250 small discs (1.5 mm)
# and 1000 large (2.5 mm), none overlapping or cut. Expected pixels of the
# class colours in the ratio of the drawn areas, 2250*1.5^2/(1000*2.5^2)
# = 0.81, within 3 % (pixel edges average out over 3250 discs; measured
# 0.809). Also: the picture is 1200 px high, case.foam is created, and the
# window is the bed (not the 0.9 m column: width > height), and the voidage
# is drawn when 0/ lacks it. Then on the files the solver wrote (the test
# column, 600 small and 130 large discs, 0.02 s): the class colours in the
# ratio of the drawn areas of that file's particles within 3 % (the packed
# discs touch and overlap a little, and a disc may cross the bed's edge).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/pictures/pictureFunctions"
. "$testsDir/solver/testFunctions"

makeParticleCase "$workDir/bed" 1.5 1.6
dpmSnapshot "$workDir/bed" -time 1.5 -o "$workDir/snap.png" >log.dpmSnapshot 2>&1 \
    || { cat log.dpmSnapshot; fail "dpmSnapshot failed"; }
[ -f "$workDir/bed/case.foam" ] || fail "case.foam not created"
/usr/bin/python3 "$testsDir/pictures/countClassPixels.py" "$workDir/snap.png" \
    "$workDir/bed/particles/1.5.h5" 0.03 || fail "class colour proportions"
/usr/bin/python3 - "$workDir/snap.png" <<'PY' || fail "picture size"
import sys, matplotlib.image as m
h, w = m.imread(sys.argv[1]).shape[:2]
print("picture %d x %d px" % (w, h))
sys.exit(0 if h == 1200 and w > h else 1)
PY
# Default output name, latest time.
dpmSnapshot "$workDir/bed" >log.default 2>&1 || { cat log.default; fail "dpmSnapshot (defaults)"; }
[ -f "$workDir/bed/images/snapshot_1.6.png" ] || fail "no images/snapshot_1.6.png"

# A 0/ without voidage (a case set up by hand) must not hide the field: the
# most common grey is the colour map's for the bed's voidage 0.40,
# 0.3 + 0.7 (0.40 - 0.35)/0.65 = 0.354 (within 0.02, about 5 of 255 levels).
mkdir -p "$workDir/bed/0"
cat > "$workDir/bed/0/U" <<'FOAM'
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { ".*" { type calculated; value uniform (0 0 0); } }
FOAM
dpmSnapshot "$workDir/bed" -time 1.5 -o "$workDir/zero.png" >log.zero 2>&1 \
    || { cat log.zero; fail "dpmSnapshot (0/ without voidage)"; }
/usr/bin/python3 - "$workDir/zero.png" <<'PY' || fail "voidage hidden by a 0/ without it"
import sys, numpy as np, matplotlib.image as m
im = m.imread(sys.argv[1])[..., :3]
grey = (np.ptp(im, axis=2) < 0.02) & (im[..., 0] > 0.05) & (im[..., 0] < 0.95)
levels, counts = np.unique(np.round(im[..., 0][grey] * 255), return_counts=True)
top = levels[np.argmax(counts)] / 255
share = counts.max() / grey.size
print("most common grey %.3f (expected 0.354), %.0f %% of the picture" % (top, 100 * share))
sys.exit(0 if abs(top - 0.354) < 0.02 and share > 0.05 else 1)
PY
# The solver's own files
makeCase "$workDir/column"
(cd "$workDir/column" && runSolver) || fail "the test column"
dpmSnapshot "$workDir/column" -o "$workDir/column.png" >log.column 2>&1 \
    || { cat log.column; fail "dpmSnapshot on the solver's files"; }
/usr/bin/python3 "$testsDir/pictures/countClassPixels.py" "$workDir/column.png" \
    "$workDir/column/particles/0.02.h5" 0.03 || fail "class colour proportions (solver's files)"
pass "snapshot shows both classes in the proportion of their areas, and the voidage"
