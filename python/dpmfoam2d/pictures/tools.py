# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared steps of the dpm* picture commands: running the off-screen
renderer, and the layout of the mixing plots."""

import importlib.resources
import os
import random
import socket
import subprocess
import tempfile
import time

from .. import particles as pio
from ..files import create_new

def package_script(name):
    """The path of a script shipped in this package (pictures/<name>), which
    ParaView's Python runs as a file."""
    return str(importlib.resources.files(__package__).joinpath(name))


def paraview_env(**extra):
    """The environment of a pvbatch that imports this package: ParaView's
    own Python finds it where this process found it (a pip installation
    outside the project, or the project's python/ on PYTHONPATH)."""
    top = os.path.dirname(str(importlib.resources.files("dpmfoam2d")).rstrip(os.sep))
    path = [top] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
    return dict(os.environ, PYTHONPATH=os.pathsep.join(path), **extra)


RENDER = package_script("render.py")

# Class colours (RGB 0-1), drawn unlit: ColorBrewer red for small (class 0),
# blue for large (class 1). The renderer and the tests take them from here.
CLASS_COLOURS = {0: (0.894, 0.102, 0.110), 1: (0.216, 0.494, 0.722)}
CLASS_NAMES = {0: "small", 1: "large"}


def ensure_foam(case):
    """<case>/case.foam, the empty file ParaView's OpenFOAM reader opens."""
    path = os.path.join(case, "case.foam")
    if not os.path.lexists(path):       # a dangling link is not followed
        try:
            create_new(path).close()
        except FileExistsError:         # made meanwhile by another tool
            pass
    return path


class VirtualDisplay:
    """An Xvfb server of its own on a free display, for pvbatch's window.

    Started directly rather than through xvfb-run: xvfb-run waits for the
    server with a SIGUSR1 handshake that cannot work when the caller runs
    with SIGUSR1 ignored (as test drivers may), and two xvfb-run -a started
    together can race for one display. Here the server's socket is awaited,
    and the display number is random."""

    def __enter__(self):
        for _ in range(20):
            n = random.randint(100, 30000)
            if os.path.exists("/tmp/.X%d-lock" % n):
                continue
            # -noreset: without it the server resets when its last client leaves
            # (our probe below), and a reset on a busy machine can refuse the
            # renderer's connection
            self.log = tempfile.TemporaryFile(mode="w+")
            self.server = subprocess.Popen(
                ["Xvfb", ":%d" % n, "-screen", "0", "2048x2048x24", "-nolisten", "tcp",
                 "-noreset"], stdout=subprocess.DEVNULL, stderr=self.log)
            for _ in range(200):
                if self._accepts("/tmp/.X11-unix/X%d" % n):
                    self.display = ":%d" % n
                    return self
                if self.server.poll() is not None:
                    break
                time.sleep(0.05)
            self.server.kill()
            self.server.wait()
            self.log.close()
        raise RuntimeError("cannot start a virtual X display (Xvfb)")

    def messages(self):
        """What the server has said (its stderr), for a failure report."""
        self.log.seek(0)
        return self.log.read()[-1500:]

    @staticmethod
    def _accepts(path):
        """True once the server takes connections: its socket file appears
        before it listens, and a busy machine can leave a gap between the two
        (pvbatch then aborts creating its window)."""
        if not os.path.exists(path):
            return False
        with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as probe:
            try:
                probe.connect(path)
                return True
            except OSError:
                return False

    def __exit__(self, *exc):
        self.server.terminate()
        try:
            self.server.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.server.kill()
        self.log.close()
        return False


def render(case, times, outs, height=1200, full=False):
    """Render the particle times to the PNG files outs with pvbatch on a
    virtual display (one ParaView session for all of them). A particle
    file that cannot be read is refused here, naming it (ValueError)."""
    for t in times:
        problem = pio.readable(pio.nearest_time(case, t)[1])
        if problem:
            raise ValueError(problem)
    ensure_foam(case)
    for out in outs:
        os.makedirs(os.path.dirname(os.path.abspath(out)) or ".", exist_ok=True)
        if os.path.exists(out):
            os.remove(out)
    cmd = ["pvbatch", RENDER, "--case", os.path.abspath(case),
           "--height", str(height), "--times"] + ["%r" % float(t) for t in times] \
        + ["--out"] + [os.path.abspath(o) for o in outs] + (["--full"] if full else [])
    # Retry a failed window (not a Python error of the renderer).
    failures = []
    for attempt in range(3):
        with VirtualDisplay() as xvfb:
            env = paraview_env(DISPLAY=xvfb.display)
            r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               text=True, env=env)
            alive = xvfb.server.poll() is None
            server = xvfb.messages()
        missing = [o for o in outs if not os.path.isfile(o)]
        # A Python error of the renderer will not go away; a window that
        # could not be made (SIGABRT in ParaView's render view) may
        if (r.returncode == 0 and not missing) or \
                ("Traceback" in r.stdout and "SIGABRT" not in r.stdout):
            break
        failures.append("attempt %d: exit %d; %s\n  Xvfb %s; its messages: %s" % (
            attempt + 1, r.returncode, "\n  ".join(
                line for line in r.stdout.splitlines()
                if any(k in line for k in ("ERR", "rror", "SIGABRT", "Traceback")))[:1500],
            "still running" if alive else "had exited", server.strip() or "none"))
        time.sleep(1 + 2 * random.random())
    if r.returncode != 0 or missing:
        raise RuntimeError("rendering failed (%s):\n%s\nlast output:\n%s"
                           % (" ".join(cmd), "\n".join(failures), r.stdout[-2000:]))
    return r.stdout
