#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The documentation site builds with MkDocs in strict mode: every internal
# link and nav entry resolves, every page is in the nav, the dictionary
# tables list exactly the entries the code knows, every command's -h runs.
# The theory pages' equations are math markup for MathJax (displayed and
# inline, no TeX left in the text), and MathJax is in the site itself: every
# page loads it by a relative path to a file that the site holds, and no
# page loads a script from elsewhere.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
"$testsDir/../etc/buildDocs" -o "$workDir/site" || fail "the site does not build (above)"
for page in index.html user-guide/dictionaries.html user-guide/commands.html theory/paper-model.html reproduction.html performance.html; do
    [ -s "$workDir/site/$page" ] || fail "no $page in the site"
done
grep -q "dpmStudy" "$workDir/site/user-guide/commands.html" || fail "the commands page lacks dpmStudy"
/usr/bin/python3 - "$workDir/site" theory/paper-model.html theory/drag-closures.html theory/slab-mode.html model.html \
        <<'PYTHON' || fail "the math of the site (above)"
import html.parser
import os
import sys

site, pages = sys.argv[1], sys.argv[2:]
VOID = {"br", "img", "hr", "input", "meta", "link", "wbr", "source"}


class Page(html.parser.HTMLParser):
    """The page's scripts, its math elements and the text outside math and code"""

    def __init__(self):
        super().__init__()
        self.scripts, self.math, self.text = [], {"div": 0, "span": 0}, []
        self.open = []          # the elements that hide text from the check

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "script" and attrs.get("src"):
            self.scripts.append(attrs["src"])
        math = "arithmatex" in (attrs.get("class") or "").split()
        if math and tag in self.math:
            self.math[tag] += 1
        if tag not in VOID and (self.open or math or tag in ("code", "pre", "script", "style")):
            self.open.append(tag)

    def handle_endtag(self, tag):
        if self.open and self.open[-1] == tag:
            self.open.pop()

    def handle_data(self, data):
        if not self.open:
            self.text.append(data)


errors = []
for name in pages:
    page = Page()
    with open(os.path.join(site, name), encoding="utf-8") as f:
        page.feed(f.read())
    if page.math["div"] == 0 or page.math["span"] == 0:
        errors.append("%s: %d displayed and %d inline equations marked for MathJax, expected some of each"
                      % (name, page.math["div"], page.math["span"]))
    text = "".join(page.text)
    for tex in ("$", "\\frac", "\\mathrm", "\\varepsilon", "\\sqrt"):
        if tex in text:
            at = text.index(tex)
            errors.append("%s: TeX outside the math markup: ...%s..." % (name, text[max(0, at - 40):at + 40]))
    mathjax = [s for s in page.scripts if s.split("?")[0].endswith("/MathJax.js")]
    if not mathjax:
        errors.append("%s: no MathJax script" % name)
    for src in page.scripts:
        if "://" in src or src.startswith("//"):
            errors.append("%s: a script from outside the site: %s" % (name, src))
        elif not os.path.isfile(os.path.normpath(os.path.join(site, os.path.dirname(name), src.split("?")[0]))):
            errors.append("%s: the script %s is not in the site" % (name, src))
for error in errors:
    print(error)
sys.exit(1 if errors else 0)
PYTHON
grep -rlE '<script[^>]+src="(https?:)?//' "$workDir/site" --include='*.html' \
    && fail "pages that load scripts from outside the site (above)"
pass "the documentation site builds with warnings as errors, its equations typeset by a MathJax of its own"
