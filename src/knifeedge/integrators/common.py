"""Compiled helpers shared by the integrator kernels (they never call a right-hand side).

Dense output comes in two forms:

* Hairer's DOP853 interpolant (:func:`dense_dop853`): ``F`` has 7 rows and
  ``y(x) = y_old + x(F0 + (1-x)(F1 + x(F2 + (1-x)(F3 + ...))))``;
* a power series without constant term (:func:`dense_power`):
  ``y(x) = y_old + sum_j F[j] x^(j+1)`` (Dormand--Prince 5(4), Tsitouras 5(4)
  and cubic Hermite).

``x = (t - t_old) / h`` in [0, 1].  Events are the sign changes of state
components between the ends of an accepted step, located on the
interpolant by the Illinois variant of regula falsi (always bracketed).

Every helper avoids array slicing and broadcasting assignments: numba
compiles those with their error-message machinery (string formatting),
which used to be half the compile time of a kernel.
"""
import numpy as np
from numba import njit

_EPS = np.finfo(np.float64).eps


@njit(cache=True, error_model="numpy")
def dense_dop853(F, y_old, x, i):
    """Component ``i`` of Hairer's DOP853 interpolant at ``x`` in [0, 1]."""
    m = F.shape[0]
    y = 0.0
    for j in range(m):
        y += F[m - 1 - j, i]
        if j % 2 == 0:
            y *= x
        else:
            y *= 1.0 - x
    return y_old[i] + y


@njit(cache=True, error_model="numpy")
def dense_power(F, y_old, x, i):
    """Component ``i`` of the power-series interpolant at ``x`` in [0, 1]."""
    y = 0.0
    for j in range(F.shape[0] - 1, -1, -1):
        y = (y + F[j, i]) * x
    return y_old[i] + y


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
def illinois(F, y_old, i, g0, g1, dop853):
    """``x`` in [0, 1] where component ``i`` of the interpolant crosses zero.

    ``g0`` and ``g1`` are its values at the ends, of opposite signs;
    ``dop853`` selects the interpolant's form.  Iterates to the resolution
    of ``x`` (a few ulps), at most 200 times.
    """
    a, b, fa, fb = 0.0, 1.0, g0, g1
    side = 0
    x = 0.5
    for _ in range(200):
        x = (a * fb - b * fa) / (fb - fa)
        if not (a < x < b):
            x = 0.5 * (a + b)
        fx = dense_dop853(F, y_old, x, i) if dop853 else dense_power(F, y_old, x, i)
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
def crossing(g_old, g_new):
    """True when a step from ``g_old`` to ``g_new`` crosses zero (a zero at the start is not counted)."""
    if g_old == 0.0:
        return False
    return g_new == 0.0 or (g_old > 0.0) != (g_new > 0.0)


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
