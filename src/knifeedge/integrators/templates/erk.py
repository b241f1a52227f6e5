"""Adaptive embedded explicit Runge--Kutta kernel for any registered tableau (DOP853, DP54, Tsit5, ...).

The algorithm is the one of SciPy's ``solve_ivp`` (``DOP853`` and ``RK45``):
same tableaus (for those two), initial step (Hairer, Norsett & Wanner I, Sect. II.4), error
norms and step-size controller (safety 0.9, factors in [0.2, 10], no increase
right after a rejection), so the two agree step for step up to round-off.

Error control: ``scale_i = atol_i + rtol * max(|y_i|, |y_new_i|)``.  With
``mode_scaled`` the magnitude of a component is taken as the larger of itself
and its partner ``pair[i]`` (a tilt and its rate), i.e. each oscillation
mode is measured on its own amplitude rather than through its zero crossings.
"""
import numpy as np
from numba import njit

from knifeedge.integrators import common as _c
from knifeedge.integrators import tableau as _tableau
from knifeedge.integrators.templates._stub import constants as _constants, rhs_q_into as _rhs  # knifeedge:rhs

TABLEAU = "DOP853"  # knifeedge:variant  (a registered ExplicitTableau, see knifeedge.integrators.tableau)
N = 3  # knifeedge:n  (the state size, a compile-time constant so that the loops over it unroll)

_T = _tableau.get(TABLEAU)
#: Hairer's DOP853: a second error estimator and an interpolant with extra stages
HAIRER = _T.hairer is not None
N_STAGES = _T.stages
N_EXT = N_STAGES + 1 + (_T.hairer["c_ext"].size if HAIRER else 0)
# A and C over every stage: the method's, then the weights (the stage at t + h, first same as last), then
# the extra stages of the dense output
A = np.zeros((N_EXT, N_EXT))
A[:N_STAGES, :N_STAGES] = _T.A
A[N_STAGES, :N_STAGES] = _T.b
C = np.ones(N_EXT)
C[:N_STAGES] = _T.c
E5 = _T.e.copy()
ERROR_ORDER = _T.error_order
if HAIRER:
    A[N_STAGES + 1:] = _T.hairer["A_ext"]
    C[N_STAGES + 1:] = _T.hairer["c_ext"]
    E3 = _T.hairer["e3"].copy()
    DD = _T.hairer["D"].copy()
    P = np.zeros((1, 1))
    DENSE_ROWS = 3 + DD.shape[0]
else:
    E3 = np.zeros(N_EXT)
    DD = np.zeros((1, 1))
    P = _T.P.copy()
    DENSE_ROWS = P.shape[1]
ERROR_EXPONENT = -1.0 / (ERROR_ORDER + 1)
SAFETY = 0.9
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0


_EPS = np.finfo(np.float64).eps


@njit(cache=True, error_model="numpy", inline="always")
def _min_step(t):
    """The smallest step SciPy allows at ``t``: 10 ulps."""
    return 10.0 * abs(np.nextafter(t, np.inf) - t)


@njit(cache=True, error_model="numpy", inline="always")
def _power(err):
    """``err ** ERROR_EXPONENT`` of the step-size controller; -1/8 as three square roots (cheaper than pow)."""
    if ERROR_ORDER == 7:
        return 1.0 / np.sqrt(np.sqrt(np.sqrt(err)))
    return err ** ERROR_EXPONENT


@njit(cache=True, error_model="numpy", inline="always")
def _rms(v):
    s = 0.0
    for x in v:
        s += x * x
    return np.sqrt(s / v.size)


@njit(cache=True, error_model="numpy", inline="always")
def _scale(y, y_new, rtol, atol, pair, mode_scaled, out):
    for i in range(N):
        m = max(abs(y[i]), abs(y_new[i]))
        if mode_scaled and pair[i] >= 0:
            j = pair[i]
            m = max(m, abs(y[j]), abs(y_new[j]))
        out[i] = atol[i] + rtol * m


@njit(cache=True, error_model="numpy")
def initial_step(t0, y0, f0, q, t1, max_step, rtol, atol, work):
    """Hairer, Norsett & Wanner I, Sect. II.4 (as SciPy's ``select_initial_step``); one rhs call."""
    n = N
    interval = abs(t1 - t0)
    d0 = 0.0
    d1 = 0.0
    for i in range(n):
        sc = atol[i] + abs(y0[i]) * rtol
        d0 += (y0[i] / sc) ** 2
        d1 += (f0[i] / sc) ** 2
    d0 = np.sqrt(d0 / n)
    d1 = np.sqrt(d1 / n)
    h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
    h0 = min(h0, interval)
    if not h0 > 0.0:  # the derivative overflows the scale: start at the smallest step
        return 0.0
    y1 = np.empty(n)
    for i in range(n):
        y1[i] = y0[i] + h0 * f0[i]
    _rhs(t0 + h0, y1, q, work)
    d2 = 0.0
    for i in range(n):
        sc = atol[i] + abs(y0[i]) * rtol
        d2 += ((work[i] - f0[i]) / sc) ** 2
    d2 = np.sqrt(d2 / n) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / (ERROR_ORDER + 1))
    return min(100 * h0, h1, interval, max_step)


