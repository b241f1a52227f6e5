"""Tsitouras 5(4) (``"Tsit5"``): the default explicit method of OrdinaryDiffEq.jl and diffrax.

Ch. Tsitouras, "Runge--Kutta pairs of order 5(4) satisfying only the first
column simplifying assumption", Comput. Math. Appl. 62 (2011) 770--775.
Seven stages with the first-same-as-last property, a 4th-order embedded
estimate, and a continuous extension of order 4 whose weights ``b_j(x)``
are the polynomials of the paper (as given, factored, in OrdinaryDiffEq.jl
and diffrax); they are expanded here into the power-series matrix ``P``.
"""
import numpy as np
from numpy.polynomial import polynomial as _poly

from .tableau import ExplicitTableau

_C = [0.0, 0.161, 0.327, 0.9, 0.9800255409045096857298102862870245954942, 1.0]
_A = np.zeros((6, 6))
_A[1, 0] = 0.161
_A[2, :2] = [-0.008480655492356988544426874250230774675121, 0.3354806554923569885444268742502307746751]
_A[3, :3] = [2.897153057105493432130432594192938764925, -6.359448489975074843148159912383825625953,
             4.362295432869581411017727318190886861028]
_A[4, :4] = [5.325864828439256604428877920840511317836, -11.74888356406282787774717033978577296189,
             7.495539342889836208304604784564358155659, -0.09249506636175524925650207933207191611350]
_A[5, :5] = [5.861455442946420028659251486982647890394, -12.92096931784710929170611868178335939542,
             8.159367898576158643180400794539253485182, -0.07158497328140099722453054252582973869127,
             -0.02826905039406838290900305721271224146718]
_B = np.array([0.09646076681806522951816731316512876333712, 0.01, 0.4798896504144995747752495322905965199130,
               1.379008574103741893192274821856872770756, -3.290069515436080679901047585711363850116,
               2.324710524099773982415355918398765796109])
#: weights of the embedded 4th-order solution (the 7th over K_s = f(t + h, y_new))
_B_HAT = np.array([0.09468075576583945807478876255758922856118, 0.009183565540343253096776363936645313759814,
                   0.4877705284247615707855642599631228241517, 1.234297566930478985655109673884237654036,
                   -2.707712349983525454881109975059321670690, 1.866628418170587035753719399566211498666,
                   1 / 66])


def _dense_matrix() -> np.ndarray:
    """``P[j, r]``: coefficient of ``x^(r+1)`` in the continuous weight ``b_j(x)`` (Tsitouras 2011, Sect. 3)."""
    x = [0.0, 1.0]  # the polynomial x
    factored = [  # b_j(x) = scale * product of factors (polynomials in x, lowest degree first)
        (-1.0530884977290216, [x, [-1.3299890189751412, 1.0], [0.7139816917074209, -1.4364028541716351, 1.0]]),
        (0.1017, [x, x, [1.2949852507374631, -2.1966568338249754, 1.0]]),
        (2.490627285651252793, [x, x, [1.57803468208092486, -2.38535645472061657, 1.0]]),
        (-16.54810288924490272, [x, x, [-1.21712927295533244, 1.0], [-0.61620406037800089, 1.0]]),
        (47.37952196281928122, [x, x, [-1.203071208372362603, 1.0], [-0.658047292653547382, 1.0]]),
        (-34.87065786149660974, [x, x, [-1.2, 1.0], [-0.666666666666666667, 1.0]]),
        (2.5, [x, x, [-1.0, 1.0], [-0.6, 1.0]]),
    ]
    P = np.zeros((7, 4))
    for j, (scale, factors) in enumerate(factored):
        p = np.array([scale])
        for f in factors:
            p = _poly.polymul(p, f)
        P[j, : p.size - 1] = p[1:]  # no constant term
    # the published factors are rounded to ~16 digits: make b_j(1) equal the weights exactly
    P[:6, -1] += _B - P[:6].sum(axis=1)
    P[6, -1] -= P[6].sum()
    return P


TSIT5 = ExplicitTableau(
    name="Tsit5", c=_C, A=_A, b=_B, e=np.append(_B, 0.0) - _B_HAT, order=5, error_order=4, P=_dense_matrix(),
    description="Tsitouras 5(4), 7 stages (first same as last), dense output of order 4",
    reference="Ch. Tsitouras, Comput. Math. Appl. 62 (2011) 770-775",
)
