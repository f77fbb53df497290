#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""dpmfoam2d.statistics against answers computed here, independently:
Welch's standard error and degrees of freedom by their formulas, the t
quantiles and tails from scipy.stats.t, the one-sided p-values also from
scipy.stats.ttest_ind (its own Welch test) on shifted samples; TOST's
verdicts where they are known (equal means: equivalent; three margins
apart: not equivalent); that fewer seeds never make equivalence easier; and
V&V 20's u_val from stated terms. Run by netlCompare.sh; exits 1 on a
failure, naming it."""

import math
import sys

import numpy as np
from scipy import stats

from dpmfoam2d import statistics as st

failures = []


def check(what, good):
    print("%s: %s" % (what, "ok" if good else "WRONG"))
    if not good:
        failures.append(what)


def close(a, b, tol=1e-9):
    return math.isfinite(a) and math.isfinite(b) and abs(a - b) <= tol * max(1.0, abs(b))


def sample(mean, sd, n):
    """n values of exactly this mean and standard deviation (ddof 1)."""
    z = np.linspace(-1.0, 1.0, n) if n > 1 else np.zeros(1)
    if n > 1:
        z = (z - z.mean()) / z.std(ddof=1)
    return mean + sd * z


# (d) Welch and TOST by hand. Stated numbers: a has 8 values of sd 0.5, b 8
# of sd 1, means 0.2 apart, margin 1. By hand: s_a^2/n_a = 0.03125,
# s_b^2/n_b = 0.125, se = sqrt(0.15625) = 0.395285; Welch-Satterthwaite
# dof = 0.15625^2 / ((0.03125^2 + 0.125^2) / 7) = 175/17 = 10.294118.
a, b, margin = sample(8.2, 0.5, 8), sample(8.0, 1.0, 8), 1.0
se, dof = math.sqrt(0.15625), 175.0 / 17.0
d = st.welch_difference(a, b)
check("Welch: difference 0.2", close(d.difference, 0.2))
check("Welch: standard error sqrt(0.15625)", close(d.standard_error, se))
check("Welch-Satterthwaite dof 175/17", close(d.dof, dof))
check("Welch-Satterthwaite dof from moments",
      close(st.welch_dof(0.25, 8, 1.0, 8), dof))
t90 = stats.t.ppf(0.95, dof)
test = st.tost(a, b, margin)
check("TOST: 90 %% interval 0.2 +- t(0.95, %.6f) se = %.6f to %.6f (got %.6f to %.6f)"
      % (dof, 0.2 - t90 * se, 0.2 + t90 * se, test.low, test.high),
      close(test.low, 0.2 - t90 * se) and close(test.high, 0.2 + t90 * se))
p_lower = stats.t.sf((0.2 + margin) / se, dof)
p_upper = stats.t.cdf((0.2 - margin) / se, dof)
check("TOST: p_lower %.6g, p_upper %.6g by hand (got %.6g, %.6g)"
      % (p_lower, p_upper, test.p_lower, test.p_upper),
      close(test.p_lower, p_lower) and close(test.p_upper, p_upper)
      and close(test.p, max(p_lower, p_upper)))
# scipy's own Welch test on the samples shifted by the margin
ref_lower = stats.ttest_ind(a + margin, b, equal_var=False, alternative="greater").pvalue
ref_upper = stats.ttest_ind(a - margin, b, equal_var=False, alternative="less").pvalue
check("TOST: p-values as scipy.stats.ttest_ind's Welch tests (%.6g, %.6g)"
      % (ref_lower, ref_upper),
      close(test.p_lower, ref_lower, 1e-7) and close(test.p_upper, ref_upper, 1e-7))
check("TOST: p < 0.05 exactly when the 90 % interval lies inside the margin",
      (test.p < 0.05) == (-margin < test.low and test.high < margin)
      and test.outcome == st.EQUIVALENT)
# from published-style moments: the same numbers
dm = st.welch_difference_from_moments(8.2, 0.5, 8, 8.0, 1.0, 8)
check("Welch from moments: the samples' difference, se and dof",
      close(dm.difference, 0.2) and close(dm.standard_error, se) and close(dm.dof, dof))
one = st.one_sided(a, b)
check("one-sided Welch: p as ttest_ind's 'greater' (%.6g)"
      % stats.ttest_ind(a, b, equal_var=False, alternative="greater").pvalue,
      close(one.p_greater, stats.ttest_ind(a, b, equal_var=False,
                                           alternative="greater").pvalue, 1e-7)
      and one.outcome == st.UNDECIDED)
one = st.one_sided(b + 2, a)
check("one-sided Welch: 1.8 s later on these spreads is shown", one.outcome == "greater")
one = st.one_sided(a, b + 2)
check("one-sided Welch: 1.8 s earlier shows the reverse", one.outcome == "less")
interval = st.mean_interval(b)
check("mean_interval: t(0.975, 7) sd / sqrt(8)",
      close(interval[0], 8.0) and close(interval[1], stats.t.ppf(0.975, 7) / math.sqrt(8)))

# (a) equal means, 8 and 8, small spread against the margin: equivalent
test = st.tost(sample(8.0, 0.5, 8), sample(8.0, 1.0, 8), 1.0)
check("equal means, 8 seeds of sd 0.5, 8 repeats of sd 1, margin 1: equivalent "
      "(90 %% interval %.3f to %.3f)" % (test.low, test.high), test.outcome == st.EQUIVALENT)
# (b) three margins apart: not equivalent
test = st.tost(sample(11.0, 0.5, 8), sample(8.0, 1.0, 8), 1.0)
check("means 3 margins apart: not equivalent (90 %% interval %.3f to %.3f)"
      % (test.low, test.high), test.outcome == st.NOT_EQUIVALENT)
test = st.tost(sample(5.0, 0.5, 8), sample(8.0, 1.0, 8), 1.0)
check("means 3 margins apart below: not equivalent", test.outcome == st.NOT_EQUIVALENT)

# (c) 0.3 s apart, repeats: 12 of sd 1 (margin 1), seeds of sd 0.5:
# equivalent on 10 seeds, undecided on 3 (not "more equivalent")
exp = sample(8.0, 1.0, 12)
ten, three = st.tost(sample(8.3, 0.5, 10), exp, 1.0), st.tost(sample(8.3, 0.5, 3), exp, 1.0)
check("0.3 s apart: equivalent on 10 seeds (%.3f to %.3f), undecided on 3 (%.3f to %.3f)"
      % (ten.low, ten.high, three.low, three.high),
      ten.outcome == st.EQUIVALENT and three.outcome == st.UNDECIDED and three.p > ten.p)
# ... and for any difference and spread, fewer seeds never make either shown
# verdict easier: the interval only widens as n falls
monotone = True
for diff in np.linspace(0.0, 3.0, 13):
    for sd in (0.3, 0.8, 1.0, 2.0):
        previous = None
        for n in range(2, 41):
            t = st.tost_difference(st.welch_difference_from_moments(8.0 + diff, sd, n,
                                                                    8.0, 1.0, 12), 1.0)
            width = t.high - t.low
            if previous is not None:
                p_width, p_outcome = previous
                # n - 1 seeds: the interval no narrower; a shown verdict there is shown here too
                monotone &= width <= p_width + 1e-12
                monotone &= p_outcome == st.UNDECIDED or t.outcome == p_outcome
            previous = (width, t.outcome)
check("fewer seeds never narrow the interval nor turn undecided into a shown verdict "
      "(differences 0-3, seed sd 0.3-2, n 2-40)", monotone)
# the old rule's flaw, for the record: two 95 % intervals overlap on 2 seeds
# at a difference TOST cannot call equivalent on any number of seeds
few = st.tost_difference(st.welch_difference_from_moments(15.9, 0.8, 2, 8.0, 0.8, 12), 0.8)
check("7.9 s apart on 2 seeds: not equivalent or undecided, never equivalent",
      few.outcome != st.EQUIVALENT)

# no test without a spread on a side, nor without a margin
check("one seed: no test", st.tost([8.0], exp, 1.0).outcome is None)
check("margin 0 or nan: no test", st.tost(sample(8, 1, 8), exp, 0.0).outcome is None
      and st.tost(sample(8, 1, 8), exp, math.nan).outcome is None)

# (e) V&V 20: u_val = sqrt(0.3^2 + 0.4^2 + 1.2^2) = 1.3
u, missing = st.validation_uncertainty(1.2, u_input=0.4, u_num=0.3)
check("V&V 20: u_val of u_num 0.3, u_input 0.4, u_D 1.2 is 1.3", close(u, 1.3) and not missing)
u, missing = st.validation_uncertainty(1.2, u_input=None, u_num=math.nan)
check("V&V 20: u_D alone, u_input and u_num named as not estimated",
      close(u, 1.2) and sorted(missing) == ["u_input", "u_num"])
u, missing = st.validation_uncertainty(0.5, u_input=1.2)
check("V&V 20: u_val of u_input 1.2, u_D 0.5 is 1.3, u_num not estimated",
      close(u, 1.3) and missing == ["u_num"])

if failures:
    print("FAILED: %s" % "; ".join(failures))
    sys.exit(1)
print("all statistics checks passed")