@njit(cache=True, error_model="numpy", inline="always")
def _stage_state(K, s, y, h, out):  # knifeedge:stages
    """``out = y + h * sum_j A[s, j] K[j]``; the specializer keeps only the dense-output stages, unrolled."""
    for i in range(N):
        acc = 0.0
        for j in range(s):
            a = A[s, j]
            if a != 0.0:
                acc += a * K[j, i]
        out[i] = y[i] + h * acc


@njit(cache=True, error_model="numpy", inline="always")
def _attempt(t, t_new, y, h, q, K, work, y_new):  # knifeedge:attempt
    """Stages 1 .. N_STAGES of a step from ``(t, y)``; ``K[0]`` holds f(t, y) (FSAL).

    Writes ``K[1 .. N_STAGES]`` and ``y_new = y + h sum_j B_j K[j]``; the
    specializer replaces this body by straight-line code with the tableau's
    coefficients as literals.
    """
    for s in range(1, N_STAGES):
        _stage_state(K, s, y, h, work)
        _rhs(t + C[s] * h, work, q, K[s])
    _stage_state(K, N_STAGES, y, h, y_new)
    _rhs(t_new, y_new, q, K[N_STAGES])


@njit(cache=True, error_model="numpy", inline="always")
def _error_norm(K, h, scale, work5, work3):  # knifeedge:error
    """Scaled norm of the embedded error estimate; the specializer unrolls it like :func:`_attempt`."""
    n = N
    for i in range(n):
        e5 = 0.0
        e3 = 0.0
        for j in range(N_STAGES + 1):
            e5 += E5[j] * K[j, i]
            e3 += E3[j] * K[j, i]
        work5[i] = e5 / scale[i]
        work3[i] = e3 / scale[i]
    if HAIRER:
        n5 = 0.0
        n3 = 0.0
        for i in range(n):
            n5 += work5[i] * work5[i]
            n3 += work3[i] * work3[i]
        if n5 == 0.0 and n3 == 0.0:
            return 0.0
        return abs(h) * n5 / np.sqrt((n5 + 0.01 * n3) * n)
    return abs(h) * _rms(work5)


@njit(cache=True, error_model="numpy")
def _dense(K, y_old, y_new, t_old, h, q, F, work):
    """Interpolant coefficients of the accepted step; returns the rhs calls it made."""
    n = N
    if HAIRER:
        for s in range(N_STAGES + 1, N_EXT):
            _stage_state(K, s, y_old, h, work)
            _rhs(t_old + C[s] * h, work, q, K[s])
        for i in range(n):
            dy = y_new[i] - y_old[i]
            F[0, i] = dy
            F[1, i] = h * K[0, i] - dy
            F[2, i] = 2.0 * dy - h * (K[N_STAGES, i] + K[0, i])
            for r in range(4):
                acc = 0.0
                for j in range(N_EXT):
                    acc += DD[r, j] * K[j, i]
                F[3 + r, i] = h * acc
        return N_EXT - N_STAGES - 1
    for i in range(n):
        for r in range(DENSE_ROWS):
            acc = 0.0
            for j in range(N_EXT):
                acc += K[j, i] * P[j, r]
            F[r, i] = h * acc
    return 0


@njit(cache=True, error_model="numpy")
def _interpolate(F, y_old, x, i):
    """Component ``i`` of the step's interpolant at ``x`` in [0, 1]."""
    if HAIRER:
        return _c.dense_dop853(F, y_old, x, i)
    return _c.dense_power(F, y_old, x, i)


@njit(cache=True, error_model="numpy")
def _record(F, y, y_new, t, t_new, t_eval, ie, every, ys, ts, n_out, events, ev_t, ev_k, n_ev):
    """Store what the accepted step from ``t`` to ``t_new`` produced; returns ``ie, n_out, n_ev``.

    Zero crossings of the components ``events`` (sign change between the
    step's ends) are located on the interpolant; unless ``every`` (the caller
    stores every step itself), output rows are the requested times
    ``t_eval[ie:]`` in ``(t, t_new]``.  The caller guarantees the room.
    """
    h = t_new - t
    for k in range(events.size):
        i = events[k]
        if _c.crossing(y[i], y_new[i]):
            x = 1.0
            if y_new[i] != 0.0:
                x = _c.illinois(F, y, i, y[i], y_new[i], HAIRER)
            ev_t[n_ev] = t + x * h
            ev_k[n_ev] = k
            n_ev += 1
    if not every:
        while ie < t_eval.size and t_eval[ie] <= t_new:
            te = t_eval[ie]
            ts[n_out] = te
            if te == t_new:
                for i in range(N):
                    ys[n_out, i] = y_new[i]
            else:
                x = (te - t) / h
                for i in range(N):
                    ys[n_out, i] = _interpolate(F, y, x, i)
            n_out += 1
            ie += 1
    return ie, n_out, n_ev


