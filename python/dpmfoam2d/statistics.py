# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The project's statistics: intervals of means and of their differences,
equivalence tests, and the spectrum of a record, all on scipy.

Comparing the mean of simulated seeds with the mean of measured repeats:
both are samples of a random quantity (a rise time, a bed height): the
simulation's over random packings, the experiment's over its repeats, with
different spreads and sizes. Everything here works on the difference of the
two means with Welch's standard error and the Welch-Satterthwaite degrees
of freedom (no equal variances assumed), the t quantiles from scipy.stats:

  t_quantile           the two-sided Student-t quantile of a level
  mean_interval        a sample's mean and its two-sided Student-t interval
  satterthwaite_dof    the degrees of freedom of a sum of variance estimates
  welch_dof            the Welch-Satterthwaite degrees of freedom
  welch_difference     mean(a) - mean(b), its standard error, dof, interval
  tost                 the two one-sided tests of equivalence (Schuirmann
                       1987) within a margin: equivalent, not equivalent or
                       undecided
  one_sided            the sign of a difference, a one-sided Welch test
  validation_uncertainty  ASME V&V 20's u_val from the terms that are known
  spectrum             Welch's power spectral density of a sampled record
  dominant_frequency   the frequency of its highest peak in a band

Each verdict is a test at a stated level whose bar rises as the samples
shrink: fewer values widen the interval of the difference, so they can only
move a verdict from equivalent or not equivalent towards undecided, never
the other way.

References: D.J. Schuirmann (1987), "A comparison of the two one-sided
tests procedure and the power approach for assessing the equivalence of
average bioavailability", J. Pharmacokinet. Biopharm. 15:657-680;
S. Wellek (2010), "Testing Statistical Hypotheses of Equivalence and
Noninferiority", 2nd ed., CRC Press; B.L. Welch (1947), Biometrika
34:28-35; F.E. Satterthwaite (1946), Biometrics Bulletin 2:110-114;
ASME V&V 20-2009, "Standard for Verification and Validation in
Computational Fluid Dynamics and Heat Transfer"; P.D. Welch (1967), "The
use of fast Fourier transform for the estimation of power spectra", IEEE
Trans. Audio Electroacoust. 15:70-73.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np
from scipy import signal, stats

EQUIVALENT = "equivalent"
NOT_EQUIVALENT = "not equivalent"
UNDECIDED = "undecided"


def _values(x: Sequence[float]) -> np.ndarray:
    return np.asarray(x, dtype=float).ravel()


def t_quantile(level: float, dof):
    """The quantile t of Student's distribution with dof degrees of freedom
    that a two-sided interval at `level` reaches: P(|T| <= t) = level
    (dof may be an array)."""
    return stats.t.ppf(0.5 + level / 2, dof)


def mean_interval(x: Sequence[float], level: float = 0.95) -> tuple[float, float]:
    """(mean, half-width of its two-sided Student-t interval at `level`)
    over the values x; the half-width is nan for fewer than two values and
    the mean nan for none."""
    x = _values(x)
    n = len(x)
    if n == 0:
        return math.nan, math.nan
    if n < 2:
        return float(x.mean()), math.nan
    return float(x.mean()), float(t_quantile(level, n - 1) * x.std(ddof=1) / math.sqrt(n))


def satterthwaite_dof(variances: Sequence[float], dofs: Sequence[float]) -> float:
    """The degrees of freedom of a sum of independent variance estimates
    v_i, each with d_i degrees of freedom (Satterthwaite 1946):

        (sum v_i)^2 / sum (v_i^2 / d_i)

    nan when the sum is 0 (no spread: nothing to estimate)."""
    v = _values(variances)
    total = float(v.sum())
    if total == 0:
        return math.nan
    return float(total ** 2 / np.sum(v ** 2 / _values(dofs)))


def welch_dof(var_a: float, n_a: int, var_b: float, n_b: int) -> float:
    """The Welch-Satterthwaite degrees of freedom of mean(a) - mean(b) from
    the samples' variances (ddof 1) and sizes:

        (s_a^2/n_a + s_b^2/n_b)^2 / ((s_a^2/n_a)^2/(n_a-1) + (s_b^2/n_b)^2/(n_b-1))

    min(n_a, n_b) - 1 <= dof <= n_a + n_b - 2. nan when both variances are
    0 (no spread: the difference is exact) or a sample has fewer than two
    values."""
    if n_a < 2 or n_b < 2:
        return math.nan
    return satterthwaite_dof([var_a / n_a, var_b / n_b], [n_a - 1, n_b - 1])


