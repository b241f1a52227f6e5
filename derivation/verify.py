"""Re-derive the verdict of every published equation from the derivation.

:func:`evaluate` compares one equation (as printed, or its correction) with
the derived ``full`` system and returns an :class:`Evidence`; the test suite
asserts that every ``agrees`` entry passes, that every ``erratum`` entry
fails as printed and passes once corrected.
"""
from __future__ import annotations

import sympy as sp

from . import published as pub
from .amplitude_checks import CHECKS as AMPLITUDE_CHECKS
from .amplitude_checks import published_flow
from .dimensions import check_equation
from .engine import ReducedSystem
from .evidence import Evidence
from .models import MODELS, phi
from .rigid_knife_edge import CHECKS as RIGID_CHECKS
from .truncation import eps, small_scaling

__all__ = ["Evidence", "evaluate", "all_evidence", "solution_substitutions", "is_zero", "tilt_order"]
#: the paper's multiplier symbols, in the order of each model's constraints
_MULTIPLIER_SYMBOLS = (pub.lambda1, pub.lambda2)


def solution_substitutions(system: ReducedSystem) -> dict:
    """Accelerations, multipliers and pose velocities/accelerations on the full equations, at a general pose.

    Every pose coordinate whose velocity is not a state (the bar's ``x, y``)
    gets its velocity from the pose rates and its acceleration as their time
    derivative along the flow; the multipliers become the paper's
    ``lambda_k = M * multiplier_k``.
    """
    spec = system.spec
    sub = dict(zip(system.accelerations, system.explicit))
    rates = dict(zip(system.state, system.state_rhs()))
    rates.update({q: spec.velocity_of(q) for q in spec.pose if spec.velocity_of(q) in system.state})
    for q in spec.pose:
        if spec.velocity_of(q) in system.state:
            continue
        v = system.pose_rates[q]
        sub[spec.velocity_of(q)] = v
        sub[spec.acceleration_of(q)] = sum((sp.diff(v, s) * r for s, r in rates.items()), sp.S.Zero)
    for symbol, lam in zip(_MULTIPLIER_SYMBOLS, system.multipliers):
        sub[symbol] = pub.M * lam
    return sub


_SA, _CA, _SP, _CP = sp.symbols("s_alpha c_alpha s_phi c_phi", real=True)
_UNIT_CIRCLES = (_SA**2 + _CA**2 - 1, _SP**2 + _CP**2 - 1)


def is_zero(e: sp.Expr, system: ReducedSystem | None = None) -> bool:
    """Exact zero test of a rational function of the state, the parameters and sin/cos of alpha, phi.

    Sines and cosines become polynomial variables; the numerator is reduced
    modulo ``s^2 + c^2 - 1`` (a Groebner basis of a prime ideal), so the
    remainder is zero exactly when the expression vanishes identically.
    """
    from .models import alpha

    e = sp.expand_trig(e).subs({sp.sin(alpha): _SA, sp.cos(alpha): _CA, sp.sin(phi): _SP, sp.cos(phi): _CP})
    num = sp.expand(sp.numer(sp.together(e)))
    if num == 0:
        return True
    gens = sorted(num.free_symbols | {_SA, _CA, _SP, _CP}, key=lambda s: (s not in (_SA, _SP), s.name))
    _, rem = sp.reduced(num, list(_UNIT_CIRCLES), *gens, order="lex")
    return rem == 0


def tilt_order(e: sp.Expr, system: ReducedSystem, max_order: int = 5) -> int | None:
    """Lowest power of the tilt scale in ``e`` (``None`` if zero to ``max_order``)."""
    d = e.subs(small_scaling(system.spec), simultaneous=True)
    for k in range(max_order + 1):
        if not is_zero(d.subs(eps, 0)):
            return k
        d = sp.diff(d, eps)
    return None


def _on_solution(e: sp.Expr, system: ReducedSystem) -> sp.Expr:
    return e.subs(solution_substitutions(system), simultaneous=True)


def _constraint(lhs, rhs, system) -> Evidence:
    spec = system.spec
    expr = sp.expand(lhs - rhs)
    for c in spec.constraints:
        if sp.simplify(sp.expand_trig(expr - c)) == 0:
            return Evidence(True, None, "identical to the model's constraint")
    return Evidence(False, None, "matches none of the model's constraints")


def _exact(lhs, rhs, system) -> Evidence:
    r = _on_solution(lhs - rhs, system)
    if is_zero(r, system):
        return Evidence(True, None, "lhs - rhs vanishes identically on the full equations")
    k = tilt_order(r, system)
    return Evidence(False, None, f"lhs - rhs on the full equations is nonzero, of order theta^{k}")


