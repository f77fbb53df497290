#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# A bed shared by two cases through initialBed/file:
#   - dpmPackBed saves it (reporting the settling every 0.1 s); run again for the same particles it keeps it
#     (nothing packed, the file unchanged);
#   - a second case with the same particles starts from it;
#   - dpmPackBed -overwrite in a case of another mix replaces it and says
#     so; that case then runs on the new bed, and the first case, whose
#     particles now differ from the bed, is refused.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

bed="$workDir/bed.state"
for c in a b
do
    makeCase "$workDir/$c"
    setEntry "$workDir/$c/constant/particleProperties" initialBed.file "\"$bed\""
done

cd "$workDir/a" || fail "no case a"
dpmPackBed >log.dpmPackBed 2>&1 || { tail -20 log.dpmPackBed; fail "dpmPackBed"; }
grep -q "^Saved the bed of 730 particles to \"$bed\"" log.dpmPackBed || fail "no bed saved"
grep -q "^Particles: settling, 0.1 s of 0.3, kinetic energy per particle " log.dpmPackBed \
    || fail "dpmPackBed does not report the settling's progress every 0.1 s"
cp "$bed" "$workDir/bed.first"

dpmPackBed >log.dpmPackBed.again 2>&1 || { tail -20 log.dpmPackBed.again; fail "dpmPackBed again"; }
grep -q "was made for these particles and settings already: kept as it is" log.dpmPackBed.again \
    || fail "the second dpmPackBed does not say it kept the bed"
grep -q "Particles: packing" log.dpmPackBed.again && fail "the second dpmPackBed packed"
cmp -s "$bed" "$workDir/bed.first" || fail "the second dpmPackBed changed the bed"

cd "$workDir/b" || fail "no case b"
runSolver
grep -q "^Particles: 730 read from \"$bed\" (a bed made for these particles)" log.dpmFoam2D \
    || fail "case b did not start from the shared bed"

# Another mix in b: -overwrite replaces the bed and says what it held
setEntry constant/particleProperties classes.small.count 500
rm -rf 0 0.01 0.02 particles && cp -r 0.orig 0
dpmPackBed -overwrite >log.dpmPackBed 2>&1 || { tail -20 log.dpmPackBed; fail "dpmPackBed -overwrite"; }
grep -q "^Overwriting \"$bed\" (-overwrite): bed '$bed' was made for other particles: class 'small' count = 600 in the file, 500 here" \
    log.dpmPackBed || fail "dpmPackBed -overwrite does not say what it replaced"
grep -q "^Saved the bed of 630 particles" log.dpmPackBed || fail "no new bed saved"
cmp -s "$bed" "$workDir/bed.first" && fail "the bed was not replaced"
runSolver
grep -q "^Particles: 630 read from \"$bed\"" log.dpmFoam2D || fail "case b did not start from the new bed"

# Case a asks for the old mix: refused, the difference named
cd "$workDir/a" || fail "no case a"
dpmFoam2D >log.dpmFoam2D 2>&1 && fail "case a ran on a bed of another mix"
grep -q "was made for other particles: class 'small' count = 500 in the file, 600 here" log.dpmFoam2D \
    || { tail -15 log.dpmFoam2D; fail "case a is refused without the difference named"; }

pass "a shared bed is kept, reused, replaced with -overwrite only, and refused for another mix"
