# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The dictionary edits of dpmStudy (its settings, a variant's edits), made
with OpenFOAM's foamDictionary.

foamDictionary writes an edited file as it read it: with its #include
expanded, so the entries of a settings file it includes (a template's
constant/caseSettings: wSmall, pressure ...) would land in the solver's
dictionary, which knows no such entries. After each edit those entries are
removed again: their values are already expanded where the dictionary used
them ($wSmall, #eval), and the dictionary keeps only its own entries.
"""

import os
import re
import subprocess

_COMMENTS = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
_TOKENS = re.compile(r'"(?:[^"\\]|\\.)*"|[{}();]|[^\s{}();"]+')
_INCLUDE = re.compile(r'#(?:include|includeIfPresent|sinclude)\s+"([^"]+)"')


def _foam_dictionary(*args, **kwargs):
    return subprocess.run(["foamDictionary"] + list(args), **kwargs)


def own_entries(text):
    """The top-level entry names a dictionary's text defines itself
    (#directives and what the files they include define aside)."""
    keys, depth, expect_key, skip_argument = [], 0, True, False
    for t in _TOKENS.findall(_COMMENTS.sub(" ", text)):
        if t in ("{", "("):
            depth += 1
        elif t in ("}", ")"):
            depth -= 1
            expect_key = expect_key or (depth == 0 and t == "}")
        elif depth:
            continue
        elif t == ";":
            expect_key = True
        elif skip_argument:
            skip_argument, expect_key = False, True
        elif expect_key:
            if t.startswith("#"):
                skip_argument = True       # #include "file" and the like
            else:
                keys.append(t)
            expect_key = False
    return keys


def included_entries(dict_file, text):
    """The top-level entry names of the files text #includes (resolved as
    OpenFOAM does for a case's constant/ or system/ file)."""
    here = os.path.dirname(os.path.abspath(dict_file))
    case = os.path.dirname(here)
    keys = set()
    for name in _INCLUDE.findall(_COMMENTS.sub(" ", text)):
        for tag, directory in (("<case>", case), ("<constant>", os.path.join(case, "constant")),
                               ("<system>", os.path.join(case, "system"))):
            if name.startswith(tag):
                name = directory + name[len(tag):]
        name = name.replace("$FOAM_CASE", case)
        path = name if os.path.isabs(name) else os.path.join(here, name)
        if not os.path.isfile(path):
            continue
        r = _foam_dictionary("-keywords", path, stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, universal_newlines=True)
        keys.update(k for k in r.stdout.split() if k != "FoamFile")
    return keys


def _edit(dict_file, entry, args):
    """foamDictionary -entry entry <args> dict_file, keeping out of the file
    the entries of the files it includes."""
    with open(dict_file) as f:
        text = f.read()
    foreign = included_entries(dict_file, text) - set(own_entries(text)) \
        - {entry.split("/")[0]} if "#" in text else set()
    _foam_dictionary("-entry", entry, *args, dict_file, check=True,
                     stdout=subprocess.DEVNULL)
    for key in sorted(foreign):
        _foam_dictionary("-entry", key, "-remove", dict_file, check=True,
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def foam_set(dict_file, entry, value):
    _edit(dict_file, entry, ["-set", str(value)])


def foam_remove(dict_file, entry):
    """Remove entry if the dictionary has it."""
    r = _foam_dictionary("-entry", entry, dict_file, stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL)
    if r.returncode == 0:
        _edit(dict_file, entry, ["-remove"])


def foam_get(dict_file, entry):
    r = _foam_dictionary("-entry", entry, "-value", dict_file, check=True,
                         stdout=subprocess.PIPE, universal_newlines=True)
    return r.stdout.strip()
