#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The voidage the spheres see in each code, and the drag it gives them.

  voidageSeen.py <run dir> [-transient 0.5] [-every 1]

For the written times after the transient of <run>/DPMFoam (positions in
lagrangian/kinematicCloud) and <run>/dpmFoam2D (particles/<t>.h5), particle
means of two voidages at each sphere:
  field    the one the code's drag used: its own field in the sphere's cell
           (DPMFoam alpha.air: the volume of the spheres whose centre is in
           the cell, 2 cells across the depth; dpmFoam2D voidage: the
           spheres' volume in each one-cell-thick column)
  column   the spheres' volume in one-cell-thick columns of the case's
           in-plane cells, computed here from the same positions by
           quadrature over the plane (pixels of 0.1 mm, each holding the
           chords of the spheres through the depth): the same definition
           for both codes
and, for each, the mean over the spheres of the Ergun-Wen-Yu drag on a
sphere held at rest in the gas of the tutorial's U0 (interstitial U0/eps)
over its weight less buoyancy: above 1 the gas can lift it. Also the bed's
mean voidage below its surface. Why the codes' beds differ (README.md).
"""

import argparse
import os
import re
import struct

import numpy as np

HERE = os.path.dirname(os.path.realpath(__file__))
from dpmfoam2d import fields as ff      # noqa: E402
from dpmfoam2d import particles as pio     # noqa: E402
import compare                  # noqa: E402

U0 = 1.875                      # the tutorial's inlet (superficial), m/s
MU = 1.2e-5                     # rho nu of transportProperties
PIXEL = 1e-4                    # m, the quadrature's pixel


def ergun_wen_yu_over_weight(eps):
    """Drag on a sphere at rest in gas of superficial U0 at voidage eps
    over its weight less buoyancy (the closure of both codes; the switch at
    eps 0.8)."""
    d, rho = compare.D, compare.RHO_G
    slip = U0 / eps
    vp = np.pi * d ** 3 / 6
    ergun = vp * (150 * (1 - eps) * MU / (eps * eps * d * d) + 1.75 * rho * slip / (eps * d))
    re_ = rho * d * eps * slip / MU
    cd_slip = np.where(re_ < 1000, 24 * MU / (rho * d * eps) * (1 + 0.15 * re_ ** 0.687),
                       0.44 * slip)
    wen_yu = vp * 0.75 * cd_slip * rho / d * eps ** -2.65
    k = np.where(eps < 0.8, ergun, wen_yu)
    return k * slip / (vp * (compare.RHO_P - rho) * compare.G)


def dpmfoam_positions(path):
    """Cartesian positions [N, 3] of OpenFOAM's legacy 'positions' file
    (ascii or binary: x y z and the cell label per particle) and the cells."""
    data = open(path, "rb").read()
    m = re.search(rb"\n(\d+)\s*\n\(", data[data.find(b"FoamFile"):])
    start = data.find(b"FoamFile") + m.end()
    n = int(m.group(1))
    if b"format      binary" in data[:1000] or b"format binary" in data[:1000]:
        rec = struct.Struct("<c3dic")          # ( x y z cell )
        out = np.empty((n, 3))
        cells = np.empty(n, dtype=int)
        at = start
        for i in range(n):
            while data[at:at + 1] in (b"\n", b" "):
                at += 1
            _, x, y, z, c, _ = rec.unpack_from(data, at)
            out[i], cells[i] = (x, y, z), c
            at += rec.size
        return out, cells
    rows = re.findall(rb"\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)\s+(\d+)", data[start:])
    a = np.array([[float(r[0]), float(r[1]), float(r[2])] for r in rows])
    return a, np.array([int(r[3]) for r in rows])


def column_voidage(xy_depth, width, dx, dy, ny, depth):
    """Voidage of one-cell-thick columns (nx x ny cells of dx x dy, the whole
    depth) from sphere centres (x across, y up, z across the depth):
    pixels of the plane hold the spheres' chords through the depth (clipped
    to the slab), summed per cell."""
    r = compare.D / 2
    nx = int(round(width / dx))
    px, py = int(round(width / PIXEL)), int(round(ny * dy / PIXEL))
    thick = np.zeros(px * py)
    k = int(np.ceil(2 * r / PIXEL)) + 2
    off = np.arange(k) - k // 2
    for chunk in np.array_split(xy_depth, max(1, len(xy_depth) // 4000)):
        ix = np.floor(chunk[:, 0] / PIXEL).astype(int)[:, None, None] + off[None, :, None]
        iy = np.floor(chunk[:, 1] / PIXEL).astype(int)[:, None, None] + off[None, None, :]
        ux = (ix + 0.5) * PIXEL - chunk[:, 0, None, None]
        uy = (iy + 0.5) * PIXEL - chunk[:, 1, None, None]
        half = np.sqrt(np.maximum(r * r - ux * ux - uy * uy, 0))
        z = chunk[:, 2, None, None]
        chord = np.clip(z + half, 0, depth) - np.clip(z - half, 0, depth)
        ok = (chord > 0) & (ix >= 0) & (ix < px) & (iy >= 0) & (iy < py)
        ix, iy = np.broadcast_arrays(ix, iy)
        np.add.at(thick, (iy[ok] * px + ix[ok]), chord[ok])
    solid = thick.reshape(py, px) * PIXEL * PIXEL
    cells = solid.reshape(ny, py // ny, nx, px // nx).sum(axis=(1, 3))
    return 1 - cells / (dx * dy * depth)        # [ny, nx]


def summarize(name, eps_field, eps_column, bed_eps):
    print("  %-9s field %.3f (drag/weight %.2f)   column %.3f (drag/weight %.2f)   "
          "bed below its surface %.3f"
          % (name, eps_field.mean(), ergun_wen_yu_over_weight(eps_field).mean(),
             eps_column.mean(), ergun_wen_yu_over_weight(eps_column).mean(), bed_eps))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run")
    ap.add_argument("-transient", type=float, default=0.5)
    ap.add_argument("-every", type=int, default=1, help="every n-th written time")
    a = ap.parse_args()
    n, width = compare.bed_size(a.run)
    dx = dy = 5e-3
    ny = int(round(compare.HEIGHT / dy))
    print("%s: %d spheres, %g mm wide; particle means over the written times after %g s"
          % (a.run, n, 1e3 * width, a.transient))
    for name in ("DPMFoam", "dpmFoam2D"):
        case = os.path.join(a.run, name)
        if not os.path.isdir(case):
            continue
        C, V = ff.cell_geometry(case)
        if name == "dpmFoam2D":     # its cells as a [ny, nx] grid: one block of dx x dy
            grid = np.lexsort((np.floor(C[:, 0] / dx), np.floor(C[:, 1] / dy))).reshape(ny, -1)
        f_all, c_all, beds = [], [], []
        worst = 0.0         # dpmFoam2D's field against the quadrature, per cell
        if name == "DPMFoam":
            times = [(t, os.path.join(case, d, "lagrangian", "kinematicCloud", "positions"))
                     for t, d in ff.time_dirs(case)]
        else:
            times = pio.list_times(case)
        times = [tp for tp in times if tp[0] > a.transient + 1e-9 and os.path.isfile(tp[1])]
        for t, path in times[::a.every]:
            if name == "DPMFoam":
                p, cell = dpmfoam_positions(path)
                ours = np.column_stack([p[:, 1] + 0.075, p[:, 2], p[:, 0] + compare.DEPTH / 2])
            else:
                ours = pio.read_particles(path)["position"].astype(float)
            col = column_voidage(ours, width, dx, dy, ny, compare.DEPTH)
            # each centre's column
            i = np.clip((ours[:, 0] / dx).astype(int), 0, col.shape[1] - 1)
            j = np.clip((ours[:, 1] / dy).astype(int), 0, ny - 1)
            c_all.append(col[j, i])
            if name == "DPMFoam":
                time_dir = path.rsplit(os.sep + "lagrangian" + os.sep, 1)[0]
                f_all.append(ff.internal_field(os.path.join(time_dir, "alpha.air"), len(V))[cell])
            else:
                eps = ff.internal_field(os.path.join(case, pio.time_name(t), "voidage"),
                                        len(V))[grid]
                f_all.append(eps[j, i])
                worst = max(worst, np.abs(col - eps).max())
            rows = col.mean(axis=1)
            top = np.nonzero(rows < 0.7)[0]
            beds.append(rows[:top[-1] + 1].mean() if len(top) else np.nan)
        if not f_all:
            print("  %s: no written positions after %g s" % (name, a.transient))
            continue
        print(" %d times" % len(f_all), end="")
        summarize(name, np.concatenate(f_all), np.concatenate(c_all), np.nanmean(beds))
        if name == "dpmFoam2D":
            print("  dpmFoam2D's voidage field against the quadrature: largest difference"
                  " in a cell %.2e" % worst)


if __name__ == "__main__":
    main()
