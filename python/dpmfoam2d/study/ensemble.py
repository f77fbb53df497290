# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Ensemble statistics over random packings (seeds) for dpmStudy.

A fluidized bed is chaotic: one run is one sample. The cases of a study that
differ only in their seed form an ensemble; a quantity is reported as the
ensemble mean with a two-sided Student-t confidence interval, and two
ensembles are compared through the difference of their means with Welch's
interval (unequal variances, Welch-Satterthwaite degrees of freedom). A
trend is called only where the interval of the difference excludes zero.
The intervals are those of dpmfoam2d.statistics.
"""

import math

import numpy as np

from .. import statistics as st

LEVEL = 0.95        # confidence level of every interval


def finite(values):
    v = np.asarray(values, dtype=float)
    return v[np.isfinite(v)]


def mean_ci(values, level=LEVEL):
    """(mean, half-width of the interval, n) over the finite values; the
    half-width is nan for fewer than two values (no spread measured)."""
    v = finite(values)
    mean, half = st.mean_interval(v, level)
    return mean, half, len(v)


def difference_ci(a, b, level=LEVEL):
    """(mean(a) - mean(b), half-width of Welch's interval, na, nb). The
    half-width is nan unless both ensembles have two or more values."""
    d = st.welch_difference(finite(a), finite(b))
    return d.difference, d.half_width(level), d.n_a, d.n_b


def sign_of(diff, half):
    """'+' or '-' where the interval excludes zero, 'none' where it holds
    zero, '+?' / '-?' for one sample (a sign without an interval)."""
    if not math.isfinite(diff):
        return "n/a"
    if diff == 0:
        return "none"
    if not math.isfinite(half):
        return "+?" if diff > 0 else "-?"
    if abs(diff) <= half:
        return "none"
    return "+" if diff > 0 else "-"


def band(curves, level=LEVEL):
    """Mean and interval half-width of several curves y_i(t) on a common
    grid: the times of the first curve within the range all curves cover
    (others linearly interpolated). Returns (t, mean, half) arrays; half
    is nan for one curve."""
    curves = [(np.asarray(t, float), np.asarray(y, float)) for t, y in curves if len(t)]
    if not curves:
        return np.array([]), np.array([]), np.array([])
    t0 = max(t[0] for t, _ in curves)
    t1 = min(t[-1] for t, _ in curves)
    grid = curves[0][0]
    grid = grid[(grid >= t0 - 1e-12) & (grid <= t1 + 1e-12)]
    Y = np.array([np.interp(grid, t, y) for t, y in curves])
    n = len(curves)
    mean = Y.mean(axis=0)
    if n < 2:
        return grid, mean, np.full_like(mean, np.nan)
    half = st.t_quantile(level, n - 1) * Y.std(axis=0, ddof=1) / math.sqrt(n)
    return grid, mean, half


def fmt(mean, half, digits=3):
    """'0.412 +- 0.031' (or the mean alone without an interval)."""
    if not math.isfinite(mean):
        return "-"
    if not math.isfinite(half):
        return "%.*f" % (digits, mean)
    return "%.*f +- %.*f" % (digits, mean, digits, half)


def shift_ci(variant, baseline, level=LEVEL):
    """How far a variant moves a contrast from the baseline's.

    variant, baseline: the values over seeds of the contrast's cases, [a]
    (the contrast is a's mean) or [a, b] (a - b), in the same order for
    both. Returns (shift, half-width, borrowed): shift = the variant's
    contrast minus the baseline's, half-width of its interval by
    Welch-Satterthwaite over the independent variance estimates. A variant
    case with one seed has no spread of its own: it takes the baseline
    case's sample variance (same packings, assumed the same scatter;
    borrowed = True), which makes the interval a prediction interval for
    one run. nan half-width where a baseline case has fewer than two seeds.
    """
    shift, terms, borrowed = 0.0, [], False
    for sign, v, b in zip((1.0, -1.0), variant, baseline):
        vv, bb = finite(v), finite(b)
        if len(vv) == 0 or len(bb) == 0:
            return math.nan, math.nan, False
        shift += sign * float(vv.mean() - bb.mean())
        if len(bb) < 2:
            return shift, math.nan, False
        base = [bb.var(ddof=1), len(bb) - 1, 1.0 / len(bb)]    # s^2, dof, weight
        if len(vv) >= 2:
            terms.append([vv.var(ddof=1), len(vv) - 1, 1.0 / len(vv)])
        else:
            base[2] += 1.0 / len(vv)
            borrowed = True
        terms.append(base)
    var = sum(s2 * c for s2, _, c in terms)
    if var == 0:
        return shift, 0.0, borrowed
    dof = st.satterthwaite_dof([s2 * c for s2, _, c in terms], [d for _, d, _ in terms])
    return shift, float(st.t_quantile(level, dof) * math.sqrt(var)), borrowed
