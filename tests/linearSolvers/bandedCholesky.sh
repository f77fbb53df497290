#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The bandedCholesky direct solver: manufactured solutions on the paper's
# 20 x 120 mesh (Test-bandedCholesky states the tolerances), and its errors
# for a singular matrix and a bandwidth above its limit.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"

cp -r "$testsDir/smoke/blockMeshCase" "$workDir/case" || fail "copy"
cd "$workDir/case" || fail "cd"
blockMesh >log.blockMesh 2>&1 || fail "blockMesh"
test="$DPMFOAM2D_BUILD/tests/bin/Test-bandedCholesky"

for patch in outlet inlet
do
    "$test" -fixedPatch $patch 2>&1 | tee log.Test-bandedCholesky.$patch
    [ "${PIPESTATUS[0]}" = 0 ] || fail "manufactured solutions, fixed at the $patch"
done

# Errors: the run must fail and say why
expectError()
{
    local log="$1" pattern="$2"; shift 2
    "$test" "$@" >"$log" 2>&1 && fail "$* ran without error"
    grep -q "$pattern" "$log" || { cat "$log"; fail "$* did not say: $pattern"; }
    echo "PASS $*: $(grep -m1 "$pattern" "$log")"
}
expectError log.singular "singular or not definite" -singular
expectError log.bandwidth "half-bandwidth 20 is outside the allowed range \[0, 10\]" -maxBandwidth 10

pass "bandedCholesky"
