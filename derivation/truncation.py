"""Small-angle truncation: the ``reduced`` fidelity from the ``full`` one.

The tilts and their rates are scaled by a bookkeeping parameter ``eps``
(``theta -> eps*theta``, ``theta_dot -> eps*theta_dot``, accelerations
likewise); the spin rate is not small.  Every expression is replaced by its
Taylor polynomial in ``eps`` of degree ``ORDER = 2``, then ``eps = 1``.

Because the system is symmetric under ``theta -> -theta`` (with ``x -> -x``),
the tilt accelerations are odd in ``eps`` and the spin acceleration is even:
the degree-2 truncation keeps the tilt equations to first order (dropping
``O(theta^3)``) and the spin equation to second order (dropping
``O(theta^4)``).  This is the order of the paper's ``FINAL1``/``FINAL2`` and
``eqs_2modes``.
"""
from __future__ import annotations

from dataclasses import replace

import sympy as sp

from .engine import ReducedSystem, tidy

ORDER = 2
eps = sp.Symbol("epsilon", positive=True)


def small_scaling(spec) -> dict:
    """Substitution ``s -> eps*s`` for the small coordinates, their rates and accelerations."""
    sub = {}
    for q in spec.small:
        for s in (q, spec.velocity_of(q), spec.acceleration_of(q)):
            sub[s] = eps * s
    return sub


def taylor(e: sp.Expr, order: int = ORDER) -> sp.Expr:
    """Taylor polynomial of ``e`` in ``eps`` of the given degree."""
    out, d = sp.S.Zero, e
    for k in range(order + 1):
        out += d.subs(eps, 0) / sp.factorial(k) * eps**k
        if k < order:
            d = sp.diff(d, eps)
    return out


def order_of(e: sp.Expr, spec, max_order: int = 6) -> int | None:
    """Lowest power of ``eps`` in ``e`` after scaling the small variables (None if zero)."""
    scaled = e.subs(small_scaling(spec), simultaneous=True)
    d = scaled
    for k in range(max_order + 1):
        if sp.simplify(d.subs(eps, 0)) != 0:
            return k
        d = sp.diff(d, eps)
    return None


def truncate(e: sp.Expr, spec, variables=None, order: int = ORDER) -> sp.Expr:
    """Degree-``order`` truncation of ``e`` in the small variables (see module doc).

    With ``variables`` the result is put in the normal form of
    :func:`derivation.engine.tidy`; without, it is only factored.
    """
    scaled = e.subs(small_scaling(spec), simultaneous=True)
    out = taylor(scaled, order).subs(eps, 1)
    return tidy(out, variables) if variables else sp.factor(out)


def reduced(system: ReducedSystem, order: int = ORDER) -> ReducedSystem:
    """The ``reduced`` fidelity of a ``full`` system.

    Its explicit form is the truncated explicit form of ``system``; its
    mass-matrix form is the identity with that explicit form as forcing (the
    truncation is defined on the explicit vector field, not on the mass
    matrix).  Multipliers, energy and pose rates are truncated the same way.
    """
    spec = system.spec
    var = list(system.state)
    imp_var = var + list(system.accelerations)
    explicit = system.explicit.applyfunc(lambda e: truncate(e, spec, var, order))
    n = len(system.accelerations)
    return replace(
        system,
        mass_matrix=sp.eye(n),
        forcing=explicit,
        explicit=explicit,
        multipliers=system.multipliers.applyfunc(lambda e: truncate(e, spec, var, order)),
        multipliers_implicit=system.multipliers_implicit.applyfunc(lambda e: truncate(e, spec, imp_var, order)),
        energy=truncate(system.energy, spec, var, order),
        pose_rates={k: truncate(v, spec, order=order) for k, v in system.pose_rates.items()},
        power=None if system.power is None else truncate(system.power, spec, var, order),
    )
