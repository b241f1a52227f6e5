"""Compiled helpers of the integrators: output rows and the location of zero crossings, for every method.

They are compiled once per machine and shared by every integrator (numba
caches them beside this module).  An event is a state component
(``events[k] = c >= 0``) or an event function of the model (``events[k] =
-1 - j``: ``event_values(s, p)[j]``, called through the address ``ev[0]``
of the model's ``events`` part).  Its zero crossings are found in three
moves: its value ``g`` and rate ``h dg/dt`` at both ends of the step (a
component's rate is its derivative; an event function's is a forward
difference over 1e-7 of the step); :func:`screen` (called only when a bound
leaves doubt): a crossing is certain when the signs at the ends differ, a
pair of crossings inside the step is suspected when the cubic Hermite
interpolant of those four numbers has an extremum inside the step that
crosses zero or comes within ``NEAR`` of the larger end value of it;
:func:`locate`: a suspected step is sampled on the step's dense output at
``SAMPLES - 1`` equally spaced interior points and the Hermite extrema, and
each sign change between neighbouring samples is refined by the Illinois
variant of regula falsi (always bracketed, to a few ulps of the step).  The interpolant of a step is ``F`` (rows
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

from .fnptr import call_void

_EPS = np.finfo(np.float64).eps
#: interior samples of a suspected step: SAMPLES - 1 equally spaced points, plus the Hermite extrema
SAMPLES = 8
#: a Hermite extremum within this fraction of the larger end value of zero makes the step suspect
NEAR = 0.5
#: Illinois iterations (it stops at the resolution of x, a few ulps, long before)
MAX_ITER = 200


@njit(cache=True)
def no_event_values(s, p):
    """Stand-in ``event_values`` of a model without event functions (never called: no event is negative)."""
    return np.empty(0)


#: the columns of the event work array ``g`` (one row per event): values at the ends of the step, rates times
#: the step at the ends, the Hermite extrema inside the step (their fractions), how many, and the flag
GA, GB, SA, SB, CRIT0, CRIT1, N_CRIT, FLAG = range(8)


@njit(cache=True, error_model="numpy")
def screen(g):
    """Which events may cross zero inside the step (rows of ``g``, columns :data:`GA` .. :data:`FLAG`): ``FLAG``
    1 (the signs at the ends differ), 2 (the cubic Hermite interpolant of values ``GA``, ``GB`` and rates times
    the step ``SA``, ``SB`` has an extremum inside the step, stored from ``CRIT0``, that crosses zero or comes
    near it), 0; returns whether any is flagged."""
    any_flag = False
    for k in range(g.shape[0]):
        g0 = g[k, GA]
        g1 = g[k, GB]
        s0 = g[k, SA]
        s1 = g[k, SB]
        flag = 0.0
        n_crit = 0
        if g0 != 0.0 and (g1 == 0.0 or (g0 > 0.0) != (g1 > 0.0)):
            flag = 1.0
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
                    g[k, CRIT0 + n_crit] = x
                    n_crit += 1
        g[k, N_CRIT] = n_crit
        g[k, FLAG] = 2.0 if n_crit > 0 else flag
        if g[k, FLAG] > 0.0:
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


@njit(cache=True, error_model="numpy")
def values(s, p, ev):
    """The model's event functions at ``s`` (``ev``: the address of its ``events`` part and their number)."""
    out = np.empty(ev[1])
    call_void(ev[0], (s, p, np.int64(p.size), out))
    return out


@njit(cache=True, error_model="numpy")
def function_ends(events, y, y_new, fa, fb, h, p, ev, work, g):
    """Values and rates (times ``h``) of the event functions at the ends of a step (a forward difference over
    1e-7 of the step), into the rows of ``g``."""
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
            g[k, GA] = va[j]
            g[k, GB] = vb[j]
            g[k, SA] = (wa[j] - va[j]) / 1e-7
            g[k, SB] = (wb[j] - vb[j]) / 1e-7


@njit(cache=True, error_model="numpy")
def screen_step(events, y, y_new, fa, fb, h, p, ev, work, g):
    """Whether any of ``events`` may cross zero inside the step from ``y`` to ``y_new`` (derivatives ``fa``,
    ``fb``, length ``h``): their values and rates at the ends, then :func:`screen` where the bound below leaves
    doubt (for an event far from zero, almost never)."""
    n_fun = 0
    for k in range(events.size):
        c = events[k]
        if c >= 0:
            g[k, GA] = y[c]
            g[k, GB] = y_new[c]
            g[k, SA] = h * fa[c]
            g[k, SB] = h * fb[c]
        else:
            n_fun += 1
    if n_fun > 0:
        function_ends(events, y, y_new, fa, fb, h, p, ev, work, g)
    # the Hermite cubic differs from the chord by at most x (1 - x) max(|s0 - d|, |s1 - d|) <= dev
    # (d = g1 - g0), so ends of one sign whose smaller magnitude exceeds dev + NEAR * the larger one
    # leave nothing to screen (the usual step)
    for k in range(events.size):
        g0 = g[k, GA]
        g1 = g[k, GB]
        if g0 == 0.0 or g1 == 0.0 or (g0 > 0.0) != (g1 > 0.0):
            return screen(g)
        d = g1 - g0
        dev = 0.25 * max(abs(g[k, SA] - d), abs(g[k, SB] - d))
        if min(abs(g0), abs(g1)) - dev <= NEAR * max(abs(g0), abs(g1)):
            return screen(g)
    return False


