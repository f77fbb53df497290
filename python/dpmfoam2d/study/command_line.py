# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""A study of a template: small-particle mass fractions x operating
pressures, each case made from the template (default the project's
tutorials/paperStudy, the paper's: Norouzi et al. 2012), run, and summed up;
over several random packings (seeds) and with named variants of the model.

  dpmStudy run [<studyDir>] [-w W ...] [-p P ...] [-seeds N | -seeds S1 S2 ...]
               [-variant NAME|FILE] [-endTime T] [-U0byUmf R | -excessVelocity X]
               [-scale S] [-settleTime T] [-writeInterval T] [-template DIR]
               [-mean X] [-rateWindow T0 T1] [-noPictures] [-j N] [-interval S]
  dpmStudy submit [<studyDir>] <run's options but -j, -interval> [-- <sbatch options>]
  dpmStudy status [<studyDir>]
  dpmStudy results [<studyDir>] [-mean X] [-rateWindow T0 T1] [-noPictures]
                   [-template DIR]
  dpmStudy export <studyDir> <archive.tar.gz>
  dpmStudy import <studyDir> <study dir or archive> ... [-mean X]
                  [-rateWindow T0 T1] [-noPictures] [-template DIR]
  dpmStudy variants [-template DIR]
  dpmStudy <command> -h         the options of one command

The template's studyDict defines the study: the default matrix (-w, -p),
the values allowed, and the findings that results/ tests (differences
between two cells of the matrix, with their expected signs); run copies it
into <studyDir>, whose copy results then follows (a template whose
studyDict differs later is refused for that study directory). Without
-template the template is tutorials/paperStudy of the project that
DPMFOAM2D_PROJECT names (set by the project's etc/bashrc).

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
<case>/constant/variant) and refuses a changed file later. dpmStudy
variants lists the template's variants. A variant that edits more than the
gas's numerics and closures (fvSchemes, fvSolution, gasProperties, the drag
model, its coefficients and the formulation), e.g. the particles, the
voidage model or the mesh, packs beds of its own with its edits
(beds/w0.50_<name>_seed1).

run runs N cases at once (-j, default: the number of cores). Run it again
after an interruption: finished cases are skipped, the others continue from
their last written time (controlDict startFrom latestTime); a time directory
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
solvers it started; run again to continue. The solver's programs
(blockMesh, dpmPackBed, dpmFoam2D) are taken from PATH.
results only remakes results/ from what has been run. results/ covers every
case of <studyDir>, whichever -w, -p, -seeds and -variant selected the cases
to run.
-U0byUmf R or -excessVelocity X sets how every case's U0 is chosen: the
paper's U0/Umf (template: 1.25), or U0 - Umf in m/s, the same bubble flow at
every pressure (use another <studyDir> for such a variant study).
status prints every bed and case with its state (not started, pending,
running, stopped, failed, done), its job (a local process or a Slurm task)
and its simulated time (a running case's with the solver's ETA), then the
simulated seconds left over all cases; a summary case (below) shows as
imported, at the time it records.
submit: on a Slurm cluster, prepares the beds and cases as run does, then
submits the beds as a job array, the cases as a second array that waits
for them (afterok) and a last job that makes results/ (afterany); one task
per bed or case, each running it as a local run would and continuing from
its latest complete time, in the environment of the project's etc/bashrc
(DPMFOAM2D_PROJECT); options after -- go to every sbatch (e.g. -- --partition=short
--time=4:00:00 --cpus-per-task=2; --cpus-per-task sets the DEM threads). A
task that reached its time limit continues when the study is submitted
again; beds and cases already pending or running are not submitted twice.
Logs: <case>/log.dpmFoam2D, <case>/log.slurm (task starts and ends),
<study>/slurm/<study>-cases_<job>_<task>.out.
export <studyDir> A.tar.gz writes an archive of the study: its studyDict
and a small summary case of each finished case (its settings, its
dictionaries, the tables results/ reads, the head of its log and the builds
it ran with, constant/studyBuild); import <studyDir> <other study dir or
archive> ... adds the finished cases found there to <studyDir> as summary
cases (marked by constant/archivedCase), which results/ reads like its own
and the runner counts as finished, never running them again. An import
refuses, naming the difference, a study of another studyDict and a case
whose settings (other than its w, pressure and seed) or dictionaries differ
from the study's cases; a case of the same name with the same settings is
kept as it is (if it has not finished here, the import says that this local
case is used). A summary case cannot be continued: a run with a longer
-endTime says so and leaves it at its time, and packs no bed that only
summaries would use. An archive is unpacked only if it holds nothing but
the studyDict and summary cases (no links, no other files) within 64 MiB a
file, 1024 MiB in all and 100000 members; its files get this process's
modes (umask), not the archive's. A symbolic link among the files a summary
takes from a case (constant/, system/, log.dpmFoam2D, the tables) is
refused, naming it, by export and import alike. import then remakes
results/ (a summary case has no snapshot); run the study as usual for the
cases still to run.
-rateWindow T0 T1: the window (T0, T1] of M/M(0) that findings.md compares
for the segregation rate (finding 4); default the first -mean window.
-scale, -settleTime and -writeInterval make a reduced study for tests
(fewer particles: a fraction of Table 3's counts, or of a variant's own
particleScale, e.g. slab5mm's twice Table 3's; shorter settling).
"""

import errno
import os
import re
import sys

from . import archive as study_archive, cases as study_cases, results as study_results, \
    slurm as study_slurm
from . import definition as study_definition
from .jobs import latest_complete_time, path_problem, running_in
from .locks import LockError
from .options import parser
from .runner import Study, say
from .variants import first_line_comment, list_variants
from ..project import ProjectError, project_path


def template_of(args):
    """-template, or the project's tutorials/paperStudy."""
    if args.template is not None:
        return args.template
    return project_path("dpmStudy's default template (tutorials/paperStudy; or give "
                        "-template DIR)", "tutorials", "paperStudy")


