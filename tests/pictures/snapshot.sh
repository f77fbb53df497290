#!/bin/bash
# dpmSnapshot on a synthetic bed (makeCase.py): 2250 small discs (1.5 mm)
# and 1000 large (2.5 mm), none overlapping or cut. Expected pixels of the
# class colours in the ratio of the drawn areas, 2250*1.5^2/(1000*2.5^2)
# = 0.81, within 3 % (pixel edges average out over 3250 discs; measured
# 0.809). Also: the picture is 1200 px high, case.foam is created, and the
# window is the bed (not the 0.9 m column: width > height).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/pictures/pictureFunctions"

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
pass "snapshot shows both classes in the proportion of their areas"
