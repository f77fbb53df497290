# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The tables of a dpmStudy's results/: summary, windows, ensembles,
findings and variants, as CSV and Markdown."""

import csv
import os
from collections import OrderedDict

from . import ensemble as ens
from .cases import BASELINE, BED_STATISTICS
from ..files import replacing, write_text


def write_csv(path, rows):
    if not rows:
        write_text(path, "")
        return
    with replacing(path, newline="") as f:
        wr = csv.DictWriter(f, list(rows[0]))
        wr.writeheader()
        wr.writerows(rows)


def write_summary(out, rows, windows, X):
    with replacing(os.path.join(out, "summary.md")) as f:
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


def write_ensemble(out, ensemble, ewindows, found, X, rate_window, definition):
    lvl = int(round(ens.LEVEL * 100))
    t0, t1 = rate_window or (0.0, X)
    with replacing(os.path.join(out, "ensemble.md")) as f:
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
    with replacing(os.path.join(out, "findings.md")) as f:
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
    with replacing(os.path.join(out, "variants.md")) as f:
        f.write("Variants of this study (%s: the template as it is). Each case keeps its "
                "edits in constant/variant; `dpmStudy run <dir> -variant "
                "<case>/constant/variant` reruns them.\n" % BASELINE)
        for name, (case, text) in seen.items():
            f.write("\n## %s (recorded in %s/constant/variant)\n\n```\n%s```\n"
                    % (name, case, text if text.endswith("\n") else text + "\n"))
