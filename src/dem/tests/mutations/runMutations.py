#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Mutation check of the DEM library's tests: each mutation of mutations.txt (a small change
of the physics: a flipped sign, a wrong factor, a dropped limit) is applied alone to a scratch
copy of src/dem, the library and its tests are built there and the `dem` and `verification`
labels run; a mutation that every test lets through has survived. Prints the survivors, the
count killed and the time. A developer tool (minutes per mutation), not a CI step.

    runMutations.py [-k SUBSTRING] [--tests REGEX] [--jobs N] [--keep] [--reuse DIR]
                    [--list FILE]
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DEM = os.path.dirname(os.path.dirname(HERE))   # src/dem

# The tests that take most of a run (over ten seconds each on one core): run after the rest,
# so that a mutation the quick tests kill does not wait for them.
SLOW = ["SettledBed.PaperBedSettlesDenseAndAtRest", "SlabFacade.SaveAndLoadContinueBitForBit",
        "SlabSortByCell.LeavesTheTrajectoryAlone", "SlabBed.SettledSlabCarriesItsWeightOnTheFloor"]


# A missing reference table fails its test instead of skipping it: no mutation survives
# by a skip. The tests load the scratch build's libdem through their RUNPATH, which
# LD_LIBRARY_PATH would override (etc/bashrc puts the project's own libdem there, with
# which every mutation survives): left out.
ENVIRONMENT = dict(os.environ, DPMFOAM2D_REQUIRE_REFERENCE="1")
ENVIRONMENT.pop("LD_LIBRARY_PATH", None)


# A mutation of the contact kernel's inline functions changes the code of the sources that
# call them only: those are rebuilt (the header's time stamp kept), not every source that
# includes it for its types, whose objects the mutation leaves as they are. Another header's
# mutation rebuilds the sources that include it, directly or through other headers.
KERNEL_HEADER = "ContactKernel.hpp"
KERNEL_CALLS = re.compile(r"\b(contactForce|rollingResistance|selectWithoutBranch)\s*[<(]")


def sources(source):
    """Every .cpp and .hpp file of the scratch copy with its text."""
    found = {}
    for folder, _, files in os.walk(source):
        for name in files:
            if name.endswith((".cpp", ".hpp")):
                path = os.path.join(folder, name)
                found[path] = open(path).read()
    return found


def header_users(source, header):
    """The .cpp files to rebuild after a mutation of `header`."""
    texts = sources(source)
    if os.path.basename(header) == KERNEL_HEADER:
        return [p for p, t in texts.items() if p.endswith(".cpp") and KERNEL_CALLS.search(t)]
    including, names = set(), {os.path.basename(header)}
    while True:
        more = {p for p, t in texts.items() if p not in including
                and any(re.search(r'#include\s+"(?:[^"]*/)?' + re.escape(n) + '"', t) for n in names)}
        if not more:
            break
        including |= more
        names |= {os.path.basename(p) for p in more if p.endswith(".hpp")}
    return sorted(p for p in including if p.endswith(".cpp"))


def touch(paths):
    for path in paths:
        os.utime(path)


def sync(tree, copy):
    """The files of `tree` that differ from (or are missing in) `copy` copied there, the
    others left with their time stamps: a reused build rebuilds what changed only."""
    for folder, dirs, files in os.walk(tree):
        dirs[:] = [d for d in dirs if not d.startswith("build") and d != ".git"]
        for name in files:
            path = os.path.join(folder, name)
            target = os.path.join(copy, os.path.relpath(path, tree))
            if not os.path.isfile(target) or open(path, "rb").read() != open(target, "rb").read():
                os.makedirs(os.path.dirname(target), exist_ok=True)
                shutil.copyfile(path, target)


def read_mutations(path, optional=()):
    """The blocks of `path`: 'name:', 'file:', 'from:', 'to:' lines (and any of the keys
    `optional`), a blank line between blocks, '#' lines comments, '\\n' a line break. 'from'
    must occur once in its file."""
    mutations, block = [], {}
    with open(path) as f:
        lines = f.read().splitlines() + [""]
    for number, line in enumerate(lines, 1):
        if line.startswith("#"):
            continue
        if not line.strip():
            if block:
                missing = {"name", "file", "from", "to"} - block.keys()
                if missing:
                    sys.exit(f"{path}:{number}: mutation {block.get('name', '?')!r} lacks "
                             f"{', '.join(sorted(missing))}")
                mutations.append(block)
                block = {}
            continue
        key, sep, value = line.partition(":")
        if not sep or key not in ("name", "file", "from", "to") + tuple(optional):
            keys = ", ".join(f"'{k}:'" for k in ("name", "file", "from", "to") + tuple(optional))
            sys.exit(f"{path}:{number}: expected one of {keys}, got {line!r}")
        value = value[1:] if value.startswith(" ") else value
        block[key] = value.replace("\\n", "\n")
    return mutations


def check_texts(mutations, root):
    """Exits naming the first mutation whose file (under `root`) is missing or whose 'from'
    text does not occur there exactly once."""
    for m in mutations:
        path = os.path.join(root, m["file"])
        if not os.path.isfile(path):
            sys.exit(f"mutation {m['name']!r}: file {m['file']} is not in {root}")
        count = open(path).read().count(m["from"])
        if count != 1:
            sys.exit(f"mutation {m['name']!r}: its 'from' text occurs {count} times in "
                     f"{m['file']}, not once")


