"""Event location shared by the kernels (:mod:`.fixed`, :mod:`.erk`), and how it works.

:func:`alloc` (inlined by numba into the kernel) makes the events' workspace;
:func:`function_ends` makes the ends of a model's event functions for one
kernel, :func:`.common.locator` the one locator of every event's crossings.
The per-step moves (the events' values at the ends of a step, the
``suspect`` bound, the output rows) are written out in each kernel's loop:
as functions, inlined by numba or called, they cost the kernels 1.5-4x per evaluation (numba counts the references to every array
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

from .common import SAMPLES

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


def function_ends(values):
    """``function_ends(...)`` for a kernel whose model's event functions are ``values(s, p, ev)`` (a compiled
    function): their values and rates (times ``h``) at the ends of a step (:func:`.common.locator` finds
    their crossings, as the components')."""

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
