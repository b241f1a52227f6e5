"""Functions of a model whose multipliers are eliminated numerically (``ReducedSystem.kkt``).

Past a size where the closed form stops paying (:data:`.engine.NUMERIC_FROM`), nothing symbolic inverts or
expands the constraint block: the generated module evaluates ``M``, ``f``, ``A`` and ``c`` (:class:`.engine.Kkt`)
with shared subexpressions and solves at every call, in straight-line code written as a :class:`Program`:

1. the dependent velocities from ``A_dep v_dep = -A_ind v_ind`` (an unrolled LU with partial pivoting);
2. the dependent accelerations ``q_ddot = T a + d`` with ``T = [-A_dep^-1 A_ind; I]`` and ``d = [-A_dep^-1 c; 0]``
   (the same LU, ``k + 1`` right-hand sides), so that the independent accelerations ``a`` solve the reduced
   system ``(T^T M T) a = T^T (f - M d)``: k x k, symmetric positive definite (the kinetic energy on the
   constraint manifold), factored as ``L D L^T`` without pivoting;
3. the multipliers from the dependent rows, ``A_dep^T lambda = (M q_ddot - f)_dep`` (LU of ``A_dep^T``).

Every step is an assignment ``symbol = expression`` of earlier symbols, so the Jacobians are the same program
differentiated in forward mode along one direction (:func:`.jacobian.program_tangent`), called once per column:
exact, and about three right-hand sides long.
The pivoting is written as selects (``b if abs(b) > abs(a) else a``); a structural zero needs none.  No array
is allocated and no LAPACK is bound.
"""
from __future__ import annotations

import itertools

import sympy as sp

from . import jacobian, names
from .codegen import code as _code, rhs_functions as _rhs_source


class Program:
    """Straight-line code: ``(symbol, expression)`` assignments in order, every symbol ``_c<k>`` (one counter)."""

    def __init__(self, prefix: str = "_c"):
        self.lines: list = []
        self.prefix = prefix
        self._count = itertools.count()

    def _fresh(self):
        while True:
            yield names.Own(f"{self.prefix}{next(self._count)}")

    def let(self, e):
        """A symbol bound to ``e`` (``e`` itself when it is a number or a symbol)."""
        e = sp.sympify(e)
        if e.is_Atom:
            return e
        s = next(self._fresh())
        self.lines.append((s, e))
        return s

    def cse(self, exprs) -> list:
        """Bind ``exprs`` with their common subexpressions shared; returns a symbol (or atom) per expression.
        A power ``x**(-k/2)`` (``k`` odd, ``x`` a symbol) whose ``x**(-1/2)`` is bound already is written as that
        symbol to the ``k``-th power (:func:`_by_root`): products for a call of ``pow``."""
        subs, reduced = sp.cse(list(exprs), symbols=self._fresh(), order="canonical")
        roots = {e.base: s for s, e in self.lines if e.is_Pow and e.exp == sp.Rational(-1, 2) and e.base.is_Symbol}
        for s, e in subs:
            e = _by_root(e, roots)
            self.lines.append((s, e))
            if e.is_Pow and e.exp == sp.Rational(-1, 2) and e.base.is_Symbol:
                roots.setdefault(e.base, s)
        return [self.let(_by_root(e, roots)) for e in reduced]


def _by_root(e, roots: dict):
    """``e`` with each ``x**(-k/2)`` (``k`` odd, at least 3) whose ``x`` has a bound root ``r = x**(-1/2)`` in
    ``roots`` written ``r**k`` (printed as products of ``r``: about 4 % of the Whipple bicycle's right-hand side
    was its three calls of ``pow``; the values differ from ``pow``'s in the last bits)."""
    def swap(power):
        return roots[power.base] ** (-2 * power.exp)

    return e.replace(lambda x: (x.is_Pow and x.base in roots and x.exp.is_Rational and x.exp.q == 2
                                and x.exp < -sp.Rational(1, 2)), swap)


