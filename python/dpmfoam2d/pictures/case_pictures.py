# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""All pictures of a set of dpmFoam2D cases in one command.

  dpmPictures <case> [<case> ...] [-times T1 T2 ...] [-labels L1 L2 ...]
              [-o combined.png] [-movie] [-every K] [-report]

For each case: snapshots (dpmSnapshot) at the given times, default the
latest particle time, as <case>/images/snapshot_<T>.png; its M(t) and
segregation plot (dpmPlotMixing) as <case>/images/mixing.png when the case
has laceyIndex data; with -movie its movie (dpmMovie, every K-th time) as
<case>/images/movie.mp4. Then one plot of all cases' M(t), default
mixing_all.png in the current directory. -report prints a JSON summary.
"""

import argparse
import math
import json
import os
import sys

from .. import particles as pio, tables
from . import movie as case_movie, plot_mixing, tools


def main():
    ap = argparse.ArgumentParser(prog="dpmPictures", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="+")
    ap.add_argument("-times", nargs="+", type=float, default=None)
    ap.add_argument("-labels", nargs="+", default=None)
    ap.add_argument("-o", dest="out", default="mixing_all.png")
    ap.add_argument("-movie", action="store_true")
    ap.add_argument("-every", type=int, default=1)
    ap.add_argument("-report", action="store_true")
    args = ap.parse_args()
    labels = args.labels or [os.path.basename(os.path.abspath(c)) for c in args.cases]
    if len(labels) != len(args.cases):
        sys.exit("dpmPictures: %d labels for %d cases" % (len(labels), len(args.cases)))
    if args.every < 1:
        sys.exit("dpmPictures: -every %d must be >= 1" % args.every)
    if args.times and not all(math.isfinite(t) for t in args.times):
        sys.exit("dpmPictures: -times %s: times must be finite numbers (s)"
                 % " ".join("%g" % t for t in args.times))
    for case in args.cases:
        pio.check_case(case)
        if not pio.list_times(case) and tables.read_postprocessing(
                case, "laceyIndex", "laceyIndex.dat", quiet=True) is None:
            sys.exit("dpmPictures: nothing to draw in %s: no particle files "
                     "(particles/<time>.h5) and no laceyIndex table (has it run?)" % case)

    summary = {"cases": [], "combined": None}
    withMixing = []
    for case, label in zip(args.cases, labels):
        entry = {"case": case, "snapshots": [], "mixing": None, "movie": None}
        times = pio.list_times(case)
        if times:
            wanted = sorted({pio.nearest_time(case, t)[0] for t in args.times}) \
                if args.times else [times[-1][0]]
            outs = [os.path.join(case, "images", "snapshot_%s.png" % pio.time_name(t))
                    for t in wanted]
            tools.render(case, wanted, outs)
            entry["snapshots"] = outs
        else:
            print("dpmPictures: no particle files in %s" % case, file=sys.stderr)
        if tables.read_postprocessing(case, "laceyIndex", "laceyIndex.dat") is not None:
            out = os.path.join(case, "images", "mixing.png")
            plot_mixing.plot([case], [label], out, title=label)
            entry["mixing"] = out
            withMixing.append((case, label))
        if args.movie and times:
            # a movie that cannot be made is said; the other pictures stand
            try:
                entry["movie"] = case_movie.make_movie(
                    case, os.path.join(case, "images", "movie.mp4"), every=args.every)
            except (FileNotFoundError, RuntimeError, ValueError) as e:
                print("dpmPictures: no movie of %s: %s" % (case, e), file=sys.stderr)
        summary["cases"].append(entry)
        for path in entry["snapshots"] + [entry["mixing"], entry["movie"]]:
            if path:
                print(path)
    if withMixing:
        rep = plot_mixing.plot([c for c, _ in withMixing], [lbl for _, lbl in withMixing],
                           args.out)
        summary["combined"] = args.out
        summary["combinedCurves"] = rep["mixingCurves"]
        print(args.out)
    if args.report:
        print(json.dumps(summary))


def command():
    """The console script dpmPictures."""
    try:
        main()
    except (FileNotFoundError, RuntimeError, ValueError) as e:
        sys.exit("dpmPictures: %s" % e)
