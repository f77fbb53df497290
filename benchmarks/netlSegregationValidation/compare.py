#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The rise times of NETL's segregating bed (LaMarche et al. 2022) against
the experiment's (its files measurements/<condition>.txt, in the folder
REFERENCE): for each condition and k (the k-th intruder to emerge), the
mean over the seeds beside the experiment's mean over its repeats (each
with its 95 % t-interval), and the verdicts of the criteria declared before
the runs (README.md):

  1. equivalence of the means, for each condition and k: the two one-sided
     tests (TOST) at 5 % on the simulated minus the measured mean, Welch's
     standard error and degrees of freedom, within the margin +-Delta,
     Delta twice the experiment's repeat standard deviation of that
     condition and k: met when the 90 % interval of the difference lies inside
     (-Delta, +Delta), not met when it lies wholly outside, undecided
     otherwise;
  2.-5. the trends, each a one-sided Welch test at 5 % on the seeds that
     t_r(1) of the first condition exceeds the second's: met when shown
     (the 90 % interval above 0), not met when the reverse is shown (below
     0), undecided otherwise:
  2. a heavier bed rises slower: 227.47 g against 177.46 g (1.83 m/s);
  3. a slower gas rises slower: 1.83 m/s against 2.134 m/s (177.46 g);
  and on the held-out conditions, the two trends the experiment shows there:
  4. small intruders rise slower: two small against two large
     (2.134 m/s, 177.46 g);
  5. a slower gas rises slower with four intruders: 1.83 m/s against
     2.134 m/s (177.46 g).

