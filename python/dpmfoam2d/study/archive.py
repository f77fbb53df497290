# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Studies that travel between machines: a finished case kept as a small
summary case (its settings, its template's dictionaries, the tables that
results/ reads, the head of its log and the builds it ran with) that
-results reads like the case itself, exported into an archive and imported
into another study directory (dpmStudy -export, -import).

A summary case is a directory of the study like a case, marked by
constant/archivedCase; the runner counts it as finished and never runs it.
An import refuses a study of another studyDict, and a case whose settings
or template dictionaries differ from the study's, naming the difference."""

import datetime
import difflib
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile

from .. import PROJECT_DIR
from ..files import write_text
from . import cases as study_cases, definition as study_definition
from .jobs import latest_complete_time

MARKER = os.path.join("constant", "archivedCase")
BUILD_RECORD = os.path.join("constant", "studyBuild")

# What a summary case keeps: the study's records, the tables results/
# reads (M, the indices, the bed statistics), and the dictionaries the case
# ran with (compared at an import)
KEPT_FILES = (os.path.join("constant", "caseSettings"), os.path.join("constant", "variant"),
              BUILD_RECORD)
KEPT_TABLES = ("laceyIndex", "laceyIndexPerSample", "bedStatistics")
DICTIONARY_DIRS = ("constant", "system")
NOT_COMPARED = {"caseSettings", "variant", "studyBuild", "archivedCase", "packedBed",
                "packedBed.state"}
LOG_HEAD_END = "Starting time loop"


class ArchiveError(Exception):
    """An archive or study that cannot be imported, the reason in words."""


def build():
    """The project's commit (with '+local changes' when the checkout has
    uncommitted ones), or 'unknown' outside a git checkout."""
    def git(*args):
        return subprocess.run(["git", "-C", PROJECT_DIR] + list(args), capture_output=True,
                              text=True).stdout.strip()
    try:
        commit = git("rev-parse", "--short=12", "HEAD")
        dirty = git("status", "--porcelain", "--untracked-files=no")
    except OSError:
        return "unknown"
    return (commit + (" +local changes" if dirty else "")) if commit else "unknown"


def record_build(case):
    """A line of the build that a run of case starts with (UTC time, commit)."""
    path = os.path.join(case, BUILD_RECORD)
    before = open(path).read() if os.path.isfile(path) else ""
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M:%S UTC")
    write_text(path, before + "%s %s\n" % (stamp, build()))


def is_summary(case):
    return os.path.isfile(os.path.join(case, MARKER))


def summary_time(case):
    """The latest time of the run that a summary case records."""
    with open(os.path.join(case, MARKER)) as f:
        for line in f:
            if line.startswith("time "):
                return float(line.split()[1])
    return None


def dictionaries(case):
    """{relative path: text} of the case's dictionaries (constant/ and
    system/, not the study's records, the bed or the mesh)."""
    out = {}
    for d in DICTIONARY_DIRS:
        top = os.path.join(case, d)
        if not os.path.isdir(top):
            continue
        for name in sorted(os.listdir(top)):
            path = os.path.join(top, name)
            if name not in NOT_COMPARED and os.path.isfile(path) and not name.startswith("."):
                with open(path, errors="replace") as f:
                    out[os.path.join(d, name)] = f.read()
    return out


def summarise(case, dest, source):
    """dest made as the summary case of the finished case (source: where it
    was run, for the record)."""
    t = latest_complete_time(case) if not is_summary(case) else summary_time(case)
    os.makedirs(os.path.join(dest, "constant"))
    os.makedirs(os.path.join(dest, "system"))
    for rel, text in dictionaries(case).items():
        write_text(os.path.join(dest, rel), text)
    for rel in KEPT_FILES:
        if os.path.isfile(os.path.join(case, rel)):
            shutil.copy2(os.path.join(case, rel), os.path.join(dest, rel))
    for table in KEPT_TABLES:
        src = os.path.join(case, "postProcessing", table)
        if os.path.isdir(src):
            shutil.copytree(src, os.path.join(dest, "postProcessing", table))
    log = os.path.join(case, "log.dpmFoam2D")
    if os.path.isfile(log):
        with open(log, errors="replace") as f, open(os.path.join(dest, "log.dpmFoam2D"), "w") as out:
            for line in f:
                out.write(line)
                if line.startswith(LOG_HEAD_END):
                    break
    if is_summary(case):
        shutil.copy2(os.path.join(case, MARKER), os.path.join(dest, MARKER))
    else:
        write_text(os.path.join(dest, MARKER),
                   "# A finished case kept as its summary (dpmStudy -export); the run's\n"
                   "# settings, dictionaries, tables and log head; never run again\n"
                   "time %.9g\nfrom %s\n" % (t, source))


