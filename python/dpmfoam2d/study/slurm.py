# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""dpmStudy on a Slurm cluster: the beds as one job array, the cases as a
second array that depends on it, results/ as a last job; and the state of
every bed and case of a study (local or Slurm runs) for dpmStudy status.

Each bed or case directory gets dpmStudy.sh (what its task runs: the same
steps as a local run, its log rotated, the DEM threads from
--cpus-per-task), log.slurm (one line per task start and end) and
.dpmStudy.slurm (the Slurm id of its task, <arrayJob>_<task>, for status
and to refuse a second submission while it is pending or running).
"""

import os
import shlex
import shutil
import subprocess
import sys
import time
from ..files import own_directory, replacing
from ..project import project_path

RECORD = ".dpmStudy.slurm"
ACTIVE = ("PENDING", "RUNNING", "CONFIGURING", "COMPLETING", "SUSPENDED", "REQUEUED",
          "RESIZING", "SIGNALING", "STAGE_OUT")


def say(*args):
    print(*args, flush=True)


def read_record(directory):
    try:
        with open(os.path.join(directory, RECORD)) as f:
            return f.read().strip() or None
    except OSError:
        return None


def queue_states():
    """Slurm id -> state of every job and array task in the queue ({} when
    there is no squeue or no controller answers)."""
    if shutil.which("squeue") is None:
        return {}
    r = subprocess.run(["squeue", "-h", "-r", "-o", "%i %T"], stdout=subprocess.PIPE,
                       stderr=subprocess.DEVNULL, universal_newlines=True)
    if r.returncode != 0:
        return {}
    return dict(line.split()[:2] for line in r.stdout.splitlines() if line.strip())


def active(directory, states=None):
    """(Slurm id, state) of a pending or running task of this directory,
    or None."""
    job = read_record(directory)
    if job is None:
        return None
    state = (queue_states() if states is None else states).get(job)
    return (job, state) if state in ACTIVE else None


def task_script(job, bashrc):
    """<dir>/dpmStudy.sh: one bed or case as a Slurm task (or by hand)."""
    log = job.log
    return """#!/bin/bash
# Written by dpmStudy: %(name)s as a Slurm task (runs by hand as well).
. %(bashrc)s || exit 1
cd %(dir)s || exit 1
if [ -n "${SLURM_ARRAY_TASK_ID:-}" ]; then     # the task, not its whole array
    scontrol update JobId="${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID}" \
        JobName=%(qname)s >/dev/null 2>&1
fi
if [ -n "${SLURM_CPUS_PER_TASK:-}" ]; then
    foamDictionary -entry nThreads -set "$SLURM_CPUS_PER_TASK" constant/particleProperties \\
        >/dev/null || exit 1
fi
if [ -e %(log)s ]; then
    n=1; while [ -e %(log)s.$n ]; do n=$((n + 1)); done; mv %(log)s %(log)s.$n
