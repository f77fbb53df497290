# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The records the comparison with van Wachem et al. (2001) reads: a run's
pressure probe and bed height, and the experiment's digitized curves.

  pressure_probe(case)   postProcessing/pressureProbe/<t0>/p_rgh (OpenFOAM's
                         probes), the start-time directories of a restarted
                         run joined: a later start replaces what an earlier
                         run wrote at or after it
  bed_heights(case)      every particles/<time>.h5: the bed height (the
                         height below which BED_FRACTION of the particles'
                         tops lie) and the highest particle's top
  reference(folder)      height.csv, relative_pressure.csv (t, value)
"""

import os

import numpy as np
import h5py

HERE = os.path.dirname(os.path.realpath(__file__))
from dpmfoam2d import particles as pio  # noqa: E402
from dpmfoam2d.fields import TIME_NAME  # noqa: E402

PROBE_NAME, PROBE_FIELD = "pressureProbe", "p_rgh"

# The bed height: the height below which 99 % of the particles' tops
# (y + d/2) lie. The experiment's is the top of the dense bed seen through
# the front wall; a quantile of the particles follows that surface and
# leaves out the few particles thrown above it (1 % is 176 of the slab's
# 17,562), and it reads the particles alone, so the slab's spheres and the
# 2D model's discs are measured alike (a voidage threshold would measure
# each model's own voidage). The highest particle (Lethe's measure) is the
# second line.
BED_FRACTION = 0.99

# OpenFOAM's probes write -VGREAT for a probe outside the mesh
_OUTSIDE = -1e299

# The digitized curves of the experiment (SOURCES.md of the folder)
REFERENCE_FILES = {"pressure": ("relative_pressure.csv", ("t", "p")),
                   "height": ("height.csv", ("t", "h"))}
REFERENCE_ORIGIN = ("chaos-polymtl/lethe, examples/unresolved-cfd-dem/"
                    "pseudo-2d-gas-solid-fluidized-bed/reference/")


def _probe_rows(path):
    """(t, value) of one probe file; one probe, one scalar field. A last
    line cut short (a run killed while writing it) is left out."""
    with open(path) as f:
        lines = [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")]
    rows = []
    for n, words in enumerate(lines):
        try:
            if len(words) != 2:
                raise ValueError
            rows.append((float(words[0]), float(words[1])))
        except ValueError:
            if n + 1 < len(lines):
                raise ValueError("%s: row '%s': one probe of a scalar ('time value') "
                                 "expected" % (path, " ".join(words)))
    a = np.array(rows, dtype=float).reshape(-1, 2)
    if np.any(a[:, 1] < _OUTSIDE):
        raise ValueError("%s: the probe lies outside the mesh (OpenFOAM writes -VGREAT); "
                         "fix probeLocations in system/controlDict" % path)
    return a[:, 0], a[:, 1]


def pressure_probe(case):
    """(t, p_rgh) at the pressure probe over all start-time directories."""
    root = os.path.join(case, "postProcessing", PROBE_NAME)
    starts = sorted((float(s), s) for s in (os.listdir(root) if os.path.isdir(root) else [])
                    if TIME_NAME.match(s) and os.path.isfile(os.path.join(root, s, PROBE_FIELD)))
    if not starts:
        raise FileNotFoundError("%s: no %s/<startTime>/%s (the probes function object "
                                "'%s' of system/controlDict)"
                                % (case, root, PROBE_FIELD, PROBE_NAME))
    ts, ps = [], []
    for i, (start, name) in enumerate(starts):
        t, p = _probe_rows(os.path.join(root, name, PROBE_FIELD))
        if i + 1 < len(starts):
            keep = t < starts[i + 1][0] - 1e-9 * max(1.0, abs(starts[i + 1][0]))
            t, p = t[keep], p[keep]
        ts.append(t)
        ps.append(p)
    t, p = np.concatenate(ts), np.concatenate(ps)
    if not len(t):
        raise ValueError("%s: no rows ('time value'): the probe has written nothing (an "
                         "empty file, or its header only)"
                         % ", ".join(os.path.join(root, name, PROBE_FIELD) for _, name in starts))
    if np.any(np.diff(t) <= 0):
        raise ValueError("%s: the probe's times do not increase strictly" % root)
    return t, p


def bed_heights(case, fraction=BED_FRACTION):
    """(t, bed height, highest particle's top) [s, m, m] of every particle file."""
    times = pio.list_times(case)
    if not times:
        raise FileNotFoundError("%s: no particle files <time>.h5" % pio.particles_dir(case))
    out = []
    for t, path in times:
        try:
            with h5py.File(path, "r") as f:
                top = f["position"][:, 1].astype(float) + 0.5 * f["diameter"][()].astype(float)
        except (OSError, KeyError) as e:
            raise pio.ParticleFileError(
                "%s: unreadable particle file (%s): cut short or damaged; remove it or "
                "rerun from an earlier time" % (path, str(e).split("\n")[0]))
        out.append((t, np.quantile(top, fraction), top.max()))
    return np.array(out).T


def default_reference():
    """../shared/reference/vanWachem2001 beside the repository."""
    return os.path.realpath(os.path.join(HERE, "..", "..", "..", "shared", "reference",
                                         "vanWachem2001"))


def reference(folder):
    """{'pressure': (t, p), 'height': (t, h)} of the experiment's folder."""
    out = {}
    for key, (fname, columns) in REFERENCE_FILES.items():
        path = os.path.join(folder, fname)
        if not os.path.isfile(path):
            raise FileNotFoundError("%s: missing (the digitized curves of %s)"
                                    % (path, REFERENCE_ORIGIN))
        with open(path) as f:
            header = f.readline().strip().split(",")
        if tuple(h.strip() for h in header) != columns:
            raise ValueError("%s: header '%s'; expected '%s'"
                             % (path, ",".join(header), ",".join(columns)))
        a = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
        if a.shape[0] < 8 or np.any(np.diff(a[:, 0]) <= 0):
            raise ValueError("%s: expected at least 8 rows in strictly increasing time" % path)
        out[key] = (a[:, 0], a[:, 1])
    return out
