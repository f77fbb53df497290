#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The particle index the solver writes opens in ParaView as a time series:
# the test column (600 small and 130 large particles, 0.02 s, a particle
# file every 0.01 s) gives 3 times of 730 points each, every array the
# index lists one of the package's FIELDS (dpmfoam2d.particles), and the
# class counts 600/130 at every time; after dpmPackBed (as the main job
# runs) every dataset the index lists is in its file, time 0's too.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/column"
cd "$workDir/column" || fail "cd"
runSolver
fields=$(py -c "import dpmfoam2d as dpm; print(' '.join(dpm.FIELDS))") \
    || fail "the package's FIELDS"
cat >"$workDir/readXdmf.py" <<'PY'
import sys
import paraview.simple as ps
from paraview import servermanager as sm
from vtkmodules.numpy_interface import dataset_adapter as dsa
fields = sys.argv[2].split()
r = ps.XDMFReader(FileNames=[sys.argv[1]])
r.UpdatePipelineInformation()
times = list(r.TimestepValues)
ok = [round(t, 9) for t in times] == [0, 0.01, 0.02]
for t in times:
    r.UpdatePipeline(t)
    data = dsa.WrapDataObject(sm.Fetch(r))
    arrays = sorted(data.PointData.keys())
    cls = data.PointData["class"]
    print("t", t, "points", data.GetNumberOfPoints(), "arrays", arrays,
          "small", int((cls == 0).sum()), "large", int((cls == 1).sum()))
    ok = (ok and data.GetNumberOfPoints() == 730 and arrays and set(arrays) <= set(fields)
          and {"class", "diameter", "velocity"} <= set(arrays)
          and int((cls == 0).sum()) == 600 and int((cls == 1).sum()) == 130)
print("times", times)
sys.exit(0 if ok else 1)
PY
dpmPvbatch "$workDir/readXdmf.py" "$workDir/column/particles/particles.xdmf" "$fields" \
    >log.pvbatch 2>&1 || { cat log.pvbatch; fail "ParaView did not read particles.xdmf as expected"; }
grep "^t \|^times" log.pvbatch

# As the main job runs it: dpmPackBed writes the bed's file at time 0 before
# the gas exists, then the solver starts. Every dataset the index lists for
# a time is in that time's file (else ParaView reports XDMF errors), and
# the start file has the gas the particles saw like every later one.
makeCase "$workDir/packed"
cd "$workDir/packed" || fail "cd"
dpmPackBed >log.dpmPackBed 2>&1 || { tail -20 log.dpmPackBed; fail "dpmPackBed"; }
runSolver
py - particles <<'PY' || fail "particles.xdmf lists datasets its files do not have"
import re, sys, h5py
d = sys.argv[1]
items = re.findall(r">([^<>]+\.h5):/(\w+)</DataItem>", open(d + "/particles.xdmf").read())
missing = []
for name, dataset in items:
    with h5py.File("%s/%s" % (d, name), "r") as f:
        if dataset not in f:
            missing.append("%s:/%s" % (name, dataset))
print("%d datasets listed, %d missing %s" % (len(items), len(missing), " ".join(missing)))
with h5py.File(d + "/0.h5", "r") as f:
    start = sorted(f.keys())
print("0.h5:", " ".join(start))
sys.exit(1 if missing or "voidage" not in start or "gasVelocity" not in start else 0)
PY
dpmPvbatch "$workDir/readXdmf.py" "$workDir/packed/particles/particles.xdmf" "$fields" \
    >log.pvbatch 2>&1 || { cat log.pvbatch; fail "ParaView did not read the packed case's particles.xdmf"; }
grep -qiE "error" log.pvbatch && { cat log.pvbatch; fail "ParaView reported errors reading the packed case's particles.xdmf"; }
pass "the solver's particles.xdmf opens in ParaView as a time series of the package's fields, after dpmPackBed too, every listed dataset in its file"
