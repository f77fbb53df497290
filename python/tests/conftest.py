# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Fixtures of the package's unit tests: the folder of small fixture files,
and writers of the files a run makes, in the solver's layout
(docs/user-guide/output.md), written here with h5py and plain text so that
no writer of the package is under test when a reader is."""

import os

import h5py
import numpy as np
import pytest

FIXTURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures")


@pytest.fixture
def fixtures():
    return FIXTURES


def particle_file(case, t, y, cls, ids=None, x=None, diameter=1.5e-3):
    """<case>/particles/<t>.h5 as the solver writes it: the attribute time
    and the datasets of its table (float32 vectors, int8 classes, int32
    ids), particles at heights y (m) of the classes cls."""
    y = np.asarray(y, float)
    n = len(y)
    x = np.linspace(0.01, 0.05, n) if x is None else np.asarray(x, float)
    folder = os.path.join(case, "particles")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "%.6g.h5" % t)
    with h5py.File(path, "w") as f:
        f.attrs["time"] = np.float64(t)
        f["position"] = np.column_stack([x, y, np.full(n, 2e-3)]).astype(np.float32)
        f["velocity"] = np.zeros((n, 3), np.float32)
        f["omega"] = np.zeros(n, np.float32)
        f["diameter"] = np.full(n, diameter, np.float32)
        f["class"] = np.asarray(cls, np.int8)
        f["id"] = (np.arange(n) if ids is None else np.asarray(ids)).astype(np.int32)
        f["voidage"] = np.full(n, 0.45, np.float32)
        f["gasVelocity"] = np.zeros((n, 3), np.float32)
    return path


def summary_case(study, name, seed, final_m, end_time=0.05, gas="viscosity 1.8e-05;"):
    """A finished case of a study kept as its summary (as dpmStudy export
    keeps one): its settings (w 0.5, 1 bar, seed), dictionaries, the
    summary's record, the head of its log and its tables, M rising
    linearly to final_m at end_time."""
    case = os.path.join(study, name)
    for d in ("constant", "system", os.path.join("postProcessing", "laceyIndex", "0")):
        os.makedirs(os.path.join(case, d), exist_ok=True)

    def write(rel, text):
        with open(os.path.join(case, rel), "w") as f:
            f.write(text)

    write("constant/caseSettings", "wSmall 0.5;\npressure 1;\nseed %d;\nendTime %g;\n"
          % (seed, end_time))
    write("constant/gasProperties", gas + "\n")
    write("system/controlDict", "application dpmFoam2D;\n")
    write("constant/archivedCase", "# a finished case kept as its summary\ntime %g\n"
          "from a test\n" % end_time)
    write("log.dpmFoam2D", "dpmFoam2D\nUmf (Wen-Yu) 0.3 m/s, U0/Umf 1.25, U0 0.375 m/s\n"
          "Starting time loop\n")
    times = np.linspace(0.01, end_time, 5)
    write("postProcessing/laceyIndex/0/laceyIndex.dat", "# Time M\n" + "".join(
        "%g %g\n" % (t, final_m * t / end_time) for t in times))
    write("postProcessing/laceyIndex/0/segregation.dat",
          "# Time vertical horizontal hSmall hLarge rSmall rLarge\n" + "".join(
              "%g 0.1 0.2 0.03 0.04 0.01 0.02\n" % t for t in times))
    return case


def study_dir(path, *cases):
    """A study directory with a studyDict of one cell (w 0.5, 1 bar) and
    the summary cases (name, seed, final M) given."""
    os.makedirs(path, exist_ok=True)
    with open(os.path.join(path, "studyDict"), "w") as f:
        f.write("massFractions { values (0.5); }\npressures { values (1); }\n")
    for name, seed, final_m in cases:
        summary_case(path, name, seed, final_m)
    return path
