#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Checks of the gas grid of any 3D mesh (gasGrid unstructured) on three
# meshes blockMesh makes as regions of one case: box (a uniform 6 x 6 x 6
# grid, against cartesianGrid's exact answers), cylinder (an O-grid 100 mm
# across), thin (one cell thick, refused) and warped (the box with its inner
# points moved at random: warped faces). Each check states its source
# and tolerance (Test-unstructuredGrid.C).
#   unstructuredGrid.sh <workDir>
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
app=Test-unstructuredGrid

cp -r "$testsDir/dpmCoupling/unstructuredGridCase" "$workDir/case" || fail "copy"
cd "$workDir/case" || fail "cd"
for region in box cylinder thin warped
do
    blockMesh -region $region >log.blockMesh.$region 2>&1 || fail "blockMesh $region"
done
"$DPMFOAM2D_BUILD/tests/bin/$app" 2>&1 | tee "log.$app"
[ "${PIPESTATUS[0]}" = 0 ] || fail "$app checks"
grep -Eq '^[0-9]+ passed, 0 failed$' "log.$app" || fail "$app checks"
pass "$app checks"
