"""Held-out references for the celt's steady spins: eigenvalues, every stability boundary, Lyapunov exponents.

Two derivations that share nothing with ``derivation/`` (the project's engine, emitter and Jacobian block):

1. **Newton-Euler, linearized numerically**: ``tests/rigid_reference.py`` (Kane & Levinson, Int. J. Non-Linear
   Mech. 17 (1982) 175; Garcia & Hubbard, Proc. R. Soc. Lond. A 418 (1988) 165), differentiated by eighth-order
   central differences at the upright spin ``n = e_z``, ``omega = Omega e_z``.
2. **The linearization by hand** (below, :func:`hand_block`): the same balance laws expanded to first order in the
   tilts ``(n_x, n_y)`` and tilt rates ``(omega_x, omega_y)``, with the radii of curvature at the rest point
   ``R1 = a^2/c``, ``R2 = b^2/c`` and the height ``l = c - h`` of the centre of mass above the contact (the
   classical small-tilt linearization of the rattleback, as in Garcia & Hubbard 1988 and Moffatt & Tokieda,
   Proc. R. Soc. Edinburgh 138A (2008) 361).

At the upright spin the tilt equations do not depend on ``n_z`` or ``omega_z`` to first order (the contact point
is homogeneous of degree 0 in ``n`` and every tilt rate vanishes at zero tilt for any spin), so the 4 x 4 tilt
block holds exactly the physical eigenvalues (the other two are the invariant ``|n| = 1`` and the family of spins).
The stability boundaries follow from the Routh-Hurwitz conditions on that block's characteristic polynomial
``s^4 + a1 s^3 + a2 s^2 + a3 s + a4`` (all roots in the open left half-plane iff ``a1 > 0``,
``a1 a2 - a3 > 0``, ``Delta3 = a3 (a1 a2 - a3) - a1^2 a4 > 0``, ``a4 > 0``; by Orlando's formula ``Delta3`` is,
up to sign, the product of the sums of pairs of roots, so it vanishes where a pair crosses the imaginary axis and
``a4`` where a real root does): no eigenvalue solver is used to locate them.
"""
from __future__ import annotations

import importlib

import numpy as np
import pytest
from scipy.optimize import brentq

import knifeedge as ke
import rigid_reference as ref

st = importlib.import_module("knifeedge.stability")

#: (preset, sigma): the parameter sets of scene ``celt_stability`` (undamped, and damped as in its settings)
SETS = (("kane_levinson_1982", 0.0), ("kane_levinson_1982", 1e-4), ("schoemer", 0.0), ("schoemer", 5e-3))
#: the tilt coordinates (n_x, n_y, omega_x, omega_y) among the reference's (n, omega)
TILT = [0, 1, 3, 4]
_CENTRAL8 = np.array([1 / 280, -4 / 105, 1 / 5, -4 / 5, 0.0, 4 / 5, -1 / 5, 4 / 105, -1 / 280])


def reference_params(m, p) -> np.ndarray:
    """``p`` of model ``m`` as the reference's parameter vector (``rigid_reference.NAMES``; the small-tilt celt has
    no ``I_xz``, ``I_yz``: zero)."""
    named = dict(zip(m.param_names, np.asarray(p, dtype=float)))
    return np.array([named.get(k, 0.0) for k in ref.NAMES])


def newton_euler_block(p, spin: float, step: float = 1e-4) -> np.ndarray:
    """The tilt block of the Newton-Euler reference's Jacobian at the upright spin (eighth-order differences)."""
    args = ref.unpack(p)
    s0 = np.array([0.0, 0.0, 1.0, 0.0, 0.0, spin])
    A = np.empty((4, 4))
    for j, c in enumerate(TILT):
        acc = np.zeros(6)
        for k, w in enumerate(_CENTRAL8):
            if w:
                s = s0.copy()
                s[c] += (k - 4) * step
                acc += w * ref._rhs(s, *args)
        A[:, j] = acc[TILT] / step
    return A


