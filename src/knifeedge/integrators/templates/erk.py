"""Adaptive embedded explicit Runge--Kutta kernel for any registered tableau (DOP853, DP54, Tsit5, ...).

The algorithm is the one of SciPy's ``solve_ivp`` (``DOP853`` and ``RK45``):
same tableaus (for those two), initial step (Hairer, Norsett & Wanner I, Sect. II.4), error
norms and step-size controller (safety 0.9, factors in [0.2, 10], no increase
right after a rejection), so the two agree step for step up to round-off.

Error control: ``scale_i = atol_i + rtol * max(|y_i|, |y_new_i|)``.  With
``mode_scaled`` the magnitude of a component is taken as the larger of itself
and its partner ``pair[i]`` (a tilt and its rate), i.e. each oscillation
mode is measured on its own amplitude rather than through its zero crossings.

The whole kernel is one compiled function, :func:`solve`: numba's cost of
compiling a function (typing, lowering, LLVM) has a large fixed part per
function and grows when numba inlines one function into another, so the
helpers of a step are blocks of ``solve``, not functions.  The blocks between
``# knifeedge:begin NAME`` and ``# knifeedge:end NAME`` hold generic loops over
the tableau; :mod:`..specialize` replaces them by straight-line code with the
tableau's coefficients as literals.
"""
import numpy as np
from numba import njit

from knifeedge.integrators import common as _c
from knifeedge.integrators import tableau as _tableau
from knifeedge.integrators.common import MAX_ITER, SAMPLES  # noqa: F401 (MAX_ITER: the event functions)
from knifeedge.integrators.templates._stub import constants as _constants, rhs_q_into as _rhs  # knifeedge:rhs
from knifeedge.integrators.templates._stub import event_values as _event_values  # knifeedge:event_values

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
#: the interpolant, both forms as one Horner scheme over the rows of ``F`` (from the last):
#: ``v = (v + F[r, i]) * (1 - x if ALT[r] else x)``, then ``y_old[i] + v``.  Hairer's DOP853 form
#: ``x(F0 + (1-x)(F1 + x(F2 + ...)))`` alternates the factors; the power series
#: ``sum_r F[r] x^(r+1)`` (Dormand--Prince 5(4), Tsitouras 5(4)) has ``x`` throughout.
ALT = np.array([HAIRER and r % 2 == 1 for r in range(DENSE_ROWS)])
ERROR_EXPONENT = -1.0 / (ERROR_ORDER + 1)
SAFETY = 0.9
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0

_EPS = np.finfo(np.float64).eps


# knifeedge:begin function_defs
# knifeedge:end function_defs


