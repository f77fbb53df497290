# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""M(t) of several dpmFoam2D cases in one figure (like the paper's Fig. 3),
with their segregation indices below.

  dpmPlotMixing <case> [<case> ...] [-o plot.png] [-labels L1 L2 ...]
                [-title TEXT] [-report]

Reads each case's postProcessing/laceyIndex/<startTime>/laceyIndex.dat
(columns Time M ...) and segregation.dat (Time ... vertical ... horizontal),
joining the start-time directories in time order (a later start time
replaces the rows of an earlier one from that time on, as after a restart);
a table of `dpmFoam2D -postProcess` is left out, with a note, unless the case
has no other.
Top panel: Lacey index M(t), one curve per case. Bottom panel: vertical
(solid) and horizontal (dashed) segregation index of each case in the
case's colour: +1 complete segregation with the small particles on top
(vertical) or at the walls (horizontal), 0 mixed.
Default output: mixing.png (one case: <case>/images/mixing.png).
-report prints a JSON line with the curves drawn (for tests and scripts).
"""

import argparse
import json
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

from .. import particles as pio, tables  # noqa: E402
from ..files import save_figure


def plot(cases, labels, out, title=None):
    """Draw the figure; return a report dict (curves per panel, cases)."""
    fig, (axM, axS) = plt.subplots(2, 1, figsize=(7, 7.5), sharex=True,
                                   gridspec_kw={"height_ratios": [3, 2]})
    report = {"png": out, "cases": [], "mixingCurves": 0, "segregationCurves": 0}
    mMax = 1.0
    for i, (case, label) in enumerate(zip(cases, labels)):
        colour = "C%d" % (i % 10)
        lacey = tables.read_postprocessing(case, "laceyIndex", "laceyIndex.dat")
        seg = tables.read_postprocessing(case, "laceyIndex", "segregation.dat")
        entry = {"case": case, "label": label,
                 "laceyRows": 0 if lacey is None else len(lacey["Time"]),
                 "segregationRows": 0 if seg is None else len(seg["Time"])}
        report["cases"].append(entry)
        if lacey is None or not len(lacey["Time"]):
            print("dpmPlotMixing: no laceyIndex.dat in %s/postProcessing/laceyIndex"
                  % case, file=sys.stderr)
        else:
            axM.plot(lacey["Time"], lacey["M"], color=colour, label=label)
            report["mixingCurves"] += 1
            finite = lacey["M"][lacey["M"] == lacey["M"]]
            if len(finite):
                mMax = max(mMax, float(finite.max()))
            entry["finalM"] = float(lacey["M"][-1])
        if seg is not None and len(seg["Time"]):
            axS.plot(seg["Time"], seg["vertical"], color=colour, ls="-",
                     label="%s vertical" % label)
            axS.plot(seg["Time"], seg["horizontal"], color=colour, ls="--",
                     label="%s horizontal" % label)
            report["segregationCurves"] += 2
    axM.set_ylabel("Lacey mixing index M")
    axM.set_ylim(0, 1.05 * mMax)
    axM.grid(True, alpha=0.3)
    if report["mixingCurves"]:
        axM.legend(loc="best")
    if title:
        axM.set_title(title)
    axS.set_xlabel("time (s)")
    axS.set_ylabel("segregation index")
    axS.axhline(0, color="k", lw=0.5)
    axS.grid(True, alpha=0.3)
    if report["segregationCurves"]:
        axS.legend(handles=[
            Line2D([], [], color="k", ls="-", label="vertical (+1: small on top)"),
            Line2D([], [], color="k", ls="--", label="horizontal (+1: small at walls)")],
            loc="best", fontsize="small")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(out)) or ".", exist_ok=True)
    save_figure(fig, out, dpi=120)
    plt.close(fig)
    return report


def main():
    ap = argparse.ArgumentParser(prog="dpmPlotMixing", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="+")
    ap.add_argument("-o", dest="out", default=None, help="output PNG")
    ap.add_argument("-labels", nargs="+", default=None, help="one label per case")
    ap.add_argument("-title", default=None)
    ap.add_argument("-report", action="store_true", help="print a JSON report")
    args = ap.parse_args()
    labels = args.labels or [os.path.basename(os.path.abspath(c)) for c in args.cases]
    if len(labels) != len(args.cases):
        sys.exit("dpmPlotMixing: %d labels for %d cases" % (len(labels), len(args.cases)))
    for case in args.cases:
        pio.check_case(case)
    if not any(tables.read_postprocessing(c, "laceyIndex", "laceyIndex.dat", quiet=True)
               is not None for c in args.cases):
        sys.exit("dpmPlotMixing: no M(t) data (postProcessing/laceyIndex/<time>/"
                 "laceyIndex.dat) in %s" % " ".join(args.cases))
    out = args.out or (os.path.join(args.cases[0], "images", "mixing.png")
                       if len(args.cases) == 1 else "mixing.png")
    report = plot(args.cases, labels, out, args.title)
    if report["mixingCurves"] == 0:
        sys.exit("dpmPlotMixing: no M(t) data in any case")
    if args.report:
        print(json.dumps(report))
    else:
        print(out)


def command():
    """The console script dpmPlotMixing."""
    try:
        main()
    except (FileNotFoundError, ValueError) as e:
        sys.exit("dpmPlotMixing: %s" % e)
