# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The local runner of dpmStudy: each bed or case a child process group
(Job), run a few at once with progress lines (run_here), skipping a
directory another process works in (running_in, the directory's lock); and
the restart housekeeping: logs rotated, time directories without a complete
restart state set aside (latest_complete_time)."""

import os
import re
import signal
import subprocess
import sys
import time

from ..fields import time_dirs
from ..files import create_new
from .locks import LOCK_PID, LockError, lock_holder, take_lock


PROGRESS = re.compile(r"Progress: t = (\S+) s \((\d+)%\), (\S+) wall s per "
                      r"simulated s, ETA (.*)$")


def say(*args):
    print(*args, flush=True)


def ends_with_divider(path):
    """Whether a field file ends with the divider OpenFOAM writes last (a
    file cut short lacks it)."""
    with open(path, "rb") as f:
        f.seek(0, os.SEEK_END)
        f.seek(max(f.tell() - 256, 0))
        last = f.read().rstrip().rsplit(b"\n", 1)[-1]
    return last.startswith(b"// *") and last.endswith(b"//") and len(last) > 6


def complete(case, name):
    """The solver's rule (restart/incompleteTimes.C): U, p_rgh and the
    particle state, the concurrent schedule's reaction whole or absent, and
    no field file cut short."""
    d = os.path.join(case, name)
    exchange = [os.path.isfile(os.path.join(d, f)) for f in ("Kc", "Fp", "Ustar")]
    return (all(os.path.isfile(os.path.join(d, f))
                for f in ("U", "p_rgh", os.path.join("uniform", "dem.state")))
            and (all(exchange) or not any(exchange))
            and all(ends_with_divider(os.path.join(d, f))
                    for f in ("U", "p_rgh", "Kc", "Fp", "Ustar")
                    if os.path.isfile(os.path.join(d, f))))


def latest_complete_time(case, set_aside=False):
    """The latest time from which the case can continue; with set_aside,
    times after it without a complete restart state are renamed
    <time>.incomplete (only for a case about to run: in a running case they
    are being written)."""
    dirs = time_dirs(case)
    for t, name in reversed(dirs):
        if t == 0 or complete(case, name):
            return t
        if set_aside:
            os.rename(os.path.join(case, name), os.path.join(case, name + ".incomplete"))
    return None


def rotate_log(path):
    if os.path.exists(path):
        n = 1
        while os.path.exists("%s.%d" % (path, n)):
            n += 1
        os.rename(path, "%s.%d" % (path, n))


def running_in(directory):
    """PID of a solver, mesher or packer working in directory (started by
    another dpmStudy or by hand, here or, through the lock, on another host
    sharing the file system), or None. Two runs of one case would
    overwrite each other's time directories."""
    target = os.path.realpath(directory)
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/comm" % pid) as f:
                name = f.read().strip()
            if name in ("dpmFoam2D", "dpmPackBed", "blockMesh") and \
                    os.path.realpath("/proc/%s/cwd" % pid) == target:
                return int(pid)
        except OSError:         # gone, or not ours to look at
            continue
    holder = lock_holder(directory)
    if holder:
        m = LOCK_PID.search(holder)
        return int(m.group(1)) if m else -1
    return None


# Characters OpenFOAM's file names do not allow (fileName::valid)
BAD_PATH_CHARACTERS = {" ": "a space", "\t": "a tab", "\n": "a newline", "\r": "a return",
                       "\v": "a vertical tab", "\f": "a form feed",
                       '"': "a double quote", "'": "a single quote"}


def path_problem(what, path):
    """Why OpenFOAM would refuse path as a file name, as a message, or None."""
    for i, ch in enumerate(path):
        if ch in BAD_PATH_CHARACTERS:
            return ("%s %r has %s (character %d); OpenFOAM's file names allow no white "
                    "space (spaces, tabs, newlines) and no quotes (' \"): use a path "
                    "without them" % (what, path, BAD_PATH_CHARACTERS[ch], i + 1))
    return None


class Job:
    """One step of the study run as a child process group: a bed to pack or
    a case to run (its steps chained in one shell command)."""

    def __init__(self, name, directory, command, log, after=None, finished=None):
        self.name, self.dir, self.command, self.log = name, directory, command, log
        self.after = after          # a Job that must succeed first
        self.finished = finished    # is its result on disk (after exit 0)?
        self.proc = None
        self.state = "waiting"      # waiting, running, done, failed
        self.started = None

    def start(self, env=None):
        """Start it holding its directory's lock, handed to the child (the
        solver or packer takes it over); False if another process holds it."""
        lock = take_lock(self.dir)
        if lock is None:
            return False
        try:
            rotate_log(os.path.join(self.dir, self.log))
            out = create_new(os.path.join(self.dir, self.log))
        except OSError:
            os.close(lock)
            raise
        env = dict(os.environ if env is None else env, DPMFOAM2D_LOCK_FD=str(lock))
        self.proc = subprocess.Popen(["bash", "-c", self.command], cwd=self.dir,
                                     stdout=out, stderr=subprocess.STDOUT, env=env,
                                     pass_fds=(lock,),
                                     # a group of its own to stop it whole, but the
                                     # same session: a new session would start a new
                                     # scheduler autogroup, and `nice dpmStudy` would
                                     # not lower the solvers against other sessions
                                     process_group=0)
        out.close()
        os.close(lock)      # the child's copy holds it until the child ends
        self.state, self.started = "running", time.time()
        return True

    def poll(self):
        if self.state == "running" and self.proc.poll() is not None:
            if self.proc.returncode != 0:
                self.state = "failed"
            elif self.finished is not None and not self.finished():
                self.state = "failed (exit 0, but its end time is not on disk)"
            else:
                self.state = "done"
        return self.state

    def stop(self):
        if self.proc is not None and self.proc.poll() is None:
            os.killpg(self.proc.pid, signal.SIGTERM)
            try:
                self.proc.wait(20)
            except subprocess.TimeoutExpired:
                os.killpg(self.proc.pid, signal.SIGKILL)
                self.proc.wait()


def status(study, job):
    """The progress line of a job: its state, or where a running case is."""
    if job.state != "running" or job.log != "log.dpmFoam2D":
        return job.state
    last = None
    try:
        with open(os.path.join(job.dir, job.log), errors="replace") as f:
            for line in f:
                if line.startswith("Progress:"):
                    last = line
    except OSError:
        pass
    m = PROGRESS.match(last.strip()) if last else None
    if not m:
        return "running (starting)"
    return "running t = %s s of %g (%s%%), %.0f wall s per simulated s, ETA %s" % (
        m.group(1), study.end_time(job.dir), m.group(2), float(m.group(3)), m.group(4))


def run_here(study, jobs):
    """Run the jobs here, study.a.j at once, reporting every study.a.interval s."""
    def stop(signum, frame):
        say("dpmStudy: stopping the solvers (run again to continue)")
        for j in jobs:
            j.stop()
        sys.exit(128 + signum)
    signal.signal(signal.SIGINT, stop)
    signal.signal(signal.SIGTERM, stop)

    say("dpmStudy: %d job(s), %d at once, in %s" % (len(jobs), study.a.j, study.dir))
    env = None
    if study.a.j > 1 and "OMP_WAIT_POLICY" not in os.environ:
        # Cases sharing the cores: a case's OpenMP threads (nThreads > 1,
        # the concurrent schedule) must sleep, not spin, while they wait,
        # or they hold the core another case needs (docs/performance.md)
        env = dict(os.environ, OMP_WAIT_POLICY="passive")
        say("dpmStudy: OMP_WAIT_POLICY=passive for the cases (they share the cores)")
    last_report = 0
    while True:
        for j in jobs:
            j.poll()
            if j.state == "waiting" and j.after is not None and j.after.state == "failed":
                j.state = "failed (no bed)"
            if j.state == "waiting" and j.after is not None and \
                    j.after.state.startswith("skipped"):
                j.state = "skipped (its bed is packed by another process: run again)"
        running = [j for j in jobs if j.state == "running"]
        for j in jobs:
            if len(running) >= study.a.j:
                break
            if j.state == "waiting" and (j.after is None or j.after.state == "done"):
                # another dpmStudy may have started it since this one looked
                pid = running_in(j.dir)
                if pid:
                    j.state = "skipped (process %d runs in it)" % pid
                    continue
                try:
                    started = j.start(env)
                except (LockError, OSError) as e:
                    j.state = "failed (%s)" % e
                    continue
                if not started:
                    j.state = "skipped (%s holds its lock)" % (lock_holder(j.dir)
                                                               or "another process")
                    continue
                running.append(j)
        busy = any(j.state in ("waiting", "running") for j in jobs)
        if not busy or time.time() - last_report >= study.a.interval:
            last_report = time.time()
            say("-- %s" % time.strftime("%H:%M:%S"))
            for j in jobs:
                say("%-16s %s" % (j.name, status(study, j)))
        if not busy:
            break
        time.sleep(1)
    failed = [j for j in jobs if j.state.startswith("failed")]
    for j in failed:
        say("FAILED: %s, see %s" % (j.name, os.path.join(j.dir, j.log)))
    if failed:
        sys.exit(1)
