# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Studies that travel between machines: a finished case kept as a small
summary case (its settings, its template's dictionaries, the tables that
results/ reads, the head of its log and the builds it ran with) that
results/ reads like the case itself, exported into an archive and imported
into another study directory (dpmStudy export, import).

A summary case is a directory of the study like a case, marked by
constant/archivedCase; the runner counts it as finished and never runs it.
An import refuses a study of another studyDict, and a case whose settings
or template dictionaries differ from the study's, naming the difference;
an archive is unpacked only as far as it holds summary cases, within size
bounds (study.unpack), and a symbolic link inside a case is refused, at an
export and an import alike (study.summary_case). Everything is checked
before anything is written; the summaries an import makes are renamed into
the study when all of them are whole."""

import datetime
import difflib
import os
import re
import shutil
import subprocess
import tarfile
import tempfile

from ..files import replacing, write_text
from . import cases as study_cases, definition as study_definition
from .jobs import latest_complete_time
from .summary_case import (ArchiveError, BUILD_RECORD, LOG, LOG_HEAD_END, MARKER, SETTINGS,
                           VARIANT, dictionary_files, open_own, parse_marker, read_own,
                           settings_problems, summary_files)
from .unpack import unpack
from ..project import project_dir_or_none


def build():
    """The commit of the project whose solver runs (DPMFOAM2D_PROJECT, with
    '+local changes' when its checkout has uncommitted ones), or 'unknown'
    without one or outside a git checkout."""
    project = project_dir_or_none()
    if project is None:
        return "unknown"

    def git(*args):
        return subprocess.run(["git", "-C", project] + list(args), capture_output=True,
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
    """The latest time of the run that a summary case records (None if
    its record has none)."""
    with open(os.path.join(case, MARKER), errors="replace") as f:
        return parse_marker(f.read())[0]


def dictionaries(case):
    """{relative path: text} of the case's dictionaries (constant/ and
    system/, not the study's records, the bed or the mesh)."""
    return {rel: read_own(case, rel) for rel in dictionary_files(case)}


def summarise(case, dest, source):
    """dest made as the summary case of the finished case (source: where it
    was run, for the record): the contents of the files summary_files
    names (never their modes), the log up to its head's end."""
    if is_summary(case):
        marker = read_own(case, MARKER)
    else:
        marker = ("# A finished case kept as its summary (dpmStudy export); the run's\n"
                  "# settings, dictionaries, tables and log head; never run again\n"
                  "time %.9g\nfrom %s\n" % (latest_complete_time(case), source))
    for d in ("constant", "system"):
        os.makedirs(os.path.join(dest, d), exist_ok=True)
    for rel in summary_files(case):
        if rel == MARKER:
            continue
        os.makedirs(os.path.join(dest, os.path.dirname(rel)), exist_ok=True)
        with open_own(case, rel) as f, replacing(os.path.join(dest, rel), binary=True) as out:
            if rel != LOG:
                shutil.copyfileobj(f, out)
                continue
            for line in f:
                out.write(line)
                if line.startswith(LOG_HEAD_END.encode()):
                    break
    write_text(os.path.join(dest, MARKER), marker)


def unfinished(case, end_time):
    """Why a case (a run or a summary of one) has not reached end_time
    (None: any time on disk will do), or None if it has."""
    if is_summary(case):
        t = summary_time(case)
        if t is None:
            return "%s records no time of its run" % MARKER
    else:
        t = latest_complete_time(case)
        if t is None:
            return "no time directory"
    if end_time is not None and t < end_time - 1e-9:
        return "it ends at %g s, before its endTime %g s" % (t, end_time)
    if not os.path.isfile(os.path.join(case, LOG)):
        return "no %s" % LOG
    return None


def finished(case, end_time):
    """Whether a case (a run or a summary of one) has reached end_time
    (None: any time on disk will do) and has its log."""
    return unfinished(case, end_time) is None


def finished_cases(study_dir, say):
    """The finished cases of a study directory (runs and summaries)."""
    out = []
    for c in study_cases.find_cases(study_dir):
        if finished(c["dir"], c["endTime"]):
            out.append(c)
        else:
            say("export: %s left out: not finished" % c["case"])
    return out


