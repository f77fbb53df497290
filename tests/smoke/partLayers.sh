#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The coupling library's parts (the directories of src/dpmCoupling) form
# layers: a part includes headers only of parts below it, so the part
# directories' include graph has no circle (the developer guide's
# architecture table). Prints each circle found with the files that close it.
. "$(dirname "${BASH_SOURCE[0]}")/testFunctions" "$@"

/usr/bin/python3 - "$testsDir/../src/dpmCoupling" <<'PY' || fail "the parts of src/dpmCoupling include each other in a circle"
import os, re, sys
root = sys.argv[1]
skip = {"lnInclude", "Make"}
parts = sorted(d for d in os.listdir(root) if os.path.isdir(os.path.join(root, d)) and d not in skip)
owner, files = {}, {p: [] for p in parts}
for p in parts:
    for base, dirs, names in os.walk(os.path.join(root, p)):
        dirs[:] = [d for d in dirs if d not in skip and not d.startswith("linux64")]
        for n in names:
            if n.endswith((".H", ".C")):
                files[p].append(os.path.join(base, n))
                if n.endswith(".H"):
                    if n in owner and owner[n] != p:
                        print("header %s in two parts: %s and %s" % (n, owner[n], p)); sys.exit(1)
                    owner[n] = p
include = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
edges = {p: {} for p in parts}          # part -> {part below: a file that includes it}
for p in parts:
    for f in files[p]:
        for h in include.findall(open(f, errors="replace").read()):
            q = owner.get(os.path.basename(h))
            if q and q != p:
                edges[p].setdefault(q, os.path.relpath(f, root))
# Depth-first search for a circle
state, stack, circles = {}, [], []
def visit(p):
    state[p] = 1; stack.append(p)
    for q in sorted(edges[p]):
        if state.get(q) == 1:
            circles.append(stack[stack.index(q):] + [q])
        elif q not in state:
            visit(q)
    stack.pop(); state[p] = 2
for p in parts:
    if p not in state:
        visit(p)
for c in circles:
    print("circle: " + " -> ".join(c))
    for a, b in zip(c, c[1:]):
        print("  %s includes %s (%s)" % (a, b, edges[a][b]))
n = sum(len(e) for e in edges.values())
print("%d parts, %d part-to-part includes, %d circles" % (len(parts), n, len(circles)))
sys.exit(1 if circles else 0)
PY
pass "the parts of src/dpmCoupling include only parts below them"
