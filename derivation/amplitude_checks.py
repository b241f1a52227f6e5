"""Checks of the amplitude-level claims of the paper, against the machine-averaged slow flows.

Registered in :data:`derivation.verify._CHECKS` for the entries of
:mod:`derivation.published` whose ``check`` is

- ``"invariant"``: ``lhs = rhs`` names a conserved quantity (``lhs``) and its
  value; passes when ``lhs`` is conserved by the averaged flow and is a
  positive-definite quadratic form (level sets are ellipses);
- ``"stability"``: ``lhs = rhs`` is the linearized tilt equation
  ``d(A)/dt = lambda A`` at the equilibria ``A = 0``; passes when ``rhs``
  equals the derived linearization;
- ``"reversal"``: ``lhs = rhs`` is the dimensionless reversal interval
  ``t_R D phi_dot0/ell`` of the two-mode model with a background ``theta0``
  on the inactive mode (``theta_max`` stands for ``phi_dot0 L/sqrt(g ell)``,
  the largest tilt amplitude); passes when ``rhs`` equals the leading asymptotics of
  the averaged flow (``docs/amplitude.md``), for ``0 < alpha < pi/2`` and tilts
  negligible against the spin (``E = phi_dot0^2``).
"""
from __future__ import annotations

import sympy as sp

from . import averaging, truncation
from .engine import ReducedSystem
from .evidence import Evidence

_CACHE: dict = {}


def amplitude_system(system: ReducedSystem) -> averaging.AmplitudeSystem:
    """The averaged slow flow of a ``full`` system (truncated, then averaged); cached per model."""
    name = system.spec.name
    if name not in _CACHE:
        _CACHE[name] = averaging.average(truncation.reduced(system))
    return _CACHE[name]


def _as_published(amp: averaging.AmplitudeSystem) -> dict:
    from . import published as pub

    if len(amp.amplitudes) != 1:
        return {}
    return {amp.amplitudes[0]: pub.A_theta, amp.spin_amplitudes[0]: pub.A_phi}


def published_flow(system: ReducedSystem) -> dict:
    """The single-mode slow flow in the paper's symbols: ``{A_theta_dot: ..., A_phi_dot: ...}``."""
    from . import published as pub

    amp = amplitude_system(system)
    rename = _as_published(amp)
    dots = {pub.A_theta: pub.A_theta_dot, pub.A_phi: pub.A_phi_dot}
    return {dots[rename[s]]: r.subs(rename, simultaneous=True) for s, r in zip(amp.state, amp.rates)}


def _invariant(lhs, rhs, system):
    amp = amplitude_system(system)
    rename = _as_published(amp)
    state = [rename.get(s, s) for s in amp.state]
    rates = [r.subs(rename, simultaneous=True) for r in amp.rates]
    drift = sp.simplify(sum(sp.diff(lhs, s) * r for s, r in zip(state, rates)))
    H = sp.hessian(lhs, state)
    definite = all(H[i, j] == 0 for i in range(len(state)) for j in range(len(state)) if i != j) and all(
        H[i, i].is_positive for i in range(len(state)))
    passed = drift == 0 and definite
    return Evidence(passed, None, f"d/dt along the slow flow = {drift}; positive-definite quadratic form: {definite}")


def _stability(lhs, rhs, system):
    amp = amplitude_system(system)
    rename = _as_published(amp)
    A, S = (rename[s] for s in amp.state)
    rates = [r.subs(rename, simultaneous=True) for r in amp.rates]
    lam = sp.diff(rates[0], A).subs(A, 0)
    claimed = sp.diff(rhs, A).subs(A, 0)
    r = sp.simplify(lam - claimed)
    sign = "unstable" if (lam / S).is_positive else "stable"
    return Evidence(r == 0, None, f"derived eigenvalue {lam}: equilibria with A_phi > 0 are {sign}")


def reversal_asymptotics(system: ReducedSystem) -> sp.Expr:
    """``t_R D phi_dot0/ell`` of the two-mode slow flow with a background ``theta0`` on the fast mode.

    ``T = (1/sqrt(E)) [ln(2 A1_max/theta0)/|c1| + ln 2/c2]`` with
    ``E = phi_dot0^2``, ``A1_max = sqrt(E/w1)``, ``w_i = -k_i/c_i``.
    """
    from . import published as pub

    amp = amplitude_system(system)
    c1, c2 = amp.growth
    drive = sp.Poly(sp.expand(amp.rates[-1]), *amp.amplitudes)
    k1 = drive.coeff_monomial(amp.amplitudes[0] ** 2)
    w1 = sp.simplify(-k1 / c1)
    a_max = pub.phi_dot0 / sp.sqrt(w1)
    T = (sp.log(2 * a_max / pub.theta0) / (-c1) + sp.log(2) / c2) / pub.phi_dot0
    d_, ell_ = system.spec.params[3], system.spec.params[1]
    return sp.simplify(T * d_ * pub.phi_dot0 / ell_)


def _reversal(lhs, rhs, system):
    from . import published as pub

    g_, ell_, L_ = system.spec.params[0], system.spec.params[1], system.spec.params[2]
    derived = reversal_asymptotics(system)
    rhs = rhs.subs(pub.theta_max, pub.phi_dot0 * L_ / sp.sqrt(g_ * ell_))
    r = sp.simplify(sp.expand_log(derived - rhs, force=True))
    return Evidence(r == 0, None, f"derived t_R D phi_dot0/ell = {derived}; difference {r}")


CHECKS = {"invariant": _invariant, "stability": _stability, "reversal": _reversal}
