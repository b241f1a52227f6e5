"""Dimensional analysis of symbolic equations.

Every symbol has a dimension ``(length, time, mass)`` exponent triple.  An
equation is consistent when both sides have one dimension, every sum adds
terms of one dimension, and every transcendental function (``tanh``,
``log``, ``cos`` ...) has a dimensionless argument.
"""
from __future__ import annotations

import sympy as sp

from .models import DIMENSIONS

#: symbol name -> (length, time, mass) exponents
TABLE: dict = {name: (lt[0], lt[1], 0) for name, lt in DIMENSIONS.items()}
TABLE.update({
    "M": (0, 0, 1),                      # total mass
    "lambda1": (1, -2, 1), "lambda2": (1, -2, 1),  # constraint forces
    "A_theta": (0, 0, 0), "A_phi": (0, -1, 0), "A0": (0, -1, 0),
    "A_theta_dot": (0, -1, 0), "A_phi_dot": (0, -2, 0),
    "theta0": (0, 0, 0), "theta_max": (0, 0, 0), "phi_dot0": (0, -1, 0),
    "t0": (0, 1, 0), "t_R": (0, 1, 0), "omega": (0, -1, 0),
    "L_two_mode": (2, -2, 1),            # the two-mode Lagrangian (an energy)
})


class DimensionError(ValueError):
    """An expression mixes dimensions; the message names the offending terms."""


def dimension(e: sp.Expr) -> tuple:
    """Dimension of ``e`` as a (length, time, mass) triple; raises :class:`DimensionError`."""
    if e.is_Number or e is sp.pi or e is sp.E:
        return (0, 0, 0)
    if e.is_Symbol:
        try:
            return TABLE[e.name]
        except KeyError:
            raise DimensionError(f"no dimension known for symbol {e}") from None
    if e.is_Mul:
        dims = [dimension(a) for a in e.args]
        return tuple(sum(d[i] for d in dims) for i in range(3))
    if e.is_Pow:
        base, ex = e.args
        if dimension(ex) != (0, 0, 0):
            raise DimensionError(f"exponent {ex} is not dimensionless")
        d = dimension(base)
        if d == (0, 0, 0):
            return d
        if not ex.is_Rational:
            raise DimensionError(f"non-rational power of a dimensional quantity: {e}")
        return tuple(sp.Rational(ex) * x for x in d)
    if e.is_Add:
        dims = {a: dimension(a) for a in e.args}
        distinct = set(dims.values())
        if len(distinct) > 1:
            detail = "; ".join(f"{a}: {_fmt(d)}" for a, d in dims.items())
            raise DimensionError(f"terms of different dimensions in {e}: {detail}")
        return distinct.pop()
    if isinstance(e, sp.Function):
        for a in e.args:
            d = dimension(a)
            if d != (0, 0, 0):
                raise DimensionError(f"argument of {e.func} has dimension {_fmt(d)}: {a}")
        return (0, 0, 0)
    raise DimensionError(f"cannot analyse {e!r}")


def _fmt(d) -> str:
    names = ("length", "time", "mass")
    parts = [f"{n}^{x}" if x != 1 else n for n, x in zip(names, d) if x != 0]
    return " ".join(parts) or "dimensionless"


def check_equation(lhs: sp.Expr, rhs: sp.Expr) -> str | None:
    """``None`` when ``lhs = rhs`` is dimensionally consistent, else the reason."""
    try:
        dl = dimension(sp.expand(lhs))
        dr = dimension(sp.expand(rhs)) if rhs != 0 else dl
    except DimensionError as exc:
        return str(exc)
    if dl != dr:
        return f"left side is {_fmt(dl)}, right side is {_fmt(dr)}"
    return None
