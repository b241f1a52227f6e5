"""What a rigid body must satisfy to exist: one rule, for the front end (presets, defaults) and for every parameter
set a rigid model is given at run time.

A rigid body has a positive mass, rolls under a positive gravity, is damped by a nonnegative ``sigma``; its
inertia tensor about the centre of mass is positive semi-definite and its principal moments obey the triangle
inequality ``I1 + I2 >= I3`` (``I1 + I2 - I3 = 2 * sum m z^2`` in principal axes; a zero moment only for mass on
a line); its centre of mass is above the table at rest (unless it hangs below an edge it balances on).
"""
from __future__ import annotations

import math

import numpy as np


def problems(mass: float, gravity: float, sigma: float, inertia, height: float | None) -> list:
    """Why these numbers describe no rigid body (empty: they describe one), as sentences.

    ``inertia``: the 3x3 tensor about the centre of mass (any nested sequence); ``height``: of the centre of mass
    above the table at the rest orientation (``None``: not checked, a body that hangs).
    """
    out = []
    for what, v, sign in (("mass", mass, "positive"), ("gravity", gravity, "positive"),
                          ("sigma", sigma, "nonnegative")):
        if not (v > 0 if sign == "positive" else v >= 0):
            out.append(f"`{what}` must be {sign}, got {v:g}")
    m = [[float(x) for x in row] for row in inertia]
    if not all(map(math.isfinite, m[0] + m[1] + m[2])):
        return out + ["the inertia tensor must be finite"]
    half = (m[0][0] + m[1][1] + m[2][2]) / 2
    if not _semidefinite(m):
        out.append(f"the inertia tensor must be positive definite; its principal moments are {_moments(m)}")
    elif not _semidefinite([[(half if i == j else 0.0) - m[i][j] for j in range(3)] for i in range(3)]):
        out.append(f"the principal moments of the inertia tensor ({_moments(m)}) break the triangle inequality "
                   f"I1 + I2 >= I3: no mass distribution has them")
    if height is not None and not (math.isfinite(height) and height > 0):
        out.append(f"the centre of mass must be above the table at rest; it is {-height:g} below it")
    return out


def _semidefinite(m) -> bool:
    """A symmetric 3x3 matrix is positive semi-definite: all its principal minors are >= 0 (to round-off)."""
    scale = max(abs(x) for row in m for x in row) or 1.0
    tol = 1e-9 * scale
    minors2 = (m[0][0] * m[1][1] - m[0][1] * m[1][0], m[0][0] * m[2][2] - m[0][2] * m[2][0],
               m[1][1] * m[2][2] - m[1][2] * m[2][1])
    det = (m[0][0] * minors2[2] - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
           + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    return (min(m[0][0], m[1][1], m[2][2]) >= -tol and min(minors2) >= -tol * scale
            and det >= -tol * scale * scale)


def _moments(m) -> str:
    return ", ".join(f"{x:.6g}" for x in np.linalg.eigvalsh(np.array(m)))
