"""Adaptive embedded explicit Runge--Kutta integrator for any registered tableau (DOP853, DP54, Tsit5, ...).

The algorithm is the one of SciPy's ``solve_ivp`` (``DOP853`` and ``RK45``):
same tableaus (for those two), initial step (Hairer, Norsett & Wanner I, Sect. II.4), error
norms and step-size controller (safety 0.9, factors in [0.2, 10], no increase
right after a rejection), so the two agree step for step up to round-off.

Error control: ``scale_i = atol_i + rtol * max(|y_i|, |y_new_i|)``.  With
``mode_scaled`` the magnitude of a component is taken as the larger of itself
and its partner ``pair[i]`` (a tilt and its rate), i.e. each oscillation
mode is measured on its own amplitude rather than through its zero crossings.

This module is the part of the integrator that does not depend on the
model: the step-size control, the output and the location of zero crossings.
It is compiled once per method and machine and serves every model.  The
model's parts -- its right-hand side, the stages of a step with the error
norm, the interpolant's extra stages, its event functions (``erk_parts.py``,
specialized to the model with the state size as a constant and the tableau's
coefficients as literals) -- are passed as machine addresses in ``fns`` and
called through them (:mod:`knifeedge.integrators.fnptr`): one indirect call
per step, per initial step and per interpolant.

The whole integrator is one compiled function, :func:`solve`: numba's cost
of compiling a function has a large fixed part per function and grows when
numba inlines one function into another, so the helpers of a step are blocks
of ``solve``, not functions.
"""
import numpy as np
from numba import njit

from knifeedge.integrators import common as _c
from knifeedge.integrators import tableau as _tableau
from knifeedge.integrators.common import MAX_ITER, NEAR, SAMPLES  # noqa: F401 (used by the blocks)
from knifeedge.integrators.fnptr import call_f8, call_void

TABLEAU = "DOP853"  # knifeedge:variant  (a registered ExplicitTableau, see knifeedge.integrators.tableau)

#: the tables of the method (see ``tableau.erk_arrays``): only their sizes and the controller are used here
(A, C, E5, E3, DD, P, HAIRER, N_STAGES, N_EXT, DENSE_ROWS, ALT, ERROR_ORDER) = _tableau.erk_arrays(TABLEAU)
ERROR_EXPONENT = -1.0 / (ERROR_ORDER + 1)
SAFETY = 0.9
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
#: right-hand-side evaluations of the interpolant beyond those of the step (DOP853: 3)
DENSE_NFEV = N_EXT - N_STAGES - 1

_EPS = np.finfo(np.float64).eps


@njit(cache=True, error_model="numpy")
def _values(s, p, ev):
    """The model's event functions at ``s`` (``ev``: the address of its ``events`` part and their number)."""
    out = np.empty(ev[1])
    call_void(ev[0], (s, p, np.int64(p.size), out))
    return out


# knifeedge:begin function_defs
# knifeedge:end function_defs


@njit(cache=True, error_model="numpy")
def solve(fns, t0, t1, y0, f0, q, p, rtol, atol, h_init, max_step, t_eval, every, events, max_steps, pair,
          mode_scaled, chunk, ts, ys, ev_t, ev_k):
    """Integrate from ``t0`` toward ``t1 > t0``: at most ``chunk`` accepted steps, as many as the buffers hold.

    Parameters
    ----------
    fns : (5,) int64: the addresses of the model's parts ``rhs``, ``attempt``, ``dense``, ``events`` (see
        ``erk_parts.py``) and the number of its event functions.
    y0 : (n,) initial state; f0 : (n,) its derivative when continuing (``h_init > 0``), else ignored.
    q : ``constants(p)`` of the right-hand side; p : the parameters (of the event functions).
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
    N = y0.size
    rhs, attempt, dense = fns[0], fns[1], fns[2]
    ev = fns[3:5]
    ms = np.int64(1 if mode_scaled else 0)
    nq = np.int64(q.size)
    # one workspace laid out as erk_parts.py reads it (K, y, y_new, work, scale, F, then q): the model's parts
    # take their arrays at fixed offsets of one pointer, so the compiler can tell them apart
    ws = np.empty((N_EXT + 4 + DENSE_ROWS) * N + nq)
    K = ws[:N_EXT * N].reshape((N_EXT, N))
    o = N_EXT * N
    y = ws[o:o + N]
    y_new = ws[o + N:o + 2 * N]
    work = ws[o + 2 * N:o + 3 * N]
    scale = ws[o + 3 * N:o + 4 * N]
    F = ws[o + 4 * N:o + (4 + DENSE_ROWS) * N].reshape((DENSE_ROWS, N))
    qw = ws[o + (4 + DENSE_ROWS) * N:]
    for i in range(nq):
        qw[i] = q[i]
    for i in range(N):
        y[i] = y0[i]
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
        call_void(rhs, (t0, y, q, nq, K[0]))
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
            call_void(rhs, (t0 + h0, y_new, q, nq, K[1]))
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
            # the stages, y_new, K[N_STAGES] and the scaled error norm: the model's part
            err = call_f8(attempt, (t, h, t_new, rtol, ms, ws, nq, atol, pair))
            nfev += N_STAGES
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
                _function_ends(events, y, y_new, fa, fb, h, p, ev, work, ga, gb, sa, sb)
            # knifeedge:end functions
            # knifeedge:begin suspect
            # knifeedge:end suspect
            if suspect:
                any_flag = _c.screen(ga, gb, sa, sb, crit, n_crit, flag)
        if any_flag or (ie < t_eval.size and t_eval[ie] < t_new):
            # the interpolant of the step: F (DENSE_ROWS x N)
            call_void(dense, (t, h, ws, nq))
            nfev += DENSE_NFEV
        if any_flag:
            n_ev = _c.locate(events, F, y, ALT, t, h, ga, gb, crit, n_crit, flag, xs, gs, ev_t, ev_k, n_ev)
            # knifeedge:begin functions
            if n_fun > 0:
                n_ev = _locate_functions(events, F, y, t, h, p, ev, work, ga, gb, crit, n_crit, flag, xs, gs, ev_t,
                                         ev_k, n_ev)
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
