# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Rise times and bed statistics on beds whose answers are worked by hand."""

import os

import numpy as np
import pytest

from dpmfoam2d import bed_statistics, rise_time, tables
from conftest import particle_file

# A bed of ten particles at 0.01 ... 0.10 m and two intruders (ids 10, 11)
BED = list(np.linspace(0.01, 0.10, 10))
INTRUDERS = {1.0: (0.02, 0.01), 1.1: (0.05, 0.06), 1.2: (0.10, 0.099), 1.3: (0.10, 0.12)}


@pytest.fixture
def rising(tmp_path):
    for t, heights in INTRUDERS.items():
        particle_file(str(tmp_path), t, BED + list(heights), [0] * 10 + [1, 1])
    return str(tmp_path)


def test_rise_times_by_hand(rising):
    # surfaces (numpy's linear quantile of the bed): q 0.99 at
    # 0.01 + 0.99 x 0.09 = 0.0991 m, q 0.5 at 0.055 m. Risen (from 1.0 s):
    # id 10 at 1.2 s for both; id 11 at 1.3 s (0.099 < 0.0991 at 1.2 s)
    # for q 0.99, at 1.1 s (0.06 >= 0.055) for q 0.5
    assert rise_time.surface_heights(np.array(BED), np.ones(10, bool), [0.99, 0.5]) == \
        pytest.approx([0.0991, 0.055], abs=1e-9)
    ids, times, t0 = rise_time.rise_times(rising, 1, [0.99, 0.5])
    assert ids.tolist() == [10, 11] and t0 == 1.0
    assert times == pytest.approx(np.array([[0.2, 0.2], [0.3, 0.1]]), abs=1e-9)
    with pytest.raises(ValueError, match="each must be in"):
        rise_time.rise_times(rising, 1, [1.5])


def test_rise_time_command_tables(rising):
    rise_time.main([rising, "-class", "1", "-fraction", "0.5", "0.99"])
    out = os.path.join(rising, rise_time.OUT)
    T = tables.read_dat(os.path.join(out, "riseTime.dat"))
    assert T["id"].tolist() == [10, 11]
    assert T["riseTime_q0.5"] == pytest.approx([0.2, 0.1], abs=1e-6)
    assert T["riseTime_q0.99"] == pytest.approx([0.2, 0.3], abs=1e-6)
    order = tables.read_dat(os.path.join(out, "riseOrder.dat"))
    assert order["riseTime_q0.5"] == pytest.approx([0.1, 0.2], abs=1e-6)


def field_file(path, kind, values):
    """An ASCII OpenFOAM field of the cells' values (scalars or vectors)."""
    body = "\n".join("(%g %g %g)" % tuple(v) if kind == "vector" else "%g" % v for v in values)
    with open(path, "w") as f:
        f.write("FoamFile { format ascii; class vol%sField; }\ninternalField nonuniform "
                "List<%s> %d\n(\n%s\n)\n;\n" % (kind.capitalize(), kind, len(values), body))


def test_bed_statistics_by_hand(tmp_path):
    # Two columns of four rows of unit cells (centres at 0.5 ... 3.5); row
    # voidages 0.4, (0.9 + 0.4)/2, (0.75 + 0.45)/2, 1: the bed ends below
    # row 3 (the first row at or above 0.7 after the last below it), so its
    # surface is half-way between rows 2 and 3, 3.0; the bubble (> 0.8) is
    # one cell of the bed's six, 1/6 (0.75 is emulsion); the emulsion's mean
    # (0.4 x 3 + 0.75 + 0.45)/5 = 0.48
    case = tmp_path / "column"
    (case / "system").mkdir(parents=True)
    (case / "system" / "controlDict").write_text("application dpmFoam2D;\n")
    for t in ("0", "0.1"):
        (case / t).mkdir()
    centres = [(x, y, 0.5) for y in (0.5, 1.5, 2.5, 3.5) for x in (0.5, 1.5)]
    field_file(case / "0" / "C", "vector", centres)
    field_file(case / "0" / "V", "scalar", [1.0] * 8)
    field_file(case / "0.1" / "voidage", "scalar", [0.4, 0.4, 0.9, 0.4, 0.75, 0.45, 1, 1])
    particle_file(str(case), 0.1, [0.5, 1.0, 2.5], [0, 0, 1])
    bed, parts, out = bed_statistics.write_bed_statistics(str(case))
    assert len(bed) == 1 and bed[0][0] == pytest.approx(0.1)
    assert bed[0][1:] == pytest.approx((3.0, 1 / 6, 0.48))
    T = tables.read_dat(os.path.join(out, "bed.dat"))
    assert T["bedHeight"] == pytest.approx([3.0])
    # particles at rest: rms speed 0, all still, the voidage they saw
    P = tables.read_dat(os.path.join(out, "particles.dat"))
    assert P["speedRmsSmall"] == pytest.approx([0.0]) and P["stillLarge"] == pytest.approx([1.0])
    assert P["voidageSmall"] == pytest.approx([0.45])
    with pytest.raises(bed_statistics.BedStatisticsError, match="not a dpmFoam2D case"):
        bed_statistics.write_bed_statistics(str(tmp_path))