@dataclass(frozen=True)
class Difference:
    """mean(a) - mean(b) with Welch's standard error and degrees of freedom."""
    difference: float
    standard_error: float       # sqrt(s_a^2/n_a + s_b^2/n_b); 0 with no spread
    dof: float                  # Welch-Satterthwaite; nan when standard_error is 0
    n_a: int
    n_b: int

    def half_width(self, level: float) -> float:
        """Half-width of the two-sided interval at `level` (0 with no
        spread: the difference is exact; nan with fewer than two values on
        a side)."""
        if not math.isfinite(self.standard_error):
            return math.nan
        if self.standard_error == 0:
            return 0.0
        return float(t_quantile(level, self.dof) * self.standard_error)

    def interval(self, level: float) -> tuple[float, float]:
        """The two-sided interval at `level`, (low, high)."""
        h = self.half_width(level)
        return self.difference - h, self.difference + h


def welch_difference(a: Sequence[float], b: Sequence[float]) -> Difference:
    """mean(a) - mean(b), Welch's standard error and dof. Fewer than two
    values on a side: standard error and dof nan (no spread measured)."""
    a, b = _values(a), _values(b)
    if not len(a) or not len(b):
        return Difference(math.nan, math.nan, math.nan, len(a), len(b))
    d = float(a.mean() - b.mean())
    if len(a) < 2 or len(b) < 2:
        return Difference(d, math.nan, math.nan, len(a), len(b))
    va, vb = float(a.var(ddof=1)), float(b.var(ddof=1))
    return Difference(d, math.sqrt(va / len(a) + vb / len(b)),
                      welch_dof(va, len(a), vb, len(b)), len(a), len(b))


def welch_difference_from_moments(mean_a: float, sd_a: float, n_a: int,
                                  mean_b: float, sd_b: float, n_b: int) -> Difference:
    """welch_difference from each sample's mean, standard deviation (ddof 1)
    and size, as published tables give them."""
    if n_a < 2 or n_b < 2:
        return Difference(mean_a - mean_b, math.nan, math.nan, n_a, n_b)
    va, vb = sd_a ** 2, sd_b ** 2
    return Difference(mean_a - mean_b, math.sqrt(va / n_a + vb / n_b),
                      welch_dof(va, n_a, vb, n_b), n_a, n_b)


@dataclass(frozen=True)
class Tost:
    """The two one-sided tests of |true difference| < margin at level alpha.

    p_lower tests H0: difference <= -margin, p_upper H0: difference >=
    +margin; equivalence is shown when both are rejected, p = max of the
    two < alpha, which is the same as the (1 - 2 alpha) two-sided interval
    (90 % for alpha 5 %) lying inside (-margin, +margin). Non-equivalence
    is shown when that interval lies wholly outside the margin (at or
    beyond +margin, or at or below -margin): the one-sided test of H0:
    |difference| <= margin on the side the interval lies, at level alpha.
    Otherwise undecided."""
    difference: Difference
    margin: float
    alpha: float
    low: float                  # the (1 - 2 alpha) interval
    high: float
    p_lower: float
    p_upper: float
    outcome: Optional[str]      # EQUIVALENT, NOT_EQUIVALENT, UNDECIDED; None: no test

    @property
    def p(self) -> float:
        """The TOST p-value: max(p_lower, p_upper)."""
        return max(self.p_lower, self.p_upper)


def _outcome(low: float, high: float, margin: float) -> str:
    if -margin < low and high < margin:
        return EQUIVALENT
    if low >= margin or high <= -margin:
        return NOT_EQUIVALENT
    return UNDECIDED


def tost_difference(d: Difference, margin: float, alpha: float = 0.05) -> Tost:
    """TOST on a difference already computed (see Tost). No test (outcome
    None, p nan) when the standard error is unknown (fewer than two values
    on a side) or the margin is not a finite number > 0."""
    if not (math.isfinite(d.standard_error) and math.isfinite(margin) and margin > 0
            and math.isfinite(d.difference)):
        return Tost(d, margin, alpha, math.nan, math.nan, math.nan, math.nan, None)
    low, high = d.interval(1 - 2 * alpha)
    if d.standard_error == 0:       # no spread on either side: the difference is exact
        p_lower = 0.0 if d.difference > -margin else 1.0
        p_upper = 0.0 if d.difference < margin else 1.0
    else:
        p_lower = float(stats.t.sf((d.difference + margin) / d.standard_error, d.dof))
        p_upper = float(stats.t.cdf((d.difference - margin) / d.standard_error, d.dof))
    return Tost(d, margin, alpha, low, high, p_lower, p_upper, _outcome(low, high, margin))


