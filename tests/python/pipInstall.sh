#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The package installed as a user installs it, not editable: a copy of
# python/ built into a fresh virtual environment (the system's numpy,
# scipy, h5py, matplotlib and pytest; no network: Debian's setuptools), so
# that nothing of the checkout is left to find. There, without the
# project's PYTHONPATH:
#   - dpmfoam2d imports from the environment, not from the checkout;
#   - every command is a console script of the environment, and -h runs;
#   - dpmStudy's default template needs the project: without
#     DPMFOAM2D_PROJECT it is refused naming the variable, with it the
#     template's variants are listed as the checkout holds them;
#   - the package's unit tests (python/tests) pass against the installed
#     package.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
top="$(cd "$testsDir/.." && pwd -P)"
cd "$workDir" || fail "cd"

# The user's shell: no project PYTHONPATH, no user site, no pip cache or
# configuration from outside, no project environment
clean() { env -u PYTHONPATH -u DPMFOAM2D_PROJECT PYTHONNOUSERSITE=1 PIP_NO_CACHE_DIR=1 \
          PIP_CONFIG_FILE=/dev/null PYTHONDONTWRITEBYTECODE=1 "$@"; }
venv="$workDir/venv"
clean /usr/bin/python3 -m venv --system-site-packages "$venv" \
    || fail "python3 -m venv failed (Debian's python3-venv, etc/install)"
clean "$venv/bin/python" -c "import dpmfoam2d" 2>/dev/null \
    && fail "dpmfoam2d is importable before the install: the test would prove nothing"

# A copy, so that the build's files stay out of the checkout
mkdir source && cp -r "$top/python/dpmfoam2d" "$top/python/pyproject.toml" \
    "$top/python/README.md" "$top/python/tests" source/ || fail "copy python/"
clean "$venv/bin/pip" install --no-build-isolation --no-index ./source >log.pip 2>&1 \
    || { tail -20 log.pip; fail "pip install python/ failed"; }
rm -rf source

clean "$venv/bin/python" - "$venv" "$top" <<'PY' || fail "dpmfoam2d in the virtual environment"
import os
import sys

import dpmfoam2d
venv, top = (os.path.realpath(p) for p in sys.argv[1:])
where = os.path.realpath(dpmfoam2d.__file__)
assert where.startswith(venv + os.sep), "dpmfoam2d imported from %s" % where
print("dpmfoam2d %s imported from %s" % (dpmfoam2d.__version__, os.path.dirname(where)))
PY

commands="dpmStudy dpmPictures dpmPlotMixing dpmSnapshot dpmMovie dpmParaView dpmPvbatch
          dpmRiseTime dpmBedStatistics"
for c in $commands
do
    [ -x "$venv/bin/$c" ] || fail "no console script $c in the environment"
    clean "$venv/bin/$c" -h > "log.$c" 2>&1
    grep -q "Traceback" "log.$c" && { cat "log.$c"; fail "$c -h: a traceback"; }
    grep -qi "usage\|$c" "log.$c" || { cat "log.$c"; fail "$c -h says no usage"; }
done
echo "ok   the console scripts: $(echo $commands)"

clean "$venv/bin/dpmStudy" variants > log.noProject 2>&1 && fail "dpmStudy variants ran without the project"
grep -q "DPMFOAM2D_PROJECT is not set: dpmStudy's default template" log.noProject \
    || { cat log.noProject; fail "no message naming DPMFOAM2D_PROJECT"; }
echo "ok   without the project: $(cat log.noProject)"
clean env DPMFOAM2D_PROJECT="$top" "$venv/bin/dpmStudy" variants > log.variants 2>&1 \
    || { cat log.variants; fail "dpmStudy variants with DPMFOAM2D_PROJECT"; }
[ "$(awk '{print $1}' log.variants)" = "$(ls "$top/tutorials/paperStudy/variants")" ] \
    || { cat log.variants; fail "dpmStudy variants does not list the template's variants"; }
echo "ok   dpmStudy variants through DPMFOAM2D_PROJECT: $(awk '{print $1}' log.variants | tr '\n' ' ')"

# the unit tests, on the installed package (a copy of them, outside the checkout)
cp -r "$top/python/tests" unitTests || fail "copy the tests"
(cd unitTests && clean "$venv/bin/python" -m pytest -q -p no:cacheprovider \
    --rootdir . --basetemp "$workDir/pytest" .) > log.pytest 2>&1 \
    || { cat log.pytest; fail "the unit tests on the installed package"; }
grep -q "passed" log.pytest || { cat log.pytest; fail "no unit test ran"; }
pass "pip installs dpmfoam2d (not editable) with its commands; they need the project only through DPMFOAM2D_PROJECT; the unit tests pass on it ($(tail -1 log.pytest | sed 's/=//g; s/^ *//'))"
