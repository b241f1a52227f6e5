"""Compiled helpers shared by the integrator kernels (they never call a right-hand side).

Dense output comes in two forms, selected by an integer ``kind``:

* ``DENSE_DOP853`` -- Hairer's DOP853 interpolant: ``F`` has 7 rows and
  ``y(x) = y_old + x(F0 + (1-x)(F1 + x(F2 + (1-x)(F3 + ...))))``;
* ``DENSE_POWER`` -- a power series without constant term:
  ``y(x) = y_old + sum_j F[j] x^(j+1)`` (Dormand--Prince 5(4) and cubic Hermite).

``x = (t - t_old) / h`` in [0, 1].  Spin reversals are the sign changes of one
state component between the ends of an accepted step, located on the
interpolant by the Illinois variant of regula falsi (always bracketed).
"""
import numpy as np
from numba import njit

DENSE_DOP853 = 0
DENSE_POWER = 1
_EPS = np.finfo(np.float64).eps


@njit(cache=True, error_model="numpy")
def dense_component(kind, F, y_old, x, i):
    """Interpolant of component ``i`` at ``x`` in [0, 1]."""
    m = F.shape[0]
    y = 0.0
    if kind == DENSE_DOP853:
        for j in range(m):
            y += F[m - 1 - j, i]
            if j % 2 == 0:
                y *= x
            else:
                y *= 1.0 - x
    else:
        for j in range(m - 1, -1, -1):
            y = (y + F[j, i]) * x
    return y_old[i] + y


@njit(cache=True, error_model="numpy")
def dense_state(kind, F, y_old, x, out):
    """Interpolated state at ``x`` in [0, 1], written into ``out``."""
    for i in range(y_old.size):
        out[i] = dense_component(kind, F, y_old, x, i)


@njit(cache=True, error_model="numpy")
def hermite_coefficients(y_old, y_new, f_old, f_new, h, F):
    """Cubic Hermite interpolant of one step in the ``DENSE_POWER`` form (``F`` is 3 x n)."""
    for i in range(y_old.size):
        dy = y_new[i] - y_old[i]
        a = h * f_old[i]
        b = h * f_new[i]
        F[0, i] = a
        F[1, i] = 3.0 * dy - 2.0 * a - b
        F[2, i] = -2.0 * dy + a + b


@njit(cache=True, error_model="numpy")
def locate_root(kind, F, y_old, i, g0, g1):
    """``x`` in [0, 1] where component ``i`` of the interpolant crosses zero.

    ``g0`` and ``g1`` are the values at the ends (opposite signs, or ``g1 == 0``).
    Iterates to the resolution of ``x`` (a few ulps), at most 200 times.
    """
    if g1 == 0.0:
        return 1.0
    a, b, fa, fb = 0.0, 1.0, g0, g1
    side = 0
    x = 0.5
    for _ in range(200):
        x = (a * fb - b * fa) / (fb - fa)
        if not (a < x < b):
            x = 0.5 * (a + b)
        fx = dense_component(kind, F, y_old, x, i)
        if fx == 0.0:
            return x
        if (fx > 0.0) == (fb > 0.0):
            b, fb = x, fx
            if side == -1:
                fa *= 0.5
            side = -1
        else:
            a, fa = x, fx
            if side == 1:
                fb *= 0.5
            side = 1
        if b - a <= 4.0 * _EPS:
            break
    return x


@njit(cache=True, error_model="numpy")
def grow_rows(ts, ys):
    """Double the capacity of the output arrays (times ``ts`` and rows ``ys``)."""
    cap = max(2 * ts.size, 16)
    nts = np.empty(cap)
    nys = np.empty((cap, ys.shape[1]))
    nts[: ts.size] = ts
    nys[: ts.size] = ys
    return nts, nys


@njit(cache=True, error_model="numpy")
def push_row(ts, ys, n, t, y):
    """Append ``(t, y)`` as row ``n``; returns the (maybe reallocated) arrays and ``n + 1``."""
    if n >= ts.size:
        ts, ys = grow_rows(ts, ys)
    ts[n] = t
    ys[n, :] = y
    return ts, ys, n + 1


