"""Compiled helpers of the kernels that never call a right-hand side.

They are compiled once per machine and shared by every kernel (numba caches
them beside this module): the screening and location of zero crossings of
state components (the method is described in :mod:`.blocks`) and
the fixed-step kernel's helpers.  The interpolant of a step is ``F`` (rows
x n) in one Horner scheme: ``v = (v + F[r, i]) * (1 - x if alt[r] else x)``
from the last row, then ``y[i] + v`` (Hairer's DOP853 form alternates the
factors; the power series of Dormand--Prince, Tsitouras and cubic Hermite
has ``x`` throughout).

Every helper avoids array slicing and broadcasting assignments: numba
compiles those with their error-message machinery (string formatting),
which used to be half the compile time of a kernel.
"""
import numpy as np
from numba import njit

_EPS = np.finfo(np.float64).eps
#: interior samples of a suspected step: SAMPLES - 1 equally spaced points, plus the Hermite extrema
SAMPLES = 8
#: a Hermite extremum within this fraction of the larger end value of zero makes the step suspect
NEAR = 0.5
#: Illinois iterations (it stops at the resolution of x, a few ulps, long before)
MAX_ITER = 200


@njit(cache=True, error_model="numpy")
def screen(ga, gb, sa, sb, crit, n_crit, flag):
    """Which events may cross zero inside the step: ``flag[k]`` 1 (the signs at the ends differ), 2 (the
    cubic Hermite interpolant of values ``ga``, ``gb`` and rates times the step ``sa``, ``sb`` has an
    extremum inside the step, stored in ``crit[k]``, that crosses zero or comes near it), 0; returns
    whether any is flagged."""
    any_flag = False
    for k in range(ga.size):
        g0 = ga[k]
        g1 = gb[k]
        s0 = sa[k]
        s1 = sb[k]
        flag[k] = 0
        n_crit[k] = 0
        if g0 != 0.0 and (g1 == 0.0 or (g0 > 0.0) != (g1 > 0.0)):
            flag[k] = 1
        # p(x) = g0 + s0 x + b x^2 + a x^3; its extrema: roots of s0 + 2 b x + 3 a x^2 in (0, 1)
        b = 3.0 * (g1 - g0) - 2.0 * s0 - s1
        a = s0 + s1 - 2.0 * (g1 - g0)
        big = max(abs(g0), abs(g1))
        for m in range(2):
            x = -1.0
            if a != 0.0:
                disc = b * b - 3.0 * a * s0
                if disc >= 0.0:
                    root = np.sqrt(disc)
                    x = (-b - root) / (3.0 * a) if m == 0 else (-b + root) / (3.0 * a)
            elif m == 0 and b != 0.0:
                x = -s0 / (2.0 * b)
            if 0.0 < x < 1.0:
                v = g0 + x * (s0 + x * (b + x * a))
                if v * g0 <= 0.0 or v * g1 <= 0.0 or abs(v) < NEAR * big:
                    crit[k, n_crit[k]] = x
                    n_crit[k] += 1
        if n_crit[k] > 0:
            flag[k] = 2
        if flag[k] > 0:
            any_flag = True
    return any_flag


@njit(cache=True, error_model="numpy")
def interpolate(F, y, alt, x, i):
    """Component ``i`` of the step's interpolant at ``x`` in [0, 1]."""
    xm = 1.0 - x
    v = 0.0
    for r in range(F.shape[0] - 1, -1, -1):
        v = (v + F[r, i]) * (xm if alt[r] else x)
    return y[i] + v


def _interpolant_event(values):
    def event_at(F, y, alt, x, c, p, ev, work):
        """Event ``c`` (a component, or ``-1 - j``: event function ``j``) of the interpolant at ``x``."""
        if c >= 0:
            return interpolate(F, y, alt, x, c)
        xm = 1.0 - x
        for i in range(y.size):
            v = 0.0
            for r in range(F.shape[0] - 1, -1, -1):
                v = (v + F[r, i]) * (xm if alt[r] else x)
            work[i] = y[i] + v
        return values(work, p, ev)[-1 - c]

    return event_at


def _no_values(s, p, ev):
    """Stand-in event functions of a kernel whose model has none (never called: no event is negative)."""
    return np.empty(0)


