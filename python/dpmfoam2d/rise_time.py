# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""When the particles of one class first reach the bed's surface: the rise
time of light intruders in a bed of heavier particles (density segregation,
as NETL's small segregating bed measures it: LaMarche et al. 2022).

  dpmRiseTime <case> [-class <name or index>] [-fraction 0.99 ...]
              [-start <s>]

The bed's surface at a time: the height below which the fraction q
(-fraction, default 0.99) of the centres of the other particles (the bed)
lie. A particle of the class has risen at the first particle file in which
its centre is at or above that height; its rise time is that file's time
less the start (-start, default the first particle file's time: the gas's
onset in a run that starts with it). The time resolution is the particle
files' interval. Several fractions bracket the surface's definition.
Default class: the one with the fewest particles (the intruders).
Refused, naming the case or file: a class that is every particle (no bed
to rise through), a particle file whose particles are not the first
file's (another run's), a case the tables cannot be written into.

Writes postProcessing/riseTime/0/
  riseTime.dat   one row per particle of the class: id, then its rise time
                 for each fraction (nan: it did not rise within the run)
  riseOrder.dat  one row per rank k: the k-th rise time of the class
                 (the 1st, 2nd ... to emerge), for each fraction
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from typing import Sequence

import numpy as np

from . import particles as pio
from .files import outside_case, replacing

OUT = os.path.join("postProcessing", "riseTime", "0")


def surface_heights(y: np.ndarray, in_bed: np.ndarray, fractions: Sequence[float]) -> np.ndarray:
    """The heights below which each fraction of the bed's centres lie."""
    return np.quantile(y[in_bed], fractions) if in_bed.any() else np.full(len(fractions), np.nan)


def rise_times(case: str, cls: int, fractions: Sequence[float], start: float | None = None,
               label: str | None = None) -> tuple[np.ndarray, np.ndarray, float]:
    """(ids, times, start): the ids of class cls's particles (sorted) and
    their rise times, an array [particle, fraction] (nan where not risen),
    measured from start (default: the first particle file's time). Each
    fraction must lie in (0, 1] and start be finite; label names the class
    in messages (default 'class <cls>'). Refused (ValueError naming the
    case or file): a class that is every particle (no bed to rise
    through), and a particle file whose particles are not the first one's
    (another run's)."""
    fractions = np.atleast_1d(np.asarray(fractions, dtype=float))
    for q in fractions:
        if not 0 < q <= 1:
            raise ValueError("rise_times: fractions %s: each must be in (0, 1] (the bed's "
                             "fraction below its surface)" % " ".join("%g" % f for f in fractions))
    if start is not None and not math.isfinite(start):
        raise ValueError("rise_times: start %g is not a finite time" % start)
    label = label or "class %d" % cls
    files = pio.list_times(case)
    if not files:
        raise ValueError("%s: no particle files <time>.h5 in %s" % (case, pio.particles_dir(case)))
    t0 = files[0][0] if start is None else start
    ids = times = everyone = first = None
    for t, path in files:
        if t < t0:
            continue
        p = pio.read_particles(path)
        y, c, pid = p["position"][:, 1], p["class"], p["id"]
        mine = c == cls
        if ids is None:
            first, everyone = path, np.sort(pid)
            ids = np.sort(pid[mine])
            if not len(ids):
                raise ValueError("%s: no particle of class %d" % (path, cls))
            if mine.all():
                named = label if label == "class %d" % cls else "%s (class %d)" % (label, cls)
                raise ValueError("%s: every one of the %d particles of %s is of %s: no bed "
                                 "of other particles to rise through; give the intruders' "
                                 "class (-class)" % (case, len(ids), path, named))
            times = np.full((len(ids), len(fractions)), np.nan)
        elif len(pid) != len(everyone) or not np.array_equal(np.sort(pid), everyone) \
                or not np.array_equal(np.sort(pid[mine]), ids):
            # a file of another run left in particles/: its ids would be
            # matched to the wrong particles, or to none
            what = ("%d particles, %d of %s; %s has %d, %d of them"
                    % (len(pid), int(mine.sum()), label, first, len(everyone), len(ids))
                    if len(pid) != len(everyone) or mine.sum() != len(ids) else
                    "other particle ids than %s" % first)
            raise ValueError("%s: not the particles of the other files (%s): a particle file "
                             "of another run? Remove it, or give -start after it"
                             % (path, what))
        heights = surface_heights(y, ~mine, fractions)
        rows = np.searchsorted(ids, pid[mine])
        for k, h in enumerate(heights):
            risen = (y[mine] >= h) & np.isnan(times[rows, k])
            times[rows[risen], k] = t - t0
    if ids is None:
        raise ValueError("%s: no particle file at or after the start %g s" % (case, t0))
    return ids, times, t0