def checked_template(ap, args):
    """The template's real path, a directory whose path OpenFOAM takes."""
    template = template_of(args)
    if not os.path.isdir(template):
        ap.error("-template %s: no such directory" % template)
    problem = path_problem("the template", os.path.realpath(template))
    if problem:
        sys.exit("dpmStudy: " + problem)
    return os.path.realpath(template)


def checked_study_dir(ap, args, must_exist):
    problem = path_problem("the study directory", os.path.abspath(args.studyDir))
    if problem:
        sys.exit("dpmStudy: " + problem)
    if must_exist and not os.path.isdir(args.studyDir):
        ap.error("no study directory %s" % args.studyDir)


def recorded_definition(ap, args):
    """The study's copy of its studyDict, else the template's."""
    recorded = os.path.join(args.studyDir, study_definition.FILE_NAME)
    try:
        if os.path.isfile(recorded):
            return study_definition.Definition(recorded)
        return study_definition.of_template(checked_template(ap, args))
    except study_definition.DefinitionError as e:
        sys.exit("dpmStudy: %s" % e)


def make_results(ap, args):
    study_results.results(os.path.abspath(args.studyDir), args.mean, args.rateWindow,
                          not args.noPictures, recorded_definition(ap, args))


def check_matrix(ap, args):
    """The matrix's values against the template's studyDict; seeds listed."""
    args.template = checked_template(ap, args)
    try:
        args.definition = study_definition.of_template(args.template)
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


def run(ap, args, _):
    checked_study_dir(ap, args, must_exist=False)
    check_matrix(ap, args)
    study = Study(args)
    study.run()
    # results/ sums up every case of the study directory, not only those run now
    study_results.results(study.dir, args.mean, args.rateWindow, not args.noPictures,
                          study_results.definition_of(study.dir, study.template))


def submit(ap, args, sbatch_options):
    checked_study_dir(ap, args, must_exist=False)
    check_matrix(ap, args)
    results_args = ["-mean", repr(args.mean)] + \
        (["-noPictures"] if args.noPictures else []) + \
        (["-rateWindow"] + [repr(t) for t in args.rateWindow] if args.rateWindow else [])
    Study(args).submit(sbatch_options, results_args)


def status(ap, args, _):
    checked_study_dir(ap, args, must_exist=True)
    study_slurm.status(os.path.abspath(args.studyDir), running_in, latest_complete_time)


def results(ap, args, _):
    checked_study_dir(ap, args, must_exist=True)
    make_results(ap, args)


def export(ap, args, _):
    checked_study_dir(ap, args, must_exist=True)
    try:
        study_archive.export(args.studyDir, args.archive, say)
    except (study_archive.ArchiveError, OSError) as e:
        sys.exit("dpmStudy: %s" % e)


def import_cases(ap, args, _):
    checked_study_dir(ap, args, must_exist=False)
    try:
        for source in args.sources:
            study_archive.import_study(args.studyDir, source, import_say(args.studyDir))
    except (study_archive.ArchiveError, OSError) as e:
        sys.exit("dpmStudy: %s" % e)
    make_results(ap, args)


def variants(ap, args, _):
    template = checked_template(ap, args)
    for name in list_variants(template):
        say("%-14s %s" % (name, first_line_comment(os.path.join(template, "variants", name))))


COMMANDS = {"run": run, "submit": submit, "status": status, "results": results,
            "export": export, "import": import_cases, "variants": variants}


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    own, sbatch_options = (argv[:argv.index("--")], argv[argv.index("--") + 1:]) \
        if "--" in argv else (argv, [])
    ap, subparsers = parser(__doc__)
    args = ap.parse_args(own)
    sub = subparsers[args.command]
    if sbatch_options and args.command != "submit":
        sub.error("options after -- are for sbatch: dpmStudy submit")
    window = getattr(args, "rateWindow", None)
    if window and not 0 <= window[0] < window[1]:
        sub.error("-rateWindow %g %g: 0 <= T0 < T1 wanted" % tuple(window))
    COMMANDS[args.command](sub, args, sbatch_options)


# study.archive's line for a case of the import that is here already
KEPT_LINE = re.compile(r"^import: (\S+) is here already, with the same settings: kept$")


def import_say(study_dir):
    """say for import: a case that the import finds here already and keeps
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
    """The console script dpmStudy: a file it cannot write, a lock path that
    cannot be one, or a project it cannot find ends it with the path named."""
    try:
        main()
    except (LockError, ProjectError) as e:
        sys.exit("dpmStudy: %s" % e)
    except OSError as e:
        if e.filename is None:
            raise
        hint = ": the study must be on a writable file system" if e.errno == errno.EROFS else ""
        sys.exit("dpmStudy: %s: %s%s" % (e.filename, e.strerror, hint))