def export(study_dir, archive, say):
    """archive (.tar.gz) made of the study's definition and a summary case
    of each finished case (their bed statistics made first)."""
    if not archive.endswith((".tar.gz", ".tgz")):
        raise ArchiveError("export %s: the archive's name must end in .tar.gz" % archive)
    folder = os.path.dirname(archive) or "."
    if not os.path.isdir(folder):
        raise ArchiveError("export %s: no directory %s to write it into" % (archive, folder))
    definition = os.path.join(study_dir, study_definition.FILE_NAME)
    if not os.path.isfile(definition):
        raise ArchiveError("%s has no %s: not a study directory dpmStudy made"
                           % (study_dir, study_definition.FILE_NAME))
    cases = finished_cases(study_dir, say)
    for c in cases:             # a link refused before anything is written
        summary_files(c["dir"])
    name = os.path.basename(os.path.normpath(study_dir))
    with tempfile.TemporaryDirectory() as tmp:
        top = os.path.join(tmp, name)
        os.makedirs(top)
        write_text(os.path.join(top, study_definition.FILE_NAME),
                   read_own(study_dir, study_definition.FILE_NAME))
        for c in cases:
            if not is_summary(c["dir"]):
                study_cases.remake_bed_statistics(c["dir"])
            summarise(c["dir"], os.path.join(top, c["case"]), os.path.realpath(c["dir"]))
        # A new file of a fresh name beside the archive, renamed onto it
        # when whole: a link at either name is replaced, never written through
        with replacing(archive, binary=True) as f, \
                tarfile.open(fileobj=f, mode="w:gz") as tar:
            tar.add(top, arcname=name)
    say("export: %d finished cases of %s -> %s" % (len(cases), study_dir, archive))
    return len(cases)


# OpenFOAM's comments: the banner, the dividers, the notes beside entries
COMMENTS = re.compile(r"/\*.*?\*/|//[^\n]*", re.S)


def entry_lines(text):
    """The lines of an OpenFOAM file that hold entries (no comments, no
    blank lines)."""
    return [line.rstrip() for line in COMMENTS.sub("", text).splitlines() if line.strip()]


def first_difference(a, b, what_a, what_b):
    """The first differing line of two texts, in words: of their entries
    when those differ, else of the texts (a comment)."""
    for x, y in ((entry_lines(a), entry_lines(b)), (a.splitlines(), b.splitlines())):
        diff = list(difflib.unified_diff(x, y, what_a, what_b, n=0, lineterm=""))[2:]
        for line in diff:
            if line.startswith(("-", "+")):
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
    path = os.path.join(case, VARIANT)
    return open(path).read() if os.path.isfile(path) else ""


def import_study(study_dir, source, say):
    """Every finished case of source (a study directory or an archive made
    by export) into study_dir as summary cases; returns the number
    imported. Refuses (ArchiveError) another studyDict, a case whose
    settings or template dictionaries differ from the study's, and
    anything but summary cases in an archive."""
    with tempfile.TemporaryDirectory() as tmp:
        if os.path.isfile(source):
            other = unpack(source, os.path.join(tmp, "unpacked"))
            top = os.path.dirname(other)

            def name_of(path):          # the archive's member
                return "%s: %s" % (source, os.path.relpath(path, top))
        elif os.path.isdir(source):
            other, name_of = source, lambda path: path
        else:
            raise ArchiveError("import %s: no study directory or archive there" % source)
        return merge(study_dir, other, source, say, name_of, os.path.isfile(source))


def candidate_dirs(other):
    """The directories of a study that may be cases (as find_cases looks)."""
    return [os.path.join(other, n) for n in sorted(os.listdir(other))
            if n not in ("beds", "results") and not n.startswith(".")
            and os.path.isdir(os.path.join(other, n))]