def write_table(path, comment, names, rows, formats):
    # A new file renamed onto path when whole: a killed command leaves the
    # previous table
    with replacing(path) as f:
        for line in comment:
            f.write("# %s\n" % line)
        f.write("# " + "\t".join("%-14s" % n for n in names).rstrip() + "\n")
        for r in rows:
            f.write("\t".join(fmt % v for fmt, v in zip(formats, r)).rstrip() + "\n")


def main(argv=None):
    ap = argparse.ArgumentParser(prog="dpmRiseTime", description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("case")
    ap.add_argument("-class", dest="cls", help="the class (its name in particleProperties, "
                    "or its index); default: the one with the fewest particles")
    ap.add_argument("-fraction", type=float, nargs="+", default=[0.99],
                    help="the bed's fraction below the surface, each in (0, 1) (default 0.99)")
    ap.add_argument("-start", type=float, help="s from which rise times count (default: the "
                    "first particle file's time)")
    a = ap.parse_args(argv)

    def refuse(text):
        sys.exit("dpmRiseTime: " + text)

    for q in a.fraction:
        if not 0 < q < 1:
            refuse("-fraction %g is outside (0, 1)" % q)
    if a.start is not None and not math.isfinite(a.start):
        refuse("-start %g is not a time" % a.start)
    try:
        pio.check_case(a.case)
        files = pio.list_times(a.case)
        if not files:
            refuse("%s has no particle files <time>.h5 in particles/: run dpmFoam2D first" % a.case)
        names = pio.class_names(a.case)
        if a.cls is None:
            counts = np.bincount(pio.read_particles(files[0][1])["class"])
            present = np.flatnonzero(counts)
            cls = int(present[np.argmin(counts[present])])
        elif a.cls.isdigit():
            cls = int(a.cls)
        elif a.cls in names:
            cls = names.index(a.cls)
        else:
            refuse("-class %s: not a class of %s (classes: %s)"
                   % (a.cls, os.path.join(a.case, "constant", "particleProperties"),
                      " ".join(names) or "none found: give the index"))
        label = names[cls] if cls < len(names) else "class %d" % cls
        ids, times, t0 = rise_times(a.case, cls, a.fraction, a.start, label)
    except (ValueError, OSError) as e:
        refuse(str(e))

    out = os.path.join(a.case, OUT)
    escape = outside_case(a.case, OUT)
    if escape:
        refuse("cannot write the tables into %s: it resolves to %s, outside the case (a "
               "symbolic link); a run's tables are written only inside its case: remove the "
               "link, and copy the tables after" % (out, escape))
    blocker = not_a_folder(a.case, OUT)
    if blocker:
        refuse("cannot write the tables into %s: %s is a file, not a folder; remove or "
               "rename it" % (out, blocker))
    try:
        write_tables(out, label, cls, t0, a.fraction, ids, times)
    except IsADirectoryError as e:
        refuse("cannot write %s: a folder is in the way of the table; remove or rename it"
               % e.filename)
    except OSError as e:
        refuse("cannot write the tables into %s: %s (the case must be writable)"
               % (out, e.strerror or e))
    order = np.sort(times, axis=0)      # nan last
    risen = int(np.isfinite(times[:, 0]).sum())
    print("dpmRiseTime: %s: %d of %d risen (q %g), the first %s -> %s"
          % (label, risen, len(ids), a.fraction[0],
             "at %g s" % order[0, 0] if risen else "none", out))


def not_a_folder(case, rel):
    """The first step of case/rel that exists but is no folder, or None."""
    path = case
    for part in rel.split(os.sep):
        path = os.path.join(path, part)
        if os.path.lexists(path) and not os.path.isdir(path):
            return path
    return None


def write_tables(out, label, cls, t0, fractions, ids, times):
    """riseTime.dat and riseOrder.dat in the directory out (made if missing)."""
    os.makedirs(out, exist_ok=True)
    columns = ["riseTime_q%g" % q for q in fractions]
    comment = ["Rise time of %s (class %d): the first particle file with its centre at or "
               "above the bed's surface, s after %g s" % (label, cls, t0),
               "surface: the height below which the fraction q of the other particles' "
               "centres lie; q = %s" % " ".join("%g" % q for q in fractions),
               "resolution: the particle files' interval; nan: not risen within the run"]
    write_table(os.path.join(out, "riseTime.dat"), comment, ["id"] + columns,
                [[i] + list(r) for i, r in zip(ids, times)], ["%-14d"] + ["%-14.6g"] * len(columns))
    order = np.sort(times, axis=0)      # nan last
    write_table(os.path.join(out, "riseOrder.dat"), comment, ["rank"] + columns,
                [[k + 1] + list(r) for k, r in enumerate(order)],
                ["%-14d"] + ["%-14.6g"] * len(columns))


def command():
    """The console script dpmRiseTime."""
    main()
