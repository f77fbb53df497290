#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# dpmRiseTime: the rise time of a class is the first particle file in which
# a particle's centre is at or above the bed's surface, the height below
# which the fraction q of the other particles' centres lie.
#   - Written trajectories, particle files every 0.1 s over 2 s: a bed of
#     100 centres at 1, 2 ... 100 mm (the surface at q = 0.99: 99.01 mm, at
#     q = 0.5: 50.5 mm, the linear-interpolation quantile), and four
#     intruders: rising at 60 and 100 mm/s from 2 mm (at q 0.99 they reach
#     the surface at 1.617 and 0.970 s: the files of 1.7 and 1.0 s; at q 0.5
#     at 0.808 and 0.485 s: 0.9 and 0.5 s), one never rising (nan), one
#     above it in the file of 0.3 s only (its first crossing counts): the
#     table per particle and the ranks; -start 0.2 counts from 0.2 s.
#   - A run of the test column: one row per particle of the class named
#     by its name in particleProperties.
#   - Bad options are refused naming them; so are a class that is every
#     particle (no bed to rise through), a file or folder where the tables
#     go, a read-only case (run as nobody by root) and a particle file of
#     another run (other particles or ids than the first file's), each in
#     one line naming the path, without a traceback.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

mkdir -p "$workDir/written/system" && touch "$workDir/written/system/controlDict"
py - "$workDir/written" <<'PY' || fail "writing the trajectories"
import sys
import numpy as np
from dpmfoam2d import particles
case = sys.argv[1]
bed = 1e-3 * np.arange(1, 101)
for k in range(21):
    t = 0.1 * k
    intruders = [0.002 + 0.06 * t, 0.002 + 0.1 * t, 0.002, 0.12 if k == 3 else 0.002]
    y = np.concatenate([bed, intruders])
    n = len(y)
    particles.write_particles(case, round(t, 9), np.column_stack([np.full(n, 0.01), y]),
                              np.full(n, 1e-3), [0] * 100 + [1] * 4, ids=np.arange(n))
PY
dpmRiseTime "$workDir/written" -class 1 -fraction 0.99 0.5 > "$workDir/log.written" 2>&1 \
    || { cat "$workDir/log.written"; fail "dpmRiseTime on the written trajectories"; }
cat "$workDir/log.written"
check()
{
    py - "$@" <<'PY'
import sys
import numpy as np
from dpmfoam2d import tables
table, expected = sys.argv[1], np.array(eval(sys.argv[2]), float)
got = np.atleast_2d(np.loadtxt(table))
ok = got.shape == expected.shape and np.allclose(got, expected, atol=1e-9, equal_nan=True)
print(table, "ok" if ok else "FAILED", "\n got", got.tolist(), "\n expected", expected.tolist())
sys.exit(0 if ok else 1)
PY
}
out="$workDir/written/postProcessing/riseTime/0"
nan='float("nan")'
check "$out/riseTime.dat" "[[100, 1.7, 0.9], [101, 1.0, 0.5], [102, $nan, $nan], [103, 0.3, 0.3]]" \
    || fail "rise times per particle"
check "$out/riseOrder.dat" "[[1, 0.3, 0.3], [2, 1.0, 0.5], [3, 1.7, 0.9], [4, $nan, $nan]]" \
    || fail "rise times by rank"
dpmRiseTime "$workDir/written" -class 1 -start 0.2 > "$workDir/log.start" 2>&1 \
    || { cat "$workDir/log.start"; fail "dpmRiseTime -start 0.2"; }
check "$out/riseTime.dat" "[[100, 1.5], [101, 0.8], [102, $nan], [103, 0.1]]" \
    || fail "rise times counted from -start 0.2"

refused()
{
    local pattern="$1"; shift
    dpmRiseTime "$@" > "$workDir/log.refused" 2>&1 && fail "dpmRiseTime $* ran"
    grep -qE "$pattern" "$workDir/log.refused" || { cat "$workDir/log.refused"; fail "dpmRiseTime $*: no message '$pattern'"; }
    grep -q Traceback "$workDir/log.refused" && fail "dpmRiseTime $*: a traceback"
    echo "ok   refused: $(head -1 "$workDir/log.refused")"
}
refused "^dpmRiseTime: -fraction 1 is outside \(0, 1\)" "$workDir/written" -fraction 1
refused "^dpmRiseTime: -class intruder: not a class of .*particleProperties" "$workDir/written" -class intruder
refused "^dpmRiseTime: no case directory .*/missing" "$workDir/missing"
refused "^dpmRiseTime: .*: no particle of class 5" "$workDir/written" -class 5
# A class that is every particle: no bed to rise through
mkdir -p "$workDir/oneClass/system" && touch "$workDir/oneClass/system/controlDict"
py - "$workDir/oneClass" <<'PY' || fail "writing oneClass"
import sys
import numpy as np
from dpmfoam2d import particles
for t in (0, 0.1):
    particles.write_particles(sys.argv[1], t, np.column_stack([np.full(5, 0.01), 1e-3 * np.arange(1, 6)]),
                              np.full(5, 1e-3), [0] * 5)
