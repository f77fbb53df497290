# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Movie of a dpmFoam2D case: one snapshot per particle output time, then mp4.

  dpmMovie <case> [-o movie.mp4] [-fps N] [-every K] [-height PX] [-full]
           [-start T0] [-end T1] [-keep]

Frames as dpmSnapshot draws them (one window for all frames: the bed up to
a quarter above its highest top over the run), every K-th particle time in
[T0, T1], rendered in one pvbatch session into <case>/images/frames/, then
encoded with ffmpeg (H.264, yuv420p, N frames per second; default 25).
Default output <case>/images/movie.mp4. -keep keeps the frames. A particle
file that cannot be read (cut short) is left out with a warning naming it.
"""

import argparse
import math
import os
import shutil
import subprocess
import sys
from typing import Optional

from .. import particles as pio
from . import tools


def make_movie(case: str, out: Optional[str] = None, fps: int = 25, every: int = 1,
               height: int = 720, full: bool = False, start: Optional[float] = None,
               end: Optional[float] = None, keep: bool = False) -> str:
    """The movie of the case (see the module's usage); returns its path.
    ValueError for arguments out of range or no readable particle file,
    RuntimeError when rendering or ffmpeg fails."""
    if every < 1 or fps < 1 or height < 2:
        raise ValueError("-every and -fps must be >= 1, -height >= 2")
    for name, value in (("start", start), ("end", end)):
        if value is not None and not math.isfinite(value):
            raise ValueError("-%s %g: a time must be a finite number (s)" % (name, value))
    pio.check_case(case)

    times = [t for t, _ in pio.list_times(case)
             if (start is None or t >= start - 1e-12)
             and (end is None or t <= end + 1e-12)][::every]
    # a series: a file that cannot be read is left out, said, not drawn
    readable = []
    for t in times:
        problem = pio.readable(pio.nearest_time(case, t)[1])
        if problem:
            print("dpmMovie: warning: %s; its frame is left out" % problem, file=sys.stderr)
        else:
            readable.append(t)
    times = readable
    if not times:
        raise ValueError("no particle files in %s for these times" % pio.particles_dir(case))
    out = out or os.path.join(case, "images", "movie.mp4")
    frameDir = os.path.join(case, "images", "frames")
    shutil.rmtree(frameDir, ignore_errors=True)
    os.makedirs(frameDir)
    frames = [os.path.join(frameDir, "frame_%06d.png" % i) for i in range(len(times))]
    print("dpmMovie: rendering %d frames" % len(frames))
    tools.render(case, times, frames, height=height, full=full)
    os.makedirs(os.path.dirname(os.path.abspath(out)) or ".", exist_ok=True)
    # encoded beside out, then renamed onto it: a link at out is replaced,
    # not written through
    tmp = os.path.join(os.path.dirname(os.path.abspath(out)),
                       ".%s.%d%s" % (os.path.basename(out), os.getpid(),
                                     os.path.splitext(out)[1] or ".mp4"))
    cmd = ["ffmpeg", "-y", "-loglevel", "error", "-framerate", str(fps),
           "-i", os.path.join(frameDir, "frame_%06d.png"),
           "-c:v", "libx264", "-pix_fmt", "yuv420p",
           "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", tmp]
    r = subprocess.run(cmd)
    if r.returncode != 0 or not os.path.isfile(tmp):
        if os.path.exists(tmp):
            os.remove(tmp)
        raise RuntimeError("ffmpeg failed: %s" % " ".join(cmd))
    os.replace(tmp, out)
    if not keep:
        shutil.rmtree(frameDir, ignore_errors=True)
    return out


def main():
    ap = argparse.ArgumentParser(prog="dpmMovie", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("-o", dest="out", default=None, help="output mp4")
    ap.add_argument("-fps", type=int, default=25, help="frames per second")
    ap.add_argument("-every", type=int, default=1, help="use every K-th output time")
    ap.add_argument("-height", type=int, default=720, help="height in pixels")
    ap.add_argument("-full", action="store_true", help="whole column, not just the bed")
    ap.add_argument("-start", type=float, default=None, help="first time (s)")
    ap.add_argument("-end", type=float, default=None, help="last time (s)")
    ap.add_argument("-keep", action="store_true", help="keep the frame PNGs")
    args = ap.parse_args()
    print(make_movie(args.case, args.out, args.fps, args.every, args.height, args.full,
                     args.start, args.end, args.keep))


def command():
    """The console script dpmMovie."""
    try:
        main()
    except (FileNotFoundError, RuntimeError, ValueError) as e:
        sys.exit("dpmMovie: %s" % e)
