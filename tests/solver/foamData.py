# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Small helpers for the solver tests: OpenFOAM fields (the project's own
reader, dpmfoam2d.fields: ASCII or binary) and correlations."""

import glob
import os

import numpy as np

from dpmfoam2d.fields import internal_field  # noqa: F401  (used by the tests)


def wen_yu_umf(d, rho_p, rho_g, mu=1.75e-5, g=9.81):
    """Wen and Yu (1966) minimum fluidization velocity."""
    ar = d**3 * rho_g * (rho_p - rho_g) * g / mu**2
    re_mf = np.sqrt(33.7**2 + 0.0408 * ar) - 33.7
    return re_mf * mu / (rho_g * d)


def hoomans(porosity2d):
    """3D voidage from 2D porosity, Hoomans et al. (1996), exponent 3/2."""
    return 1 - 2 / np.sqrt(np.pi * np.sqrt(3)) * (1 - porosity2d) ** 1.5


def ergun_gradient(eps, d, us, rho, mu=1.75e-5):
    """Ergun (1952) pressure gradient of a fixed bed, Pa/m."""
    return (150 * (1 - eps)**2 * mu * us / (eps**3 * d**2)
            + 1.75 * (1 - eps) * rho * us**2 / (eps**3 * d))


def patch_mean(path, patch):
    """Mean of a scalar field's nonuniform value on a patch (ASCII field)."""
    import re
    text = open(path).read()
    m = re.search(patch + r"\s*\{[^}]*?value\s+nonuniform List<scalar>\s*\d+\s*\(([^)]*)\)", text)
    if m is None:
        raise ValueError(f"{path}: no nonuniform value on patch {patch}")
    return np.array(m.group(1).split(), dtype=float).mean()


def exchange_balance(case="."):
    """(writes, worst relative mismatch) of a case's exchange balance
    (the function object exchangeBalance's tables, every start time): at
    each write the force on the particles against the reaction the gas
    cells carry, the particles' area or volume against what the cells
    received, and their drag coefficients against the gas's implicit
    share."""
    worst, writes = 0.0, 0
    for path in sorted(glob.glob(os.path.join(case, "postProcessing", "exchangeBalance",
                                              "*", "exchangeBalance.dat"))):
        rows = np.loadtxt(path, ndmin=2)
        if not rows.size:
            continue
        # the relative excess computed at full precision, the amounts, and
        # the drag coefficients (none before the first step: 0 and 0)
        worst = max(worst, rows[:, 7].max())
        worst = max(worst, (np.abs(rows[:, 9] - rows[:, 8]) / rows[:, 8]).max())
        drag = rows[:, 10] > 0
        worst = max(worst, (np.abs(rows[drag, 11] - rows[drag, 10])
                            / rows[drag, 10]).max(initial=0.0))
        writes += len(rows)
    return writes, worst
