"""The fixed-step integrator shared by every model and every fixed-step method (RK4, Gauss--Legendre).

A method is data (:mod:`.fixed_methods`): ``meth`` holds its weights, whether
it is implicit, and its extrapolation matrix (:meth:`FixedMethod.driver_data`);
a model's stages of one step are LLVM IR written from the tableau with the
model's right-hand side inlined (:func:`.irparts.fixed_step_ir`), called
through their address ``fns[1]``.  This module is compiled once per machine
and serves every (model, method) pair.

The step is ``h = (t1 - t0) / N`` with ``N = ceil((t1 - t0) / h_req)``, so the
grid ends on ``t1``.  The state update uses compensated (Kahan) summation, so
round-off does not accumulate as a random walk over long runs.  Gauss methods
are symmetric, hence time-reversible, and keep quadratic invariants exactly;
their stage equations are solved by fixed-point iteration to round-off,
started from the previous step's collocation polynomial.  Dense output (events,
output times) is the cubic Hermite interpolant of each step; zero crossings are
located by :mod:`.common`, as for the adaptive methods.
"""
import numpy as np
from numba import njit

from knifeedge.integrators import common as _c
from knifeedge.integrators.common import SAMPLES
from knifeedge.integrators.fnptr import call_f8, call_void

MAX_STAGE_ITER = 100
_EPS = 2.220446049250313e-16
#: the interpolant of a step: cubic Hermite as a power series (``alt`` all false, see ``common.interpolate``)
ALT = np.zeros(3, dtype=np.bool_)


@njit(cache=True, error_model="numpy")
def _iterate(step, t, y, h, nq, scale, ws, meth, dy):
    """Solve the stage equations by fixed-point iteration (the model's sweep ``step`` maps the stages ``Z`` at
    the start of ``ws`` to ``Zn`` after them); returns ``(rhs calls, status)``: 0 converged, -3 non-finite,
    -4 diverged or stalled.

    The iteration stops when the largest change of a stage increment relative to ``scale`` is a few ulps, or
    when it stops decreasing (round-off reached) while the change relative to the largest state component is
    below 1e-14.  It fails when the change grows a thousandfold above its first value (divergence), becomes
    non-finite, or ``MAX_STAGE_ITER`` iterations pass.
    """
    s, n = meth.shape[1], y.size
    Z = ws[:s * n].reshape((s, n))
    Zn = ws[s * n:2 * s * n].reshape((s, n))
    nfev = 0
    dprev = np.inf
    dfirst = np.inf
    ynorm = 1e-300
    for i in range(n):
        ynorm = max(ynorm, abs(y[i]))
    for it in range(MAX_STAGE_ITER):
        failed = call_f8(step, (t, h, ws, nq))
        nfev += s
        d = 0.0
        dglob = 0.0
        for k in range(s):
            for i in range(n):
                change = abs(h * (Zn[k, i] - Z[k, i]))
                r = change / scale[i]
                if not (r <= d):
                    d = r
                if not (change <= dglob):
                    dglob = change
                Z[k, i] = Zn[k, i]
        if failed != 0.0:
            return nfev, -3
        if not np.isfinite(d):
            return nfev, -4
        if it == 0:
            dfirst = d
        if d <= 4.0 * _EPS or dglob == 0.0 or (d >= dprev and dglob <= 1e-14 * ynorm):
            for i in range(n):
                acc = 0.0
                for k in range(s):
                    acc += meth[0, k] * Z[k, i]
                dy[i] = h * acc
            return nfev, 0
        if d > 1e3 * dfirst:
            return nfev, -4
        dprev = d
    return nfev, -4


@njit(cache=True, error_model="numpy")
def _solver_scale(y, atol, pair, out):
    """Scale of the stage solver's test: a component's magnitude, or its mode partner's if larger, or atol."""
    for i in range(y.size):
        m = abs(y[i])
        if pair[i] >= 0:
            m = max(m, abs(y[pair[i]]))
        out[i] = max(m, atol[i])


@njit(cache=True, error_model="numpy")
def _extrapolate(ws, meth, n):
    """The next step's starting stages from this step's collocation polynomial (``Z`` through ``Zn``)."""
    s = meth.shape[1]
    Z = ws[:s * n].reshape((s, n))
    Zn = ws[s * n:2 * s * n].reshape((s, n))
    for k in range(s):
        for i in range(n):
            acc = 0.0
            for j in range(s):
                acc += meth[2 + k, j] * Z[j, i]
            Zn[k, i] = acc
    for k in range(s):
        for i in range(n):
            Z[k, i] = Zn[k, i]


@njit(cache=True, error_model="numpy")
def _advance(fns, meth, t, h, ws, nq, f_old, atol, pair, scale, dy):
    """The increment ``dy`` of one step from ``t`` (the state ``y`` in ``ws``); returns ``(rhs calls, status)``."""
    s, n = meth.shape[1], f_old.size
    y = ws[2 * s * n:(2 * s + 1) * n]
    if meth[1, 0] == 0.0:  # explicit: the stages after Z[0] = f(t, y), and dy, by the model's part
        for i in range(n):
            ws[i] = f_old[i]
        failed = call_f8(fns[1], (t, h, ws, nq))
        for i in range(n):
            dy[i] = ws[(2 * s + 2) * n + i]
        return s - 1, (-3 if failed != 0.0 else 0)
    _solver_scale(y, atol, pair, scale)
    return _iterate(fns[1], t, y, h, nq, scale, ws, meth, dy)


