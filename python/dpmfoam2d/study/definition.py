# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""A study's definition, the studyDict its template carries: the matrix
(small-particle mass fractions x operating pressures: their default values
and the values allowed) and the findings that results/ tests, as
differences between the ensembles of two cells of the matrix.

    massFractions { values (0.25 0.5); allowed (0.25 0.5 0.75); allowedNote "..."; }
    pressures     { values (1 8); }
    findingsTitle "The paper's findings 2-4";
    findingsNotes { 2 "..."; 3 "..."; }         // {rateWindow}: the rate window
    findings
    {
        <group>
        {
            each        wSmall;     // or pressure: one contrast per value present
            contrasts
            {
                <name>
                {
                    finding     2;
                    comparison  "final M, 64 - 1 bar, w {wSmall}";
                    quantity    Mmean;  // a column of summary.csv averaged over seeds
                    a           64;     // the other parameter's value of case a
                    b           1;      // of case b (none: a's mean against 0)
                    sign        +;      // the expected sign of a - b
                }
            }
        }
    }

The file is written in OpenFOAM's dictionary syntax (comments, nested
dictionaries, lists, quoted strings; no #include or $macros). The runner
copies it into the study directory, whose copy the results then follow.
"""

import math
import os
import re

FILE_NAME = "studyDict"
PARAMETERS = ("wSmall", "pressure")       # the matrix's axes, caseSettings' entries
QUANTITIES = ("Mmean", "Mfinal", "Mrate", "M0", "vertical", "horizontal",
              "bedHeight", "bubbleFraction", "emulsionVoidage", "speedRmsSmall",
              "speedRmsLarge", "stillSmall", "stillLarge", "voidageSmall", "voidageLarge")

_TOKEN = re.compile(r'\s+|//[^\n]*|/\*.*?\*/|"((?:[^"\\]|\\.)*)"|([{}();])|([^\s{}();"]+)', re.S)


class DefinitionError(Exception):
    """A studyDict this reader refuses, the file and the entry in the message."""


def parse(text, path):
    """An OpenFOAM-syntax dictionary as nested dicts; a value is a string
    (quoted or a word), a list of them, or a dict. Directives (#include,
    #eval ...) and $macros are refused, naming the line."""
    tokens, pos = [], 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m:
            raise DefinitionError("%s line %d: cannot read the text at character %d"
                                  % (path, _line(text, pos), pos))
        if m.group(1) is not None:
            tokens.append(("string", m.group(1), pos))
        elif m.group(2):
            tokens.append((m.group(2), m.group(2), pos))
        elif m.group(3):
            word = m.group(3)
            if word.startswith("#") or word.startswith("$"):
                raise DefinitionError(
                    "%s line %d: %s is not supported in a %s: it is read without "
                    "OpenFOAM's directives and macros (#include, #eval, $name); write the "
                    "entries out" % (path, _line(text, pos), word, FILE_NAME))
            tokens.append(("word", word, pos))
        pos = m.end()
    out, i = _dictionary(tokens, 0, path, top=True, text=text)
    return out


def _line(text, pos):
    return text.count("\n", 0, pos) + 1


def _dictionary(tokens, i, path, top=False, text=""):
    out = {}
    while i < len(tokens):
        kind, key, pos = tokens[i]
        where = "%s line %d" % (path, _line(text, pos))
        if kind == "}":
            if top:
                raise DefinitionError("%s: a '}' closes no dictionary" % where)
            return out, i + 1
        if kind != "word":
            raise DefinitionError("%s: an entry's name expected, got '%s'" % (where, key))
        i += 1
        if i < len(tokens) and tokens[i][0] == "{":
            out[key], i = _dictionary(tokens, i + 1, path, text=text)
            continue
        values = []
        while i < len(tokens) and tokens[i][0] != ";":
            kind, value, pos = tokens[i]
            if kind == "(":
                items, i = [], i + 1
                while i < len(tokens) and tokens[i][0] != ")":
                    if tokens[i][0] not in ("word", "string"):
                        raise DefinitionError("%s: %s: only words and numbers in a list"
                                              % (where, key))
                    items.append(tokens[i][1])
                    i += 1
                values.append(items)
            elif kind in ("word", "string"):
                values.append(value)
            else:
                raise DefinitionError("%s line %d: %s: unexpected '%s'"
                                      % (path, _line(text, pos), key, value))
            i += 1
        if i >= len(tokens):
            raise DefinitionError("%s: %s: no ';' ends the entry" % (where, key))
        out[key] = values[0] if len(values) == 1 else values
        i += 1
    if not top:
        raise DefinitionError("%s: a dictionary is not closed with '}'" % path)
    return out, i


def check_placeholders(path, where, text, allowed):
    """text formatted with the placeholders it will get (allowed: their
    names), here, before any case runs: an unknown one is refused."""
    try:
        text.format(**{name: "1" for name in allowed})
    except KeyError as e:
        got = "{%s}" % e.args[0]
    except IndexError:
        got = "a positional placeholder ({} or {0})"
    except ValueError as e:
        got = "a brace without its pair (%s)" % e
    else:
        return
    raise DefinitionError("%s: %s \"%s\": %s is no placeholder of it; allowed: %s "
                          "(a literal brace: {{ or }})"
                          % (path, where, text, got,
                             " ".join("{%s}" % n for n in allowed) or "none"))


def _numbers(path, where, value):
    items = value if isinstance(value, list) else [value]
    try:
        numbers = [float(v) for v in items]
    except (TypeError, ValueError):
        raise DefinitionError("%s: %s: numbers expected, got %s" % (path, where, value))
    if not numbers:
        raise DefinitionError("%s: %s: an empty list; at least one number (a study of no "
                              "cases would run nothing)" % (path, where))
    for v in numbers:
        if not math.isfinite(v):
            raise DefinitionError("%s: %s: %s is not a finite number" % (path, where, v))
    return [int(v) if v == int(v) else v for v in numbers]


class Contrast:
    """One finding's difference a - b at each value of `each`."""

    def __init__(self, path, where, each, spec):
        self.each = each
        self.other = PARAMETERS[1 - PARAMETERS.index(each)]
        for key in ("finding", "comparison", "quantity", "a", "sign"):
            if key not in spec:
                raise DefinitionError("%s: %s: no entry '%s'" % (path, where, key))
        unknown = set(spec) - {"finding", "comparison", "quantity", "a", "b", "sign"}
        if unknown:
            raise DefinitionError("%s: %s: unknown entry '%s' (known: finding comparison "
                                  "quantity a b sign)" % (path, where, sorted(unknown)[0]))
        self.finding = str(spec["finding"])
        self.comparison = str(spec["comparison"])
        check_placeholders(path, where + "/comparison", self.comparison, (each,))
        self.quantity = spec["quantity"]
        if self.quantity not in QUANTITIES:
            raise DefinitionError("%s: %s/quantity %s: one of %s"
                                  % (path, where, self.quantity, " ".join(QUANTITIES)))
        self.a = _numbers(path, where + "/a", spec["a"])[0]
        self.b = None if spec.get("b", "none") == "none" else \
            _numbers(path, where + "/b", spec["b"])[0]
        self.sign = spec["sign"]
        if self.sign not in ("+", "-"):
            raise DefinitionError("%s: %s/sign %s: + or -" % (path, where, self.sign))

    def cell(self, value, other):
        """(wSmall, pressure) of the case at `each` = value, the other = other."""
        return (value, other) if self.each == "wSmall" else (other, value)


class Definition:
    """The studyDict of a template or of a study directory."""

    def __init__(self, path):
        self.path = path
        try:
            with open(path) as f:
                self.text = f.read()
        except OSError as e:
            raise DefinitionError("%s: %s; a study template carries its matrix and findings "
                                  "in %s (tutorials/paperStudy/%s shows the entries)"
                                  % (path, e.strerror, FILE_NAME, FILE_NAME))
        d = parse(self.text, path)
        d.pop("FoamFile", None)
        known = {"massFractions", "pressures", "findings", "findingsTitle", "findingsNotes"}
        unknown = set(d) - known
        if unknown:
            raise DefinitionError("%s: unknown entry '%s' (known: %s)"
                                  % (path, sorted(unknown)[0], " ".join(sorted(known))))
        self.w, self.w_allowed, self.w_note = self._axis(d, "massFractions", 0, 1)
        self.p, self.p_allowed, self.p_note = self._axis(d, "pressures", 0, float("inf"))
        self.findings_title = str(d.get("findingsTitle", "The findings"))
        notes = d.get("findingsNotes", {})
        if not isinstance(notes, dict):
            raise DefinitionError("%s: findingsNotes: a dictionary of finding \"text\"" % path)
        self.findings_notes = [(str(k), str(v)) for k, v in notes.items()]
        for k, v in self.findings_notes:
            check_placeholders(path, "findingsNotes/%s" % k, v, ("rateWindow",))
        self.groups = []
        findings = d.get("findings", {})
        if not isinstance(findings, dict):
            raise DefinitionError("%s: findings: a dictionary of groups" % path)
        for name, group in findings.items():
            where = "findings/" + name
            if not isinstance(group, dict) or group.get("each") not in PARAMETERS:
                raise DefinitionError("%s: %s/each: %s (one contrast per value of it)"
                                      % (path, where, " or ".join(PARAMETERS)))
            contrasts = group.get("contrasts", {})
            if not isinstance(contrasts, dict) or not contrasts:
                raise DefinitionError("%s: %s/contrasts: a dictionary of contrasts"
                                      % (path, where))
            self.groups.append([Contrast(path, "%s/contrasts/%s" % (where, c), group["each"],
                                         spec if isinstance(spec, dict) else {})
                                for c, spec in contrasts.items()])

    def _axis(self, d, name, low, high):
        if not isinstance(d.get(name), dict) or "values" not in d[name]:
            raise DefinitionError("%s: no %s { values (...); }" % (self.path, name))
        a = d[name]
        values = _numbers(self.path, name + "/values", a["values"])
        allowed = _numbers(self.path, name + "/allowed", a["allowed"]) if "allowed" in a \
            else None
        for v in values + (allowed or []):
            if not low < v < high and not (name == "massFractions" and v == 1):
                raise DefinitionError("%s: %s: %g is outside (%g, %g%s"
                                      % (self.path, name, v, low, high,
                                         "]" if name == "massFractions" else ")"))
        if allowed is not None:
            for v in values:
                if v not in allowed:
                    raise DefinitionError("%s: %s/values: %g is not allowed (%s)"
                                          % (self.path, name, v, " ".join("%g" % x
                                                                          for x in allowed)))
        return values, allowed, a.get("allowedNote")

    def contrasts(self, have):
        """(finding, comparison, quantity, case a, case b, sign) of every
        contrast whose cases are in have, a set of (wSmall, pressure); case
        b None: a's mean against zero. In the file's order of groups; within
        a group value by value, each value's contrasts in their order."""
        out = []
        for group in self.groups:
            each = group[0].each
            axis = sorted({c[PARAMETERS.index(each)] for c in have})
            for value in axis:
                for c in group:
                    a = c.cell(value, c.a)
                    b = None if c.b is None else c.cell(value, c.b)
                    if a in have and (b is None or b in have):
                        out.append((c.finding, c.comparison.format(**{each: "%g" % value}),
                                    c.quantity, a, b, c.sign))
        return out

    def notes(self, rate_window):
        """The findings.md lines that say what each finding is."""
        window = "%g < t <= %g s" % rate_window
        return " ".join("Finding %s: %s." % (k, v.format(rateWindow=window))
                        for k, v in self.findings_notes)


def of_template(template):
    return Definition(os.path.join(template, FILE_NAME))
