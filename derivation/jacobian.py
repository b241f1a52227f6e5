"""The Jacobians of a right-hand side, emitted beside it (every generated module has them).

``jacobian(s, p)`` is ``d rhs / d s`` of the closed state, shape ``(n, n)``;
``jacobian_p(s, p)`` is ``d rhs / d p``, shape ``(n, n_params)``.  Both are
derived exactly and printed with shared subexpressions, like the right-hand
side (SymForce emits Jacobians beside values; jitcode derives the variational
equations the same way).  ``jvp_into(s, p, _V, ds, out)`` writes the rates and
the Jacobian-vector product ``J(s) _V`` of the columns of ``_V`` (what the
Lyapunov loop steps its tangent vectors with; :func:`jvp_source`), and
``jvp1_into(s, p, _v, ds, _dv)`` the same of one vector ``_v``.  An emitter
appends :func:`block_source` to its module; the block also adds the functions'
operation counts to the module's ``OP_COUNTS``.

The derivatives are taken through the right-hand side's own common
subexpressions (forward mode: each intermediate ``c_k = f(...)`` gets its
gradient ``sum_j df/dx_j dx_j``), so that the size of the result grows with
that of the right-hand side, not with the size of its expanded expressions.
"""
from __future__ import annotations

import sympy as sp

from . import names
from .codegen import Function, code as _code, hoist_parameters, unpack as _unpack


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


def partial(e: sp.Expr, x: sp.Symbol) -> sp.Expr:
    """``d e / d x`` by the chain rule on the node types of a program's line (sums, products, powers, ``sin``,
    ``cos``, ``sqrt``, selects), ``sp.diff`` for anything else: equal to ``sp.diff``, without its dispatch (which
    took two thirds of the Whipple bicycle's Jacobians)."""
    if e.is_Symbol:
        return sp.S.One if e == x else sp.S.Zero
    if e.is_Atom or x not in e.free_symbols:
        return sp.S.Zero
    if e.is_Add:
        return sp.Add(*[partial(a, x) for a in e.args])
    if e.is_Mul:
        args = e.args
        terms = []
        for i, a in enumerate(args):
            da = partial(a, x)
            if da != 0:
                terms.append(sp.Mul(*args[:i], da, *args[i + 1:]))
        return sp.Add(*terms)
    if e.is_Pow and x not in e.exp.free_symbols:
        return e.exp * e.base ** (e.exp - 1) * partial(e.base, x)
    if isinstance(e, sp.sin):
        return sp.cos(e.args[0]) * partial(e.args[0], x)
    if isinstance(e, sp.cos):
        return -sp.sin(e.args[0]) * partial(e.args[0], x)
    if isinstance(e, sp.Piecewise):
        return sp.Piecewise(*[(partial(v, x), c) for v, c in e.args])
    return sp.diff(e, x)


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


def _power_partial(c: sp.Symbol, e: sp.Expr, x: sp.Symbol) -> sp.Expr:
    """``d e / d x`` of the line ``c = e``: a reciprocal's or a root's derivative written with the line's value
    ``c`` (``d(1/u) = -c^2 du``, ``d(u^a) = a c / u du``), not with a power of ``u`` again; :func:`partial` else."""
    if not (e.is_Pow and e.exp.is_Number) or (e.exp.is_Integer and e.exp > 0):
        return partial(e, x)
    factor = -c * c if e.exp == -1 else e.exp * c / e.base
    return factor * partial(e.base, x)


def program_tangent(subs, outputs, seeds: dict) -> tuple:
    """Forward mode along one direction: ``(lines, tangents)``, the program's lines each followed by its
    derivative ``_t<k>`` along ``seeds`` ({variable: symbol of its tangent component}), and the derivative of
    each output; only the lines the tangents need are kept."""
    tangent: dict = {}
    assigns = []

    def dot(e, c=None):
        terms = []
        for x in sorted(e.free_symbols, key=str):
            tx = seeds.get(x, tangent.get(x))
            if tx is None:
                continue
            dx = _power_partial(c, e, x) if c is not None else partial(e, x)
            if dx != 0:
                terms.append(dx * tx)
        return sp.Add(*terms)

    for c, e in subs:
        assigns.append((c, e))
        d = dot(e, c)
        if d != 0:
            tangent[c] = d if d.is_Atom else names.Own(f"_t{str(c)[2:]}")
            if not d.is_Atom:
                assigns.append((tangent[c], d))
    tangents = [dot(sp.sympify(o)) for o in outputs]
    used = set().union(set(), *(e.free_symbols for e in tangents))
    kept = []
    for sym, e in reversed(assigns):
        if sym in used:
            kept.append((sym, e))
            used |= e.free_symbols
    return kept[::-1], tangents


