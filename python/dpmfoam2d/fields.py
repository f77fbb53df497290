# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Cell values of OpenFOAM fields for the post-processing commands, without
OpenFOAM's Python bindings (there are none): the internal field of a
volScalarField or volVectorField written in ASCII or binary, and the cell
centres and volumes of a case (written once by OpenFOAM's own
writeCellCentres / writeCellVolumes function objects).
"""

from __future__ import annotations

import os
import re
import subprocess

import numpy as np

_HEADER = re.compile(rb"internalField\s+(uniform|nonuniform)\s+")
_LIST = re.compile(rb"List<(scalar|vector)>\s*(\d+)\s*\(")
# A time as OpenFOAM names its directories (and dpmFoam2D its particle files)
TIME_NAME = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")
_COMPONENTS = {b"scalar": 1, b"vector": 3}


class FieldError(Exception):
    """A field file this reader cannot read, with its path in the message."""


def _scalar_bytes(text, path):
    # Written by the case's OpenFOAM: arch "LSB;label=32;scalar=64"
    m = re.search(rb'arch\s+"([^"]*)"', text)
    arch = m.group(1).decode() if m else "LSB;scalar=64"
    if "scalar=64" not in arch or "MSB" in arch:
        raise FieldError("%s: binary arch \"%s\" is not the little-endian 64-bit "
                         "scalars this reader handles" % (path, arch))
    return 8


def internal_field(path: str, n_cells: int | None = None) -> np.ndarray | float:
    """The internal field of a volScalarField ([N]) or volVectorField
    ([N, 3]). A uniform field is expanded to n_cells values, or returned as
    its one value (a float, or an array of 3) when n_cells is None."""
    try:
        with open(path, "rb") as f:
            text = f.read()
    except OSError as e:
        raise FieldError("%s: %s" % (path, e.strerror))
    m = _HEADER.search(text)
    if not m:
        raise FieldError("%s: no internalField entry" % path)
    rest = text[m.end():]
    if m.group(1) == b"uniform":
        value = rest.split(b";", 1)[0].strip()
        a = np.array(value.strip(b"()").split(), float)
        if n_cells is None:
            return a if a.size > 1 else float(a[0])
        return np.tile(a, (n_cells, 1)) if a.size > 1 else np.full(n_cells, a[0])
    m = _LIST.match(rest)
    if not m:
        raise FieldError("%s: internalField is not a List<scalar> or List<vector>" % path)
    ncomp = _COMPONENTS[m.group(1)]
    n = int(m.group(2))
    body = rest[m.end():]
    binary = re.search(rb"format\s+binary\s*;", text) is not None
    if binary:
        size = _scalar_bytes(text, path)
        need = n * ncomp * size
        if len(body) < need + 1 or body[need:need + 1] != b")":
            raise FieldError("%s: binary internalField shorter than its %d values"
                             % (path, n))
        a = np.frombuffer(body[:need], dtype="<f8").copy()
    else:
        words = body.replace(b"(", b" ").replace(b")", b" ").split(None, n * ncomp)
        if len(words) < n * ncomp:
            raise FieldError("%s: internalField shorter than its %d values" % (path, n))
        a = np.array(words[:n * ncomp], float)
    return a.reshape(n, ncomp) if ncomp > 1 else a


def time_dirs(case: str) -> list[tuple[float, str]]:
    """(time, name) of the case's numeric time directories, in time order.
    A case directory that does not exist is refused (FileNotFoundError
    naming it): a mistyped path is not a case without times."""
    if not os.path.isdir(case):
        raise FileNotFoundError("no case directory %s" % case)
    return sorted((float(name), name) for name in os.listdir(case)
                  if TIME_NAME.match(name) and os.path.isdir(os.path.join(case, name)))


def cell_geometry(case: str) -> tuple[np.ndarray, np.ndarray]:
    """Cell centres [N, 3] and volumes [N] of the case's mesh. Written by
    OpenFOAM (postProcess -funcs '(writeCellCentres writeCellVolumes)') into
    the first time directory the first time they are asked for."""
    times = time_dirs(case)
    if not times:
        raise FieldError("%s: no time directory to hold the cell centres" % case)
    first = os.path.join(case, times[0][1])
    centres, volumes = os.path.join(first, "C"), os.path.join(first, "V")
    if not (os.path.isfile(centres) and os.path.isfile(volumes)):
        cmd = ["postProcess", "-case", case, "-time", times[0][1],
               "-funcs", "(writeCellCentres writeCellVolumes)"]
        try:
            r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               universal_newlines=True)
        except OSError as e:
            raise FieldError("%s: cannot run postProcess (%s): source etc/bashrc first"
                             % (case, e.strerror))
        if r.returncode != 0 or not os.path.isfile(centres):
            raise FieldError("%s: postProcess could not write the cell centres:\n%s"
                             % (case, r.stdout[-2000:]))
    C = internal_field(centres)
    V = internal_field(volumes, len(C))
    return C, V
