# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The comparison's figures: the time series side by side over the
experiment's windows (timeSeries.png) and the spectra on log axes
(spectra.png)."""

import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SIGNALS = [  # record, title, unit, scale
    ("pressure", "pressure fluctuation at 45 mm", "Pa", 1.0),
    ("height", "bed height", "mm", 1e3),
]


def window_of(record, window):
    """The record over the experiment's window if the run covers it, else
    over its last span of the window's length (or all of it)."""
    t, x = record["t"], record["x"]
    a, b = window
    if t[0] <= a + 0.01 and t[-1] >= b - 0.01:
        keep = (t >= a) & (t <= b)
    else:
        keep = t >= t[-1] - (b - a)
    return t[keep], x[keep]


def draw(folder, runs, experiment, windows):
    """Write the two PNG figures to folder; return their paths."""
    columns = ([("experiment", experiment)] if experiment else []) + list(runs)
    fig, axes = plt.subplots(len(SIGNALS), len(columns), squeeze=False,
                             figsize=(4 * len(columns), 3.2 * len(SIGNALS)))
    for row, (key, title, unit, scale) in enumerate(SIGNALS):
        for col, (label, s) in enumerate(columns):
            ax = axes[row, col]
            record = s["records"].get(key)
            if record is None:
                ax.set_axis_off()
                continue
            t, x = window_of(record, windows[key])
            mean = record["mean"] if key == "pressure" else 0.0
            measured = col == 0 and experiment is not None
            ax.plot(t, scale * (x - mean), lw=0.8, color="k" if measured else None,
                    label="99 % of the particles" if key == "height" and not measured else None)
            if key == "height" and "maxHeight" in s["records"]:
                tm, xm = window_of(s["records"]["maxHeight"], windows[key])
                ax.plot(tm, scale * xm, lw=0.6, ls="--", label="highest particle")
                ax.legend(fontsize=7, loc="lower right")
            ax.set_title("%s: %s" % (label, title), fontsize=8)
            ax.set_xlabel("t (s)")
            ax.set_ylabel(unit)
        # one scale along the row, so that the amplitudes compare by eye
        lims = [ax.get_ylim() for ax in axes[row] if ax.axison]
        for ax in axes[row]:
            if ax.axison:
                ax.set_ylim(min(l[0] for l in lims), max(l[1] for l in lims))
    fig.tight_layout()
    series = os.path.join(folder, "timeSeries.png")
    fig.savefig(series, dpi=110)
    plt.close(fig)

    fig, axes = plt.subplots(1, len(SIGNALS), figsize=(5 * len(SIGNALS), 3.6))
    for ax, (key, title, unit, scale) in zip(axes, SIGNALS):
        for col, (label, s) in enumerate(columns):
            record = s["records"].get(key)
            if record is None:
                continue
            f, psd = record["f"][1:], scale ** 2 * record["psd"][1:]
            ax.loglog(f, np.maximum(psd, 1e-300), lw=1.2 if col == 0 and experiment else 0.8,
                      color="k" if col == 0 and experiment else None, label=label)
        ax.set_title("Welch spectrum: %s" % title, fontsize=8)
        ax.set_xlabel("f (Hz)")
        ax.set_ylabel("%s2/Hz" % unit)
        if ax.lines:
            ax.legend(fontsize=7)
            # ten decades below the highest peak: round-off floors out of sight
            top = max(np.max(l.get_ydata()) for l in ax.lines)
            ax.set_ylim(bottom=1e-10 * top)
    fig.tight_layout()
    spectra = os.path.join(folder, "spectra.png")
    fig.savefig(spectra, dpi=110)
    plt.close(fig)
    return [series, spectra]
