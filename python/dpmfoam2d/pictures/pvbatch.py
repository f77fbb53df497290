# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""dpmPvbatch <script.py> [args ...]

Runs ParaView's pvbatch on a virtual X display of its own (Xvfb), for
scripts that render or read data off-screen (and may import dpmfoam2d);
returns pvbatch's exit code.
"""
import subprocess
import sys

from .tools import VirtualDisplay, paraview_env


def command():
    """The console script dpmPvbatch."""
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "-help", "--help"):
        sys.exit(__doc__.strip())
    with VirtualDisplay() as xvfb:
        code = subprocess.call(["pvbatch"] + sys.argv[1:],
                               env=paraview_env(DISPLAY=xvfb.display))
    sys.exit(code)
