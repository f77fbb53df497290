#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The cases of benchmarks/netlSegregationValidation (caseFunctions) against
# the experiment of LaMarche et al. (2022): each condition's U0, glass count
# (its bed mass over one bead's, 2522 kg/m3 and 3.101 mm), intruders, their
# diameter (large 9.43 mm, small 3.155 mm), placement (one at the centre
# of the floor, as the experiment placed it; more at random) and seed, the
# held-out five too;
# a variant's entries and its shift ('add': U0plus0.10 gives 1.93 and
# 2.234 m/s); variants joined by '+'; a variant's file outside the case
# refused by makeCase itself, naming the line, and no half-made case left;
# sweepUmf's case records the inlet's pressure every 1 ms in place of the
# early end. Cases only: no solver runs.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
here=$testsDir/../benchmarks/netlSegregationValidation
cd "$workDir" || fail "work directory"
. "$here/caseFunctions" || fail "caseFunctions"

value() { foamDictionary -entry "$2" -value "$1/$3" 2>/dev/null; }
same() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a - b < 1e-9 && b - a < 1e-9) }'; }

# The glass count: the bed's mass over one bead's
beads() { awk -v m="$1" 'BEGIN { printf "%d", m / (2522 * 3.14159265358979 / 6 * 3.101e-3^3) + 0.5 }'; }
for row in "U214_M177_4L 2.134 177.46e-3 4 9.43e-3" "U183_M177_1L 1.83 177.46e-3 1 9.43e-3" \
           "U183_M227_1L 1.83 227.47e-3 1 9.43e-3" "U183_M177_4L 1.83 177.46e-3 4 9.43e-3" \
           "U183_M227_4L 1.83 227.47e-3 4 9.43e-3" "U199_M177_2L 1.99 177.46e-3 2 9.43e-3" \
           "U214_M177_2L 2.134 177.46e-3 2 9.43e-3" "U214_M177_2S 2.134 177.46e-3 2 3.155e-3"
do
    read -r c U0 mass intruders diameter <<<"$row"
    variant=""
    makeCase "$c" 3 "$c" || fail "$c: case not made"
    same "$(value $c U0 constant/gasProperties)" "$U0" || fail "$c: U0 $(value $c U0 constant/gasProperties), not $U0"
    [ "$(value $c classes.glass.count constant/particleProperties)" = "$(beads "$mass")" ] \
        || fail "$c: glass count not $(beads "$mass")"
    # one at the centre of the column's 38.1-mm floor, a radius up; more at random
    [ "$(value $c classes.intruder.count constant/particleProperties)" = "$intruders" ] \
        || fail "$c: not $intruders intruders"
    if [ "$intruders" = 1 ]
    then
        placed=$(value $c initialBed.place.intruder.positions constant/particleProperties | tr -d '()')
        read -r x y z <<<"$placed"
        same "$x" 0.01905 && same "$y" 0.004715 && same "$z" 0.01905 \
            || fail "$c: the intruder at ($placed), not the floor's centre (0.01905 0.004715 0.01905)"
    else
        [ "$(value $c initialBed.place.intruder.random constant/particleProperties)" = "$intruders" ] \
            || fail "$c: not $intruders intruders placed at random"
    fi
    same "$(value $c classes.intruder.diameter constant/particleProperties)" "$diameter" \
        || fail "$c: intruders of $(value $c classes.intruder.diameter constant/particleProperties) m, not $diameter"
    [ "$(value $c initialBed.seed constant/particleProperties)" = 3 ] || fail "$c: seed"
    grep -q "nCells: 384$" "$c/log.blockMesh" || fail "$c: mesh not 4 x 24 x 4"
    pass "$c: U0 $U0 m/s, $(beads "$mass") glass beads, $intruders intruders of $diameter m, seed 3"
done

variant=U0plus0.10
makeCase U183_M177_1L 1 plus183 && makeCase U214_M177_4L 1 plus214 || fail "U0plus0.10 cases"
same "$(value plus183 U0 constant/gasProperties)" 1.93 && same "$(value plus214 U0 constant/gasProperties)" 2.234 \
    || fail "U0plus0.10: U0 $(value plus183 U0 constant/gasProperties), $(value plus214 U0 constant/gasProperties)"
variant=formulationA
makeCase U214_M177_4L 1 formA && [ "$(value formA formulation constant/particleProperties)" = A ] \
    || fail "formulationA: formulation not A"
