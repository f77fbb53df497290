#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Bad input, table-driven: every row of badInput/*.cases breaks a fresh copy
# of the solver test case (its mesh made) and runs a command; the command
# must stop with a message matching the row's pattern (non-zero exit, never
# a signal, a hang or a silent run), or, for a suspicious but legitimate
# run, finish and warn. The rows are bash, one call each:
#
#   badInput <name> error|warning <pattern (grep -E)> <setup> [<command>]
#
# <setup> runs in the case first; <command> (default dpmFoam2D) is run
# there with a 180-s limit, its output in log.command. The names must be
# distinct; at least minimumRows rows in all (50).
#   badInput.sh <workDir> [<table> ...]   the tables badInput/<table>.cases
#                                         (default: all, and the row count)
# ctest runs one table a test (faults.badInput.<table>), so that they share
# the cores, and the count and the names' uniqueness over all tables apart
# (faults.badInput.rows: badInput.sh <workDir> -count).
# BADINPUT_ONLY=<regex> runs only the rows whose name matches (a check of
# one row while editing it; the count is then not checked).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
. "$testsDir/faults/stateFunctions"
shift
tables=("$@")

minimumRows=50
if [ "${tables[0]:-}" = -count ]
then
    names=$(cat "$testsDir"/faults/badInput/*.cases | sed -n 's/^badInput \([^ ]*\) .*/\1/p')
    n=$(echo "$names" | wc -l)
    twice=$(echo "$names" | sort | uniq -d | tr '\n' ' ')
    [ -z "$twice" ] || fail "row names used twice: $twice"
    [ "$n" -ge "$minimumRows" ] || fail "only $n rows (at least $minimumRows wanted)"
    pass "$n bad-input rows over $(ls "$testsDir"/faults/badInput/*.cases | wc -l) tables, each name once"
    exit 0
fi
makeCase "$workDir/template"
nFailed=0
nRows=0
declare -A seen

badInput()
{
    local name="$1" expect="$2" pattern="$3" setup="$4" command="${5:-dpmFoam2D}"
    [[ "$name" =~ ${BADINPUT_ONLY:-.} ]] || return 0
    nRows=$((nRows + 1))
    [ -z "${seen[$name]:-}" ] || { echo "FAIL $name: row name used twice"; nFailed=$((nFailed + 1)); return; }
    seen[$name]=1
    case "$expect" in error|warning) ;; *) echo "FAIL $name: expect '$expect'"; nFailed=$((nFailed + 1)); return ;; esac
    rm -rf "$workDir/$name" && cp -r "$workDir/template" "$workDir/$name"
    (
        cd "$workDir/$name" || exit 1
        eval "$setup" >log.setup 2>&1 || { echo "FAIL $name: setup failed"; cat log.setup; exit 1; }
        timeout -k 10 180 bash -c "$command" </dev/null >log.command 2>&1
        status=$?
        if [ "$status" = 124 ] || [ "$status" = 137 ]; then
            echo "FAIL $name: '$command' still ran after 180 s"; exit 1
        fi
        if [ "$status" -gt 128 ]; then
            echo "FAIL $name: '$command' died of signal $((status - 128))"; tail -15 log.command; exit 1
        fi
        if [ "$expect" = error ] && [ "$status" = 0 ]; then
            echo "FAIL $name: '$command' ran"; tail -5 log.command; exit 1
        fi
        if [ "$expect" = warning ] && [ "$status" != 0 ]; then
            echo "FAIL $name: '$command' failed ($status)"; tail -15 log.command; exit 1
        fi
        grep -qE "$pattern" log.command \
            || { echo "FAIL $name: no message matching '$pattern'"; tail -15 log.command; exit 1; }
        echo "ok   $name ($expect): $(grep -m1 -E "$pattern" log.command | sed 's/^ *//' | cut -c1-200)"
    ) || nFailed=$((nFailed + 1))
}

if [ ${#tables[@]} = 0 ]
then
    for table in "$testsDir"/faults/badInput/*.cases
    do
        t=${table##*/}
        tables+=("${t%.cases}")
    done
    counted=yes
fi
for table in "${tables[@]}"
do
    [ -f "$testsDir/faults/badInput/$table.cases" ] || fail "no table badInput/$table.cases"
    echo "== $table.cases"
    . "$testsDir/faults/badInput/$table.cases"
done

echo "$nRows rows"
[ "$nFailed" = 0 ] || fail "$nFailed of $nRows bad inputs were not reported as they should be"
[ -n "${BADINPUT_ONLY:-}" ] || [ -z "${counted:-}" ] || [ "$nRows" -ge "$minimumRows" ] \
    || fail "only $nRows rows (at least $minimumRows wanted)"
pass "every one of $nRows bad inputs gives its message"
