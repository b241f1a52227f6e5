"""Near-free right-hand sides for measuring an integrator's own cost per evaluation.

``linear3_into`` and ``linear5_into`` are harmonic oscillators with a drifting
last component, of the single-mode and two-mode state sizes (3 and 5): one
or two operations per component, so a kernel specialized to them spends
almost all of its time in its own arithmetic and bookkeeping.
"""
from numba import njit


@njit(cache=True)
def constants(p):
    return p.copy()


@njit(cache=True)
def linear3_into(t, s, q, ds):
    ds[0] = s[1]
    ds[1] = -s[0]
    ds[2] = q[0] * s[0]


@njit(cache=True)
def linear5_into(t, s, q, ds):
    ds[0] = s[2]
    ds[1] = s[3]
    ds[2] = -s[0]
    ds[3] = -s[1]
    ds[4] = q[0] * s[0]
