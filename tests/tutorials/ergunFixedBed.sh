#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# tutorials/ergunFixedBed as a user runs it: Allrun, then its check.
# Expected: the gas pressure gradient inside the frozen lattice equals
# Ergun's at the voidage the drag sees within 3 % (ergunCheck; the same
# case as tests/solver/ergunFixedBed.sh, which says where the numbers come
# from).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

cp -r "$testsDir/../tutorials/ergunFixedBed" "$workDir/case" || fail "copy"
cd "$workDir/case" && ./Allclean >/dev/null && ./Allrun || fail "Allrun"
cat log.ergunCheck
./ergunCheck >/dev/null || fail "pressure gradient differs from Ergun by more than 3 %"
pass "the Ergun tutorial's check passes"
