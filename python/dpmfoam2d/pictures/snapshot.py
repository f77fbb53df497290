# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Snapshot of a dpmFoam2D case like the paper's Fig. 2, rendered off-screen.

  dpmSnapshot <case> [-time T] [-o file.png] [-height PX] [-full]

Particles of <case>/particles/<T>.h5 (the file nearest to T; default the
latest) as discs at true size, red small and blue large, in front of the gas
voidage of the nearest gas time (grey, from <case>/case.foam, created empty
if missing), with the time printed. The window is the bed (mesh width, floor
to a quarter above the bed top); -full shows the whole column. Default
output <case>/images/snapshot_<T>.png; height 1200 px, width in proportion.
In the slab mode (3D spheres, real z in the files) the spheres are drawn as a
camera sees the bed through its front wall z = 0: a sphere nearer the front
hides those behind it.
Runs `pvbatch` on the package's pictures/render.py on a virtual X display (Xvfb).
"""

import argparse
import math
import os
import sys
from typing import Optional

from .. import particles as pio
from . import tools


def snapshot(case: str, time: Optional[float] = None, out: Optional[str] = None,
             height: int = 1200, full: bool = False) -> str:
    """The snapshot of the particle file nearest to time (default the
    latest) as a PNG (see the module's usage); returns its path. ValueError
    for arguments out of range or a particle file that cannot be read,
    RuntimeError when rendering fails."""
    if height < 2:
        raise ValueError("-height %d must be >= 2 pixels" % height)
    if time is not None and not math.isfinite(time):
        raise ValueError("-time %g: a time must be a finite number (s)" % time)
    pio.check_case(case)
    t, _ = pio.nearest_time(case, time)
    out = out or os.path.join(case, "images", "snapshot_%s.png" % pio.time_name(t))
    tools.render(case, [t], [out], height=height, full=full)
    return out


def main():
    ap = argparse.ArgumentParser(prog="dpmSnapshot", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("-time", type=float, default=None, help="time (s); default latest")
    ap.add_argument("-o", dest="out", default=None, help="output PNG")
    ap.add_argument("-height", type=int, default=1200, help="height in pixels")
    ap.add_argument("-full", action="store_true", help="whole column, not just the bed")
    args = ap.parse_args()
    print(snapshot(args.case, args.time, args.out, args.height, args.full))


def command():
    """The console script dpmSnapshot."""
    try:
        main()
    except (FileNotFoundError, RuntimeError, ValueError) as e:
        sys.exit("dpmSnapshot: %s" % e)
