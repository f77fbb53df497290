# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Independent check of the laceyIndex function object's output.

The Lacey index and the segregation indices are recomputed here from the
particle files particles/<time>.h5 (docs/theory/paper-model.md, "Lacey
mixing index"; the segregation definitions of
src/mixing/include/mixing/LaceyIndex.hpp), without the mixing library, and
compared with postProcessing/<name>/<startTime>/*.dat.

  laceyCheck.py particles <datDir> <cellSize> <basis> <xMin> <yMin> <xMax> <yMax>
      compare every row of datDir's .dat files with particles/<time>.h5
  laceyCheck.py same <datDirA> <datDirB> <relTol>
      the rows of B (e.g. from -postProcess) equal A's at B's times

Tolerance against the particle files: the files hold float32 positions
(relative rounding 6e-8, so <= 2e-8 m in a 0.3 m bed). Means of heights and
distances then agree to 1e-5 relative, the indices (differences of means over
a mean height ~ 0.02 m) to 1e-5 absolute. A particle closer than 1e-7 m to a
sampling cell or region edge may fall on either side in float32; such
particles are tried on both sides and the test passes if one assignment
reproduces the row (there are rarely any).
"""
import itertools
import math
import os
import sys

import numpy as np

from dpmfoam2d import particles as pio
from dpmfoam2d.tables import read_dat

REL = 1e-5          # means, M, S2, S02, SR2: relative
ABS_INDEX = 1e-5    # vertical, horizontal: absolute
EDGE = 1e-7         # m: float32 positions closer than this to an edge are ambiguous

LACEY_COLUMNS = ["M", "S2", "S02", "SR2", "nCells"]
SEG_COLUMNS = ["hSmall", "hLarge", "vertical", "rSmall", "rLarge", "horizontal"]


def table_rows(path):
    """The column names of a writeFile table and its rows, {time: [values]}."""
    table = read_dat(path)
    columns = list(table)
    return columns, {t: [table[c][i] for c in columns[1:]]
                     for i, t in enumerate(table[columns[0]])}


def lacey(x, y, small, w, region, h, basis):
    """Lacey index of the particles (x, y), small True for small ones."""
    x0, y0, x1, y1 = region
    nx = max(1, math.ceil((x1 - x0) / h))
    ny = max(1, math.ceil((y1 - y0) / h))
    cells = {}
    for xi, yi, si in zip(x, y, small):
        ix = min(nx - 1, int((xi - x0) // h))
        iy = min(ny - 1, int((yi - y0) // h))
        c = cells.setdefault((ix, iy), [0, 0])
        c[0 if si else 1] += 1
    k = {key: ns + w * nl for key, (ns, nl) in cells.items()}
    K = sum(k.values())
    p = sum(ns for ns, nl in cells.values()) / K
    S2 = sum(k[key] * (ns / k[key] - p) ** 2 for key, (ns, nl) in cells.items()) / K
    S02 = p * (1 - p)
    N = K if basis == "wholeBed" else K / len(cells)
    SR2 = S02 / N
    return [(S02 - S2) / (S02 - SR2), S2, S02, SR2, len(cells)]


def segregation(x, y, small, d, region):
    x0, y0, x1, y1 = region
    hgt = y - y0
    r = np.abs(x - 0.5 * (x0 + x1))
    v = d.astype(float) ** 3
    hS, hL = hgt[small].mean(), hgt[~small].mean()
    rS, rL = r[small].mean(), r[~small].mean()
    hAll = (v * hgt).sum() / v.sum()
    rAll = (v * r).sum() / v.sum()
    return [hS, hL, (hS - hL) / hAll, rS, rL, (rS - rL) / rAll]


def close(a, b, absolute=False):
    tol = ABS_INDEX if absolute else REL * abs(b)
    return abs(a - b) <= tol


def check_particles(dat_dir, h, basis, region):
    _, lacey_rows = table_rows(os.path.join(dat_dir, "laceyIndex.dat"))
    _, seg_rows = table_rows(os.path.join(dat_dir, "segregation.dat"))
    files = pio.list_times(".")
    assert lacey_rows, "no rows in " + dat_dir
    x0, y0, x1, y1 = region
    checked = 0
    for t, row in lacey_rows.items():
        path = [f for tf, f in files if abs(tf - t) <= 1e-9 * max(1.0, abs(t))]
        if not path:
            continue
        p = pio.read_particles(path[0])
        pos, d = p["position"].astype(float), p["diameter"]
        small = d < 0.5 * (d.min() + d.max())
        w = (float(d.max()) / float(d.min())) ** 3
        x, y = pos[:, 0], pos[:, 1]

        # Particles near an edge: each is tried on both sides
        lines_x = x0 + h * np.arange(0, math.ceil((x1 - x0) / h) + 1)
        lines_y = y0 + h * np.arange(0, math.ceil((y1 - y0) / h) + 1)
        lines_x = np.append(lines_x, x1)
        lines_y = np.append(lines_y, y1)
        near = [i for i in range(len(x))
                if np.min(np.abs(lines_x - x[i])) < EDGE
                or np.min(np.abs(lines_y - y[i])) < EDGE]
        assert len(near) <= 6, f"{t:g}: {len(near)} particles on edges"
        shifts = []
        for i in near:
            ex = lines_x[np.argmin(np.abs(lines_x - x[i]))]
            ey = lines_y[np.argmin(np.abs(lines_y - y[i]))]
            # as it is, or just across the edge (by EDGE, which changes
            # the means by far less than the tolerance)
            opts = [(0.0, 0.0)]
            if abs(ex - x[i]) < EDGE:
                opts.append((ex + (EDGE if x[i] < ex else -EDGE) - x[i], 0.0))
            if abs(ey - y[i]) < EDGE:
                opts.append((0.0, ey + (EDGE if y[i] < ey else -EDGE) - y[i]))
            shifts.append(opts)

        ok, best = False, None
        for combo in itertools.product(*shifts) if shifts else [()]:
            xs, ys = x.copy(), y.copy()
            for i, (dx, dy) in zip(near, combo):
                xs[i] += dx
                ys[i] += dy
            inside = (xs >= x0) & (xs <= x1) & (ys >= y0) & (ys <= y1)
            L = lacey(xs[inside], ys[inside], small[inside], w, region, h, basis)
            S = segregation(xs[inside], ys[inside], small[inside], d[inside], region)
            good = (all(close(a, b) for a, b in zip(row[:4], L[:4]))
                    and row[4] == L[4]
                    and all(close(a, b, absolute=(j in (2, 5)))
                            for j, (a, b) in enumerate(zip(seg_rows[t], S))))
            best = best or (L, S)
            if good:
                ok, best = True, (L, S)
                break
        print(f"  t = {t:g}: M {row[0]:.10g} (python {best[0][0]:.10g}), "
              f"nCells {int(row[4])} ({best[0][4]}), vertical {seg_rows[t][2]:.6g} "
              f"({best[1][2]:.6g}), horizontal {seg_rows[t][5]:.6g} ({best[1][5]:.6g})"
              f"{', %d particle(s) on edges' % len(near) if near else ''}")
        if not ok:
            print(f"FAIL {dat_dir} t = {t:g}:\n  file   {row} {seg_rows[t]}\n"
                  f"  python {best[0]} {best[1]}")
            return False
        checked += 1
    assert checked >= 2, f"only {checked} times with particle files in {dat_dir}"
    return True


def check_same(dir_a, dir_b, rel):
    for name in ("laceyIndex.dat", "segregation.dat"):
        cols_a, a = table_rows(os.path.join(dir_a, name))
        cols_b, b = table_rows(os.path.join(dir_b, name))
        assert cols_a == cols_b, (cols_a, cols_b)
        assert len(b) >= 2, f"{dir_b}/{name}: {len(b)} rows"
        for t, row in b.items():
            assert t in a, f"time {t:g} of {dir_b} not in {dir_a}"
            for c, u, v in zip(cols_a[1:], a[t], row):
                if not abs(u - v) <= rel * abs(u):
                    print(f"FAIL {name} t = {t:g} {c}: run {u!r}, postProcess {v!r}")
                    return False
        print(f"  {dir_b}/{name}: {len(b)} rows equal the run's "
              f"(relative tolerance {rel:g})")
    return True


if __name__ == "__main__":
    mode = sys.argv[1]
    if mode == "particles":
        dat_dir, h, basis = sys.argv[2], float(sys.argv[3]), sys.argv[4]
        region = tuple(float(v) for v in sys.argv[5:9])
        sys.exit(0 if check_particles(dat_dir, h, basis, region) else 1)
    elif mode == "same":
        sys.exit(0 if check_same(sys.argv[2], sys.argv[3], float(sys.argv[4])) else 1)
    sys.exit("usage: see the docstring")
