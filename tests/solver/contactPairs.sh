#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The coefficients of pairs of classes and of classes on the walls
# (contact/pairs, contact/walls) in the solver: pairs and walls given the
# global values are the global coefficients (from one packed bed, the same
# gas and particle state to the bit as a run without them, 0.01 s); with
# values of their own the log prints every pair's and wall's coefficients
# once, the given ones marked, those not given the global entries; such a
# run continues from its state. The physics of the coefficients: the DEM's
# tests (src/dem/tests/TestContactPairs*.cpp).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/template"
setEntry "$workDir/template/system/controlDict" endTime 0.01
setEntry "$workDir/template/constant/particleProperties" initialBed.file '"$FOAM_CASE/../bed.state"'
(cd "$workDir/template" && dpmPackBed >log.dpmPackBed 2>&1) \
    || { tail -20 "$workDir/template/log.dpmPackBed"; fail "dpmPackBed"; }

cp -r "$workDir/template" "$workDir/global" && cd "$workDir/global" || fail "cd"
runSolver

cp -r "$workDir/template" "$workDir/same" && cd "$workDir/same" || fail "cd"
setEntry constant/particleProperties contact.pairs \
    "{ small-large { restitution 0.97; frictionParticle 0.15; rollingFriction 0; } large-large { restitution 0.97; } }"
setEntry constant/particleProperties contact.walls "{ small { restitutionWall 0.97; frictionWall 0.1; rollingFrictionWall 0; } }"
runSolver
for f in 0.01/uniform/dem.state 0.01/U 0.01/p_rgh
do
    cmp -s "$f" "$workDir/global/$f" || fail "$f differs from the run without pairs and walls"
done
echo "pairs and walls of the global values: dem.state, U and p_rgh at 0.01 s the same bytes"

cp -r "$workDir/template" "$workDir/own" && cd "$workDir/own" || fail "cd"
setEntry constant/particleProperties contact.pairs \
    "{ large-small { restitution 0.9; frictionParticle 0.2; rollingFriction 0.01; } }"
setEntry constant/particleProperties contact.walls "{ large { restitutionWall 0.8; frictionWall 0.3; } }"
rm -f ../bed.own.state
setEntry constant/particleProperties initialBed.file '"$FOAM_CASE/../bed.own.state"'
runSolver
expected="    contact small-small: restitution 0.97, frictionParticle 0.15, rollingFriction 0
    contact small-large: restitution 0.9, frictionParticle 0.2, rollingFriction 0.01 (contact/pairs)
    contact large-large: restitution 0.97, frictionParticle 0.15, rollingFriction 0
    contact small on the walls: restitutionWall 0.97, frictionWall 0.1, rollingFrictionWall 0
    contact large on the walls: restitutionWall 0.8, frictionWall 0.3, rollingFrictionWall 0 (contact/walls)"
got=$(grep "^    contact " log.dpmFoam2D)
[ "$got" = "$expected" ] || fail "the log's coefficients:
$got
expected:
$expected"
echo "the log prints each pair's and wall's coefficients once"
setEntry system/controlDict endTime 0.02
runSolver
[ -f 0.02/uniform/dem.state ] || fail "the run with pairs and walls did not continue to 0.02 s"
pass "pairs and walls of the global values change no bit; own ones are printed and restart"
