# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Unpacking a study archive of dpmStudy export for import, so that it
cannot put more than a study's summary cases into the machine: every member
is checked before anything is written, and the whole archive is refused,
naming the member, when one is

  - no part of a summary study: <study>/studyDict and, per case,
    constant/ and system/ files, log.dpmFoam2D and
    postProcessing/<laceyIndex|laceyIndexPerSample|bedStatistics>/<start
    time>/*.dat (an absolute path, '..', a hidden name: refused too);
  - a link, a device or a FIFO (only files and directories are unpacked);
  - larger than MAX_FILE_BYTES, or takes the archive past MAX_TOTAL_BYTES
    or MAX_MEMBERS (the sizes the members declare, counted again while
    their contents are read).

Files are written with this process's own modes (umask applied, never the
archive's: no setuid, setgid or world-writable file comes out of one)."""

import gzip
import lzma
import os
import tarfile
import zlib

from ..fields import TIME_NAME
from .summary_case import (ArchiveError, DICTIONARY_DIRS, KEPT_TABLES, LOG, TABLE_SUFFIX)
from . import definition as study_definition

MAX_FILE_BYTES = 64 << 20       # a table of a 600 s run is a few MB
MAX_TOTAL_BYTES = 1 << 30       # a study of a few hundred cases
MAX_MEMBERS = 100000
LIMITS = "at most %d MiB a file, %d MiB in all and %d members" % (
    MAX_FILE_BYTES >> 20, MAX_TOTAL_BYTES >> 20, MAX_MEMBERS)
LAYOUT = ("<study>/%s and summary cases: <case>/constant/*, <case>/system/*, <case>/%s, "
          "<case>/postProcessing/{%s}/<start time>/*%s"
          % (study_definition.FILE_NAME, LOG, ",".join(KEPT_TABLES), TABLE_SUFFIX))
CHUNK = 1 << 20


def case_kind(parts):
    """'dir' or 'file' if parts (a path inside a summary case) is a
    directory or file a summary case holds, else None."""
    n = len(parts)
    if n == 1 and parts[0] in DICTIONARY_DIRS + ("postProcessing",):
        return "dir"
    if n == 1 and parts[0] == LOG:
        return "file"
    if n == 2 and parts[0] in DICTIONARY_DIRS:
        return "file"
    if n >= 2 and parts[0] == "postProcessing" and parts[1] in KEPT_TABLES:
        if n == 2 or (n == 3 and TIME_NAME.match(parts[2])):
            return "dir"
        if n == 4 and TIME_NAME.match(parts[2]) and parts[3].endswith(TABLE_SUFFIX):
            return "file"
    return None


def member_parts(name):
    """The components of a member's name ('./' in front dropped: [] for
    the archive's './' itself), or None if it is absolute or has an empty,
    '..' or hidden component."""
    if name.startswith("/"):
        return None
    parts = name.rstrip("/").split("/")
    while parts and parts[0] == ".":
        parts.pop(0)
    if any(p in ("", ".", "..") or p.startswith(".") for p in parts):
        return None
    return parts


def study_kind(parts):
    """'dir' or 'file' if parts (a member's name) belongs in a study
    archive, else None."""
    if len(parts) == 1:
        return "dir"
    if parts[1] in ("beds", "results"):         # a study's, never a case's names
        return None
    if len(parts) == 2:
        return "file" if parts[1] == study_definition.FILE_NAME else "dir"
    return case_kind(parts[2:])


def check_member(archive, m, parts):
    """ArchiveError if m may not be unpacked."""
    def refuse(why):
        raise ArchiveError("%s: member %s %s; nothing was imported" % (archive, m.name, why))
    if m.issym() or m.islnk():
        refuse("is a link (to %s); a study archive holds no links" % m.linkname)
    if not (m.isfile() or m.isdir()):
        refuse("is neither a file nor a directory (a device or a FIFO)")
    kind = study_kind(parts) if parts else None
    if kind is None:
        refuse("is no part of a study archive of dpmStudy export, which holds " + LAYOUT)
    if kind != ("dir" if m.isdir() else "file"):
        refuse("is a %s where a study archive has a %s" % (
            "directory" if m.isdir() else "file", "directory" if kind == "dir" else "file"))
    if m.size > MAX_FILE_BYTES:
        refuse("is %d bytes; a study archive unpacks %s" % (m.size, LIMITS))


def checked_members(archive, tar):
    """The members of tar, each checked, the sizes and count summed as
    they are read (a huge archive stops at its first member too many)."""
    members, seen, total, tops = [], set(), 0, set()
    while True:
        m = tar.next()
        if m is None:
            break
        parts = member_parts(m.name)
        if parts == [] and m.isdir():       # './' of tar -C <dir> .
            continue
        check_member(archive, m, parts)
        key = "/".join(parts)
        if key in seen and not m.isdir():
            raise ArchiveError("%s: member %s is in it twice; nothing was imported"
                               % (archive, m.name))
        seen.add(key)
        tops.add(parts[0])
        total += m.size
        if total > MAX_TOTAL_BYTES or len(members) >= MAX_MEMBERS:
            raise ArchiveError("%s: too large at member %s; a study archive unpacks %s; "
                               "nothing was imported" % (archive, m.name, LIMITS))
        members.append((m, parts))
    if len(tops) != 1:
        raise ArchiveError("%s: not a study archive of dpmStudy export (%d top "
                           "directories, one wanted)" % (archive, len(tops)))
    return members


def write_member(archive, tar, m, path, budget):
    """m's content into the new file path (the process's modes), counted
    against the member's declared size and budget (bytes left of the
    archive's total); returns the bytes written."""
    source = tar.extractfile(m)
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC,
                 0o666)
    written = 0
    with os.fdopen(fd, "wb") as out:
        while True:
            chunk = source.read(CHUNK)
            if not chunk:
                break
            written += len(chunk)
            if written > m.size or written > MAX_FILE_BYTES or written > budget:
                raise ArchiveError("%s: member %s holds more than it declares or than a "
                                   "study archive may unpack (%s); nothing was imported"
                                   % (archive, m.name, LIMITS))
            out.write(chunk)
    return written


def unpack(archive, into):
    """The study directory of archive unpacked under into (made here,
    inside a private directory); ArchiveError naming a member that may not be unpacked, or
    an archive that cannot be read."""
    try:
        tar = tarfile.open(archive, "r:*")
    except tarfile.ReadError:
        raise ArchiveError("%s: not a study archive of dpmStudy export (no tar archive, "
                           "compressed or not)" % archive)
    try:
        with tar:
            members = checked_members(archive, tar)
            os.makedirs(into)
            budget = MAX_TOTAL_BYTES
            for m, parts in members:
                path = os.path.join(into, *parts)
                if m.isdir():
                    os.makedirs(path, exist_ok=True)
                    continue
                os.makedirs(os.path.dirname(path), exist_ok=True)
                budget -= write_member(archive, tar, m, path, budget)
    except (tarfile.TarError, EOFError, zlib.error, gzip.BadGzipFile, lzma.LZMAError) as e:
        raise ArchiveError("%s: not a study archive of dpmStudy export (%s)" % (archive, e))
    return os.path.join(into, members[0][1][0])
