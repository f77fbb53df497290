#!/bin/bash
# Bad input stops dpmFoam2D with a message that names the file (or the
# setting) and the allowed range; never a crash, never a silent run.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/template"
nFailed=0

# expectError <name> <regex the log must hold> <shell commands that break the case>
expectError()
{
    local name="$1" pattern="$2" breakIt="$3"
    rm -rf "$workDir/$name" && cp -r "$workDir/template" "$workDir/$name"
    (
        cd "$workDir/$name" || exit 1
        eval "$breakIt"
        timeout 120 dpmFoam2D >log.dpmFoam2D 2>&1
        status=$?
        if [ "$status" = 0 ]; then echo "FAIL $name: dpmFoam2D ran"; exit 1; fi
        if [ "$status" -gt 128 ]; then echo "FAIL $name: dpmFoam2D crashed ($status)"; exit 1; fi
        grep -qE "$pattern" log.dpmFoam2D \
            || { echo "FAIL $name: no message matching '$pattern'"; tail -15 log.dpmFoam2D; exit 1; }
        echo "ok   $name: $(grep -m1 -E "$pattern" log.dpmFoam2D | sed 's/^ *//')"
    ) || nFailed=$((nFailed + 1))
}

expectError unknownDrag "Unknown dragModel type Stokes" \
    'setEntry constant/particleProperties dragModel Stokes'
expectError pressureNotPositive "Entry 'operatingPressure' = -1 in .*gasProperties\"? is outside the allowed range \(0, inf\)" \
    'setEntry constant/gasProperties operatingPressure -1'
expectError U0byUmfNotPositive "Entry 'U0byUmf' = 0 in .*gasProperties\"? is outside the allowed range \(0, inf\)" \
    'setEntry constant/gasProperties U0byUmf 0'
expectError particleOutsideMesh "particle of class 'small' at \(0.2, 0.1\) m is outside the box" \
    'echo "0 0.2 0.1" >positions.txt; setEntry constant/particleProperties initialBed "{ positions \"\$FOAM_CASE/positions.txt\"; }"'
expectError meshNotOneCellThick "is not a 2D mesh one cell thick in z" \
    'sed -i "s/(\$nx \$ny 1)/(\$nx \$ny 2)/" system/blockMeshDict && blockMesh >log.blockMesh 2>&1'
expectError meshNotUniform "is not a uniform Cartesian grid" \
    'sed -i "s/simpleGrading (1 1 1)/simpleGrading (2 1 1)/" system/blockMeshDict && blockMesh >log.blockMesh 2>&1'
expectError demStepNotDividing "DEM step 'deltaT' = 3e-05 in .*particleProperties does not divide the CFD step" \
    'setEntry constant/particleProperties deltaT 3e-5'
expectError demStepAboveBound "dt = 0.0001 s is outside \(0, 9.38495e-05\]: the time-step bound .* of the smallest particle" \
    'setEntry constant/particleProperties deltaT 1e-4'
expectError restitutionRange "restitution = 1.3 is outside \(0, 1\]" \
    'setEntry constant/particleProperties contact.restitution 1.3'
expectError diameterNotPositive "diameter = -0.0015 is outside \(0, inf\)" \
    'setEntry constant/particleProperties classes.small.diameter -1.5e-3'
expectError emptyClass "count' >= 1|empty size class" \
    'setEntry constant/particleProperties classes.large.count 0'
expectError diameterAboveCell "larger than the gas cell" \
    'setEntry constant/particleProperties classes.large.diameter 0.01'
expectError missingGasProperties "cannot find file .*constant/gasProperties" \
    'rm constant/gasProperties'
expectError missingParticleProperties "cannot find file .*constant/particleProperties" \
    'rm constant/particleProperties'
expectError unknownInletPatch "inletPatch 'distributor' in .*gasProperties is not a patch of the mesh" \
    'setEntry constant/gasProperties inletPatch distributor'
expectError neighbourSkinRange "Entry 'neighbourSkin' = 0.01 in .*particleProperties\"? is outside the allowed range \(0, 0.0015\]" \
    'setEntry constant/particleProperties neighbourSkin 0.01'
expectError sortIntervalRange "Entry 'sortInterval' = -5 in .*particleProperties\"? is outside the allowed range \[0, inf\)" \
    'setEntry constant/particleProperties sortInterval -5'

[ "$nFailed" = 0 ] || fail "$nFailed bad inputs were not reported as they should be"
pass "every bad input gives its message"
