#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Synthetic data for the picture tests (no solver needed).

  makeCase.py particles <case> T1 [T2 ...]
      After blockMesh on the picture-test mesh (0.15 x 0.90 m, 20 x 120
      cells): for each time Ti a 'voidage' volScalarField in <case>/<Ti>/ and
      <case>/particles/<Ti>.h5 (+ particles.xdmf) holding a known layout:
        large, d = 2.5 mm: 50 x 20 on a 3 mm lattice, centres y = 1.5..58.5 mm
        small, d = 1.5 mm: 75 x 30 on a 2 mm lattice, centres y = 62..120 mm
      No two discs overlap and all lie inside the bed, so the drawn areas are
      small 2250 x (1.5 mm)^2 and large 1000 x (2.5 mm)^2 (times pi/4):
      ratio small/large = 5062.5/6250 = 0.81.
      voidage: 0.40 in the bed (cell centre y < 0.12 m), 1 above, and a
      bubble of voidage 0.9 (radius 20 mm) rising 20 mm per time step.

  makeCase.py mixing <case> <M0> <Minf> <tau> [restart | rerun]
      postProcessing/laceyIndex/0/{laceyIndex.dat,segregation.dat} with
      M(t) = Minf + (M0 - Minf) exp(-t/tau), t = 0..5 s every 0.1 s; with
      'restart' the rows from t = 2.5 s on go to a second start-time
      directory 2.5 (and the first keeps some rows past 2.5 that a restart
      overwrites: the reader must drop them). 'rerun': as 'restart', but the
      run from 2.5 was killed at 3.5 s and run again from 2.5: its files
      hold M + 0.2 (wrong on purpose) and the second run's rows are in
      laceyIndex_2.5.dat and segregation_2.5.dat, as OpenFOAM's writeFile
      names them when the first ones exist.
"""

import os
import sys

import numpy as np

from dpmfoam2d import particles as pio

NX, NY, DX = 20, 120, 0.0075


def layout():
    xs, ys, ds, cs = [], [], [], []
    for j in range(20):
        for i in range(50):
            xs.append(0.0015 + 0.003 * i); ys.append(0.0015 + 0.003 * j)
            ds.append(0.0025); cs.append(1)
    for j in range(30):
        for i in range(75):
            xs.append(0.001 + 0.002 * i); ys.append(0.062 + 0.002 * j)
            ds.append(0.0015); cs.append(0)
    return np.array(xs), np.array(ys), np.array(ds), np.array(cs)


def write_voidage(case, tname, k):
    xc = (np.arange(NX) + 0.5) * DX
    yc = (np.arange(NY) + 0.5) * DX
    X, Y = np.meshgrid(xc, yc)          # cell order: x fastest, then y
    eps = np.where(Y < 0.12, 0.40, 1.0)
    by = 0.03 + 0.02 * k
    eps[(X - 0.075) ** 2 + (Y - by) ** 2 < 0.02 ** 2] = 0.9
    values = "\n".join("%.4f" % v for v in eps.ravel())
    os.makedirs(os.path.join(case, tname), exist_ok=True)
    with open(os.path.join(case, tname, "voidage"), "w") as f:
        f.write("""FoamFile
{
    version     2.0;
    format      ascii;
    class       volScalarField;
    location    "%s";
    object      voidage;
}
dimensions      [0 0 0 0 0 0 0];
internalField   nonuniform List<scalar>
%d
(
%s
)
;
boundaryField
{
    inlet        { type zeroGradient; }
    outlet       { type zeroGradient; }
    walls        { type zeroGradient; }
    frontAndBack { type empty; }
}
""" % (tname, NX * NY, values))


def particles(case, times):
    x, y, d, c = layout()
    for k, t in enumerate(times):
        tname = pio.time_name(t)
        write_voidage(case, tname, k)
        z = np.full(len(x), 0.00125)
        pio.write_particles(case, t, np.column_stack([x, y, z]), d, c,
                            velocity=np.zeros((len(x), 3)), omega=np.zeros(len(x)))
    pio.write_xdmf(case)
    open(os.path.join(case, "case.foam"), "a").close()


def mixing(case, M0, Minf, tau, layout):
    t = np.round(np.arange(0, 5.0001, 0.1), 10)
    M = Minf + (M0 - Minf) * np.exp(-t / tau)
    S02 = 0.25 * np.ones_like(t)
    SR2 = S02 / 10000
    S2 = S02 - M * (S02 - SR2)
    vert = 0.5 * (1 - np.exp(-t / tau))
    hor = 0.1 * np.sin(t)
    lacey = np.column_stack([t, M, S2, S02, SR2, np.full_like(t, 400)])
    seg = np.column_stack([t, 0.06 + 0.02 * vert, 0.06 - 0.02 * vert, vert,
                           0.0375 + 0.01 * hor, 0.0375 - 0.01 * hor, hor])
    killed = lacey.copy()
    killed[:, 1] += 0.2
    if layout == "rerun":
        parts = [("0", "", lacey, t <= 3.0), ("2.5", "", killed, (t >= 2.5) & (t <= 3.5)),
                 ("2.5", "_2.5", lacey, t >= 2.5)]
    elif layout == "restart":
        parts = [("0", "", lacey, t <= 3.0), ("2.5", "", lacey, t >= 2.5)]
    else:
        parts = [("0", "", lacey, t >= 0)]
    for start, suffix, table, mask in parts:
        d = os.path.join(case, "postProcessing", "laceyIndex", start)
        os.makedirs(d, exist_ok=True)
        np.savetxt(os.path.join(d, "laceyIndex%s.dat" % suffix), table[mask], fmt="%.6g",
                   header="Time M S2 S02 SR2 nCells", comments="# ")
        np.savetxt(os.path.join(d, "segregation%s.dat" % suffix), seg[mask], fmt="%.6g",
                   header="Time hSmall hLarge vertical rSmall rLarge horizontal",
                   comments="# ")


if __name__ == "__main__":
    if len(sys.argv) >= 4 and sys.argv[1] == "particles":
        particles(sys.argv[2], [float(a) for a in sys.argv[3:]])
    elif len(sys.argv) >= 6 and sys.argv[1] == "mixing":
        mixing(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5]),
               sys.argv[6] if len(sys.argv) > 6 else None)
    else:
        sys.exit(__doc__)
