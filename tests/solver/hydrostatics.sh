#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# A settled bed held at rest (frozen) in a closed column (no distributor,
# no gas supply): the gas must stay at rest and its pressure hydrostatic,
# p = p_out - rho_g g y, so that p_rgh (the pressure less the gas's
# hydrostatic head) stays zero although the particles' weight, buoyancy and
# the gas's weight all act. Tolerances, round-off level against the
# column's hydrostatic head rho_g g H = 3.5 Pa and fluidizing velocities of
# order 1 m/s: |p_rgh| < 1e-6 rho_g g H and |U| < 1e-6 m/s after 0.1 s.
# In formulation A the gas carries no buoyancy reaction and no weight term
# (-eps_g grad p + rho eps_g g = -eps_g grad p_rgh): the same state.
# In the slab mode (voidageModel slab3D, the mesh as thick as the slab) the
# same holds with the spheres' volume fraction as the voidage.
#   hydrostatics.sh <workDir> [A|B] [discs2D | slab3D <depth> | spheres3D:<nz> <depth>]
#                                      (default B discs2D)
. "$(dirname "${BASH_SOURCE[0]}")/../smoke/testFunctions" "$@"
. "$testsDir/solver/testFunctions"

makeCase "$workDir/case"
cd "$workDir/case" || fail "cd"
setEntry constant/gasProperties inletPatch none
setEntry 0/U boundaryField.inlet "{ type noSlip; }"
setEntry constant/particleProperties frozen true
setFormulation "${2:-}"
setMomentum
setVoidageModel "${3:-}"
if [ "$voidageModel" != discs2D ]
then
    setDepth "${4:?$voidageModel needs the slab depth}"
fi
setEntry system/controlDict endTime 0.1
setEntry system/controlDict writeInterval 0.1
runSolver

py - <<PY || fail "hydrostatic gas"
import sys
sys.path.insert(0, "$testsDir/solver")
from foamData import internal_field
import numpy as np
head = 1.204 * 9.81 * 0.30
p = internal_field("0.1/p_rgh")
U = internal_field("0.1/U")
pmax = np.abs(p).max() if np.ndim(p) else abs(p)
umax = np.linalg.norm(U, axis=-1).max() if np.ndim(U) > 1 else np.linalg.norm(U)
print(f"max |p_rgh| {pmax:.3e} Pa (head {head:.2f} Pa), max |U| {umax:.3e} m/s")
sys.exit(0 if pmax < 1e-6 * head and umax < 1e-6 else 1)
PY
pass "gas at rest stays at rest and hydrostatic"
