# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""A study of a template: small-particle mass fractions x operating
pressures, each case made from the template (default tutorials/paperStudy,
the paper's: Norouzi et al. 2012), run, and summed up; over several random
packings (seeds) and with named variants of the model.

  dpmStudy [<studyDir>] [-w W ...] [-p P ...] [-seeds N | -seeds S1 S2 ...]
           [-variant NAME|FILE] [-j N] [-endTime T]
           [-U0byUmf R | -excessVelocity X] [-mean X] [-rateWindow T0 T1]
           [-results] [-noPictures] [-scale S] [-settleTime T]
           [-writeInterval T] [-template DIR] [-listVariants]
           [-status] [-slurm [-- <sbatch options>]]

The template's studyDict defines the study: the default matrix (-w, -p),
the values allowed, and the findings that results/ tests (differences
between two cells of the matrix, with their expected signs); the runner
copies it into <studyDir>, whose copy -results then follows (a template
whose studyDict differs later is refused for that study directory).

<studyDir> (default ./paperStudy) gets
  beds/w0.50/           one packed and settled bed per mass fraction
                        (dpmPackBed), shared by all pressures and variants;
                        with -seeds one per mass fraction and seed:
                        beds/w0.50_seed2/
  w0.50_16bar/ ...      the cases: the template with constant/caseSettings
                        set (wSmall, pressure, seed, endTime) and
                        constant/packedBed naming the bed of their mass
                        fraction (and seed); with -seeds w0.50_16bar_seed2,
                        with -variant upwind w0.50_16bar_upwind(_seed2)
  results/              summary.md + summary.csv (one row per case: final
                        M, mean of the last X s, segregation indices, bed
                        statistics), windows.csv (M and the indices over
                        consecutive windows of X s), ensemble.md/.csv (per
                        variant, mass fraction and pressure: the mean over
                        seeds with its 95 % confidence interval),
                        findings.md (the studyDict's findings, the
                        paper's 2-4 for its template, as differences
                        between ensembles, with intervals, per variant),
                        verdicts.md (what each variant does to the
                        findings against the baseline's seeds: turns
                        round, moves beyond the packings' scatter, or
                        not), variants.md (the edits of every variant
                        used), mixing_<p>bar.png (M(t) per pressure, the
                        paper's Fig. 3; a band of 95 % over seeds),
                        mixing_w<w>.png, indices.png, hydrodynamics.png,
                        snapshots.png (Fig. 2); a variant's figures carry
                        its name (mixing_upwind_1bar.png)

Seeds: -seeds 3 runs every case from the packings of seeds 1, 2 and 3 (the
random packing of dpmPackBed; particleProperties initialBed.seed via
caseSettings); -seeds 4 7 runs seeds 4 and 7. Without -seeds the cases use
the template's seed and carry no _seed suffix.
Variants: a named set of dictionary edits kept with the template in
<template>/variants/<name> (or a file given by path), one edit a line:
    <file> <entry> <value>        foamDictionary -entry <entry> -set <value>
    <file> <entry> -remove        foamDictionary -entry <entry> -remove
(# starts a comment). The edits are applied when a case is made; the case
keeps a copy of the file as constant/variant (a rerun from it: -variant
<case>/constant/variant) and refuses a changed file later. -listVariants
lists the template's variants. A variant that edits more than the gas's
numerics and closures (fvSchemes, fvSolution, gasProperties, the drag model,
its coefficients and the formulation), e.g. the particles, the voidage model
or the mesh, packs beds of its own with its edits (beds/w0.50_<name>_seed1).

Runs N cases at once (default: the number of cores). Run it again after an
interruption: finished cases are skipped, the others continue from their
last written time (controlDict startFrom latestTime); a time directory
without a complete restart state is set aside as <time>.incomplete. A case
is finished when its end time is on disk. A bed or case another process
works in (its lock <dir>/.dpmLock is held: a solver, a packer, another
dpmStudy setting it up) is skipped, naming the process; dpmStudy holds a
case's lock while setting it up and hands it to its solver.
-endTime T sets every case's end time (a quick look: -endTime 2; later a
longer one continues from where the short one stopped). One line per case
every -interval s (default 30): state, simulated time, wall s per simulated
s, ETA (from the solver's Progress lines). Ctrl-C or SIGTERM stops the
solvers it started; run again to continue.
-results only remakes results/ from what has been run. results/ covers every
case of <studyDir>, whichever -w, -p, -seeds and -variant selected the cases
to run.
-U0byUmf R or -excessVelocity X sets how every case's U0 is chosen: the
paper's U0/Umf (template: 1.25), or U0 - Umf in m/s, the same bubble flow at
every pressure (use another <studyDir> for such a variant study).
-status prints every bed and case with its state (not started, pending,
running, stopped, failed, done), its job (a local process or a Slurm task)
and its simulated time (a running case's with the solver's ETA), then the
simulated seconds left over all cases.
-slurm: on a Slurm cluster, prepares the beds and cases as a local run does,
then submits the beds as a job array, the cases as a second array that
waits for them (afterok) and a last job that makes results/ (afterany); one
task per bed or case, each running it as a local run would and continuing
from its latest complete time; options after -- go to every sbatch (e.g.
-- --partition=short --time=4:00:00 --cpus-per-task=2; --cpus-per-task sets
the DEM threads). A task that reached its time limit continues when the
study is submitted again; beds and cases already pending or running are not
submitted twice. Logs: <case>/log.dpmFoam2D, <case>/log.slurm (task starts
and ends), <study>/slurm/<study>-cases_<job>_<task>.out.
-rateWindow T0 T1: the window (T0, T1] of M/M(0) that findings.md compares
for the segregation rate (finding 4); default the first -mean window.
-scale, -settleTime and -writeInterval make a reduced study for tests
(fewer particles: a fraction of Table 3's counts, or of a variant's own
particleScale, e.g. slab5mm's twice Table 3's; shorter settling).
"""

import argparse
import os
import re
import shutil
import sys

from .. import BIN_DIR, PROJECT_DIR
from . import definition as study_definition
from . import jobs as study_jobs, results as study_results, slurm as study_slurm
from .jobs import Job, latest_complete_time, lock_holder, path_problem, running_in, take_lock
from .foam_edit import foam_remove, foam_set
from .variants import Variant, first_line_comment, list_variants

# What a case or bed does not take from the template: run products, and
# the study's own files (its variants and studyDict)
NOT_COPIED = re.compile(r"^([0-9][0-9.eE+-]*|[0-9.]+\.incomplete(\.[0-9]+)?|particles|"
                        r"postProcessing|images|log\..*|case\.foam|dynamicCode|\.dpmLock|"
                        r"polyMesh|packedBed.*|variants|studyDict)$")


def say(*args):
    print(*args, flush=True)


def bed_name(w, seed=None, variant=None):
    return "w%.2f" % w + ("_" + variant if variant else "") + \
        ("" if seed is None else "_seed%d" % seed)


def case_name(w, p, seed=None, variant=None):
    return "w%.2f_%gbar" % (w, p) + ("_" + variant if variant else "") + \
        ("" if seed is None else "_seed%d" % seed)


def copy_template(template, dest):
    shutil.copytree(template, dest,
                    ignore=lambda d, names: [n for n in names if NOT_COPIED.match(n)])


class Study:

    def __init__(self, args):
        self.a = args
        self.dir = os.path.abspath(args.studyDir)
        self.template = os.path.realpath(args.template)
        self.ws = args.w
        self.ps = args.p
        self.seeds = args.seeds or [None]
        self.definition = args.definition
        self.here = BIN_DIR
        self.slurm_states = None     # squeue's view, read once when needed
        self.variant = Variant(args.variant, self.template) if args.variant else None
        if self.variant:
            self.variant.check(self.template)
        # caseSettings particleScale from -scale (a variant's own included)
        self.scale = self.variant.scaled(args.scale) if self.variant else args.scale

    def apply_variant(self, directory):
        """The variant's edits, then -scale's particleScale (it includes the
        variant's own)."""
        self.variant.apply(directory)
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
        if not os.path.isdir(bed):
            copy_template(self.template, bed)
        lock = take_lock(bed)
        if lock is None:
            sys.exit("dpmStudy: %s is being packed by %s: run again when it has finished"
                     % (bed, lock_holder(bed) or "another process"))
        try:
            self.settings(bed, w, seed=seed)
            if self.variant and self.variant.shapes_bed():
                self.apply_variant(bed)     # after the settings, as in its cases
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
        return float(study_results.flat_dictionary(
            os.path.join(case, "constant", "caseSettings"))["endTime"])

    def finished(self, case):
        t = latest_complete_time(case)
        return t is not None and os.path.isfile(os.path.join(case, "log.dpmFoam2D")) \
            and t >= self.end_time(case) - 1e-9

    def case_job(self, w, p, seed, bed):
        case = self.case_dir(w, p, seed)
        name = os.path.basename(case)
        existed = os.path.isdir(case)
        if not existed:
            copy_template(self.template, case)
            self.settings(case, w, p, seed)
            # before the variant: foamDictionary writes particleProperties
            # with its #includeIfPresent "packedBed" expanded as it is then
            with open(os.path.join(case, "constant", "packedBed"), "w") as f:
                f.write('// The bed of this mass fraction, packed once by dpmStudy\n'
                        'file "$FOAM_CASE/../beds/%s/constant/packedBed.state";\n'
                        % self.bed_of(w, seed))
            if self.variant:
                self.apply_variant(case)
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
        lock = take_lock(case)
        if lock is None:
            say("%-16s skipped: %s holds its lock" % (name, lock_holder(case) or "another process"))
            return None
        try:
            if existed:
                self.settings(case, w, p, seed)
            if self.finished(case):
                return None
            latest_complete_time(case, set_aside=True)
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
            tmp = "%s.tmp%d" % (path, os.getpid())
            with open(tmp, "w") as f:
                f.write(self.definition.text)
            os.replace(tmp, path)
            return
        with open(path) as f:
            if f.read() != self.definition.text:
                sys.exit("dpmStudy: %s differs from the template's %s: the study was made "
                         "with another matrix or other findings; remove %s to take the "
                         "template's, or use another study directory"
                         % (path, self.definition.path, path))

    def run(self):
        bed_jobs, case_jobs, queued = self.prepare()
        if queued:
            sys.exit("dpmStudy: Slurm packs beds of this study (tasks %s): run again when "
                     "they have finished, or submit with -slurm" % ", ".join(queued))
        jobs = bed_jobs + case_jobs
        if not jobs:
            return
        lock = os.path.join(self.dir, ".dpmStudy.running")
        os.makedirs(lock, exist_ok=True)
        mine = os.path.join(lock, str(os.getpid()))
        open(mine, "w").close()
        try:
            study_jobs.run_here(self, jobs)
        finally:
            os.remove(mine)

    def submit(self, sbatch_options, results_args):
        """The jobs as Slurm job arrays (see study.slurm)."""
        study_slurm.check_sbatch()
        lock = os.path.join(self.dir, ".dpmStudy.running")
        others = [pid for pid in (os.listdir(lock) if os.path.isdir(lock) else [])
                  if pid.isdigit() and os.path.isdir("/proc/" + pid)]
        if others:
            sys.exit("dpmStudy: a local dpmStudy (process %s) runs this study; stop it "
                     "(its cases continue on the cluster) and submit again; nothing "
                     "submitted" % ", ".join(others))
        bed_jobs, case_jobs, queued = self.prepare()
        if not bed_jobs and not case_jobs:
            say("dpmStudy: nothing to submit")
            return
        study_slurm.submit(self, bed_jobs, case_jobs, queued, sbatch_options, results_args)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("studyDir", nargs="?", default="paperStudy")
    ap.add_argument("-w", type=float, nargs="+",
                    help="small-particle mass fractions (default: the studyDict's; "
                    "tutorials/paperStudy: 0.25 0.5 0.75)")
    ap.add_argument("-p", type=float, nargs="+",
                    help="pressures, bar (default: the studyDict's; tutorials/paperStudy: "
                    "1 8 16 32 64)")
    ap.add_argument("-j", type=int, default=os.cpu_count() or 1,
                    help="cases at once (default: number of cores); with more "
                    "than one, their OpenMP threads wait passively "
                    "(OMP_WAIT_POLICY=passive unless set)")
    ap.add_argument("-endTime", type=float, help="end time of every case (s)")
    ap.add_argument("-mean", type=float, default=10,
                    help="average the indices over the last X s (default 10)")
    ap.add_argument("-interval", type=float, default=30,
                    help="seconds between progress reports (default 30)")
    gas = ap.add_mutually_exclusive_group()
    gas.add_argument("-U0byUmf", type=float,
                     help="U0/Umf of every case (the paper's, and the template's: 1.25)")
    gas.add_argument("-excessVelocity", type=float,
                     help="U0 - Umf (m/s) of every case instead of U0/Umf: the same "
                     "bubble flow at every pressure")
    ap.add_argument("-seeds", type=int, nargs="+", metavar="S",
                    help="random packings: N (seeds 1..N) or a list of seeds")
    ap.add_argument("-variant", metavar="NAME|FILE",
                    help="a named set of dictionary edits (<template>/variants/NAME)")
    ap.add_argument("-listVariants", action="store_true",
                    help="list the template's variants and exit")
    ap.add_argument("-rateWindow", type=float, nargs=2, metavar=("T0", "T1"),
                    help="window of M/M(0) for the segregation rate in findings.md "
                    "(default: the first -mean window)")
    ap.add_argument("-slurm", action="store_true",
                    help="submit to Slurm instead of running here; sbatch options after --")
    ap.add_argument("-status", action="store_true",
                    help="state, job and simulated time (ETA if running) of every bed and"
                         " case, and the simulated time left, then exit")
    ap.add_argument("-results", action="store_true", help="only remake results/")
    ap.add_argument("-noPictures", action="store_true", help="no snapshots")
    ap.add_argument("-scale", type=float, help="fraction of Table 3's counts (tests)")
    ap.add_argument("-settleTime", type=float, help="settling time (s) (tests)")
    ap.add_argument("-writeInterval", type=float,
                    help="gas fields and restart states every T s")
    ap.add_argument("-template", default=os.path.join(PROJECT_DIR, "tutorials", "paperStudy"))
    argv = sys.argv[1:]
    sbatch_options = argv[argv.index("--") + 1:] if "--" in argv else []
    args = ap.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    if sbatch_options and not args.slurm:
        ap.error("options after -- are for sbatch: give -slurm")
    for name in ("U0byUmf", "excessVelocity"):
        value = getattr(args, name)
        if value is not None and not value > 0:
            ap.error("-%s %g is outside (0, inf)" % (name, value))
    if args.j < 1:
        ap.error("-j %d: cases at once must be >= 1" % args.j)
    for name in ("endTime", "mean", "interval", "settleTime", "writeInterval"):
        value = getattr(args, name)
        if value is not None and not 0 < value < float("inf"):
            ap.error("-%s %g is outside (0, inf)" % (name, value))
    if args.scale is not None and not 0 < args.scale <= 1:
        ap.error("-scale %g is outside (0, 1]" % args.scale)
    for p in args.p or []:
        if not 0 < p < float("inf"):
            ap.error("-p %g: a pressure (bar) must be > 0" % p)
    for what, path in (("the study directory", os.path.abspath(args.studyDir)),
                       ("the template", os.path.realpath(args.template))):
        problem = path_problem(what, path)
        if problem:
            sys.exit("dpmStudy: " + problem)
    for name in ("results", "status"):
        if getattr(args, name) and not os.path.isdir(args.studyDir):
            ap.error("-%s: no study directory %s" % (name, args.studyDir))
    if not os.path.isdir(args.template):
        ap.error("-template %s: no such directory" % args.template)
    if args.listVariants:
        template = os.path.realpath(args.template)
        for name in list_variants(template):
            say("%-14s %s" % (name, first_line_comment(os.path.join(template, "variants", name))))
        return
    try:
        # -results and -status: the study's own copy, if it has one
        args.definition = study_results.definition_of(args.studyDir, args.template) \
            if args.results or args.status else \
            study_definition.of_template(os.path.realpath(args.template))
    except study_definition.DefinitionError as e:
        sys.exit("dpmStudy: %s" % e)
    d = args.definition
    args.w = args.w or d.w
    args.p = args.p or d.p
    for option, values, allowed, note in (("w", args.w, d.w_allowed, d.w_note),
                                          ("p", args.p, d.p_allowed, d.p_note)):
        for v in values:
            if allowed is not None and v not in allowed:
                ap.error("-%s %g: %s" % (option, v, note or "%s allows %s" % (
                    d.path, " ".join("%g" % a for a in allowed))))
    args.p = [int(p) if p == int(p) else p for p in args.p]
    if args.seeds is not None:
        if any(s < 1 for s in args.seeds):
            ap.error("-seeds %s: seeds are integers >= 1" % " ".join(map(str, args.seeds)))
        args.seeds = list(range(1, args.seeds[0] + 1)) if len(args.seeds) == 1 \
            else sorted(set(args.seeds))
    if args.rateWindow and not 0 <= args.rateWindow[0] < args.rateWindow[1]:
        ap.error("-rateWindow %g %g: 0 <= T0 < T1 wanted" % tuple(args.rateWindow))
    study = Study(args)
    if args.status:
        study_slurm.status(study, running_in, latest_complete_time)
        return
    if args.slurm:
        results_args = ["-results", "-mean", repr(args.mean)] + \
            (["-noPictures"] if args.noPictures else []) + \
            (["-rateWindow"] + [repr(t) for t in args.rateWindow] if args.rateWindow else [])
        study.submit(sbatch_options, results_args)
        return
    if not args.results:
        study.run()
    # results/ sums up every case of the study directory, not only those run now
    study_results.results(study.dir, args.mean, args.rateWindow, not args.noPictures,
                          study_results.definition_of(study.dir, study.template))


def command():
    """bin/dpmStudy."""
    main()
