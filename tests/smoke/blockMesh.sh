#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# blockMesh on the paper's gas mesh: 0.15 m x 0.90 m in 7.5 mm cells, one
# cell thick. Expected: 20 x 120 = 2400 cells (paper, section 2).
. "$(dirname "${BASH_SOURCE[0]}")/testFunctions" "$@"

cp -r "$testsDir/smoke/blockMeshCase" "$workDir/case" || fail "copy"
cd "$workDir/case" || fail "cd"
blockMesh >log.blockMesh 2>&1 || { tail -20 log.blockMesh; fail "blockMesh failed"; }
checkMesh >log.checkMesh 2>&1 || { tail -20 log.checkMesh; fail "checkMesh failed"; }
grep -q "Mesh OK" log.checkMesh || fail "checkMesh did not report Mesh OK"
nCells="$(sed -n 's/^ *cells: *\([0-9]*\).*/\1/p' log.checkMesh | head -1)"
[ "$nCells" = 2400 ] || fail "expected 2400 cells, got '$nCells'"
pass "blockMesh made the paper's 20 x 120 mesh"
