#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmMovie and dpmPictures on cases the solver wrote (the test column with
# the laceyIndex function object, to 0.02 s and to 0.01 s: particle files
# every 0.01 s): a movie of the 3 output times with -every 1 has 3 frames
# (ffprobe), with -every 2 two; dpmPictures makes per case the snapshots
# asked for and the M(t) plot, and one combined plot with one curve per case
# (its -report).
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

for c in a b
do
    makeCase "$workDir/$c"
    (
        cd "$workDir/$c" || exit 1
        setEntry system/controlDict functions "{ #includeFunc laceyIndex }"
        [ $c = b ] && setEntry system/controlDict endTime 0.01
        runSolver
    ) || fail "the test column $c"
done
cd "$workDir" || fail "cd"

frames() { ffprobe -v error -count_frames -select_streams v:0 \
    -show_entries stream=nb_read_frames -of csv=p=0 "$1"; }
dpmMovie a -fps 5 -o a.mp4 >log.movie 2>&1 || { cat log.movie; fail "dpmMovie failed"; }
[ "$(frames a.mp4)" = 3 ] || fail "a.mp4 has $(frames a.mp4) frames, expected 3"
dpmMovie a -every 2 -o a2.mp4 >log.movie2 2>&1 || { cat log.movie2; fail "dpmMovie -every 2"; }
[ "$(frames a2.mp4)" = 2 ] || fail "a2.mp4 has $(frames a2.mp4) frames, expected 2"
[ ! -d a/images/frames ] || fail "frames left behind without -keep"

dpmPictures a b -times 0 0.02 -o all.png -report >log.pictures 2>&1 \
    || { cat log.pictures; fail "dpmPictures failed"; }
for f in a/images/snapshot_0.png a/images/snapshot_0.02.png a/images/mixing.png \
         b/images/snapshot_0.png b/images/snapshot_0.01.png b/images/mixing.png all.png
do
    [ -s "$f" ] || fail "dpmPictures did not make $f"
done
tail -1 log.pictures | grep -q '"combinedCurves": 2' || { cat log.pictures; fail "combined plot curves"; }
pass "movie frames and the set-of-cases pictures"