def hand_block(p, spin: float) -> np.ndarray:
    """The linearization at the upright spin ``W``, by hand, of (body axes, ``n`` the upward vertical)::

        dn/dt = n x omega,   v = -omega x r,   F = m (dv/dt + omega x v) + m g n,
        I domega/dt + omega x I omega = r x F - sigma omega,

    to first order in ``x = (n1, n2, w1, w2)``: ``r = (-R1 n1, -R2 n2, -l)``, ``v = (l w2 - R2 W n2,
    -l w1 + R1 W n1, 0)``, the spin decaying at ``dW/dt = -sigma W / I_zz`` (its own equation at zeroth order)."""
    a, b, c, h, m, g, ixx, iyy, izz, ixy, ixz, iyz, sigma = (float(v) for v in p)
    assert ixz == 0 and iyz == 0  # otherwise the upright spin is not a steady motion
    r1, r2, l, w = a * a / c, b * b / c, c - h, spin
    wdot = -sigma * w / izz
    e = np.eye(4)
    dn1, dn2 = w * e[1] - e[3], e[2] - w * e[0]
    v1, v2 = l * e[3] - r2 * w * e[1], -l * e[2] + r1 * w * e[0]
    # torque r x F (x, y) = (l F2 - R2 m g n2, -l F1 + R1 m g n1); dv/dt = d/dt of v above with dW/dt = wdot;
    # the terms in d(omega)/dt (-m l^2 domega/dt) are moved to the left: the mass matrix M below
    f1 = (w * (ixy * e[2] + iyy * e[3]) - w * izz * e[3]
          + m * l * (r1 * w * dn1 + r1 * wdot * e[0] + w * v1 + g * e[1]) - r2 * m * g * e[1] - sigma * e[2])
    f2 = (-w * (ixx * e[2] + ixy * e[3]) + w * izz * e[2]
          + m * l * (r2 * w * dn2 + r2 * wdot * e[1] + w * v2 - g * e[0]) + r1 * m * g * e[0] - sigma * e[3])
    M = np.array([[ixx + m * l * l, ixy], [ixy, iyy + m * l * l]])
    return np.vstack([dn1, dn2, np.linalg.solve(M, np.vstack([f1, f2]))])


def characteristic(A: np.ndarray) -> np.ndarray:
    """``(1, a1, ..., an)`` of ``det(s I - A)`` by the Faddeev-LeVerrier recursion (no eigenvalues)."""
    n = A.shape[0]
    coeffs, Mk = [1.0], np.zeros_like(A)
    for k in range(1, n + 1):
        Mk = A @ Mk + coeffs[-1] * np.eye(n)
        coeffs.append(-np.trace(A @ Mk) / k)
    return np.array(coeffs)


def hurwitz(A: np.ndarray) -> tuple:
    """``(Delta3, a4, asymptotically stable)`` of a 4 x 4 block."""
    _, a1, a2, a3, a4 = characteristic(A)
    d3 = a3 * (a1 * a2 - a3) - a1 * a1 * a4
    return d3, a4, bool(a1 > 0 and a1 * a2 - a3 > 0 and d3 > 0 and a4 > 0)


def hurwitz_boundaries(p, lo: float, hi: float, n_grid: int = 2001) -> list:
    """Every spin in (lo, hi) where the Routh-Hurwitz verdict changes: the zeros of ``Delta3`` or ``a4`` (Brent)
    across which the verdict differs."""
    grid = np.linspace(lo, hi, n_grid)
    values = np.array([hurwitz(hand_block(p, w))[:2] for w in grid])
    found = []
    for i in range(n_grid - 1):
        for col in (0, 1):
            if values[i, col] == 0 or np.sign(values[i, col]) == np.sign(values[i + 1, col]):
                continue
            root = brentq(lambda w: hurwitz(hand_block(p, w))[col], grid[i], grid[i + 1], xtol=1e-15, rtol=1e-15)
            delta = 1e-7 * max(1.0, abs(root))
            if hurwitz(hand_block(p, root - delta))[2] != hurwitz(hand_block(p, root + delta))[2]:
                found.append(root)
    return sorted(found)


def _matched(found: np.ndarray, expected: np.ndarray) -> np.ndarray:
    """``found`` reordered to pair each expected eigenvalue with its nearest (each used once)."""
    left, out = list(found), []
    for e in expected:
        j = int(np.argmin([abs(f - e) for f in left]))
        out.append(left.pop(j))
    return np.array(out)


SPINS = (-7.0, -3.0, -0.5, 0.5, 2.0, 7.0, 30.0)


@pytest.mark.parametrize("preset,sigma", SETS)
def test_the_two_held_out_linearizations_agree(preset, sigma):
    m = ke.load("celt", "reduced")
    p = reference_params(m, m.preset(preset, sigma=sigma))
    for w in SPINS:
        hand, numeric = hand_block(p, w), newton_euler_block(p, w)
        assert np.abs(numeric - hand).max() <= 1e-9 * np.abs(hand).max()