def _tangent_function(name, program, rates, wrt, state, params, doc) -> tuple[str, int]:
    """``name(s, p)`` returning ``d rates / d wrt`` column by column: a private ``_<name>_along(s, p, v)`` (the
    derivative along ``v``, one forward pass) called once per column, so that the compiled code is about three
    right-hand sides long whatever the number of columns (the Whipple bicycle's full Jacobian, 32,600
    operations, did not compile in 14 minutes on the loaded machine)."""

    seeds = {x: names.Own(f"_v{j}") for j, x in enumerate(wrt)}
    lines, tangents = program_tangent(program, rates, seeds)
    body = [f"    {t} = {_code(e)}" for t, e in lines]
    body += [f"    out[{i}] = {_code(e)}" for i, e in enumerate(tangents)]
    ops = int(sum(sp.count_ops(e) for _, e in lines) + sum(sp.count_ops(e) for e in tangents))
    used = set().union(set(), *(e.free_symbols for _, e in lines), *(e.free_symbols for e in tangents))
    timed = names.t in set().union(*(e.free_symbols for _, e in program))
    args = "s, p, t" if timed else "s, p"
    unpack = [ln for ln, x in zip(_unpack([str(x) for x in state], "s"), state) if x in used]
    unpack += [ln for ln, x in zip(_unpack([str(x) for x in params], "p"), params) if x in used]
    seed_lines = [f"    {v} = _v[{j}]" for j, v in enumerate(seeds.values()) if v in used]
    n, k = len(rates), len(wrt)
    nl = "\n"
    return f'''

@njit(cache=True)
def _{name}_along({args}, _v):
    """d(state rate) along the direction ``_v`` of the {'state' if name == 'jacobian' else 'parameters'} ({ops} operations)."""
    out = np.zeros({n})
{nl.join(unpack + seed_lines)}
{nl.join(body)}
    return out


@njit(cache=True)
def {name}({args}):
    """{doc}, one forward pass per column ({k} x {ops} operations)."""
    out = np.zeros(({n}, {k}))
    _v = np.zeros({k})
    for _j in range({k}):
        _v[:] = 0.0
        _v[_j] = 1.0
        out[:, _j] = _{name}_along({args}, _v)
    return out
''', ops * k


def _primal_and_tangent(program, rates, seeds: dict) -> tuple[list, list, list]:
    """``(primal, tangent, tangents)``: the lines of ``program`` the rates or their derivatives along ``seeds``
    need that do not depend on the direction (in program order), the tangent lines (:func:`program_tangent`) and
    the derivatives of the rates."""
    lines, tangents = program_tangent(program, rates, seeds)
    along = set(seeds.values())  # the symbols that depend on the direction
    tangent, needed = [], set().union(set(), *(sp.sympify(e).free_symbols for e in rates))
    for sym, e in lines:
        if e.free_symbols & along:
            along.add(sym)
            tangent.append((sym, e))
        else:
            needed.add(sym)
    for sym, e in reversed(program):  # and what those need
        if sym in needed:
            needed |= e.free_symbols
    return [(sym, e) for sym, e in program if sym in needed], tangent, tangents