PY
refused "^dpmRiseTime: .*/oneClass: every one of the 5 particles of .*/0.h5 is of class 0: no bed of other particles" "$workDir/oneClass"
# Where the tables cannot go: a file or a folder in their way
copyWritten() { rm -rf "$workDir/$1" && cp -r "$workDir/written" "$workDir/$1" && rm -rf "$workDir/$1/postProcessing"; }
copyWritten inTheWay && mkdir -p "$workDir/inTheWay/postProcessing" && touch "$workDir/inTheWay/postProcessing/riseTime"
refused "^dpmRiseTime: cannot write the tables into .*/inTheWay/postProcessing/riseTime/0: .*/inTheWay/postProcessing/riseTime is a file, not a folder" "$workDir/inTheWay" -class 1
copyWritten folderInTheWay && mkdir -p "$workDir/folderInTheWay/postProcessing/riseTime/0/riseTime.dat"
refused "^dpmRiseTime: cannot write .*/folderInTheWay/postProcessing/riseTime/0/riseTime.dat: a folder is in the way" "$workDir/folderInTheWay" -class 1
# A case it may not write into: root's runs it as nobody (root writes anywhere)
copyWritten readOnly && chmod a-w "$workDir/readOnly"
if [ "$(id -u)" = 0 ]
then
    setpriv --reuid=65534 --regid=65534 --clear-groups dpmRiseTime "$workDir/readOnly" -class 1 \
        > "$workDir/log.readOnly" 2>&1 && fail "dpmRiseTime ran in a read-only case"
else
    dpmRiseTime "$workDir/readOnly" -class 1 > "$workDir/log.readOnly" 2>&1 \
        && fail "dpmRiseTime ran in a read-only case"
fi
grep -q "^dpmRiseTime: cannot write the tables into .*/readOnly/postProcessing/riseTime/0: Permission denied" \
    "$workDir/log.readOnly" && ! grep -q Traceback "$workDir/log.readOnly" \
    || { cat "$workDir/log.readOnly"; fail "a read-only case: no one-line message naming it"; }
echo "ok   refused: $(head -1 "$workDir/log.readOnly")"
chmod u+w "$workDir/readOnly"
# A particle file of another run among the others: fewer particles, or the
# same number with other ids
for kind in fewer otherIds
do
    copyWritten $kind
    py - "$workDir/$kind" $kind <<'PY' || fail "writing $kind"
import sys
import numpy as np
from dpmfoam2d import particles
n, ids = (50, np.arange(50)) if sys.argv[2] == "fewer" else (104, np.arange(1000, 1104))
particles.write_particles(sys.argv[1], 1.05, np.column_stack([np.full(n, 0.01), np.linspace(0.001, 0.1, n)]),
                          np.full(n, 1e-3), [0] * (n - 4) + [1] * 4, ids=ids)
PY
    refused "^dpmRiseTime: .*/$kind/particles/1.05.h5: not the particles of the other files \((50 particles, 4 of class 1; .*/0.h5 has 104, 4 of them|other particle ids than .*/0.h5)\)" "$workDir/$kind" -class 1
done

makeCase "$workDir/column"
(cd "$workDir/column" && runSolver) || fail "the test column"
dpmRiseTime "$workDir/column" -class large > "$workDir/log.column" 2>&1 \
    || { cat "$workDir/log.column"; fail "dpmRiseTime on the test column"; }
cat "$workDir/log.column"
grep -q "^dpmRiseTime: large: [0-9]* of 130 risen" "$workDir/log.column" || fail "the class by its name"
rows=$(grep -vc '^#' "$workDir/column/postProcessing/riseTime/0/riseTime.dat")
[ "$rows" = 130 ] || fail "$rows rows for the 130 large particles"
pass "rise times of written trajectories to the file, from -start, by rank; a run's class by name; bad options refused"
