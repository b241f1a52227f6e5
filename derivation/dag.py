"""Large expressions walked as graphs: every shared subexpression differentiated (:func:`derivative`) or evaluated
(:func:`values`) once.

The Lagrangian of several bodies is a tree of ~10^4 operations whose subtrees repeat (each body's velocity enters
its kinetic energy several times); SymPy walks it as a tree, these functions as a graph.

Derivatives
-----------

``sp.diff`` re-enters its dispatch (``Derivative.__new__``) at every node and computes the free symbols of each
subtree again at every level, which is quadratic in the depth of a Lagrangian built from several bodies (the
rattleback carrying a mass on a spring: 8,900 operations, its mass matrix and ``h`` 9 s of ``sp.diff`` against
0.2 s here).  :func:`derivative` walks the tree once per variable with two memos (does a node hold ``x``; its
derivative), on the node types the front ends build (sums, products, powers with a constant exponent, ``sin``,
``cos``, selects) and calls ``sp.diff`` for any other node.  The result is mathematically equal to ``sp.diff``'s,
not always in the same form (the order of a product's factors), so the closed-form elimination, whose emitted code
is checked in, keeps ``sp.diff``.
"""
from __future__ import annotations

import mpmath
import sympy as sp

#: the working precision of :func:`values` (decimal digits)
DIGITS = 30


class _Walk:
    def __init__(self, x: sp.Symbol):
        self.x = x
        self.holds: dict = {}
        self.memo: dict = {}

    def has_x(self, e) -> bool:
        if e.is_Atom:
            return e == self.x
        h = self.holds.get(e)
        if h is None:
            h = self.holds[e] = any(self.has_x(a) for a in e.args)
        return h

    def d(self, e):
        if e.is_Symbol:
            return sp.S.One if e == self.x else sp.S.Zero
        if e.is_Atom or not self.has_x(e):
            return sp.S.Zero
        out = self.memo.get(e)
        if out is None:
            out = self.memo[e] = self._rule(e)
        return out

    def _rule(self, e):
        d = self.d
        if e.is_Add:
            return sp.Add(*[d(a) for a in e.args])
        if e.is_Mul:
            args = e.args
            terms = []
            for i, a in enumerate(args):
                da = d(a)
                if da != 0:
                    terms.append(sp.Mul(*args[:i], da, *args[i + 1:]))
            return sp.Add(*terms)
        if e.is_Pow and not self.has_x(e.exp):
            return e.exp * e.base ** (e.exp - 1) * d(e.base)
        if isinstance(e, sp.sin):
            return sp.cos(e.args[0]) * d(e.args[0])
        if isinstance(e, sp.cos):
            return -sp.sin(e.args[0]) * d(e.args[0])
        if isinstance(e, sp.Piecewise):
            return sp.Piecewise(*[(d(v), c) for v, c in e.args])
        return sp.diff(e, self.x)


def derivative(e, x: sp.Symbol):
    """``d e / d x`` (see the module docstring)."""
    return _Walk(x).d(sp.sympify(e))


def gradient(e, variables) -> list:
    """``[d e / d v for v in variables]``."""
    return [derivative(e, v) for v in variables]


def jacobian(exprs, variables) -> sp.Matrix:
    """``d exprs / d variables`` as a matrix (rows: ``exprs``)."""
    return sp.Matrix([gradient(e, variables) for e in exprs])


def _number(e) -> mpmath.mpf:
    if e.is_Integer:
        return mpmath.mpf(int(e))
    if e.is_Rational:
        return mpmath.mpf(int(e.p)) / int(e.q)
    return mpmath.mpmathify(sp.Float(e, DIGITS + 5))


_UNARY = {sp.sin: mpmath.sin, sp.cos: mpmath.cos, sp.tan: mpmath.tan, sp.exp: mpmath.exp, sp.log: mpmath.log,
          sp.Abs: abs}


def values(exprs, point: dict) -> list:
    """Each of ``exprs`` at ``point`` (``{symbol: number}``, every free symbol given), as ``mpmath.mpf`` in
    :data:`DIGITS` digits; call it inside ``mpmath.workdps(DIGITS)``.

    Evaluated node by node with a memo: sums, products, powers, ``sin``, ``cos``, ``tan``, ``exp``, ``log``,
    ``Abs``; any other node by ``evalf`` of its subtree.  (``xreplace`` of floats then ``evalf``, its former
    form, rebuilds the whole tree: the rattleback carrying a mass on a spring spent most of its check there.)
    """
    memo = {k: _number(sp.sympify(v)) for k, v in point.items()}

    def value(e):
        out = memo.get(e)
        if out is not None:
            return out
        if e.is_Number or e.is_NumberSymbol:
            out = _number(e)
        elif e.is_Add:
            out = mpmath.fsum(value(a) for a in e.args)
        elif e.is_Mul:
            out = mpmath.fprod(value(a) for a in e.args)
        elif e.is_Pow:
            base = value(e.base)
            out = base ** int(e.exp) if e.exp.is_Integer else base ** value(e.exp)
        elif type(e) in _UNARY:
            out = _UNARY[type(e)](value(e.args[0]))
        else:
            out = mpmath.mpmathify(sp.Float(e.xreplace(point).evalf(DIGITS), DIGITS))
        memo[e] = out
        return out

    return [value(sp.sympify(e)) for e in exprs]
