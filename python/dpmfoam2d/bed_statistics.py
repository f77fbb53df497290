# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Bubbles and particle motion of a dpmFoam2D case, from what it has written:
the numbers behind the paper's argument that a bed with fewer loose regions
segregates less (Norouzi et al. 2012, section 4).

  dpmBedStatistics <case> [-bubbleVoidage 0.8] [-surfaceVoidage 0.7]
                   [-stillSpeed 0.01] [-every 0.1] [-report]

Writes postProcessing/bedStatistics/0/
  bed.dat        from the voidage field of each time directory:
                   bedHeight        m, the bed surface: half-way between the
                                    highest cell row whose mean voidage is
                                    below surfaceVoidage and the row above
                                    (rows: cells at the same height; a
                                    bubble across a row inside the bed does
                                    not end the bed)
                   bubbleFraction   volume fraction of the bed's cells whose
                                    voidage exceeds bubbleVoidage (bubbles)
                   emulsionVoidage  mean voidage of the other bed cells
  particles.dat  from the particle files, one every -every s (a file HDF5
                 cannot read, cut short, is left out with a warning naming
                 it, and the next one read):
                   speedRms<class>  rms speed of the class's particles, m/s
                   still<class>     fraction of them slower than stillSpeed
                   voidage<class>   mean voidage at their centres (the
                                    drag's), when the files hold it
Classes: small (0) and large (1), as the particle files number them.
The voidage is the one the drag sees (3D, after Hoomans' conversion), so
bubbleVoidage 0.8 is the usual CFD-DEM bubble threshold. The cell centres
and volumes are written once into the first time directory by OpenFOAM's
writeCellCentres and writeCellVolumes (source etc/bashrc first).
-report prints a JSON line with the means over the whole run.
"""

from __future__ import annotations

import argparse
import json
import os
import sys

import numpy as np

from . import fields as ff
from . import particles as pio
from .files import replacing

CLASSES = ("Small", "Large")
OUT = os.path.join("postProcessing", "bedStatistics", "0")


def row_levels(y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Index of each cell's row (cells with the same centre height, to
    1e-9 of the mesh height) and the rows' heights, bottom up."""
    span = max(y.max() - y.min(), 1e-300)
    key = np.round((y - y.min()) / span * 1e9).astype(np.int64)
    levels, index = np.unique(key, return_inverse=True)
    heights = np.array([y[index == k].mean() for k in range(len(levels))])
    return index, heights


def bed_row(voidage: np.ndarray, volume: np.ndarray, row: np.ndarray, heights: np.ndarray,
            bubble: float, surface: float) -> tuple[float, float, float]:
    """(bedHeight, bubbleFraction, emulsionVoidage) of one voidage field."""
    nrow = len(heights)
    rowVoidage = np.bincount(row, voidage * volume, nrow) / np.bincount(row, volume, nrow)
    dense = np.nonzero(rowVoidage < surface)[0]
    top = dense[-1] + 1 if len(dense) else 0        # lowest freeboard row
    if top == 0:
        return 0.0, np.nan, np.nan
    height = 0.5 * (heights[top - 1] + heights[top]) if top < nrow \
        else heights[-1] + 0.5 * (heights[-1] - heights[-2])
    inBed = row < top
    isBubble = inBed & (voidage > bubble)
    emulsion = inBed & ~isBubble
    fraction = volume[isBubble].sum() / volume[inBed].sum()
    emulsionVoidage = (voidage[emulsion] * volume[emulsion]).sum() / volume[emulsion].sum() \
        if emulsion.any() else np.nan
    return height, fraction, emulsionVoidage


def bed_table(case: str, bubble: float, surface: float) -> list[tuple]:
    C, V = ff.cell_geometry(case)
    row, heights = row_levels(C[:, 1])
    rows = []
    for t, name in ff.time_dirs(case):
        path = os.path.join(case, name, "voidage")
        if not os.path.isfile(path):
            continue
        eps = ff.internal_field(path, len(V))
        if len(eps) != len(V):
            raise ff.FieldError("%s: %d values for %d cells" % (path, len(eps), len(V)))
        rows.append((t,) + bed_row(eps, V, row, heights, bubble, surface))
    return rows


def particle_table(case: str, still: float, every: float) -> list[list[float]]:
    rows = []
    next_t = -np.inf
    for t, path in pio.list_times(case):
        if t < next_t - 1e-9:
            continue
        try:
            p = pio.read_particles(path)
        except pio.ParticleFileError as e:
            # a series: the file left out, said; the next one read instead
            print("dpmBedStatistics: warning: %s; left out of particles.dat" % e,
                  file=sys.stderr)
            continue
        next_t = t + every
        cls = p["class"]
        v = p["velocity"][:, :2].astype(float)
        eps = p["voidage"].astype(float) if "voidage" in p else None
        speed = np.hypot(v[:, 0], v[:, 1])
        row = [t]
        for k in range(len(CLASSES)):
            s = speed[cls == k]
            row += [np.sqrt((s ** 2).mean()) if len(s) else np.nan,
                    (s < still).mean() if len(s) else np.nan]
        for k in range(len(CLASSES)):
            sel = cls == k
            row.append(eps[sel].mean() if eps is not None and sel.any() else np.nan)
        rows.append(row)
    return rows


def write_table(path, comment, names, rows):
    # a new file renamed onto path: a killed run leaves the previous table
    with replacing(path) as f:
        for line in comment:
            f.write("# %s\n" % line)
        f.write("# " + "\t".join("%-24s" % n for n in names).rstrip() + "\n")
        for r in rows:
            f.write("\t".join("%-24.17g" % v for v in r).rstrip() + "\n")


BED_COLUMNS = ["Time", "bedHeight", "bubbleFraction", "emulsionVoidage"]
PARTICLE_COLUMNS = ["Time"] + [q + c for c in CLASSES for q in ("speedRms", "still")] + \
    ["voidage" + c for c in CLASSES]


class BedStatisticsError(ValueError):
    """A case whose bed statistics cannot be made, with the reason."""


def write_bed_statistics(case: str, bubble: float = 0.8, surface: float = 0.7,
                         still: float = 0.01, every: float = 0.1):
    """bed.dat and particles.dat of the case's postProcessing/bedStatistics/0
    (see the module's usage); returns (bed rows, particle rows, the folder).
    BedStatisticsError for a directory that is no case, or one without
    voidage fields and particle files; ValueError for a field that cannot
    be read."""
    if not os.path.isdir(case):
        raise BedStatisticsError("no case directory %s" % case)
    if not os.path.isfile(os.path.join(case, "system", "controlDict")) \
            and not os.path.isdir(os.path.join(case, "particles")):
        raise BedStatisticsError("%s is not a dpmFoam2D case (no system/controlDict"
                                 " or particles/)" % case)
    bed = bed_table(case, bubble, surface)
    parts = particle_table(case, still, every)
    if not bed and not parts:
        raise BedStatisticsError("%s has no voidage fields and no particle files" % case)
    out = os.path.join(case, OUT)
    os.makedirs(out, exist_ok=True)
    write_table(os.path.join(out, "bed.dat"),
                ["Bed surface, bubbles (cells of voidage > %g) and emulsion, from the "
                 "voidage fields" % bubble,
                 "surfaceVoidage         : %g" % surface],
                BED_COLUMNS, bed)
    write_table(os.path.join(out, "particles.dat"),
                ["Particle motion per class (still: speed < %g m/s) and the voidage "
                 "at the particles" % still],
                PARTICLE_COLUMNS, parts)
    return bed, parts, out


def main():
    ap = argparse.ArgumentParser(prog="dpmBedStatistics", description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("-bubbleVoidage", type=float, default=0.8)
    ap.add_argument("-surfaceVoidage", type=float, default=0.7)
    ap.add_argument("-stillSpeed", type=float, default=0.01)
    ap.add_argument("-every", type=float, default=0.1,
                    help="s between the particle files read (default 0.1)")
    ap.add_argument("-report", action="store_true")
    a = ap.parse_args()

    for name, value, low, high in (("bubbleVoidage", a.bubbleVoidage, 0, 1),
                                   ("surfaceVoidage", a.surfaceVoidage, 0, 1),
                                   ("stillSpeed", a.stillSpeed, 0, np.inf),
                                   ("every", a.every, 0, np.inf)):
        if not low < value < high:
            sys.exit("dpmBedStatistics: -%s %g is outside (%g, %g)" % (name, value, low, high))
    try:
        bed, parts, out = write_bed_statistics(a.case, a.bubbleVoidage, a.surfaceVoidage,
                                               a.stillSpeed, a.every)
    except (ff.FieldError, ValueError) as e:
        sys.exit("dpmBedStatistics: %s" % e)
    print("dpmBedStatistics: %d voidage fields, %d particle files -> %s"
          % (len(bed), len(parts), out))
    if a.report:
        mean = {}
        for names, rows in ((BED_COLUMNS, bed), (PARTICLE_COLUMNS, parts)):
            a = np.array(rows, float).reshape(-1, len(names))
            for n, column in zip(names[1:], a[:, 1:].T):
                finite = column[np.isfinite(column)]
                mean[n] = float(finite.mean()) if len(finite) else None
        print(json.dumps({"fields": len(bed), "particleFiles": len(parts), "mean": mean}))


def command():
    """The console script dpmBedStatistics."""
    main()
