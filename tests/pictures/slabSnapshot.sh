#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmSnapshot of a slab (3D spheres, particle files with real z) shows the
# bed as a camera sees it through the front wall z = 0: a sphere nearer the
# front hides the one behind it. The synthetic bed of makeCase.py (2250
# small discs of 1.5 mm, 1000 large of 2.5 mm, none overlapping) with the
# first 1000 small spheres moved onto the large ones' centres, in front
# (z = 1 mm) of them (z = 4 mm). Expected pixels small/large:
#   front view  2250 x 1.5^2 / (1000 x (2.5^2 - 1.5^2)) = 1.266
#   (drawn the other way round: 1250 x 1.5^2 / (1000 x 2.5^2) = 0.45)
# within 3 % (the 2D snapshot test's tolerance for pixel edges).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/pictures/pictureFunctions"

makeParticleCase "$workDir/bed" 1.5
/usr/bin/python3 - "$workDir/bed/particles/1.5.h5" <<'PY' || fail "the slab's particle file"
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r+") as f:
    pos = f["position"][()]
    cls = f["class"][()].reshape(-1)
    small, large = np.flatnonzero(cls == 0), np.flatnonzero(cls == 1)
    pos[:, 2] = 2.5e-3
    pos[large, 2] = 4e-3
    pos[small[:len(large)], :2] = pos[large, :2]
    pos[small[:len(large)], 2] = 1e-3
    f["position"][...] = pos
PY
dpmSnapshot "$workDir/bed" -time 1.5 -o "$workDir/slab.png" >log.dpmSnapshot 2>&1 \
    || { cat log.dpmSnapshot; fail "dpmSnapshot failed"; }
/usr/bin/python3 - "$workDir/slab.png" <<'PY' || fail "front view of the slab"
import os, sys
import numpy as np
import matplotlib.image as mpimg
from dpmfoam2d.pictures.tools import CLASS_COLOURS
img = mpimg.imread(sys.argv[1])[:, :, :3]
n = {c: int(np.all(np.abs(img - np.array(col)) <= 2.0 / 255, axis=2).sum())
     for c, col in CLASS_COLOURS.items()}
expected = 2250 * 1.5**2 / (1000 * (2.5**2 - 1.5**2))
ratio = n[0] / max(n[1], 1)
print(f"pixels small {n[0]}, large {n[1]}: ratio {ratio:.3f}, front view {expected:.3f}")
sys.exit(0 if abs(ratio / expected - 1) <= 0.03 else 1)
PY
pass "the slab's spheres are drawn as seen through the front wall"
