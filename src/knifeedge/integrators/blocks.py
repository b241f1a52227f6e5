"""Output and event location shared by the kernels (:mod:`.fixed`, :mod:`.erk`).

The block functions (:func:`alloc`, :func:`ends`, :func:`suspect`,
:func:`output`) are inlined by numba into the kernel that calls them (a
block of the kernel is cheaper to compile than a call to a helper of its
own, and its loops run over the kernel's constant state size).
:func:`event_functions` makes the helpers of the models' event functions
for one kernel.  The interpolant of a step is ``F`` (``dense_rows`` x n,
rows alternating as ``alt`` says) about ``y``, see :mod:`.common`.

An event is a state component (``events[k] = c >= 0``) or an event function
of the model (``events[k] = -1 - j``: ``event_values(s, p)[j]``).  Its zero
crossings are found in three moves (:mod:`knifeedge.integrators.common`):

1. ``ends``: its value ``g`` and rate ``h dg/dt`` at both ends of the step
   (a component's rate is its derivative; an event function's is a forward
   difference over 1e-7 of the step);
2. ``screen`` (called only when the bound ``suspect`` computes leaves doubt,
   which for an event far from zero is almost never): a crossing is
   certain when the signs at the ends differ; a
   pair of crossings inside the step (same signs at both ends) is suspected
   when the cubic Hermite interpolant of those four numbers has an extremum
   inside the step that crosses zero or comes within ``NEAR`` of the larger
   end value of it;
3. ``locate``: for a suspected step, the event is sampled on the step's
   dense output at ``SAMPLES - 1`` equally spaced interior points and the
   Hermite extrema, and each sign change between neighbouring samples is
   refined by the Illinois variant of regula falsi (always bracketed, to a
   few ulps of the step); a plain crossing is refined on the whole step.

A zero at the start of a bracket is not a crossing (it was counted as the
end of the previous one).  ``output``: the rows of an accepted step, every
step or the requested times ``t_eval`` inside it (on the interpolant).
"""
import numpy as np
from numba import njit

from . import common as _c
from .common import MAX_ITER, NEAR, SAMPLES

_EPS = np.finfo(np.float64).eps
_BLOCK = {"inline": "always", "error_model": "numpy"}


@njit(**_BLOCK)
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


@njit(**_BLOCK)
def ends(events, ne, y, y_new, fa, fb, h, ga, gb, sa, sb):
    """Values and rates (times ``h``) of the state components among the events at the ends of a step."""
    for k in range(ne):
        c = events[k]
        if c >= 0:
            ga[k] = y[c]
            gb[k] = y_new[c]
            sa[k] = h * fa[c]
            sb[k] = h * fb[c]


@njit(**_BLOCK)
def suspect(ne, ga, gb, sa, sb):
    """Whether the screen may flag any event: the Hermite cubic differs from the chord by at most
    x (1 - x) max(|s0 - d|, |s1 - d|) <= dev (d = g1 - g0), so ends of one sign whose smaller magnitude
    exceeds dev + NEAR * the larger one leave nothing to screen (the usual step: no call)."""
    doubt = False
    for k in range(ne):
        g0 = ga[k]
        g1 = gb[k]
        if g0 == 0.0 or g1 == 0.0 or (g0 > 0.0) != (g1 > 0.0):
            doubt = True
        else:
            d = g1 - g0
            dev = 0.25 * max(abs(sa[k] - d), abs(sb[k] - d))
            if min(abs(g0), abs(g1)) - dev <= NEAR * max(abs(g0), abs(g1)):
                doubt = True
    return doubt


@njit(**_BLOCK)
def output(every, ts, ys, n_out, t_new, y_new, t_eval, ie, t, h, F, y, n, dense_rows, alt):
    """Store the rows of an accepted step; returns ``n_out, ie`` (rows stored, next output time)."""
    if every:  # the common case: a row per step
        ts[n_out] = t_new
        for i in range(n):
            ys[n_out, i] = y_new[i]
        n_out += 1
    while not every and ie < t_eval.size and t_eval[ie] <= t_new:
        te = t_eval[ie]
        ts[n_out] = te
        x = (te - t) / h
        xm = 1.0 - x
        for i in range(n):
            if te == t_new:
                ys[n_out, i] = y_new[i]
            else:
                v = 0.0
                for r in range(dense_rows - 1, -1, -1):
                    v = (v + F[r, i]) * (xm if alt[r] else x)
                ys[n_out, i] = y[i] + v
        n_out += 1
        ie += 1
    return n_out, ie


