# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""results/ of a dpmStudy directory: one row per case (study.cases), the
ensembles over seeds with 95 % intervals, the findings of the study's
studyDict (study.definition) as differences between ensembles, what each
variant does to them (study.verdicts), the tables (study.reports) and the
figures. Used by dpmStudy (run, results, import)."""

import fcntl
import os
import sys
from collections import OrderedDict

import numpy as np

from . import definition as study_definition, ensemble as ens, verdicts
from ..files import own_directory
from .locks import LockError, open_lock
from .cases import BASELINE, BED_STATISTICS, case_row, find_cases, say
from .reports import write_csv, write_ensemble, write_summary, write_variants

# Quantities averaged over the seeds of an ensemble
ENSEMBLE = ("M0", "Mfinal", "Mmean", "Mrate", "vertical", "horizontal") + BED_STATISTICS


def groups_of(rows):
    """(variant, w, p) -> the rows of its seeds, in the rows' order."""
    g = OrderedDict()
    for r in rows:
        g.setdefault((r["variant"], r["wSmall"], r["pressure"]), []).append(r)
    return g


def ensembles(rows):
    """One row per (variant, w, p): n, then mean and half-width of each
    quantity of ENSEMBLE over the seeds that reached their end time (a
    case still running would mix another window in; it is counted as
    'running')."""
    out = []
    for (variant, w, p), everyone in groups_of(rows).items():
        members = [r for r in everyone if r["finished"]]
        e = OrderedDict(variant=variant, wSmall=w, pressure=p, n=len(members),
                        running=len(everyone) - len(members),
                        seeds=" ".join(str(r["seed"]) for r in members),
                        time=min(r["time"] for r in members) if members else np.nan)
        for k in ENSEMBLE:
            e[k], e[k + "CI"], _ = ens.mean_ci([r[k] for r in members])
        out.append(e)
    return out


def findings(rows, definition):
    """Rows of findings.md/csv: each contrast of the study's definition,
    for each variant, with its difference, interval and sign."""
    g = groups_of([r for r in rows if r["finished"]])     # running cases left out
    out = []
    variants = list(OrderedDict.fromkeys(r["variant"] for r in rows if r["finished"]))
    for v in variants:
        have = {(w, p) for variant, w, p in g.keys() if variant == v}
        for finding, what, k, a, b, paper in definition.contrasts(have):
            A = [r[k] for r in g[(v,) + a]]
            if b is None:
                diff, half, na = ens.mean_ci(A)
                nb = 0
            else:
                diff, half, na, nb = ens.difference_ci(A, [r[k] for r in g[(v,) + b]])
            sign = ens.sign_of(diff, half)
            if sign == "n/a":
                verdict = "no data"
            elif sign == "none":
                verdict = "no difference resolved"
            elif sign.endswith("?"):
                verdict = "one seed: %s the paper's sign (no interval)" % (
                    "as" if sign[0] == paper else "against")
            else:
                verdict = "as the paper" if sign == paper else "reversed"
            out.append(OrderedDict(variant=v, finding=finding, comparison=what, quantity=k,
                                   paperSign=paper, difference=diff, CI=half, nA=na, nB=nb,
                                   sign=sign, verdict=verdict, cases=(a, b)))
    return out


def ensemble_windows(windows):
    """Window means of M over the seeds of each (variant, w, p)."""
    g = OrderedDict()
    for r in windows:
        g.setdefault((r["variant"], r["wSmall"], r["pressure"], r["tStart"], r["tEnd"]),
                     []).append(r["M"])
    return [OrderedDict(variant=v, wSmall=w, pressure=p, tStart=a, tEnd=b, n=len(Ms),
                        M=ens.mean_ci(Ms)[0], MCI=ens.mean_ci(Ms)[1])
            for (v, w, p, a, b), Ms in g.items()]


def definition_of(study_dir, template):
    """The study's definition: the studyDict the runner copied into the
    study directory, else the template's."""
    recorded = os.path.join(study_dir, study_definition.FILE_NAME)
    if os.path.isfile(recorded):
        return study_definition.Definition(recorded)
    return study_definition.of_template(template)


def results(study_dir, X, rate_window=None, pictures=True, definition=None):
    """Remake <study_dir>/results from every case there, testing the
    findings of definition (a study.definition.Definition)."""
    out = os.path.join(study_dir, "results")
    own_directory(out)
    # One at a time: two dpmStudy runs of a work queue that finish together
    # would write the same tables (and the cases' bed statistics) at once
    try:
        lock = open_lock(os.path.join(out, ".lock"))
    except LockError as e:
        sys.exit("dpmStudy: %s" % e)
    try:
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            say("results: waiting for another dpmStudy making %s" % out)
            fcntl.flock(lock, fcntl.LOCK_EX)
        remake_results(study_dir, out, X, rate_window, pictures, definition)
    finally:
        os.close(lock)


def remake_results(study_dir, out, X, rate_window, pictures, definition):
    cases = find_cases(study_dir)
    rows, windows, dirs = [], [], {}
    for c in cases:
        try:
            row, win = case_row(c, X, rate_window)
        except ValueError as e:         # tables that do not join
            say("results: %s left out: %s" % (c["case"], e))
            continue
        if row is not None:
            rows.append(row)
            windows.extend(win)
            dirs[row["case"]] = c["dir"]
    if not rows:
        say("results: nothing to sum up yet")
        return
    write_csv(os.path.join(out, "summary.csv"), rows)
    write_csv(os.path.join(out, "windows.csv"), windows)
    write_summary(out, rows, windows, X)
    ensemble = ensembles(rows)
    ewindows = ensemble_windows(windows)
    found = findings(rows, definition)
    write_csv(os.path.join(out, "ensemble.csv"), ensemble)
    write_csv(os.path.join(out, "ensembleWindows.csv"), ewindows)
    write_csv(os.path.join(out, "findings.csv"),
              [OrderedDict((k, v) for k, v in r.items() if k != "cases") for r in found])
    write_ensemble(out, ensemble, ewindows, found, X, rate_window, definition)
    effects = verdicts.variant_effects(
        found, groups_of([r for r in rows if r["finished"]]), BASELINE)
    write_csv(os.path.join(out, "verdicts.csv"), effects)
    verdicts.write_verdicts(out, effects, ens.LEVEL)
    write_variants(out, cases)
    say("results: %s" % os.path.join(out, "summary.md"))
    from . import figures
    figures.figures(rows, ensemble, dirs, out, X, pictures)
