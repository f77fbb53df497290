# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writing the files of fixed names that the tools keep in a case or study
directory (tables, reports, records) so that a symbolic link or another
non-regular file found at the name is never written through: the text goes
to a new file beside the name and is renamed onto it (the rename replaces a
link, it does not follow it), or a new file is made where none may exist.
"""

import contextlib
import os
import tempfile


def _mode():
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


@contextlib.contextmanager
def replacing(path, newline=None, binary=False):
    """A text (or binary) file to write path's new content to: renamed onto
    path when the block ends without an error, removed otherwise. A
    directory at path is refused (IsADirectoryError naming it)."""
    if os.path.isdir(path) and not os.path.islink(path):
        raise IsADirectoryError(21, "Is a directory", path)
    directory = os.path.dirname(path) or "."
    fd, tmp = tempfile.mkstemp(dir=directory, prefix="." + os.path.basename(path) + ".")
    try:
        with (os.fdopen(fd, "wb") if binary else os.fdopen(fd, "w", newline=newline)) as f:
            yield f
        os.chmod(tmp, _mode())
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def write_text(path, text):
    """path's content replaced by text (see replacing)."""
    with replacing(path) as f:
        f.write(text)


def save_figure(fig, path, **options):
    """A matplotlib figure saved to path (see replacing), its format from
    path's extension."""
    with replacing(path, binary=True) as f:
        fig.savefig(f, format=os.path.splitext(path)[1].lstrip(".") or "png", **options)


def figure_path_problem(path):
    """What keeps a figure from being written at path, as the rest of a
    sentence that starts with the path (': no folder x', ' is a folder; ...',
    ': a file name ending in ...'), or None: the folder must exist and the
    name end in a format matplotlib writes."""
    folder = os.path.dirname(path) or "."
    if not os.path.isdir(folder):
        return ": no folder %s" % folder
    if os.path.isdir(path) and not os.path.islink(path):
        return " is a folder; give a file name (.png)"
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    formats = Figure().canvas.get_supported_filetypes()
    if os.path.splitext(path)[1].lstrip(".").lower() not in formats:
        return ": a file name ending in .%s" % ", .".join(sorted(formats))
    return None


def own_directory(path):
    """path made if missing, as a tool makes its output directory; a
    symbolic link there is refused (NotADirectoryError naming it): what is
    written into it would land where the link points."""
    if os.path.islink(path):
        raise NotADirectoryError(20, "a symbolic link, not a directory of its own (what is "
                                 "written there would land where it points): remove it", path)
    os.makedirs(path, exist_ok=True)


def create_new(path):
    """A new text file at path, opened for writing; FileExistsError if
    anything, a symbolic link included, is there already."""
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC,
                 0o666)
    return os.fdopen(fd, "w")


def outside_case(case, rel):
    """Where case/rel resolves to (its nearest existing folder's resolution
    while it is not made yet) when that lies outside the case, else None:
    a folder of the case that is a symbolic link to elsewhere would put
    what a tool writes there outside the case. Links inside it are fine."""
    top = os.path.realpath(case)
    path = os.path.join(case, rel)
    while not os.path.lexists(path) and os.path.dirname(path) not in ("", path):
        path = os.path.dirname(path)
    where = os.path.realpath(path or ".")
    return None if where == top or where.startswith(top + os.sep) else where
