# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The locks of dpmStudy: a case's or bed's (src/dpmCoupling/caseLock:
flock on <dir>/.dpmLock, its first line naming the holder), results/'s and
the study's own. A lock path is a regular file or nothing: a symbolic link,
a directory or a device there is refused, naming it, and the holder line
is written only into the file that is locked (never where a link points)."""

import errno
import fcntl
import os
import re
import stat
import time

LOCK_FILE = ".dpmLock"
LOCK_PID = re.compile(r"\(pid (\d+) ")


class LockError(Exception):
    """A lock path that cannot serve as a lock (the path and why in the message)."""


def _why(path, e):
    if e.errno == errno.ELOOP:
        return ("%s is a symbolic link; a lock must be a regular file: remove the link "
                "(nothing was written where it points)" % path)
    if e.errno == errno.EISDIR:
        return "%s is a directory; a lock must be a regular file: remove it" % path
    if e.errno == errno.EROFS:
        return ("%s: the directory is on a read-only file system; a case or study "
                "must be writable to run" % path)
    return "%s: %s; a lock must be a regular file this user may write" % (path, e.strerror)


def open_lock(path, create=True):
    """A descriptor of the regular file path (made if missing and create),
    or None if it is missing and not create. Refuses (LockError) anything
    else at path, a symbolic link included; a FIFO does not block the open."""
    flags = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC
    try:
        fd = os.open(path, flags | (os.O_CREAT if create else 0), 0o644)
    except OSError as e:
        if e.errno == errno.ENOENT and not create:
            return None
        raise LockError(_why(path, e))
    if not stat.S_ISREG(os.fstat(fd).st_mode):
        os.close(fd)
        raise LockError("%s is not a regular file; a lock must be one: remove it" % path)
    # the descriptor is handed down to the solver: as a plain open would be
    fcntl.fcntl(fd, fcntl.F_SETFL, fcntl.fcntl(fd, fcntl.F_GETFL) & ~os.O_NONBLOCK)
    return fd


def write_holder(path, fd, line):
    """line as the content of the locked file fd at path, through a
    descriptor checked to be that same file."""
    try:
        w = os.open(path, os.O_WRONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError as e:
        raise LockError(_why(path, e))
    try:
        a, b = os.fstat(fd), os.fstat(w)
        if (a.st_dev, a.st_ino) != (b.st_dev, b.st_ino):
            raise LockError("%s was replaced by another file while it was being locked: "
                            "run again" % path)
        os.ftruncate(w, 0)
        os.pwrite(w, line.encode(), 0)
    except OSError as e:
        raise LockError(_why(path, e))
    finally:
        os.close(w)


def flock_holders(path):
    """The live processes this host's /proc/locks lists as holding a flock
    on path (the process that took it; [] on another host's or none)."""
    try:
        st = os.stat(path)
        with open("/proc/locks") as f:
            lines = f.read().splitlines()
    except OSError:
        return []
    where = "%02x:%02x:%d" % (os.major(st.st_dev), os.minor(st.st_dev), st.st_ino)
    pids = []
    for line in lines:
        # "1: FLOCK  ADVISORY  READ 1234 fe:00:5678 0 EOF"; a waiter's has "->"
        w = line.split()
        if len(w) >= 6 and w[1] == "FLOCK" and w[5] == where and w[4].isdigit() \
                and os.path.isdir("/proc/" + w[4]):
            pids.append(int(w[4]))
    return sorted(set(pids))


def lock_holder(directory):
    """The holder's line of directory's lock if another process holds it,
    else None. Looks without taking it (a shared lock for an instant); a
    lock path that is no regular file holds nothing (take_lock refuses it)."""
    try:
        fd = open_lock(os.path.join(directory, LOCK_FILE), create=False)
    except LockError:
        return None
    if fd is None:
        return None
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
        except BlockingIOError:
            line = os.pread(fd, 512, 0).decode(errors="replace").split("\n")[0]
            return line or "a process starting up"
        fcntl.flock(fd, fcntl.LOCK_UN)
        return None
    finally:
        os.close(fd)


def take_lock(directory):
    """directory's lock for this process (a descriptor), or None when
    another process holds it; LockError when its path cannot be a lock. A
    child given the descriptor (DPMFOAM2D_LOCK_FD) holds it on after this
    process closes its copy."""
    path = os.path.join(directory, LOCK_FILE)
    # read-only: the descriptor handed down to the solver is never written
    fd = open_lock(path)
    for attempt in range(10):       # a look by lock_holder holds it an instant
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            break
        except BlockingIOError:
            time.sleep(0.02)
    else:
        os.close(fd)
        return None
    line = "dpmStudy (pid %d on %s, started %s)\n" % (
        os.getpid(), os.uname().nodename, time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime()))
    try:
        write_holder(path, fd, line)
    except LockError:
        os.close(fd)
        raise
    return fd
