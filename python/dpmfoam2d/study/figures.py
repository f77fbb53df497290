# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Figures of a dpmStudy's results/: M(t) per pressure and per mass
fraction (the paper's Fig. 3; the mean over seeds with its 95 % band),
the indices and the bed statistics against pressure (error bars: 95 %
intervals over seeds), and the final states side by side (Fig. 2)."""

import os
from collections import OrderedDict

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..pictures.snapshot import snapshot  # noqa: E402
from ..tables import read_postprocessing  # noqa: E402
from . import archive as study_archive, ensemble as ens  # noqa: E402
from ..files import own_directory, save_figure
BASELINE = "baseline"


def prefix(variant):
    return "" if variant == BASELINE else variant + "_"


def curves(dirs, members, name, column):
    out = []
    for r in members:
        T = read_postprocessing(dirs[r["case"]], "laceyIndex", name)
        if T is not None and len(T["Time"]):
            out.append((T["Time"], T[column]))
    return out


def mixing(dirs, groups, labels, title, png):
    """M(t) (top) and the vertical / horizontal indices (bottom) of several
    ensembles: the mean over seeds, a band of the 95 % interval."""
    fig, (axM, axS) = plt.subplots(2, 1, figsize=(7, 7.5), sharex=True,
                                   gridspec_kw={"height_ratios": [3, 2]})
    for i, (members, label) in enumerate(zip(groups, labels)):
        colour = "C%d" % (i % 10)
        n = len(members)
        t, m, h = ens.band(curves(dirs, members, "laceyIndex.dat", "M"))
        if not len(t):
            continue
        axM.plot(t, m, color=colour, lw=1.2,
                 label=label + ("" if n == 1 else " (%d seeds)" % n))
        if n > 1:
            axM.fill_between(t, m - h, m + h, color=colour, alpha=0.25, lw=0)
        for column, style in (("vertical", "-"), ("horizontal", "--")):
            t, m, h = ens.band(curves(dirs, members, "segregation.dat", column))
            axS.plot(t, m, style, color=colour, lw=1.0)
            if n > 1:
                axS.fill_between(t, m - h, m + h, color=colour, alpha=0.2, lw=0)
    axM.set_ylabel("Lacey index M")
    axM.set_ylim(bottom=0)
    axM.grid(alpha=0.3)
    axM.legend(fontsize=8)
    axM.set_title(title)
    axS.axhline(0, color="k", lw=0.5)
    axS.set_ylabel("segregation index\n(vertical -, horizontal --)")
    axS.set_xlabel("time (s)")
    axS.grid(alpha=0.3)
    fig.tight_layout()
    save_figure(fig, png, dpi=110)
    plt.close(fig)


def against_pressure(ensemble, variant, panels, png, X):
    """Panels of quantities against pressure, a line per mass fraction,
    error bars of the 95 % interval where there are seeds."""
    sel = [e for e in ensemble if e["variant"] == variant]
    ws = sorted({e["wSmall"] for e in sel})
    ps = sorted({e["pressure"] for e in sel})
    fig, axes = plt.subplots(1, len(panels), figsize=(4.4 * len(panels), 4))
    for i, w in enumerate(ws):
        rows = sorted((e for e in sel if e["wSmall"] == w), key=lambda e: e["pressure"])
        x = [e["pressure"] for e in rows]
        for ax, (keys, name) in zip(axes, panels):
            for k, style in zip(keys, ("o-", "s--")):
                y = np.array([e[k] for e in rows], float)
                err = np.array([e[k + "CI"] for e in rows], float)
                ax.errorbar(x, y, yerr=np.where(np.isfinite(err), err, 0), fmt=style,
                            color="C%d" % i, capsize=3,
                            label="w_small %g" % w if k == keys[0] else None)
    for ax, (keys, name) in zip(axes, panels):
        ax.set_xscale("log")
        ax.set_xticks(ps)
        ax.set_xticklabels(["%g" % p for p in ps])
        ax.set_xlabel("pressure (bar)")
        ax.set_ylabel(name)
        ax.grid(alpha=0.3)
        ax.axhline(0, color="k", lw=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle("%s: means of the last %g s over seeds (bars: 95 %% interval)"
                 % (variant, X), fontsize=9)
    fig.tight_layout()
    save_figure(fig, png, dpi=110)
    plt.close(fig)


def figures(rows, ensemble, dirs, out, X, pictures=True):
    groups = OrderedDict()
    for r in rows:
        groups.setdefault((r["variant"], r["wSmall"], r["pressure"]), []).append(r)
    for variant in OrderedDict.fromkeys(r["variant"] for r in rows):
        ws = sorted({w for v, w, p in groups if v == variant})
        ps = sorted({p for v, w, p in groups if v == variant})
        title = "" if variant == BASELINE else variant + ", "
        for p in ps:        # the paper's Fig. 3: M(t) at one pressure
            keys = [(variant, w, p) for w in ws if (variant, w, p) in groups]
            mixing(dirs, [groups[k] for k in keys], ["w_small %g" % k[1] for k in keys],
                   "%s%g bar" % (title, p),
                   os.path.join(out, "mixing_%s%gbar.png" % (prefix(variant), p)))
        for w in ws:
            keys = [(variant, w, p) for p in ps if (variant, w, p) in groups]
            mixing(dirs, [groups[k] for k in keys], ["%g bar" % k[2] for k in keys],
                   "%sw_small %g" % (title, w),
                   os.path.join(out, "mixing_%sw%.2f.png" % (prefix(variant), w)))
        against_pressure(ensemble, variant,
                         [(("Mmean",), "Lacey M (mean of last %g s)" % X),
                          (("vertical",), "vertical index"),
                          (("horizontal",), "horizontal index")],
                         os.path.join(out, "%sindices.png" % prefix(variant)), X)
        against_pressure(ensemble, variant,
                         [(("bubbleFraction",), "bubble fraction of the bed"),
                          (("emulsionVoidage",), "emulsion voidage"),
                          (("speedRmsSmall", "speedRmsLarge"),
                           "rms speed (m/s): small o-, large s--")],
                         os.path.join(out, "%shydrodynamics.png" % prefix(variant)), X)
    print("results: figures in %s" % out, flush=True)
    if pictures:
        snapshots(rows, groups, dirs, out)


def snapshots(rows, groups, dirs, out):
    """Final states side by side (the paper's Fig. 2): rows w, columns p;
    the first seed of each ensemble run here (a summary case, imported,
    has no particle files to picture)."""
    snaps = os.path.join(out, "snapshots")
    own_directory(snaps)
    for variant in OrderedDict.fromkeys(r["variant"] for r in rows):
        ws = sorted({w for v, w, p in groups if v == variant})
        ps = sorted({p for v, w, p in groups if v == variant})
        fig, axes = plt.subplots(len(ws), len(ps), squeeze=False,
                                 figsize=(2.2 * len(ps), 3.2 * len(ws)))
        for i, w in enumerate(ws):
            for k, p in enumerate(ps):
                ax = axes[i][k]
                ax.axis("off")
                if (variant, w, p) not in groups:
                    continue
                pictured = [r for r in groups[variant, w, p]
                            if not study_archive.is_summary(dirs[r["case"]])]
                if not pictured:
                    print("results: no snapshot of %s: a summary case (imported), "
                          "without particle files" % groups[variant, w, p][0]["case"],
                          flush=True)
                    continue
                first = pictured[0]
                png = snapshot(dirs[first["case"]], height=700,
                               out=os.path.join(snaps, first["case"] + ".png"))
                ax.imshow(plt.imread(png))
                ax.set_title("w %g, %g bar" % (w, p) +
                             ("" if not first["seed"] else ", seed %s" % first["seed"]),
                             fontsize=9)
        fig.tight_layout()
        png = os.path.join(out, "%ssnapshots.png" % prefix(variant))
        save_figure(fig, png, dpi=130)
        plt.close(fig)
        print("results: %s" % png, flush=True)
