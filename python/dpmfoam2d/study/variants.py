# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The variants of dpmStudy (-variant): named sets of dictionary edits
applied to a study's beds and cases, checked against the template (the
edits themselves: study.foam_edit)."""

import os
import re
import sys

from .foam_edit import foam_has, foam_remove, foam_set
from ..files import replacing


VARIANT_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9.-]*$")


class Variant:
    """A named set of dictionary edits (see the usage of dpmStudy)."""

    def __init__(self, spec, template):
        # a name is one of the template's; anything with a '/' is a file
        path = spec if os.sep in spec else os.path.join(template, "variants", spec)
        if not os.path.isfile(path):
            known = list_variants(template)
            sys.exit("dpmStudy: no variant '%s' (%s); the template's variants: %s"
                     % (spec, path, ", ".join(known) if known else "none"))
        self.path = os.path.realpath(path)
        with open(path) as f:
            self.text = f.read()
        self.name = self.recorded_name(self.text) or os.path.basename(path)
        if not VARIANT_NAME.match(self.name):
            sys.exit("dpmStudy: variant name '%s' (%s): letters, digits, '.' and '-' "
                     "only, starting with a letter" % (self.name, path))
        self.edits = []
        for n, line in enumerate(self.text.splitlines(), 1):
            words = line.split("#", 1)[0].split(None, 2)
            if not words:
                continue
            if len(words) < 3:
                sys.exit("dpmStudy: %s line %d: '<file> <entry> <value>' or "
                         "'<file> <entry> -remove' expected, got '%s'" % (path, n, line.strip()))
            self.edits.append((n, words[0], words[1], words[2].strip()))
        if not self.edits:
            sys.exit("dpmStudy: variant %s has no edits" % path)

    def inside(self, directory, n, f, what):
        """directory/f resolved (links followed), refused outside directory:
        a variant edits only the files of the case it makes."""
        try:
            return case_file(directory, f, what)
        except ValueError as e:
            sys.exit("dpmStudy: %s line %d: %s" % (self.path, n, e))

    @staticmethod
    def recorded_name(text):
        """A case's record starts with '# variant <name>'."""
        m = re.match(r"# variant (\S+)\n", text)
        return m.group(1) if m else None

    def check(self, template):
        """Every edit names a file of the template and an entry it has (a
        misspelt entry would otherwise be added, not changed)."""
        for n, f, entry, value in self.edits:
            target = self.inside(template, n, f, "the template")
            if not os.path.isfile(target):
                sys.exit("dpmStudy: %s line %d: the template has no file %s"
                         % (self.path, n, f))
            if not foam_has(target, entry):
                sys.exit("dpmStudy: %s line %d: %s has no entry '%s'"
                         % (self.path, n, f, entry))

    # Edits that leave the packed bed as the template's: the gas's numerics
    # and closures, the CFD step. Any other edit (particles, contact, voidage
    # model, mesh, counts) gets the variant beds of its own, packed with its
    # edits (a packing depends on the box to its last digit, and blockMesh
    # gives other cell counts a box a last digit apart).
    GAS_ONLY_FILES = ("system/fvSchemes", "system/fvSolution", "constant/gasProperties")
    GAS_ONLY_ENTRIES = {"system/controlDict": ("deltaT",)}
    GAS_ONLY_PARTICLE_ENTRIES = ("dragModel", "formulation")

    def shapes_bed(self):
        for n, f, entry, value in self.edits:
            f = os.path.normpath(f)
            if f in self.GAS_ONLY_FILES or entry in self.GAS_ONLY_ENTRIES.get(f, ()):
                continue
            if f == "constant/particleProperties" and (
                    entry in self.GAS_ONLY_PARTICLE_ENTRIES or entry.startswith("dragCoeffs")
                    or entry.endswith("Coeffs")):
                continue
            return True
        return False

    def scaled(self, scale):
        """caseSettings particleScale for -scale: a fraction of the counts
        the cases would have, this variant's own particleScale included
        (said in one line); scale itself if the variant sets none."""
        own = [e for e in self.edits
               if os.path.normpath(e[1]) == "constant/caseSettings" and e[2] == "particleScale"]
        if scale is None or not own:
            return scale
        n, f, entry, value = own[-1]
        try:
            factor = float(value)
        except ValueError:
            sys.exit("dpmStudy: %s line %d: particleScale %s is not a number"
                     % (self.path, n, value))
        print("dpmStudy: -scale %g with variant %s's particleScale %g (%s line %d): the cases "
              "get particleScale %g (-scale is a fraction of the variant's counts)"
              % (scale, self.name, factor, self.path, n, scale * factor), flush=True)
        return scale * factor

    def apply(self, case, particle_scale=None):
        """The edits in case; particle_scale (-scale's, the variant's own
        included) replaces the variant's particleScale."""
        # caseSettings first: foamDictionary writes the other files with the
        # values they include from it expanded, as they are at that moment
        # (particleProperties' #eval'd masses and fractions: so the final
        # particleScale must be in caseSettings before they are written)
        edits = sorted(self.edits, key=lambda e: os.path.normpath(e[1]) != "constant/caseSettings")
        for n, f, entry, value in edits:
            if particle_scale is not None and entry == "particleScale" and \
                    os.path.normpath(f) == "constant/caseSettings":
                value = repr(float(particle_scale))
            target = self.inside(case, n, f, "the case")
            try:
                if value == "-remove":
                    foam_remove(target, entry)
                else:
                    foam_set(target, entry, value)
            except RuntimeError as e:
                m = re.search(r"FATAL (?:IO )?ERROR:?\s*(\S.*)", str(e))
                sys.exit("dpmStudy: %s line %d: foamDictionary cannot set %s %s to '%s'%s; "
                         "correct the line"
                         % (self.path, n, f, entry, value, ": " + m.group(1) if m else ""))
        with replacing(os.path.join(case, "constant", "variant")) as f:
            f.write(self.record())

    def record(self):
        if self.recorded_name(self.text):
            return self.text
        return "# variant %s\n%s" % (self.name, self.text)


