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
  3. a slower gas rises slower: t_r(1) at 1.83 m/s > at 2.134 m/s (177.46 g);
  and on the held-out conditions, the two trends the experiment shows there:
  4. small intruders rise slower: t_r(1) of two small > of two large
     (2.134 m/s, 177.46 g);
  5. a slower gas rises slower with four intruders: t_r(1) at 1.83 m/s >
     at 2.134 m/s (177.46 g).

A trend holds when the difference's 95 % interval (Welch) lies above 0.
The surface is the height below which 99 % of the glass centres lie; 95 %
and 99.9 % bracket it (their means are printed).

An intruder that has not risen by a seed's end time is censored: its rise
time is only known to exceed the end time. Where a condition has censored
seeds, the mean is given as a lower bound (the censored taken at their end
time, marked >=); criterion 1 then fails if even that bound's interval lies
above the experiment's and is undecided otherwise. A trend holds if it holds
with the censored at their end times and the condition expected to be
faster has none (a bound on the slower one only understates the
difference); it is undecided when it would hold but the faster condition
has censored seeds, or would not hold and either has.

  compare.py <run dir> [-reference <dir>] [-figure <png>] [-perSeed]

-figure draws each condition's rise times, the seeds' beside the
experiment's repeats, with the means and their intervals. -perSeed also
prints each seed's rise times (surface at 99 %; >= a censored one, at its
end time): the record a results page keeps.
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
TRENDS = (("heavier bed rises slower", "U183_M227_1L", "U183_M177_1L"),
          ("slower gas rises slower", "U183_M177_1L", "U214_M177_4L"),
          ("small intruders rise slower", "U214_M177_2S", "U214_M177_2L"),
          ("slower gas rises slower, four intruders", "U183_M177_4L", "U214_M177_4L"))


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


def end_time(case):
    """The run's end time: its controlDict's endTime (s)."""
    with open(os.path.join(case, "system", "controlDict")) as f:
        return float(re.search(r"^endTime\s+([^;\s]+)", f.read(), re.M).group(1))


def seed_times(case):
    """A finished seed's [k, fraction] rise times, the censored at the end
    time, and which are censored; None while it runs."""
    table = os.path.join(case, "postProcessing", "riseTime", "0", "riseOrder.dat")
    if not os.path.isfile(table):
        return None
    t = np.loadtxt(table, ndmin=2)
    t = t[:, 1:] if t.shape[1] == len(FRACTIONS) + 1 else t
    return np.where(np.isnan(t), end_time(case), t), np.isnan(t)


def seeds(run, condition):
    """The condition's seed directories, in the order of their numbers."""
    return sorted(glob.glob(os.path.join(run, condition + "_seed*")),
                  key=lambda p: int(re.search(r"_seed(\d+)$", p).group(1)))


def simulated(run, condition):
    """([seed, k, fraction] rise times of the finished seeds, with the
    censored at their end time; [seed, k, fraction] censored or not)."""
    found = [t for t in map(seed_times, seeds(run, condition)) if t is not None]
    return (np.array([t for t, _ in found]),
            np.array([c for _, c in found], dtype=bool))


def welch_above_zero(a, b):
    """Is mean(a) - mean(b) > 0 with 95 % confidence (Welch's interval)?"""
    a, b = np.asarray(a, float), np.asarray(b, float)
    if len(a) < 2 or len(b) < 2:
        return None, np.nan, np.nan
    va, vb = a.var(ddof=1) / len(a), b.var(ddof=1) / len(b)
    if va + vb == 0:            # no spread (every seed censored at one end time)
        return bool(a.mean() > b.mean()), a.mean() - b.mean(), 0.0
    dof = (va + vb)**2 / (va**2 / (len(a) - 1) + vb**2 / (len(b) - 1))
    d, h = a.mean() - b.mean(), stats.t.ppf(0.975, dof) * np.sqrt(va + vb)
    return bool(d - h > 0), d, h      # a bool, not numpy's: the verdicts test `is False`


def print_per_seed(run, conditions):
    """Each seed's t_r(k), s, at the criteria's surface."""
    print()
    print("| condition | seed | t_r(1), t_r(2) ..., s |")
    print("| --- | --- | --- |")
    for c in conditions:
        for case in seeds(run, c):
            found = seed_times(case)
            if found is not None:
                t, cens = found
                print("| %s | %s | %s |" % (c, case.rsplit("_seed", 1)[1], ", ".join(
                    "%s%.2f" % (">=" if cens[k, SURFACE] else "", t[k, SURFACE])
                    for k in range(len(t)))))


