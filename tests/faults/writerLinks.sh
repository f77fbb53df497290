#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The project's writers write only inside their case: a folder they write
# into that is a symbolic link resolving outside the case is refused, the
# link and where it leads named, and nothing lands there; a link that stays
# inside the case is followed (docs/user-guide/output.md, "Links").
#   1. particles/ linked outside, or to nothing: dpmFoam2D refuses;
#   2. particles/ linked to a folder of the case: the run writes there;
#   3. a link planted at a particle file's temporary name (<t>.h5.partial)
#      to a file outside: the file is left as it was;
#   4. postProcessing/intrudersRisen linked outside: the function object
#      refuses;
#   5. postProcessing/ linked outside: dpmRiseTime refuses.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

outside="$workDir/outside"
mkdir -p "$outside"
echo "not to be written" > "$outside/target"
untouched()
{
    [ "$(cat "$outside/target")" = "not to be written" ] || fail "$1: the file outside was written"
    [ "$(ls "$outside" | wc -l)" = 1 ] || fail "$1: files landed outside: $(ls "$outside")"
}
refused()   # <log> <what>: the run stopped naming the link's target
{
    grep -q "resolves to $(realpath "$outside")[^ ]*, outside the case" "$1" \
        || { tail -20 "$1"; fail "$2: no refusal naming where the link leads"; }
}

makeCase "$workDir/template"
(
    cd "$workDir/template" || exit 1
    setEntry system/controlDict endTime 0.02
    setEntry system/controlDict writeInterval 0.01
    setEntry constant/particleProperties writeInterval 0.01
) || fail "template"

echo "1. particles/ linked outside the case"
cp -r "$workDir/template" "$workDir/c1" && cd "$workDir/c1" || fail "copy"
ln -s "$outside" particles
dpmFoam2D > log.dpmFoam2D 2>&1 && fail "dpmFoam2D wrote its particles through a link outside the case"
refused log.dpmFoam2D "particles/ linked outside"
untouched "particles/ linked outside"
echo "ok   refused: $(grep -o "particles resolves to .*, outside the case" log.dpmFoam2D | head -1)"

echo "1b. particles/ a link to nothing outside the case"
cp -r "$workDir/template" "$workDir/c1b" && cd "$workDir/c1b" || fail "copy"
ln -s "$outside/new" particles
dpmFoam2D > log.dpmFoam2D 2>&1 && fail "dpmFoam2D wrote its particles through a link to nothing"
grep -q "cannot resolve .*particles" log.dpmFoam2D && ! grep -q "Traceback\|sigSegv" log.dpmFoam2D \
    || { tail -20 log.dpmFoam2D; fail "a link to nothing: no refusal naming it"; }
untouched "particles/ a link to nothing"
echo "ok   refused"

echo "2. particles/ linked to a folder of the case"
cp -r "$workDir/template" "$workDir/c2" && cd "$workDir/c2" || fail "copy"
mkdir store && ln -s store particles
runSolver
[ -f store/0.02.h5 ] || fail "the particle files did not land in the case's own folder"
echo "ok   written through the link into store/"

echo "3. a link at a particle file's temporary name"
cp -r "$workDir/template" "$workDir/c3" && cd "$workDir/c3" || fail "copy"
mkdir particles && ln -s "$outside/target" particles/0.01.h5.partial
runSolver
untouched "a link at 0.01.h5.partial"
[ -f particles/0.01.h5 ] && [ ! -L particles/0.01.h5 ] || fail "0.01.h5 not written as a file of its own"
echo "ok   the link replaced by the file, the target untouched"

echo "4. postProcessing/intrudersRisen linked outside the case"
cp -r "$workDir/template" "$workDir/c4" && cd "$workDir/c4" || fail "copy"
cat >>system/controlDict <<'EOF2'
functions
{
    intrudersRisen
    {
        #includeEtc "caseDicts/postProcessing/segregation/intrudersRisen"
        class       large;
        endRun      false;
    }
}
EOF2
mkdir postProcessing && ln -s "$outside" postProcessing/intrudersRisen
dpmFoam2D > log.dpmFoam2D 2>&1 && fail "intrudersRisen wrote through a link outside the case"
refused log.dpmFoam2D "postProcessing/intrudersRisen linked outside"
untouched "postProcessing/intrudersRisen linked outside"
echo "ok   refused"

echo "5. dpmRiseTime with postProcessing/ linked outside the case"
cd "$workDir/c2" || fail "cd"
rm -rf postProcessing && ln -s "$outside" postProcessing
dpmRiseTime . -class large > log.riseTime 2>&1 && fail "dpmRiseTime wrote through a link outside the case"
refused log.riseTime "dpmRiseTime, postProcessing/ linked outside"
untouched "dpmRiseTime, postProcessing/ linked outside"
grep -q Traceback log.riseTime && fail "dpmRiseTime: a traceback"
echo "ok   refused"

pass "the writers keep to their case: links outside refused, links inside followed"
