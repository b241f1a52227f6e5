"""Fixed-step kernel for any registered :class:`~knifeedge.integrators.fixed_methods.FixedMethod`.

``METHOD`` names the method; its tableau is read from the registry (the
classical RK4, the Gauss--Legendre methods with 1, 2, 3 stages, orders 2, 4,
6; one stage is the implicit midpoint rule).  An explicit method is stepped
stage after stage; an implicit one by fixed-point iteration of its stage
equations.  Gauss methods are symmetric, hence
time-reversible, and keep quadratic invariants exactly; their stage
equations are solved by fixed-point iteration to round-off, started from the
previous step's collocation polynomial.

The step is ``h = (t1 - t0) / N`` with ``N = ceil((t1 - t0) / h_req)``, so the
grid ends on ``t1``.  The state update uses compensated (Kahan) summation, so
round-off does not accumulate as a random walk over long runs.  Dense output
(events, output times) is the cubic Hermite interpolant of each step.
"""

import numpy as np
from numba import njit

from knifeedge.integrators import common as _c
from knifeedge.integrators.fixed_methods import FIXED_METHODS
from knifeedge.integrators.common import MAX_ITER, NEAR, SAMPLES  # noqa: F401 (used by the blocks)
from knifeedge.integrators.templates._stub import constants as _constants, rhs_q_into as _rhs  # knifeedge:rhs
from knifeedge.integrators.templates._stub import event_values as _event_values  # knifeedge:event_values

METHOD = "RK4"  # knifeedge:variant  (a registered FixedMethod)
N = 3  # knifeedge:n  (the state size, a compile-time constant so that the loops over it unroll)

_METHOD = FIXED_METHODS[METHOD]
IMPLICIT = _METHOD.implicit
S = _METHOD.stages
GA = _METHOD.A.copy()
GC = _METHOD.c.copy()
#: the increment is h / DENOMINATOR * sum_j GB[j] K_j
DENOMINATOR = _METHOD.denominator
GB = _METHOD.b * DENOMINATOR
EXTRAP = _METHOD.extrapolation
#: the classical RK4's tableau: its increment is written out (the general loops cost it 10-17 % per evaluation)
CLASSICAL_RK4 = _METHOD.is_classical_rk4
MAX_STAGE_ITER = 100
_EPS = 2.220446049250313e-16
#: the interpolant of a step: cubic Hermite as a power series (see the adaptive template's ALT)
DENSE_ROWS = 3
ALT = np.zeros(DENSE_ROWS, dtype=np.bool_)


@njit(cache=True, error_model="numpy")
def _rk4_increment(t, y, h, q, f0, K, work, dy):
    """The classical RK4's stages and increment ``h/6 (K_0 + 2 K_1 + 2 K_2 + K_3)``, as written."""
    for i in range(N):
        work[i] = y[i] + 0.5 * h * f0[i]
    _rhs(t + 0.5 * h, work, q, K[1])
    for i in range(N):
        work[i] = y[i] + 0.5 * h * K[1, i]
    _rhs(t + 0.5 * h, work, q, K[2])
    for i in range(N):
        work[i] = y[i] + h * K[2, i]
    _rhs(t + h, work, q, K[3])
    for i in range(N):
        dy[i] = h / 6.0 * (f0[i] + 2.0 * K[1, i] + 2.0 * K[2, i] + K[3, i])
    return 3


@njit(cache=True, error_model="numpy")
def _explicit_increment(t, y, h, q, f0, K, work, dy):
    """The stages of an explicit method from ``K[0] = f0``: ``y + (a_j0 h) K_0 + ...`` (zero coefficients
    skipped), and ``dy = h / DENOMINATOR * (GB_0 K_0 + ...)``; returns the right-hand-side calls."""
    for i in range(N):
        K[0, i] = f0[i]
    for s in range(1, S):
        for i in range(N):
            acc = y[i]
            for j in range(s):
                if GA[s, j] != 0.0:
                    acc += GA[s, j] * h * K[j, i]
            work[i] = acc
        _rhs(t + GC[s] * h, work, q, K[s])
    for i in range(N):
        acc = 0.0
        for j in range(S):
            acc += GB[j] * K[j, i]
        dy[i] = h / DENOMINATOR * acc
    return S - 1


