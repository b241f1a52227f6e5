"""Right-hand side of a model whose multipliers are eliminated numerically (``ReducedSystem.kkt``).

Past a size where the closed form stops paying (:data:`.engine.NUMERIC_FROM`), the generated module solves
``[[M, -A^T], [A, 0]] [q_ddot, lambda] = [f, -c]`` at the state instead of evaluating the closed form.  The
constraints give the dependent accelerations, ``q_ddot = T a + d`` with ``T = [-A_dep^-1 A_ind; I]`` and
``d = [-A_dep^-1 c; 0]`` (``a`` the independent accelerations), so ``a`` solves ``(T^T M T) a = T^T (f - M d)``:
a k x k symmetric positive-definite system (the kinetic energy on the constraint manifold), factored as
``L D L^T`` without pivoting, unrolled for its fixed size; the multipliers follow from the dependent rows,
``lambda = A_dep^-T (M q_ddot - f)_dep``.  Every entry is written once with common subexpressions shared (the
products are never expanded).  The code stays straight-line arithmetic on scalars: no array is allocated, no
LAPACK is bound, and ``integrators/irexpr.py`` writes it as IR like any closed form.
"""
from __future__ import annotations

import sympy as sp

from . import names
from .codegen import cse_block as _cse_block, rhs_functions as _rhs_source, unpack as _unpack


def _reduced(system):
    """``(Mr, fr, qdd, lam)``: the reduced matrix and forcing, and ``q_ddot`` and ``lambda`` in the symbols ``_a*``."""
    kkt = system.kkt
    n, k = kkt.mass.rows, len(kkt.independent)
    dep = [i for i in range(n) if i not in kkt.independent]
    A_ind = kkt.constraint.extract(list(range(kkt.constraint.rows)), list(kkt.independent))
    T, d = sp.zeros(n, k), sp.zeros(n, 1)
    T_dep, d_dep = -kkt.dependent_inverse * A_ind, -kkt.dependent_inverse * kkt.bias
    for r, i in enumerate(dep):
        T[i, :], d[i] = T_dep[r, :], d_dep[r]
    for r, i in enumerate(kkt.independent):
        T[i, r] = 1
    MT = kkt.mass * T
    Mr = T.T * MT
    fr = T.T * (kkt.forcing - kkt.mass * d)
    a = sp.Matrix([names.Own(f"_a{i}", real=True) for i in range(k)])
    qdd = T * a + d
    residual = kkt.mass * qdd - kkt.forcing
    lam = kkt.dependent_inverse.T * sp.Matrix([residual[i] for i in dep])
    return Mr, fr, a, lam


def _ldl_lines(k: int) -> list:
    """Straight-line ``L D L^T`` solve of ``_m{i}_{j} a = _f{i}`` (i <= j stored) into ``_a{i}``."""
    m = lambda i, j: f"_m{min(i, j)}_{max(i, j)}"  # noqa: E731
    lines = []
    for j in range(k):
        lines.append(f"    _d{j} = {m(j, j)}" + "".join(f" - _l{j}_{p}*_l{j}_{p}*_d{p}" for p in range(j)))
        for i in range(j + 1, k):
            lines.append(f"    _l{i}_{j} = ({m(i, j)}" + "".join(f" - _l{i}_{p}*_l{j}_{p}*_d{p}" for p in range(j))
                         + f")/_d{j}")
    for i in range(k):
        lines.append(f"    _y{i} = _f{i}" + "".join(f" - _l{i}_{p}*_y{p}" for p in range(i)))
    for i in reversed(range(k)):
        lines.append(f"    _a{i} = _y{i}/_d{i}" + "".join(f" - _l{p}_{i}*_a{p}" for p in range(i + 1, k)))
    return lines


def _solve_block(system, allowed):
    """Lines binding ``_a*`` (the independent accelerations) and their op count."""
    Mr, fr, _, _ = _reduced(system)
    k = Mr.rows
    pairs = [(i, j) for i in range(k) for j in range(i, k)]
    lines, ops = _cse_block([Mr[i, j] for i, j in pairs] + list(fr), [f"_m{i}_{j}" for i, j in pairs]
                            + [f"_f{i}" for i in range(k)], allowed, prefix="_e")
    return lines + _ldl_lines(k), ops + k * (k + 1) * (2 * k + 1) // 3 + 2 * k * k


