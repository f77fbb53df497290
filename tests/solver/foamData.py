"""Small readers for the solver tests: OpenFOAM ASCII fields and the
particle HDF5 files (layout in src/dpmCoupling/particleWriter)."""
import re
import numpy as np


def internal_field(path):
    """Values of a volScalarField/volVectorField written in ASCII."""
    text = open(path).read()
    m = re.search(r"internalField\s+uniform\s+([^;]+);", text)
    if m:
        return float(m.group(1)) if "(" not in m.group(1) else \
            np.array(m.group(1).strip("() ").split(), float)
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", text)
    kind, n = m.group(1), int(m.group(2))
    body = text[m.end():]
    if kind == "scalar":
        return np.array(body.split(None, n)[:n], float)
    rows = re.findall(r"\(([^()]*)\)", body)[:n]
    return np.array([r.split() for r in rows], float)


def wen_yu_umf(d, rho_p, rho_g, mu=1.75e-5, g=9.81):
    """Wen and Yu (1966) minimum fluidization velocity."""
    ar = d**3 * rho_g * (rho_p - rho_g) * g / mu**2
    re_mf = np.sqrt(33.7**2 + 0.0408 * ar) - 33.7
    return re_mf * mu / (rho_g * d)


def hoomans(porosity2d):
    """3D voidage from 2D porosity, Hoomans et al. (1996), exponent 3/2."""
    return 1 - 2 / np.sqrt(np.pi * np.sqrt(3)) * (1 - porosity2d) ** 1.5