def lu_solve(prog: Program, A: list, columns: list) -> list:
    """``X`` with ``A X = B``: LU with partial pivoting, unrolled (``A`` m x m rows of atoms, ``B`` as columns).

    Row ``j`` takes the largest ``|a_ij|`` of the rows below by a select for each candidate row (none where
    an entry is a structural zero); the right-hand sides ride along.  Returns the solution columns.
    """
    m = len(A)
    rows = [list(A[i]) + [col[i] for col in columns] for i in range(m)]
    width = len(rows[0]) if rows else 0
    for j in range(m):
        for i in range(j + 1, m):
            if rows[i][j] == 0:
                continue
            if rows[j][j] == 0:
                rows[i], rows[j] = rows[j], rows[i]
                continue
            larger = sp.Abs(rows[i][j]) > sp.Abs(rows[j][j])
            for k in range(j, width):
                a, b = rows[j][k], rows[i][k]
                if a != b:
                    rows[j][k] = prog.let(sp.Piecewise((b, larger), (a, True)))
                    rows[i][k] = prog.let(sp.Piecewise((a, larger), (b, True)))
        if rows[j][j] == 0:
            raise ValueError("the constraint block of the dependent velocities is structurally singular")
        for i in range(j + 1, m):
            if rows[i][j] == 0:
                continue
            factor = prog.let(rows[i][j] / rows[j][j])
            for k in range(j + 1, width):
                if rows[j][k] != 0:
                    rows[i][k] = prog.let(rows[i][k] - factor * rows[j][k])
            rows[i][j] = sp.S.Zero
    out = []
    for c in range(len(columns)):
        x = [sp.S.Zero] * m
        for i in reversed(range(m)):
            e = rows[i][m + c] - sum((rows[i][k] * x[k] for k in range(i + 1, m)), sp.S.Zero)
            x[i] = prog.let(e / rows[i][i])
        out.append(x)
    return out


def ldl_solve(prog: Program, Mr: dict, fr: list) -> list:
    """``a`` with ``Mr a = fr``, ``Mr`` symmetric positive definite (``Mr[i, j]`` for ``i <= j``): ``L D L^T``."""
    k = len(fr)
    m = lambda i, j: Mr[min(i, j), max(i, j)]  # noqa: E731
    d, low = [], {}
    for j in range(k):
        d.append(prog.let(m(j, j) - sum((low[j, p] ** 2 * d[p] for p in range(j)), sp.S.Zero)))
        for i in range(j + 1, k):
            low[i, j] = prog.let((m(i, j) - sum((low[i, p] * low[j, p] * d[p] for p in range(j)), sp.S.Zero)) / d[j])
    y = []
    for i in range(k):
        y.append(prog.let(fr[i] - sum((low[i, p] * y[p] for p in range(i)), sp.S.Zero)))
    a = [sp.S.Zero] * k
    for i in reversed(range(k)):
        a[i] = prog.let(y[i] / d[i] - sum((low[p, i] * a[p] for p in range(i + 1, k)), sp.S.Zero))
    return a


def _columns(X: sp.Matrix, cols) -> list:
    return [[X[r, c] for r in range(X.rows)] for c in cols]


def _velocities(prog: Program, kkt, general: bool, held: bool = False) -> tuple:
    """Bind the dependent velocities (at the representative pose, or the general one): ``({symbol: atom}, A_dep,
    A_ind)``, the blocks of the constraint matrix as rows of atoms.

    With ``held`` (and holonomic constraints held, ``kkt.holonomic_rhs``) the same LU also solves a second
    right-hand side, ``-A_ind v_ind - [0, rate f]``: the rates ``kkt.held_velocities`` of the kept dependent
    coordinates, under which ``f`` decays as ``exp(-rate t)``; the dynamics keep the exact dependent velocities.
    """
    A = kkt.constraint_general if general else kkt.constraint
    dep = kkt.dependent
    ind = list(kkt.independent)
    v_ind = [kkt.velocities[i] for i in ind]
    rhs = [-sum((A[r, i] * v for i, v in zip(ind, v_ind)), sp.S.Zero) for r in range(A.rows)]
    m, k = len(dep), len(ind)
    held = held and not general and bool(kkt.holonomic_rhs)
    extra = [rhs[r] - kkt.holonomic_rhs[r] for r in range(m)] if held else []
    entries = prog.cse([A[r, c] for r in range(m) for c in dep] + [A[r, c] for r in range(m) for c in ind] + rhs
                       + extra)
    block = [entries[r * m:(r + 1) * m] for r in range(m)]
    rest = [entries[m * m + r * k: m * m + (r + 1) * k] for r in range(m)]
    start = m * m + m * k
    x, *xh = lu_solve(prog, block, [entries[start:start + m]] + ([entries[start + m:]] if held else []))
    keys = kkt.general_velocities if general else tuple(kkt.velocities[i] for i in dep)
    solved = dict(zip(keys, x))
    if held:
        solved.update(zip(kkt.held_velocities, xh[0]))
    return solved, block, rest


