# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The study of dpmStudy: its beds and cases made from the template (names,
settings, variants, locks), run here (study.jobs) or submitted to Slurm
(study.slurm). The command line and its usage: study.command_line."""

import fcntl
import os
import re
import shutil
import sys

from . import definition as study_definition
from . import archive as study_archive, cases as study_cases, jobs as study_jobs, \
    slurm as study_slurm
from .foam_edit import foam_remove, foam_set
from ..files import own_directory, write_text
from .jobs import Job, latest_complete_time, lock_holder, running_in
from .locks import LockError, flock_holders, open_lock, take_lock
from .variants import Variant
from ..project import require_programs


# What a case or bed does not take from the template: run products, and
# the study's own files (its variants and studyDict)
NOT_COPIED = re.compile(r"^([0-9][0-9.eE+-]*|[0-9.]+\.incomplete(\.[0-9]+)?|particles|"
                        r"postProcessing|images|log\..*|case\.foam|dynamicCode|\.dpmLock|"
                        r"polyMesh|packedBed.*|variants|studyDict)$")


# The study's own lock: shared by its local runs, held alone by a Slurm
# submission (dpmStudy submit)
STUDY_LOCK = ".dpmStudy.lock"


def say(*args):
    print(*args, flush=True)


def bed_name(w, seed=None, variant=None):
    return "w%.2f" % w + ("_" + variant if variant else "") + \
        ("" if seed is None else "_seed%d" % seed)


def case_name(w, p, seed=None, variant=None):
    return "w%.2f_%gbar" % (w, p) + ("_" + variant if variant else "") + \
        ("" if seed is None else "_seed%d" % seed)


def end_time(case):
    """The end time a case's constant/caseSettings sets."""
    return float(study_cases.flat_dictionary(
        os.path.join(case, "constant", "caseSettings"))["endTime"])


def finished(case):
    """Whether the case's end time is on disk (or its summary records it)."""
    return study_archive.finished(case, end_time(case))


def locked(directory):
    """take_lock, its refusal of a lock path that cannot be one an exit."""
    try:
        return take_lock(directory)
    except LockError as e:
        sys.exit("dpmStudy: %s" % e)


def copy_template(template, dest):
    shutil.copytree(template, dest,
                    ignore=lambda d, names: [n for n in names if NOT_COPIED.match(n)])


def make_dir(template, dest, fill):
    """dest made whole or not at all: the template copied into a directory
    of its own beside dest (a dot name, which no study lists), fill(it)
    run there, then renamed to dest. A failed fill (a variant value
    foamDictionary refuses) leaves nothing."""
    tmp = os.path.join(os.path.dirname(dest), ".%s.making%d" % (os.path.basename(dest),
                                                               os.getpid()))
    shutil.rmtree(tmp, ignore_errors=True)
    try:
        copy_template(template, tmp)
        fill(tmp)
        os.rename(tmp, dest)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise


