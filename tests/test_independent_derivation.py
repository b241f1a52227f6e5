"""The generated ``full`` right-hand sides against an independent derivation.

The independent derivation uses ``sympy.physics.mechanics.LagrangesMethod``
with the paper's Lagrangians and non-holonomic constraints (section II:
vinculo1, vinculo2; section III: Const22, Const23) written here from the
paper, in dynamicsymbols, at a general pose (phi, x, y not zero), and solves
its full mass matrix (accelerations and multipliers) numerically.  It shares
no code with ``derivation/``.
"""
import numpy as np
import pytest
import sympy as sp
from sympy.physics.mechanics import LagrangesMethod, dynamicsymbols

import knifeedge as ke

g, ell, L, D, alpha = sp.symbols("g ell L D alpha")
t = dynamicsymbols._t


def _single():
    x, y, th, ph = dynamicsymbols("x y theta phi")
    xd, yd, thd, phd = (sp.diff(c, t) for c in (x, y, th, ph))
    v = sp.Matrix([-sp.sin(ph), sp.cos(ph)])
    u = sp.Matrix([sp.cos(ph), sp.sin(ph)])
    X = sp.Matrix([xd, yd])
    lag = (X.dot(X) + ell**2 * thd**2 + L**2 * phd**2 + 2 * ell * thd * X.dot(v)) / 2 - g * ell * th**2 / 2
    cons = [u.dot(X), X.dot(v) + D * th * phd]
    return [x, y, th, ph], lag, cons, [g, ell, L, D], (th, thd, phd)


def _two():
    x, y, t1, t2, ph = dynamicsymbols("x y theta1 theta2 phi")
    xd, yd, t1d, t2d, phd = (sp.diff(c, t) for c in (x, y, t1, t2, ph))
    v = sp.Matrix([-sp.sin(ph), sp.cos(ph)])
    u = sp.Matrix([sp.cos(ph), sp.sin(ph)])
    ua = sp.Matrix([sp.cos(ph + alpha), sp.sin(ph + alpha)])
    va = sp.Matrix([-sp.sin(ph + alpha), sp.cos(ph + alpha)])
    X = sp.Matrix([xd, yd])
    lag = (X.dot(X) + (L**2 + ell**2) * t2d**2 + ell**2 * t1d**2 + L**2 * phd**2
           + 2 * ell * X.dot(t1d * v - t2d * u)) / 2 - g * ell * (t1**2 + t2**2) / 2
    th_a = t2 * sp.cos(alpha) - t1 * sp.sin(alpha)
    cons = [X.dot(ua), D * th_a * phd + X.dot(va)]
    return [x, y, t1, t2, ph], lag, cons, [g, ell, L, D, alpha], (t1, t2, t1d, t2d, phd)


@pytest.mark.parametrize("name,build", [("single_mode", _single), ("two_mode", _two)])
def test_full_rhs_and_multipliers_match_lagranges_method(name, build):
    qs, lag, cons, params, state_syms = build()
    lm = LagrangesMethod(lag, qs, nonhol_coneqs=cons)
    lm.form_lagranges_equations()
    MM, F = lm.mass_matrix_full, lm.forcing_full
    n = len(qs)
    qd = [sp.diff(q, t) for q in qs]
    syms = sp.symbols(f"q0:{n}"), sp.symbols(f"u0:{n}")
    rep = dict(zip(qd, syms[1])) | dict(zip(qs, syms[0]))
    MM, F = MM.subs(rep), F.subs(rep)
    f_num = sp.lambdify([syms[0], syms[1], params], [MM, F], "numpy")

    m = ke.load(name, fidelity="full")
    rng = np.random.default_rng(2023)
    worst = worst_lam = 0.0
    for _ in range(20):
        pv = rng.uniform(0.3, 2.0, len(params))
        if name == "two_mode":
            pv[-1] = rng.uniform(-np.pi, np.pi)  # chiral angle: any finite value
        q = rng.uniform(-1, 1, n)  # general pose x, y, phi and finite tilts
        # independent speeds at random; dependent ones from the constraints
        ind = rng.uniform(-1, 1, n - 2)
        u = np.zeros(n)
        u[2:] = ind
        A = np.array(sp.lambdify([syms[0], syms[1], params],
                                 sp.Matrix([c.subs(rep) for c in cons]).jacobian(syms[1]))(q, u, pv), dtype=float)
        u[:2] = np.linalg.solve(A[:, :2], -A[:, 2:] @ ind)
        MMv, Fv = (np.array(a, dtype=float) for a in f_num(q, u, pv))
        sol = np.linalg.solve(MMv, Fv.ravel())
        qdd = sol[n:2 * n]
        # generated state: tilts, tilt rates, spin rate
        tilts = q[2:-1]
        y = np.concatenate([tilts, u[2:-1], [u[-1]]])
        dy = m.rhs(0.0, y, pv)
        expect = np.concatenate([u[2:-1], qdd[2:-1], [qdd[-1]]])
        rel = np.max(np.abs(dy - expect)) / np.max(np.abs(expect))
        # multipliers (contact forces per unit mass), same constraint rows and sign convention
        lam = sol[2 * n:]
        rel_lam = np.max(np.abs(m.multipliers(y, pv) - lam)) / np.max(np.abs(lam))
        worst = max(worst, rel)
        worst_lam = max(worst_lam, rel_lam)
    assert worst < 1e-10, f"{name}: generated full rhs differs from LagrangesMethod by {worst:.2e} (relative)"
    assert worst_lam < 1e-10, f"{name}: generated multipliers differ from LagrangesMethod by {worst_lam:.2e}"
