#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# etc/licenseHeaders on a small tree of one file of each kind: the header
# each kind must get (GPL-3.0-or-later in SPDX form, as LICENSE states), the
# #! line kept first, data and documents untouched, a second run changing
# nothing; then, with the argument 'tree', every tracked source file of the
# project carries it.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
top="$testsDir/.."
script="$top/etc/licenseHeaders"
spdx="SPDX-License-Identifier: GPL-3.0-or-later"

if [ "${2:-}" = tree ]; then
    "$script" -check || fail "source files without a licence header (above): run etc/licenseHeaders"
    pass "every tracked source file carries the licence header"
    exit 0
fi

grep -q "GNU GENERAL PUBLIC LICENSE" "$top/LICENSE" && grep -q "Version 3, 29 June 2007" "$top/LICENSE" \
    || fail "LICENSE is not the GPL-3.0 text"

tree="$workDir/tree"
mkdir -p "$tree/src/app" "$tree/constant" || fail "mkdir"
cd "$tree" && git init -q . || fail "git init"
printf '/*%s*\\\nClass\n    Foo\n\\*%s*/\nint x;\n' "$(printf -- '-%.0s' {1..75})" "$(printf -- '-%.0s' {1..75})" >src/app/withBanner.H
printf '#include "foo.H"\nint y;\n' >src/app/noBanner.C
printf '#pragma once\nint z;\n' >src/app/engine.hpp
printf '#!/usr/bin/python3\n"""doc"""\nprint(1)\n' >tool
printf '#!/bin/bash\necho hi\n' >run.sh
printf '#!/bin/bash\nspdx="%s"\n' "$spdx" >quoted.sh     # a string, not a header
printf 'project(x)\n' >CMakeLists.txt
printf 'FoamFile {}\nkn 800;\n' >constant/particleProperties
printf '# Title\n' >README.md
chmod +x tool run.sh quoted.sh
git add -A . || fail "git add"
cp constant/particleProperties README.md "$workDir/" || fail "copy"

out="$("$script" -root "$tree")" || fail "the script failed: $out"
[ "$out" = "licence header added to 7 files" ] || fail "expected 7 files changed, got: $out"

# The OpenFOAM side: the licence block inside the existing banner
sed -n 2p src/app/withBanner.H | grep -q "dpmFoam2D" || fail "withBanner.H: no project line after the banner's first line"
grep -q "^    $spdx$" src/app/withBanner.H || fail "withBanner.H: no SPDX line"
[ "$(grep -c '^Class$' src/app/withBanner.H)" = 1 ] || fail "withBanner.H: the banner's own text was lost"
head -1 src/app/noBanner.C | grep -q '^/\*---' || fail "noBanner.C: no banner opened"
grep -q '^\\\*---' src/app/noBanner.C || fail "noBanner.C: the banner is not closed"
grep -q '#include "foo.H"' src/app/noBanner.C || fail "noBanner.C: its code was lost"
# C++ of the DEM: two // lines first
[ "$(sed -n 2p src/app/engine.hpp)" = "// $spdx" ] || fail "engine.hpp: $(head -2 src/app/engine.hpp)"
# Scripts: the #! line stays first
[ "$(head -1 tool)" = "#!/usr/bin/python3" ] || fail "tool: the #! line moved"
[ "$(sed -n 3p tool)" = "# $spdx" ] || fail "tool: $(head -3 tool)"
[ -x tool ] || fail "tool lost its execute bit"
[ "$(sed -n 3p run.sh)" = "# $spdx" ] || fail "run.sh: $(head -3 run.sh)"
[ "$(sed -n 3p quoted.sh)" = "# $spdx" ] || fail "quoted.sh: a string holding the SPDX text taken for a header"
[ "$(sed -n 2p CMakeLists.txt)" = "# $spdx" ] || fail "CMakeLists.txt: $(head -2 CMakeLists.txt)"
# Not source: untouched
cmp -s constant/particleProperties "$workDir/particleProperties" || fail "a dictionary was changed"
cmp -s README.md "$workDir/README.md" || fail "a document was changed"
/usr/bin/python3 -c 'import ast,sys; ast.parse(open("tool").read())' || fail "tool is no longer valid Python"
bash -n run.sh || fail "run.sh is no longer valid shell"

out="$("$script" -root "$tree")" || fail "second run failed: $out"
[ "$out" = "licence header added to 0 files" ] || fail "a second run changed files: $out"
"$script" -root "$tree" -check >/dev/null || fail "-check finds files without a header after the run"
pass "etc/licenseHeaders adds each kind's header once and leaves data alone"