fi
task="${SLURM_ARRAY_JOB_ID:-${SLURM_JOB_ID:-local}}_${SLURM_ARRAY_TASK_ID:-0}"
echo "$(date '+%%F %%T') task $task on $(hostname): start" >> log.slurm
bash -c %(command)s > %(log)s 2>&1
status=$?
echo "$(date '+%%F %%T') task $task: exit $status" >> log.slurm
exit $status
""" % dict(name=job.name, bashrc=shlex.quote(bashrc),
           dir=shlex.quote(job.dir), qname=shlex.quote(job.name.replace("/", "-")),
           log=shlex.quote(log), command=shlex.quote(job.command))


ARRAY_TASK = """#!/bin/bash
# Written by dpmStudy: task i of an array runs line i+1 of the list given.
dir="$(sed -n "$((SLURM_ARRAY_TASK_ID + 1))p" "$1")"
[ -n "$dir" ] || { echo "no line $((SLURM_ARRAY_TASK_ID + 1)) in $1" 1>&2; exit 1; }
exec bash "$dir/dpmStudy.sh"
"""


def sbatch(args, what):
    r = subprocess.run(["sbatch", "--parsable"] + args, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, universal_newlines=True)
    if r.returncode != 0:
        sys.exit("dpmStudy: sbatch refused the %s: %s\n  sbatch %s" % (
            what, r.stderr.strip() or r.stdout.strip(), " ".join(map(shlex.quote, args))))
    return r.stdout.strip().split(";")[0]


def check_sbatch():
    if shutil.which("sbatch") is None:
        sys.exit("dpmStudy: submit: no sbatch on PATH (is this a Slurm cluster's login "
                 "node, and its module loaded?); nothing submitted")


def submit(study, beds, cases, bed_deps, sbatch_options, results_args):
    """Submit the beds, then the cases (afterok on the beds they need),
    then results/ (afterany on the cases). beds, cases: Jobs to run;
    bed_deps: Slurm ids of beds already pending or running."""
    # each task sources the project's environment, as a local run has it
    bashrc = project_path("dpmStudy submit (its Slurm tasks source etc/bashrc)",
                          "etc", "bashrc")
    slurm = os.path.join(study.dir, "slurm")
    own_directory(slurm)
    task = os.path.join(slurm, "task.sh")
    with replacing(task) as f:
        f.write(ARRAY_TASK)
    stamp = time.strftime("%Y%m%d-%H%M%S")
    name = os.path.basename(study.dir)
    out = os.path.join(slurm, "%x_%A_%a.out")

    def array(jobs, kind, deps):
        for j in jobs:
            with replacing(os.path.join(j.dir, "dpmStudy.sh")) as f:
                f.write(task_script(j, bashrc))
        listing = os.path.join(slurm, "%s_%s.list" % (stamp, kind))
        with replacing(listing) as f:
            f.write("".join(j.dir + "\n" for j in jobs))
        args = ["--job-name", "%s-%s" % (name, kind), "--array", "0-%d" % (len(jobs) - 1),
                "--output", out]
        if deps:
            args += ["--dependency", "afterok:" + ":".join(deps), "--kill-on-invalid-dep=yes"]
        job = sbatch(args + sbatch_options + [task, listing], kind)
        for i, j in enumerate(jobs):
            with replacing(os.path.join(j.dir, RECORD)) as f:
                f.write("%s_%d\n" % (job, i))
        return job

    deps = list(bed_deps)
    if beds:
        bedJob = array(beds, "beds", [])
        say("dpmStudy: beds submitted as Slurm job array %s (%d tasks)" % (bedJob, len(beds)))
        deps.append(bedJob)
    if not cases:
        return
    casesJob = array(cases, "cases", deps)
    say("dpmStudy: cases submitted as Slurm job array %s (%d tasks%s)" % (
        casesJob, len(cases), ", after " + ", ".join(deps) if deps else ""))
    script = os.path.join(slurm, "results.sh")
    with replacing(script) as f:
        f.write("#!/bin/bash\n# Written by dpmStudy: results/ once the cases have run\n"
                ". %s || exit 1\nexec %s\n" % (
                    shlex.quote(bashrc),
                    " ".join(map(shlex.quote, ["dpmStudy", "results", study.dir]
                                 + results_args))))
    resultsJob = sbatch(["--job-name", "%s-results" % name, "--dependency",
                         "afterany:" + casesJob, "--kill-on-invalid-dep=yes",
                         "--output", os.path.join(slurm, "%x_%j.out")] + sbatch_options
                        + [script], "results job")
    with replacing(os.path.join(slurm, "results.job")) as f:
        f.write(resultsJob + "\n")
    say("dpmStudy: results/ submitted as Slurm job %s (after %s)" % (resultsJob, casesJob))


def last_progress(log):
    """The simulated time and the ETA (s) of a running case's last Progress line
    (None, None without one). Read from the end, in ever longer tails: a 60-s
    case's log holds ~200 MB, and Progress comes every 10 s of wall time."""
    try:
        size = os.path.getsize(log)
        with open(log, "rb") as f:
            tail = 1 << 20
            while True:
                f.seek(max(size - tail, 0))
                lines = f.read().decode(errors="replace").splitlines()
                if tail < size:
                    lines = lines[1:]       # the first may be cut
                for line in reversed(lines):
                    if line.startswith("Progress: t = "):
                        words = line.split()
                        eta = words[words.index("ETA") + 1] if "ETA" in words else None
                        return words[3], float(eta) if eta else None
                if tail >= size:
                    return None, None
                tail *= 8
    except (OSError, ValueError, IndexError):
        return None, None