def tost(a: Sequence[float], b: Sequence[float], margin: float, alpha: float = 0.05) -> Tost:
    """Is mean(a) within +-margin of mean(b)? TOST on Welch's difference
    at level alpha (see Tost)."""
    return tost_difference(welch_difference(a, b), margin, alpha)


@dataclass(frozen=True)
class OneSided:
    """Is the true difference > 0? One-sided Welch tests at level alpha."""
    difference: Difference
    alpha: float
    p_greater: float            # H0: difference <= 0
    p_less: float               # H0: difference >= 0
    outcome: Optional[str]      # "greater", "less", UNDECIDED; None: no test


def one_sided(a: Sequence[float], b: Sequence[float], alpha: float = 0.05) -> OneSided:
    """mean(a) > mean(b)? "greater" when H0: mean(a) <= mean(b) is
    rejected at alpha (Welch's one-sided t test), "less" when H0: mean(a)
    >= mean(b) is, undecided otherwise: the (1 - 2 alpha) interval of the
    difference above 0, below 0, or holding it. None with fewer than two
    values on a side."""
    d = welch_difference(a, b)
    if not math.isfinite(d.standard_error):
        return OneSided(d, alpha, math.nan, math.nan, None)
    if d.standard_error == 0:
        g = 0.0 if d.difference > 0 else 1.0
        s = 0.0 if d.difference < 0 else 1.0
    else:
        g = float(stats.t.sf(d.difference / d.standard_error, d.dof))
        s = float(stats.t.cdf(d.difference / d.standard_error, d.dof))
    outcome = "greater" if g < alpha else "less" if s < alpha else UNDECIDED
    return OneSided(d, alpha, g, s, outcome)


def validation_uncertainty(u_D: float, u_input: Optional[float] = None,
                           u_num: Optional[float] = None) -> tuple[float, list[str]]:
    """ASME V&V 20's validation uncertainty u_val = sqrt(u_num^2 +
    u_input^2 + u_D^2) from the terms that are known: a term None or nan is
    not estimated and left out. Returns (u_val, the names of the terms left
    out), u_val then a lower bound of the standard's."""
    terms = {"u_num": u_num, "u_input": u_input, "u_D": u_D}
    missing = [k for k, v in terms.items() if v is None or not math.isfinite(v)]
    for k, v in terms.items():
        if k not in missing and v < 0:
            raise ValueError("%s = %g: an uncertainty is >= 0" % (k, v))
    return (math.sqrt(sum(v ** 2 for k, v in terms.items() if k not in missing)), missing)


# One spectral estimator for every record the project analyses: Welch's
# averaged Hann periodograms (scipy.signal.welch with its default, periodic
# Hann window). A caller chooses the segment: short segments average out
# the noise of a long record, the whole record (the Hann periodogram, the
# one-segment case) keeps the resolution a short record has.
MIN_SEGMENT = 8         # samples: a shorter segment shows no peak worth naming


def spectrum(x: Sequence[float], rate: float, segment: Optional[float] = None,
             step: Optional[float] = None) -> tuple[np.ndarray, np.ndarray]:
    """Welch's power spectral density of the record x sampled at `rate`
    (Hz): Hann-windowed segments of `segment` s (default the whole record)
    overlapping by half, each less its mean, their periodograms averaged
    (density scaling: units of x^2/Hz). step (Hz): each segment zero-padded
    so that the frequencies lie step apart, a finer grid to place a peak on
    (the resolution stays 1/segment). Returns (frequencies, psd)."""
    x = _values(x)
    nperseg = len(x) if segment is None else min(len(x), int(round(segment * rate)))
    nfft = nperseg if step is None else max(nperseg, int(round(rate / step)))
    return signal.welch(x, fs=rate, window="hann", nperseg=nperseg,
                        noverlap=nperseg // 2, nfft=nfft, detrend="constant")


def dominant_frequency(x: Sequence[float], rate: float, segment: Optional[float] = None,
                       lowest: float = 0.0, step: Optional[float] = None
                       ) -> tuple[float, float]:
    """(frequency, resolution) of the highest peak of spectrum(x, rate,
    segment, step) at or above `lowest` Hz (never the mean, f = 0); the
    resolution is 1/segment, the width of a segment's bin. (nan, nan) for a
    segment of fewer than MIN_SEGMENT samples or an empty band."""
    x = _values(x)
    nperseg = len(x) if segment is None else min(len(x), int(round(segment * rate)))
    if nperseg < MIN_SEGMENT:
        return math.nan, math.nan
    f, psd = spectrum(x, rate, segment, step)
    band = (f > 0) & (f >= lowest - 1e-9)
    if not band.any():
        return math.nan, math.nan
    return float(f[band][np.argmax(psd[band])]), rate / nperseg
