#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""A series of side views of one case of NETL's segregating bed: every
particle at true size, projected through the column's depth (as an X-ray
would see it, since a view through the front wall hides the intruders
inside the bed), the glass faint so that its density shows, the intruders
in colour, with the bed's surface (99 % of the glass centres below it).

  snapshots.py <case> -times 0 2 4 ... [-o <png>] [-class intruder] [-top <m>]
"""

import argparse
import os
import sys

import numpy as np

from dpmfoam2d import particles as pio
from dpmfoam2d import rise_time
from dpmfoam2d.files import figure_path_problem, save_figure


def refuse(text):
    sys.exit("snapshots.py: " + text)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("case")
    ap.add_argument("-times", type=float, nargs="+", required=True)
    ap.add_argument("-o", dest="out", default="snapshots.png")
    ap.add_argument("-class", dest="cls", default="intruder")
    ap.add_argument("-top", type=float, default=0.16, help="height shown, m")
    a = ap.parse_args(argv)

    for t in a.times:
        if not np.isfinite(t):
            refuse("-times %g: a time must be a finite number" % t)
    if not (np.isfinite(a.top) and a.top > 0):
        refuse("-top %g: a height in m > 0 expected" % a.top)
    check_output(a.out)
    try:
        pio.check_case(a.case)
    except FileNotFoundError as e:
        refuse(str(e))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import EllipseCollection

    files = pio.list_times(a.case)
    if not files:
        refuse("no particle files in %s" % pio.particles_dir(a.case))
    names = pio.class_names(a.case)
    if a.cls in names:
        cls = names.index(a.cls)
    elif a.cls.isdigit() and (not names or int(a.cls) < len(names)):
        cls = int(a.cls)
    else:
        refuse("-class %s: not a class of %s (classes: %s)"
               % (a.cls, os.path.join(a.case, "constant", "particleProperties"),
                  " ".join(names) or "none read: . etc/bashrc for foamDictionary, or give the "
                  "index"))
    fig, axes = plt.subplots(1, len(a.times), figsize=(1.15 * len(a.times), 3.4),
                             sharey=True, squeeze=False)
    width = None
    for ax, t in zip(axes[0], a.times):
        tf, path = min(files, key=lambda f: abs(f[0] - t))
        try:
            p = pio.read_particles(path)
        except ValueError as e:     # one drawn alone: refused, not replaced by another time
            refuse(str(e))
        x, y, d, c = p["position"][:, 0], p["position"][:, 1], p["diameter"], p["class"]
        if not (c == cls).any() or (c == cls).all():
            refuse("%s: %s particle of class %s: nothing %s (-class: the class that rises)"
                   % (path, "no" if not (c == cls).any() else "every",
                      a.cls, "to colour" if not (c == cls).any() else "around it"))
        width = width or float(np.max(x + d / 2))
        for mine, face, alpha in ((c != cls, "0.45", 0.12), (c == cls, "C3", 0.95)):
            ax.add_collection(EllipseCollection(d[mine], d[mine], 0, units="xy",
                                                offsets=np.column_stack([x[mine], y[mine]]),
                                                transOffset=ax.transData, facecolors=face,
                                                edgecolors="none", alpha=alpha))
        surface = rise_time.surface_heights(y, c != cls, [0.99])[0]
        ax.axhline(surface, color="k", lw=0.6, ls="--")
        ax.set_xlim(0, width)
        ax.set_ylim(0, a.top)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_title("%g s" % tf, fontsize=8)
    axes[0][0].set_ylabel("height, m")
    axes[0][0].tick_params(labelsize=7)
    fig.tight_layout(w_pad=0.3)
    save_figure(fig, a.out, dpi=100)    # renamed onto -o: a link there is replaced
    print("wrote %s" % a.out)


def check_output(out):
    """-o: a file name of a format matplotlib writes, in a folder that exists."""
    problem = figure_path_problem(out)
    if problem:
        refuse("-o %s%s" % (out, problem))


if __name__ == "__main__":
    main()
