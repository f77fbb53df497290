#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The package dpmfoam2d reads what dpmFoam2D writes: the test column (600
# small and 130 large particles, 0.02 s, the laceyIndex function object) is
# run, then
#   - every dataset of every particle file is one of the reader's FIELDS,
#     with its type and components, those always written are there, and
#     read_particles returns all of them (voidage and gasVelocity in every
#     file, the start's included; spin in the slab mode only);
#   - particles.xdmf lists, for each time, every dataset of that time's
#     file as an attribute (position as the geometry), each one of FIELDS;
#   - the counts per class are the case's (600 and 130), and the voidage
#     the particles saw lies in (0, 1];
#   - lacey() and segregation() give the function object's rows, one per
#     0.01 s from 0 to the end time, 0.02 s;
#   - the docs' five-line example (docs/user-guide/python.md) runs in the
#     case and draws its picture.
# Arguments after the work directory: setSlab's (slab3D <depth>).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"
shift

makeCase "$workDir/column"
cd "$workDir/column" || fail "cd"
setSlab "$@"
setEntry system/controlDict functions "{ #includeFunc laceyIndex }"
runSolver

py - "${1:-discs2D}" <<'PY' || fail "the particle files through dpmfoam2d.particles"
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

import dpmfoam2d as dpm
from dpmfoam2d import particles

slab = sys.argv[1] == "slab3D"
times = dpm.list_times(".")
assert [round(t, 9) for t, _ in times] == [0, 0.01, 0.02], times
for t, path in times:
    with h5py.File(path, "r") as f:
        written = set(f)
        unknown = written - set(dpm.FIELDS)
        assert not unknown, "%s: datasets %s are not in the reader's FIELDS" % (path, unknown)
        for name in written:
            dtype, components, _ = dpm.FIELDS[name]
            shape = f[name].shape
            assert f[name].dtype == dtype and (shape[1:] == ((components,) if components > 1 else ())), \
                "%s: %s is %s %s, FIELDS says %s x %d" % (path, name, f[name].dtype, shape,
                                                         np.dtype(dtype), components)
    missing = set(particles.REQUIRED) - written
    assert not missing, "%s: no %s" % (path, missing)
    assert {"voidage", "gasVelocity"} <= written, "%s: no voidage, gasVelocity" % path
    assert ("spin" in written) == slab, "%s: spin %s in the %s mode" % (
        path, "present" if "spin" in written else "absent", "slab" if slab else "2D")
    p = dpm.read_particles(path)
    assert set(p) == written | {"time"}, (sorted(p), sorted(written))
    assert abs(p["time"] - t) < 1e-12
    counts = np.bincount(p["class"], minlength=2)
    assert list(counts) == [600, 130], counts
    if "voidage" in p:
        assert np.all((p["voidage"] > 0) & (p["voidage"] <= 1)), (p["voidage"].min(), p["voidage"].max())
latest = dpm.particles_at(".")
assert abs(latest["time"] - 0.02) < 1e-12

index = ET.parse("particles/particles.xdmf")
names = {a.get("Name") for a in index.iter("Attribute")}
assert names and names <= set(dpm.FIELDS), "particles.xdmf attributes %s not in FIELDS" % (
    names - set(dpm.FIELDS))
grids = [g for g in index.iter("Grid") if g.get("GridType") == "Uniform"]
assert len(grids) == len(times), "particles.xdmf lists %d times, the case has %d" % (
    len(grids), len(times))
for grid, (t, path) in zip(grids, times):
    with h5py.File(path, "r") as f:
        written = set(f)
    listed = {a.get("Name") for a in grid.iter("Attribute")} | {"position"}
    assert listed == written, "particles.xdmf at %s lists %s, its file has %s" % (
        grid.find("Time").get("Value"), sorted(listed), sorted(written))
print("%d particle files: datasets %s; particles.xdmf attributes %s"
      % (len(times), " ".join(sorted(written)), " ".join(sorted(names))))

M, S = dpm.lacey("."), dpm.segregation(".")
for table, columns in ((M, ("Time", "M")), (S, ("Time", "vertical", "horizontal"))):
    assert table is not None and all(c in table for c in columns), table and list(table)
    assert np.allclose(table["Time"], [0, 0.01, 0.02], atol=1e-9), table["Time"]
print("laceyIndex: M = %s; segregation: vertical = %s" % (
    " ".join("%.4f" % m for m in M["M"]), " ".join("%+.4f" % v for v in S["vertical"])))
PY

sed -n '/<!-- example: mixing-and-snapshot -->/,/^```$/p' "$testsDir/../docs/user-guide/python.md" \
    | sed '1,2d;$d' >example.py
[ "$(wc -l <example.py)" = 5 ] || { cat example.py; fail "the docs' example is not five lines"; }
MPLBACKEND=Agg py example.py >log.example 2>&1 || { cat log.example; fail "the docs' example failed"; }
py - <<'PY' || fail "the docs' example drew no picture"
import matplotlib.image as m
im = m.imread("bed.png")
assert im.shape[0] > 100 and im.shape[1] > 200, im.shape
print("the docs' example drew bed.png, %d x %d px" % (im.shape[1], im.shape[0]))
PY
pass "dpmfoam2d reads every field the solver writes${1:+ ($1)}, its tables, and runs the docs' example"