@njit(cache=True, error_model="numpy")
def event_at(F, y, alt, x, c, p, ev, work):
    """Event ``c`` (a state component ``c >= 0``, or event function ``-1 - c``) on the interpolant at ``x``."""
    if c >= 0:
        return interpolate(F, y, alt, x, c)
    xm = 1.0 - x
    for i in range(y.size):
        v = 0.0
        for r in range(F.shape[0] - 1, -1, -1):
            v = (v + F[r, i]) * (xm if alt[r] else x)
        work[i] = y[i] + v
    return values(work, p, ev)[-1 - c]


@njit(cache=True, error_model="numpy")
def _brackets(gk, F, y, alt, c, p, ev, work, xs, gs):
    """The brackets of a flagged event (its row ``gk`` of ``g``): ``xs[0] = 0 < xs[1] < ... < xs[ns - 1] = 1``
    with its values ``gs`` (flag 2: at ``SAMPLES - 1`` equally spaced interior points and its Hermite extrema);
    returns ``ns``."""
    xs[0] = 0.0
    gs[0] = gk[GA]
    ns = 1
    if gk[FLAG] == 2.0:
        for m in range(1, SAMPLES):
            xs[ns] = m / SAMPLES
            ns += 1
        for m in range(int(gk[N_CRIT])):
            xs[ns] = gk[CRIT0 + m]
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
    gs[ns] = gk[GB]
    return ns + 1


@njit(cache=True, error_model="numpy")
def _refine(a, b, fa_, fb_, F, y, alt, c, p, ev, work):
    """The zero in the bracket ``[a, b]`` (values ``fa_ != 0``, ``fb_`` of opposite signs or ``fb_ == 0``):
    Illinois, regula falsi on the interpolant with the stale end's value halved, to a few ulps."""
    x = b
    if fb_ == 0.0:
        return x
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
    return x


@njit(cache=True, error_model="numpy")
def locate(events, F, y, alt, t, h, p, ev, work, g, ev_t, ev_k, n_ev):
    """Zero crossings of the events :func:`screen` flagged inside the step from ``t`` (length ``h``,
    interpolant ``F``, ``alt``), appended to ``ev_t``, ``ev_k`` from ``n_ev`` (state components first, then
    event functions); returns the new count.  Each sign change between neighbouring samples is refined on the
    interpolant (:func:`_refine`); a zero at the start of a bracket is not a crossing (it ended the last one)."""
    xs = np.empty(SAMPLES + 3)
    gs = np.empty(SAMPLES + 3)
    for functions in range(2):
        for k in range(events.size):
            c = events[k]
            if g[k, FLAG] == 0.0 or (c < 0) != (functions == 1):
                continue
            ns = _brackets(g[k], F, y, alt, c, p, ev, work, xs, gs)
            for m in range(1, ns):
                a, b, fa_, fb_ = xs[m - 1], xs[m], gs[m - 1], gs[m]
                if b <= a or fa_ == 0.0 or not (fb_ == 0.0 or (fa_ > 0.0) != (fb_ > 0.0)):
                    continue
                x = _refine(a, b, fa_, fb_, F, y, alt, c, p, ev, work)
                if n_ev < ev_t.size:
                    ev_t[n_ev] = t + x * h
                    ev_k[n_ev] = k
                    n_ev += 1
    return n_ev


@njit(cache=True, error_model="numpy")
def output(every, ts, ys, n_out, t_eval, ie, t, h, t_new, y, y_new, F, alt):
    """The rows of an accepted step from ``t`` to ``t_new``: every step, or the times ``t_eval[ie:]`` inside
    it on the interpolant ``F``; returns the new ``(n_out, ie)``."""
    if every:  # the common case: a row per step
        ts[n_out] = t_new
        for i in range(y.size):
            ys[n_out, i] = y_new[i]
        return n_out + 1, ie
    while ie < t_eval.size and t_eval[ie] <= t_new:
        te = t_eval[ie]
        ts[n_out] = te
        x = (te - t) / h
        for i in range(y.size):
            ys[n_out, i] = y_new[i] if te == t_new else interpolate(F, y, alt, x, i)
        n_out += 1
        ie += 1
    return n_out, ie


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