def _order(lhs, rhs, system) -> Evidence:
    own = tilt_order(_on_solution(lhs, system), system)
    res = tilt_order(_on_solution(lhs - rhs, system), system)
    passed = res is None or (own is not None and res > own)
    return Evidence(passed, None, f"equation is O(theta^{own}); residual on the full equations is "
                                  f"{'zero' if res is None else f'O(theta^{res})'}")


def _amplitude(lhs, rhs, system) -> Evidence:
    """Compare with the slow flow that :mod:`derivation.averaging` derives from the reduced model."""
    r = sp.simplify(published_flow(system)[lhs] - rhs)
    return Evidence(r == 0, None, "equals the averaged slow flow" if r == 0 else f"averaged slow flow minus rhs = {r}")


def _closed_form(lhs, rhs, system) -> Evidence:
    """Does ``lhs = rhs`` (with its partner, corrected or as printed) solve corrected Chap1/Chap2?"""
    partner_label = {"A_phi": "an2", "A_theta": "an1"}[lhs.name]
    partner = pub.BY_LABEL[partner_label].corrected or (pub.BY_LABEL[partner_label].lhs, pub.BY_LABEL[partner_label].rhs)
    sol = {lhs: rhs, partner[0]: partner[1]}
    out = []
    for label in ("Chap1", "Chap2"):
        e = pub.BY_LABEL[label]
        elhs, erhs = e.corrected or (e.lhs, e.rhs)
        var = {pub.A_phi_dot: pub.A_phi, pub.A_theta_dot: pub.A_theta}[elhs]
        res = sp.simplify((sp.diff(sol[var], pub.t) - erhs.subs(sol)).rewrite(sp.exp))
        out.append((label, res))
    passed = all(r == 0 for _, r in out)
    detail = "; ".join(f"residual in {lab}: {sp.simplify(r.rewrite(sp.cosh))}" for lab, r in out)
    return Evidence(passed, None, detail)


def _estimate(lhs, rhs, system) -> Evidence:
    """Compare a reversal-time estimate with the corrected closed form an2.

    The amplitude ``theta_max sech(A0 D t/(2 ell))`` with ``A0 = phi_dot0``
    rises from ``theta0`` to ``theta_max`` in ``(2 ell/(D phi_dot0))
    arccosh(theta_max/theta0)``.  ``t0`` must agree with it as
    ``theta0/theta_max -> 0`` (ratio -> 1); ``t_R`` must have its scaling
    (ratio free of ell, D, phi_dot0).
    """
    exact = 2 * pub.ell / (pub.D * pub.phi_dot0) * sp.acosh(pub.theta_max / pub.theta0)
    s = sp.Symbol("s", positive=True)
    ratio = (rhs / exact).subs(pub.theta0, pub.theta_max * sp.exp(-s))
    if lhs == pub.t0:
        lim = sp.limit(sp.simplify(ratio), s, sp.oo)
        return Evidence(lim == 1, None, f"estimate / closed form -> {lim} as theta0/theta_max -> 0")
    scale_free = not (sp.simplify(exact / rhs).free_symbols & {pub.ell, pub.D, pub.phi_dot0})
    return Evidence(scale_free, None, "closed form / estimate = " + str(sp.simplify(exact / rhs)))


_CHECKS = {"constraint": _constraint, "exact": _exact, "order": _order, "amplitude": _amplitude,
           "closed_form": _closed_form, "estimate": _estimate}
_CHECKS.update(AMPLITUDE_CHECKS)  # invariant, stability, reversal
_CHECKS.update(RIGID_CHECKS)  # rigid_limit (section III against the rigid body)


def evaluate(entry: pub.Published, systems: dict, corrected: bool = False) -> Evidence:
    """Evidence for ``entry`` as printed, or for its correction when ``corrected``."""
    lhs, rhs = entry.corrected if corrected else (entry.lhs, entry.rhs)
    dim = check_equation(lhs, rhs)
    system = systems[(entry.model, "full")]
    ev = _CHECKS[entry.check](lhs, rhs, system)
    return Evidence(ev.passed and dim is None, dim, ev.detail)


def all_evidence(systems: dict | None = None) -> dict:
    """``{label: (evidence as printed, evidence corrected or None)}`` for every entry."""
    if systems is None:
        from .emit import build_all

        systems = build_all()
    return {e.label: (evaluate(e, systems), evaluate(e, systems, True) if e.corrected else None)
            for e in pub.PUBLISHED}


def _check_models_cover_published():
    missing = {e.model for e in pub.PUBLISHED} - set(MODELS)
    if missing:
        raise ValueError(f"published equations refer to unknown models {missing}")


_check_models_cover_published()
