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
           [-export <archive.tar.gz>] [-import <study dir or archive> ...]

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
(# starts a comment; <file> relative to the case and inside it: an absolute
path or one leaving the case is refused). The edits are applied when a case
is made (in a directory beside it, renamed when whole: an edit
foamDictionary refuses leaves no case); the case
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
case's lock while setting it up and hands it to its solver. A lock path that
is not a regular file (a symbolic link, a directory) is refused, naming it.
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
simulated seconds left over all cases; a summary case (below) shows as
imported, at the time it records.
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
-export A.tar.gz writes an archive of the study: its studyDict and a small
summary case of each finished case (its settings, its dictionaries, the
tables results/ reads, the head of its log and the builds it ran with,
constant/studyBuild); -import <other study dir or archive> ... adds the
finished cases found there to <studyDir> as summary cases (marked by
constant/archivedCase), which results/ reads like its own and the runner
counts as finished, never running them again. An import refuses, naming the
difference, a study of another studyDict and a case whose settings (other
than its w, pressure and seed) or dictionaries differ from the study's
cases; a case of the same name with the same settings is kept as it is (if
it has not finished here, the import says that this local case is used).
A summary case cannot be continued: a run with a longer -endTime says so
and leaves it at its time, and packs no bed that only summaries would use.
An archive is unpacked only if it holds nothing but the studyDict and
summary cases (no links, no other files) within 64 MiB a file, 1024 MiB in
all and 100000 members; its files get this process's modes (umask), not
the archive's. A symbolic link among the files a summary takes from a case
(constant/, system/, log.dpmFoam2D, the tables) is refused, naming it, at
-export and -import alike. -import then remakes results/ (a summary case
has no snapshot); run the study as usual for the cases still to run.
-rateWindow T0 T1: the window (T0, T1] of M/M(0) that findings.md compares
for the segregation rate (finding 4); default the first -mean window.
-scale, -settleTime and -writeInterval make a reduced study for tests
(fewer particles: a fraction of Table 3's counts, or of a variant's own
particleScale, e.g. slab5mm's twice Table 3's; shorter settling).
"""

import argparse
import errno
import os
import re
import sys

from .. import PROJECT_DIR
from . import definition as study_definition
from . import archive as study_archive, cases as study_cases, results as study_results, \
    slurm as study_slurm
from .jobs import latest_complete_time, path_problem, running_in
from .locks import LockError
from .runner import Study, say
from .variants import first_line_comment, list_variants


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
    ap.add_argument("-export", metavar="ARCHIVE",
                    help="write the study's finished cases' summaries into ARCHIVE (.tar.gz)")
    ap.add_argument("-import", dest="importFrom", nargs="+", metavar="SOURCE",
                    help="add the finished cases of other study directories or archives")
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
    for name in ("results", "status", "export"):
        if getattr(args, name) and not os.path.isdir(args.studyDir):
            ap.error("-%s: no study directory %s" % (name, args.studyDir))
    if args.export or args.importFrom:
        study_archive.command(args, import_say(args.studyDir))
        if args.export and not args.importFrom:
            return
        args.results = True
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


# study.archive's line for a case of the import that is here already
KEPT_LINE = re.compile(r"^import: (\S+) is here already, with the same settings: kept$")


def import_say(study_dir):
    """say for -import: a case that the import finds here already and keeps
    is followed by which one the study uses when the local case has not
    finished (the finished one of the import is not taken)."""
    def say_import(line):
        say(line)
        m = KEPT_LINE.match(line)
        if not m:
            return
        case = os.path.join(study_dir, m.group(1))
        if study_archive.is_summary(case):
            return
        settings = study_cases.flat_dictionary(os.path.join(case, "constant", "caseSettings"))
        why = study_archive.unfinished(case, float(settings["endTime"])
                                       if "endTime" in settings else None)
        if why:
            say("import: %s: the local case is used, unfinished (%s); the finished case of "
                "the import is not taken: run the study to finish the local one, or remove "
                "%s and import again to use the finished one" % (m.group(1), why, case))
    return say_import


def command():
    """bin/dpmStudy: a file it cannot write, or a lock path that cannot be
    one, ends it with the path named."""
    try:
        main()
    except LockError as e:
        sys.exit("dpmStudy: %s" % e)
    except OSError as e:
        if e.filename is None:
            raise
        hint = ": the study must be on a writable file system" if e.errno == errno.EROFS else ""
        sys.exit("dpmStudy: %s: %s%s" % (e.filename, e.strerror, hint))
