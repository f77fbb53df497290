#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The particle index the solver writes opens in ParaView as a time series:
# the test column (600 small and 130 large particles, 0.02 s, a particle
# file every 0.01 s) gives 3 times of 730 points each, every array the
# index lists one of the package's FIELDS (dpmfoam2d.particles), and the
# class counts 600/130 at every time.
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
pass "the solver's particles.xdmf opens in ParaView as a time series of the package's fields"
