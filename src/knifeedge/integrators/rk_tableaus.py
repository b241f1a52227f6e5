"""Butcher tableaus of the Dormand--Prince 5(4) pair and the Gauss--Legendre methods.

Dormand--Prince 5(4) (``DP54``): J. R. Dormand, P. J. Prince, "A family of
embedded Runge-Kutta formulae", J. Comput. Appl. Math. 6 (1980) 19-26; the
dense-output matrix ``DP54_P`` is Shampine's (Math. Comp. 46 (1986) 135-150)
with the optimum c6, the same tables SciPy's ``RK45`` uses.

Gauss--Legendre collocation with s = 1, 2, 3 stages (orders 2, 4, 6): E. Hairer,
C. Lubich, G. Wanner, *Geometric Numerical Integration*, Table II.1.1 and
Sect. II.1.3.  s = 1 is the implicit midpoint rule.  These methods are
symmetric (time-reversible) and conserve every quadratic invariant.
"""
import math

import numpy as np

from .tableau import ExplicitTableau

DP54_C = np.array([0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0])
DP54_A = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0],
    [1 / 5, 0.0, 0.0, 0.0, 0.0],
    [3 / 40, 9 / 40, 0.0, 0.0, 0.0],
    [44 / 45, -56 / 15, 32 / 9, 0.0, 0.0],
    [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0.0],
    [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656],
])
DP54_B = np.array([35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84])
#: error estimator over the 6 stages and f at the new point (FSAL)
DP54_E = np.array([-71 / 57600, 0.0, 71 / 16695, -71 / 1920, 17253 / 339200, -22 / 525, 1 / 40])
#: dense output: y(t + x h) = y + h * sum_j (K^T P)[:, j] x^(j+1)
DP54_P = np.array([
    [1.0, -8048581381 / 2820520608, 8663915743 / 2820520608, -12715105075 / 11282082432],
    [0.0, 0.0, 0.0, 0.0],
    [0.0, 131558114200 / 32700410799, -68118460800 / 10900136933, 87487479700 / 32700410799],
    [0.0, -1754552775 / 470086768, 14199869525 / 1410260304, -10690763975 / 1880347072],
    [0.0, 127303824393 / 49829197408, -318862633887 / 49829197408, 701980252875 / 199316789632],
    [0.0, -282668133 / 205662961, 2019193451 / 616988883, -1453857185 / 822651844],
    [0.0, 40617522 / 29380423, -110615467 / 29380423, 69997945 / 29380423],
])

_S3 = math.sqrt(3.0)
_S15 = math.sqrt(15.0)
#: stages -> (A, b, c) of the Gauss--Legendre method of order 2 s
GAUSS = {
    1: (np.array([[0.5]]), np.array([1.0]), np.array([0.5])),
    2: (
        np.array([[0.25, 0.25 - _S3 / 6], [0.25 + _S3 / 6, 0.25]]),
        np.array([0.5, 0.5]),
        np.array([0.5 - _S3 / 6, 0.5 + _S3 / 6]),
    ),
    3: (
        np.array([
            [5 / 36, 2 / 9 - _S15 / 15, 5 / 36 - _S15 / 30],
            [5 / 36 + _S15 / 24, 2 / 9, 5 / 36 - _S15 / 24],
            [5 / 36 + _S15 / 30, 2 / 9 + _S15 / 15, 5 / 36],
        ]),
        np.array([5 / 18, 4 / 9, 5 / 18]),
        np.array([0.5 - _S15 / 10, 0.5, 0.5 + _S15 / 10]),
    ),
}

#: classical Runge--Kutta method of order 4
RK4_C = np.array([0.0, 0.5, 0.5, 1.0])
RK4_B = np.array([1 / 6, 1 / 3, 1 / 3, 1 / 6])

#: Dormand--Prince 5(4) as registry data (see :mod:`.tableau`), SciPy's ``RK45``
DP54 = ExplicitTableau(
    name="DP54", c=DP54_C, A=np.pad(DP54_A, ((0, 0), (0, 1))), b=DP54_B, e=DP54_E, order=5, error_order=4,
    P=DP54_P, description="Dormand-Prince 5(4), dense output of order 4 (SciPy's RK45)",
    reference="J. R. Dormand, P. J. Prince, J. Comput. Appl. Math. 6 (1980) 19-26; Shampine, Math. Comp. 46 (1986)",
)
