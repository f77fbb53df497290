#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmStudy on a study whose case is an imported summary (a summary case made
# by hand, w 0.5 at 1 bar, seed 1, its run ended at 0.05 s, exported and
# imported into the study S). Nothing is run:
#   1. status shows the summary at the time it records (not 0), imported;
#   2. a run with a longer -endTime says that the summary cannot be
#      continued and keeps its time, and packs no bed for it (its bed would
#      serve no case);
#   3. an import that finds the same case here, unfinished, keeps the local
#      one and says so: the local case is used, not the finished import.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/faults/summaryFunctions"
cd "$workDir" || fail "cd"
case1=w0.50_1bar_seed1
noTraceback() { ! grep -q "Traceback" "$1" || { cat "$1"; fail "$2: a traceback"; }; }

# The study src: one summary case made by hand (the template's dictionaries)
summaryCaseDictionaries src $case1 || fail "the summary case's dictionaries"
cp -r src/$case1 local          # the same case, not run yet (for 3.)
markSummaryCase src/$case1 || fail "the summary case"
dpmStudy export src base.tar.gz > log.export 2>&1 || { cat log.export; fail "export of src"; }
dpmStudy import S base.tar.gz -noPictures > log.import 2>&1 || { cat log.import; fail "import into S"; }
[ -f S/$case1/constant/archivedCase ] || fail "no summary case imported into S"

echo "1. status"
dpmStudy status S > log.status 2>&1 || { cat log.status; fail "status"; }
noTraceback log.status "status"
cat log.status
grep -Eq "^$case1 +done +imported +0.05 of 0.05 s \(an imported summary\)" log.status \
    || fail "status does not show the summary at its time 0.05 s, imported"

echo "2. a run with a longer -endTime"
nice dpmStudy run S -w 0.5 -p 1 -seeds 1 -endTime 0.1 -scale 0.05 -noPictures > log.longer 2>&1 \
    || { cat log.longer; fail "a run with -endTime 0.1"; }
noTraceback log.longer "-endTime 0.1"
grep -q "^$case1 *an imported summary (t = 0.05 s): it cannot be continued to -endTime 0.1 s and keeps its time" log.longer \
    || { cat log.longer; fail "no word that the summary cannot be continued to -endTime 0.1"; }
grep -q "finished (t = 0.1 s)" log.longer && { cat log.longer; fail "the summary reported finished at 0.1 s"; }
[ ! -e S/beds/w0.50_seed1 ] || fail "a bed was packed for a case that is only a summary: $(ls S/beds)"
[ -z "$(ls -d S/$case1/[0-9]* 2>/dev/null)" ] || fail "the summary case was run"
echo "ok   $(grep -m1 "imported summary" log.longer)"

echo "3. an import of a case that is here, unfinished"
mkdir -p L && cp "$DPMFOAM2D_PROJECT/tutorials/paperStudy/studyDict" L/ && cp -r local L/$case1
dpmStudy import L base.tar.gz -noPictures > log.importLocal 2>&1 || { cat log.importLocal; fail "import into L"; }
noTraceback log.importLocal "import onto an unfinished local case"
cat log.importLocal | grep "^import"
grep -q "^import: $case1: the local case is used, unfinished (no time directory); the finished case of the import is not taken" log.importLocal \
    || { cat log.importLocal; fail "no word on which of the local case and the import is used"; }
[ ! -e L/$case1/constant/archivedCase ] || fail "the local case was replaced by the summary"
pass "an imported summary: status at its time, not continued to a longer -endTime (said so), no bed packed for it; an unfinished local case kept over a finished import, said so"
