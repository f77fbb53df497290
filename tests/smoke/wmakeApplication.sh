#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Compiles a trivial application with wmake against Debian's OpenFOAM
# libraries and runs it. Expected API and patch level come from the installed
# package's version (dpkg), not from the code.
. "$(dirname "${BASH_SOURCE[0]}")/testFunctions" "$@"

cp -r "$testsDir/smoke/foamApiVersion" "$workDir/" || fail "copy"
cd "$workDir/foamApiVersion" || fail "cd"
rm -rf Make/linux64*
wmake >log.wmake 2>&1 || { tail -20 log.wmake; fail "wmake did not build foamApiVersion"; }
grep -qi "warning" log.wmake && { grep -i -A3 warning log.wmake | head -20; fail "compiler warnings"; }

out="$("$DPMFOAM2D_BUILD/tests/bin/foamApiVersion")" || fail "foamApiVersion did not run"
echo "$out"
version="$(dpkg-query -W -f='${Version}' openfoam)"      # e.g. 1912.200626-1+b1
expectApi="${version%%.*}"
expectPatch="${version#*.}"; expectPatch="${expectPatch%%-*}"
echo "$out" | grep -qx "api $expectApi" || fail "api is not $expectApi"
echo "$out" | grep -qx "patch $expectPatch" || fail "patch is not $expectPatch"
echo "$out" | grep -qx "label bytes 4" || fail "label size is not 32 bit (Debian builds WM_LABEL_SIZE=32)"
echo "$out" | grep -qx "scalar bytes 8" || fail "scalar is not double (Debian builds DP)"
pass "wmake application against OpenFOAM $version"