def step_events(function_ends, locate_functions, HAS_FUN: bool, ALT):
    """``(screen_step, record_step)`` of a kernel (inlined into it): the events' screen of an accepted step
    and the location of the crossings it flagged, the model's event functions by ``function_ends`` and
    ``locate_functions`` (:func:`event_functions`; left out where ``HAS_FUN`` is false)."""

    def screen_step(events, work_ev, y, y_new, fa, fb, h, p, ev, work):
        """Whether any event may cross zero in the step (the screen's flags and extrema in ``work_ev``)."""
        ne, n_fun, ga, gb, sa, sb, crit, n_crit, flag, xs, gs = work_ev
        if ne == 0:
            return False
        ends(events, ne, y, y_new, fa, fb, h, ga, gb, sa, sb)
        if HAS_FUN:
            if n_fun > 0:
                function_ends(events, y, y_new, fa, fb, h, p, ev, work, ga, gb, sa, sb)
        if suspect(ne, ga, gb, sa, sb):
            return _c.screen(ga, gb, sa, sb, crit, n_crit, flag)
        return False

    def record_step(events, work_ev, F, y, t, h, p, ev, work, ev_t, ev_k, n_ev):
        """The crossings of the flagged events on the step's interpolant ``F``, appended; returns ``n_ev``."""
        ne, n_fun, ga, gb, sa, sb, crit, n_crit, flag, xs, gs = work_ev
        n_ev = _c.locate(events, F, y, ALT, t, h, ga, gb, crit, n_crit, flag, xs, gs, ev_t, ev_k, n_ev)
        if HAS_FUN:
            if n_fun > 0:
                n_ev = locate_functions(events, F, y, t, h, p, ev, work, ga, gb, crit, n_crit, flag, xs, gs, ev_t,
                                        ev_k, n_ev)
        return n_ev

    return njit(**_BLOCK)(screen_step), njit(**_BLOCK)(record_step)


def event_functions(values, dense_rows: int, alt):
    """``(function_ends, locate_functions)`` for a kernel whose model's event functions are ``values(s, p,
    ev)`` (a compiled function), on its interpolant of ``dense_rows`` rows (``alt``)."""

    def event_at_(F, y, x, j, p, ev, work):
        """Event function ``j`` of the state interpolated at ``x`` in [0, 1] (into ``work``)."""
        xm = 1.0 - x
        for i in range(y.size):
            v = 0.0
            for r in range(dense_rows - 1, -1, -1):
                v = (v + F[r, i]) * (xm if alt[r] else x)
            work[i] = y[i] + v
        return values(work, p, ev)[j]

    event_at = njit(error_model="numpy")(event_at_)

    def function_ends(events, y, y_new, fa, fb, h, p, ev, work, ga, gb, sa, sb):
        """Values and rates (times ``h``) of the event functions at the ends of a step."""
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

    def locate_functions(events, F, y, t, h, p, ev, work, ga, gb, crit, n_crit, flag, xs, gs, ev_t, ev_k, n_ev):
        """As :func:`knifeedge.integrators.common.locate`, for the event functions (``events[k] < 0``)."""
        for k in range(events.size):
            if flag[k] == 0 or events[k] >= 0:
                continue
            c = -1 - events[k]
            ns = _brackets(flag[k], crit, n_crit[k], k, xs, gs, ga[k])
            for m in range(1, ns):
                gs[m] = event_at(F, y, xs[m], c, p, ev, work)
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
                        fx = event_at(F, y, x, c, p, ev, work)
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

    return njit(error_model="numpy")(function_ends), njit(error_model="numpy")(locate_functions)


@njit(**_BLOCK)
def _brackets(flag, crit, n_crit, k, xs, gs, g0):
    """The interior points of a suspected step, sorted: ``xs[0] = 0 < xs[1] < ... < xs[ns - 1]``; returns
    ``ns`` (``gs[0] = g0``; the caller fills ``gs[1:ns]`` and appends the end ``x = 1``)."""
    xs[0] = 0.0
    gs[0] = g0
    ns = 1
    if flag == 2:
        for m in range(1, SAMPLES):
            xs[ns] = m / SAMPLES
            ns += 1
        for m in range(n_crit):
            xs[ns] = crit[k, m]
            ns += 1
        for m in range(2, ns):  # insertion sort of the interior points
            x = xs[m]
            j = m - 1
            while j >= 1 and xs[j] > x:
                xs[j + 1] = xs[j]
                j -= 1
            xs[j + 1] = x
    return ns
