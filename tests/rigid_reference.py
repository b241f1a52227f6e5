"""An independent formulation of the rolling rattleback (Newton--Euler in body axes, numpy only).

Written directly from the textbook equations, not from :mod:`derivation.rigid`
(Kane & Levinson, Int. J. Non-Linear Mech. 17 (1982) 175; Garcia & Hubbard,
Proc. R. Soc. Lond. A 418 (1988) 165; Moffatt & Tokieda, Proc. R. Soc.
Edinburgh 138A (2008) 361).  In body axes with ``n`` the upward vertical,
``r`` the contact point relative to the centre of mass and ``F`` the contact
force::

    m (dv/dt + omega x v) = F - m g n,     v = -omega x r   (rolling)
    I domega/dt + omega x (I omega) = r x F - sigma omega
    dn/dt = n x omega

For an ellipsoid ``x^2/a^2 + y^2/b^2 + (z - h)^2/c^2 = 1`` the lowest point
is ``r = (0, 0, h) - E n / sqrt(n.E n)`` with ``E = diag(a^2, b^2, c^2)``.
"""
from __future__ import annotations

import numpy as np
from numba import njit

NAMES = ("a", "b", "c", "h", "m", "g", "I_xx", "I_yy", "I_zz", "I_xy", "I_xz", "I_yz", "sigma")


def unpack(p):
    a, b, c, h, m, g, ixx, iyy, izz, ixy, ixz, iyz, sigma = (float(v) for v in p)
    inertia = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
    return np.array([a * a, b * b, c * c]), h, m, g, inertia, sigma


# numba compiles these plain loops in about a second; with ``@``, ``np.outer`` and ``np.linalg.solve`` (BLAS
# and LAPACK bindings) it took 12 s
@njit(cache=True)
def cross(u, v):
    return np.array([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]])


@njit(cache=True)
def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


@njit(cache=True)
def matvec(a, v):
    return np.array([dot(a[0], v), dot(a[1], v), dot(a[2], v)])


@njit(cache=True)
def contact(n, e2, h):
    """Contact point r(n) and its derivative matrix dr/dn."""
    en = e2 * n
    d = np.sqrt(dot(n, en))
    r = np.array([0.0, 0.0, h]) - en / d
    drdn = np.empty((3, 3))
    for i in range(3):
        for j in range(3):
            drdn[i, j] = en[i] * en[j] / d**3 - (e2[i] / d if i == j else 0.0)
    return r, drdn


@njit(cache=True)
def solve3(a, b):
    """``x`` with ``a x = b`` for a 3 x 3 ``a`` by Cramer's rule (the matrix here, inertia plus
    ``m (r.r 1 - r r^T)``, is symmetric positive definite and well conditioned)."""
    c0, c1, c2 = a[:, 0].copy(), a[:, 1].copy(), a[:, 2].copy()
    k = cross(c1, c2)
    det = dot(c0, k)
    return np.array([dot(b, k), dot(c0, cross(b, c2)), dot(c0, cross(c1, b))]) / det


@njit(cache=True)
def _rhs(s, e2, h, m, g, inertia, sigma):
    n, w = s[:3].copy(), s[3:6].copy()
    r, drdn = contact(n, e2, h)
    n_dot = cross(n, w)
    r_dot = matvec(drdn, n_dot)
    v = -cross(w, r)
    lhs = inertia.copy()
    rr = dot(r, r)
    for i in range(3):
        for j in range(3):
            lhs[i, j] += m * ((rr if i == j else 0.0) - r[i] * r[j])
    rhs_ = -cross(w, matvec(inertia, w)) + m * cross(r, -cross(w, r_dot) + cross(w, v) + g * n) - sigma * w
    w_dot = solve3(lhs, rhs_)
    return np.concatenate((n_dot, w_dot))


def rhs(t, s, p):
    """d/dt of (n, omega) (6 components)."""
    return _rhs(np.asarray(s, dtype=float), *unpack(p))


def energy(s, p):
    e2, h, m, g, inertia, _ = unpack(p)
    n, w = s[:3], s[3:6]
    r, _ = contact(n, e2, h)
    v = -np.cross(w, r)
    return 0.5 * m * v @ v + 0.5 * w @ inertia @ w + m * g * (-(r @ n))


def integrate(s0, t_span, p, rtol=1e-12, atol=1e-14, **kw):
    """SciPy DOP853 run of the reference with the zero crossings of omega . n as events."""
    from scipy.integrate import solve_ivp

    def spin(t, s, p=p):
        return s[:3] @ s[3:6]

    args = unpack(p)

    def fun(t, s):
        return _rhs(s, *args)

    return solve_ivp(fun, t_span, np.asarray(s0[:6], float), method="DOP853", rtol=rtol, atol=atol,
                     events=spin, dense_output=True, **kw)
