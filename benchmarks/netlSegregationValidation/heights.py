#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The intruders' heights against time in cases of NETL's segregating bed,
one panel per case: each intruder's centre, the bed's surface (the height
below which 99 % of the glass centres lie: the rise time's surface) and the
glass's mean height, read from the particle files every -every seconds.
Where an intruder stays, and whether the glass around it moves, tells a
slow rise from a stuck one.

  heights.py <case> [<case> ...] [-o <png>] [-every <s>] [-class intruder]
"""

import argparse
import os
import sys

import numpy as np

from dpmfoam2d import particles as pio
from dpmfoam2d.files import figure_path_problem, save_figure


def refuse(text):
    sys.exit("heights.py: " + text)


def warn(text):
    print("heights.py: warning: " + text, file=sys.stderr)


def class_index(case, cls):
    """The index of class cls (its name in particleProperties, or its
    index) in case's particle files."""
    names = pio.class_names(case)
    if cls in names:
        return names.index(cls)
    if cls.isdigit() and (not names or int(cls) < len(names)):
        return int(cls)
    refuse("-class %s: not a class of %s (classes: %s)"
           % (cls, os.path.join(case, "constant", "particleProperties"),
              " ".join(names) or "none read: . etc/bashrc for foamDictionary, or give the index"))


def series(case, cls, every):
    """Times, the class's heights [time, particle], the surface and the
    glass's mean height at each time, m. A particle file that cannot be
    read (cut short) is left out, with a warning naming it."""
    try:
        pio.check_case(case)
    except FileNotFoundError as e:
        refuse(str(e))
    k = class_index(case, cls)
    rows = []
    first = None
    next_time = -np.inf
    for t, path in pio.list_times(case):
        if t < next_time - 1e-9:
            continue
        try:
            d = pio.read_particles(path)
        except ValueError as e:
            warn("%s; left out" % e)
            continue
        next_time = t + every
        y, c = d["position"][:, 1], d["class"]
        mine = c == k
        if not mine.any():
            refuse("%s: no particle of class %s (-class: the class that rises)" % (path, cls))
        if mine.all():
            refuse("%s: every particle is of class %s: no bed around it (-class: the class "
                   "that rises)" % (path, cls))
        first = first or (path, mine.sum())
        if mine.sum() != first[1]:
            refuse("%s: %d particles of class %s, %s has %d"
                   % (path, mine.sum(), cls, first[0], first[1]))
        order = np.argsort(d["id"][mine])       # each intruder by its id
        rows.append((t, y[mine][order], np.quantile(y[~mine], 0.99), y[~mine].mean()))
    if not rows:
        refuse("no readable particle files in %s" % pio.particles_dir(case))
    return (np.array([r[0] for r in rows]), np.array([r[1] for r in rows]),
            np.array([r[2] for r in rows]), np.array([r[3] for r in rows]))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("cases", nargs="+")
    ap.add_argument("-o", dest="out", default="heights.png")
    ap.add_argument("-every", type=float, default=0.25, help="s between the files read")
    ap.add_argument("-class", dest="cls", default="intruder")
    a = ap.parse_args(argv)
    if not (np.isfinite(a.every) and a.every >= 0):
        refuse("-every %g: a time in s >= 0 expected (0: every particle file)" % a.every)
    check_output(a.out)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(a.cases), figsize=(3.0 * len(a.cases), 2.8),
                             sharey=True, squeeze=False)
    for ax, case in zip(axes[0], a.cases):
        t, y, surface, mean = series(case, a.cls, a.every)
        ax.plot(t, 1e3 * surface, color="0.3", lw=0.8, label="surface (99 %)")
        ax.plot(t, 1e3 * mean, color="0.6", lw=0.8, ls="--", label="glass, mean")
        for j in range(y.shape[1]):
            ax.plot(t, 1e3 * y[:, j], color="C3", lw=1.0, label="intruder" if j == 0 else None)
        ax.set_title(os.path.basename(os.path.normpath(case)), fontsize=8)
        ax.set_xlabel("t, s")
    axes[0][0].set_ylabel("height, mm")
    axes[0][0].legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    save_figure(fig, a.out, dpi=110)    # renamed onto -o: a link there is replaced
    print("wrote %s" % a.out)


def check_output(out):
    """-o: a file name of a format matplotlib writes, in a folder that exists."""
    problem = figure_path_problem(out)
    if problem:
        refuse("-o %s%s" % (out, problem))


if __name__ == "__main__":
    main()
