#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The laceyIndex function object writes what the Lacey index and the
# segregation indices of the particles are, in a run and after the fact.
#
# A short run of the test column (730 particles settled 0.3 s, then 0.02 s
# of gas) with two instances, every 0.01 s:
#   laceyIndex   `#includeFunc laceyIndex` (whole bed, 5 mm cells, wholeBed N)
#   laceyRegion  a box (0.01 0.005)-(0.05 0.03) m cut by 7.5 mm cells
#                (partial cells), perSample N
# Expected:
#   1. the rows equal an independent Python computation (laceyCheck.py) from
#      particles/<time>.h5 at 0, 0.01 and 0.02 s; the files hold float32
#      positions, hence relative 1e-5 (indices 1e-5 absolute; see the script);
#   2. `dpmFoam2D -postProcess` rebuilds the cloud from each time's exact
#      restart state (uniform/dem.state, doubles) and must reproduce the run's
#      rows to 1e-12 relative (written with 12 digits);
#   3. `dpmFoam2D -postProcess -func laceyIndex` (the etc/caseDicts entry found
#      by name) reproduces them too.
# In the slab mode (slab3D <depth>: 3D spheres in a slab, the mesh that
# thick) the sampling cells are columns through the depth, so the same
# x-y computation holds, and -postProcess rebuilds the slab's cloud.
#   laceyIndex.sh <workDir> [slab3D <depth>]
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

# #includeFunc and -func find etc/caseDicts/postProcessing of the project
# through OpenFOAM's site directory, $WM_PROJECT_SITE/etc.
export WM_PROJECT_SITE="${WM_PROJECT_SITE:-$DPMFOAM2D_PROJECT}"

makeCase "$workDir/case"
cd "$workDir/case" || fail "cd"
setSlab "${2:-}" "${3:-}"

# Set entries first: foamDictionary -set would expand #includeFunc.
setEntry system/controlDict endTime 0.02
setEntry system/controlDict writePrecision 12     # the .dat files' too
cat >>system/controlDict <<'EOF2'
functions
{
    #includeFunc laceyIndex

    laceyRegion
    {
        #include "$DPMFOAM2D_PROJECT/etc/caseDicts/postProcessing/mixing/laceyIndex"
        cellSize        7.5e-3;
        box             (0.01 0.005 0) (0.05 0.03 0);
        varianceBasis   perSample;
    }
}
EOF2
runSolver

check() { py "$testsDir/functionObjects/laceyCheck.py" "$@"; }
run=postProcessing
for name in laceyIndex laceyRegion
do
    [ -f "$run/$name/0/laceyIndex.dat" ] && [ -f "$run/$name/0/segregation.dat" ] \
        || fail "no $run/$name/0/{laceyIndex,segregation}.dat"
    times=$(grep -v '^#' "$run/$name/0/laceyIndex.dat" | awk '{printf "%s ", $1}')
    [ "$times" = "0 0.01 0.02 " ] || fail "$name rows at times '$times', expected 0 0.01 0.02"
done
grep -q "^# varianceBasis *: wholeBed" $run/laceyIndex/0/laceyIndex.dat \
    || fail "laceyIndex.dat does not name the wholeBed basis"
grep -q "^# varianceBasis *: perSample" $run/laceyRegion/0/laceyIndex.dat \
    || fail "laceyRegion's laceyIndex.dat does not name the perSample basis"
grep -q "(d_large/d_small)^3: 4.6296296" $run/laceyIndex/0/laceyIndex.dat \
    || fail "laceyIndex.dat does not give the weight (2.5/1.5)^3"
grep -q "^laceyIndex laceyIndex: t = 0.01, M = " log.dpmFoam2D \
    || fail "no summary line in log.dpmFoam2D"

echo "1. run against the particle files"
check particles $run/laceyIndex/0 5e-3 wholeBed 0 0 0.06 0.3 \
    || fail "laceyIndex differs from the particle files"
check particles $run/laceyRegion/0 7.5e-3 perSample 0.01 0.005 0.05 0.03 \
    || fail "laceyRegion differs from the particle files"

# After the fact: the output of each post-processing goes to its own place
mv postProcessing run

echo "2. dpmFoam2D -postProcess (controlDict functions)"
dpmFoam2D -postProcess >log.postProcess 2>&1 || fail "dpmFoam2D -postProcess"
grep -qi "warning\|error" log.postProcess && { grep -i -A5 "warning\|error" log.postProcess; fail "messages in log.postProcess"; }
for name in laceyIndex laceyRegion
do
    check same run/$name/0 postProcessing/$name/0.02 1e-12 \
        || fail "-postProcess differs from the run for $name"
done
mv postProcessing postAll

echo "3. dpmFoam2D -postProcess -func laceyIndex"
dpmFoam2D -postProcess -func laceyIndex >log.postProcessFunc 2>&1 \
    || fail "dpmFoam2D -postProcess -func laceyIndex"
check same run/laceyIndex/0 postProcessing/laceyIndex/0.02 1e-12 \
    || fail "-postProcess -func laceyIndex differs from the run"

pass "laceyIndex output equals the independent computation, in a run and after it"