def _steady_spin_eigenvalues(fidelity):
    m = ke.load("celt", fidelity)
    for preset, sigma in SETS:
        p = m.preset(preset, sigma=sigma)
        table = ke.stability(m, p, "steady_spin", SPINS)
        p = reference_params(m, p)
        for w, found in zip(SPINS, table.eigenvalues):
            expected = np.linalg.eigvals(hand_block(p, w))
            scale = np.abs(expected).max()
            assert np.abs(_matched(found, expected) - expected).max() <= 1e-8 * scale, (preset, sigma, w)
            expected_ne = np.linalg.eigvals(newton_euler_block(p, w))
            assert np.abs(_matched(found, expected_ne) - expected_ne).max() <= 1e-8 * scale, (preset, sigma, w)


def test_small_tilt_celt_steady_spin_eigenvalues_are_the_held_out_ones():
    _steady_spin_eigenvalues("reduced")


@pytest.mark.slow  # the full celt's Jacobian compiles in 10-20 s cold
def test_full_celt_steady_spin_eigenvalues_are_the_held_out_ones():
    _steady_spin_eigenvalues("full")


#: how many boundaries each set has in (-100, 100) rad/s
COUNTS = {("kane_levinson_1982", 0.0): 0, ("kane_levinson_1982", 1e-4): 2, ("schoemer", 0.0): 1, ("schoemer", 5e-3): 1}


def _boundaries(fidelity):
    m = ke.load("celt", fidelity)
    for preset, sigma in SETS:
        p = m.preset(preset, sigma=sigma)
        expected = hurwitz_boundaries(reference_params(m, p), -100.0, 100.0)
        found = ke.stability_boundaries(m, p, "steady_spin", (-100.0, 100.0))
        # Routh-Hurwitz finds: KL undamped none (unstable at every spin), KL sigma 1e-4 -3.91224 and 0.0694699,
        # Schoemer undamped 1.80083901188, Schoemer sigma 5e-3 -0.129932 rad/s
        assert len(found) == len(expected) == COUNTS[preset, sigma], (preset, sigma, found, expected)
        np.testing.assert_allclose(found, expected, rtol=1e-8, atol=0, err_msg=f"{preset}, sigma = {sigma}")


def test_small_tilt_celt_stability_boundaries_are_routh_hurwitzs():
    _boundaries("reduced")


@pytest.mark.slow  # the full celt's Jacobian
def test_full_celt_stability_boundaries_are_routh_hurwitzs():
    _boundaries("full")


# slow tier: 4000 s of the celt's variational equations (~3 s of CPU beyond the loop's compile); the default tier
# checks the loop (test_lyapunov) and these held-out eigenvalues (test_small_tilt_celt_steady_spin_eigenvalues...)
@pytest.mark.slow
@pytest.mark.parametrize("steps", [{"h": 0.05}, {"rtol": 1e-8}], ids=["RK4", "DP54"])
@pytest.mark.xdist_group("lyapunov")  # the worker that compiles the Benettin loop for test_lyapunov
def test_lyapunov_exponents_at_an_asymptotically_stable_steady_spin_are_the_held_out_real_parts(steps):
    """At an asymptotically stable equilibrium of the physical flow every tangent vector ends up in the linearized
    flow's eigenspaces, so the Lyapunov exponents are the real parts of the eigenvalues (each twice for a complex
    pair), plus 0 along the family of spins (Benettin et al., Meccanica 15 (1980) 9; Oseledets' theorem for a
    constant linear flow). The undamped Schoemer celt at 5 rad/s is such a spin (energy conserved, phase volume
    not: Borisov & Mamaev's "mixed dynamics"); the real parts are the held-out block's.  With step control the
    tangent vectors' errors are controlled too: at an equilibrium the state's alone would let the step outgrow the
    tangent dynamics."""
    m = ke.load("celt", "reduced")
    p = m.preset("schoemer", sigma=0.0)
    real = np.linalg.eigvals(hand_block(reference_params(m, p), 5.0)).real
    expected = np.sort(np.concatenate([real, [0.0]]))[::-1]
    assert expected[1] < 0  # asymptotically stable in every physical direction
    res = ke.lyapunov(m, st.steady_state(m, p, "steady_spin", 5.0), p, 4000.0, tau=1.0, **steps)
    # the finite-time estimates approach their limits like (log of the transient's growth) / T
    np.testing.assert_allclose(res.exponents, expected, rtol=0, atol=2e-3)