def list_variants(template):
    d = os.path.join(template, "variants")
    return sorted(n for n in os.listdir(d) if VARIANT_NAME.match(n)) \
        if os.path.isdir(d) else []


def first_line_comment(path):
    with open(path) as f:
        for line in f:
            if line.startswith("#") and not line.startswith("# variant "):
                return line.lstrip("#").strip()
    return ""


# The rules of a variant, for dpmStudy (Variant.inside) and for the scripts
# that apply variants line by line with foamDictionary
# (benchmarks/netlSegregationValidation): a variant is a file of a variants/
# folder, named without a path, and each line's file resolves inside the case
# it edits.

def case_file(case, f, what="the case"):
    """case/f resolved (links followed), or ValueError saying the rule f
    breaks: a variant names the files of a case relative to it, and they
    resolve inside it (what: the case's name in the message)."""
    if os.path.isabs(f):
        raise ValueError("%s is an absolute path; a variant names the files of a case relative "
                         "to it (system/..., constant/...)" % f)
    root = os.path.realpath(case)
    target = os.path.realpath(os.path.join(root, f))
    if not target.startswith(root + os.sep):
        raise ValueError("%s lies outside %s (it resolves to %s); a variant edits only "
                         "the files of the case it makes" % (f, what, target))
    return target


def variant_file_edits(variants_dir, name, case):
    """The edits of the variant variants_dir/name in case: [(line number,
    case's file resolved, entry, value)], each file one the case has. A name
    is that of a file of variants_dir (VARIANT_NAME: no '/', no leading '.'),
    and the lines are '<file> <entry> <value>' ('#' starts a comment line).
    ValueError naming the variant file, the line and the rule it breaks."""
    if not VARIANT_NAME.match(name):
        raise ValueError("variant name '%s': the name of a file of %s (letters, digits, '.' and "
                         "'-', starting with a letter: no '/' or '..')" % (name, variants_dir))
    path = os.path.join(variants_dir, name)
    if not os.path.isfile(path):
        known = sorted(n for n in os.listdir(variants_dir) if VARIANT_NAME.match(n)) \
            if os.path.isdir(variants_dir) else []
        raise ValueError("no variant file %s (the variants: %s)"
                         % (path, ", ".join(known) if known else "none"))
    edits = []
    with open(path) as f:
        for n, line in enumerate(f, 1):
            words = line.split(None, 2)
            if not words or words[0].startswith("#"):
                continue
            if len(words) < 3:
                raise ValueError("%s line %d: '<file> <entry> <value>' expected, got '%s'"
                                 % (path, n, line.strip()))
            try:
                target = case_file(case, words[0])
            except ValueError as e:
                raise ValueError("%s line %d: %s" % (path, n, e))
            if not os.path.isfile(target):
                raise ValueError("%s line %d: the case has no file %s" % (path, n, words[0]))
            edits.append((n, target, words[1], words[2].strip()))
    if not edits:
        raise ValueError("variant %s has no edits" % path)
    return edits


def print_variant_file_edits(argv=None):
    """The command line of variant_file_edits for a shell script:
    <tool> <variants dir> <name>[+<name> ...] <case>: every edit, the parts
    in turn, one a line: variant file, line number, file, entry, value
    (tab-separated); nothing and exit status 1, with the message after
    '<tool>: ' on stderr, if any line breaks a rule."""
    tool, variants_dir, names, case = sys.argv[1:] if argv is None else argv
    try:
        out = ["%s\t%d\t%s\t%s\t%s" % ((os.path.join(variants_dir, name),) + edit)
               for name in names.split("+")
               for edit in variant_file_edits(variants_dir, name, case)]
    except ValueError as e:
        sys.exit("%s: %s" % (tool, e))
    for line in out:
        print(line)
