#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Goldschmidt slab run by DPMFoam and by dpmFoam2D (./Allrun): wall
times, and the bed's statistics measured alike from both runs.

  compare.py <run dir> [-transient 1]

From <run>/DPMFoam and <run>/dpmFoam2D (either may be missing):
  wall time per simulated second (their 'timing' files, written by Allrun)
  bed height       every written voidage field (DPMFoam alpha.air, ours
                   voidage): the surface of dpmBedStatistics (half-way
                   between the highest row of cells whose mean voidage is
                   below 0.7 and the row above) and twice the solids'
                   centroid height; mean and rms after the transient
  pressure drop    the pressure at the distributor (areaAverage, every
                   1e-4 s) less the gas's own head: DPMFoam rho p - rho g H
                   (its p is kinematic and holds the head), ours p_rgh;
                   mean, rms and the dominant frequency (peak of Welch's
                   spectrum, 2-s Hann windows, 50 % overlap)
Then the differences against the tolerances of README.md, when both runs
have at least MIN_STATS s of statistics.
"""

import argparse
import glob
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.realpath(__file__))
from dpmfoam2d import bed_statistics as bedStats, fields as ff  # noqa: E402
from dpmfoam2d.statistics import dominant_frequency  # noqa: E402

# The tutorial's spheres and gas (constant/kinematicCloudProperties,
# transportProperties) and its box's depth and height (blockMeshDict); the
# sphere count and the width are read from the run (Allrun's LATTICE_COLUMNS
# and LATTICE_LAYERS cut them)
D, RHO_P, RHO_G, G = 2.5e-3, 2526.0, 1.2, 9.81
DEPTH, HEIGHT = 0.015, 0.45

# README.md, "Tolerances" (fixed before the first long run)
TOLERANCES = {                     # |DPMFoam - dpmFoam2D| / dpmFoam2D
    "bedHeightMean": 0.10,
    "bedHeightRms": 0.30,
    "pressureDropMean": 0.05,
    "pressureDropRms": 0.30,
    "frequency": 0.25,             # or one bin of the spectrum, if larger
}
PRESSURE_VS_WEIGHT = 0.05          # each mean pressure drop against W/A
MIN_STATS = 2.0                    # s of statistics the comparison needs
WINDOW = 2.0                       # s, Welch's window

SOLVERS = {
    # name: (voidage field, vertical axis, pressure -> Pa less the gas head)
    "DPMFoam": ("alpha.air", 2, lambda p: RHO_G * p - RHO_G * G * HEIGHT),
    "dpmFoam2D": ("voidage", 1, lambda p: p),
}


def bed_size(run):
    """(spheres, box width [m]) of the run's cases, which must agree: the
    positions each case starts from, and the mesh's volume over depth x
    height."""
    sizes = {}
    for name, positions, pattern in (
            ("DPMFoam", "kinematicCloudPositions", r"^\(\S+ \S+ \S+\)\s*$"),
            ("dpmFoam2D", "latticePositions", r"^\d+ \S+ \S+ \S+\s*$")):
        case = os.path.join(run, name)
        path = os.path.join(case, "constant", positions)
        if not os.path.isfile(path):
            continue
        n = len(re.findall(pattern, open(path).read(), re.M))
        _, V = ff.cell_geometry(case)
        sizes[name] = (n, round(V.sum() / (DEPTH * HEIGHT), 6))
    if len(set(sizes.values())) > 1:
        sys.exit("%s: the cases hold different beds (spheres, width): %s" % (run, sizes))
    if not sizes:
        sys.exit("%s: no DPMFoam or dpmFoam2D case" % run)
    return next(iter(sizes.values()))


def pressure_record(case, convert):
    """(t, pressure drop [Pa]) of the inletPressure function object, the
    files of a continued run merged (a later start replaces what an earlier
    run wrote past it)."""
    rows = {}
    files = glob.glob(os.path.join(case, "postProcessing", "inletPressure", "*",
                                   "surfaceFieldValue*.dat"))
    for path in sorted(files, key=lambda p: (float(p.split(os.sep)[-2]), p)):
        a = np.loadtxt(path, comments="#", ndmin=2)
        if a.size == 0:
            continue
        for t in [k for k in rows if k >= a[0, 0] - 1e-9]:
            del rows[t]
        rows.update(zip(a[:, 0], a[:, 1]))
    t = np.array(sorted(rows))
    return t, convert(np.array([rows[k] for k in t]))


def bed_record(case, field, axis):
    """(t, surface height, 2 x centroid height) of every written voidage field."""
    C, V = ff.cell_geometry(case)
    h = C[:, axis]
    row, heights = bedStats.row_levels(h)
    out = []
    for t, name in ff.time_dirs(case):
        path = os.path.join(case, name, field)
        if t <= 0 or not os.path.isfile(path):
            continue
        eps = ff.internal_field(path, len(V))
        surface = bedStats.bed_row(eps, V, row, heights, 0.8, 0.7)[0]
        solid = (1 - eps) * V
        out.append((t, surface, 2 * (solid * h).sum() / solid.sum()))
    return np.array(out).reshape(-1, 3)


def wall_times(case):
    """(wall s, simulated s, load averages) summed over the case's runs."""
    path = os.path.join(case, "timing")
    if not os.path.isfile(path):
        return np.nan, np.nan, []
    wall = sim = 0.0
    loads = []
    for line in open(path):
        w = line.split(None, 3)
        wall += float(w[0])
        sim += float(w[2]) - float(w[1])
        loads.append(w[3].strip())
    return wall, sim, loads