def run(command, cwd, log):
    """The command's exit code; its output appended to `log`."""
    done = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          env=ENVIRONMENT, text=True)
    with open(log, "a") as out:
        out.write("$ " + " ".join(command) + "\n" + done.stdout)
    run.output = done.stdout
    return done.returncode


def failed_tests(output):
    """The tests ctest lists as failed in `output`."""
    return re.findall(r"^\s*\d+ - (\S+) \((?:Failed|Timeout|SEGFAULT|Subprocess aborted|"
                      r"Exception|Child aborted)[^)]*\)", output, re.MULTILINE)


def tests_pass(build, jobs, log, only=""):
    """The dem and verification labels (or the tests matching `only`), the quick tests first;
    stops at the first failure. Returns the failed tests (none: the mutation survived)."""
    slow = "|".join(s.replace(".", "\\.") for s in SLOW)
    base = ["ctest", "-j", str(jobs), "--stop-on-failure", "--output-on-failure"]
    stages = [["-R", only]] if only else [["-E", slow], ["-R", slow]]
    for stage in stages:
        if run(base + ["-L", "dem|verification"] + stage, build, log) != 0:
            return failed_tests(run.output) or ["(ctest failed: see the log)"]
    return []


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-k", default="", help="run only the mutations whose name contains this")
    parser.add_argument("--jobs", type=int, default=2, help="build and test jobs (default 2)")
    parser.add_argument("--keep", action="store_true", help="keep the scratch folder")
    parser.add_argument("--list", default=os.path.join(HERE, "mutations.txt"))
    parser.add_argument("--tests", default="",
                        help="run only the tests matching this ctest regex (which mutations "
                             "does a test kill?)")
    parser.add_argument("--reuse", default="",
                        help="a scratch folder kept by --keep: its copy and build are reused")
    args = parser.parse_args()

    mutations = [m for m in read_mutations(args.list) if args.k in m["name"]]
    check_texts(mutations, DEM)
    if not mutations:
        sys.exit("no mutation selected")

    start = time.time()
    scratch = args.reuse or tempfile.mkdtemp(prefix="dem-mutations-")
    source = os.path.join(scratch, "dem")
    build = os.path.join(scratch, "build")
    log = os.path.join(scratch, "log.txt")
    if not args.reuse:
        shutil.copytree(DEM, source, ignore=shutil.ignore_patterns("build*", ".git"))
    elif not os.path.isdir(source):
        sys.exit(f"--reuse {scratch}: no scratch copy there")
    else:
        sync(DEM, source)
    print(f"scratch copy {source}, log {log}", flush=True)
    # The reference folder as the tree's own configuration finds it (beside the top)
    reference = os.path.join(os.path.dirname(os.path.dirname(DEM)), "..", "shared",
                             "reference", "dem-verification")
    if run(["cmake", "-S", source, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
            "-DDEM_VERIFICATION_REFERENCE=" + os.path.abspath(reference)], scratch, log) != 0:
        sys.exit(f"the scratch copy does not configure (see {log})")
    targets = ["--target", "demTests", "demVerification"]
    if run(["cmake", "--build", build, "-j", str(args.jobs)] + targets, scratch, log) != 0:
        sys.exit(f"the unmutated copy does not build (see {log})")

    survived, unbuilt = [], []
    for k, m in enumerate(mutations, 1):
        path = os.path.join(source, m["file"])
        original = open(path).read()
        stamp = os.stat(path)
        header = path.endswith(".hpp")
        users = header_users(source, path) if header else []
        with open(path, "w") as f:
            f.write(original.replace(m["from"], m["to"]))
        if header:
            os.utime(path, ns=(stamp.st_atime_ns, stamp.st_mtime_ns))
            touch(users)
        t0 = time.time()
        killer = ""
        if run(["cmake", "--build", build, "-j", str(args.jobs)] + targets, scratch, log) != 0:
            outcome = "did not build"
            unbuilt.append(m["name"])
        else:
            failed = tests_pass(build, args.jobs, log, args.tests)
            if failed:
                outcome = "killed"
                killer = " by " + ", ".join(failed)
            else:
                outcome = "SURVIVED"
                survived.append(m["name"])
        with open(path, "w") as f:   # restored (its new time stamp rebuilds it next time)
            f.write(original)
        if header:
            os.utime(path, ns=(stamp.st_atime_ns, stamp.st_mtime_ns))
            touch(users)
        print(f"[{k}/{len(mutations)}] {outcome:13s} {m['name']} ({time.time() - t0:.0f} s)"
              f"{killer}", flush=True)

    killed = len(mutations) - len(survived) - len(unbuilt)
    minutes = (time.time() - start) / 60.0
    print(f"\n{len(mutations)} mutations, {killed} killed, {len(survived)} survived, "
          f"{len(unbuilt)} did not build; {minutes:.1f} min")
    for name in survived:
        print("  survived: " + name)
    for name in unbuilt:
        print("  did not build (fix the list): " + name)
    if args.keep or args.reuse:
        print(f"scratch folder kept: {scratch}")
    else:
        shutil.rmtree(scratch)
    return 0 if not survived and not unbuilt else 1


if __name__ == "__main__":
    sys.exit(main())