@njit(cache=True, error_model="numpy")
def solve(fns, meth, t0, t1, y0, f0, q, p, h_fixed, n_steps, first, atol, t_eval, every, events, max_steps, pair,
          chunk, comp, Zc, ts, ys, ev_t, ev_k):
    """Integrate from ``t0`` over steps ``first + 1 .. n_steps`` of size ``h_fixed``, at most ``chunk`` of them.

    ``fns``: the addresses of the model's parts (``rhs``, ``step``, unused, ``events``) and its number of
    event functions; ``meth``: the method's data (:meth:`.fixed_methods.FixedMethod.driver_data`); ``q``:
    ``constants(p)``.  Step ``k`` ends at ``t0 + k h_fixed`` (the last at ``t1``).  ``atol`` (n,) is the floor
    of the scale of the implicit solver's convergence test and ``pair`` (n,) the mode partner of each component
    (-1: none) whose magnitude also sets it.  ``y0`` is the state after step ``first`` and ``f0`` its
    derivative (ignored when ``first == 0``); ``comp`` (n,), the Kahan compensation, and ``Zc`` (>= s, n), the
    stage derivatives of the last step, are carried from one call to the next and updated in place, so that a
    run in chunks takes the same steps as one call.  Other arguments and the returned tuple are as for the
    adaptive integrator (rejected steps are always 0; ``h_next`` is the index of the last step taken).
    """
    s, n, nq = meth.shape[1], y0.size, q.size
    # the workspace of the model's part (irparts.FixedLayout): Z, Zn (s x n), y, work, dy (n), then q
    ws = np.empty((2 * s + 3) * n + nq)
    y = ws[2 * s * n:(2 * s + 1) * n]
    for i in range(nq):
        ws[(2 * s + 3) * n + i] = q[i]
    for i in range(n):
        y[i] = y0[i]
    y_new, dy, comp_trial, scale = np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    work, f_old, f_new = np.empty(n), np.empty(n), np.empty(n)
    F = np.empty((3, n))
    ne = events.size
    g = np.zeros((ne, 8))  # the events' work rows (see integrators.common)
    n_out = np.int64(0)
    ie = np.int64(0)
    n_ev = np.int64(0)
    nfev = np.int64(0)
    t = t0 if first == 0 else t0 + first * h_fixed
    if first == 0:
        call_void(fns[0], (t, y, q, nq, f_old))
        nfev += 1
        for k in range(s):
            for i in range(n):
                ws[k * n + i] = f_old[i]
    else:
        for i in range(n):
            f_old[i] = f0[i]
        for k in range(s):
            for i in range(n):
                ws[k * n + i] = Zc[k, i]
    ev = fns[3:5]
    status = 0
    n_acc = 0
    step = first
    while step < n_steps:
        if n_acc >= max_steps:
            status = -2
            break
        if n_acc >= chunk or (every and n_out == ts.size) or n_ev + ne * (SAMPLES + 2) > ev_t.size:
            status = 1
            break
        step += 1
        t_new = t1 if step == n_steps else t0 + step * h_fixed
        calls, status = _advance(fns, meth, t, h_fixed, ws, nq, f_old, atol, pair, scale, dy)
        nfev += calls
        if status != 0:
            break
        for i in range(n):
            comp_trial[i] = comp[i]
        _c.compensated_add(y, dy, comp_trial, y_new)
        if not _c.all_finite(y_new):
            status = -3
            break
        call_void(fns[0], (t_new, y_new, q, nq, f_new))
        nfev += 1
        if not _c.all_finite(f_new):
            status = -3
            break
        for i in range(n):
            comp[i] = comp_trial[i]
        n_acc += 1
        h = t_new - t  # the step as taken
        any_flag = ne > 0 and _c.screen_step(events, y, y_new, f_old, f_new, h, p, ev, work, g)
        if any_flag or (ie < t_eval.size and t_eval[ie] < t_new):
            _c.hermite_coefficients(y, y_new, f_old, f_new, h, F)
        if any_flag:
            n_ev = _c.locate(events, F, y, ALT, t, h, p, ev, work, g, ev_t, ev_k, n_ev)
        n_out, ie = _c.output(every, ts, ys, n_out, t_eval, ie, t, h, t_new, y, y_new, F, ALT)
        if meth[1, 0] != 0.0:
            _extrapolate(ws, meth, n)
        for i in range(n):
            y[i] = y_new[i]
            f_old[i] = f_new[i]
        t = t_new
    for k in range(s):
        for i in range(n):
            Zc[k, i] = ws[k * n + i]
    y_out = np.empty(n)
    for i in range(n):
        y_out[i] = y[i]
    return n_out, n_ev, status, nfev, n_acc, 0, t, y_out, f_old, float(step)
