"""Shared steps of the dpm* picture commands: running the off-screen
renderer, and the layout of the mixing plots."""

import os
import random
import subprocess
import time

HERE = os.path.dirname(os.path.realpath(__file__))
RENDER = os.path.join(HERE, "dpmRender.py")

# Class colours (RGB 0-1), drawn unlit: ColorBrewer red for small (class 0),
# blue for large (class 1). The renderer and the tests take them from here.
CLASS_COLOURS = {0: (0.894, 0.102, 0.110), 1: (0.216, 0.494, 0.722)}
CLASS_NAMES = {0: "small", 1: "large"}


def ensure_foam(case):
    """<case>/case.foam, the empty file ParaView's OpenFOAM reader opens."""
    path = os.path.join(case, "case.foam")
    if not os.path.exists(path):
        open(path, "a").close()
    return path


def render(case, times, outs, height=1200, full=False):
    """Render the particle times to the PNG files outs under
    `xvfb-run -a pvbatch` (one ParaView session for all of them)."""
    ensure_foam(case)
    for out in outs:
        os.makedirs(os.path.dirname(os.path.abspath(out)) or ".", exist_ok=True)
        if os.path.exists(out):
            os.remove(out)
    cmd = ["xvfb-run", "-a", "pvbatch", RENDER, "--case", os.path.abspath(case),
           "--height", str(height), "--times"] + ["%r" % float(t) for t in times] \
        + ["--out"] + [os.path.abspath(o) for o in outs] + (["--full"] if full else [])
    # xvfb-run -a can pick the same display as another xvfb-run started at
    # the same moment, and pvbatch then aborts opening its window: retry
    # (but not a Python error of the renderer).
    for attempt in range(4):
        r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        missing = [o for o in outs if not os.path.isfile(o)]
        if (r.returncode == 0 and not missing) or "Traceback" in r.stdout:
            break
        time.sleep(1 + 2 * random.random())
    if r.returncode != 0 or missing:
        raise RuntimeError("rendering failed (%s):\n%s" % (" ".join(cmd), r.stdout[-3000:]))
    return r.stdout
