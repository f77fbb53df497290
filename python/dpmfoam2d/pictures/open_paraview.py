# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Open a dpmFoam2D case in ParaView in one step: the gas and the particles.

  dpmParaView <case> [-time T] [-screenshot file.png] [-height PX]

Shows the gas voidage (case.foam, created empty if missing) behind the
particles of particles/particles.xdmf as spheres of their true diameter,
coloured by class, at the latest time (or the one nearest to T; its
particle file must be readable, else it is refused, naming it). Without
-screenshot it opens ParaView's window with this scene (a display is
needed); with -screenshot it renders the scene off-screen (a virtual X
display) to the PNG and exits. The scene is the package's
pictures/paraview_scene.py, which ParaView can also run by itself (its header lists the settings).
"""

import argparse
import math
import os
import shutil
import subprocess
import sys

from .. import particles as pio
from . import tools

SCENE = tools.package_script("paraview_scene.py")


def class_labels(case, path):
    """'small 1.5 mm', ...: each class's name (particleProperties, in its
    order) and its particles' mean diameter in the particle file path."""
    p = pio.read_particles(path)
    names = pio.class_names(case)
    out = []
    for k in range(int(p["class"].max()) + 1 if len(p["class"]) else 0):
        d = p["diameter"][p["class"] == k]
        name = names[k] if k < len(names) else "class %d" % k
        out.append("%s %.3g mm" % (name, 1e3 * d.mean()) if len(d) else name)
    return out


def main():
    ap = argparse.ArgumentParser(prog="dpmParaView", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("-time", type=float, default=None, help="time (s); default latest")
    ap.add_argument("-screenshot", default=None, help="render off-screen to this PNG")
    ap.add_argument("-height", type=int, default=1200, help="screenshot height in pixels")
    args = ap.parse_args()
    if args.height < 2:
        sys.exit("dpmParaView: -height %d must be >= 2 pixels" % args.height)
    if args.time is not None and not math.isfinite(args.time):
        sys.exit("dpmParaView: -time %g: a time must be a finite number (s)" % args.time)
    xdmf = os.path.join(args.case, "particles", "particles.xdmf")
    if not os.path.isfile(xdmf):
        sys.exit("dpmParaView: %s not found: run dpmFoam2D in the case first"
                 " (it writes the particle files there)" % xdmf)
    # the particle file the scene shows (the XDMF's time nearest to -time):
    # one that cannot be read would leave an earlier time drawn
    try:
        t, path = pio.nearest_time(args.case, args.time)
    except FileNotFoundError as e:
        sys.exit("dpmParaView: %s" % e)
    problem = pio.readable(path)
    if problem:
        sys.exit("dpmParaView: %s; the scene would show another time than %g s" % (problem, t))
    tools.ensure_foam(args.case)
    env = dict(os.environ, DPM_PARAVIEW_CASE=os.path.abspath(args.case),
               DPM_PARAVIEW_HEIGHT=str(args.height),
               DPM_PARAVIEW_CLASSES="\n".join(class_labels(args.case, path)))
    if args.time is not None:
        env["DPM_PARAVIEW_TIME"] = repr(args.time)

    if args.screenshot:
        env["DPM_PARAVIEW_SCREENSHOT"] = os.path.abspath(args.screenshot)
        os.makedirs(os.path.dirname(env["DPM_PARAVIEW_SCREENSHOT"]), exist_ok=True)
        with tools.VirtualDisplay() as xvfb:
            env["DISPLAY"] = xvfb.display
            code = subprocess.call(["pvbatch", SCENE], env=env)
        if code != 0 or not os.path.isfile(args.screenshot):
            sys.exit("dpmParaView: pvbatch failed (exit %d); no %s" % (code, args.screenshot))
        return
    if not os.environ.get("DISPLAY"):
        sys.exit("dpmParaView: no display (DISPLAY is not set): use -screenshot"
                 " file.png to render off-screen")
    if shutil.which("paraview") is None:
        sys.exit("dpmParaView: the paraview command is not on PATH (etc/install installs it)")
    sys.exit(subprocess.call(["paraview", "--script=" + SCENE], env=env))


def command():
    """The console script dpmParaView."""
    main()
