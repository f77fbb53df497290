#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Sourcing another checkout's etc/bashrc switches to it: its applications and
# libraries come first and the other's leave PATH and LD_LIBRARY_PATH, also
# when switching back to one sourced before (they once stayed behind the
# other's, and a run took the other build's libraries without a word); and
# etc/checkEnvironment names another build's libraries found first.
. "$(dirname "${BASH_SOURCE[0]}")/testFunctions" "$@"

for name in a b; do
    mkdir -p "$workDir/$name/etc" \
        && cp "$testsDir/../etc/bashrc" "$testsDir/../etc/checkEnvironment" "$workDir/$name/etc/" \
        || fail "copy"
done
a="$(cd "$workDir/a" && pwd -P)"; b="$(cd "$workDir/b" && pwd -P)"
lib() { echo "$1/platforms/$WM_OPTIONS/lib"; }
app() { echo "$1/platforms/$WM_OPTIONS/bin"; }
count() { tr ':' '\n' <<< "$1" | grep -cxF "$2"; }
first() { tr ':' '\n' <<< "$1" | grep -m1 "$2"; }

. "$a/etc/bashrc"; . "$b/etc/bashrc"; . "$a/etc/bashrc"
[ "$DPMFOAM2D_PROJECT" = "$a" ] || fail "DPMFOAM2D_PROJECT is $DPMFOAM2D_PROJECT, not $a"
[ "$(first "$LD_LIBRARY_PATH" /platforms/)" = "$(lib "$a")" ] \
    || fail "the first project library directory is $(first "$LD_LIBRARY_PATH" /platforms/), not a's"
[ "$(first "$PATH" /platforms/)" = "$(app "$a")" ] \
    || fail "the first project application directory is $(first "$PATH" /platforms/), not a's"
[ "$(count "$LD_LIBRARY_PATH" "$(lib "$b")")" = 0 ] || fail "b's $(lib "$b") is still in LD_LIBRARY_PATH"
for d in "$(app "$b")" "$b/bin"; do
    [ "$(count "$PATH" "$d")" = 0 ] || fail "b's $d is still in PATH"
done
for d in "$(app "$a")" "$a/bin"; do
    [ "$(count "$PATH" "$d")" = 1 ] || fail "a's $d is in PATH $(count "$PATH" "$d") times, not once"
done
[ "$(count "$LD_LIBRARY_PATH" "$(lib "$a")")" = 1 ] || fail "a's library directory is not in LD_LIBRARY_PATH once"
[ "$(count "$PYTHONPATH" "$b/python")" = 0 ] || fail "b's Python package $b/python is still in PYTHONPATH"
[ "$(first "$PYTHONPATH" /python)" = "$a/python" ] || fail "a's Python package $a/python is not first in PYTHONPATH"
"$a/etc/checkEnvironment" -quiet || fail "checkEnvironment refuses a's environment"
LD_LIBRARY_PATH="$(lib "$b"):$LD_LIBRARY_PATH" "$a/etc/checkEnvironment" -quiet 2>/dev/null \
    && fail "checkEnvironment passes with b's libraries first"
pass "sourcing a, b, then a again leaves a's directories (PATH, LD_LIBRARY_PATH, PYTHONPATH) first, once, and none of b's; checkEnvironment refuses another build's libraries first"