def finished(case, end_time):
    """Whether a case (a run or a summary of one) has reached end_time
    (None: any time on disk will do)."""
    t = summary_time(case) if is_summary(case) else latest_complete_time(case)
    return t is not None and (end_time is None or t >= end_time - 1e-9) and \
        os.path.isfile(os.path.join(case, "log.dpmFoam2D"))


def finished_cases(study_dir, say):
    """The finished cases of a study directory (runs and summaries)."""
    out = []
    for c in study_cases.find_cases(study_dir):
        if finished(c["dir"], c["endTime"]):
            out.append(c)
        else:
            say("export: %s left out: not finished" % c["case"])
    return out


def export(study_dir, archive, X, say):
    """archive (.tar.gz) made of the study's definition and a summary case
    of each finished case (their bed statistics made first)."""
    if not archive.endswith((".tar.gz", ".tgz")):
        raise ArchiveError("-export %s: the archive's name must end in .tar.gz" % archive)
    definition = os.path.join(study_dir, study_definition.FILE_NAME)
    if not os.path.isfile(definition):
        raise ArchiveError("%s has no %s: not a study directory dpmStudy made"
                           % (study_dir, study_definition.FILE_NAME))
    cases = finished_cases(study_dir, say)
    name = os.path.basename(os.path.normpath(study_dir))
    with tempfile.TemporaryDirectory() as tmp:
        top = os.path.join(tmp, name)
        os.makedirs(top)
        shutil.copy2(definition, top)
        for c in cases:
            if not is_summary(c["dir"]):
                study_cases.bed_statistics(c["dir"], X)
            summarise(c["dir"], os.path.join(top, c["case"]), os.path.realpath(c["dir"]))
        partial = archive + ".partial"
        with tarfile.open(partial, "w:gz") as tar:
            tar.add(top, arcname=name)
        os.replace(partial, archive)
    say("export: %d finished cases of %s -> %s" % (len(cases), study_dir, archive))
    return len(cases)


def first_difference(a, b, what_a, what_b):
    """The first differing line of two texts, in words."""
    for line in difflib.unified_diff(a.splitlines(), b.splitlines(), what_a, what_b, n=0,
                                     lineterm=""):
        if line.startswith(("-", "+")) and not line.startswith(("---", "+++")):
            return line
    return "(they differ in white space only)"


def settings_difference(mine, theirs, ignore=()):
    """Entries of two caseSettings that differ: 'name here -> there'."""
    a, b = study_cases.flat_dictionary(mine), study_cases.flat_dictionary(theirs)
    return ["%s %s here, %s there" % (k, a.get(k, "(none)"), b.get(k, "(none)"))
            for k in sorted(set(a) | set(b)) if k not in ignore and a.get(k) != b.get(k)]


def template_difference(case, other):
    """The dictionaries of two cases that differ, with their first
    differing line."""
    a, b = dictionaries(case), dictionaries(other)
    out = []
    for rel in sorted(set(a) | set(b)):
        if a.get(rel) != b.get(rel):
            out.append("%s: %s" % (rel, first_difference(a.get(rel, ""), b.get(rel, ""),
                                                          case, other)
                                   if rel in a and rel in b else "only in one of them"))
    return out


def variant_text(case):
    path = os.path.join(case, "constant", "variant")
    return open(path).read() if os.path.isfile(path) else ""