def unreadable_cases(other, name_of, from_archive):
    """What makes the cases of the study other unfit to import, before
    their settings are read: links (summary_files), settings that are no
    numbers in range, a summary's record without its time; in an archive
    any directory that is no summary case."""
    problems = []
    for d in candidate_dirs(other):
        if not os.path.lexists(os.path.join(d, SETTINGS)):
            if from_archive:
                problems.append("%s: no %s: not a summary case" % (name_of(d), SETTINGS))
            continue
        try:
            summary_files(d)
            for rel in (SETTINGS, MARKER, VARIANT):     # read as text below
                if os.path.isfile(os.path.join(d, rel)):
                    with open_own(d, rel) as f:
                        f.read().decode()
        except ArchiveError as e:
            problems.append(str(e))
            continue
        except UnicodeDecodeError:
            problems.append("%s: not a text file (UTF-8)" % name_of(os.path.join(d, rel)))
            continue
        for why in settings_problems(study_cases.flat_dictionary(os.path.join(d, SETTINGS))):
            problems.append("%s: %s" % (name_of(os.path.join(d, SETTINGS)), why))
        if is_summary(d):
            _, why = parse_marker(read_own(d, MARKER))
            if why:
                problems.append("%s: %s" % (name_of(os.path.join(d, MARKER)), why))
        elif from_archive:
            problems.append("%s: no %s: not a summary case" % (name_of(d), MARKER))
    return problems


def in_the_way(path):
    """What at path (the name an imported case gets) is no case, in words."""
    if os.path.islink(path):
        return "a symbolic link (to %s)" % os.readlink(path)
    if os.path.isdir(path):
        return "a directory without %s" % SETTINGS
    return "a file"


def merge(study_dir, other, source, say, name_of, from_archive):
    """The finished cases of the study directory other (source: as the
    user named it; name_of: a path of other as the message names it) into
    study_dir; the number imported."""
    if not os.path.lexists(os.path.join(other, study_definition.FILE_NAME)):
        raise ArchiveError("%s has no %s: not a study of dpmStudy"
                           % (source, study_definition.FILE_NAME))
    their_text = read_own(other, study_definition.FILE_NAME)
    mine = os.path.join(study_dir, study_definition.FILE_NAME)
    if os.path.isfile(mine):
        my_text = open(mine).read()
        if my_text != their_text:
            raise ArchiveError("%s was made with another studyDict than %s: %s"
                               % (source, study_dir,
                                  first_difference(my_text, their_text, mine,
                                                   name_of(os.path.join(
                                                       other, study_definition.FILE_NAME)))))
    problems = unreadable_cases(other, name_of, from_archive)
    if problems:
        raise ArchiveError("cannot import from %s:\n  %s" % (source, "\n  ".join(problems)))
    here = {c["case"]: c for c in study_cases.find_cases(study_dir)} \
        if os.path.isdir(study_dir) else {}
    # Everything checked before anything is written
    new = []
    for c in study_cases.find_cases(other):
        name = c["case"]
        why = unfinished(c["dir"], c["endTime"])
        if why and (from_archive or is_summary(c["dir"])):
            problems.append("%s: a summary case of an unfinished run: %s"
                            % (name_of(c["dir"]), why))
            continue
        if why:
            say("import: %s left out: not finished (%s)" % (name, why))
            continue
        target = os.path.join(study_dir, name)
        if name not in here and os.path.lexists(target):
            problems.append("%s: %s is %s, no case of the study: remove or rename it to "
                            "import %s" % (name, target, in_the_way(target), name))
            continue
        mate = here.get(name) or next((h for h in here.values()
                                       if h["variant"] == c["variant"]), None)
        if mate is None:
            new.append(c)
            continue
        settings = settings_difference(
            os.path.join(mate["dir"], SETTINGS), os.path.join(c["dir"], SETTINGS),
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
    os.makedirs(study_dir, exist_ok=True)
    if not os.path.isfile(mine):
        write_text(mine, their_text)
    place(study_dir, new, source, from_archive, say)
    return len(new)


def place(study_dir, new, source, from_archive, say):
    """The summaries of the cases new made beside their names (dot names,
    which no study lists), then renamed onto them when all are whole;
    nothing of them is left behind if one fails."""
    mask = os.umask(0)
    os.umask(mask)
    made = []
    try:
        for c in new:
            d = tempfile.mkdtemp(dir=study_dir, prefix=".%s.importing" % c["case"])
            made.append(d)
            os.chmod(d, 0o777 & ~mask)      # a case's modes, not mkdtemp's private ones
            summarise(c["dir"], d, os.path.realpath(source) + ":" + c["case"]
                      if from_archive else os.path.realpath(c["dir"]))
        for i, c in enumerate(new):
            os.rename(made[i], os.path.join(study_dir, c["case"]))
            made[i] = None
            say("import: %s from %s" % (c["case"], source))
    finally:
        for d in made:
            if d is not None:
                shutil.rmtree(d, ignore_errors=True)