@njit(cache=True, error_model="numpy")
def _gauss_increment(t, y, h, q, scale, Z, Znew, work, dy):
    """Solve the stage equations by fixed-point iteration; returns (rhs calls, converged).

    The iteration stops when the largest change of a stage increment relative
    to ``scale`` is a few ulps, or when it stops decreasing (round-off
    reached) while the change relative to the largest state component is
    below 1e-14.  It fails when the change grows a thousandfold above its
    first value (divergence), becomes non-finite, or ``MAX_ITER`` iterations
    pass.
    """
    n = N
    nfev = 0
    dprev = np.inf
    dfirst = np.inf
    ynorm = 1e-300
    for i in range(n):
        ynorm = max(ynorm, abs(y[i]))
    for it in range(MAX_STAGE_ITER):
        for k in range(S):
            for i in range(n):
                acc = 0.0
                for j in range(S):
                    acc += GA[k, j] * Z[j, i]
                work[i] = y[i] + h * acc
            _rhs(t + GC[k] * h, work, q, Znew[k])
        nfev += S
        d = 0.0
        dglob = 0.0
        for k in range(S):
            for i in range(n):
                change = abs(h * (Znew[k, i] - Z[k, i]))
                r = change / scale[i]
                if not (r <= d):
                    d = r
                if not (change <= dglob):
                    dglob = change
                Z[k, i] = Znew[k, i]
        if not np.isfinite(d):
            return nfev, False
        if it == 0:
            dfirst = d
        if d <= 4.0 * _EPS or dglob == 0.0 or (d >= dprev and dglob <= 1e-14 * ynorm):
            for i in range(n):
                acc = 0.0
                for k in range(S):
                    acc += GB[k] * Z[k, i]
                dy[i] = h / DENOMINATOR * acc
            return nfev, True
        if d > 1e3 * dfirst:
            return nfev, False
        dprev = d
    return nfev, False


@njit(cache=True, error_model="numpy")
def _solver_scale(y, atol, pair, out):
    """Scale of the stage solver's test: a component's magnitude, or its mode partner's if larger, or atol."""
    for i in range(N):
        m = abs(y[i])
        if pair[i] >= 0:
            m = max(m, abs(y[pair[i]]))
        out[i] = max(m, atol[i])


#: the event functions are the model's own ``_event_values`` (the adaptive integrator's ``ev`` is unused here)
NO_EV = np.zeros(2, dtype=np.int64)


@njit(cache=True, error_model="numpy")
def _values(s, p, ev):
    """The model's event functions at ``s``."""
    return _event_values(s, p)


# knifeedge:begin function_defs
# knifeedge:end function_defs


