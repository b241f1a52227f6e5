"""Lyapunov exponents of the physical phase space by the Benettin/QR method on the emitted variational equations.

The state and ``k`` tangent vectors are stepped together by the classical fourth-order Runge-Kutta method in one
compiled loop (the generated ``rhs_into`` and ``jacobian``; no Python call per step); every ``tau`` of time the
tangent vectors are re-orthonormalized (modified Gram-Schmidt, the QR of ChaosTools.jl's ``lyapunovspectrum``)
and the logarithms of the diagonal of R are summed.  The tangent vectors start orthogonal to the gradients of the
closed state's invariants (``STATE_INVARIANTS``), so they span the physical phase space, which the tangent flow
keeps (the round-off that leaks out of it is projected away before each re-orthonormalization).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit, types

from .models import Model

@njit(cache=True)
def _times(J, Q, out):
    n, k = Q.shape
    for i in range(n):
        for j in range(k):
            acc = 0.0
            for m in range(n):
                acc += J[i, m] * Q[m, j]
            out[i, j] = acc


@njit(cache=True)
def _orthonormalize(Q, sums):
    """Modified Gram-Schmidt in place; adds log |R_jj| to ``sums``."""
    n, k = Q.shape
    for j in range(k):
        for i in range(j):
            r = 0.0
            for m in range(n):
                r += Q[m, i] * Q[m, j]
            for m in range(n):
                Q[m, j] -= r * Q[m, i]
        norm = 0.0
        for m in range(n):
            norm += Q[m, j] * Q[m, j]
        norm = math.sqrt(norm)
        sums[j] += math.log(norm)
        for m in range(n):
            Q[m, j] /= norm


@njit(cache=True)
def _project_out(G, Q):
    """Remove from the columns of ``Q`` their components along the rows of ``G`` (orthonormalized here)."""
    m, n = G.shape
    for i in range(m):
        for j in range(i):
            r = 0.0
            for c in range(n):
                r += G[i, c] * G[j, c]
            for c in range(n):
                G[i, c] -= r * G[j, c]
        norm = 0.0
        for c in range(n):
            norm += G[i, c] * G[i, c]
        norm = math.sqrt(norm)
        for c in range(n):
            G[i, c] /= norm
        for j in range(Q.shape[1]):
            r = 0.0
            for c in range(n):
                r += G[i, c] * Q[c, j]
            for c in range(n):
                Q[c, j] -= r * G[i, c]


@njit(cache=True)
def _shifted(out, x, c, dx):
    """``out = x + c dx`` (vectors)."""
    for i in range(x.size):
        out[i] = x[i] + c * dx[i]


@njit(cache=True)
def _rk4_update(x, h, d1, d2, d3, d4):
    """The classical Runge-Kutta step ``x += h/6 (d1 + 2 d2 + 2 d3 + d4)`` in place (vectors)."""
    for i in range(x.size):
        x[i] += h / 6.0 * (d1[i] + 2.0 * d2[i] + 2.0 * d3[i] + d4[i])


#: the first-class function types of a generated module's ``rhs_into(t, s, p, ds)``, ``jacobian(s, p)`` and
#: ``invariant_gradients(s, p)``: the loop below is compiled for these types, not for one module's functions, so
#: one compiled loop (in numba's cache, once per machine) serves every model and calls them through their addresses
_VECTOR = types.float64[::1]
_MATRIX = types.float64[:, ::1]
_RHS = types.FunctionType(types.none(types.float64, _VECTOR, _VECTOR, _VECTOR))
_MATRIX_OF_STATE = types.FunctionType(_MATRIX(_VECTOR, _VECTOR))
_SIGNATURE = (_RHS, _MATRIX_OF_STATE, _MATRIX_OF_STATE, _VECTOR, _MATRIX, _VECTOR, types.float64, types.int64,
              types.int64)


@njit(cache=True)
def _benettin(rhs_into, jacobian, gradients, y, Q, p, h, n_blocks, steps_per_block):
    """RK4 on the state ``y`` and the tangent vectors ``Q`` (n x k) for ``n_blocks`` blocks of ``steps_per_block``
    steps of ``h``, re-orthonormalized after each block; returns the final y, Q, the sums of log |R_jj|, and the
    times and running estimates of the re-orthonormalizations (from time 0)."""
    n, k = Q.shape
    sums = np.zeros(k)
    hist = np.empty((n_blocks, k))
    hist_t = np.empty(n_blocks)
    k1, k2, k3, k4, yt = np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    K1, K2, K3, K4, Qt = (np.empty((n, k)), np.empty((n, k)), np.empty((n, k)), np.empty((n, k)),
                          np.empty((n, k)))
    # the tangent vectors as flat views, so that one loop over a vector serves the state and the tangents
    q, q1, q2, q3, q4, qt = Q.ravel(), K1.ravel(), K2.ravel(), K3.ravel(), K4.ravel(), Qt.ravel()
    for b in range(n_blocks):
        for _ in range(steps_per_block):
            rhs_into(0.0, y, p, k1)
            _times(jacobian(y, p), Q, K1)
            _shifted(yt, y, 0.5 * h, k1)
            _shifted(qt, q, 0.5 * h, q1)
            rhs_into(0.0, yt, p, k2)
            _times(jacobian(yt, p), Qt, K2)
            _shifted(yt, y, 0.5 * h, k2)
            _shifted(qt, q, 0.5 * h, q2)
            rhs_into(0.0, yt, p, k3)
            _times(jacobian(yt, p), Qt, K3)
            _shifted(yt, y, h, k3)
            _shifted(qt, q, h, q3)
            rhs_into(0.0, yt, p, k4)
            _times(jacobian(yt, p), Qt, K4)
            _rk4_update(y, h, k1, k2, k3, k4)
            _rk4_update(q, h, q1, q2, q3, q4)
        # round-off leaks into the invariants' directions (rate 0), which would outgrow decaying directions
        _project_out(gradients(y, p), Q)
        _orthonormalize(Q, sums)
        hist_t[b] = (b + 1) * steps_per_block * h
        hist[b] = sums / hist_t[b]
    return y, Q, sums, hist_t, hist


def _kernel():
    """The compiled Benettin loop for the first-class function types (compiled, or loaded from numba's cache,
    once per process; its entry point takes a module's numba functions and passes their addresses)."""
    if _SIGNATURE not in _benettin.overloads:
        _benettin.compile(_SIGNATURE)
    return _benettin.overloads[_SIGNATURE].entry_point


@dataclass(frozen=True)
class LyapunovResult:
    """Lyapunov exponents (1/time, largest first) and their running estimates.

    exponents : (k,) the estimates at ``t_end``.
    history_t : (n_blocks,) times of the re-orthonormalizations; ``history`` (n_blocks, k) the running estimates
        there (sorted like ``exponents``), to judge convergence.
    uncertainty : (k,) half the spread of each running estimate over the last quarter of the run.
    y : the final closed state; ``h``, ``tau``: the step and the re-orthonormalization interval used.
    """

    exponents: np.ndarray
    history_t: np.ndarray
    history: np.ndarray
    uncertainty: np.ndarray
    y: np.ndarray
    h: float
    tau: float


def _physical_basis(m: Model, y: np.ndarray, p: np.ndarray, k: int | None) -> np.ndarray:
    from .stability import _basis

    n = len(m.closed_state_names)
    G = m.module.invariant_gradients(y, p) if getattr(m.module, "STATE_INVARIANTS", ()) else np.zeros((0, n))
    _, Q = _basis(G, n)
    if k is None:
        return np.ascontiguousarray(Q)
    if not isinstance(k, int) or not 1 <= k <= Q.shape[1]:
        raise ValueError(f"`k` must be an integer from 1 to {Q.shape[1]} (the physical dimension), got {k!r}")
    return np.ascontiguousarray(Q[:, :k])


def lyapunov(m: Model, y0, p, t_end: float, k: int | None = None, h: float | None = None,
             tau: float | None = None, t0: float = 0.0) -> LyapunovResult:
    """The ``k`` largest Lyapunov exponents (default: all, of the physical phase space) from ``y0`` over
    ``(t0, t_end)``.

    ``h``: the Runge-Kutta step (default: 1/50 of the period of the fastest linear mode at ``y0``);
    ``tau``: the time between re-orthonormalizations (default ``10 h``), rounded to a whole number of steps.
    """
    p = m.check_params(p)
    y = m._closed(y0).copy()
    if m.jacobian_needs_time:
        raise ValueError(f"{m.name} depends on the time explicitly: its Lyapunov exponents are not computed "
                         f"(the variational loop steps autonomous systems)")
    if not (isinstance(t_end, (int, float)) and math.isfinite(t_end) and t_end > t0):
        raise ValueError(f"`t_end` must be a finite time after `t0` = {t0}, got {t_end!r}")
    span = float(t_end) - float(t0)
    if h is None:
        rho = float(np.max(np.abs(np.linalg.eigvals(m.jacobian(y, p)))))
        h = min(2 * math.pi / rho / 50 if rho > 0 else span / 1e4, span / 100)
    if not (isinstance(h, (int, float)) and math.isfinite(h) and 0 < h <= span):
        raise ValueError(f"`h` must be a positive step no longer than the span, got {h!r}")
    tau = 10 * h if tau is None else tau
    if not (isinstance(tau, (int, float)) and math.isfinite(tau) and h <= tau <= span):
        raise ValueError(f"`tau` must lie between the step `h` = {h} and the span, got {tau!r}")
    steps_per_block = max(1, round(tau / h))
    n_blocks = max(1, int(round(span / (steps_per_block * h))))
    h = span / (n_blocks * steps_per_block)
    Q = _physical_basis(m, y, p, k)
    mod = m.module
    y, Q, sums, hist_t, hist = _kernel()(mod.rhs_into, mod.jacobian, mod.invariant_gradients, y, Q,
                                         np.ascontiguousarray(p, dtype=float), h, n_blocks, steps_per_block)
    hist_t = hist_t + float(t0)
    order = np.argsort(-hist[-1], kind="stable")
    hist = hist[:, order]
    tail = hist[-max(1, n_blocks // 4):]
    return LyapunovResult(hist[-1].copy(), hist_t, hist, 0.5 * (tail.max(axis=0) - tail.min(axis=0)), y, h,
                          steps_per_block * h)
