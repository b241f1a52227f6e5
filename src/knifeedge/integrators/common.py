"""Event location shared by every path (the kernels of :mod:`.erk` and :mod:`.fixed`, the SciPy hand-over), and
the kernels' helpers that never call a right-hand side.

A step's interpolant is ``F`` (rows x n) in one Horner scheme, ``y[i] + v`` with
``v = (v + F[r, i]) * (1 - x if alt[r] else x)`` from the last row (Hairer's DOP853 form alternates the
factors; the power series of the others has ``x`` throughout).  An event is a state component
(``events[k] = c >= 0``) or the model's event function ``j`` (``events[k] = -1 - j``).  Its crossings:

1. its value and rate times ``h`` at both ends of the step (an event function's rate: a forward difference over
   1e-7 of the step);
2. :func:`screen`, called only when the bound ``suspect`` of the kernels' loops leaves doubt (the Hermite
   cubic is within ``dev = max(|s0 - d|, |s1 - d|) / 4`` of the chord, ``d = g1 - g0``: ends of one sign whose
   smaller magnitude exceeds ``dev`` + ``NEAR`` times the larger leave nothing to screen): a crossing is certain when the signs at the ends differ, a pair inside the step is suspected when the
   cubic Hermite interpolant of those four numbers has an extremum inside that crosses zero or comes within
   ``NEAR`` of the larger end value;
3. :func:`locator`: a suspected step is sampled at ``SAMPLES - 1`` equally spaced points and the Hermite
   extrema, each sign change refined by Illinois regula falsi to a few ulps of the step.

A zero at the start of a bracket is not a crossing (it ended the previous one).  The helpers avoid array
slicing and broadcasting assignments (numba compiles their error messages, half a kernel's compile time).
"""
import numpy as np
from numba import njit

_EPS = np.finfo(np.float64).eps
#: interior samples of a suspected step: SAMPLES - 1 equally spaced points, plus the Hermite extrema
SAMPLES = 8
#: most zero crossings of one event a kernel finds in one step (room the event buffers keep per event)
EVENTS_PER_STEP = SAMPLES + 2
#: a Hermite extremum within this fraction of the larger end value of zero makes the step suspect
NEAR = 0.5
#: Illinois iterations (it stops at the resolution of x, a few ulps, long before)
MAX_ITER = 200
#: the step-size controller's safety factor and the bounds of its factor (SciPy's)
SAFETY, MIN_FACTOR, MAX_FACTOR = 0.9, 0.2, 10.0


@njit(cache=True, error_model="numpy")
def step_factor(err, exponent, eighth):
    """The step-size controller, every adaptive loop's: the factor of the next step after a step with the scaled
    error ``err``, ``SAFETY err**exponent`` (``exponent`` = -1 / (1 + the order of the error estimate); ``eighth``:
    ``err**(-1/8)`` as three square roots, cheaper than pow) within [``MIN_FACTOR``, ``MAX_FACTOR``];
    ``MAX_FACTOR`` at a zero error, ``MIN_FACTOR`` at one that is not finite."""
    if err == 0.0:
        return MAX_FACTOR
    if not np.isfinite(err):
        return MIN_FACTOR
    power = 1.0 / np.sqrt(np.sqrt(np.sqrt(err))) if eighth else err ** exponent
    return min(MAX_FACTOR, max(MIN_FACTOR, SAFETY * power))


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
    def event_at(step, x, c):
        """Event ``c`` (a component, or ``-1 - j``: event function ``j``) of the interpolant at ``x``."""
        F, y, alt, p, ev, work = step
        if c >= 0:
            return interpolate(F, y, alt, x, c)
        for i in range(y.size):
            work[i] = interpolate(F, y, alt, x, i)
        return values(work, p, ev)[-1 - c]

    return event_at


def _no_values(s, p, ev):
    """Stand-in event functions of a kernel whose model has none (never called: no event is negative)."""
    return np.empty(0)


def locator(values=None, event_at=None):
    """``locate(events, step, t, h, marks, found, n_ev)``, the one zero-crossing locator of every path: the
    crossings of the flagged events in the step from ``t`` (length ``h``), the components' first, then the event
    functions', appended to ``found = (ev_t, ev_k)`` from ``n_ev``; returns the new count.  ``marks`` is
    ``(ga, gb, crit, n_crit, flag, xs, gs)``: the ends' values, :func:`screen`'s verdicts, two work arrays.

    ``event_at(step, x, c)``: event ``c`` at ``x`` in [0, 1]; by default on the kernels' interpolant, ``step =
    (F, y, alt, p, ev, work)``, event function ``j`` being ``values(s, p, ev)[j]`` (``None``: the model has
    none).  The SciPy hand-over passes its own and runs ``locate.py_func`` in Python.
    """
    if event_at is None:
        event_at = njit(error_model="numpy")(_interpolant_event(
            njit(error_model="numpy")(_no_values) if values is None else values))

    def locate(events, step, t, h, marks, found, n_ev):
        ga, gb, crit, n_crit, flag, xs, gs = marks
        ev_t, ev_k = found
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
                        gs[m] = event_at(step, xs[m], c)
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
                            fx = event_at(step, x, c)
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


@njit(inline="always", error_model="numpy")
def alloc(events):
    """The event workspace: ``ne, n_fun, ga, gb, sa, sb, crit, n_crit, flag, xs, gs``."""
    ne = events.size
    n_fun = 0
    for k in range(ne):
        if events[k] < 0:
            n_fun += 1
    ga = np.zeros(ne)
    gb = np.zeros(ne)
    sa = np.zeros(ne)
    sb = np.zeros(ne)
    crit = np.zeros((ne, 2))
    n_crit = np.zeros(ne, dtype=np.int64)
    flag = np.zeros(ne, dtype=np.int64)
    xs = np.empty(SAMPLES + 3)
    gs = np.empty(SAMPLES + 3)
    return ne, n_fun, ga, gb, sa, sb, crit, n_crit, flag, xs, gs


def function_ends(values):
    """``function_ends(...)``: the values and rates (times ``h``) at a step's ends of the event functions
    ``values(s, p, ev)`` (a compiled function)."""

    def function_ends(events, y, y_new, fa, fb, h, p, ev, work, ga, gb, sa, sb):
        dt = 1e-7 * h
        va = values(y, p, ev)
        vb = values(y_new, p, ev)
        for i in range(y.size):
            work[i] = y[i] + dt * fa[i]
        wa = values(work, p, ev)
        for i in range(y.size):
            work[i] = y_new[i] + dt * fb[i]
        wb = values(work, p, ev)
        for k in range(events.size):
            j = -1 - events[k]
            if j >= 0:
                ga[k] = va[j]
                gb[k] = vb[j]
                sa[k] = (wa[j] - va[j]) / 1e-7
                sb[k] = (wb[j] - vb[j]) / 1e-7

    return njit(error_model="numpy")(function_ends)
