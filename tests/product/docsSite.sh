#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The documentation site builds with MkDocs in strict mode: every internal
# link and nav entry resolves, every page is in the nav, the dictionary
# tables list exactly the entries the code knows, every command's -h runs.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
"$testsDir/../etc/buildDocs" -o "$workDir/site" || fail "the site does not build (above)"
for page in index.html user-guide/dictionaries.html user-guide/commands.html theory/paper-model.html reproduction.html performance.html; do
    [ -s "$workDir/site/$page" ] || fail "no $page in the site"
done
grep -q "dpmStudy" "$workDir/site/user-guide/commands.html" || fail "the commands page lacks dpmStudy"
pass "the documentation site builds with warnings as errors"