# "contract": fused multiply-adds in the stage sums (see specialize._attempt_body)
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
    events : (e,) int, whose zero crossings are recorded: a state component ``c >= 0``, or ``-1 - j`` for
        the model's event function ``j`` (``event_values(s, p)[j]``).
    max_steps : accepted steps allowed (the caller subtracts those already taken).
    pair : (n,) int, partner component for ``mode_scaled`` error control (-1: none).
    chunk : accepted steps after which the call returns with status 1 (paused).
    ts (r,), ys (r, n) : output rows (with ``every``, the call pauses when they are full; otherwise they
        must hold ``t_eval``); ev_t (c,), ev_k (c,) int: event times and numbers (the call pauses when
        a step could overflow them: a step finds at most ``SAMPLES + 2`` crossings of each event).

    A paused run continues from the returned ``t, y, f, h_next`` (passed as ``t0, y0, f0, h_init``)
    with the steps, evaluations and results of one uninterrupted call.

    Zero crossings of the ``events`` (a state component ``c >= 0`` or the
    model's event function ``-1 - c``) are found on the step's interpolant,
    two or more inside one step included (see :mod:`._blocks`).

    Returns
    -------
    n_out, n_ev, status, nfev, accepted, rejected, t, y, f, h_next
    """
    if y0.size != N:
        raise ValueError("the initial state does not have the size this kernel was specialized to")
    q = _constants(p)
    K = np.empty((N_EXT, N))
    y = np.empty(N)
    for i in range(N):
        y[i] = y0[i]
    y_new = np.empty(N)
    work = np.empty(N)
    scale = np.empty(N)
    F = np.empty((DENSE_ROWS, N))
    fa = K[0]  # the derivatives at the ends of a step (views of the first and the last stage)
    fb = K[N_STAGES]
    # knifeedge:begin alloc
    # knifeedge:end alloc
    # counters start as int64, not as the literal 0 (numba would type them twice)
    n_out = np.int64(0)
    ie = np.int64(0)
    n_ev = np.int64(0)
    nfev = np.int64(0)
    t = t0
    if h_init > 0.0:
        h_abs = h_init
        for i in range(N):
            K[0, i] = f0[i]
    else:
        # the first step: Hairer, Norsett & Wanner I, Sect. II.4 (as SciPy's select_initial_step)
        _rhs(t0, y, q, K[0])
        d0 = 0.0
        d1 = 0.0
        for i in range(N):
            sc = atol[i] + abs(y[i]) * rtol
            d0 += (y[i] / sc) * (y[i] / sc)
            d1 += (K[0, i] / sc) * (K[0, i] / sc)
        d0 = np.sqrt(d0 / N)
        d1 = np.sqrt(d1 / N)
        h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
        h0 = min(h0, t1 - t0)
        h_abs = 0.0
        if h0 > 0.0:  # else the derivative overflows the scale: start at the smallest step
            for i in range(N):
                y_new[i] = y[i] + h0 * K[0, i]
            _rhs(t0 + h0, y_new, q, K[1])
            d2 = 0.0
            for i in range(N):
                sc = atol[i] + abs(y[i]) * rtol
                d2 += ((K[1, i] - K[0, i]) / sc) * ((K[1, i] - K[0, i]) / sc)
            d2 = np.sqrt(d2 / N) / h0
            if d1 <= 1e-15 and d2 <= 1e-15:
                h1 = max(1e-6, h0 * 1e-3)
            else:
                h1 = (0.01 / max(d1, d2)) ** (1.0 / (ERROR_ORDER + 1))
            h_abs = min(100 * h0, h1, t1 - t0, max_step)
        nfev += 2
    status = 0
    n_acc = 0
    n_rej = 0
    while t < t1:
        if n_acc >= max_steps:
            status = -2
            break
        if n_acc >= chunk or (every and n_out == ts.size) or n_ev + ne * (SAMPLES + 2) > ev_t.size:
            status = 1
            break
        # SciPy's smallest step is 10 ulps of t; nextafter is called only near it (10 ulps <= 10 eps |t|)
        near = 10.0 * _EPS * abs(t) + 1e-300
        if h_abs > max_step:
            h_abs = max_step
        elif h_abs < near and h_abs < 10.0 * abs(np.nextafter(t, np.inf) - t):
            h_abs = 10.0 * abs(np.nextafter(t, np.inf) - t)
        rejected = False
        while True:
            if h_abs < near and h_abs < 10.0 * abs(np.nextafter(t, np.inf) - t):
                status = -1
                break
            t_new = t + h_abs
            if t_new > t1:
                t_new = t1
            h = t_new - t
            h_abs = abs(h)
            # knifeedge:begin attempt
            # stages 1 .. N_STAGES from K[0] = f(t, y) (first same as last), then y_new and K[N_STAGES]
            for s in range(1, N_STAGES + 1):
                for i in range(N):
                    acc = 0.0
                    for j in range(s):
                        acc += A[s, j] * K[j, i]
                    if s < N_STAGES:
                        work[i] = y[i] + h * acc
                    else:
                        y_new[i] = y[i] + h * acc
                if s < N_STAGES:
                    _rhs(t + C[s] * h, work, q, K[s])
                else:
                    _rhs(t_new, y_new, q, K[s])
            # knifeedge:end attempt
            nfev += N_STAGES
            for i in range(N):
                m = max(abs(y[i]), abs(y_new[i]))
                if mode_scaled and pair[i] >= 0:
                    m = max(m, abs(y[pair[i]]), abs(y_new[pair[i]]))
                scale[i] = atol[i] + rtol * m
            # knifeedge:begin error
            # the scaled norm of the embedded estimate (DOP853: its 5th- and 3rd-order ones combined as Hairer's)
            n5 = 0.0
            n3 = 0.0
            for i in range(N):
                e5 = 0.0
                e3 = 0.0
                for j in range(N_STAGES + 1):
                    e5 += E5[j] * K[j, i]
                    e3 += E3[j] * K[j, i]
                n5 += (e5 / scale[i]) * (e5 / scale[i])
                n3 += (e3 / scale[i]) * (e3 / scale[i])
            if not HAIRER:
                err = abs(h) * np.sqrt(n5 / N)
            elif n5 == 0.0 and n3 == 0.0:
                err = 0.0
            else:
                err = abs(h) * n5 / np.sqrt((n5 + 0.01 * n3) * N)
            # knifeedge:end error
            if err < 1.0:
                if err == 0.0:
                    factor = MAX_FACTOR
                else:
                    # knifeedge:begin power
                    factor = min(MAX_FACTOR, SAFETY * err ** ERROR_EXPONENT)
                    # knifeedge:end power
                if rejected:
                    factor = min(1.0, factor)
                h_abs *= factor
                break
            if not np.isfinite(err):
                h_abs *= MIN_FACTOR
            else:
                # knifeedge:begin power
                h_abs *= max(MIN_FACTOR, SAFETY * err ** ERROR_EXPONENT)
                # knifeedge:end power
            rejected = True
            n_rej += 1
        if status != 0:
            break
        n_acc += 1
        any_flag = False
        if ne > 0:
            # knifeedge:begin ends
            # knifeedge:end ends
            # knifeedge:begin functions
            if n_fun > 0:
                _function_ends(events, y, y_new, fa, fb, h, p, work, ga, gb, sa, sb)
            # knifeedge:end functions
            any_flag = _c.screen(ga, gb, sa, sb, crit, n_crit, flag)
        if any_flag or (ie < t_eval.size and t_eval[ie] < t_new):
            # the interpolant of the step: F (DENSE_ROWS x N)
            # knifeedge:begin dense
            if HAIRER:
                for s in range(N_STAGES + 1, N_EXT):
                    for i in range(N):
                        acc = 0.0
                        for j in range(s):
                            acc += A[s, j] * K[j, i]
                        work[i] = y[i] + h * acc
                    _rhs(t + C[s] * h, work, q, K[s])
                for i in range(N):
                    dy = y_new[i] - y[i]
                    F[0, i] = dy
                    F[1, i] = h * K[0, i] - dy
                    F[2, i] = 2.0 * dy - h * (K[N_STAGES, i] + K[0, i])
                    for r in range(DENSE_ROWS - 3):
                        acc = 0.0
                        for j in range(N_EXT):
                            acc += DD[r, j] * K[j, i]
                        F[3 + r, i] = h * acc
                nfev += N_EXT - N_STAGES - 1
            else:
                for i in range(N):
                    for r in range(DENSE_ROWS):
                        acc = 0.0
                        for j in range(N_EXT):
                            acc += K[j, i] * P[j, r]
                        F[r, i] = h * acc
            # knifeedge:end dense
        if any_flag:
            n_ev = _c.locate(events, F, y, ALT, t, h, ga, gb, crit, n_crit, flag, xs, gs, ev_t, ev_k, n_ev)
            # knifeedge:begin functions
            if n_fun > 0:
                n_ev = _locate_functions(events, F, y, t, h, p, work, ga, gb, crit, n_crit, flag, xs, gs, ev_t, ev_k,
                                         n_ev)
            # knifeedge:end functions
        # knifeedge:begin output
        # knifeedge:end output
        for i in range(N):
            y[i] = y_new[i]
            K[0, i] = K[N_STAGES, i]
        t = t_new
    f = np.empty(N)
    for i in range(N):
        f[i] = K[0, i]
    return n_out, n_ev, status, nfev, n_acc, n_rej, t, y, f, h_abs