def locator(values=None, event_at=None):
    """``locate(...)``, the one zero-crossing locator of every path: the crossings of the flagged events inside
    the step from ``t`` (length ``h``), the state components' (``events[k] >= 0``) first, then the model's
    event functions' (``events[k] = -1 - j``), appended to ``ev_t``, ``ev_k`` from ``n_ev``; returns the new
    count.  ``xs``, ``gs`` (SAMPLES + 3): work arrays.

    ``event_at(F, y, alt, x, c, p, ev, work)``: event ``c`` at ``x`` in [0, 1] of the step; by default on the
    kernels' interpolant ``F``, ``alt`` about ``y``, event function ``j`` as ``values(s, p, ev)[j]`` (a
    compiled function; ``None`` for a model without them) at the interpolated state (into ``work``).  The
    SciPy hand-over passes its own (on SciPy's dense output) and runs ``locate.py_func`` in Python.
    """
    if event_at is None:
        event_at = njit(error_model="numpy")(_interpolant_event(
            njit(error_model="numpy")(_no_values) if values is None else values))

    def locate(events, F, y, alt, t, h, p, ev, work, ga, gb, crit, n_crit, flag, xs, gs, ev_t, ev_k, n_ev):
        for functions in range(2):  # the components' rows first, then the event functions'
            for k in range(events.size):
                c = events[k]
                if flag[k] == 0 or (c < 0) != (functions == 1):
                    continue
                # the brackets: xs[0] = 0 < xs[1] < ... < xs[ns - 1] = 1 with the event's values gs
                xs[0] = 0.0
                gs[0] = ga[k]
                ns = 1
                if flag[k] == 2:
                    for m in range(1, SAMPLES):
                        xs[ns] = m / SAMPLES
                        ns += 1
                    for m in range(n_crit[k]):
                        xs[ns] = crit[k, m]
                        ns += 1
                    for m in range(2, ns):  # insertion sort of the interior points
                        x = xs[m]
                        j = m - 1
                        while j >= 1 and xs[j] > x:
                            xs[j + 1] = xs[j]
                            j -= 1
                        xs[j + 1] = x
                    for m in range(1, ns):
                        gs[m] = event_at(F, y, alt, xs[m], c, p, ev, work)
                xs[ns] = 1.0
                gs[ns] = gb[k]
                ns += 1
                for m in range(1, ns):
                    a, b, fa_, fb_ = xs[m - 1], xs[m], gs[m - 1], gs[m]
                    if b <= a or fa_ == 0.0 or not (fb_ == 0.0 or (fa_ > 0.0) != (fb_ > 0.0)):
                        continue
                    x = b
                    if fb_ != 0.0:
                        # Illinois: regula falsi on the interpolant, the stale end's value halved
                        side = 0
                        for _ in range(MAX_ITER):
                            x = (a * fb_ - b * fa_) / (fb_ - fa_)
                            if not (a < x < b):
                                x = 0.5 * (a + b)
                            fx = event_at(F, y, alt, x, c, p, ev, work)
                            if fx == 0.0:
                                break
                            if (fx > 0.0) == (fb_ > 0.0):
                                b, fb_ = x, fx
                                if side == -1:
                                    fa_ *= 0.5
                                side = -1
                            else:
                                a, fa_ = x, fx
                                if side == 1:
                                    fb_ *= 0.5
                                side = 1
                            if b - a <= 4.0 * _EPS:
                                break
                    if n_ev < ev_t.size:
                        ev_t[n_ev] = t + x * h
                        ev_k[n_ev] = k
                        n_ev += 1
        return n_ev

    return njit(error_model="numpy")(locate)


@njit(cache=True, error_model="numpy")
def hermite_coefficients(y_old, y_new, f_old, f_new, h, F):
    """Cubic Hermite interpolant of one step in the power-series form (``F`` is 3 x n)."""
    for i in range(y_old.size):
        dy = y_new[i] - y_old[i]
        a = h * f_old[i]
        b = h * f_new[i]
        F[0, i] = a
        F[1, i] = 3.0 * dy - 2.0 * a - b
        F[2, i] = -2.0 * dy + a + b


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
