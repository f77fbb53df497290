# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""What a summary case holds (dpmStudy export, import) and how those
files are read from a case: its records (constant/caseSettings, variant,
studyBuild, archivedCase), its dictionaries (the files of constant/ and
system/), the head of log.dpmFoam2D and the tables results/ reads
(postProcessing/<table>/<start time>/*.dat).

A file taken from a case must be the case's own: a symbolic link at any
step of its path is refused, naming it, and nothing is read where it
points (an export or import would carry that file along); the files are
opened component by component without following links."""

import errno
import math
import os
import stat

from ..fields import TIME_NAME

MARKER = os.path.join("constant", "archivedCase")
BUILD_RECORD = os.path.join("constant", "studyBuild")
SETTINGS = os.path.join("constant", "caseSettings")
LOG = "log.dpmFoam2D"
LOG_HEAD_END = "Starting time loop"

VARIANT = os.path.join("constant", "variant")
KEPT_FILES = (SETTINGS, VARIANT, BUILD_RECORD)
KEPT_TABLES = ("laceyIndex", "laceyIndexPerSample", "bedStatistics")
DICTIONARY_DIRS = ("constant", "system")
# Files of constant/ that are records or the bed, not the run's dictionaries
NOT_COMPARED = {"caseSettings", "variant", "studyBuild", "archivedCase", "packedBed",
                "packedBed.state"}
TABLE_SUFFIX = ".dat"


class ArchiveError(Exception):
    """An archive or study that cannot be exported or imported, the reason
    in words."""


def link_refusal(path):
    return ArchiveError("%s is a symbolic link; the files export and import take from a "
                        "case must be its own: put the file itself there (nothing was read "
                        "where the link points)" % path)


def _open_step(parent_fd, name, path, last):
    """name in the directory parent_fd opened without following a link:
    a directory, or (last) a regular file."""
    try:
        st = os.stat(name, dir_fd=parent_fd, follow_symlinks=False)
    except FileNotFoundError:
        raise ArchiveError("%s: no such file" % path)
    if stat.S_ISLNK(st.st_mode):
        raise link_refusal(path)
    if not last and not stat.S_ISDIR(st.st_mode):
        raise ArchiveError("%s is not a directory" % path)
    if last and not stat.S_ISREG(st.st_mode):
        raise ArchiveError("%s is not a regular file (a directory, a FIFO or a device); "
                           "a case's records, dictionaries and tables are files" % path)
    flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_CLOEXEC | \
        (os.O_NONBLOCK if last else os.O_DIRECTORY)
    try:
        return os.open(name, flags, dir_fd=parent_fd)
    except OSError as e:
        if e.errno in (errno.ELOOP, errno.ENOTDIR):     # swapped for a link since
            raise link_refusal(path)
        raise


def open_own(case, rel):
    """A binary file object of the regular file case/rel, no step of rel a
    symbolic link (ArchiveError naming it)."""
    fd = os.open(case, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
    parts = rel.split(os.sep)
    try:
        for i, part in enumerate(parts):
            path = os.path.join(case, *parts[:i + 1])
            step = _open_step(fd, part, path, i == len(parts) - 1)
            os.close(fd)
            fd = step
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise ArchiveError("%s is not a regular file" % os.path.join(case, rel))
        return os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise


def read_own(case, rel):
    """The text of case/rel (see open_own)."""
    with open_own(case, rel) as f:
        return f.read().decode(errors="replace")


def is_link(case, rel):
    return os.path.islink(os.path.join(case, rel))


def own_directory_entries(case, rel):
    """The names in the directory case/rel ([] if there is none); a link
    there, or at a step of its path, is refused."""
    parts = rel.split(os.sep)
    for i in range(len(parts)):
        step = os.path.join(case, *parts[:i + 1])
        if os.path.islink(step):
            raise link_refusal(step)
        if not os.path.isdir(step):
            return []
    return sorted(os.listdir(os.path.join(case, rel)))


def dictionary_files(case):
    """The relative paths of the case's dictionaries: the files of
    constant/ and system/ but its records and its bed. A link where a file
    is taken is refused; a link to a directory (a shared polyMesh) is left
    like any directory."""
    out = []
    for d in DICTIONARY_DIRS:
        for name in own_directory_entries(case, d):
            path = os.path.join(case, d, name)
            if name in NOT_COMPARED or name.startswith(".") or os.path.isdir(path):
                continue
            if os.path.islink(path):
                raise link_refusal(path)
            if os.path.isfile(path):
                out.append(os.path.join(d, name))
    return out


def table_files(case):
    """The relative paths of the tables a summary keeps:
    postProcessing/<table>/<start time>/*.dat of KEPT_TABLES."""
    out = []
    for table in KEPT_TABLES:
        top = os.path.join("postProcessing", table)
        if not os.path.lexists(os.path.join(case, top)):
            continue
        for start in own_directory_entries(case, top):
            if not TIME_NAME.match(start):
                continue
            where = os.path.join(top, start)
            if is_link(case, where):
                raise link_refusal(os.path.join(case, where))
            for name in own_directory_entries(case, where):
                rel = os.path.join(where, name)
                if not name.endswith(TABLE_SUFFIX):
                    continue
                if is_link(case, rel):
                    raise link_refusal(os.path.join(case, rel))
                if os.path.isfile(os.path.join(case, rel)):
                    out.append(rel)
    return out


def summary_files(case):
    """The relative paths of everything a summary of case takes from it
    (the log's head among them), links refused (ArchiveError): called
    before anything is written, and by the summary itself."""
    files = dictionary_files(case)          # a linked constant/ refused here
    for rel in KEPT_FILES + (LOG, MARKER):
        if os.path.lexists(os.path.join(case, rel)):
            if is_link(case, rel):
                raise link_refusal(os.path.join(case, rel))
            files.append(rel)
    return files + table_files(case)


def parse_marker(text):
    """(time, problem) of an archivedCase's text: the latest time of the
    run it records, or None and why not."""
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["time"]:
            value = words[1] if len(words) > 1 else ""
            try:
                t = float(value)
            except ValueError:
                return None, "time '%s' is not a number" % value
            if not math.isfinite(t) or t < 0:
                return None, "time %s is not a time (a finite number >= 0 wanted)" % value
            return t, None
    return None, "no 'time <latest time of the run>' line"


# caseSettings entries that find the case its place in the study, with
# their allowed ranges
SETTINGS_RANGES = {"wSmall": (lambda v: 0 <= v <= 1, "a mass fraction in [0, 1]"),
                   "pressure": (lambda v: v > 0, "a pressure in bar, > 0"),
                   "endTime": (lambda v: v > 0, "a time in s, > 0"),
                   "seed": (lambda v: v >= 1 and v == int(v), "an integer >= 1")}


def settings_problems(entries):
    """Why the entries of a caseSettings (name -> text) cannot place its
    case in a study, one reason an entry ([] if they can)."""
    out = []
    for name in ("wSmall", "pressure"):
        if name not in entries:
            out.append("no %s entry" % name)
    for name, (allowed, what) in SETTINGS_RANGES.items():
        if name not in entries:
            continue
        try:
            value = float(entries[name])
        except ValueError:
            out.append("%s '%s' is not a number (%s wanted)" % (name, entries[name], what))
            continue
        if not math.isfinite(value) or not allowed(value):
            out.append("%s %s is outside the allowed range (%s wanted)"
                       % (name, entries[name], what))
    return out
