"""Stand-in right-hand side of the templates: a harmonic oscillator with a drifting third component.

State ``(q, v, w)`` with ``q' = v``, ``v' = -p[0]**2 q``, ``w' = -q`` (so ``w``
crosses zero); only used when a template module is imported as it is.
"""
from numba import njit


@njit(cache=True)
def rhs_into(t, s, p, ds):
    ds[0] = s[1]
    ds[1] = -p[0] * p[0] * s[0]
    ds[2] = -s[0]
