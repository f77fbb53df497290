# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The dictionary edits of dpmStudy (its settings, a variant's edits), made
with OpenFOAM's foamDictionary.

An edit leaves a dictionary's directives and variables as they are
(foamDictionary -disableFunctionEntries): a template's
#include "<constant>/caseSettings" stays an include and $endTime a variable,
so a later change of the settings still reaches every file that uses them.
foamDictionary cannot read an #eval's expression unexpanded: a dictionary
with #eval is edited expanded (its values as they are at that moment) and the
entries of the files it includes (a template's caseSettings: wSmall,
pressure ...) are removed again afterwards, so that it keeps only its own
entries. A lookup (foam_has, foam_get) sees the dictionary as the solver
does, with its includes expanded.
"""

import os
import re
import subprocess

_COMMENTS = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
_TOKENS = re.compile(r'"(?:[^"\\]|\\.)*"|[{}();]|[^\s{}();"]+')
_INCLUDE = re.compile(r'#(?:include|includeIfPresent|sinclude)\s+"([^"]+)"')
_EXPRESSION = re.compile(r"#(?:eval|calc|codeStream)\b")


def _foam_dictionary(dict_file, *args, **kwargs):
    """foamDictionary <args> dict_file, in the case the file belongs to (an
    #include "<constant>/..." resolves against that case, whatever the
    working directory)."""
    case = os.path.dirname(os.path.dirname(os.path.abspath(dict_file)))
    return subprocess.run(["foamDictionary", "-case", case] + list(args) + [dict_file],
                          **kwargs)


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
        r = _foam_dictionary(path, "-keywords", stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, universal_newlines=True)
        keys.update(k for k in r.stdout.split() if k != "FoamFile")
    return keys


def _edit(dict_file, entry, args):
    with open(dict_file) as f:
        text = f.read()
    if _EXPRESSION.search(_COMMENTS.sub(" ", text)):
        _edit_expanded(dict_file, entry, args, text)
    else:
        _run_edit(dict_file, entry, ["-disableFunctionEntries"], args)


def _edit_expanded(dict_file, entry, args, text):
    foreign = included_entries(dict_file, text) - set(own_entries(text)) - {entry.split("/")[0]}
    _run_edit(dict_file, entry, [], args)
    for key in sorted(foreign):
        _run_edit(dict_file, key, [], ["-remove"])


def _run_edit(dict_file, entry, options, args):
    # stderr kept for a failure: foamDictionary's own message names the problem
    r = _foam_dictionary(dict_file, *options, "-entry", entry, *args,
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         universal_newlines=True)
    if r.returncode != 0:
        raise RuntimeError("foamDictionary -entry %s %s %s failed:\n%s"
                           % (entry, " ".join(args), dict_file, r.stderr))


def foam_set(dict_file, entry, value):
    _edit(dict_file, entry, ["-set", str(value)])


def foam_has(dict_file, entry):
    return _foam_dictionary(dict_file, "-entry", entry, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL).returncode == 0


def foam_remove(dict_file, entry):
    """Remove entry if the dictionary has it."""
    if foam_has(dict_file, entry):
        _edit(dict_file, entry, ["-remove"])


def foam_get(dict_file, entry):
    r = _foam_dictionary(dict_file, "-entry", entry, "-value", check=True,
                         stdout=subprocess.PIPE, universal_newlines=True)
    return r.stdout.strip()