def loop_cpu(case, name):
    """CPU s per simulated s of the time loop, start-up left out: OpenFOAM's
    ExecutionTime from the first step to the last in log.<solver> (both
    solvers print it; one thread each)."""
    path = os.path.join(case, "log." + name)
    if not os.path.isfile(path):
        return np.nan, 0
    text = open(path).read()
    steps = re.findall(r"^Time = (\S+)\s*$(.*?)^ExecutionTime = (\S+) s", text, re.M | re.S)
    if len(steps) < 2:
        return np.nan, len(steps)
    t = np.array([float(s[0]) for s in steps])
    cpu = np.array([float(s[2]) for s in steps])
    # a continued run restarts the clock: add up the runs' own spans
    total = sim = 0.0
    for k in range(1, len(t)):
        if cpu[k] >= cpu[k - 1] and t[k] > t[k - 1]:
            total += cpu[k] - cpu[k - 1]
            sim += t[k] - t[k - 1]
    return total / sim, len(steps)


def statistics(case, name, transient):
    field, axis, convert = SOLVERS[name]
    s = {}
    s["wall"], s["sim"], s["loads"] = wall_times(case)
    s["loopCpu"], s["steps"] = loop_cpu(case, name)
    t, dp = pressure_record(case, convert)
    keep = t > transient + 1e-9
    # the span the samples cover, each standing for one sampling interval
    # (0.5001 .. 2.5 by 1e-4 is 2 s of record)
    s["pressureSpan"] = (t[keep][-1] - t[keep][0] + np.median(np.diff(t[keep]))
                         if keep.sum() > 1 else 0.0)
    if keep.sum() > 1:
        s["pressureDropMean"] = dp[keep].mean()
        s["pressureDropRms"] = dp[keep].std()
        # the peak of Welch's spectrum (WINDOW-s segments) and its bin width
        s["frequency"], s["bin"] = dominant_frequency(
            dp[keep], 1.0 / np.median(np.diff(t[keep])), segment=WINDOW)
    bed = bed_record(case, field, axis)
    keep = bed[:, 0] > transient + 1e-9
    s["fields"] = int(keep.sum())
    if keep.any():
        s["bedHeightMean"], s["centroidHeightMean"] = bed[keep, 1:].mean(axis=0)
        s["bedHeightRms"], s["centroidHeightRms"] = bed[keep, 1:].std(axis=0)
    return s


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run")
    ap.add_argument("-transient", type=float, default=None,
                    help="s before the statistics (default 1, or half the run if shorter)")
    a = ap.parse_args()

    n, width = bed_size(a.run)
    weight_per_area = n * np.pi / 6 * D ** 3 * (RHO_P - RHO_G) * G / (width * DEPTH)
    stats = {}
    for name in SOLVERS:
        case = os.path.join(a.run, name)
        if not os.path.isdir(case):
            continue
        times = [t for t, _ in ff.time_dirs(case)]
        end = max(times) if times else 0.0
        transient = a.transient if a.transient is not None else min(1.0, 0.5 * end)
        stats[name] = statistics(case, name, transient)
        stats[name]["transient"] = transient

    print()
    print("Goldschmidt slab: %d spheres of %g mm, %g mm wide, W/A (weight less buoyancy"
          " per area) %.1f Pa" % (n, 1e3 * D, 1e3 * width, weight_per_area))
    for name, s in stats.items():
        print("%s:" % name)
        print("  wall time %.1f s for %.4g simulated s: %.0f wall s per simulated s"
              " (load before each run: %s)"
              % (s["wall"], s["sim"], s["wall"] / s["sim"], "; ".join(s["loads"])))
        print("  time loop: %.0f CPU s per simulated s (ExecutionTime over %d steps)"
              % (s["loopCpu"], s["steps"]))
        print("  statistics after %g s: %d voidage fields, %.3g s of pressure"
              % (s["transient"], s["fields"], s["pressureSpan"]))
        if "bedHeightMean" in s:
            print("  bed height     %.4f m, rms %.4f m (2 x centroid %.4f m, rms %.4f m)"
                  % (s["bedHeightMean"], s["bedHeightRms"],
                     s["centroidHeightMean"], s["centroidHeightRms"]))
        if "pressureDropMean" in s:
            print("  pressure drop  %.1f Pa (%.3f W/A), rms %.1f Pa; dominant frequency"
                  " %.2f Hz (bin %.2f Hz)"
                  % (s["pressureDropMean"], s["pressureDropMean"] / weight_per_area,
                     s["pressureDropRms"], s["frequency"], s["bin"]))
    if len(stats) < 2:
        return
    of, us = stats["DPMFoam"], stats["dpmFoam2D"]
    print("Ratio of wall times per simulated s, DPMFoam / dpmFoam2D: %.1f"
          " (time loops' CPU: %.1f)"
          % ((of["wall"] / of["sim"]) / (us["wall"] / us["sim"]),
             of["loopCpu"] / us["loopCpu"]))
    short = min(of["pressureSpan"], us["pressureSpan"])
    if short < MIN_STATS:
        print("Too short to compare the beds: %.3g s of statistics, %g s needed"
              % (short, MIN_STATS))
        return
    ok = True
    for key, tol in TOLERANCES.items():
        if tol is None or key not in of or key not in us:
            continue
        diff = abs(of[key] - us[key])
        allowed = tol * abs(us[key])
        if key == "frequency":
            allowed = max(allowed, of["bin"])
        good = diff <= allowed
        ok &= good
        print("  %-17s DPMFoam %10.4g  dpmFoam2D %10.4g  difference %6.1f %%  "
              "tolerance %4.0f %%  %s" % (key, of[key], us[key], 100 * diff / abs(us[key]),
                                          100 * allowed / abs(us[key]),
                                          "within" if good else "OUTSIDE"))
    for name, s in stats.items():
        r = s["pressureDropMean"] / weight_per_area - 1
        good = abs(r) <= PRESSURE_VS_WEIGHT
        ok &= good
        print("  %-9s mean pressure drop / (W/A) - 1 = %+.3f (tolerance %g): %s"
              % (name, r, PRESSURE_VS_WEIGHT, "within" if good else "OUTSIDE"))
    print("All within the tolerances" if ok else "Some differences are outside the tolerances")


if __name__ == "__main__":
    main()
