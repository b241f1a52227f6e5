"""Event location shared by the kernels (:mod:`.fixed`, :mod:`.erk`), and how it works.

:func:`alloc` (inlined by numba into the kernel) makes the events' workspace;
:func:`event_functions` makes the helpers of a model's event functions for
one kernel.  The per-step moves below (the events' values at the ends of a
step, the ``suspect`` bound, the output rows) are written out in each
kernel's loop: as functions, inlined by numba or called, they cost the
kernels 1.5-4x per evaluation (numba counts the references to every array
passed to them, at every step).  The interpolant of a step is ``F``
(``dense_rows`` x n, rows alternating as ``alt`` says) about ``y``, see
:mod:`.common`.

An event is a state component (``events[k] = c >= 0``) or an event function
of the model (``events[k] = -1 - j``: ``event_values(s, p)[j]``).  Its zero
crossings are found in three moves (:mod:`knifeedge.integrators.common`):

1. the ends: its value ``g`` and rate ``h dg/dt`` at both ends of the step
   (a component's rate is its derivative; an event function's is a forward
   difference over 1e-7 of the step);
2. ``screen`` (called only when the bound ``suspect`` leaves doubt: the Hermite
   cubic differs from the chord by at most x (1 - x) max(|s0 - d|, |s1 - d|) <= dev
   (d = g1 - g0), so ends of one sign whose smaller magnitude exceeds dev + NEAR
   times the larger one leave nothing to screen,
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
end of the previous one).  The output: the rows of an accepted step, every
step or the requested times ``t_eval`` inside it (on the interpolant).
"""
import numpy as np
from numba import njit

from .common import MAX_ITER, SAMPLES

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
