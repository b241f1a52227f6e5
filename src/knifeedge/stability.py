"""Linear stability: the linearization at a state, steady motions and where they change stability.

Everything is read from the generated module: the exact Jacobian (``jvp_into`` of the identity: forward mode
through the rates, the function the Lyapunov loop compiles; a model with inputs, or a module without it, through
``jacobian``), the invariants of the closed
state (``STATE_INVARIANTS``, ``invariant_gradients``) and the families of steady motions (``STEADY_FAMILIES``,
``steady_state``), written by ``derivation/jacobian.py`` and ``derivation/steady.py``.

The trivial directions are separated by construction, not by the size of their eigenvalues: the physical
phase space at ``y`` is the subspace orthogonal to the invariants' gradients and to the tangent of the family
of steady motions through ``y``.  On a family (where the flow keeps both the invariants' level set and the
family) these subspaces are invariant under the linearization ``A``, so the physical eigenvalues are those of
``A`` restricted to the quotient, ``Q^T A Q`` with ``Q`` an orthonormal basis of the physical directions, and
the trivial ones those of the invariants' block and the family's tangent; together they are the eigenvalues of
``A``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from . import _validate
from .models import Model

#: a real part counts as nonzero above this fraction of the size of the linearization (its physical block's norm):
#: the eigenvalues of a nearly defective block, at a collision of two imaginary pairs, are only fixed to about
#: machine epsilon over their separation
MARGINAL = 1e-7
#: most points of the grid of :func:`stability_boundaries` (a point costs ~0.2 ms: the celt's 100,000 take ~20 s)
MAX_GRID = 100_000


@dataclass(frozen=True)
class Mode:
    """One eigenvalue of the linearization with its eigenvector (closed-state coordinates) and what it is."""

    name: str
    eigenvalue: complex
    vector: np.ndarray

    @property
    def growth_rate(self) -> float:
        """Real part of the eigenvalue (1/time): > 0 grows, < 0 decays."""
        return float(self.eigenvalue.real)

    @property
    def frequency(self) -> float:
        """Imaginary part of the eigenvalue (angular frequency, 1/time)."""
        return float(self.eigenvalue.imag)


@dataclass(frozen=True)
class Linearization:
    """The linearization of a model's closed state at ``y``.

    Attributes
    ----------
    A : (n, n) array, the Jacobian ``d rhs / d y`` at ``y``.
    eigenvalues : (n,) complex array, every eigenvalue of ``A``; ``eigenvectors`` (n, n), columns.
    modes : the physical modes (eigenvalues of ``A`` on the physical directions), largest real part first, each
        named by its largest component (the family's ``mode_names``, else the state's name).
    trivial : the trivial directions, each a :class:`Mode` whose ``name`` says what it is (an invariant of the
        closed state, or the tangent of the family of steady motions).
    family, value : the family of steady motions through ``y`` and its parameter there (``None`` if none).
    """

    A: np.ndarray
    eigenvalues: np.ndarray
    eigenvectors: np.ndarray
    modes: tuple
    trivial: tuple
    state_names: tuple
    family: str | None = None
    value: float | None = None
    #: orthonormal basis of the physical directions (columns) and ``A`` in it (``basis.T @ A @ basis``)
    basis: np.ndarray | None = None
    A_physical: np.ndarray | None = None

    @property
    def physical_eigenvalues(self) -> np.ndarray:
        return np.array([m.eigenvalue for m in self.modes])

    @property
    def max_growth_rate(self) -> float:
        """Largest real part of the physical modes."""
        return max((m.growth_rate for m in self.modes), default=float("nan"))


def _family_index(m: Model, family: str) -> int:
    families = list(getattr(m.module, "STEADY_FAMILIES", {}))
    if not isinstance(family, str) or family not in families:
        raise ValueError(f"unknown `family` {family!r} for {m.name} ({m.fidelity}); accepted: "
                         f"{', '.join(families) or 'none (the model declares no steady motions)'}")
    return families.index(family)


def steady_state(m: Model, p, family: str, value: float) -> np.ndarray:
    """The closed state of the steady motion ``family`` at the parameter ``value``."""
    k = _family_index(m, family)
    return _steady(m, m.check_params(p), k, value)


def _steady(m: Model, p: np.ndarray, k: int, value: float) -> np.ndarray:
    """:func:`steady_state` of the family of index ``k`` with ``p`` validated."""
    return _steady_rows(m, k, value, p)[0].copy()


def _steady_rows(m: Model, k: int, value: float, p: np.ndarray) -> np.ndarray:
    """The generated ``steady_state(k, value, p)`` (the state and the tangent of family ``k``) as plain Python
    (``py_func``): a few assignments, called a few hundred times at most, cost less so than numba's compile of
    them on a first run (0.13-0.26 s of CPU; docs/performance.md, "the compiles other than the DOP853 driver")."""
    f = m.module.steady_state
    return getattr(f, "py_func", f)(k, float(value), p)


def _through(m: Model, y: np.ndarray, p: np.ndarray):
    """``(family, value)`` of the steady motion through ``y``, or ``(None, None)``."""
    for k, (name, info) in enumerate(getattr(m.module, "STEADY_FAMILIES", {}).items()):
        if not info["value_state"]:
            continue
        value = float(y[m.closed_state_names.index(info["value_state"])])
        if np.allclose(_steady_rows(m, k, value, p)[0], y, rtol=1e-12, atol=1e-12):
            return name, value
    return None, None


def jacobian(m: Model, y: np.ndarray, p: np.ndarray) -> np.ndarray:
    """``d rhs / d y`` at the closed state ``y``: the generated Jacobian-vector product of the identity.

    The same derivative as ``m.jacobian`` (forward mode through the rates' subexpressions instead of the
    differentiated expressions: equal to round-off), and the function :func:`knifeedge.lyapunov` compiles, so
    that a linearization beside Lyapunov exponents compiles nothing more; the full ``jacobian`` (2,360
    operations for the celt against ``jvp_into``'s 443 + 381 per column) is much slower to compile.  A model with
    inputs (whose Jacobian needs the time) or a module written without ``jvp_into`` goes through ``m.jacobian``.
    """
    if m.input_names or not hasattr(m.module, "jvp_into"):
        return m.jacobian(y, p)
    n = y.size
    out = np.empty((n, n))
    m.module.jvp_into(y, np.ascontiguousarray(p), np.eye(n), np.empty(n), out)
    return out


def _basis(rows: np.ndarray, n: int) -> tuple:
    """Orthonormal bases ``(N, Q)`` of the span of ``rows`` and of its orthogonal complement in R^n."""
    if rows.shape[0] == 0:
        return np.zeros((n, 0)), np.eye(n)
    u, s, vt = np.linalg.svd(rows)
    rank = int(np.sum(s > 1e-12 * s[0]))
    return vt[:rank].T, vt[rank:].T


def _name(vector: np.ndarray, names: tuple, mode_names: dict, skip: str) -> str:
    weights = np.abs(vector)
    labelled = [i for i, nm in enumerate(names) if nm in mode_names]
    if labelled and weights[labelled].max() > 1e-8 * weights.max():
        i = max(labelled, key=lambda j: weights[j])
        return mode_names[names[i]]
    order = [i for i in np.argsort(-weights) if names[i] != skip] or [int(np.argmax(weights))]
    return names[order[0]]


def linearize(m: Model, y, p, family: str | None = None) -> Linearization:
    """Linearize ``m`` at the state ``y`` (closed or pose-extended) with parameters ``p``.

    ``family``: the family of steady motions whose tangent is a trivial direction (default: the declared family
    through ``y``, if any).  Works at any state; off a family, or away from an equilibrium, the physical block
    is ``A`` on the directions orthogonal to the invariants' gradients.
    """
    p = m.check_params(p)
    y = m._closed(y)
    if m.jacobian_needs_time:
        raise ValueError(f"{m.name} depends on the time explicitly: a linearization at a state alone is not "
                         f"defined (its steady motions are those of autonomous models)")
    if family is None:
        family, value = _through(m, y, p)
    else:
        _family_index(m, family)
        value = _family_value(m, y, family)
    return _linearize(m, y, p, family, value)


def _family_value(m: Model, y: np.ndarray, family: str) -> float | None:
    """The parameter of the steady motions ``family`` read from the closed state ``y`` (``None`` if it has none)."""
    info = m.module.STEADY_FAMILIES[family]
    return float(y[m.closed_state_names.index(info["value_state"])]) if info["value_state"] else None


def _frame(m: Model, y: np.ndarray, p: np.ndarray, family: str | None, value: float | None) -> tuple:
    """``(A, G, N, t, Q, B)`` at the closed state ``y`` (``p`` validated): the Jacobian, the invariants' gradients
    and an orthonormal basis ``N`` of their complement, the unit tangent of the family (``None`` off one), the
    basis ``Q`` of the physical directions and ``B = Q^T A Q``."""
    n = y.size
    A = jacobian(m, y, p)
    G = m.module.invariant_gradients(y, p) if getattr(m.module, "STATE_INVARIANTS", ()) else np.zeros((0, n))
    N, _ = _basis(G, n)
    t, rows = None, G
    if family is not None:
        t = _steady_rows(m, _family_index(m, family), value if value is not None else 0.0, p)[1]
        t = t - N @ (N.T @ t)
        t = t / np.linalg.norm(t)
        rows = np.vstack([G, t])
    _, Q = _basis(rows, n)
    return A, G, N, t, Q, Q.T @ A @ Q


def _linearize(m: Model, y: np.ndarray, p: np.ndarray, family: str | None, value: float | None) -> Linearization:
    """:func:`linearize` at the closed state ``y`` with ``p`` validated and the family's ``value`` known."""
    names = m.closed_state_names
    A, G, N, t, Q, B = _frame(m, y, p, family, value)
    eigenvalues, eigenvectors = np.linalg.eig(A)
    inv_names = tuple(getattr(m.module, "STATE_INVARIANTS", ()))
    trivial = []
    if N.shape[1]:
        lam, w = np.linalg.eig(N.T @ A @ N)
        for j in range(len(lam)):
            v = N @ w[:, j]
            which = int(np.argmax(np.abs(G @ v.real) + np.abs(G @ v.imag)))
            trivial.append(Mode(f"invariant: {inv_names[which]}", complex(lam[j]), v))
    mode_names, skip = {}, ""
    if family is not None:
        info = m.module.STEADY_FAMILIES[family]
        mode_names, skip = info["mode_names"], info["value_state"]
        trivial.append(Mode(f"family {family}: {info['description']}", complex(t @ A @ t), t))
    lam, w = np.linalg.eig(B)
    order = np.lexsort((-lam.imag, -lam.real))
    modes = tuple(Mode(_name(Q @ w[:, j], names, mode_names, skip), complex(lam[j]), Q @ w[:, j]) for j in order)
    return Linearization(A, eigenvalues, eigenvectors, modes, tuple(trivial), names, family, value, Q, B)


@dataclass(frozen=True)
class StabilityTable:
    """The physical eigenvalues along a family: ``eigenvalues[i]`` at ``values[i]`` (largest real part first)."""

    family: str
    values: np.ndarray
    eigenvalues: np.ndarray
    names: tuple

    @property
    def max_growth_rate(self) -> np.ndarray:
        return self.eigenvalues.real.max(axis=1)


def _values(values, what: str = "`values`") -> np.ndarray:
    """``values``, a number or a sequence of them (the rule of :mod:`knifeedge._validate`), as a 1-D array."""
    if isinstance(values, (str, bytes)) or not hasattr(values, "__len__") or np.ndim(values) == 0:
        arr = np.array([_validate.real(values, f"each of {what}")])
    else:
        arr = _validate.real_array(values, what)
    if arr.ndim != 1 or arr.size == 0 or not np.isfinite(arr).all():
        raise ValueError(f"{what} must be one or more finite numbers, got {values!r}")
    return arr


def stability(m: Model, p, family: str, values) -> StabilityTable:
    """The physical eigenvalues of the steady motions ``family`` at each of ``values`` (its parameter)."""
    p = m.check_params(p)
    values = _values(values)
    rows, names = [], []
    k = _family_index(m, family)
    for v in values:
        y = _steady(m, p, k, v)
        lin = _linearize(m, y, p, family, _family_value(m, y, family))
        rows.append(lin.physical_eigenvalues)
        names.append(tuple(md.name for md in lin.modes))
    return StabilityTable(family, values, np.array(rows), tuple(names))


def _growth(m: Model, p: np.ndarray, family: str, v: float) -> tuple:
    """Largest physical real part at ``v`` and the threshold below which it counts as zero (``p`` validated: the
    eigenvalues of the physical block alone, as :func:`linearize` computes them, without naming the modes)."""
    y = _steady(m, p, _family_index(m, family), v)
    B = _frame(m, y, p, family, _family_value(m, y, family))[-1]
    return float(np.linalg.eig(B)[0].real.max()), MARGINAL * max(float(np.linalg.norm(B)), 1e-300)


def stability_boundaries(m: Model, p, family: str, interval, n_grid: int = 400) -> np.ndarray:
    """Every value of the family's parameter in ``interval = (lo, hi)`` where the steady motion changes stability.

    The largest real part of the physical modes is tabulated on ``n_grid`` points; each change of its sign
    (a real part counts as zero below :data:`MARGINAL` times the norm of the physical block, as for the imaginary pairs of a
    conservative system) is refined: by Brent's method on the real part where it crosses zero transversally
    (a pair crossing the imaginary axis), else by bisection of the sign (two imaginary pairs colliding), to
    1e-13 relative.
    """
    p = m.check_params(p)
    lo, hi = _values(interval, "`interval`")[:2] if np.size(interval) == 2 else (None, None)
    if lo is None or not lo < hi:
        raise ValueError(f"`interval` must be (lo, hi) with lo < hi, got {interval!r}")
    if isinstance(n_grid, bool) or not isinstance(n_grid, (int, np.integer)) or not 2 <= n_grid <= MAX_GRID:
        raise ValueError(f"`n_grid` must be an integer from 2 to {MAX_GRID}, got {n_grid!r}")
    _family_index(m, family)
    return growth_boundaries(lambda v: _growth(m, p, family, v), lo, hi, n_grid)


def growth_boundaries(growth, lo: float, hi: float, n_grid: int = 400) -> np.ndarray:
    """Every value in ``(lo, hi)`` where ``growth(v) = (largest physical real part, threshold of zero)`` changes
    sign: tabulated on ``n_grid`` points, each change refined as :func:`stability_boundaries` says (the search
    behind it, also for linear models given as matrices, e.g. the scene ``bicycle_stability``)."""
    grid = np.linspace(lo, hi, n_grid)
    state = [growth(v) for v in grid]
    unstable = [g > thr for g, thr in state]
    out = []
    xtol = 1e-13 * max(abs(lo), abs(hi))
    for i in range(n_grid - 1):
        if unstable[i] == unstable[i + 1]:
            continue
        (ga, ta), (gb, tb) = state[i], state[i + 1]
        a, b = grid[i], grid[i + 1]
        if min(abs(ga) - ta, abs(gb) - tb) > 0 and (ga > 0) != (gb > 0):
            out.append(brentq(lambda v: growth(v)[0], a, b, xtol=xtol, rtol=1e-15))
            continue
        ua = unstable[i]
        while b - a > max(xtol, 1e-15 * abs(a + b)):
            mid = 0.5 * (a + b)
            g, thr = growth(mid)
            if (g > thr) == ua:
                a = mid
            else:
                b = mid
        out.append(0.5 * (a + b))
    return np.array(out)