def hours(seconds):
    return "%.1f h" % (seconds/3600) if seconds >= 3600 else "%.0f min" % (seconds/60)


def status(study_dir, running_in, latest_complete_time):
    """One line per bed and case of study_dir: state, job, simulated time."""
    from . import cases as study_cases
    from .archive import is_summary, summary_time
    from .runner import end_time, finished as is_finished
    states = queue_states()
    beds_dir = os.path.join(study_dir, "beds")
    # (a dot name: a bed being made)
    dirs = [("beds/" + b, os.path.join(beds_dir, b), "bed")
            for b in sorted(os.listdir(beds_dir)) if not b.startswith(".")] \
        if os.path.isdir(beds_dir) else []
    dirs += [(c["case"], c["dir"], "case") for c in study_cases.find_cases(study_dir)]
    if not dirs:
        say("dpmStudy: no beds or cases in %s" % study_dir)
        return
    say("%-28s %-11s %-14s %s" % ("bed / case", "state", "job", "simulated time"))
    remaining = []      # (simulated s left, running) of every unfinished case
    for name, d, kind in dirs:
        job = read_record(d)
        pid = running_in(d)
        slurmState = states.get(job) if job else None
        last_line = ""
        try:
            with open(os.path.join(d, "log.slurm")) as f:
                last_line = f.read().strip().splitlines()[-1]
        except (OSError, IndexError):
            pass
        if kind == "bed":
            t = ""
            finished = os.path.isfile(os.path.join(d, "constant", "packedBed.state"))
            log = os.path.join(d, "log.dpmPackBed")
        elif is_summary(d):
            # imported: no time directories, the time its summary records;
            # never run here, so nothing of it is left to simulate
            tc, end = summary_time(d), end_time(d)
            finished = is_finished(d)
            say("%-28s %-11s %-14s %s" % (name, "done" if finished else "incomplete",
                                          "imported", "%s of %g s (an imported summary%s)" % (
                                              "%g" % tc if tc is not None else "no time",
                                              end, "" if finished else
                                              ": cannot be continued")))
            continue
        else:
            tc = latest_complete_time(d)
            end = end_time(d)
            finished = is_finished(d)
            log = os.path.join(d, "log.dpmFoam2D")
            running, eta = (last_progress(log) if pid or slurmState == "RUNNING"
                            else (None, None))
            t = "%s of %g s" % (running if running else "%g" % (tc or 0), end)
            if eta is not None:
                t += ", ETA " + hours(eta)
            if not finished:
                left = end - float(running if running else tc or 0)
                remaining.append((left, bool(pid) or slurmState == "RUNNING"))
        if pid:
            state, job = "running", "local pid %d" % pid
        elif slurmState in ACTIVE:
            state = slurmState.lower()
        elif finished:
            state = "done"
        elif " exit " in last_line and not last_line.endswith(" exit 0"):
            state = "failed"
        elif os.path.isfile(log) and failed_log(log):
            state = "failed"
        elif os.path.isfile(log):
            state = "stopped"
        else:
            state = "not started"
        say("%-28s %-11s %-14s %s" % (name, state, job or "-", t))
    if remaining:
        left = sum(r[0] for r in remaining)
        nRunning = sum(1 for r in remaining if r[1])
        say("left: %g simulated s in %d case(s), %d running (ETA: the solver's, at its"
            " mean pace since it started)" % (left, len(remaining), nRunning))


def failed_log(log):
    with open(log, errors="replace") as f:
        text = f.read()
    return "FOAM FATAL" in text or "Error" in text[-2000:]