def draw(drawn, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(drawn), figsize=(3.2 * len(drawn), 3.2), squeeze=False)
    for ax, (c, sim, cens, exp) in zip(axes[0], drawn):
        for k in range(exp.shape[1]):
            for x, data, colour, label in ((k - 0.15, exp[:, k], "0.4", "experiment"),
                                           (k + 0.15, sim[:, k], "C0", "simulated")):
                ax.plot(np.full(len(data), x), data, "o", ms=3, color=colour, alpha=0.6,
                        label=label if k == 0 else None)
                m, h = interval(data)
                ax.errorbar(x + 0.1, m, yerr=h if np.isfinite(h) else None, fmt="D", ms=4, lw=1.5,
                            color=colour, capsize=3)
            if cens[:, k].any():        # not risen by the end time: at it, open
                ax.plot(np.full(cens[:, k].sum(), k + 0.15), sim[cens[:, k], k], "^",
                        ms=5, mfc="white", color="C3",
                        label="not risen by the end" if not cens[:, :k].any() else None)
        ax.set_xticks(range(exp.shape[1]))
        ax.set_xticklabels(["%d" % (k + 1) for k in range(exp.shape[1])])
        ax.set_xlabel("intruder (order of emergence)")
        ax.set_title(c, fontsize=9)
    axes[0][0].set_ylabel("rise time, s")
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print("wrote %s" % path)


def main(argv):
    if not argv or argv[0].startswith("-"):
        sys.exit(__doc__)
    run = argv[0]
    reference = argv[argv.index("-reference") + 1] if "-reference" in argv else REFERENCE
    figure = argv[argv.index("-figure") + 1] if "-figure" in argv else None
    conditions = sorted({re.sub(r"_seed\d+$", "", os.path.basename(c))
                         for c in glob.glob(os.path.join(run, "U*_seed*"))})
    print("| condition | k | seeds | simulated t_r, s | experiment t_r, s | overlap |"
          " surface 95 % / 99.9 % | not risen |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    first = {}
    passed = []
    drawn = []
    for c in conditions:
        (sim, cens), exp = simulated(run, c), experiment(reference, c)
        if not len(sim):
            continue
        drawn.append((c, sim[:, :, SURFACE], cens[:, :, SURFACE], exp))
        first[c] = (sim[:, 0, SURFACE], exp[:, 0], cens[:, 0, SURFACE].any())
        for k in range(exp.shape[1]):
            m, h = interval(sim[:, k, SURFACE])
            me, he = interval(exp[:, k])
            n_cens = int(cens[:, k, SURFACE].sum())
            overlap = bool(abs(m - me) <= h + he) if np.isfinite(h) else None
            if n_cens and overlap is not None:
                overlap = False if m - h > me + he else None
            passed.append(overlap)
            bounds = ["%s%.2f" % (">=" if cens[:, k, j].any() else "", sim[:, k, j].mean())
                      for j in (0, 2)]
            print("| %s | %d | %d | %s%.2f +- %.2f | %.2f +- %.2f | %s | %s / %s | %d |"
                  % (c, k + 1, len(sim), ">=" if n_cens else "", m, h, me, he,
                     {True: "yes", False: "no", None: "-"}[overlap], bounds[0], bounds[1],
                     n_cens))
    print()
    for name, a, b in TRENDS:
        if a in first and b in first:
            for which, j in (("simulated", 0), ("experiment", 1)):
                ok, d, h = welch_above_zero(first[a][j], first[b][j])
                slower, faster = (first[a][2], first[b][2]) if which == "simulated" \
                    else (False, False)
                verdict = {True: "holds", False: "not shown", None: "too few"}[ok]
                if (ok is True and faster) or (ok is False and (slower or faster)):
                    ok, verdict = None, "undecided (censored seeds)"
                print("%s, %s: t_r(1) %s - %s = %.2f +- %.2f s: %s"
                      % (name, which, a, b, d, h, verdict))
                if which == "simulated":
                    passed.append(ok)
    if "-perSeed" in argv:
        print_per_seed(run, conditions)
    if figure and drawn:
        draw(drawn, figure)
    decided = [p for p in passed if p is not None]
    print("\ncriteria met: %d of %d decided (%d undecided)"
          % (sum(decided), len(decided), len(passed) - len(decided)))


if __name__ == "__main__":
    main(sys.argv[1:])
