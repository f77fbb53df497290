#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The Python package installs with pip as a user installs it: a fresh virtual
# environment with the system's numpy, h5py and matplotlib, where dpmfoam2d
# is not importable before the install, then
#   pip install --no-build-isolation --no-index -e python/
# (no network: Debian's setuptools builds it). In that environment, without
# the project's PYTHONPATH, dpmfoam2d imports from the checkout, pip knows
# it under the version dpmfoam2d.__version__ states, and the docs' five-line
# example (docs/user-guide/python.md) draws its picture in a case the solver
# wrote (the test column, 0.02 s, with the laceyIndex function object).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
top="$(cd "$testsDir/.." && pwd -P)"

makeCase "$workDir/column"
cd "$workDir/column" || fail "cd"
setEntry system/controlDict functions "{ #includeFunc laceyIndex }"
runSolver

# The user's shell: no project PYTHONPATH, no user site, no pip cache or
# configuration from outside
clean() { env -u PYTHONPATH PYTHONNOUSERSITE=1 PIP_NO_CACHE_DIR=1 PIP_CONFIG_FILE=/dev/null "$@"; }
venv="$workDir/venv"
clean /usr/bin/python3 -m venv --system-site-packages "$venv" \
    || fail "python3 -m venv failed (Debian's python3-venv, etc/install)"
clean "$venv/bin/python" -c "import numpy, h5py, matplotlib" \
    || fail "the virtual environment does not see the system's numpy, h5py and matplotlib"
clean "$venv/bin/python" -c "import dpmfoam2d" 2>/dev/null \
    && fail "dpmfoam2d is importable before the install: the test would prove nothing"

clean "$venv/bin/pip" install --no-build-isolation --no-index -e "$top/python" >"$workDir/log.pip" 2>&1 \
    || { tail -20 "$workDir/log.pip"; fail "pip install -e python/ failed"; }

clean "$venv/bin/python" - "$top/python/dpmfoam2d/__init__.py" <<'PY' || fail "dpmfoam2d in the virtual environment"
import importlib.metadata
import os
import re
import sys

import dpmfoam2d

expected = sys.argv[1]
assert os.path.samefile(dpmfoam2d.__file__, expected), \
    "dpmfoam2d imported from %s, not the checkout's %s" % (dpmfoam2d.__file__, expected)
assert re.fullmatch(r"[0-9]+\.[0-9]+\.[0-9]+", dpmfoam2d.__version__), dpmfoam2d.__version__
installed = importlib.metadata.version("dpmfoam2d")
assert installed == dpmfoam2d.__version__, \
    "pip installed version %s, dpmfoam2d.__version__ is %s" % (installed, dpmfoam2d.__version__)
print("dpmfoam2d %s installed, imported from the checkout" % installed)
PY

sed -n '/<!-- example: mixing-and-snapshot -->/,/^```$/p' "$top/docs/user-guide/python.md" \
    | sed '1,2d;$d' >example.py
[ "$(wc -l <example.py)" = 5 ] || { cat example.py; fail "the docs' example is not five lines"; }
MPLBACKEND=Agg clean "$venv/bin/python" example.py >log.example 2>&1 \
    || { cat log.example; fail "the docs' example failed in the virtual environment"; }
clean "$venv/bin/python" - <<'PY' || fail "the docs' example drew no picture"
import matplotlib.image as m
im = m.imread("bed.png")
assert im.shape[0] > 100 and im.shape[1] > 200, im.shape
print("the docs' example drew bed.png, %d x %d px" % (im.shape[1], im.shape[0]))
PY
pass "pip installs dpmfoam2d into a fresh virtual environment offline, and the docs' example runs there"