def rhs_source(system) -> tuple:
    """The right-hand-side functions (:func:`.codegen.rhs_functions`: their signatures and op counts).

    The closed-form emitter writes the functions; the accelerations enter as the symbols ``_a*`` that the solve
    lines (placed first in each body) bind.
    """
    spec = system.spec
    _, _, a, _ = _reduced(system)
    a_of = {acc: a[r] for r, acc in enumerate(system.accelerations)}
    rates = [a_of.get(e, e) for e in system.state_rhs()]
    solve = _solve_block(system, set(system.state) | set(spec.params) | {names.t})
    return _rhs_source(system.state, spec.params, rates, spec.pose, [system.pose_rates[q] for q in spec.pose],
                       solve=solve, known=set(a))


def multiplier_lines(system, allowed) -> tuple[list, int]:
    """Body lines of ``multipliers`` (writing ``out``) and their op count."""
    _, _, a, lam = _reduced(system)
    solve, ops = _solve_block(system, allowed)
    lam_lines, lam_ops = _cse_block(list(lam), [f"out[{i}]" for i in range(len(lam))], set(allowed) | set(a))
    return solve + lam_lines, ops + lam_ops


def _jacobian_function(system, name: str, wrt: list, allowed) -> tuple[str, int]:
    """``name(s, p)``: ``d rates / d wrt`` exactly, by implicit differentiation of ``Mr a = fr``.

    ``d a / d x = Mr^-1 (d fr / d x - (d Mr / d x) a)``: the factor of ``Mr`` the right-hand side computes is
    reused for every column (one forward and one back substitution each).
    """
    spec = system.spec
    Mr, fr, a, _ = _reduced(system)
    k = Mr.rows
    a_of = {acc: a[r] for r, acc in enumerate(system.accelerations)}
    rates = [a_of.get(e, e) for e in system.state_rhs()]
    solve, ops = _solve_block(system, allowed)
    g_exprs = [sp.diff(fr[i], x) - sum((sp.diff(Mr[i, c], x) * a[c] for c in range(k)), sp.S.Zero)
               for x in wrt for i in range(k)]
    g_lines, g_ops = _cse_block(g_exprs, [f"_g{i}_{j}" for j in range(len(wrt)) for i in range(k)],
                                set(allowed) | set(a), prefix="_h")
    z_lines = []
    for j in range(len(wrt)):  # L y = g, D w = y, L^T z = w (the factors of the solve block)
        z_lines += [f"    _w{i}_{j} = _g{i}_{j}" + "".join(f" - _l{i}_{c}*_w{c}_{j}" for c in range(i)) for i in range(k)]
        z_lines += [f"    _z{i}_{j} = _w{i}_{j}/_d{i}" + "".join(f" - _l{c}_{i}*_z{c}_{j}" for c in range(i + 1, k))
                    for i in reversed(range(k))]
    Z = {(c, j): names.Own(f"_z{c}_{j}", real=True) for c in range(k) for j in range(len(wrt))}
    outputs, targets = [], []
    for r, e in enumerate(rates):
        for j, x in enumerate(wrt):
            d = sp.diff(e, x) + sum((sp.diff(e, a[c]) * Z[c, j] for c in range(k)), sp.S.Zero)
            if d != 0:
                outputs.append(d)
                targets.append(f"out[{r}, {j}]")
    out_lines, out_ops = _cse_block(outputs, targets, set(allowed) | set(a) | set(Z.values()), prefix="_o")
    args = "s, p, t" if names.t in set(allowed) else "s, p"
    n = len(rates)
    total = int(ops + g_ops + out_ops + 2 * k * k * len(wrt))
    nl = "\n"
    unpack = _unpack([str(x) for x in system.state], "s") + _unpack([str(q) for q in spec.params], "p")
    return f'''

@njit(cache=True)
def {name}({args}):
    """d(state rate)/d({'state' if name == 'jacobian' else 'parameters'}), exact: the multipliers' system
    differentiated implicitly, shape ({n}, {len(wrt)}) ({total} operations)."""
    out = np.zeros(({n}, {len(wrt)}))
{nl.join(unpack)}
{nl.join(solve + g_lines + z_lines + out_lines)}
    return out
''', total


def jacobian_source(system, allowed) -> str:
    """``jacobian(s, p)`` and ``jacobian_p(s, p)`` of a numeric-elimination model (what :mod:`.jacobian` writes
    for a closed form), with their operation counts added to ``OP_COUNTS``."""
    src_s, ops_s = _jacobian_function(system, "jacobian", list(system.state), allowed)
    src_p, ops_p = _jacobian_function(system, "jacobian_p", list(system.spec.params), allowed)
    return (f"\n\n#: operation counts of the Jacobians (derivation/kkt_emit.py: implicit differentiation)\n"
            f"OP_COUNTS.update(jacobian={ops_s}, jacobian_p={ops_p})" + src_s + src_p)
