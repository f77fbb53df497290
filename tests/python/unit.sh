#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The package's unit tests (python/tests, pytest): the readers on small
# fixture files, the statistics against a printed t table and closed forms,
# rise times and bed statistics worked by hand, the study's merge and
# results, dpmStudy's subcommands. Each test states where its numbers come
# from. pytest is Debian's python3-pytest.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
/usr/bin/python3 -c "import pytest" 2>/dev/null \
    || fail "no pytest for /usr/bin/python3: install Debian's python3-pytest"
cd "$testsDir/../python" || fail "cd python"
# nothing written into the checkout: no bytecode, no cache; temporary
# files in the work directory
PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -m pytest -q -p no:cacheprovider \
    --basetemp "$workDir/pytest" tests > "$workDir/log.pytest" 2>&1
status=$?
cat "$workDir/log.pytest"
[ $status = 0 ] || fail "python/tests: $(tail -1 "$workDir/log.pytest")"
pass "python/tests: $(tail -1 "$workDir/log.pytest" | sed 's/=//g; s/^ *//')"