class Study:

    def __init__(self, args):
        self.a = args
        self.dir = os.path.abspath(args.studyDir)
        self.template = os.path.realpath(args.template)
        self.ws = args.w
        self.ps = args.p
        self.seeds = args.seeds or [None]
        self.definition = args.definition
        self.slurm_states = None     # squeue's view, read once when needed
        self.variant = Variant(args.variant, self.template) if args.variant else None
        if self.variant:
            self.variant.check(self.template)
        # caseSettings particleScale from -scale (a variant's own included)
        self.scale = self.variant.scaled(args.scale) if self.variant else args.scale

    def apply_variant(self, directory):
        """The variant's edits with -scale's particleScale (it includes the
        variant's own) in place of the variant's, then that particleScale."""
        self.variant.apply(directory, self.scale)
        if self.scale is not None:
            foam_set(os.path.join(directory, "constant", "caseSettings"),
                     "particleScale", self.scale)

    # -- setting up ---------------------------------------------------------

    def settings(self, case, w, p=None, seed=None):
        s = os.path.join(case, "constant", "caseSettings")
        foam_set(s, "wSmall", w)
        if seed is not None:
            foam_set(s, "seed", seed)
        if p is not None:
            foam_set(s, "pressure", p)
        for entry in ("endTime", "settleTime", "writeInterval"):
            value = getattr(self.a, entry)
            if value is not None:
                foam_set(s, entry, value)
        if self.scale is not None:
            foam_set(s, "particleScale", self.scale)
        # How U0 is set (gasProperties has exactly one of the two entries)
        gas = os.path.join(case, "constant", "gasProperties")
        for entry, other in (("U0byUmf", "excessVelocity"), ("excessVelocity", "U0byUmf")):
            value = getattr(self.a, entry)
            if value is not None and p is not None:
                foam_remove(gas, other)
                foam_set(gas, entry, value)

    def bed_of(self, w, seed=None):
        """The bed's name: the template's, or the variant's own if it shapes it."""
        own = self.variant and self.variant.shapes_bed()
        return bed_name(w, seed, self.variant.name if own else None)

    def bed_job(self, w, seed=None):
        bed = os.path.join(self.dir, "beds", self.bed_of(w, seed))
        state = os.path.join(bed, "constant", "packedBed.state")
        if os.path.isfile(state):
            return None
        queued = self.slurm_active(bed)
        if queued:
            return queued[0]
        pid = running_in(bed)
        if pid:
            sys.exit("dpmStudy: %s is being packed by process %d (another dpmStudy?): "
                     "run again when it has finished" % (bed, pid))
        def fill(d):
            self.settings(d, w, seed=seed)
            if self.variant and self.variant.shapes_bed():
                self.apply_variant(d)     # after the settings, as in its cases
        made = not os.path.isdir(bed)
        if made:
            own_directory(os.path.dirname(bed))
            make_dir(self.template, bed, fill)
        lock = locked(bed)
        if lock is None:
            sys.exit("dpmStudy: %s is being packed by %s: run again when it has finished"
                     % (bed, lock_holder(bed) or "another process"))
        try:
            if not made:            # a bed whose packing did not end: today's settings
                fill(bed)
        finally:
            os.close(lock)
        # Saved under a temporary name first: a packing killed half-way
        # leaves no bed that looks finished (-overwrite: a temporary left by
        # an earlier, interrupted study is the study's own to replace).
        command = ("set -e; rm -rf 0; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1; "
                   "dpmPackBed -overwrite -output constant/packedBed.state.tmp; "
                   "mv constant/packedBed.state.tmp constant/packedBed.state")
        return Job("beds/" + self.bed_of(w, seed), bed, command, "log.dpmPackBed")

    def case_dir(self, w, p, seed=None):
        return os.path.join(self.dir, case_name(w, p, seed,
                                                self.variant.name if self.variant else None))

    def end_time(self, case):
        return end_time(case)

    def finished(self, case):
        return finished(case)

    def case_job(self, w, p, seed, bed):
        case = self.case_dir(w, p, seed)
        name = os.path.basename(case)
        existed = os.path.isdir(case)
        if not existed:
            def fill(d):
                self.settings(d, w, p, seed)
                # before the variant: foamDictionary writes particleProperties
                # with its #includeIfPresent "packedBed" expanded as it is then
                write_text(os.path.join(d, "constant", "packedBed"),
                           '// The bed of this mass fraction, packed once by dpmStudy\n'
                           'file "$FOAM_CASE/../beds/%s/constant/packedBed.state";\n'
                           % self.bed_of(w, seed))
                if self.variant:
                    self.apply_variant(d)
            make_dir(self.template, case, fill)
        elif study_archive.is_summary(case):
            # run elsewhere and imported: its tables stand for it
            self.check_variant(case)
            if not self.finished(case):
                sys.exit("dpmStudy: %s is the summary of a run that ended at %g s, before "
                         "this study's endTime %g s: it cannot be continued here; remove it "
                         "to run the case anew" % (case, study_archive.summary_time(case),
                                                    self.end_time(case)))
            t = study_archive.summary_time(case)
            if self.a.endTime is not None and t < self.a.endTime - 1e-9:
                say("%-16s an imported summary (t = %g s): it cannot be continued to "
                    "-endTime %g s and keeps its time; remove it to run the case anew"
                    % (name, t, self.a.endTime))
            else:
                say("%-16s finished (t = %g s): an imported summary" % (name, t))
            return None
        else:
            self.check_variant(case)
            queued = self.slurm_active(case)
            if queued:
                say("%-16s skipped: Slurm task %s is %s" % (name, queued[0], queued[1].lower()))
                return None
            pid = running_in(case)
            if pid:
                say("%-16s skipped: process %d runs in it (another dpmStudy?)" % (name, pid))
                return None
        # the case's lock while it is set up: no solver starts in it meanwhile
        lock = locked(case)
        if lock is None:
            say("%-16s skipped: %s holds its lock" % (name, lock_holder(case) or "another process"))
            return None
        try:
            if existed:
                self.settings(case, w, p, seed)
            if self.finished(case):
                return None
            latest_complete_time(case, set_aside=True)
            study_archive.record_build(case)
        finally:
            os.close(lock)
        steps = ["set -e"]
        if not os.path.isdir(os.path.join(case, "0")):
            steps.append("cp -r 0.orig 0")
        if not os.path.isfile(os.path.join(case, "constant", "polyMesh", "faces")):
            steps.append("blockMesh > log.blockMesh 2>&1")
        steps.append("exec dpmFoam2D")
        return Job(name, case, "; ".join(steps), "log.dpmFoam2D", bed,
                   finished=lambda: self.finished(case))

    def slurm_active(self, directory):
        """(Slurm id, state) of a pending or running task of directory."""
        if study_slurm.read_record(directory) is None:
            return None
        if self.slurm_states is None:
            self.slurm_states = study_slurm.queue_states()
        return study_slurm.active(directory, self.slurm_states)

    def check_variant(self, case):
        """An existing case was made with this variant's edits, unchanged."""
        record = os.path.join(case, "constant", "variant")
        had = open(record).read() if os.path.isfile(record) else None
        want = self.variant.record() if self.variant else None
        if had != want:
            sys.exit("dpmStudy: %s was made %s, now %s: the edits differ; remove the "
                     "case or use another study directory"
                     % (case, "with the variant recorded in " + record if had else
                        "without a variant", "variant " + self.variant.path
                        if self.variant else "without one"))

    # -- running ------------------------------------------------------------

    def prepare(self):
        """Make the beds and cases not made yet; return the jobs still to
        run (beds, cases) and the Slurm ids of beds being packed there."""
        os.makedirs(self.dir, exist_ok=True)
        self.record_definition()
        beds, bed_jobs, queued = {}, [], []
        for w in self.ws:
            for seed in self.seeds:
                if all(study_archive.is_summary(self.case_dir(w, p, seed)) for p in self.ps):
                    beds[w, seed] = None    # no case of it runs here: nothing to pack
                    continue
                job = self.bed_job(w, seed)
                if isinstance(job, str):        # a Slurm task packs it
                    queued.append(job)
                    job = None
                beds[w, seed] = job
                if job:
                    bed_jobs.append(job)
        case_jobs = []
        for w in self.ws:
            for p in self.ps:
                for seed in self.seeds:
                    job = self.case_job(w, p, seed, beds[w, seed])
                    if job:
                        case_jobs.append(job)
                    elif study_archive.is_summary(self.case_dir(w, p, seed)):
                        pass                # case_job said what it is
                    elif self.finished(self.case_dir(w, p, seed)):
                        case = self.case_dir(w, p, seed)
                        say("%-16s finished (t = %g s)" % (os.path.basename(case),
                                                           self.end_time(case)))
        return bed_jobs, case_jobs, queued

    def record_definition(self):
        """The template's studyDict copied into the study directory (the
        results follow the copy); a study made with another one is refused."""
        path = os.path.join(self.dir, study_definition.FILE_NAME)
        if not os.path.isfile(path):
            write_text(path, self.definition.text)
            return
        with open(path) as f:
            if f.read() != self.definition.text:
                sys.exit("dpmStudy: %s differs from the template's %s: the study was made "
                         "with another matrix or other findings; remove %s to take the "
                         "template's, or use another study directory"
                         % (path, self.definition.path, path))

    def study_lock(self, exclusive):
        """The study's lock (STUDY_LOCK), shared by its local runs, held
        alone by a submission; None while the other kind holds it."""
        try:
            fd = open_lock(os.path.join(self.dir, STUDY_LOCK))
        except LockError as e:
            sys.exit("dpmStudy: %s" % e)
        try:
            fcntl.flock(fd, (fcntl.LOCK_EX if exclusive else fcntl.LOCK_SH) | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            return None
        return fd

    def run(self):
        os.makedirs(self.dir, exist_ok=True)
        lock = self.study_lock(exclusive=False)
        if lock is None:
            sys.exit("dpmStudy: a Slurm submission of %s is under way (it holds %s): run "
                     "again when it has ended" % (self.dir, os.path.join(self.dir, STUDY_LOCK)))
        try:
            self.run_locked()
        finally:
            os.close(lock)

    def run_locked(self):
        bed_jobs, case_jobs, queued = self.prepare()
        if queued:
            sys.exit("dpmStudy: Slurm packs beds of this study (tasks %s): run again when "
                     "they have finished, or use dpmStudy submit" % ", ".join(queued))
        jobs = bed_jobs + case_jobs
        if not jobs:
            return
        require_programs(["blockMesh"] + (["dpmPackBed"] if bed_jobs else [])
                         + (["dpmFoam2D"] if case_jobs else []), "dpmStudy run")
        study_jobs.run_here(self, jobs)

    def submit(self, sbatch_options, results_args):
        """The jobs as Slurm job arrays (see study.slurm), unless a local
        run holds the study's lock (the lock decides: a killed run leaves
        nothing that could name another process later)."""
        study_slurm.check_sbatch()
        lock = None
        if os.path.isdir(self.dir):
            lock = self.study_lock(exclusive=True)
            if lock is None:
                pids = flock_holders(os.path.join(self.dir, STUDY_LOCK))
                sys.exit("dpmStudy: a local dpmStudy (%s) runs this study (it holds %s); "
                         "stop it (its cases continue on the cluster) and submit again; "
                         "nothing submitted"
                         % ("process " + ", ".join(map(str, pids)) if pids else "on another host",
                            os.path.join(self.dir, STUDY_LOCK)))
        try:
            self.submit_locked(sbatch_options, results_args)
        finally:
            if lock is not None:
                os.close(lock)

    def submit_locked(self, sbatch_options, results_args):
        bed_jobs, case_jobs, queued = self.prepare()
        if not bed_jobs and not case_jobs:
            say("dpmStudy: nothing to submit")
            return
        study_slurm.submit(self, bed_jobs, case_jobs, queued, sbatch_options, results_args)
