# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Where the dpmFoam2D project is, for the few functions that need its tree
(the study's default template, the commit a run was built from, the
environment a Slurm task sources) and the programs they start.

The package is installed apart from the project (pip install python/), so
it never looks for the project beside its own files: the project is the
directory that its etc/bashrc exports as DPMFOAM2D_PROJECT, and the
solver's programs are found on PATH, which etc/bashrc sets too.
"""

import os
import shutil
from typing import Iterable, Optional

VARIABLE = "DPMFOAM2D_PROJECT"


class ProjectError(RuntimeError):
    """The project, or a program of it, is not where the environment says."""


def project_dir_or_none() -> Optional[str]:
    """The project's directory from DPMFOAM2D_PROJECT, or None when unset."""
    path = os.environ.get(VARIABLE)
    return os.path.abspath(path) if path else None


def project_dir(needed_for: str) -> str:
    """The project's directory (DPMFOAM2D_PROJECT); ProjectError naming
    the variable and what needed it when it is unset or no directory."""
    path = project_dir_or_none()
    if path is None:
        raise ProjectError("%s is not set: %s needs the dpmFoam2D project; source its "
                           "etc/bashrc" % (VARIABLE, needed_for))
    if not os.path.isdir(path):
        raise ProjectError("%s=%s is no directory: %s needs the dpmFoam2D project; source "
                           "its etc/bashrc" % (VARIABLE, path, needed_for))
    return path


def project_path(needed_for: str, *parts: str) -> str:
    """A path inside the project, which must exist (ProjectError naming it)."""
    path = os.path.join(project_dir(needed_for), *parts)
    if not os.path.exists(path):
        raise ProjectError("%s needs %s, which is missing (%s=%s)"
                           % (needed_for, path, VARIABLE, project_dir(needed_for)))
    return path


def require_programs(programs: Iterable[str], needed_for: str) -> None:
    """Each program on PATH, or ProjectError naming the missing ones."""
    missing = [p for p in programs if shutil.which(p) is None]
    if missing:
        raise ProjectError("%s needs %s, not found on PATH: build the project (./Allwmake) "
                           "and source its etc/bashrc" % (needed_for, ", ".join(missing)))
