"""The knife-edge rattlebacks of Jagla & Rojo (arXiv:2309.06154) as data.

Each model is the paper's unconstrained Lagrangian (divided by the total mass
``M``, which cancels) and its non-holonomic constraints, handed unchanged to
:func:`derivation.engine.derive`.  Nothing here is an equation of motion.

Units: lengths ``ell, L, D`` and position ``x, y``; ``g`` is length/time^2;
angles are dimensionless.
"""
from __future__ import annotations

import sympy as sp

from .engine import ModelSpec

t = sp.Symbol("t", real=True)
g, ell, L, D = sp.symbols("g ell L D", positive=True)
alpha = sp.Symbol("alpha", real=True)

x, y, phi = sp.symbols("x y phi", real=True)
x_dot, y_dot, phi_dot = sp.symbols("x_dot y_dot phi_dot", real=True)
x_ddot, y_ddot, phi_ddot = sp.symbols("x_ddot y_ddot phi_ddot", real=True)

theta, theta_dot, theta_ddot = sp.symbols("theta theta_dot theta_ddot", real=True)
theta1, theta1_dot, theta1_ddot = sp.symbols("theta1 theta1_dot theta1_ddot", real=True)
theta2, theta2_dot, theta2_ddot = sp.symbols("theta2 theta2_dot theta2_ddot", real=True)

#: unit vector along the bar, u_phi = (cos phi, sin phi)
u_phi = sp.Matrix([sp.cos(phi), sp.sin(phi)])
#: unit vector perpendicular to the bar, v_phi = (-sin phi, cos phi)
v_phi = sp.Matrix([-sp.sin(phi), sp.cos(phi)])
#: horizontal unit vectors along and across the plane of the contact circle,
#: rotated by the chiral angle alpha from the bar (section III, Fig. sketch_2modes)
u_alpha = sp.Matrix([sp.cos(phi + alpha), sp.sin(phi + alpha)])
v_alpha = sp.Matrix([-sp.sin(phi + alpha), sp.cos(phi + alpha)])
x_vel = sp.Matrix([x_dot, y_dot])

#: theta_alpha = theta2 cos(alpha) - theta1 sin(alpha) (section III)
theta_alpha = theta2 * sp.cos(alpha) - theta1 * sp.sin(alpha)

LENGTH = {"L": 1, "T": 0}
DIMENSIONS = {
    # symbol name -> (length exponent, time exponent)
    "g": (1, -2), "ell": (1, 0), "L": (1, 0), "D": (1, 0), "alpha": (0, 0),
    "x": (1, 0), "y": (1, 0), "phi": (0, 0), "theta": (0, 0), "theta1": (0, 0), "theta2": (0, 0),
    "x_dot": (1, -1), "y_dot": (1, -1), "phi_dot": (0, -1), "theta_dot": (0, -1),
    "theta1_dot": (0, -1), "theta2_dot": (0, -1),
    "x_ddot": (1, -2), "y_ddot": (1, -2), "phi_ddot": (0, -2), "theta_ddot": (0, -2),
    "theta1_ddot": (0, -2), "theta2_ddot": (0, -2),
    "t": (0, 1),
}


def _single_mode() -> ModelSpec:
    """Section II: one tilt ``theta``, spin ``phi``, bar centre ``(x, y)``."""
    lag = sp.Rational(1, 2) * (
        x_dot**2 + y_dot**2 + ell**2 * theta_dot**2 + L**2 * phi_dot**2
        + 2 * ell * theta_dot * (x_vel.dot(v_phi))
    ) - sp.Rational(1, 2) * g * ell * theta**2
    vinculo1 = u_phi.dot(x_vel)
    vinculo2 = x_vel.dot(v_phi) + D * theta * phi_dot
    return ModelSpec(
        name="single_mode",
        coordinates=(x, y, theta, phi),
        velocities=(x_dot, y_dot, theta_dot, phi_dot),
        accelerations=(x_ddot, y_ddot, theta_ddot, phi_ddot),
        lagrangian=lag,
        constraints=(vinculo1, vinculo2),
        constraint_labels=("vinculo1", "vinculo2"),
        dependent=(x, y),
        cyclic={x: 0, y: 0, phi: 0},
        small=(theta,),
        params=(g, ell, L, D),
        pose=(phi, x, y),
        description=(
            "Single-mode knife edge (paper section II): a massless bar of length 2L on the "
            "table, two masses M/2 hanging at distance ell from its ends; one tilt theta, "
            "the contact point shifted by D*theta along the bar (vinculo1, vinculo2)."
        ),
    )


def _two_mode() -> ModelSpec:
    """Section III: tilts ``theta1, theta2``, chiral angle ``alpha``."""
    lag = sp.Rational(1, 2) * (
        x_dot**2 + y_dot**2 + (L**2 + ell**2) * theta2_dot**2 + ell**2 * theta1_dot**2
        + L**2 * phi_dot**2
        + 2 * ell * x_vel.dot(theta1_dot * v_phi - theta2_dot * u_phi)
    ) - sp.Rational(1, 2) * g * ell * (theta1**2 + theta2**2)
    const22 = x_vel.dot(u_alpha)
    const23 = D * theta_alpha * phi_dot + x_vel.dot(v_alpha)
    return ModelSpec(
        name="two_mode",
        coordinates=(x, y, theta1, theta2, phi),
        velocities=(x_dot, y_dot, theta1_dot, theta2_dot, phi_dot),
        accelerations=(x_ddot, y_ddot, theta1_ddot, theta2_ddot, phi_ddot),
        lagrangian=lag,
        constraints=(const22, const23),
        constraint_labels=("Const22", "Const23"),
        dependent=(x, y),
        cyclic={x: 0, y: 0, phi: 0},
        small=(theta1, theta2),
        params=(g, ell, L, D, alpha),
        pose=(phi, x, y),
        description=(
            "Two-mode knife edge (paper section III): tilts theta1, theta2; the contact is the "
            "lowest point of a circle of radius D whose plane makes the chiral angle alpha "
            "with the bar (Const22, Const23)."
        ),
    )


from .sleigh import DIMENSIONS as _SLEIGH_DIMENSIONS, chaplygin_sleigh  # noqa: E402

DIMENSIONS.update(_SLEIGH_DIMENSIONS)
MODELS = {"single_mode": _single_mode(), "two_mode": _two_mode(), "chaplygin_sleigh": chaplygin_sleigh()}
