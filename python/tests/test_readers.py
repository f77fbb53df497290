# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The readers on small files of known content: a function object's table
over a restart (fixtures/restartedCase: a first run to 0.05 s, killed, its
rows from 0.03 s on replaced by a run restarted there, whose last line was
cut by a kill, and a table of dpmFoam2D -postProcess), gas fields
(fixtures/fields) and particle files in the solver's layout."""

import os
import shutil

import numpy as np
import pytest

import dpmfoam2d as dpm
from dpmfoam2d import fields, particles
from conftest import particle_file


def test_lacey_joins_a_restart(fixtures, capsys):
    M = dpm.lacey(os.path.join(fixtures, "restartedCase"))
    # the first run's 0.01, 0.02; the restart's 0.04-0.06; 0.07 cut short
    assert M["Time"] == pytest.approx([0.01, 0.02, 0.04, 0.05, 0.06])
    assert M["M"] == pytest.approx([0.1, 0.2, 0.4, 0.5, 0.6])
    assert list(M) == ["Time", "M", "S2", "S02", "SR2", "nCells"]
    err = capsys.readouterr().err
    assert "0.03/laceyIndex.dat line 7: cut short (no end of line): left out" in err
    assert "0.05/laceyIndex.dat: not joined with the run's table" in err


def test_postprocess_table_apart(fixtures):
    P = dpm.lacey(os.path.join(fixtures, "restartedCase"), postprocess=True)
    assert P["Time"] == pytest.approx([0.02, 0.04])
    assert P["M"] == pytest.approx([0.25, 0.45])


def test_table_refusals(tmp_path, fixtures):
    case = tmp_path / "case"
    shutil.copytree(os.path.join(fixtures, "restartedCase"), case)
    table = case / "postProcessing/laceyIndex/0/segregation.dat"
    S = dpm.segregation(str(case))
    assert S["vertical"] == pytest.approx([0.4, 0.4])
    table.write_text(table.read_text() + "0.03\t0.03\tx\t0.4\t0.02\t0.03\t-0.4\n")
    with pytest.raises(ValueError, match=r"segregation\.dat line 4: 'x' is not a number"):
        dpm.segregation(str(case))
    with pytest.raises(FileNotFoundError, match="no case directory"):
        dpm.lacey(str(tmp_path / "nothing"))
    (tmp_path / "postProcessing").mkdir()
    assert dpm.lacey(str(tmp_path)) is None             # a case without the table


def test_internal_fields(fixtures):
    voidage = fields.internal_field(os.path.join(fixtures, "fields", "voidage"))
    assert voidage == pytest.approx([0.41, 0.5, 0.95, 1.0])
    U = fields.internal_field(os.path.join(fixtures, "fields", "U"), 3)
    assert U.shape == (3, 3) and U[:, 1] == pytest.approx([0.3] * 3)


def test_binary_field(tmp_path):
    # OpenFOAM's binary list: the count, '(', the raw little-endian doubles, ')'
    values = np.array([0.4, 0.45, 0.9])
    path = tmp_path / "voidage"
    path.write_bytes(b'FoamFile { format binary; class volScalarField; '
                     b'arch "LSB;label=32;scalar=64"; }\ninternalField nonuniform '
                     b'List<scalar> 3(' + values.astype("<f8").tobytes() + b');\n')
    assert fields.internal_field(str(path)) == pytest.approx(values)
    path.write_bytes(path.read_bytes()[:-12])              # cut short
    with pytest.raises(fields.FieldError, match="shorter than its 3 values"):
        fields.internal_field(str(path))


def test_time_dirs(tmp_path):
    for name in ("0", "0.5", "1e-3", "10", "constant", "0.5.incomplete"):
        (tmp_path / name).mkdir()
    assert fields.time_dirs(str(tmp_path)) == [(0.0, "0"), (1e-3, "1e-3"), (0.5, "0.5"),
                                               (10.0, "10")]


def test_particle_files(tmp_path):
    case = str(tmp_path)
    particle_file(case, 0.0, [0.01, 0.02, 0.03], [0, 1, 1])
    particle_file(case, 0.01, [0.011, 0.021, 0.031], [0, 1, 1], ids=[5, 6, 7])
    assert [t for t, _ in dpm.list_times(case)] == [0.0, 0.01]
    assert dpm.particles_at(case, 0.004)["time"] == 0.0    # the nearest
    p = dpm.particles_at(case, 0.008)
    assert p["time"] == 0.01
    assert p["id"].tolist() == [5, 6, 7] and p["class"].dtype == np.int8
    assert p["position"].shape == (3, 3) and p["position"].dtype == np.float32
    assert p["position"][:, 1] == pytest.approx([0.011, 0.021, 0.031])
    # every dataset of the solver's table, read
    assert set(p) == set(particles.FIELDS) - {"spin"} | {"time"}
    with pytest.raises(ValueError, match="not a finite number"):
        dpm.particles_at(case, float("nan"))
    # a file cut short by a kill: named, as a ParticleFileError
    path = dpm.nearest_time(case, 0.01)[1]
    with open(path, "r+b") as f:
        f.truncate(os.path.getsize(path) // 2)
    with pytest.raises(particles.ParticleFileError, match="0.01.h5: unreadable particle file"):
        dpm.read_particles(path)
