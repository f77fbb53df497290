# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""results/ of a dpmStudy directory: one row per case, the ensembles over
seeds with 95 % intervals, the findings of the study's studyDict
(study.definition) as differences between ensembles, what each variant
does to them (study.verdicts) and the figures. Used by bin/dpmStudy
(-results)."""

import csv
import fcntl
import os
import re
import subprocess
from collections import OrderedDict

import numpy as np

from .. import BIN_DIR
from ..tables import read_postprocessing
from . import definition as study_definition, ensemble as ens, verdicts
# Columns of dpmBedStatistics' tables that the summary averages
BED_STATISTICS = ("bedHeight", "bubbleFraction", "emulsionVoidage", "speedRmsSmall",
                  "speedRmsLarge", "stillSmall", "stillLarge", "voidageSmall",
                  "voidageLarge")
INDICES = ("vertical", "horizontal", "hSmall", "hLarge", "rSmall", "rLarge")
# Quantities averaged over the seeds of an ensemble
ENSEMBLE = ("M0", "Mfinal", "Mmean", "Mrate", "vertical", "horizontal") + BED_STATISTICS

BASELINE = "baseline"       # the template as it is (no variant)


def say(*args):
    print(*args, flush=True)


def flat_dictionary(path):
    """Entries of a flat OpenFOAM dictionary (caseSettings): name -> text."""
    out = {}
    with open(path) as f:
        text = re.sub(r"//[^\n]*", "", f.read())
    for m in re.finditer(r"^\s*([A-Za-z]\w*)\s+([^;{}]+);", text, re.M):
        out[m.group(1)] = m.group(2).strip()
    return out


def find_cases(study_dir):
    """Every case of the study directory: dicts with dir, case, wSmall,
    pressure, seed (None: the template's, no suffix) and variant."""
    cases = []
    for name in sorted(os.listdir(study_dir)):
        d = os.path.join(study_dir, name)
        settings = os.path.join(d, "constant", "caseSettings")
        if name in ("beds", "results") or not os.path.isfile(settings):
            continue
        s = flat_dictionary(settings)
        if "pressure" not in s or "wSmall" not in s:
            continue
        record = os.path.join(d, "constant", "variant")
        variant = BASELINE
        if os.path.isfile(record):
            with open(record) as f:
                m = re.match(r"# variant (\S+)", f.readline())
            variant = m.group(1) if m else name
        seeded = re.search(r"_seed(\d+)$", name) is not None
        p = float(s["pressure"])
        cases.append({"dir": d, "case": name, "variant": variant,
                      "wSmall": float(s["wSmall"]), "pressure": int(p) if p == int(p) else p,
                      "seed": int(float(s["seed"])) if seeded and "seed" in s else None,
                      "endTime": float(s["endTime"]) if "endTime" in s else None})
    cases.sort(key=lambda c: (c["variant"] != BASELINE, c["variant"], c["wSmall"],
                              c["pressure"], c["seed"] or 0))
    return cases


def time_windows(t, M, tS, S, X):
    """Means of M and of the vertical and horizontal indices over the
    complete windows (k X, (k+1) X], k = 0, 1, ... of one case's tables."""
    def within(times, t0, t1):
        return (times > t0 + 1e-9) & (times <= t1 + 1e-9)

    out, k = [], 0
    while (k + 1) * X <= t[-1] + 1e-9:
        t0, t1 = k * X, (k + 1) * X
        inM, inS = within(t, t0, t1), within(tS, t0, t1)
        if inM.any() and inS.any():
            out.append({"tStart": round(t0, 9), "tEnd": round(t1, 9), "M": M[inM].mean(),
                        "vertical": S["vertical"][inS].mean(),
                        "horizontal": S["horizontal"][inS].mean()})
        k += 1
    return out


def case_row(c, X, rate_window):
    """One case's summary row and its windows, or (None, None) without data."""
    case = c["dir"]
    M = read_postprocessing(case, "laceyIndex", "laceyIndex.dat")
    S = read_postprocessing(case, "laceyIndex", "segregation.dat")
    if M is None or S is None or len(M["Time"]) == 0:
        say("results: no laceyIndex data in %s" % case)
        return None, None
    t = M["Time"]
    last = t >= t[-1] - X - 1e-9
    tS = S["Time"]
    lastS = tS >= tS[-1] - X - 1e-9
    t0, t1 = rate_window or (0.0, X)
    inRate = (t > t0 + 1e-9) & (t <= t1 + 1e-9)
    row = OrderedDict(case=c["case"], variant=c["variant"], seed=c["seed"] or "",
                      wSmall=c["wSmall"], pressure=c["pressure"], Umf=np.nan, U0=np.nan,
                      time=t[-1], finished=c["endTime"] is None or t[-1] >= c["endTime"] - 1e-6,
                      M0=M["M"][0], Mfinal=M["M"][-1], Mmean=M["M"][last].mean(),
                      Mrate=(M["M"][inRate] / M["M"][0]).mean()
                      if inRate.any() and M["M"][0] > 0 and t[-1] >= t1 - 1e-9 else np.nan)
    for k in INDICES:
        row[k] = S[k][lastS].mean()
    # Lacey's own N (one sample), when the case has it
    L = read_postprocessing(case, "laceyIndexPerSample", "laceyIndex.dat")
    row["MsampleFinal"] = L["M"][-1] if L is not None and len(L["M"]) else np.nan
    row["MsampleMean"] = L["M"][L["Time"] >= L["Time"][-1] - X - 1e-9].mean() \
        if L is not None and len(L["M"]) else np.nan
    row.update(bed_statistics(case, X))
    windows = [OrderedDict(case=c["case"], variant=c["variant"], seed=c["seed"] or "",
                           wSmall=c["wSmall"], pressure=c["pressure"], **win)
               for win in time_windows(t, M["M"], tS, S, X)]
    for name in sorted(f for f in os.listdir(case) if f.startswith("log.dpmFoam2D")):
        with open(os.path.join(case, name), errors="replace") as f:
            m = re.search(r"Umf \(Wen-Yu\) (\S+) m/s, U0/Umf \S+, (?:U0 - Umf \S+ m/s, )?"
                          r"U0 (\S+) m/s", f.read())
        if m:
            row["Umf"], row["U0"] = float(m.group(1)), float(m.group(2))
            break
    return row, windows


def bed_statistics(case, X):
    """Means over the last X s of dpmBedStatistics' tables (run first)."""
    r = subprocess.run([os.path.join(BIN_DIR, "dpmBedStatistics"), case],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       universal_newlines=True)
    if r.returncode != 0:
        say("results: %s" % r.stdout.strip())
    out = {k: np.nan for k in BED_STATISTICS}
    for name in ("bed.dat", "particles.dat"):
        T = read_postprocessing(case, "bedStatistics", name)
        if T is None or not len(T["Time"]):
            continue
        last = T["Time"] >= T["Time"][-1] - X - 1e-9
        for k in BED_STATISTICS:
            if k in T:
                out[k] = np.nanmean(T[k][last]) if np.isfinite(T[k][last]).any() \
                    else np.nan
    return out


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


def write_csv(path, rows):
    if not rows:
        open(path, "w").close()
        return
    with open(path, "w", newline="") as f:
        wr = csv.DictWriter(f, list(rows[0]))
        wr.writeheader()
        wr.writerows(rows)


def write_summary(out, rows, windows, X):
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("Lacey index M (paper's N: whole bed) and segregation indices; "
                "'mean' columns: mean over the last %g s of each case.\n"
                "vertical > 0: small particles above the large; horizontal > 0: "
                "small particles nearer the walls.\n"
                "h: mean height (m), r: mean distance from the centre line (m).\n\n" % X)
        f.write("| case | variant | seed | w_small | p (bar) | Umf (m/s) | U0 (m/s) | t (s) "
                "| M(0) | M final | M mean | M mean (N per sample) | vertical | horizontal "
                "| h small | h large | r small | r large |\n")
        f.write("|" + "---|" * 18 + "\n")
        for r in rows:
            f.write("| %s | %s | %s | %.2f | %g | %.3f | %.3f | %.2f | %.3f | %.3f | %.3f "
                    "| %.3f | %+.3f | %+.3f | %.4f | %.4f | %.4f | %.4f |\n" % (
                        r["case"], r["variant"], r["seed"] or "-", r["wSmall"], r["pressure"],
                        r["Umf"], r["U0"], r["time"], r["M0"], r["Mfinal"], r["Mmean"],
                        r["MsampleMean"], r["vertical"], r["horizontal"], r["hSmall"],
                        r["hLarge"], r["rSmall"], r["rLarge"]))
        f.write("\nBubbles and particle motion (dpmBedStatistics; 'mean' over the last "
                "%g s): bubble = gas cell of voidage > 0.8 in the bed; emulsion: the "
                "other bed cells; speed: rms particle speed of a class (m/s); still: "
                "its fraction slower than 1 cm/s; voidage at: mean voidage at the "
                "class's particles.\n\n" % X)
        f.write("| case | bed height (m) | bubble fraction | emulsion voidage | speed small "
                "| speed large | still small | still large | voidage at small "
                "| voidage at large |\n")
        f.write("|" + "---|" * 10 + "\n")
        for r in rows:
            f.write("| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n"
                    % tuple([r["case"]] + [r[k] for k in BED_STATISTICS]))
        write_windows(f, windows, X)


def write_windows(md, windows, X):
    """The summary.md table of window means of M."""
    if not windows:
        return
    edges = sorted({(r["tStart"], r["tEnd"]) for r in windows})
    md.write("\nM averaged over consecutive windows of %g s (t0 < t <= t1; only "
             "complete windows): has a case levelled off?\n\n" % X)
    md.write("| case | " + " | ".join("%g-%g s" % e for e in edges) + " |\n")
    md.write("|" + "---|" * (len(edges) + 1) + "\n")
    for case in OrderedDict.fromkeys(r["case"] for r in windows):
        mean = {(r["tStart"], r["tEnd"]): r["M"] for r in windows if r["case"] == case}
        md.write("| %s | " % case + " | ".join(
            "%.3f" % mean[e] if e in mean else "-" for e in edges) + " |\n")


def ensemble_windows(windows):
    """Window means of M over the seeds of each (variant, w, p)."""
    g = OrderedDict()
    for r in windows:
        g.setdefault((r["variant"], r["wSmall"], r["pressure"], r["tStart"], r["tEnd"]),
                     []).append(r["M"])
    return [OrderedDict(variant=v, wSmall=w, pressure=p, tStart=a, tEnd=b, n=len(Ms),
                        M=ens.mean_ci(Ms)[0], MCI=ens.mean_ci(Ms)[1])
            for (v, w, p, a, b), Ms in g.items()]


def write_ensemble(out, ensemble, ewindows, found, X, rate_window, definition):
    lvl = int(round(ens.LEVEL * 100))
    t0, t1 = rate_window or (0.0, X)
    with open(os.path.join(out, "ensemble.md"), "w") as f:
        f.write("Means over the seeds (random packings) of each variant, mass fraction and "
                "pressure, +- the half-width of the %d %% Student-t interval (none for one "
                "seed). M mean, the indices and the bed statistics: over the last %g s; "
                "M/M(0): over %g < t <= %g s. Only cases that reached their end time count "
                "(n); 'running': those that have not yet.\n\n" % (lvl, X, t0, t1))
        f.write("| variant | w_small | p (bar) | n | running | t (s) | M(0) | M mean | M/M(0) "
                "| vertical | horizontal | bubble fraction | emulsion voidage "
                "| speed small | speed large |\n")
        f.write("|" + "---|" * 15 + "\n")
        for e in ensemble:
            f.write("| %s | %.2f | %g | %d | %d | %.2f | %s |\n" % (
                e["variant"], e["wSmall"], e["pressure"], e["n"], e["running"], e["time"],
                " | ".join(
                    ens.fmt(e[k], e[k + "CI"]) for k in (
                        "M0", "Mmean", "Mrate", "vertical", "horizontal", "bubbleFraction",
                        "emulsionVoidage", "speedRmsSmall", "speedRmsLarge"))))
        if ewindows:
            edges = sorted({(r["tStart"], r["tEnd"]) for r in ewindows})
            f.write("\nM over consecutive windows of %g s, mean over the seeds +- %d %% "
                    "interval:\n\n" % (X, lvl))
            f.write("| variant | w_small | p (bar) | " +
                    " | ".join("%g-%g s" % e for e in edges) + " |\n")
            f.write("|" + "---|" * (len(edges) + 3) + "\n")
            for key in OrderedDict.fromkeys((r["variant"], r["wSmall"], r["pressure"])
                                            for r in ewindows):
                cell = {(r["tStart"], r["tEnd"]): ens.fmt(r["M"], r["MCI"])
                        for r in ewindows if (r["variant"], r["wSmall"], r["pressure"]) == key}
                f.write("| %s | %.2f | %g | " % key +
                        " | ".join(cell.get(e, "-") for e in edges) + " |\n")
    with open(os.path.join(out, "findings.md"), "w") as f:
        f.write("%s as differences between ensembles (a - b, mean over seeds, +- "
                "Welch's %d %% interval; for a contrast without b its mean and interval). "
                "A sign is called only where the interval excludes zero; one seed gives a "
                "sign without an interval (screening only).\n%s\n\n"
                % (definition.findings_title, lvl, definition.notes((t0, t1))))
        f.write("| variant | finding | comparison | paper | ours | n (a, b) | sign "
                "| verdict |\n")
        f.write("|" + "---|" * 8 + "\n")
        for r in found:
            f.write("| %s | %s | %s | %s | %s | %d, %d | %s | %s |\n" % (
                r["variant"], r["finding"], r["comparison"], r["paperSign"],
                ens.fmt(r["difference"], r["CI"]), r["nA"], r["nB"], r["sign"],
                r["verdict"]))


def write_variants(out, cases):
    """variants.md: the edits of every variant in the study (from the
    record of its first case)."""
    seen = OrderedDict()
    for c in cases:
        record = os.path.join(c["dir"], "constant", "variant")
        if c["variant"] != BASELINE and c["variant"] not in seen and os.path.isfile(record):
            with open(record) as f:
                seen[c["variant"]] = (c["case"], f.read())
    with open(os.path.join(out, "variants.md"), "w") as f:
        f.write("Variants of this study (%s: the template as it is). Each case keeps its "
                "edits in constant/variant; `dpmStudy <dir> -variant "
                "<case>/constant/variant` reruns them.\n" % BASELINE)
        for name, (case, text) in seen.items():
            f.write("\n## %s (recorded in %s/constant/variant)\n\n```\n%s```\n"
                    % (name, case, text if text.endswith("\n") else text + "\n"))


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
    os.makedirs(out, exist_ok=True)
    # One at a time: two dpmStudy runs of a work queue that finish together
    # would write the same tables (and the cases' bed statistics) at once
    with open(os.path.join(out, ".lock"), "w") as lock:
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            say("results: waiting for another dpmStudy making %s" % out)
            fcntl.flock(lock, fcntl.LOCK_EX)
        remake_results(study_dir, out, X, rate_window, pictures, definition)


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
