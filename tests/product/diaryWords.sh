#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# etc/checkDiary finds the words of a diary (numbered work periods, issue
# numbers, helpers, one machine's paths) and lets the allow-list's
# legitimate uses pass; then, with the argument 'tree', no tracked file of
# the project holds one.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
top="$testsDir/.."
script="$top/etc/checkDiary"

if [ "${2:-}" = tree ]; then
    "$script" || fail "diary words in tracked files (above): say what is true now"
    pass "no diary words in the tracked files"
    exit 0
fi

tree="$workDir/tree"
mkdir -p "$tree/etc" "$tree/src" || fail "mkdir"
cd "$tree" && git init -q . || fail "git init"
cat >src/a.C <<'TEXT'
// measured in session 9 on the shared host
// fixed for issue #16
// see Issue 4 for the tolerance
// scratch copy in /tmp/run3 and /work/main
// one of the helpers found it, see ../../shared/reference/model.md
// the cell form of sessions 6-7, rerun in this session
// the pair loop, then the kick
TEXT
cat >src/b.C <<'TEXT'
#include "TestHelpers.hpp"
TEXT
printf 'src/b.C   TestHelpers\n' >etc/checkDiary.allow
git add -A . || fail "git add"

out="$("$script" -root "$tree")" && fail "no hit reported: $out"
for line in 1 2 3 4 5 6; do
    echo "$out" | grep -q "^src/a.C:$line:" || fail "line $line of src/a.C not reported: $out"
done
echo "$out" | grep -q "^src/a.C:7:" && fail "a line without diary words reported: $out"
echo "$out" | grep -q "^src/b.C" && fail "an allowed use reported: $out"
echo "$out" | tail -1 | grep -q "^6 diary words in 1 files" || fail "summary: $(echo "$out" | tail -1)"
pass "etc/checkDiary reports each diary word and passes the allowed uses"