@njit(cache=True, error_model="numpy")
def solve(t0, t1, y0, f0, p, h_fixed, n_steps, first, atol, t_eval, every, events, max_steps, pair, chunk, comp, Z,
          ts, ys, ev_t, ev_k):
    """Integrate from ``t0`` over steps ``first + 1 .. n_steps`` of size ``h_fixed``, at most ``chunk`` of them.

    Step ``k`` ends at ``t0 + k h_fixed`` (the last at ``t1``).  ``atol`` (n,) is
    the floor of the scale of the implicit solver's convergence test and
    ``pair`` (n,) the mode partner of each component (-1: none) whose
    magnitude also sets it (Gauss only).  ``y0`` is the state after step
    ``first`` and ``f0`` its derivative (ignored when ``first == 0``);
    ``comp`` (n,), the Kahan compensation, and ``Z`` (S, n), the stage
    derivatives of the last step, are carried from one call to the next and
    updated in place, so that a run in chunks takes the same steps as one
    call.  Other arguments and the returned tuple are as for the adaptive
    kernel (rejected steps are always 0; ``h_next`` is the index of the
    last step taken).
    """
    if y0.size != N:
        raise ValueError("the initial state does not have the size this kernel was specialized to")
    q = _constants(p)
    n = N
    y = np.empty(n)
    for i in range(n):
        y[i] = y0[i]
    y_new = np.empty(n)
    dy = np.empty(n)
    comp_trial = np.empty(n)
    scale = np.empty(n)
    work = np.empty(n)
    f_old = np.empty(n)
    f_new = np.empty(n)
    K = np.empty((S, n))
    Znew = np.empty((S, n))
    F = np.empty((DENSE_ROWS, n))
    fa = f_old  # the derivatives at the ends of a step
    fb = f_new
    # knifeedge:begin alloc
    # knifeedge:end alloc
    # counters start as int64, not as the literal 0 (numba would compile the callees for both types)
    n_out = np.int64(0)
    ie = np.int64(0)
    n_ev = np.int64(0)
    nfev = np.int64(0)
    t = t0 if first == 0 else t0 + first * h_fixed
    if first == 0:
        _rhs(t, y, q, f_old)
        nfev += 1
        for k in range(S):
            for i in range(n):
                Z[k, i] = f_old[i]
    else:
        for i in range(n):
            f_old[i] = f0[i]
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
        if IMPLICIT:  # globals numba prunes on: only the method's branch is compiled in
            _solver_scale(y, atol, pair, scale)
            calls, ok = _gauss_increment(t, y, h_fixed, q, scale, Z, Znew, work, dy)
            nfev += calls
            if not ok:
                status = -4
                break
        elif CLASSICAL_RK4:
            nfev += _rk4_increment(t, y, h_fixed, q, f_old, K, work, dy)
        else:
            nfev += _explicit_increment(t, y, h_fixed, q, f_old, K, work, dy)
        for i in range(n):
            comp_trial[i] = comp[i]
        _c.compensated_add(y, dy, comp_trial, y_new)
        if not _c.all_finite(y_new):
            status = -3
            break
        _rhs(t_new, y_new, q, f_new)
        nfev += 1
        if not _c.all_finite(f_new):
            status = -3
            break
        for i in range(n):
            comp[i] = comp_trial[i]
        n_acc += 1
        h = t_new - t  # the step as taken (the blocks' name)
        any_flag = False
        if ne > 0:
            # knifeedge:begin ends
            # knifeedge:end ends
            # knifeedge:begin functions
            if n_fun > 0:
                _function_ends(events, y, y_new, fa, fb, h, p, NO_EV, work, ga, gb, sa, sb)
            # knifeedge:end functions
            # knifeedge:begin suspect
            # knifeedge:end suspect
            if suspect:
                any_flag = _c.screen(ga, gb, sa, sb, crit, n_crit, flag)
        if any_flag or (ie < t_eval.size and t_eval[ie] < t_new):
            _c.hermite_coefficients(y, y_new, f_old, f_new, h, F)
        if any_flag:
            n_ev = _c.locate(events, F, y, ALT, t, h, ga, gb, crit, n_crit, flag, xs, gs, ev_t, ev_k, n_ev)
            # knifeedge:begin functions
            if n_fun > 0:
                n_ev = _locate_functions(events, F, y, t, h, p, NO_EV, work, ga, gb, crit, n_crit, flag, xs, gs,
                                         ev_t, ev_k, n_ev)
            # knifeedge:end functions
        # knifeedge:begin output
        # knifeedge:end output
        if IMPLICIT:
            # start the next stage iteration from this step's collocation polynomial
            for k in range(S):
                for i in range(n):
                    acc = 0.0
                    for j in range(S):
                        acc += EXTRAP[k, j] * Z[j, i]
                    Znew[k, i] = acc
            for k in range(S):
                for i in range(n):
                    Z[k, i] = Znew[k, i]
        for i in range(n):
            y[i] = y_new[i]
            f_old[i] = f_new[i]
        t = t_new
    return n_out, n_ev, status, nfev, n_acc, 0, t, y, f_old, float(step)