def program(system, exprs, *, general: bool = False, prefix: str = "_c") -> tuple:
    """A :class:`Program` binding ``exprs`` (of the state, the parameters and the dependent velocities at the
    representative pose, or ``kkt.general_velocities`` with ``general``), and the atom of each."""
    kkt = system.kkt
    prog = Program(prefix)
    exprs = [sp.sympify(e) for e in exprs]
    wanted = set(kkt.general_velocities if general else (kkt.velocities[i] for i in kkt.dependent))
    if set().union(*(e.free_symbols for e in exprs)) & wanted:
        solved = _velocities(prog, kkt, general)[0]
        exprs = [e.xreplace(solved) for e in exprs]
    return prog, prog.cse(exprs)


def _dynamics(system) -> tuple:
    """The right-hand side's program: ``(prog, a, v_dep, lam, end)`` (independent accelerations, dependent
    velocities and the held rates of :func:`_velocities`, multipliers as atoms; the multipliers' lines come last,
    from ``end`` on, so a caller that needs only ``a`` drops them).

    Formed once per system (its common subexpressions are most of the emitter's time) and shared by the right-hand
    side, the multipliers and the Jacobians; each caller gets its own copy of the lines.
    """
    cached = system.__dict__.get("_kkt_dynamics")
    if cached is None:
        cached = system.__dict__["_kkt_dynamics"] = _form_dynamics(system)
    prog, *rest = cached
    copy = Program(prog.prefix)
    copy.lines, copy._count = list(prog.lines), prog._count
    return (copy, *rest)


def _form_dynamics(system) -> tuple:
    kkt = system.kkt
    n, k = kkt.mass.rows, len(kkt.independent)
    dep, ind = list(kkt.dependent), list(kkt.independent)
    prog = Program()
    solved, Ad, Ai = _velocities(prog, kkt, general=False, held=True)
    m = len(dep)
    M, f, c = (X.xreplace(solved) for X in (kkt.mass, kkt.forcing, kkt.bias))
    pairs = [(i, j) for i in range(n) for j in range(i, n)]
    entries = prog.cse([M[i, j] for i, j in pairs] + list(f) + list(c))
    Ms = dict(zip(pairs, entries[:len(pairs)]))
    Mf = lambda i, j: Ms[min(i, j), max(i, j)]  # noqa: E731
    fs, cs = entries[len(pairs):len(pairs) + n], entries[len(pairs) + n:]
    X = lu_solve(prog, Ad, [[Ai[r][j] for r in range(m)] for j in range(k)] + [cs])
    T = [[sp.S.Zero] * k for _ in range(n)]
    d = [sp.S.Zero] * n
    for r, i in enumerate(dep):
        T[i] = [-X[j][r] for j in range(k)]
        d[i] = -X[k][r]
    for j, i in enumerate(ind):
        T[i][j] = sp.S.One
    MT = [[prog.let(sum((Mf(i, q) * T[q][j] for q in range(n)), sp.S.Zero)) for j in range(k)] for i in range(n)]
    Mr = {(i, j): prog.let(sum((T[q][i] * MT[q][j] for q in range(n)), sp.S.Zero)) for i in range(k)
          for j in range(i, k)}
    g = [prog.let(fs[i] - sum((Mf(i, q) * d[q] for q in range(n)), sp.S.Zero)) for i in range(n)]
    fr = [prog.let(sum((T[q][i] * g[q] for q in range(n)), sp.S.Zero)) for i in range(k)]
    a = ldl_solve(prog, Mr, fr)
    end = len(prog.lines)
    qdd = [prog.let(sum((T[i][j] * a[j] for j in range(k)), d[i])) for i in range(n)]
    residual = [prog.let(sum((Mf(i, q) * qdd[q] for q in range(n)), -fs[i])) for i in dep]
    (lam,) = lu_solve(prog, [[Ad[r][col] for r in range(m)] for col in range(m)], [residual])
    return prog, a, solved, lam, end


