# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""dpmfoam2d.statistics against numbers from outside the code: Student-t
quantiles of a printed table (NIST/SEMATECH e-Handbook of Statistical
Methods, 1.3.6.7.2, three decimals), intervals and Welch-Satterthwaite
degrees of freedom worked by hand, and spectra of sines whose frequency and
power are known in closed form."""

import math

import numpy as np
import pytest

from dpmfoam2d import statistics as st
from dpmfoam2d.study import ensemble

# t(1 - alpha/2; dof) from the printed table: the table's 3 decimals
T_TABLE = [(0.95, 1, 12.706), (0.95, 2, 4.303), (0.95, 4, 2.776), (0.95, 10, 2.228),
           (0.90, 14, 1.761), (0.99, 5, 4.032)]


@pytest.mark.parametrize("level, dof, t", T_TABLE)
def test_t_quantile_is_the_printed_table(level, dof, t):
    assert st.t_quantile(level, dof) == pytest.approx(t, abs=5e-4)


def test_mean_interval_by_hand():
    # 1..5: mean 3, s = sqrt(2.5), half-width t(0.975; 4) s / sqrt(5)
    mean, half = st.mean_interval([1, 2, 3, 4, 5])
    assert mean == 3
    assert half == pytest.approx(2.776 * math.sqrt(2.5) / math.sqrt(5), abs=5e-4)
    assert math.isnan(st.mean_interval([7.0])[1])
    assert all(math.isnan(v) for v in st.mean_interval([]))


def test_welch_by_hand():
    # 8 values of sd 0.5 against 8 of sd 1: se^2 = 0.25/8 + 1/8 = 0.15625,
    # dof = 0.15625^2 / ((0.25/8)^2/7 + (1/8)^2/7) = 175/17
    a = 8.2 + 0.5 * np.array([-1, 1] * 4) * math.sqrt(7 / 8)
    b = 8.0 + 1.0 * np.array([-1, 1] * 4) * math.sqrt(7 / 8)
    d = st.welch_difference(a, b)
    assert d.difference == pytest.approx(0.2, abs=1e-12)
    assert d.standard_error == pytest.approx(math.sqrt(0.15625), rel=1e-12)
    assert d.dof == pytest.approx(175 / 17, rel=1e-12)
    assert st.satterthwaite_dof([0.25 / 8, 1 / 8], [7, 7]) == pytest.approx(175 / 17, rel=1e-12)
    # equal sizes and spreads: the dof is the pooled test's, 2n - 2
    assert st.welch_dof(1.0, 3, 1.0, 3) == pytest.approx(4, rel=1e-12)


def test_ensemble_difference_uses_welch():
    # [1 2 3] - [4 5 6]: -3, se sqrt(2/3), dof 4: half-width t(0.975; 4) se
    diff, half, na, nb = ensemble.difference_ci([1, 2, 3], [4, 5, 6])
    assert (diff, na, nb) == (-3, 3, 3)
    assert half == pytest.approx(2.776 * math.sqrt(2 / 3), abs=5e-4)
    assert ensemble.sign_of(diff, half) == "-"
    mean, half, n = ensemble.mean_ci([0.5, 0.7, float("nan")])
    assert (mean, n) == (pytest.approx(0.6), 2)
    assert half == pytest.approx(12.706 * 0.1, abs=5e-4)    # s = 0.1 sqrt(2), n = 2


def test_tost_verdicts():
    # difference 0.2, se sqrt(0.15625), dof 175/17: the 90 % interval is
    # 0.2 +- 1.8 x 0.395 (t(0.95; 10.3) between the table's 1.812 and 1.796)
    d = st.welch_difference_from_moments(8.2, 0.5, 8, 8.0, 1.0, 8)
    low, high = d.interval(0.90)
    assert low == pytest.approx(0.2 - 1.80 * 0.3953, abs=0.01)
    assert high == pytest.approx(0.2 + 1.80 * 0.3953, abs=0.01)
    assert st.tost_difference(d, 1.0).outcome == st.EQUIVALENT
    assert st.tost_difference(d, 0.5).outcome == st.UNDECIDED
    far = st.welch_difference_from_moments(11.0, 0.5, 8, 8.0, 1.0, 8)
    assert st.tost_difference(far, 1.0).outcome == st.NOT_EQUIVALENT


def test_validation_uncertainty():
    assert st.validation_uncertainty(3.0, 4.0) == (5.0, ["u_num"])


def sine(freq, amplitude=1.0, rate=100.0, seconds=8.0):
    t = np.arange(0, seconds, 1 / rate)
    return amplitude * np.sin(2 * np.pi * freq * t)


def test_dominant_frequency_of_sines():
    # 2.5 Hz over 8 s lies on the grids of both: 1/8 Hz (the whole record)
    # and 1/2 Hz (2-s segments)
    assert st.dominant_frequency(sine(2.5), 100.0) == (pytest.approx(2.5), 0.125)
    assert st.dominant_frequency(sine(2.5), 100.0, segment=2.0) == (pytest.approx(2.5), 0.5)
    # off the grid (2.25 and 2.375 Hz the nearest bins): zero-padding to
    # 0.01 Hz places it within a step; the resolution stays 1/8 Hz
    f, resolution = st.dominant_frequency(sine(2.33), 100.0, step=0.01)
    assert f == pytest.approx(2.33, abs=0.01) and resolution == 0.125
    # a stronger wave below the band is not the peak
    two = sine(0.5, 3.0) + sine(3.0)
    assert st.dominant_frequency(two, 100.0)[0] == pytest.approx(0.5)
    assert st.dominant_frequency(two, 100.0, lowest=1.0)[0] == pytest.approx(3.0)
    # too short a segment names no peak
    assert all(math.isnan(v) for v in st.dominant_frequency(sine(2.5)[:7], 100.0))


def test_spectrum_holds_the_power_of_a_sine():
    # a sine of amplitude A carries the power A^2/2 (Parseval); the density
    # integrates to it (Hann's leakage stays within the band summed)
    for segment in (None, 2.0):
        f, psd = st.spectrum(sine(2.5, 2.0), 100.0, segment=segment)
        assert psd.sum() * (f[1] - f[0]) == pytest.approx(2.0 ** 2 / 2, rel=0.02)
