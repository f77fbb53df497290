#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The case of the coupling's unit tests (a ctest fixture's set-up): the
# smoke test's case and its mesh in <workDir>/case.
#   mesh.sh <workDir> paper   the paper's 20 x 120 x 1 mesh (0.15 m x 0.9 m,
#                             2.5 mm thick): Test-dpmCoupling,
#                             Test-sphereColumnOverlap
#   mesh.sh <workDir> netl    NETL's column, 38.1 mm square and 228.6 mm
#                             tall, 4 x 24 x 4 cells with walls in front and
#                             behind: Test-gasInDepth
#   mesh.sh <workDir> unstructured
#                             the case of Test-unstructuredGrid, its four
#                             meshes as regions: box, cylinder, thin, warped
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
mesh="${2:?usage: $0 <workDir> paper|netl|unstructured}"

if [ "$mesh" = unstructured ]
then
    cp -r "$testsDir/dpmCoupling/unstructuredGridCase" "$workDir/case" \
        || fail "copy"
    cd "$workDir/case" || fail "cd"
    # The smoke case's schemes and solution for the case and each region
    for dir in system system/box system/cylinder system/thin system/warped
    do
        cp "$testsDir"/smoke/blockMeshCase/system/{fvSchemes,fvSolution} \
            "$dir" || fail "copy the schemes into $dir"
    done
    for region in box cylinder thin warped
    do
        blockMesh -region $region >log.blockMesh.$region 2>&1 \
            || fail "blockMesh $region"
    done
    pass "$mesh meshes in $workDir/case"
    exit 0
fi

cp -r "$testsDir/smoke/blockMeshCase" "$workDir/case" || fail "copy"
cd "$workDir/case" || fail "cd"
case "$mesh" in
paper) ;;
netl)
    sed -i -e 's/^depth .*/depth   0.0381;/' -e 's/0\.15 /0.0381 /g' \
        -e 's/0\.9 /0.2286 /g' -e 's/(20 120 1)/(4 24 4)/' \
        -e 's/type empty/type wall/' system/blockMeshDict || fail "3D mesh"
    ;;
*) fail "unknown mesh $mesh (paper, netl or unstructured)" ;;
esac
blockMesh >log.blockMesh 2>&1 || fail "blockMesh"
pass "$mesh mesh in $workDir/case"