A condition with fewer than MIN_SEEDS finished seeds gets no verdict ("too
few seeds"), nor a trend that uses it. Beside each verdict, not counted:
ASME V&V 20's comparison error E = S - D with its validation uncertainty
u_val = sqrt(u_num^2 + u_input^2 + u_D^2), u_D the experiment's standard
error of the mean, u_input and u_num from the tables <condition>.dat of
the folder -uncertainty (by default <run dir>/uncertainty), each a '#'
header line 'rank u_input u_num' (either may be left out; nan: not
estimated) and a row for each k; u_val from the terms known when not; and
the spread ratio s_sim/s_exp (the seeds' standard deviation over the
repeats').

The surface is the height below which 99 % of the glass centres lie; 95 %
and 99.9 % bracket it (their means are printed).

An intruder that has not risen by a seed's end is censored: its rise time
is only known to exceed the time the run ended (its end time, or sooner
where the bed came to rest and bedAtRest ended it: marked "at rest"). Where a condition has censored
seeds, the mean is given as a lower bound (the censored taken at their end
time, marked >=); criterion 1 is then not met if even that bound's 90 %
interval lies above +Delta, and undecided otherwise. A trend is met if it is
shown with the censored at their end times and the condition expected to
be faster has none (a bound on the slower one only understates the
difference), not met if the reverse is shown and the slower one has none,
undecided otherwise.

  compare.py <run dir> [-reference <dir>] [-uncertainty <dir>] [-figure <png>] [-perSeed]

-figure draws each condition's rise times, the seeds' beside the
experiment's repeats, with the means and their intervals. -perSeed also
prints each seed's rise times (surface at 99 %; >= a censored one, at the
time its run ended; "at rest" where the bed came to rest): the record a
results page keeps.
"""

import math
import os
import re
import sys

import numpy as np

try:
    from dpmfoam2d import statistics
    from dpmfoam2d.files import figure_path_problem
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
MIN_SEEDS = 8       # the project's rule: a validation verdict needs 8 seeds a condition
ALPHA = 0.05        # every test's level: TOST's 90 % interval, the trends' one-sided tests
MARGIN_SDS = 2      # criterion 1's margin Delta, in the experiment's repeat standard deviations
K_VAL = 2           # ASME V&V 20: |E| against K_VAL u_val
UNCERTAINTY = ("u_input", "u_num")


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
    """The time the run ended (s): its latest time directory, which is the
    end time, or sooner where intrudersRisen or bedAtRest ended the run; a
    refusal naming the seed when it has none, as its censored rise times
    need it."""
    times = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if math.isfinite(t) and t > 0 and os.path.isdir(os.path.join(case, name)):
            times.append(t)
    if times:
        return max(times)
    refuse("seed %s: an intruder not risen by the end (nan in riseOrder.dat), and no time "
           "directory after 0 to tell when the run ended; rerun the seed or leave it out of "
           "the run folder" % case)


def came_to_rest(case):
    """Whether the bed came to rest and bedAtRest ended the run (its line in
    log.dpmFoam2D)."""
    log = os.path.join(case, "log.dpmFoam2D")
    if not os.path.isfile(log):
        return False
    with open(log, errors="replace") as f:
        return any(line.startswith("bedAtRest ") and ": the bed has been at rest" in line
                   for line in f)


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


def uncertainties(folder, condition, intruders):
    """{k: {"u_input": s, "u_num": s}} of a condition from its table
    <folder>/<condition>.dat ('#' header 'rank u_input u_num', either
    column may be left out, nan where not estimated; a row for each rank),
    checked: refused naming the file otherwise; {} when there is none."""
    path = os.path.join(folder, condition + ".dat")
    if not os.path.isfile(path):
        return {}
    try:
        columns = read_dat(path)
    except ValueError as e:
        refuse("%s (the condition's uncertainties: '# rank u_input u_num', then a row for "
               "each k)" % e)
    names = list(columns)
    extra = [c for c in names if c not in ("rank",) + UNCERTAINTY]
    if "rank" not in names or extra or not any(c in names for c in UNCERTAINTY):
        refuse("%s: columns %s; 'rank' and one or both of %s expected"
               % (path, " ".join(names), ", ".join(UNCERTAINTY)))
    rank = columns["rank"]
    if not np.array_equal(np.sort(rank), np.arange(1, intruders + 1)):
        refuse("%s: ranks %s; a row for each of 1 to %d (the condition's intruders)"
               % (path, " ".join("%g" % r for r in rank), intruders))
    found = {}
    for row, k in enumerate(rank):
        found[int(k)] = {}
        for c in UNCERTAINTY:
            u = float(columns[c][row]) if c in columns else math.nan
            if not (math.isnan(u) or (math.isfinite(u) and u >= 0)):
                refuse("%s: rank %d, %s = %g: a standard uncertainty in s (>= 0, or nan "
                       "where not estimated)" % (path, k, c, u))
            found[int(k)][c] = u
    return found


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
                print("| %s | %s | %s%s |" % (c, case.rsplit("_seed", 1)[1], ", ".join(
                    "%s%.2f" % (">=" if cens[k, SURFACE] else "", t[k, SURFACE])
                    for k in range(len(t))), " (at rest)" if came_to_rest(case) else ""))


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
                m, h = statistics.mean_interval(data)
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
    """run, reference, uncertainty, figure, perSeed from the command line,
    checked."""
    if not argv or argv[0].startswith("-"):
        sys.exit(__doc__)
    run, reference, uncertainty, figure, per_seed = argv[0], REFERENCE, None, None, False
    values = {"-reference": "the experiment's measurements folder",
              "-uncertainty": "a folder of <condition>.dat tables of u_input and u_num",
              "-figure": "a .png"}
    i = 1
    while i < len(argv):
        if argv[i] in values:
            if i + 1 == len(argv):
                refuse("%s needs a value (%s)" % (argv[i], values[argv[i]]))
            if argv[i] == "-reference":
                reference = argv[i + 1]
            elif argv[i] == "-uncertainty":
                uncertainty = argv[i + 1]
                if not os.path.isdir(uncertainty):
                    refuse("-uncertainty %s: no such folder (%s)"
                           % (uncertainty, values["-uncertainty"]))
            else:
                figure = argv[i + 1]
            i += 2
        elif argv[i] == "-perSeed":
            per_seed, i = True, i + 1
        else:
            refuse("unknown argument '%s' (compare.py <run dir> [-reference <dir>] "
                   "[-uncertainty <dir>] [-figure <png>] [-perSeed])" % argv[i])
    if not os.path.isdir(run):
        refuse("no run folder %s" % run)
    if not os.path.isdir(reference):
        refuse("no reference folder %s (the experiment's measurements/: -reference <dir>, or "
               "the shared reference beside the repository, README.md)" % reference)
    if uncertainty is None:
        uncertainty = os.path.join(run, "uncertainty")
    if figure is not None:
        problem = figure_path_problem(figure)
        if problem:
            refuse("-figure %s%s" % (figure, problem))
    return run, reference, uncertainty, figure, per_seed


def equivalence(sim, censored, exp):
    """Criterion 1 for one condition and k: (verdict, Tost). sim: the
    seeds' rise times (the censored at their end time), exp: the repeats'."""
    margin = MARGIN_SDS * float(np.std(exp, ddof=1)) if len(exp) > 1 else math.nan
    test = statistics.tost(sim, exp, margin, ALPHA)
    if len(sim) < MIN_SEEDS:
        return "too few seeds (n < %d)" % MIN_SEEDS, test
    if test.outcome is None:
        return "undecided (no spread measured)", test
    if censored:        # a lower bound: only "above the margin" is certain
        return ("not met" if test.low >= margin else "undecided (censored seeds)"), test
    return {statistics.EQUIVALENT: "met", statistics.NOT_EQUIVALENT: "not met",
            statistics.UNDECIDED: "undecided"}[test.outcome], test


def trend(a, b, censored_a=False, censored_b=False, simulated=True):
    """A trend: t_r(1) of a exceeds b's, a one-sided Welch test at ALPHA.
    (verdict, OneSided). The simulated ones need MIN_SEEDS seeds on each
    side; a censored slower side (a) can only understate a shown trend, a
    censored faster side (b) only understate a shown reverse."""
    test = statistics.one_sided(a, b, ALPHA)
    if simulated and min(len(a), len(b)) < MIN_SEEDS:
        return "too few seeds (n < %d)" % MIN_SEEDS, test
    if test.outcome is None:
        return "undecided (no spread measured)", test
    if test.outcome == "greater":
        return ("undecided (censored seeds)" if censored_b else "met"), test
    if test.outcome == "less":
        return ("undecided (censored seeds)" if censored_a else "not met (the reverse shown)"), \
            test
    return ("undecided (censored seeds)" if censored_a or censored_b else "undecided"), test


def vv20(sim, exp, u):
    """ASME V&V 20 for one condition and k: (E, u_val, the terms not
    estimated). u: this k's {"u_input": s, "u_num": s} (nan or absent: not
    estimated)."""
    e = float(np.mean(sim) - np.mean(exp))
    u_D = float(np.std(exp, ddof=1) / math.sqrt(len(exp))) if len(exp) > 1 else math.nan
    u_val, missing = statistics.validation_uncertainty(u_D, u.get("u_input"), u.get("u_num"))
    return e, u_val, missing


def verdict_word(verdict):
    """The count a verdict goes to in the summary."""
    for word in ("met", "not met", "too few seeds"):
        if verdict.startswith(word) and (word != "met" or verdict == "met"):
            return word
    return "undecided"


def main(argv):
    run, reference, uncertainty, figure, per_seed = arguments(argv)
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
    us = {c: uncertainties(uncertainty, c, intruders[c]) for c in conditions}
    print("Criterion 1: TOST at %g %% within +-Delta (%g times the experiment's repeat "
          "standard deviation), %d seeds or more; V&V 20: |E| against %d u_val, not a verdict"
          % (100 * ALPHA, MARGIN_SDS, MIN_SEEDS, K_VAL))
    print()
    print("| condition | k | seeds | simulated t_r, s | experiment t_r, s | S - D, s |"
          " 90 %% interval, s | Delta, s | TOST p | criterion 1 | u_val, s |"
          " abs(E) vs %d u_val, s | s_sim/s_exp | surface 95 %% / 99.9 %% | not risen |" % K_VAL)
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- "
          "| --- |")
    first = {}
    verdicts = []
    drawn = []
    not_estimated = {}
    for c in conditions:
        (sim, cens), exp = sims[c], exps[c]
        if not len(sim):
            continue
        drawn.append((c, sim[:, :, SURFACE], cens[:, :, SURFACE], exp))
        first[c] = (sim[:, 0, SURFACE], exp[:, 0], bool(cens[:, 0, SURFACE].any()))
        for k in range(exp.shape[1]):
            x = sim[:, k, SURFACE]
            n_cens = int(cens[:, k, SURFACE].sum())
            verdict, test = equivalence(x, n_cens > 0, exp[:, k])
            verdicts.append(verdict)
            m, h = statistics.mean_interval(x)
            me, he = statistics.mean_interval(exp[:, k])
            e, u_val, missing = vv20(x, exp[:, k], us[c].get(k + 1, {}))
            if missing:
                not_estimated.setdefault(", ".join(missing), []).append("%s k %d" % (c, k + 1))
            s_sim = float(np.std(x, ddof=1)) if len(x) > 1 else math.nan
            bounds = ["%s%.2f" % (">=" if cens[:, k, j].any() else "", sim[:, k, j].mean())
                      for j in (0, 2)]
            lower = ">=" if n_cens else ""
            print("| %s | %d | %d | %s%.2f +- %.2f | %.2f +- %.2f | %s%.2f | %s | %.2f | %s | %s "
                  "| %.2f%s | %.2f %s %.2f | %.2f | %s / %s | %d |"
                  % (c, k + 1, len(sim), lower, m, h, me, he, lower, e,
                     "%.2f to %.2f" % (test.low, test.high) if math.isfinite(test.low) else "-",
                     test.margin, "%.3f" % test.p if math.isfinite(test.p) else "-", verdict,
                     u_val, " (u_D alone)" if len(missing) == 2 else
                     " (without %s)" % missing[0] if missing else "",
                     abs(e), "<=" if abs(e) <= K_VAL * u_val else ">", K_VAL * u_val,
                     s_sim * MARGIN_SDS / test.margin, bounds[0], bounds[1], n_cens))
    for terms, where in not_estimated.items():
        print("\n%s not estimated (no table %s, or nan there) for %s: u_val from the other "
              "terms, a lower bound of V&V 20's"
              % (terms, os.path.join(uncertainty, "<condition>.dat"), ", ".join(where)))
    print()
    for name, a, b in TRENDS:
        if a in first and b in first:
            for which, j in (("simulated", 0), ("experiment", 1)):
                cens_a, cens_b = (first[a][2], first[b][2]) if which == "simulated" \
                    else (False, False)
                verdict, test = trend(first[a][j], first[b][j], cens_a, cens_b,
                                      which == "simulated")
                d = test.difference
                low, high = d.interval(1 - 2 * ALPHA)
                if which == "experiment":       # the repeats' own trend, not a criterion
                    verdict = {"met": "shown", "not met (the reverse shown)": "reverse shown",
                               "undecided": "not shown"}.get(verdict, verdict)
                print("%s, %s: t_r(1) %s - %s = %.2f s, 90 %% interval %s, one-sided p %s: %s"
                      % (name, which, a, b, d.difference,
                         "%.2f to %.2f" % (low, high) if math.isfinite(low) else "-",
                         "%.3f" % test.p_greater if math.isfinite(test.p_greater) else "-",
                         verdict))
                if which == "simulated":
                    verdicts.append(verdict)
    if per_seed:
        print_per_seed(run, conditions, intruders)
    if figure and drawn:
        draw(drawn, figure)
    elif figure:
        print("no figure %s: no seed has finished (riseOrder.dat)" % figure)
    counts = {w: 0 for w in ("met", "not met", "undecided", "too few seeds")}
    for v in verdicts:
        counts[verdict_word(v)] += 1
    print("\ncriteria: met %d of %d, not met %d, undecided %d, too few seeds %d"
          % (counts["met"], len(verdicts), counts["not met"], counts["undecided"],
             counts["too few seeds"]))


if __name__ == "__main__":
    try:
        main(sys.argv[1:])
    except OSError as e:        # unreadable: its path in the message
        refuse(str(e))
