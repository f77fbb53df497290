#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# A study that travels: a reduced study (w_small 0.5 at 1 bar, 5 % of
# Table 3's particles, 0.1 s of settling, 0.05 s of gas) with seeds 1 and 2
# run in one study directory is the reference. Seed 1 run in a study A and
# seed 2 in a study B, B exported (export) and imported into A (import),
# give results/ equal to the reference's (summary, ensemble and findings
# tables: the same runs, bit for bit); a third study importing A's
# directory (one run, one summary) gives them too. The imported summary is
# never run again. An archive of another studyDict, of a case with other
# settings or other dictionaries is refused naming the difference, leaving
# the study as it was; an unfinished case is left out of an export.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
export WM_PROJECT_SITE="${WM_PROJECT_SITE:-$DPMFOAM2D_PROJECT}"
cd "$workDir" || fail "cd"

args=(-w 0.5 -p 1 -j 2 -scale 0.05 -settleTime 0.1 -endTime 0.05 -writeInterval 0.01
      -mean 0.02 -interval 60 -noPictures)
run() { local dir="$1"; shift; dpmStudy run "$dir" "${args[@]}" "$@" > "log.$dir" 2>&1 || { tail -20 "log.$dir"; fail "dpmStudy run $dir $*"; }; }
run reference -seeds 2          # seeds 1 and 2
run A -seeds 1 1                # seed 1 alone
run B -seeds 2 2                # seed 2 alone

sameResults()
{
    for t in summary.csv ensemble.csv findings.csv
    do
        cmp -s reference/results/$t "$1/results/$t" \
            || { diff reference/results/$t "$1/results/$t" | head -10; fail "$1/results/$t differs from the reference's"; }
    done
    echo "ok   $1/results: summary, ensemble and findings equal to the reference's"
}

dpmStudy export B B.tar.gz > log.export 2>&1 || { cat log.export; fail "export"; }
grep -q "export: 1 finished cases of B -> B.tar.gz" log.export || { cat log.export; fail "the export's line"; }
du -k B.tar.gz
dpmStudy import A B.tar.gz -mean 0.02 -noPictures > log.importA 2>&1 || { cat log.importA; fail "import into A"; }
grep -q "import: w0.50_1bar_seed2 from B.tar.gz" log.importA || { cat log.importA; fail "the import's line"; }
[ -f A/w0.50_1bar_seed2/constant/archivedCase ] || fail "no summary case in A"
grep -Eq "^[0-9-]+ [0-9:]+ UTC [0-9a-f]+" A/w0.50_1bar_seed2/constant/studyBuild \
    || fail "the summary case records no build it ran with"
sameResults A

dpmStudy import C A -mean 0.02 -noPictures > log.importC 2>&1 || { cat log.importC; fail "import of a study directory"; }
[ "$(ls -d C/w0.50_1bar_seed*/constant/archivedCase | wc -l)" = 2 ] || fail "C has not both summaries"
sameResults C

# The runner counts a summary case as finished and never runs it
run A -seeds 2 2
ls -d A/w0.50_1bar_seed2/[0-9]* >/dev/null 2>&1 && fail "the runner ran the imported summary case"
grep -q "w0.50_1bar_seed2 *finished" log.A || { cat log.A; fail "the summary case not reported finished"; }
echo "ok   the imported case counts as finished and is not run"

# Refusals: the archive edited, the study left as it was
refused()
{
    local pattern="$1" edit="$2"
    rm -rf edited && mkdir edited && tar -xzf B.tar.gz -C edited || fail "unpack"
    (cd edited/B && eval "$edit") || fail "edit: $edit"
    tar -czf edited.tar.gz -C edited B
    rm -rf D && cp -r A D
    dpmStudy import D edited.tar.gz > log.refused 2>&1 && { cat log.refused; fail "an archive edited by '$edit' was imported"; }
    grep -qE "$pattern" log.refused || { cat log.refused; fail "no message '$pattern'"; }
    grep -q Traceback log.refused && fail "a traceback"
    diff -rq A D > /dev/null || fail "a refused import changed the study"
    echo "ok   refused: $(grep -m1 -E "$pattern" log.refused | cut -c1-200)"
}
rm -rf A/w0.50_1bar_seed2       # so that the archive's case is new to A
refused "was made with another studyDict than D: \+.*an edited line" \
    'echo "// an edited line" >> studyDict'
refused "w0.50_1bar_seed2: its settings differ from w0.50_1bar_seed1's: endTime 0.05 here, 0.04 there" \
    'sed -i "s/^endTime .*/endTime 0.04;/" w0.50_1bar_seed2/constant/caseSettings'
refused "w0.50_1bar_seed2: its dictionaries differ from w0.50_1bar_seed1's: constant/gasProperties: [-+]viscosity" \
    'sed -i "s/^viscosity .*/viscosity 1.9e-05;/" w0.50_1bar_seed2/constant/gasProperties'

# An unfinished case is left out of an export: A's finished case given a
# later end time
rm -rf E && cp -r A E
sed -i 's/^endTime .*/endTime 0.1;/' E/w0.50_1bar_seed1/constant/caseSettings
dpmStudy export E E.tar.gz > log.exportE 2>&1 || { cat log.exportE; fail "export of E"; }
grep -q "export: w0.50_1bar_seed1 left out: not finished" log.exportE || { cat log.exportE; fail "the unfinished case not left out"; }
pass "two study directories merged through export/import give the single directory's results; summaries are not rerun; other studyDicts, settings and dictionaries are refused"
