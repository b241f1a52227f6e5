"""Closed-form solution of the single-mode amplitude equations (paper Eqs. Chap3, an).

With the errata applied (``docs/errata.md``): the spin equation is
``dA_phi/dt = -(g D / (2 L^2)) A_theta^2`` (no factor ell), and

    A_phi(t)   = -A0 tanh(A0 D (t - t_R) / (2 ell))           (an1, sign corrected)
    A_theta(t) =  A0 L / sqrt(g ell) sech(A0 D (t - t_R) / (2 ell))   (an2, dimensions corrected)

for a spin that starts positive.  ``A_phi^2 + (g ell / L^2) A_theta^2 = A0^2``
is conserved (the ellipses of Fig. 'Elipses').  Units: any consistent set.
"""
from __future__ import annotations

import math

import numpy as np


def asymptotic_spin(phi_dot0: float, a_theta0: float, g: float, ell: float, L: float) -> float:
    """``A0``: the conserved ``sqrt(A_phi^2 + (g ell/L^2) A_theta^2)`` at t = 0."""
    return math.sqrt(phi_dot0**2 + g * ell / L**2 * a_theta0**2)


def first_reversal_time(phi_dot0: float, a_theta0: float, g: float, ell: float, L: float, D: float) -> float:
    """Time at which ``A_phi`` crosses zero, for ``A_phi(0) = phi_dot0 > 0``, ``A_theta(0) = a_theta0``.

    ``t_R = (2 ell / (A0 D)) arccosh(A0 L / (sqrt(g ell) a_theta0))``.
    """
    a0 = asymptotic_spin(phi_dot0, a_theta0, g, ell, L)
    return 2 * ell / (a0 * D) * math.acosh(a0 * L / (math.sqrt(g * ell) * a_theta0))


def amplitudes(t, t_r: float, a0: float, g: float, ell: float, L: float, D: float) -> tuple:
    """``(A_theta(t), A_phi(t))``, arrays of the shape of ``t``."""
    x = a0 * D * (np.asarray(t, float) - t_r) / (2 * ell)
    return a0 * L / math.sqrt(g * ell) / np.cosh(x), -a0 * np.tanh(x)