def import_study(study_dir, source, say):
    """Every finished case of source (a study directory or an archive made
    by -export) into study_dir as summary cases; returns the number
    imported. Refuses (ArchiveError) another studyDict, and a case whose
    settings or template dictionaries differ from the study's."""
    with tempfile.TemporaryDirectory() as tmp:
        if os.path.isfile(source):
            other = unpack(source, tmp)
        elif os.path.isdir(source):
            other = source
        else:
            raise ArchiveError("-import %s: no study directory or archive there" % source)
        return merge(study_dir, other, source, tmp, say)


def unpack(archive, tmp):
    try:
        with tarfile.open(archive, "r:*") as tar:
            members = tar.getmembers()
            for m in members:
                if os.path.isabs(m.name) or ".." in m.name.split("/") or \
                        not (m.isfile() or m.isdir()):
                    raise ArchiveError("%s: %s is not a file of a study archive (absolute, "
                                       "outside it, or a link)" % (archive, m.name))
            tar.extractall(os.path.join(tmp, "unpacked"), members)
    except (tarfile.TarError, OSError, EOFError) as e:
        raise ArchiveError("%s: not a study archive (%s)" % (archive, e))
    tops = os.listdir(os.path.join(tmp, "unpacked"))
    if len(tops) != 1:
        raise ArchiveError("%s: not a study archive of dpmStudy -export (%d top "
                           "directories)" % (archive, len(tops)))
    return os.path.join(tmp, "unpacked", tops[0])


def merge(study_dir, other, source, tmp, say):
    theirs = os.path.join(other, study_definition.FILE_NAME)
    if not os.path.isfile(theirs):
        raise ArchiveError("%s has no %s: not a study of dpmStudy" % (source, study_definition.FILE_NAME))
    os.makedirs(study_dir, exist_ok=True)
    mine = os.path.join(study_dir, study_definition.FILE_NAME)
    their_text = open(theirs).read()
    if os.path.isfile(mine):
        my_text = open(mine).read()
        if my_text != their_text:
            raise ArchiveError("%s was made with another studyDict than %s: %s"
                               % (source, study_dir,
                                  first_difference(my_text, their_text, mine, theirs)))
    here = {c["case"]: c for c in study_cases.find_cases(study_dir)}
    incoming = finished_cases(other, lambda *a: None)
    # Everything checked before anything is written
    problems, new = [], []
    for c in incoming:
        name = c["case"]
        mate = here.get(name) or next((h for h in here.values()
                                       if h["variant"] == c["variant"]), None)
        if mate is None:
            new.append(c)
            continue
        settings = settings_difference(
            os.path.join(mate["dir"], "constant", "caseSettings"),
            os.path.join(c["dir"], "constant", "caseSettings"),
            ignore=() if name in here else ("wSmall", "pressure", "seed"))
        if settings:
            problems.append("%s: its settings differ from %s's: %s"
                            % (name, mate["case"], "; ".join(settings)))
        elif variant_text(mate["dir"]) != variant_text(c["dir"]):
            problems.append("%s: made with other variant edits than %s (constant/variant)"
                            % (name, mate["case"]))
        else:
            template = template_difference(mate["dir"], c["dir"])
            if template:
                problems.append("%s: its dictionaries differ from %s's: %s"
                                % (name, mate["case"], "; ".join(template)))
            elif name in here:
                say("import: %s is here already, with the same settings: kept" % name)
            else:
                new.append(c)
    if problems:
        raise ArchiveError("cannot import from %s:\n  %s" % (source, "\n  ".join(problems)))
    if not os.path.isfile(mine):
        write_text(mine, their_text)
    for c in new:
        made = os.path.join(study_dir, ".%s.importing%d" % (c["case"], os.getpid()))
        summarise(c["dir"], made, os.path.realpath(source) if not os.path.isfile(source)
                  else os.path.realpath(source) + ":" + c["case"])
        os.rename(made, os.path.join(study_dir, c["case"]))
        say("import: %s from %s" % (c["case"], source))
    return len(new)


def command(args, say):
    """-export and -import of the command line; exits with the reason on
    an archive or study that cannot be read or merged."""
    try:
        if args.export:
            export(args.studyDir, args.export, args.mean, say)
        for source in args.importFrom or []:
            import_study(args.studyDir, source, say)
    except (ArchiveError, OSError) as e:
        sys.exit("dpmStudy: %s" % e)
