#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Mutation check of the coupling's tests: each mutation of coupling.txt (a flipped sign, a
dropped factor, a wrong share in the OpenFOAM side: the formulations, the exchange, the gas's
momentum equation, the voidage models' overlaps, the interpolation weights) is applied alone
to the project's own tree, the project rebuilt (./Allwmake) and the mutation's tests run
(its 'tests:' regex; --all: the coupling and solver labels); a mutation that they let
through has survived. Prints the survivors, the count killed and the time, then restores
every file and rebuilds. A developer tool (minutes per mutation), not a CI step.

The DEM library's own mutations: src/dem/tests/mutations/runMutations.py.

    tests/mutations/runMutations.py [-k SUBSTRING] [--all] [--jobs N] [--list FILE]
"""

import argparse
import os
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(PROJECT, "src", "dem", "tests", "mutations"))
from runMutations import check_texts, failed_tests, read_mutations  # noqa: E402  (the DEM tool's)

# The labels that guard the coupling, for --all
LABELS = "coupling|solver"


def run(command, cwd, log):
    """The command's exit code, its output appended to `log` and kept in run.output."""
    done = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True)
    with open(log, "a") as out:
        out.write("$ " + " ".join(command) + "\n" + done.stdout)
    run.output = done.stdout
    return done.returncode


def build(log):
    """./Allwmake of the tree; True when it built."""
    return run(["./Allwmake"], PROJECT, log) == 0


def killers(mutation, everything, jobs, build_dir, log):
    """The tests that fail with the mutation in (none: it survived); stops at the first."""
    selection = ["-L", LABELS] if everything else ["-R", mutation["tests"]]
    command = ["ctest", "-j", str(jobs), "--stop-on-failure", "--output-on-failure"]
    if run(command + selection, build_dir, log) != 0:
        return failed_tests(run.output) or ["(ctest failed: see the log)"]
    return []


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-k", default="", help="run only the mutations whose name contains this")
    parser.add_argument("--all", action="store_true",
                        help=f"run the labels {LABELS} for each mutation, not its own tests")
    parser.add_argument("--jobs", type=int, default=2, help="test jobs (default 2)")
    parser.add_argument("--list", default=os.path.join(HERE, "coupling.txt"))
    args = parser.parse_args()

    build_dir = os.environ.get("DPMFOAM2D_BUILD")
    if not build_dir or not os.path.isdir(build_dir):
        sys.exit("DPMFOAM2D_BUILD is not a build folder: source etc/bashrc and ./Allwmake first")
    mutations = [m for m in read_mutations(args.list, optional=("tests",)) if args.k in m["name"]]
    if not mutations:
        sys.exit("no mutation selected")
    check_texts(mutations, PROJECT)
    for m in mutations:
        if "tests" not in m and not args.all:
            sys.exit(f"mutation {m['name']!r}: no 'tests:' (or run with --all)")

    log = os.path.join(build_dir, "couplingMutations.log")
    open(log, "w").close()
    print(f"log {log}", flush=True)
    # A stop (TERM, as INT) restores the file under mutation before the tool ends
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    start = time.time()
    if not build(log):
        sys.exit(f"the tree does not build unmutated (see {log})")
    survived, unbuilt = [], []
    try:
        for k, m in enumerate(mutations, 1):
            path = os.path.join(PROJECT, m["file"])
            original = open(path).read()
            t0 = time.time()
            try:
                with open(path, "w") as f:
                    f.write(original.replace(m["from"], m["to"]))
                killer = ""
                if not build(log):
                    outcome = "did not build"
                    unbuilt.append(m["name"])
                else:
                    failed = killers(m, args.all, args.jobs, build_dir, log)
                    if failed:
                        outcome = "killed"
                        killer = " by " + ", ".join(failed)
                    else:
                        outcome = "SURVIVED"
                        survived.append(m["name"])
            finally:
                with open(path, "w") as f:
                    f.write(original)
            print(f"[{k}/{len(mutations)}] {outcome:13s} {m['name']} "
                  f"({time.time() - t0:.0f} s){killer}", flush=True)
    finally:
        print("rebuilding the unmutated tree ...", flush=True)
        if not build(log):
            print(f"the unmutated tree did not build (see {log})")

    killed = len(mutations) - len(survived) - len(unbuilt)
    print(f"\n{len(mutations)} mutations, {killed} killed, {len(survived)} survived, "
          f"{len(unbuilt)} did not build; {(time.time() - start) / 60.0:.1f} min")
    for name in survived:
        print("  survived: " + name)
    for name in unbuilt:
        print("  did not build (fix the list): " + name)
    return 0 if not survived and not unbuilt else 1


if __name__ == "__main__":
    sys.exit(main())
