#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The package dpmfoam2d on paths and arguments that are not what it reads
# (nothing is run; a case of written particle files and tables):
#   - a missing case or study directory is refused naming the path, never
#     taken for an empty one: study_table, list_times, time_dirs,
#     class_names (FileNotFoundError);
#   - particles_at with a time that is no finite number (nan, inf) is
#     refused (ValueError), not answered with a file;
#   - rise_times with a fraction outside (0, 1] is refused naming the
#     argument;
#   - a table whose last line has no end of line (being written, or cut by
#     a kill) loses that line with a note, even when it has every column
#     (its last number may be cut short); the lines before are kept.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
cd "$workDir" || fail "cd"

mkdir -p case/system case/postProcessing/laceyIndex/0 && touch case/system/controlDict
printf '# Time M\n0.01 0.5\n0.02 0.6\n0.03 0.712' > case/postProcessing/laceyIndex/0/laceyIndex.dat
py - <<'PY' 2>log.stderr || fail "the package on missing paths and bad arguments"
import math
import numpy as np
import dpmfoam2d as dpm
from dpmfoam2d import particles, rise_time

particles.write_particles("case", 0.0, np.column_stack([np.full(3, 0.01), [0.01, 0.02, 0.03]]),
                          np.full(3, 1e-3), [0, 0, 1])


def refused(kind, words, call, *args):
    try:
        got = call(*args)
    except kind as e:
        missing = [w for w in words if w not in str(e)]
        assert not missing, "%s%r: '%s' does not name %s" % (call.__name__, args, e, missing)
        print("ok   %s%r refused: %s" % (call.__name__, args, e))
        return
    raise AssertionError("%s%r gave %r, no %s" % (call.__name__, args, got, kind.__name__))


refused(FileNotFoundError, ["missingStudy"], dpm.study_table, "missingStudy")
refused(FileNotFoundError, ["missingCase"], dpm.list_times, "missingCase")
refused(FileNotFoundError, ["missingCase"], dpm.time_dirs, "missingCase")
refused(FileNotFoundError, ["missingCase"], particles.class_names, "missingCase")
for t in (math.nan, math.inf):
    refused(ValueError, [str(t), "finite"], dpm.particles_at, "case", t)
refused(ValueError, ["fractions 2", "(0, 1]"], rise_time.rise_times, "case", 1, [2])
refused(ValueError, ["fractions 0", "(0, 1]"], rise_time.rise_times, "case", 1, 0)

# What exists but is empty stays empty, not refused
assert dpm.study_table("case") is None
assert dpm.time_dirs("case") == []

M = dpm.read_dat("case/postProcessing/laceyIndex/0/laceyIndex.dat")
assert np.allclose(M["Time"], [0.01, 0.02]) and np.allclose(M["M"], [0.5, 0.6]), \
    "a last line without its end of line was kept: Time %s M %s" % (M["Time"], M["M"])
print("ok   a last line without its end of line (all its columns there) left out")
PY
cat log.stderr
grep -q "note: case/postProcessing/laceyIndex/0/laceyIndex.dat line 4: cut short (no end of line): left out" log.stderr \
    || fail "no note on the line left out"
pass "missing paths refused naming them; particles_at(nan) and rise_times' fraction 2 refused; a table's last line without its end of line left out with a note"
