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

import os
import re
import sys

import numpy as np
from scipy import stats

try:
    from dpmfoam2d.tables import read_dat
except ModuleNotFoundError as e:
    if not (e.name or "").startswith("dpmfoam2d"):
        raise
    sys.exit("compare.py: no Python package dpmfoam2d on PYTHONPATH: source the project's "
             "etc/bashrc first")

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


COLUMNS = ["rank"] + ["riseTime_q%g" % q for q in FRACTIONS]
RISE_TIME = "dpmRiseTime <seed> -class intruder -fraction %s, as Allrun does" \
    % " ".join("%g" % q for q in FRACTIONS)
SEED = re.compile(r"^(U.+)_seed(\d+)$")


def refuse(text):
    sys.exit("compare.py: " + text)


def experiment(reference, condition):
    """The experiment's rise times of a condition, [repeat, k]: its file's
    rows of equal length, each a time > 0 s."""
    path = os.path.join(reference, condition + ".txt")
    rows = []
    with open(path, errors="replace") as f:
        for n, line in enumerate(f, 1):
            words = line.split()
            if not words:
                continue
            try:
                row = [float(w) for w in words]
            except ValueError:
                refuse("%s line %d: '%s' is not a number" % (path, n, line.strip()))
            if not all(np.isfinite(v) and v > 0 for v in row):
                refuse("%s line %d: a rise time not > 0 s ('%s')" % (path, n, line.strip()))
            if rows and len(row) != len(rows[0]):
                refuse("%s line %d: %d rise times, line 1 has %d"
                       % (path, n, len(row), len(rows[0])))
            rows.append(row)
    if not rows:
        refuse("%s: no rows (one per repeat: its intruders' rise times)" % path)
    return np.array(rows)


def end_time(case):
    """The run's end time: its controlDict's endTime (s); a refusal naming
    the seed when it cannot be read, as its censored rise times need it."""
    path = os.path.join(case, "system", "controlDict")
    why = "no file %s" % path
    if os.path.isfile(path):
        with open(path, errors="replace") as f:
            found = re.findall(r"^endTime\s+([^;]*);", f.read(), re.M)
        why = "no endTime in %s" % path
        if found:       # the last, as OpenFOAM reads it
            try:
                t = float(found[-1])
                if np.isfinite(t) and t > 0:
                    return t
            except ValueError:
                pass
            why = "its endTime '%s' (%s) is not a time in s" % (found[-1].strip(), path)
    refuse("seed %s: an intruder not risen by the end (nan in riseOrder.dat), and the end "
           "time it stands for cannot be read: %s; give the seed a plain 'endTime <s>;' or "
           "leave it out of the run folder" % (case, why))


def seed_times(case, intruders):
    """A finished seed's [k, fraction] rise times, the censored at the end
    time, and which are censored; None while it runs. Its riseOrder.dat is
    dpmRiseTime's with FRACTIONS' columns and a row for each of the
    experiment's intruders (checked: refused naming the file otherwise)."""
    table = os.path.join(case, "postProcessing", "riseTime", "0", "riseOrder.dat")
    if not os.path.isfile(table):
        return None
    try:
        columns = read_dat(table)
    except ValueError as e:
        refuse("%s; write it with %s" % (e, RISE_TIME))
    if list(columns) != COLUMNS:
        refuse("%s: columns %s; %s expected: write it with %s"
               % (table, " ".join(columns), " ".join(COLUMNS), RISE_TIME))
    rank = columns["rank"]
    if len(rank) != intruders:
        refuse("%s: %d rows, one per intruder: the experiment's condition has %d intruders"
               % (table, len(rank), intruders))
    if not np.array_equal(rank, np.arange(1, intruders + 1)):
        refuse("%s: ranks %s, not 1 to %d" % (table, " ".join("%g" % r for r in rank), intruders))
    t = np.column_stack([columns[c] for c in COLUMNS[1:]])
    bad = ~np.isnan(t) & ~(np.isfinite(t) & (t >= 0))
    if bad.any():
        k, j = np.argwhere(bad)[0]
        refuse("%s: rank %d, %s: %g is not a rise time (>= 0 s, or nan where not risen)"
               % (table, k + 1, COLUMNS[1 + j], t[k, j]))
    censored = np.isnan(t)
    return np.where(censored, end_time(case) if censored.any() else np.nan, t), censored


def seeds(run, condition):
    """The condition's seed directories, in the order of their numbers."""
    found = [(int(m.group(2)), os.path.join(run, name)) for name, m in
             ((name, SEED.match(name)) for name in os.listdir(run))
             if m and m.group(1) == condition and os.path.isdir(os.path.join(run, name))]
    return [path for _, path in sorted(found)]