def jvp_source(program, rates, state, params) -> tuple[str, int, int]:
    """Source of ``jvp_into(s, p, _V, ds, out)``: the rates ``ds`` (as ``rhs_into``) and their derivatives along
    the ``k`` columns of ``_V``, ``out = J(s) _V`` (both ``(n, k)``), as JAX's ``jvp`` returns the value with the
    derivative; with the operations once per call and per column.

    ``rates`` bound by the straight-line ``program`` (pairs ``(symbol, expression)``: a closed form's CSE, or the
    numeric elimination's program) are differentiated in forward mode along a direction (:func:`program_tangent`):
    the lines that do not depend on the direction (the program itself, and the partial derivatives of each line,
    hoisted out of the products and sums of the tangent lines) are written once, before a loop over the columns
    that holds only the tangent lines, each a short sum of products.
    """
    seeds = {x: names.Own(f"_v{j}") for j, x in enumerate(state)}
    primal, tangent, tangents = _primal_and_tangent(program, rates, seeds)
    fixed = set(state) | set(params) | {names.t} | {sym for sym, _ in primal}
    hoisted, moved = hoist_parameters([e for _, e in tangent] + list(tangents), fixed)
    subs, reduced = sp.cse([e for _, e in hoisted], symbols=sp.numbered_symbols("_p", cls=names.Own),
                           order="canonical")
    once = primal + subs + [(k, e) for (k, _), e in zip(hoisted, reduced)]
    values = [(f"ds[{i}]", sp.sympify(e)) for i, e in enumerate(rates)]
    loop = [(sym, e) for (sym, _), e in zip(tangent, moved)] + [(f"out[{i}, _j]", e)
                                                                 for i, e in enumerate(moved[len(tangent):])]
    ops_once = int(sum(sp.count_ops(e) for _, e in once + values))
    ops_column = int(sum(sp.count_ops(e) for _, e in loop))
    used = set().union(set(), *(e.free_symbols for _, e in once + values + loop))
    unpack = [ln for ln, x in zip(_unpack([str(x) for x in state], "s"), state) if x in used]
    unpack += [ln for ln, x in zip(_unpack([str(x) for x in params], "p"), params) if x in used]
    timed = names.t in set().union(set(), *(e.free_symbols for _, e in program), *(e.free_symbols for _, e in values))
    nl = "\n"
    head = (nl.join(unpack), nl.join(f"    {sym} = {_code(e)}" for sym, e in once + values))
    body = (*head, "    for _j in range(_V.shape[1]):",
            nl.join(f"        {v} = _V[{j}, _j]" for j, v in enumerate(seeds.values()) if v in used),
            nl.join(f"        {sym} = {_code(e)}" for sym, e in loop))
    doc = (f"Write d(state)/dt into ``ds`` and ``J(s) _V`` into ``out`` (``_V``, ``out``: ({len(state)}, k)), the "
           f"derivatives of the rates along the columns of ``_V`` by forward mode through the right-hand side "
           f"({ops_once} operations once, {ops_column} per column).")
    # the directions named with "_" (no user's name is): a model may name a parameter ``V``
    args = "s, p, t, _V, ds, out" if timed else "s, p, _V, ds, out"
    # one column, the same lines without the loop over the columns: straight-line code is ~13 % faster per call
    # (the Lyapunov loop's largest exponent: ~6 % of its time)
    one = (*head, nl.join(f"    {v} = _v[{j}]" for j, v in enumerate(seeds.values()) if v in used),
           nl.join(f"    {str(sym).replace('out[', '_dv[').replace(', _j]', ']')} = {_code(e)}" for sym, e in loop))
    doc1 = (f"``jvp_into`` of one column: d(state)/dt into ``ds`` and ``J(s) _v`` into ``_dv`` (vectors of length "
            f"{len(state)}; {ops_once + ops_column} operations).")
    args1 = "s, p, t, _v, ds, _dv" if timed else "s, p, _v, ds, _dv"
    return ("\n\n" + Function("jvp_into", args, doc, tuple(b for b in body if b)).source()
            + "\n\n" + Function("jvp1_into", args1, doc1, tuple(b for b in one if b)).source(), ops_once, ops_column)


def program_block_source(program, rates, state, params) -> str:
    """:func:`block_source` of the rates ``rates`` bound by the straight-line ``program`` (the numeric
    elimination's, :mod:`.kkt_emit`): the program differentiated in forward mode, line by line."""
    rates, state, params = list(rates), list(state), list(params)
    n, k = len(state), len(params)
    src_s, ops_s = _tangent_function("jacobian", program, rates, state, state, params,
                                     f"d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape ({n}, {n})")
    src_p, ops_p = _tangent_function("jacobian_p", program, rates, params, state, params,
                                     f"d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape ({n}, {k})")
    src_v, once, column = jvp_source(program, rates, state, params)
    return (f"\n\n#: operation counts of the Jacobians and of the Jacobian-vector product, once and per column "
            f"(derivation/jacobian.py, forward mode through the program of derivation/kkt_emit.py)\n"
            f"OP_COUNTS.update(jacobian={ops_s}, jacobian_p={ops_p}, jvp_once={once}, jvp_column={column})"
            + src_s + src_p + src_v)


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
    subs, reduced = sp.cse(rates, symbols=sp.numbered_symbols("_c", cls=names.Own), order="canonical")
    src_v, once, column = jvp_source(subs, reduced, state, params)
    return (f"\n\n#: operation counts of the Jacobians and of the Jacobian-vector product, once and per column "
            f"(derivation/jacobian.py)\n"
            f"OP_COUNTS.update(jacobian={ops_s}, jacobian_p={ops_p}, jvp_once={once}, jvp_column={column})"
            + src_s + src_p + src_v)
