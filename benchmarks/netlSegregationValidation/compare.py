#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The rise times of NETL's segregating bed (LaMarche et al. 2022) against
the experiment's: for each condition, the mean over the seeds of the k-th
intruder's rise time with its 95 % t-interval, beside the experiment's mean
and interval over its repeats (its files measurements/<condition>.txt, in
the folder REFERENCE), and the verdicts of the criteria fixed before the
runs (README.md):

  1. each mean's interval overlaps the experiment's (k = 1 .. intruders);
  2. a heavier bed rises slower: t_r(1) at 227.47 g > at 177.46 g (1.83 m/s);
  3. a slower gas rises slower: t_r(1) at 1.83 m/s > at 2.134 m/s (177.46 g).

A trend holds when the difference's 95 % interval (Welch) lies above 0.
The surface is the height below which 99 % of the glass centres lie; 95 %
and 99.9 % bracket it (their means are printed).

  compare.py <run dir> [-reference <dir>]
"""

import glob
import os
import re
import sys

import numpy as np
from scipy import stats

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(HERE, "..", "..", "..", "shared", "reference",
                         "netlSegregation2022", "measurements")
FRACTIONS = (0.95, 0.99, 0.999)     # the columns of riseOrder.dat
SURFACE = 1                          # 0.99: the criteria's


def interval(x):
    """Mean and half-width of its 95 % t-interval (nan for one value)."""
    x = np.asarray(x, dtype=float)
    n = len(x)
    if n < 2:
        return (x.mean() if n else np.nan), np.nan
    return x.mean(), stats.t.ppf(0.975, n - 1) * x.std(ddof=1) / np.sqrt(n)


def experiment(reference, condition):
    path = os.path.join(reference, condition + ".txt")
    return np.loadtxt(path, ndmin=2)


def simulated(run, condition):
    """[seed, k, fraction] rise times of the finished seeds."""
    rows = []
    for case in sorted(glob.glob(os.path.join(run, condition + "_seed*"))):
        table = os.path.join(case, "postProcessing", "riseTime", "0", "riseOrder.dat")
        if os.path.isfile(table):
            t = np.loadtxt(table, ndmin=2)
            rows.append(t[:, 1:] if t.shape[1] == len(FRACTIONS) + 1 else t)
    return np.array(rows)


def welch_above_zero(a, b):
    """Is mean(a) - mean(b) > 0 with 95 % confidence (Welch's interval)?"""
    a, b = np.asarray(a, float), np.asarray(b, float)
    if len(a) < 2 or len(b) < 2:
        return None, np.nan, np.nan
    va, vb = a.var(ddof=1) / len(a), b.var(ddof=1) / len(b)
    dof = (va + vb)**2 / (va**2 / (len(a) - 1) + vb**2 / (len(b) - 1))
    d, h = a.mean() - b.mean(), stats.t.ppf(0.975, dof) * np.sqrt(va + vb)
    return d - h > 0, d, h


def main(argv):
    if not argv or argv[0].startswith("-"):
        sys.exit(__doc__)
    run = argv[0]
    reference = argv[argv.index("-reference") + 1] if "-reference" in argv else REFERENCE
    conditions = sorted({re.sub(r"_seed\d+$", "", os.path.basename(c))
                         for c in glob.glob(os.path.join(run, "U*_seed*"))})
    print("| condition | k | seeds | simulated t_r, s | experiment t_r, s | overlap |"
          " surface 95 % / 99.9 % |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    first = {}
    passed = []
    for c in conditions:
        sim, exp = simulated(run, c), experiment(reference, c)
        if not len(sim):
            continue
        first[c] = (sim[:, 0, SURFACE], exp[:, 0])
        for k in range(exp.shape[1]):
            m, h = interval(sim[:, k, SURFACE])
            me, he = interval(exp[:, k])
            overlap = bool(abs(m - me) <= h + he) if np.isfinite(h) else None
            passed.append(overlap)
            lo, hi = np.nanmean(sim[:, k, 0]), np.nanmean(sim[:, k, 2])
            print("| %s | %d | %d | %.2f +- %.2f | %.2f +- %.2f | %s | %.2f / %.2f |"
                  % (c, k + 1, len(sim), m, h, me, he,
                     {True: "yes", False: "no", None: "-"}[overlap], lo, hi))
    print()
    for name, a, b in (("heavier bed rises slower", "U183_M227_1L", "U183_M177_1L"),
                       ("slower gas rises slower", "U183_M177_1L", "U214_M177_4L")):
        if a in first and b in first:
            for which, j in (("simulated", 0), ("experiment", 1)):
                ok, d, h = welch_above_zero(first[a][j], first[b][j])
                print("%s, %s: t_r(1) %s - %s = %.2f +- %.2f s: %s"
                      % (name, which, a, b, d, h,
                         {True: "holds", False: "not shown", None: "too few"}[ok]))
                if which == "simulated":
                    passed.append(ok)
    decided = [p for p in passed if p is not None]
    print("\ncriteria met: %d of %d decided (%d undecided)"
          % (sum(decided), len(decided), len(passed) - len(decided)))


if __name__ == "__main__":
    main(sys.argv[1:])