def simulated(run, condition, intruders):
    """([seed, k, fraction] rise times of the finished seeds, with the
    censored at their end time; [seed, k, fraction] censored or not)."""
    found = [t for t in (seed_times(case, intruders) for case in seeds(run, condition))
             if t is not None]
    return (np.array([t for t, _ in found]).reshape(-1, intruders, len(FRACTIONS)),
            np.array([c for _, c in found], dtype=bool).reshape(-1, intruders, len(FRACTIONS)))


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


def print_per_seed(run, conditions, intruders):
    """Each seed's t_r(k), s, at the criteria's surface."""
    print()
    print("| condition | seed | t_r(1), t_r(2) ..., s |")
    print("| --- | --- | --- |")
    for c in conditions:
        for case in seeds(run, c):
            found = seed_times(case, intruders[c])
            if found is not None:
                t, cens = found
                print("| %s | %s | %s |" % (c, case.rsplit("_seed", 1)[1], ", ".join(
                    "%s%.2f" % (">=" if cens[k, SURFACE] else "", t[k, SURFACE])
                    for k in range(len(t)))))


def draw(drawn, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from dpmfoam2d.files import save_figure
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
    save_figure(fig, path, dpi=110)     # renamed onto path: a link there is replaced
    print("wrote %s" % path)


def arguments(argv):
    """run, reference, figure, perSeed from the command line, checked."""
    if not argv or argv[0].startswith("-"):
        sys.exit(__doc__)
    run, reference, figure, per_seed = argv[0], REFERENCE, None, False
    i = 1
    while i < len(argv):
        if argv[i] in ("-reference", "-figure"):
            if i + 1 == len(argv):
                refuse("%s needs a value (%s)" % (argv[i], "the experiment's measurements folder"
                                                  if argv[i] == "-reference" else "a .png"))
            if argv[i] == "-reference":
                reference = argv[i + 1]
            else:
                figure = argv[i + 1]
            i += 2
        elif argv[i] == "-perSeed":
            per_seed, i = True, i + 1
        else:
            refuse("unknown argument '%s' (compare.py <run dir> [-reference <dir>] "
                   "[-figure <png>] [-perSeed])" % argv[i])
    if not os.path.isdir(run):
        refuse("no run folder %s" % run)
    if not os.path.isdir(reference):
        refuse("no reference folder %s (the experiment's measurements/: -reference <dir>, or "
               "the shared reference beside the repository, README.md)" % reference)
    if figure is not None:
        folder = os.path.dirname(figure) or "."
        if not os.path.isdir(folder):
            refuse("-figure %s: no folder %s" % (figure, folder))
        if os.path.isdir(figure) and not os.path.islink(figure):
            refuse("-figure %s is a folder; give a file name (.png)" % figure)
        import matplotlib
        matplotlib.use("Agg")
        from matplotlib.figure import Figure
        formats = Figure().canvas.get_supported_filetypes()
        if os.path.splitext(figure)[1].lstrip(".").lower() not in formats:
            refuse("-figure %s: a file name ending in .%s" % (figure, ", .".join(sorted(formats))))
    return run, reference, figure, per_seed


def main(argv):
    run, reference, figure, per_seed = arguments(argv)
    conditions = sorted({SEED.match(name).group(1) for name in os.listdir(run)
                         if SEED.match(name) and os.path.isdir(os.path.join(run, name))})
    if not conditions:
        refuse("no seeds <condition>_seed<k> in %s" % run)
    known = sorted(f[:-len(".txt")] for f in os.listdir(reference) if f.endswith(".txt"))
    for c in conditions:
        if c not in known:
            refuse("%s: condition %s is not one of the experiment's (no %s.txt in %s; its "
                   "conditions: %s)" % (seeds(run, c)[0], c, c, reference,
                                        ", ".join(known) or "none"))
    # Everything read, and checked, before the table starts
    exps = {c: experiment(reference, c) for c in conditions}
    intruders = {c: exps[c].shape[1] for c in conditions}
    sims = {c: simulated(run, c, intruders[c]) for c in conditions}
    print("| condition | k | seeds | simulated t_r, s | experiment t_r, s | overlap |"
          " surface 95 % / 99.9 % | not risen |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    first = {}
    passed = []
    drawn = []
    for c in conditions:
        (sim, cens), exp = sims[c], exps[c]
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
    if per_seed:
        print_per_seed(run, conditions, intruders)
    if figure and drawn:
        draw(drawn, figure)
    elif figure:
        print("no figure %s: no seed has finished (riseOrder.dat)" % figure)
    decided = [p for p in passed if p is not None]
    print("\ncriteria met: %d of %d decided (%d undecided)"
          % (sum(decided), len(decided), len(passed) - len(decided)))


if __name__ == "__main__":
    try:
        main(sys.argv[1:])
    except OSError as e:        # unreadable: its path in the message
        refuse(str(e))
