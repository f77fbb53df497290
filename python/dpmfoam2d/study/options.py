# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""dpmStudy's command line: one subcommand per thing it does (run, submit,
status, results, export, import, variants), each taking only the options
that mean something to it; the options' values checked where they are
parsed, each refusal naming the option and its range."""

import argparse
import math
import os


def _number(name, high=math.inf, closed=False):
    """An argparse type: a number in (0, high), or (0, high] if closed; a
    refusal reads -<name> <value> is outside (0, high)."""
    def number(text):
        value = float(text)
        if not (0 < value < high or (closed and value == high)):
            raise argparse.ArgumentTypeError("-%s %g is outside (0, %s%s" % (
                name, value, "inf" if math.isinf(high) else "%g" % high, "]" if closed else ")"))
        return value
    return number


def _pressure(text):
    value = float(text)
    if not 0 < value < math.inf:
        raise argparse.ArgumentTypeError("-p %g: a pressure (bar) must be > 0" % value)
    return value


def _jobs(text):
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError("-j %d: cases at once must be >= 1" % value)
    return value


class _Parser(argparse.ArgumentParser):
    """Refusals of a value say only the value's message (argparse would
    prefix 'argument -x:', which repeats the option the message names)."""

    def error(self, message):
        message = message.split(": ", 1)[1] if message.startswith("argument -") \
            and ": -" in message else message
        super().error(message)


def _study_dir(required=False):
    p = _Parser(add_help=False)
    if required:
        p.add_argument("studyDir", help="the study directory")
    else:
        p.add_argument("studyDir", nargs="?", default="paperStudy",
                       help="the study directory (default ./paperStudy)")
    return p


def _template():
    p = _Parser(add_help=False)
    p.add_argument("-template", metavar="DIR",
                   help="the template case (default: the project's tutorials/paperStudy, "
                   "found through DPMFOAM2D_PROJECT)")
    return p


def _summing():
    """How results/ sums the cases up."""
    p = _Parser(add_help=False)
    p.add_argument("-mean", metavar="X", type=_number("mean"), default=10,
                   help="average the indices over the last X s (default 10)")
    p.add_argument("-rateWindow", type=float, nargs=2, metavar=("T0", "T1"),
                   help="window of M/M(0) for the segregation rate in findings.md "
                   "(default: the first -mean window)")
    p.add_argument("-noPictures", action="store_true", help="no snapshots")
    return p


def _matrix():
    """Which beds and cases, and their settings."""
    p = _Parser(add_help=False)
    p.add_argument("-w", type=float, nargs="+",
                   help="small-particle mass fractions (default: the studyDict's; "
                   "tutorials/paperStudy: 0.25 0.5 0.75)")
    p.add_argument("-p", type=_pressure, nargs="+",
                   help="pressures, bar (default: the studyDict's; tutorials/paperStudy: "
                   "1 8 16 32 64)")
    p.add_argument("-seeds", type=int, nargs="+", metavar="S",
                   help="random packings: N (seeds 1..N) or a list of seeds")
    p.add_argument("-variant", metavar="NAME|FILE",
                   help="a named set of dictionary edits (<template>/variants/NAME)")
    p.add_argument("-endTime", metavar="T", type=_number("endTime"),
                   help="end time of every case (s)")
    gas = p.add_mutually_exclusive_group()
    gas.add_argument("-U0byUmf", metavar="R", type=_number("U0byUmf"),
                     help="U0/Umf of every case (the paper's, and the template's: 1.25)")
    gas.add_argument("-excessVelocity", metavar="X", type=_number("excessVelocity"),
                     help="U0 - Umf (m/s) of every case instead of U0/Umf: the same "
                     "bubble flow at every pressure")
    p.add_argument("-scale", metavar="S", type=_number("scale", 1.0, closed=True),
                   help="fraction of Table 3's counts (tests)")
    p.add_argument("-settleTime", metavar="T", type=_number("settleTime"),
                   help="settling time (s) (tests)")
    p.add_argument("-writeInterval", metavar="T", type=_number("writeInterval"),
                   help="gas fields and restart states every T s")
    return p


def parser(doc):
    """(the parser, {command: its subparser}); doc: the usage text, whose
    first paragraph is the description and the rest the epilog."""
    head, rest = doc.split("\n\n", 1)
    ap = _Parser(prog="dpmStudy", description=head, epilog=rest,
                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", metavar="<command>", parser_class=_Parser)
    sub.required = True
    study, template, summing, matrix = _study_dir(), _template(), _summing(), _matrix()
    commands = {}

    def add(name, help_text, parents):
        commands[name] = sub.add_parser(name, help=help_text, description=help_text,
                                        parents=parents)
        return commands[name]

    run = add("run", "make and run the study's beds and cases here, then results/",
              [study, matrix, template, summing])
    run.add_argument("-j", metavar="N", type=_jobs, default=os.cpu_count() or 1,
                     help="cases at once (default: number of cores); with more than one, "
                     "their OpenMP threads wait passively (OMP_WAIT_POLICY=passive unless set)")
    run.add_argument("-interval", metavar="S", type=_number("interval"), default=30,
                     help="seconds between progress reports (default 30)")
    add("submit", "make the beds and cases, and submit them and results/ to Slurm; "
        "sbatch options after --", [study, matrix, template, summing])
    add("status", "state, job and simulated time (ETA if running) of every bed and case, "
        "and the simulated time left", [study])
    add("results", "remake results/ from what has run", [study, template, summing])
    export = add("export", "write the study's finished cases' summaries into an archive",
                 [_study_dir(required=True)])
    export.add_argument("archive", help="the archive to write (.tar.gz)")
    imports = add("import", "add the finished cases of other study directories or archives, "
                  "then remake results/", [_study_dir(required=True), template, summing])
    imports.add_argument("sources", nargs="+", metavar="SOURCE",
                         help="a study directory or an archive of dpmStudy export")
    add("variants", "list the template's variants", [template])
    return ap, commands