# "contract": fused multiply-adds in the stage sums, which are inlined here (see specialize._attempt_body)
@njit(cache=True, error_model="numpy", fastmath={"contract"})
def solve(t0, t1, y0, f0, p, rtol, atol, h_init, max_step, t_eval, every, events, max_steps, pair, mode_scaled,
          chunk, ts, ys, ev_t, ev_k):
    """Integrate from ``t0`` toward ``t1 > t0``: at most ``chunk`` accepted steps, as many as the buffers hold.

    Parameters
    ----------
    y0 : (n,) initial state; f0 : (n,) its derivative when continuing (``h_init > 0``), else ignored.
    p : parameters of the right-hand side.
    rtol : float; atol : (n,) absolute tolerances.
    h_init : next step when continuing a run, or 0 to start one (the first step is then chosen).
    max_step : largest step.
    t_eval : (m,) increasing output times in (t0, t1] still ahead (used when not ``every``).
    every : store every accepted step instead of ``t_eval`` (the start is not stored).
    events : (e,) int, components whose zero crossings are recorded.
    max_steps : accepted steps allowed (the caller subtracts those already taken).
    pair : (n,) int, partner component for ``mode_scaled`` error control (-1: none).
    chunk : accepted steps after which the call returns with status 1 (paused).
    ts (r,), ys (r, n) : output rows (with ``every``, the call pauses when they are full; otherwise they
        must hold ``t_eval``); ev_t (c,), ev_k (c,) int: event times and numbers (the call pauses when
        a step could overflow them).

    A paused run continues from the returned ``t, y, f, h_next`` (passed as ``t0, y0, f0, h_init``)
    with the steps, evaluations and results of one uninterrupted call.

    Returns
    -------
    n_out, n_ev, status, nfev, accepted, rejected, t, y, f, h_next
    """
    if y0.size != N:
        raise ValueError("the initial state does not have the size this kernel was specialized to")
    q = _constants(p)
    n = N
    K = np.empty((N_EXT, n))
    y = np.empty(n)
    for i in range(n):
        y[i] = y0[i]
    y_new = np.empty(n)
    work = np.empty(n)
    work3 = np.empty(n)
    scale = np.empty(n)
    F = np.empty((DENSE_ROWS, n))
    # counters start as int64, not as the literal 0 (numba would compile the callees for both types)
    n_out = np.int64(0)
    ie = np.int64(0)
    n_ev = np.int64(0)
    nfev = np.int64(0)
    if h_init > 0.0:
        h_abs = h_init
        for i in range(n):
            K[0, i] = f0[i]
    else:
        _rhs(t0, y, q, K[0])
        h_abs = initial_step(t0, y, K[0], q, t1, max_step, rtol, atol, work)
        nfev += 2
    t = t0
    status = 0
    n_acc = 0
    n_rej = 0
    while t < t1:
        if n_acc >= max_steps:
            status = -2
            break
        if n_acc >= chunk or (every and n_out == ts.size) or n_ev + events.size > ev_t.size:
            status = 1
            break
        # SciPy's smallest step is 10 ulps of t; nextafter is called only near it (10 ulps <= 10 eps |t|)
        near = 10.0 * _EPS * abs(t) + 1e-300
        if h_abs > max_step:
            h_abs = max_step
        elif h_abs < near and h_abs < _min_step(t):
            h_abs = _min_step(t)
        rejected = False
        while True:
            if h_abs < near and h_abs < _min_step(t):
                status = -1
                break
            t_new = t + h_abs
            if t_new > t1:
                t_new = t1
            h = t_new - t
            h_abs = abs(h)
            _attempt(t, t_new, y, h, q, K, work, y_new)
            nfev += N_STAGES
            _scale(y, y_new, rtol, atol, pair, mode_scaled, scale)
            err = _error_norm(K, h, scale, work, work3)
            if err < 1.0:
                if err == 0.0:
                    factor = MAX_FACTOR
                else:
                    factor = min(MAX_FACTOR, SAFETY * _power(err))
                if rejected:
                    factor = min(1.0, factor)
                h_abs *= factor
                break
            if not np.isfinite(err):
                h_abs *= MIN_FACTOR
            else:
                h_abs *= max(MIN_FACTOR, SAFETY * _power(err))
            rejected = True
            n_rej += 1
        if status != 0:
            break
        n_acc += 1
        dense = ie < t_eval.size and t_eval[ie] < t_new
        for k in range(events.size):
            if _c.crossing(y[events[k]], y_new[events[k]]):
                dense = True
        if dense:
            nfev += _dense(K, y, y_new, t, h, q, F, work)
        if every:  # the common case, inline: a row per step
            ts[n_out] = t_new
            for i in range(n):
                ys[n_out, i] = y_new[i]
            n_out += 1
        if dense or (not every and ie < t_eval.size and t_eval[ie] <= t_new):
            ie, n_out, n_ev = _record(F, y, y_new, t, t_new, t_eval, ie, every, ys, ts, n_out, events, ev_t, ev_k,
                                      n_ev)
        for i in range(n):
            y[i] = y_new[i]
            K[0, i] = K[N_STAGES, i]
        t = t_new
    f = np.empty(n)
    for i in range(n):
        f[i] = K[0, i]
    return n_out, n_ev, status, nfev, n_acc, n_rej, t, y, f, h_abs
