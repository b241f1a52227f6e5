"""The Jacobians of a right-hand side, emitted beside it (every generated module has them).

``jacobian(s, p)`` is ``d rhs / d s`` of the closed state, shape ``(n, n)``;
``jacobian_p(s, p)`` is ``d rhs / d p``, shape ``(n, n_params)``.  Both are
derived exactly and printed with shared subexpressions, like the right-hand
side (SymForce emits Jacobians beside values; jitcode derives the variational
equations the same way).  An emitter appends :func:`block_source` to its
module; the block also adds the two functions' operation counts to the
module's ``OP_COUNTS``.

The derivatives are taken through the right-hand side's own common
subexpressions (forward mode: each intermediate ``c_k = f(...)`` gets its
gradient ``sum_j df/dx_j dx_j``), so that the size of the result grows with
that of the right-hand side, not with the size of its expanded expressions.
"""
from __future__ import annotations

import sympy as sp

from . import names
from .codegen import code as _code, unpack as _unpack


def _gradients(exprs, variables):
    """``(subs, rows)``: the CSE of ``exprs`` and, for each expression, its gradient ``{variable: derivative}``.

    The derivatives are written with the CSE symbols of ``subs`` (``_c0, _c1, ...``) and the derivative symbols
    ``_dK_J`` (``d _cK / d variables[J]``), which come first in ``subs`` order as pairs ``(symbol, expression)``.
    """
    subs, reduced = sp.cse(list(exprs), symbols=sp.numbered_symbols("_c", cls=names.Own), order="canonical")
    index = {v: j for j, v in enumerate(variables)}
    grad: dict = {}  # symbol -> {j: expression of d symbol / d variables[j]}
    deriv_subs = []

    def gradient(e):
        out: dict = {}
        for x in sorted(e.free_symbols, key=str):
            if x in index:
                parts = {index[x]: sp.Integer(1)}
            elif x in grad:
                parts = grad[x]
            else:
                continue
            if not parts:
                continue
            dx = sp.diff(e, x)
            if dx == 0:
                continue
            for j, g in parts.items():
                out[j] = out.get(j, sp.Integer(0)) + dx * g
        return {j: g for j, g in out.items() if g != 0}

    for c, e in subs:
        g = gradient(e)
        named = {}
        for j, expr in sorted(g.items()):
            if expr.is_Atom:
                named[j] = expr
            else:
                d = names.Own(f"_d{str(c)[2:]}_{j}")
                deriv_subs.append((c, d, expr))
                named[j] = d
        grad[c] = named
    return subs, deriv_subs, [gradient(e) for e in reduced]


def _function(name, exprs, wrt, state, params, shape, doc):
    """Source and op count of ``name(s, p)`` returning ``d exprs / d wrt`` as an array of ``shape``."""
    subs, deriv_subs, rows = _gradients(exprs, list(wrt))
    allowed = set(state) | set(params) | {names.t}
    bad = set().union(*(e.free_symbols for e in exprs)) - allowed
    if bad:
        raise ValueError(f"refusing to emit: undeclared symbols {sorted(map(str, bad))}")
    by_c: dict = {}
    for c, d, e in deriv_subs:
        by_c.setdefault(c, []).append((d, e))
    assigns = []  # each intermediate, then its derivatives (which may use it)
    for c, e in subs:
        assigns.append((c, e))
        assigns.extend(by_c.get(c, ()))
    outputs = [(f"out[{i}, {j}]", e) for i, row in enumerate(rows) for j, e in sorted(row.items())]
    used = set().union(set(), *(e.free_symbols for _, e in outputs))
    kept = []
    for sym, e in reversed(assigns):  # only what the derivatives need
        if sym in used:
            kept.append((sym, e))
            used |= e.free_symbols
    kept.reverse()
    lines = [f"    {t} = {_code(e)}" for t, e in kept + outputs]
    ops = sum(sp.count_ops(e) for _, e in kept + outputs)
    args = "s, p, t" if names.t in set().union(*(e.free_symbols for e in exprs)) else "s, p"
    nl = "\n"
    unpack = [ln for ln, x in zip(_unpack([str(x) for x in state], "s"), state) if x in used]
    unpack += [ln for ln, x in zip(_unpack([str(x) for x in params], "p"), params) if x in used]
    return f'''

@njit(cache=True)
def {name}({args}):
    """{doc} ({int(ops)} operations)."""
    out = np.zeros({shape})
{nl.join(unpack)}
{nl.join(lines)}
    return out
''', int(ops)


def block_source(rates, state, params) -> str:
    """Source of ``jacobian(s, p)`` and ``jacobian_p(s, p)`` of the right-hand side ``rates`` for any emitter.

    Parameters
    ----------
    rates : SymPy expressions of d(state)/dt, in the order of ``state``.
    state : symbols of the closed state vector ``s``, in order.
    params : symbols of the parameter vector ``p``, in order.
    """
    rates, state, params = list(rates), list(state), list(params)
    n, k = len(state), len(params)
    src_s, ops_s = _function("jacobian", rates, state, state, params, f"({n}, {n})",
                             f"d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape ({n}, {n})")
    src_p, ops_p = _function("jacobian_p", rates, params, state, params, f"({n}, {k})",
                             f"d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape ({n}, {k})")
    return (f"\n\n#: operation counts of the Jacobians (derivation/jacobian.py)\n"
            f"OP_COUNTS.update(jacobian={ops_s}, jacobian_p={ops_p})" + src_s + src_p)
