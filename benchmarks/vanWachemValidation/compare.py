#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Runs of van Wachem et al.'s (2001) pseudo-2D bed against the experiment
and against Lethe's reported outcome (README.md).

  compare.py <case> | --run <label>=<case> [--run ...] [--reference <dir>]
             [--transient 2] [--until <s>] [--window <s>] [--figures <dir>]
             [--table <file.md>]

For each run (tutorials/vanWachemBed, tutorials/vanWachemBed2D or a
bracket of either) and for the experiment's digitized curves: the mean, rms
and peak-to-peak of the pressure fluctuation 45 mm above the distributor,
its dominant frequency and the peak of its spectrum; the mean bed height,
its rms (the amplitude), its range and dominant frequency; the highest
particle (Lethe's measure). Each run's figure is marked within or outside
the tolerances below, which were fixed before the first long run. The
figures (time series over the experiment's windows, spectra on log axes)
go to <dir> (default <first case>/validationFigures).
"""

import argparse
import os
import sys

import numpy as np

import vanWachemData as data
import vanWachemFigures as figures
from dpmfoam2d.statistics import dominant_frequency, spectrum

# Fixed before the first long run: |ours - experiment| / experiment
TOLERANCES = {
    "pressureFrequency": 0.10,
    "pressureRms": 0.25,
    "heightFrequency": 0.10,
    "heightRms": 0.25,          # the bed height's amplitude
    "heightMean": 0.10,
}

# The experiment's records (SOURCES.md of the reference folder), s
WINDOWS = {"pressure": (3.0, 6.0), "height": (2.0, 4.0)}
# Both signals on a uniform grid: the pressure at the experiment's sampling
# rate, the bed height at the particle files' 100 Hz; each sample the mean
# of the linear interpolant over its interval (a denser record is averaged,
# a sparser one, the digitized curves, interpolated)
RATES = {"pressure": 1000.0, "height": 100.0}
# The spectrum (dpmfoam2d.statistics.spectrum): Welch's, Hann segments of
# half the experiment's record, 50 % overlap (three segments of the
# experiment's, more of a longer run's, the same bins). The dominant
# frequency: the whole record as one segment (the Hann periodogram), whose
# resolution 1/record a 3-s record needs, zero-padded to FREQUENCY_STEP
SEGMENTS = {"pressure": 1.5, "height": 1.0}
FREQUENCY_STEP = 0.01           # Hz, the zero-padded periodogram's grid
MIN_SAMPLES = 8                 # of a record on its grid, for any statistics

# Lethe's outcome for this experiment, as its documentation states it
# (doc/source/examples/unresolved-cfd-dem/pseudo-2d-gas-solid-fluidized-bed/
# pseudo-2d-gas-solid-fluidized-bed.rst in chaos-polymtl/lethe): no numbers
LETHE = {
    "pressureMean": "-",
    "pressureRms": "below exp.",
    "pressurePeakToPeak": "below exp.",
    "pressureFrequency": "as exp.",
    "pressureSpectrumPeak": "orders of magnitude below",
    "heightMean": "not stated",
    "heightRms": "below exp.",
    "heightRange": "below exp.",
    "heightFrequency": "as exp.",
    "maxHeightMean": "its measure",
    "maxHeightRms": "-",
}

# Compared without a tolerance: as a ratio (spans decades) or a difference
RATIO_ONLY = ("pressureSpectrumPeak",)
DIFFERENCE_ONLY = ("pressurePeakToPeak", "heightRange")

ROWS = [  # key, label, unit, scale for printing
    ("pressureMean", "pressure: mean (exp.: removed)", "Pa", 1),
    ("pressureRms", "pressure: rms fluctuation", "Pa", 1),
    ("pressurePeakToPeak", "pressure: peak-to-peak", "Pa", 1),
    ("pressureFrequency", "pressure: dominant frequency", "Hz", 1),
    ("pressureSpectrumPeak", "pressure: spectrum's peak", "Pa2/Hz", 1),
    ("heightMean", "bed height (99 %): mean", "mm", 1e3),
    ("heightRms", "bed height: rms (amplitude)", "mm", 1e3),
    ("heightRange", "bed height: range", "mm", 1e3),
    ("heightFrequency", "bed height: dominant frequency", "Hz", 1),
    ("maxHeightMean", "highest particle: mean", "mm", 1e3),
    ("maxHeightRms", "highest particle: rms", "mm", 1e3),
]


def uniform(t, x, rate):
    """(t, x) on a grid of 1/rate: each sample the mean of the linear
    interpolant of x over its interval."""
    edges = np.arange(t[0], t[-1] + 1e-12, 1.0 / rate)
    if len(edges) < 2:
        return np.zeros(0), np.zeros(0)
    # the interpolant is linear between the union of samples and edges
    knots = np.union1d(t, edges)
    v = np.interp(knots, t, x)
    area = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(knots))])
    mean = np.diff(area[np.searchsorted(knots, edges)]) * rate
    return 0.5 * (edges[1:] + edges[:-1]), mean


def signal_statistics(t, x, kind):
    """Mean, rms, peak-to-peak (median over windows of the experiment's
    record length), dominant frequency and Welch spectrum of one record."""
    rate = RATES[kind]
    tu, xu = uniform(t, x, rate)
    if len(xu) < MIN_SAMPLES:
        return None
    s = {"t": tu, "x": xu, "mean": xu.mean(), "rms": xu.std(),
         "span": len(xu) / rate}
    n = int(round((WINDOWS[kind][1] - WINDOWS[kind][0]) * rate))
    chunks = [xu[k:k + n] for k in range(0, len(xu) - n + 1, n)] or [xu]
    s["peakToPeak"] = float(np.median([np.ptp(c) for c in chunks]))
    # one cycle per experiment's record: the lowest frequency it shows (the
    # same band for the experiment and the runs); the resolution 1/record
    s["frequency"], s["resolution"] = dominant_frequency(
        xu, rate, lowest=1.0 / (WINDOWS[kind][1] - WINDOWS[kind][0]), step=FREQUENCY_STEP)
    s["f"], s["psd"] = spectrum(xu, rate, segment=SEGMENTS[kind])
    s["spectrumPeak"] = s["psd"][1:].max()
    return s


def run_records(case):
    """The run's pressure at the probe and its bed heights: (tp, p), (th, h, hmax)."""
    return data.pressure_probe(case), data.bed_heights(case)


def run_statistics(case, transient, until=None, records=None):
    """The table's figures of one run, after the transient and up to until
    (default its end), or over the second half of a run too short for it,
    with a note. records: run_records(case), read once for many windows."""
    (tp, p), (th, h, hmax) = records or run_records(case)
    end = min(tp[-1], th[-1])
    if until is not None:
        if until > end + 1e-9:
            raise ValueError("%s: --until %g s: the run ends at %.4g s" % (case, until, end))
        end = until
        keep = tp <= end + 1e-9
        tp, p = tp[keep], p[keep]
        keep = th <= end + 1e-9
        th, h, hmax = th[keep], h[keep], hmax[keep]
    start = transient
    if end - start < MIN_SAMPLES / RATES["height"]:
        start = 0.5 * end
        print("note: %s: %.4g s of gas, too short for statistics after the transient "
              "%g s: statistics over its second half (a check of the machinery, not of "
              "the bed)" % (case, end, transient), file=sys.stderr)
    out = {"start": start, "end": end, "records": {}}
    keep = tp >= start - 1e-9
    ps = signal_statistics(tp[keep], p[keep], "pressure")
    keep = th >= start - 1e-9
    hs = signal_statistics(th[keep], h[keep], "height")
    ms = signal_statistics(th[keep], hmax[keep], "height")
    if ps:
        out["records"]["pressure"] = ps
        out.update(pressureMean=ps["mean"], pressureRms=ps["rms"],
                   pressurePeakToPeak=ps["peakToPeak"], pressureFrequency=ps["frequency"],
                   pressureFrequencyResolution=ps["resolution"],
                   pressureSpectrumPeak=ps["spectrumPeak"])
    if hs:
        out["records"]["height"] = hs
        out["records"]["maxHeight"] = ms
        out.update(heightMean=hs["mean"], heightRms=hs["rms"], heightRange=hs["peakToPeak"],
                   heightFrequency=hs["frequency"], heightFrequencyResolution=hs["resolution"],
                   maxHeightMean=ms["mean"], maxHeightRms=ms["rms"])
    return out


def window_statistics(case, transient, until, window, step=1.0):
    """Each figure of one run over windows of window s, starting every step
    s from transient to until (default the run's end): the median and the
    range over the windows, the scatter a chaotic bed shows between records
    as long as the window."""
    records = run_records(case)
    whole = run_statistics(case, transient, until, records)
    end = whole["end"]
    starts = np.arange(transient, end - window + 1e-9, step)
    if len(starts) < 2:
        raise ValueError("%s: --window %g s: the record %.4g-%.4g s holds fewer than two "
                         "windows" % (case, window, transient, end))
    parts = [run_statistics(case, t0, t0 + window, records) for t0 in starts]
    out = dict(whole, windows=len(parts), window=window)
    for key in ("pressureFrequencyResolution", "heightFrequencyResolution"):
        if key in parts[0]:
            out[key] = parts[0][key]        # a window's, 1/window
    for key, _, _, _ in ROWS:
        values = [p[key] for p in parts if key in p]
        if values:
            out[key] = float(np.median(values))
            out[key + "Range"] = (min(values), max(values))
    return out


def experiment_statistics(ref):
    ps = signal_statistics(*ref["pressure"], "pressure")
    hs = signal_statistics(*ref["height"], "height")
    return {"records": {"pressure": ps, "height": hs},
            "pressureMean": ps["mean"], "pressureRms": ps["rms"],
            "pressurePeakToPeak": ps["peakToPeak"], "pressureFrequency": ps["frequency"],
            "pressureFrequencyResolution": ps["resolution"],
            "pressureSpectrumPeak": ps["spectrumPeak"],
            "heightMean": hs["mean"], "heightRms": hs["rms"], "heightRange": hs["peakToPeak"],
            "heightFrequency": hs["frequency"], "heightFrequencyResolution": hs["resolution"]}


def verdict(key, ours, experiment):
    """'+12 % within' against the experiment, or '' where no tolerance."""
    if experiment is None or key not in experiment or key not in ours:
        return ""
    if key in RATIO_ONLY:
        return "x %.2g" % (ours[key] / experiment[key])
    if key not in TOLERANCES and key not in DIFFERENCE_ONLY:
        return ""
    rel = (ours[key] - experiment[key]) / abs(experiment[key])
    if key not in TOLERANCES:
        return "%+.0f %%" % (100 * rel)
    return "%+.0f %% %s" % (100 * rel, "within" if abs(rel) <= TOLERANCES[key] else "OUTSIDE")


def table(runs, experiment):
    """Rows of strings: quantity, unit, experiment, each run (value, verdict), Lethe."""
    head = ["quantity", "unit", "experiment"]
    for label, _ in runs:
        head += [label, ""]
    head += ["Lethe (reported)", "tolerance"]
    rows = [head]
    for key, label, unit, scale in ROWS:
        def value(s):
            if s is None or key not in s:
                return "-"
            if key + "Range" in s:
                lo, hi = s[key + "Range"]
                return "%.4g (%.3g-%.3g)" % (scale * s[key], scale * lo, scale * hi)
            return "%.4g" % (scale * s[key])
        row = [label, unit, value(experiment)]
        for _, s in runs:
            row += [value(s), verdict(key, s, experiment)]
        tol = TOLERANCES.get(key)
        row += [LETHE[key], "%.0f %%" % (100 * tol) if tol else ""]
        rows.append(row)
    return rows


def print_table(rows):
    widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
    for r in rows:
        print("  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip())


def write_markdown(path, rows, notes):
    with open(path, "w") as f:
        f.write("| " + " | ".join(rows[0]) + " |\n")
        f.write("|" + " --- |" * len(rows[0]) + "\n")
        for r in rows[1:]:
            f.write("| " + " | ".join(r) + " |\n")
        for n in notes:
            f.write("\n" + n + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("case", nargs="?", help="one run (label: its directory's name)")
    ap.add_argument("--run", action="append", default=[], metavar="LABEL=CASE",
                    help="a run and its label in the table; repeat for brackets")
    ap.add_argument("--reference", help="the experiment's digitized curves (default "
                    "%s)" % data.default_reference())
    ap.add_argument("--transient", type=float, default=2.0,
                    help="s of gas before the statistics (default 2: the experiment's "
                    "records begin at 2 s)")
    ap.add_argument("--until", type=float,
                    help="s of gas at which the statistics end (default each run's end): "
                    "runs of different lengths compared over one window")
    ap.add_argument("--window", type=float,
                    help="s of each window: every figure of a run as the median (and "
                    "range) over windows starting every second (default: one record)")
    ap.add_argument("--figures", help="folder of the PNG figures (default "
                    "<first case>/validationFigures)")
    ap.add_argument("--table", help="also write the table as Markdown to this file")
    a = ap.parse_args()

    specs = [(os.path.basename(os.path.normpath(a.case)), a.case)] if a.case else []
    for spec in a.run:
        label, sep, case = spec.partition("=")
        if not sep or not label or not case:
            ap.error("--run %s: expected <label>=<case directory>" % spec)
        specs.append((label, case))
    if not specs:
        ap.error("no run: give a case directory or --run <label>=<case>")
    if len({label for label, _ in specs}) < len(specs):
        ap.error("two runs have the same label: %s" % " ".join(l for l, _ in specs))

    experiment = None
    folder = a.reference or data.default_reference()
    if a.reference or os.path.isdir(folder):
        try:
            experiment = experiment_statistics(data.reference(folder))
        except (OSError, ValueError) as e:
            sys.exit("compare.py: %s" % e)
    else:
        print("note: no reference folder %s: the experiment's column and the verdicts "
              "are left out (the digitized curves are in %s; give their folder with "
              "--reference)" % (folder, data.REFERENCE_ORIGIN), file=sys.stderr)

    runs = []
    for label, case in specs:
        try:
            data.pio.check_case(case)
            if a.window:
                runs.append((label, window_statistics(case, a.transient, a.until,
                                                      a.window)))
            else:
                runs.append((label, run_statistics(case, a.transient, a.until)))
        except (OSError, ValueError) as e:
            sys.exit("compare.py: %s" % e)

    print("van Wachem et al. (2001): 45 mm above the distributor; bed height: the "
          "height below which %g %% of the particles' tops lie" % (100 * data.BED_FRACTION))
    for (label, case), (_, s) in zip(specs, runs):
        print("  %s: %s, statistics over %.4g-%.4g s%s" % (
            label, case, s["start"], s["end"],
            ", median (range) of %d windows of %g s" % (s["windows"], s["window"])
            if "windows" in s else ""))
    if experiment:
        print("  experiment: %s (pressure %g-%g s, bed height %g-%g s)"
              % (folder, *WINDOWS["pressure"], *WINDOWS["height"]))
    rows = table(runs, experiment)
    print_table(rows)
    notes = ["Frequency resolution (1/record): " + ", ".join(
        "%s %.2g Hz (pressure), %.2g Hz (bed height)"
        % (label, s.get("pressureFrequencyResolution", np.nan),
           s.get("heightFrequencyResolution", np.nan))
        for label, s in ([("experiment", experiment)] if experiment else []) + runs)]
    for n in notes:
        print(n)

    out = a.figures or os.path.join(specs[0][1], "validationFigures")
    os.makedirs(out, exist_ok=True)
    for path in figures.draw(out, runs, experiment, WINDOWS):
        print("wrote %s" % path)
    if a.table:
        write_markdown(a.table, rows, notes)
        print("wrote %s" % a.table)


if __name__ == "__main__":
    main()
