#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# initialBed/settleFriction in the solver's cases (restitution 0.5: the beds
# come to rest in the 0.3 s of settling):
#   - dpmPackBed settles with it and says so (and says nothing without it);
#   - settled with 0, the bed is the same whatever the contacts' own friction
#     (0.5 or the template's 0.15 and 0.1: the particle files' positions the
#     same bits), and lower than the bed settled with its own 0.5 (the
#     frictionless discs pack denser);
#   - the solver starts from it as a bed made for its particles.
# The physics and the record: the DEM's tests (src/dem/tests/TestSettleFriction*.cpp).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

for c in own frictionless frictionlessOwn015
do
    makeCase "$workDir/$c"
    cd "$workDir/$c" || fail "no case $c"
    setEntry constant/particleProperties initialBed.file '"$FOAM_CASE/bed.state"'
    setEntry system/controlDict endTime 0.01
    setEntry constant/particleProperties contact.restitution 0.5
    setEntry constant/particleProperties contact.restitutionWall 0.5
    if [ "$c" != frictionlessOwn015 ]
    then
        setEntry constant/particleProperties contact.frictionParticle 0.5
        setEntry constant/particleProperties contact.frictionWall 0.5
    fi
    [ "$c" = own ] || setEntry constant/particleProperties initialBed.settleFriction 0
    dpmPackBed >log.dpmPackBed 2>&1 || { tail -20 log.dpmPackBed; fail "dpmPackBed in $c"; }
done

cd "$workDir/frictionless" || fail "cd"
grep -q "^Particles: packing .*, then 0.3 s of settling with sliding friction 0 on every contact (their own after)$" \
    log.dpmPackBed || { grep "Particles: packing" log.dpmPackBed; fail "dpmPackBed does not say the settle friction"; }
grep -q "sliding friction" "$workDir/own/log.dpmPackBed" \
    && fail "dpmPackBed names a settle friction where none is set"

# The beds' particle files: the same positions settled without friction,
# and their mean centre height lower than settled with friction 0.5
heights=$(py - "$workDir" <<'PY'
import sys, h5py, numpy
position = {}
for c in ("own", "frictionless", "frictionlessOwn015"):
    with h5py.File(f"{sys.argv[1]}/{c}/particles/0.h5", "r") as f:
        position[c] = f["position"][...]
same = numpy.array_equal(position["frictionless"], position["frictionlessOwn015"])
print(position["own"][:, 1].mean(), position["frictionless"][:, 1].mean(), int(same))
PY
) || fail "reading the beds' particle files"
set -- $heights
[ "$3" = 1 ] || fail "settled without friction, the beds of own friction 0.5 and 0.15 differ"
echo "mean centre height: $1 m settled with friction 0.5, $2 m settled without"
py -c "import sys; sys.exit(0 if float(sys.argv[2]) < 0.99*float(sys.argv[1]) else 1)" "$1" "$2" \
    || fail "the bed settled without friction is not 1 % lower ($2 m against $1 m)"

runSolver
grep -q "^Particles: 730 read from \".*/frictionless/bed.state\" (a bed made for these particles)" log.dpmFoam2D \
    || fail "the solver did not start from the bed settled without friction"

pass "settleFriction 0: said in the log, the same bed whatever the own friction, lower than with friction, the solver starts from it"