@njit(cache=True, error_model="numpy")
def start_output(t0, y, t_eval, every):
    """Output buffers holding the initial point.

    Returns ``(ts, ys, n_out, ie)``: with ``every`` the row ``(t0, y)``;
    otherwise a row for each requested time ``t_eval[i] <= t0``, and ``ie``
    the index of the first requested time still ahead.
    """
    cap = 64 if every else max(t_eval.size, 1)
    ts = np.empty(cap)
    ys = np.empty((cap, y.size))
    n_out = 0
    ie = 0
    if every:
        ts, ys, n_out = push_row(ts, ys, n_out, t0, y)
    else:
        while ie < t_eval.size and t_eval[ie] <= t0:
            ts, ys, n_out = push_row(ts, ys, n_out, t_eval[ie], y)
            ie += 1
    return ts, ys, n_out, ie


@njit(cache=True, error_model="numpy")
def push_time(ev, n, t):
    """Append the event time ``t``; returns the (maybe reallocated) array and ``n + 1``."""
    if n >= ev.size:
        new = np.empty(max(2 * ev.size, 8))
        new[: ev.size] = ev
        ev = new
    ev[n] = t
    return ev, n + 1


@njit(cache=True, error_model="numpy")
def crossing(g_old, g_new):
    """True when a step from ``g_old`` to ``g_new`` crosses zero (a zero at the start is not counted)."""
    if g_old == 0.0:
        return False
    return g_new == 0.0 or (g_old > 0.0) != (g_new > 0.0)


@njit(cache=True, error_model="numpy")
def needs_dense(spin, y_old, y_new, t_eval, ie, t_new):
    """Whether the accepted step needs its interpolant (an event, or an output time strictly inside)."""
    if spin >= 0 and crossing(y_old[spin], y_new[spin]):
        return True
    return ie < t_eval.size and t_eval[ie] < t_new


@njit(cache=True, error_model="numpy")
def record_step(kind, F, y_old, y_new, t_old, t_new, spin, t_eval, ie, every, ts, ys, n_out, ev, n_ev, work):
    """Store what an accepted step from ``t_old`` to ``t_new`` produced.

    Events (zero crossings of component ``spin``; ``spin < 0`` disables them)
    go to ``ev``; output rows go to ``ts``/``ys`` -- every step when ``every``,
    otherwise the requested times ``t_eval[ie:]`` that fall in ``(t_old, t_new]``.
    ``F`` is only read when :func:`needs_dense` said so.
    Returns ``ie, ts, ys, n_out, ev, n_ev``.
    """
    h = t_new - t_old
    if spin >= 0 and crossing(y_old[spin], y_new[spin]):
        x = locate_root(kind, F, y_old, spin, y_old[spin], y_new[spin])
        ev, n_ev = push_time(ev, n_ev, t_old + x * h)
    if every:
        ts, ys, n_out = push_row(ts, ys, n_out, t_new, y_new)
    else:
        while ie < t_eval.size and t_eval[ie] <= t_new:
            te = t_eval[ie]
            if te == t_new:
                ts, ys, n_out = push_row(ts, ys, n_out, te, y_new)
            else:
                dense_state(kind, F, y_old, (te - t_old) / h, work)
                ts, ys, n_out = push_row(ts, ys, n_out, te, work)
            ie += 1
    return ie, ts, ys, n_out, ev, n_ev


@njit(cache=True, error_model="numpy")
def all_finite(y):
    for v in y:
        if not np.isfinite(v):
            return False
    return True


@njit(cache=True, error_model="numpy")
def compensated_add(y, dy, comp, out):
    """``out = y + dy`` with Kahan compensation carried in ``comp`` (updated in place)."""
    for i in range(y.size):
        inc = dy[i] + comp[i]
        s = y[i] + inc
        comp[i] = inc - (s - y[i])
        out[i] = s
