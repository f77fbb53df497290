# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The tables the function objects write, <case>/postProcessing/<name>/
<startTime>/<file>: read one (read_dat) or a whole run's, joined over its
restarts (read_postprocessing); the Lacey index and the segregation indices
of the laceyIndex function object (lacey, segregation); and the tables of a
study's results/ (study_table).

laceyIndex.dat    Time M ... (M: Lacey's index of the whole bed)
segregation.dat   Time ... vertical horizontal hSmall hLarge rSmall rLarge
"""

from __future__ import annotations

import csv
import os
import sys

import numpy as np

from .fields import TIME_NAME
from .particles import check_case

def read_dat(path: str) -> dict[str, np.ndarray]:
    """Columns of a whitespace table (laceyIndex.dat, segregation.dat):
    dict name -> numpy array. The column names are the last '#' line before
    the first row of numbers (OpenFOAM's writeFile may put other comment
    lines above it). A row that is not one number per column is refused,
    naming the file and line; a last line without its end of line (a run
    writing it, or killed while it did) is left out, with a note on stderr,
    even when it has every column (its last number may be cut short)."""
    names = None
    rows = []
    with open(path, errors="replace") as f:
        lines = f.read().split("\n")
    complete = len(lines) - 1          # the lines that end in a newline
    for n, line in enumerate(lines, 1):
        s = line.strip()
        if not s:
            continue
        if s.startswith("#"):
            if not rows:
                names = s.lstrip("#").split()
            continue
        if names is None:
            raise ValueError("%s line %d: a row before the '#' header line naming the "
                             "columns" % (path, n))
        if n > complete:
            # Being written, or cut by a kill: even with every column its
            # last number may be cut short, so it is never trusted
            print("note: %s line %d: cut short (no end of line): left out" % (path, n),
                  file=sys.stderr)
            continue
        words = s.split()
        try:
            values = [float(v) for v in words]
        except ValueError:
            bad = next(v for v in words if not _is_number(v))
            values = None
        if values is not None and len(values) == len(names):
            rows.append(values)
            continue
        if values is None:
            raise ValueError("%s line %d: '%s' is not a number (columns: %s)"
                             % (path, n, bad, " ".join(names)))
        raise ValueError("%s line %d: %d values for the %d columns %s"
                         % (path, n, len(values), len(names), " ".join(names)))
    if names is None:
        raise ValueError("%s: no '#' header line naming the columns" % path)
    a = np.array(rows, dtype=float).reshape(-1, len(names)) if rows \
        else np.zeros((0, len(names)))
    return {name: a[:, i] for i, name in enumerate(names)}


def _is_number(word):
    try:
        float(word)
        return True
    except ValueError:
        return False


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


def read_postprocessing(case: str, name: str, fname: str, postprocess: bool = False,
                        quiet: bool = False) -> dict[str, np.ndarray] | None:
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
    is no such table; a case directory that does not exist is refused
    (FileNotFoundError naming it)."""
    if not os.path.isdir(case):
        raise FileNotFoundError("no case directory %s" % case)
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


def lacey(case: str, name: str = "laceyIndex",
          postprocess: bool = False) -> dict[str, np.ndarray] | None:
    """M(t) of a case: the columns of laceyIndex.dat (Time, M, ...) of the
    function object name, joined over the run's restarts; None if the case
    has none. A path that is not a case is refused (FileNotFoundError)."""
    check_case(case)
    return read_postprocessing(case, name, "laceyIndex.dat", postprocess)


def segregation(case: str, name: str = "laceyIndex",
                postprocess: bool = False) -> dict[str, np.ndarray] | None:
    """The vertical and horizontal segregation indices and the classes'
    mean heights and distances from the centre line over time
    (segregation.dat); None if the case has none. A path that is not a case
    is refused (FileNotFoundError)."""
    check_case(case)
    return read_postprocessing(case, name, "segregation.dat", postprocess)


def study_table(study_dir: str, name: str = "summary") -> dict[str, np.ndarray] | None:
    """A table of a study's results, <study_dir>/results/<name>.csv
    (summary, windows, ensemble, ensembleWindows, findings, verdicts), as a
    dict column -> numpy array: numbers where every value of the column is
    one (empty: nan), text otherwise. None if dpmStudy has not written it;
    a study directory that does not exist is refused (FileNotFoundError
    naming it): a mistyped path is no study without results."""
    if not os.path.isdir(study_dir):
        raise FileNotFoundError("no study directory %s" % study_dir)
    path = os.path.join(study_dir, "results", name + ".csv")
    if not os.path.isfile(path):
        return None
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return {}
    out = {}
    for i, column in enumerate(rows[0]):
        values = [r[i] if i < len(r) else "" for r in rows[1:]]
        try:
            out[column] = np.array([float(v) if v != "" else np.nan for v in values])
        except ValueError:
            out[column] = np.array(values, dtype=object)
    return out
