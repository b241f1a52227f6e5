"""Right-hand side of a model whose multipliers are eliminated numerically (``ReducedSystem.kkt``).

Past a size where the closed form stops paying (:data:`.engine.NUMERIC_FROM`), the generated module assembles
``[[M, -A^T], [A, 0]] [q_ddot, lambda] = [f, -c]`` at the state, common subexpressions shared across all its
entries, and solves it by Gaussian elimination with partial pivoting written as plain loops (numba compiles
them in well under a second; its LAPACK bindings would cost ~12 s cold, NOTES.md).  ``rhs_into`` then reads the
independent accelerations from the solution and ``multipliers`` the multipliers.  The functions have the
signatures of :func:`.emit._rhs_source`; ``constants(p)`` hoists nothing (``q`` is a copy of ``p``), and since
the bodies call other functions, ``integrators/irexpr.py`` declines them and numba's compilation is used.
"""
from __future__ import annotations

from . import names
from .emit import _cse_block, _unpack

_LU = '''@njit(cache=True)
def _lu_solve(a, b):
    """Solve ``a x = b`` in place (``b`` becomes ``x``): Gaussian elimination with partial pivoting."""
    n = b.shape[0]
    for k in range(n):
        piv = k
        big = abs(a[k, k])
        for i in range(k + 1, n):
            if abs(a[i, k]) > big:
                big = abs(a[i, k])
                piv = i
        if piv != k:
            for j in range(n):
                tmp = a[k, j]
                a[k, j] = a[piv, j]
                a[piv, j] = tmp
            tmp = b[k]
            b[k] = b[piv]
            b[piv] = tmp
        for i in range(k + 1, n):
            f = a[i, k] / a[k, k]
            for j in range(k + 1, n):
                a[i, j] -= f * a[k, j]
            b[i] -= f * b[k]
    for k in range(n - 1, -1, -1):
        acc = b[k]
        for j in range(k + 1, n):
            acc -= a[k, j] * b[j]
        b[k] = acc / a[k, k]
'''


def rhs_source(system) -> tuple[str, dict]:
    """Source of ``_kkt_solve`` and of the right-hand-side functions; returns it and the operation counts."""
    spec, kkt = system.spec, system.kkt
    nl = "\n"
    state, params, pose = ([str(x) for x in xs] for xs in (system.state, spec.params, spec.pose))
    n, npose, nparams = len(state), len(pose), len(params)
    K, r = kkt.matrix()
    size = K.rows
    entries = [(i, j) for i in range(size) for j in range(size) if K[i, j] != 0]
    allowed = set(system.state) | set(spec.params) | {names.t}
    kkt_lines, kkt_ops = _cse_block([K[i, j] for i, j in entries] + list(r),
                                    [f"_K[{i}, {j}]" for i, j in entries] + [f"_x[{i}]" for i in range(size)], allowed)
    rates = system.state_rhs()
    solved = {a: spec.accelerations.index(a) for a in system.accelerations}
    slow = [(i, e) for i, e in enumerate(rates) if e not in solved]
    rate_lines, rate_ops = _cse_block([e for _, e in slow], [f"ds[{i}]" for i, _ in slow], allowed)
    rate_lines += [f"    ds[{i}] = _x[{solved[e]}]" for i, e in enumerate(rates) if e in solved]
    pose_exprs = [system.pose_rates[q] for q in spec.pose]
    pose_lines, pose_ops = _cse_block(pose_exprs, [f"ds[{n + i}]" for i in range(npose)], allowed | set(spec.pose))
    coords = ", ".join(map(str, spec.coordinates))

    def body(par: str, with_pose: bool) -> str:  # every ``*_into`` writes its rates itself (modulecheck reads them)
        return nl.join([f"    _x = np.empty({size})", f"    _kkt_solve(t, s, {par}, _x)", *_unpack(state, "s"),
                        *(_unpack(pose, "s", start=n) if with_pose else []), *_unpack(params, par), *rate_lines,
                        *(pose_lines if with_pose else [])])
    src = f'''{_LU}

@njit(cache=True)
def _kkt_solve(t, s, p, _x):
    """Solve [[M, -A^T], [A, 0]] [q_ddot, lambda] = [f, -c] at the state ``s`` into ``_x``: the accelerations of
    ({coords}), then the multipliers ({kkt_ops} operations to assemble, then a {size} x {size} solve)."""
    _K = np.zeros(({size}, {size}))
{nl.join(_unpack(state, "s"))}
{nl.join(_unpack(params, "p"))}
{nl.join(kkt_lines)}
    _lu_solve(_K, _x)


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (the accelerations from ``_kkt_solve``, then {rate_ops} operations)."""
{body("p", False)}


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length {n}."""
    ds = np.empty({n})
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters (the numeric elimination hoists nothing)."""
    q = np.empty({nparams})
{nl.join(f"    q[{i}] = p[{i}]" for i in range(nparams))}
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p``."""
{body("q", False)}
'''
    ops = {"rhs": kkt_ops + rate_ops, "constants": 0, "rhs_q": kkt_ops + rate_ops}
    if not npose:
        return src, ops
    ops.update(rhs_pose=kkt_ops + rate_ops + pose_ops, rhs_pose_q=kkt_ops + rate_ops + pose_ops)
    return src + f'''

@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds``."""
{body("p", True)}


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length {n + npose}."""
    ds = np.empty({n + npose})
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p``."""
{body("q", True)}
''', ops


def multiplier_lines(system, timed: bool) -> tuple[list, int]:
    """Body lines of ``multipliers`` (writing ``out``): the multipliers from ``_kkt_solve``."""
    n, size = system.kkt.mass.rows, system.kkt.mass.rows + system.kkt.constraint.rows
    return ([f"    _x = np.empty({size})", f"    _kkt_solve({'t' if timed else '0.0'}, s, p, _x)"]
            + [f"    out[{i}] = _x[{n + i}]" for i in range(size - n)]), 0
