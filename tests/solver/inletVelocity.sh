#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The inlet velocity U0 from constant/gasProperties: U0 as given (m/s),
# U0byUmf x Umf or Umf + excessVelocity, where Umf is Wen and Yu's
# (1966) for the mixture: mass-weighted harmonic mean diameter of the test
# column's 600 small (1.5 mm) and 130 large (2.5 mm) particles, density
# 2525 kg/m3, gas density 1.204 x pressure, viscosity 1.75e-5 Pa s
# (computed here independently of the solver). Expected on the inlet patch
# after 0.01 s: U = (0 U0 0) within 1e-6 relative, at 8 bar with U0byUmf
# 1.25, with excessVelocity 0.3 m/s and with U0 0.6 m/s (the log then
# gives U0/Umf and U0 - Umf). Two of the entries, or none, stop the solver
# with a message naming the file, the three entries and those given.
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/template"
setEntry "$workDir/template/constant/gasProperties" operatingPressure 8
setEntry "$workDir/template/system/controlDict" endTime 0.01
setEntry "$workDir/template/system/controlDict" writePrecision 12

umf=$(py - "$testsDir/solver" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from foamData import wen_yu_umf
ms, ml = 600 * 1.5e-3 ** 3, 130 * 2.5e-3 ** 3      # masses (common factors cancel)
ws, wl = ms / (ms + ml), ml / (ms + ml)
d = 1 / (ws / 1.5e-3 + wl / 2.5e-3)
print("%.12g" % wen_yu_umf(d, 2525.0, 1.204 * 8))
PY
) || fail "Wen-Yu Umf"
echo "Wen-Yu Umf of the mixture at 8 bar: $umf m/s"

check()   # check <case> <expected U0>
{
    local inlet
    inlet=$(foamDictionary -entry boundaryField.inlet.value -value -precision 12 "$1/0.01/U") \
        || fail "no inlet value in $1/0.01/U"
    py - "$inlet" "$2" <<'PY' || fail "$1: inlet $inlet, expected U0 = $2"
import sys
v = [float(s) for s in sys.argv[1].replace("uniform", "").strip("() ").split()]
u0 = float(sys.argv[2])
print("inlet U %s, expected (0 %.6g 0)" % (v, u0))
assert v[0] == 0 and v[2] == 0 and abs(v[1] - u0) <= 1e-6 * u0
PY
}

cp -r "$workDir/template" "$workDir/ratio" && cd "$workDir/ratio" || fail "cd"
setEntry constant/gasProperties U0byUmf 1.25
runSolver
grep "U0/Umf" log.dpmFoam2D
check "$workDir/ratio" "$(py -c "print(1.25 * $umf)")"

cp -r "$workDir/template" "$workDir/excess" && cd "$workDir/excess" || fail "cd"
foamDictionary -entry U0byUmf -remove constant/gasProperties >/dev/null || fail "remove U0byUmf"
setEntry constant/gasProperties excessVelocity 0.3
runSolver
grep "U0/Umf" log.dpmFoam2D
grep -q "(set by U0 - Umf 0.3 m/s)" log.dpmFoam2D || fail "log does not say U0 was set by U0 - Umf"
check "$workDir/excess" "$(py -c "print($umf + 0.3)")"

cp -r "$workDir/template" "$workDir/velocity" && cd "$workDir/velocity" || fail "cd"
foamDictionary -entry U0byUmf -remove constant/gasProperties >/dev/null || fail "remove U0byUmf"
setEntry constant/gasProperties U0 0.6
runSolver
expected=$(py -c "print('U0/Umf %.5g, U0 - Umf %.5g m/s, U0 0.6 m/s' % (0.6 / $umf, 0.6 - $umf))")
grep "U0/Umf" log.dpmFoam2D
grep -q "U0/Umf [0-9.]*, U0 - Umf [0-9.]* m/s, U0 0.6 m/s at patch inlet (set by U0 0.6 m/s)" log.dpmFoam2D \
    || fail "log does not give U0/Umf and U0 - Umf for U0 0.6 m/s (expected about: $expected)"
py - "$(grep -m1 'U0/Umf' log.dpmFoam2D)" "$umf" <<'PY' || fail "the log's U0/Umf and U0 - Umf"
import re, sys
m = re.search(r"U0/Umf (\S+), U0 - Umf (\S+) m/s", sys.argv[1])
umf = float(sys.argv[2])
ratio, excess = float(m.group(1)), float(m.group(2))
print("U0/Umf %g (expected %g), U0 - Umf %g (expected %g)" % (ratio, 0.6 / umf, excess, 0.6 - umf))
assert abs(ratio / (0.6 / umf) - 1) < 1e-6 and abs(excess - (0.6 - umf)) < 1e-6
PY
check "$workDir/velocity" 0.6

for c in two three none
do
    cp -r "$workDir/template" "$workDir/$c" && cd "$workDir/$c" || fail "cd"
    case $c in
        two)   setEntry constant/gasProperties excessVelocity 0.3; given="U0byUmf and excessVelocity" ;;
        three) setEntry constant/gasProperties excessVelocity 0.3; setEntry constant/gasProperties U0 0.6
               given="U0, U0byUmf and excessVelocity" ;;
        none)  foamDictionary -entry U0byUmf -remove constant/gasProperties >/dev/null || fail "remove"
               given="none" ;;
    esac
    dpmFoam2D >log.dpmFoam2D 2>&1 && fail "$c: dpmFoam2D ran"
    grep -qE "gasProperties\"? needs exactly one of the entries 'U0' .*, 'U0byUmf' .* and 'excessVelocity' .*; it has $given" \
        log.dpmFoam2D || { tail -15 log.dpmFoam2D; fail "$c: no message naming the three entries and those given"; }
    echo "ok   $c: $(grep -m1 "needs exactly one" log.dpmFoam2D | sed 's/^ *//')"
done
pass "U0 as given, U0byUmf x Umf or Umf + excessVelocity, exactly one of them required"