variant=slab
makeCase U214_M177_4L 1 slab && [ "$(value slab voidageModel constant/particleProperties)" = slab3D ] \
    && [ "$(value slab nz system/bedGeometry)" = 1 ] || fail "slab: not one cell deep with slab3D"
grep -q "nCells: 96$" slab/log.blockMesh || fail "slab: mesh not 4 x 24 x 1 ($(grep nCells slab/log.blockMesh))"
pass "variants: U0 shifted to 1.93 and 2.234 m/s, formulation A, the slab one cell deep"

variant=Beetstra+packedFrictionless
makeCase U183_M177_1L 1 joined && [ "$(value joined dragModel constant/particleProperties)" = Beetstra ] \
    && [ "$(value joined initialBed.settleFriction constant/particleProperties)" = 0 ] \
    || fail "Beetstra+packedFrictionless: not both applied"
missing=$(checkVariant netlCases Beetstra+noSuchBracket 2>&1) \
    && fail "a missing part of a joined variant not refused"
[[ $missing == "netlCases: no variant file $here/variants/noSuchBracket (the variants: "* ]] \
    && checkVariant netlCases Beetstra+packedFrictionless || fail "a missing part of a joined variant not named: $missing"
pass "joined variants: Beetstra's drag and the frictionless settling in one case; a missing part named"

# makeCase itself keeps a variant inside the case it makes (as Allrun's and
# sweepUmf's checks before it), and leaves no half-made case when a line
# cannot be applied: variants of a copy of the benchmark's folder, the other
# case's controlDict unchanged
mkdir -p copy/benchmarks/netl/variants other/system \
    && ln -s "$testsDir/../tutorials" copy/tutorials && ln -s "$testsDir/../python" copy/python \
    && printf 'endTime 5;\n' > other/system/controlDict || fail "a copy of the benchmark"
here=$workDir/copy/benchmarks/netl
printf 'system/controlDict writeInterval 2\n%s/other/system/controlDict endTime 77\n' "$workDir" \
    > "$here/variants/absolute"
printf 'system/../../other/system/controlDict endTime 77\n' > "$here/variants/relative"
printf 'constant/gasProperties U0 (1 2\n' > "$here/variants/unbalanced"
for variant in absolute relative unbalanced
do
    makeCase U214_M177_4L 1 "$variant" 2> "log.$variant" && fail "$variant: the case was made"
    [ -e "$variant" ] || ls -a | grep -q "^$variant\.making" && fail "$variant: a half-made case was left"
    [ "$(cat other/system/controlDict)" = "endTime 5;" ] || fail "$variant: the other case's controlDict changed"
    cat "log.$variant"
done
grep -q "^makeCase: $here/variants/absolute line 2: $workDir/other/system/controlDict is an absolute path" log.absolute \
    && grep -q "^makeCase: $here/variants/relative line 1: system/../../other/system/controlDict lies outside the case" log.relative \
    && grep -q "^makeCase: $here/variants/unbalanced line 1: foamDictionary cannot set constant/gasProperties U0 to '(1 2'" log.unbalanced \
    || fail "the refusals do not name the variant file, its line and the rule"
here=$testsDir/../benchmarks/netlSegregationValidation
pass "makeCase: a variant's file outside the case refused, naming its line; no half-made case"

variant=""
makeSweepCase U183_M227_1L 1 sweep 0.5 || fail "sweepUmf's case"
[ "$(value sweep functions.inletPressure.type system/controlDict)" = surfaceFieldValue ] \
    && [ "$(value sweep functions.inletPressure.name system/controlDict)" = inlet ] \
    && [ "$(value sweep functions.inletPressure.writeControl system/controlDict)" = timeStep ] \
    && same "$(awk -v n="$(value sweep functions.inletPressure.writeInterval system/controlDict)" \
                   -v dt="$(value sweep deltaT system/controlDict)" 'BEGIN { print n * dt }')" 1e-3 \
    || fail "sweepUmf's case: no inlet pressure record every 1 ms"
value sweep functions.intrudersRisen system/controlDict >/dev/null \
    && fail "sweepUmf's case: the early end on the rise is still there"
same "$(value sweep writeInterval system/controlDict)" 0.5 || fail "sweepUmf's case: a write per step"
pass "sweepUmf's case: p_rgh on the inlet every 1 ms, no early end, a write every step"
