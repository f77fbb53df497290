# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Particle output of dpmFoam2D: write, read and index it (no OpenFOAM needed).

The contract with the solver, one file per output time:

    <case>/particles/<timeName>.h5     timeName as OpenFOAM prints the time
        attribute  time      float64 (root)
        position   float32 [N,3]   x, y, z (z = bed depth/2) (m)
        velocity   float32 [N,3]   (m/s)
        omega      float32 [N]     spin about z (rad/s)
        diameter   float32 [N]     (m)
        class      int8    [N]     0 = small, 1 = large (the case's class list)
        id         int32   [N]
    <case>/particles/particles.xdmf   XDMF 2 temporal collection, one
        Polyvertex grid per time, that ParaView opens as a time series.

Used by the dpm* picture commands and by the tests that make synthetic data.
"""

import os
import sys

import numpy as np
import h5py

from dpmFoamFields import TIME_NAME

PARTICLES_DIR = "particles"
XDMF_NAME = "particles.xdmf"

# name: (dtype, components) of every dataset of the contract
DATASETS = {
    "position": (np.float32, 3),
    "velocity": (np.float32, 3),
    "omega": (np.float32, 1),
    "diameter": (np.float32, 1),
    "class": (np.int8, 1),
    "id": (np.int32, 1),
}

# XDMF NumberType and Precision of each dtype
_XDMF_TYPES = {
    np.dtype(np.float32): ("Float", 4),
    np.dtype(np.float64): ("Float", 8),
    np.dtype(np.int8): ("Char", 1),
    np.dtype(np.int32): ("Int", 4),
}


def time_name(t):
    """The time as OpenFOAM prints it in directory names (general format,
    6 significant digits): 0.01 -> '0.01', 1.5 -> '1.5', 2 -> '2'."""
    return "%.6g" % float(t)


def check_case(case):
    """Raise FileNotFoundError naming the path unless case is a dpmFoam2D
    case directory (system/controlDict, particles/ or postProcessing/): a
    mistyped path must not pass, nor be created by the output."""
    if not os.path.isdir(case):
        raise FileNotFoundError("no case directory %s" % case)
    if not any(os.path.exists(os.path.join(case, p))
               for p in (os.path.join("system", "controlDict"), PARTICLES_DIR,
                         "postProcessing")):
        raise FileNotFoundError("%s is not a dpmFoam2D case (no system/controlDict, "
                                "particles/ or postProcessing/)" % case)


def particles_dir(case):
    return os.path.join(case, PARTICLES_DIR)


def write_particles(case, t, position, diameter, cls, velocity=None,
                    omega=None, ids=None, name=None):
    """Write one output time, <case>/particles/<timeName>.h5; return its path.

    position may be [N,2] (z is then 0) or [N,3]; velocity, omega and ids
    default to zeros and 0..N-1.
    """
    position = np.asarray(position, dtype=np.float64)
    n = position.shape[0]
    if position.ndim != 2 or position.shape[1] not in (2, 3):
        raise ValueError("position: shape %s; allowed: [N,2] or [N,3]"
                         % (position.shape,))
    if position.shape[1] == 2:
        position = np.column_stack([position, np.zeros(n)])
    data = {
        "position": position,
        "velocity": np.zeros((n, 3)) if velocity is None else velocity,
        "omega": np.zeros(n) if omega is None else omega,
        "diameter": diameter,
        "class": cls,
        "id": np.arange(n) if ids is None else ids,
    }
    os.makedirs(particles_dir(case), exist_ok=True)
    path = os.path.join(particles_dir(case), (name or time_name(t)) + ".h5")
    with h5py.File(path, "w") as f:
        f.attrs["time"] = np.float64(t)
        for key, (dtype, ncomp) in DATASETS.items():
            a = np.asarray(data[key], dtype=dtype)
            shape = (n, ncomp) if ncomp > 1 else (n,)
            if a.shape != shape:
                raise ValueError("%s: shape %s; expected %s" % (key, a.shape, shape))
            f.create_dataset(key, data=a)
    return path


def read_particles(path):
    """One output file as a dict of numpy arrays plus 'time' (float)."""
    with h5py.File(path, "r") as f:
        out = {key: f[key][()] for key in DATASETS if key in f}
        out["time"] = float(f.attrs["time"])
    return out


def list_times(case):
    """[(time, path)] of the particle files of a case, in time order. The
    time is read from the file name (as OpenFOAM names time directories)."""
    d = particles_dir(case)
    out = []
    if os.path.isdir(d):
        for fname in os.listdir(d):
            stem, ext = os.path.splitext(fname)
            if ext == ".h5" and TIME_NAME.match(stem):
                out.append((float(stem), os.path.join(d, fname)))
    return sorted(out)


def nearest_time(case, t=None):
    """(time, path) of the particle file nearest to t; the latest if t is None."""
    times = list_times(case)
    if not times:
        raise FileNotFoundError("no particle files <time>.h5 in %s" % particles_dir(case))
    if t is None:
        return times[-1]
    return min(times, key=lambda tp: abs(tp[0] - float(t)))


def write_xdmf(case):
    """(Re)write <case>/particles/particles.xdmf indexing every <time>.h5
    (XDMF 2 temporal collection of Polyvertex grids); return its path."""
    grids = []
    for t, path in list_times(case):
        fname = os.path.basename(path)
        with h5py.File(path, "r") as f:
            n = f["position"].shape[0]
            items = {k: (f[k].dtype, f[k].shape) for k in DATASETS if k in f}

        def item(key):
            dtype, shape = items[key]
            ntype, prec = _XDMF_TYPES[np.dtype(dtype)]
            dims = " ".join(str(s) for s in shape)
            return ('<DataItem Dimensions="%s" NumberType="%s" Precision="%d" '
                    'Format="HDF">%s:/%s</DataItem>' % (dims, ntype, prec, fname, key))

        attrs = []
        for key in ("velocity", "omega", "diameter", "class", "id"):
            if key in items:
                kind = "Vector" if len(items[key][1]) == 2 else "Scalar"
                attrs.append('      <Attribute Name="%s" AttributeType="%s" Center="Node">\n'
                             '        %s\n      </Attribute>' % (key, kind, item(key)))
        grids.append(
            '    <Grid Name="particles" GridType="Uniform">\n'
            '      <Time Value="%r"/>\n'
            '      <Topology TopologyType="Polyvertex" NumberOfElements="%d"/>\n'
            '      <Geometry GeometryType="XYZ">\n        %s\n      </Geometry>\n'
            '%s\n    </Grid>' % (float(t), n, item("position"), "\n".join(attrs)))
    text = ('<?xml version="1.0" ?>\n'
            '<!DOCTYPE Xdmf SYSTEM "Xdmf.dtd" []>\n'
            '<Xdmf Version="2.0">\n  <Domain>\n'
            '    <Grid Name="particles" GridType="Collection" CollectionType="Temporal">\n'
            '%s\n    </Grid>\n  </Domain>\n</Xdmf>\n'
            % "\n".join("  " + g.replace("\n", "\n  ") for g in grids))
    path = os.path.join(particles_dir(case), XDMF_NAME)
    with open(path, "w") as f:
        f.write(text)
    return path


def read_dat(path):
    """Columns of a whitespace table (laceyIndex.dat, segregation.dat):
    dict name -> numpy array. The column names are the last '#' line before
    the first row of numbers (OpenFOAM's writeFile may put other comment
    lines above it)."""
    names = None
    rows = []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                if not rows:
                    names = s.lstrip("#").split()
                continue
            rows.append([float(v) for v in s.split()])
    if names is None:
        raise ValueError("%s: no '#' header line naming the columns" % path)
    a = np.array(rows, dtype=float).reshape(-1, len(names)) if rows \
        else np.zeros((0, len(names)))
    return {name: a[:, i] for i, name in enumerate(names)}


POSTPROCESS_MARK = "# postProcess"


def _is_postprocess_table(path, start, time):
    """A table of `dpmFoam2D -postProcess` (recomputed at the saved times
    after the run), not of a run: its header says so, or (tables written
    before the header line) its rows begin before its start-time directory,
    which a run's never do."""
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            if line.startswith(POSTPROCESS_MARK):
                return True
    return len(time) > 0 and time[0] < start - 1e-9 * max(1.0, abs(start))


def _join(tables):
    """Join [(start time, path, table)], oldest first: the rows of an earlier
    table at or after a later table's start are dropped (a run restarted
    from an earlier time replaces what followed). The joined times must
    increase strictly; anything else is refused, naming the files."""
    keep = []
    for i, (start, path, part) in enumerate(tables):
        time = part[next(iter(part))]
        if np.any(np.diff(time) <= 0):
            raise ValueError("%s: times do not increase strictly" % path)
        mask = np.ones(len(time), bool)
        if i + 1 < len(tables):
            mask = time < tables[i + 1][0] - 1e-9 * max(1.0, abs(tables[i + 1][0]))
        keep.append({k: v[mask] for k, v in part.items()})
    columns = list(keep[-1])
    for (_, path, _), part in zip(tables, keep):
        if list(part) != columns:
            raise ValueError("%s: columns %s differ from %s's %s"
                             % (path, " ".join(part), tables[-1][1], " ".join(columns)))
    out = {k: np.concatenate([p[k] for p in keep]) for k in columns}
    if np.any(np.diff(out[columns[0]]) <= 0):
        raise ValueError("the tables %s do not join into increasing times"
                         % ", ".join(p for _, p, _ in tables))
    return out


def read_postprocessing(case, name, fname, postprocess=False, quiet=False):
    """A function object's table over all its start-time directories,
    <case>/postProcessing/<name>/<startTime>/<fname>, joined in time order
    into strictly increasing times: rows of an earlier run at or after a
    later run's start time are dropped (as after a restart from an earlier
    time). A second run from the same start time finds <fname> there and
    OpenFOAM's writeFile names its file <stem>_<startTime><ext>; that file is
    the later run and replaces <fname>.

    Tables written by `dpmFoam2D -postProcess` (recomputed at the saved
    times, possibly with other settings) are kept apart: they are left out
    of the run's table, with a note on stderr naming them, unless the case
    has no run table; postprocess=True returns them instead (joined in the
    order they were written). Returns dict name -> array, or None if there
    is no such table."""
    root = os.path.join(case, "postProcessing", name)
    if not os.path.isdir(root):
        return None
    stem, ext = os.path.splitext(fname)
    runs, recomputed = [], []
    for s in os.listdir(root):
        if not TIME_NAME.match(s):
            continue
        for rank, f in enumerate((fname, "%s_%s%s" % (stem, s, ext))):
            path = os.path.join(root, s, f)
            if os.path.isfile(path):
                table = read_dat(path)
                time = table[next(iter(table))]
                if _is_postprocess_table(path, float(s), time):
                    recomputed.append((os.path.getmtime(path), float(s), rank, path, table))
                else:
                    runs.append((float(s), rank, path, table))
    if postprocess or not runs:
        if not recomputed:
            return None
        # In the order written: a later -postProcess replaces the rows it
        # recomputed, keeping the others
        recomputed.sort(key=lambda r: (r[0], r[1], r[2]))
        out = None
        for _, _, _, path, table in recomputed:
            time = table[next(iter(table))]
            if np.any(np.diff(time) <= 0):
                raise ValueError("%s: times do not increase strictly" % path)
            if out is None:
                out = table
                continue
            t = out[next(iter(out))]
            mask = (t < time[0]) | (t > time[-1]) if len(time) else np.ones(len(t), bool)
            order = np.argsort(np.concatenate([t[mask], time]), kind="stable")
            out = {k: np.concatenate([out[k][mask], table[k]])[order] for k in table}
        return out
    if recomputed and not quiet:
        print("note: %s: not joined with the run's table: written by dpmFoam2D "
              "-postProcess (recomputed at the saved times)"
              % ", ".join(r[3] for r in sorted(recomputed, key=lambda r: r[3])),
              file=sys.stderr)
    runs.sort(key=lambda r: (r[0], r[1]))
    return _join([(start, path, table) for start, _, path, table in runs])
