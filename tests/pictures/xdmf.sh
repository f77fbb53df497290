#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The particle index written by bin/dpmParticleIO.py (the solver's format)
# opens in ParaView as a time series: 3 times, 3250 points each, with the
# arrays velocity, omega, diameter, class, id, and class counts 2250/1000.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/pictures/pictureFunctions"

makeParticleCase "$workDir/bed" 0.01 0.02 0.03
cat >"$workDir/readXdmf.py" <<'PY'
import sys
import paraview.simple as ps
from paraview import servermanager as sm
from vtkmodules.numpy_interface import dataset_adapter as dsa
r = ps.XDMFReader(FileNames=[sys.argv[1]])
r.UpdatePipelineInformation()
times = list(r.TimestepValues)
r.UpdatePipeline(times[1])
data = dsa.WrapDataObject(sm.Fetch(r))
arrays = sorted(data.PointData.keys())
cls = data.PointData["class"]
print("times", times, "points", data.GetNumberOfPoints(), "arrays", arrays,
      "small", int((cls == 0).sum()), "large", int((cls == 1).sum()))
ok = (times == [0.01, 0.02, 0.03] and data.GetNumberOfPoints() == 3250
      and arrays == ["class", "diameter", "id", "omega", "velocity"]
      and int((cls == 0).sum()) == 2250 and int((cls == 1).sum()) == 1000)
sys.exit(0 if ok else 1)
PY
dpmPvbatch "$workDir/readXdmf.py" "$workDir/bed/particles/particles.xdmf" \
    >log.pvbatch 2>&1 || { cat log.pvbatch; fail "ParaView did not read particles.xdmf as expected"; }
grep "^times" log.pvbatch
pass "particles.xdmf opens in ParaView as a time series"