def _lines(prog: Program, targets: dict, indent: str = "    ") -> tuple[list, int]:
    """Code lines of a program and of ``target = atom`` assignments, and the operation count."""
    lines = [f"{indent}{s} = {_code(e)}" for s, e in prog.lines]
    lines += [f"{indent}{t} = {_code(e)}" for t, e in targets.items()]
    return lines, int(sum(sp.count_ops(e) for _, e in prog.lines))


def _check(prog: Program, allowed) -> None:
    bound = {s for s, _ in prog.lines}
    bad = set().union(set(), *(e.free_symbols for _, e in prog.lines)) - bound - set(allowed)
    if bad:
        raise ValueError(f"refusing to emit: undeclared symbols {sorted(map(str, bad))}")


def _rates(system, a, solved) -> list:
    a_of = dict(zip(system.accelerations, a))
    return [sp.sympify(e).xreplace({**a_of, **solved}) for e in system.state_rhs()]


def rhs_source(system) -> tuple:
    """The right-hand-side functions (:func:`.codegen.rhs_functions`: their signatures and op counts).

    The closed-form emitter writes the functions; the program's lines (placed first in each body) bind the
    rates, and those of the general pose's dependent velocities the pose rates.
    """
    spec = system.spec
    prog, a, solved, _, end = _dynamics(system)
    prog.lines = prog.lines[:end]
    rates = _rates(system, a, solved)
    allowed = set(system.state) | set(spec.params) | {names.t}
    _check(prog, allowed)
    lines, ops = _lines(prog, {})
    pose_exprs = [system.pose_rates[q] for q in spec.pose]
    pose_prog, pose_atoms = program(system, pose_exprs, general=True, prefix="_g")
    _check(pose_prog, allowed | set(spec.pose))
    pose_lines, pose_ops = _lines(pose_prog, {})
    return _rhs_source(system.state, spec.params, rates, spec.pose, pose_atoms, solve=(lines, ops),
                       known={s for s, _ in prog.lines} | {s for s, _ in pose_prog.lines},
                       pose_solve=(pose_lines, pose_ops))


def function_lines(system, exprs, targets, allowed, general: bool = False) -> tuple[list, int]:
    """Body lines binding ``targets`` to ``exprs`` (functions of the state and the dependent velocities) and their
    op count: what :func:`.codegen.cse_block` writes for a closed form (energy, powers, pose rates)."""
    prog, atoms = program(system, exprs, general=general)
    _check(prog, allowed)
    return _lines(prog, dict(zip(targets, atoms)))


def multiplier_lines(system, allowed) -> tuple[list, int]:
    """Body lines of ``multipliers`` (writing ``out``) and their op count."""
    prog, _, _, lam, _ = _dynamics(system)
    _check(prog, allowed)
    return _lines(prog, {f"out[{i}]": x for i, x in enumerate(lam)})


def jacobian_source(system, allowed) -> str:
    """``jacobian(s, p)`` and ``jacobian_p(s, p)`` of a numeric-elimination model: the right-hand side's program
    differentiated in forward mode (what :mod:`.jacobian` writes for a closed form), with their operation counts
    added to ``OP_COUNTS``."""
    prog, a, solved, _, end = _dynamics(system)
    prog.lines = prog.lines[:end]
    rates = _rates(system, a, solved)
    _check(prog, allowed)
    return jacobian.program_block_source(prog.lines, rates, system.state, system.spec.params)
