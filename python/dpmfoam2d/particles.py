# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The particle files of dpmFoam2D: read, list and index them (no OpenFOAM
needed). The solver writes one file per output time
(src/dpmCoupling/particleWriter):

    <case>/particles/<timeName>.h5     timeName as OpenFOAM prints the time
        attribute   time      float64 (root)
        position    float32 [N,3]   x, y, z (z = bed depth/2 in 2D) (m)
        velocity    float32 [N,3]   (m/s)
        omega       float32 [N]     spin about z (rad/s)
        spin        float32 [N,3]   the spin vector (slab mode only) (rad/s)
        diameter    float32 [N]     (m)
        class       int8    [N]     index in particleProperties' classes
        id          int32   [N]
        voidage     float32 [N]     3D voidage the particle saw
        gasVelocity float32 [N,3]   gas velocity the particle saw (m/s)
    <case>/particles/particles.xdmf   XDMF 2 temporal collection, one
        Polyvertex grid per time, that ParaView opens as a time series.

read(case, t) gives the file nearest to t as a dict of arrays; FIELDS is
the list above, the one the reader reads. write_particles and write_xdmf
make files of the same layout from arrays (synthetic beds of known
geometry for the picture tests).
"""

from __future__ import annotations

import math
import os
import subprocess

import numpy as np
import h5py

from .fields import TIME_NAME
from .files import replacing

PARTICLES_DIR = "particles"
XDMF_NAME = "particles.xdmf"

# name: (dtype, components, always written) of every dataset the solver writes
FIELDS = {
    "position": (np.float32, 3, True),
    "velocity": (np.float32, 3, True),
    "omega": (np.float32, 1, True),
    "spin": (np.float32, 3, False),
    "diameter": (np.float32, 1, True),
    "class": (np.int8, 1, True),
    "id": (np.int32, 1, True),
    "voidage": (np.float32, 1, False),
    "gasVelocity": (np.float32, 3, False),
}
REQUIRED = tuple(k for k, (_, _, always) in FIELDS.items() if always)

# XDMF NumberType and Precision of each dtype
_XDMF_TYPES = {
    np.dtype(np.float32): ("Float", 4),
    np.dtype(np.float64): ("Float", 8),
    np.dtype(np.int8): ("Char", 1),
    np.dtype(np.int32): ("Int", 4),
}


class ParticleFileError(ValueError):
    """A particle file that HDF5 cannot read, its path in the message."""


def time_name(t: float) -> str:
    """The time as OpenFOAM prints it in directory names (general format,
    6 significant digits): 0.01 -> '0.01', 1.5 -> '1.5', 2 -> '2'."""
    return "%.6g" % float(t)


def check_case(case: str) -> None:
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


def class_names(case: str) -> list[str]:
    """The class names of constant/particleProperties in their order (the
    particle files' class indices), or [] when foamDictionary cannot say (no
    such file, or no OpenFOAM). A case directory that does not exist is
    refused (FileNotFoundError naming it)."""
    if not os.path.isdir(case):
        raise FileNotFoundError("no case directory %s" % case)
    path = os.path.join(case, "constant", "particleProperties")
    try:
        out = subprocess.run(["foamDictionary", "-entry", "classes", "-keywords", path],
                             capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return []
    return out.split()


def particles_dir(case: str) -> str:
    return os.path.join(case, PARTICLES_DIR)


def write_particles(case, t, position, diameter, cls, velocity=None,
                    omega=None, ids=None, name=None, voidage=None, gas_velocity=None):
    """Write one output time, <case>/particles/<timeName>.h5; return its path.

    position may be [N,2] (z is then 0) or [N,3]; velocity, omega and ids
    default to zeros and 0..N-1; voidage and gas_velocity are written when
    given (both, as the solver does).
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
    if (voidage is None) != (gas_velocity is None):
        raise ValueError("voidage and gas_velocity: both or neither (as the solver writes)")
    if voidage is not None:
        data["voidage"], data["gasVelocity"] = voidage, gas_velocity
    os.makedirs(particles_dir(case), exist_ok=True)
    path = os.path.join(particles_dir(case), (name or time_name(t)) + ".h5")
    with h5py.File(path, "w") as f:
        f.attrs["time"] = np.float64(t)
        for key, value in data.items():
            dtype, ncomp, _ = FIELDS[key]
            a = np.asarray(value, dtype=dtype)
            shape = (n, ncomp) if ncomp > 1 else (n,)
            if a.shape != shape:
                raise ValueError("%s: shape %s; expected %s" % (key, a.shape, shape))
            f.create_dataset(key, data=a)
    return path


def read_particles(path: str) -> dict[str, np.ndarray | float]:
    """One particle file as a dict: every dataset of FIELDS it holds (numpy
    arrays) plus 'time' (float). A file without one of the datasets the
    solver always writes is refused, naming it; so is a file HDF5 cannot
    read (cut short, damaged: ParticleFileError, naming it)."""
    try:
        with h5py.File(path, "r") as f:
            missing = [key for key in REQUIRED if key not in f]
            if missing or "time" not in f.attrs:
                raise ValueError("%s: not a dpmFoam2D particle file (no %s)"
                                 % (path, ", ".join(missing or ["time attribute"])))
            out = {key: f[key][()] for key in FIELDS if key in f}
            out["time"] = float(f.attrs["time"])
    except FileNotFoundError:
        raise FileNotFoundError("no particle file %s" % path)
    except (OSError, KeyError, RuntimeError) as e:
        raise ParticleFileError("%s: unreadable particle file (%s): cut short or damaged "
                                "(a run killed while writing it?); remove it or rerun from "
                                "an earlier time" % (path, str(e).split("\n")[0]))
    return out


def readable(path: str) -> str | None:
    """None if path reads as a particle file, else why not (the message)."""
    try:
        read_particles(path)
    except (ValueError, OSError) as e:
        return str(e)
    return None


def read(case: str, t: float | None = None) -> dict[str, np.ndarray | float]:
    """The particles of a case at the output time nearest to t (the latest
    if t is None): read_particles of that file."""
    return read_particles(nearest_time(case, t)[1])


def list_times(case: str) -> list[tuple[float, str]]:
    """[(time, path)] of the particle files of a case, in time order ([] for
    a case without any). The time is read from the file name (as OpenFOAM
    names time directories). A case directory that does not exist is
    refused (FileNotFoundError naming it)."""
    if not os.path.isdir(case):
        raise FileNotFoundError("no case directory %s" % case)
    d = particles_dir(case)
    out = []
    if os.path.isdir(d):
        for fname in os.listdir(d):
            stem, ext = os.path.splitext(fname)
            if ext == ".h5" and TIME_NAME.match(stem):
                out.append((float(stem), os.path.join(d, fname)))
    return sorted(out)


def nearest_time(case: str, t: float | None = None) -> tuple[float, str]:
    """(time, path) of the particle file nearest to t; the latest if t is
    None. A time that is no finite number is refused (ValueError): no file
    is nearest to nan."""
    if t is not None and not math.isfinite(float(t)):
        raise ValueError("time %s is not a finite number (a time in s, or None for the "
                         "latest particle file)" % t)
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
        try:
            with h5py.File(path, "r") as f:
                n = f["position"].shape[0]
                items = {k: (f[k].dtype, f[k].shape) for k in FIELDS if k in f}
        except (OSError, KeyError) as e:
            raise ParticleFileError("%s: unreadable particle file (%s): cut short or damaged"
                                    % (path, str(e).split("\n")[0]))

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
    with replacing(path) as f:
        f.write(text)
    return path
