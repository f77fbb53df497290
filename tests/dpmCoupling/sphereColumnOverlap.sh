#!/bin/bash
# The sphere-column volume of the slab mode (Test-sphereColumnOverlap, built
# by Allwmake) against the textbook limits, an independent quadrature and
# Monte Carlo; its mapping on the paper's 20 x 120 mesh.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"

cp -r "$testsDir/smoke/blockMeshCase" "$workDir/case" || fail "copy"
cd "$workDir/case" || fail "cd"
blockMesh >log.blockMesh 2>&1 || fail "blockMesh"
"$DPMFOAM2D_BUILD/tests/bin/Test-sphereColumnOverlap" 2>&1 | tee log.Test-sphereColumnOverlap
[ "${PIPESTATUS[0]}" = 0 ] || fail "sphere-column checks"
# As unit.sh: read the summary, not only the exit status
grep -Eq '^[0-9]+ passed, 0 failed$' log.Test-sphereColumnOverlap || fail "sphere-column checks"
pass "sphere-column volume checks"
