#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The tables of benchmarks/couplingSchedule/Allrun (see there):
  compare.py <work dir> <startTime> <short endTime>"""

import os
import sys

import numpy as np

from dpmfoam2d import particles as pio, tables  # noqa: E402
from dpmfoam2d.statistics import mean_interval  # noqa: E402

BLOCK = 0.5     # s, the block of the block means


def positions(case, t):
    p = pio.read_particles(os.path.join(case, "particles",
                                        pio.time_name(t) + ".h5"))
    order = np.argsort(p["id"])
    return p["position"][order]


def block_mean(time, value, start):
    """Mean and 95 % half-width from the means of BLOCK-s blocks."""
    keep = (time > start + 1e-9) & np.isfinite(value)
    time, value = time[keep], value[keep]
    blocks = np.floor((time - start - 1e-9) / BLOCK).astype(int)
    means = np.array([value[blocks == b].mean() for b in np.unique(blocks)])
    return mean_interval(means, 0.95)


def probe(case):
    """(time, p_rgh) of the probe over all its start times (OpenFOAM's probes
    table: its header names no columns); a restart's rows replace the
    earlier run's from its start on."""
    root = os.path.join(case, "postProcessing", "distributorPressure")
    parts = sorted((float(s), np.loadtxt(os.path.join(root, s, "p_rgh"), ndmin=2))
                   for s in os.listdir(root))
    rows = [part[part[:, 0] < (parts[i + 1][0] if i + 1 < len(parts) else np.inf)]
            for i, (_, part) in enumerate(parts)]
    table = np.concatenate(rows)
    return table[:, 0], table[:, 1]


def series(case):
    out = {}
    out["pressure at the distributor [Pa]"] = probe(case)
    m = tables.read_postprocessing(case, "laceyIndex", "laceyIndex.dat", quiet=True)
    out["Lacey's M"] = (m["Time"], m["M"])
    bed = tables.read_dat(os.path.join(case, "postProcessing", "bedStatistics",
                                    "0", "bed.dat"))
    for k, name in (("bedHeight", "bed height [m]"),
                    ("bubbleFraction", "bubble fraction"),
                    ("emulsionVoidage", "emulsion voidage")):
        out[name] = (bed["Time"], bed[k])
    part = tables.read_dat(os.path.join(case, "postProcessing", "bedStatistics",
                                      "0", "particles.dat"))
    for k, name in (("speedRmsSmall", "rms speed, small [m/s]"),
                    ("speedRmsLarge", "rms speed, large [m/s]")):
        out[name] = (part["Time"], part[k])
    return out


def main():
    work, start, short = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    ref = positions(os.path.join(work, "sequential"), short)
    print("## %.3g s from the state at %g s: particle positions against the"
          " sequential schedule's\n" % (short - start, start))
    print("| run | rms difference [m] | max [m] |\n| --- | --- | --- |")
    for name, label in (("concurrent", "concurrent schedule"),
                        ("halfStep", "sequential, CFD step halved")):
        d = np.linalg.norm(positions(os.path.join(work, name), short) - ref,
                           axis=1)
        print("| %s | %.2g | %.2g |" % (label, np.sqrt((d * d).mean()), d.max()))

    seq, conc = (series(os.path.join(work, n))
                 for n in ("sequential", "concurrent"))
    print("\n## Time means after %g s (95 %% intervals of %g-s block means)\n"
          % (short, BLOCK))
    print("| quantity | sequential | concurrent | intervals overlap |")
    print("| --- | --- | --- | --- |")
    for name in seq:
        a, ha = block_mean(*seq[name], short)
        b, hb = block_mean(*conc[name], short)
        overlap = abs(a - b) <= ha + hb
        print("| %s | %.4g +- %.2g | %.4g +- %.2g | %s |"
              % (name, a, ha, b, hb, "yes" if overlap else "NO"))


if __name__ == "__main__":
    main()
