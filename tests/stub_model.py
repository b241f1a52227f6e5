"""A stand-in model of the kernels' tests: a harmonic oscillator with a drifting third component.

State ``(q, v, w)`` with ``q' = v``, ``v' = -p[0]**2 q``, ``w' = -q`` (so ``w``
crosses zero), in the form of a generated module (no ``LLVM_IR``).  Its
``constants(p)`` is ``(p[0], p[0]**2)``, as a generated module's holds the
parameters and then their precomputed combinations.
"""
import numpy as np
from numba import njit


@njit(cache=True)
def constants(p):
    return np.array([p[0], p[0] * p[0]])


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    ds[0] = s[1]
    ds[1] = -q[1] * s[0]
    ds[2] = -s[0]


#: the stand-in's event function: q^2 - p[1] (two zeros close together near each extremum of q when
#: p[1] is just below the squared amplitude)
EVENT_NAMES = ("q_squared_minus_p1",)


@njit(cache=True)
def event_values(s, p):
    out = np.empty(1)
    out[0] = s[0] * s[0] - p[1]
    return out
