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
from .steady import Steady
from .sleigh import DIMENSIONS as _SLEIGH_DIMENSIONS, chaplygin_sleigh

t = sp.Symbol("t", real=True)
g, ell, L, D = sp.symbols("g ell L D", positive=True)
alpha = sp.Symbol("alpha", real=True)

x, y, phi = sp.symbols("x y phi", real=True)
x_dot, y_dot, phi_dot = sp.symbols("x_dot y_dot phi_dot", real=True)
x_ddot, y_ddot, phi_ddot = sp.symbols("x_ddot y_ddot phi_ddot", real=True)

theta, theta_dot, theta_ddot = sp.symbols("theta theta_dot theta_ddot", real=True)
theta1, theta1_dot, theta1_ddot = sp.symbols("theta1 theta1_dot theta1_ddot", real=True)
theta2, theta2_dot, theta2_ddot = sp.symbols("theta2 theta2_dot theta2_ddot", real=True)
#: the spin rate of the steady spins (derivation/steady.py)
Omega = sp.Symbol("Omega", real=True)

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

_KNIFE_EDGE_DIMENSIONS = {
    # symbol name -> (length exponent, time exponent)
    "g": (1, -2), "ell": (1, 0), "L": (1, 0), "D": (1, 0), "alpha": (0, 0),
    "x": (1, 0), "y": (1, 0), "phi": (0, 0), "theta": (0, 0), "theta1": (0, 0), "theta2": (0, 0),
    "x_dot": (1, -1), "y_dot": (1, -1), "phi_dot": (0, -1), "theta_dot": (0, -1),
    "theta1_dot": (0, -1), "theta2_dot": (0, -1),
    "x_ddot": (1, -2), "y_ddot": (1, -2), "phi_ddot": (0, -2), "theta_ddot": (0, -2),
    "theta1_ddot": (0, -2), "theta2_ddot": (0, -2),
    "t": (0, 1),
}
#: symbol name -> (length exponent, time exponent), of every model here
DIMENSIONS = {**_KNIFE_EDGE_DIMENSIONS, **_SLEIGH_DIMENSIONS}


def units(symbols) -> dict:
    """Unit strings of ``symbols`` from their (length, time) exponents: ``rad``, ``length``, ``length/time^2``."""
    out = {}
    for s in symbols:
        length, time = DIMENSIONS[str(s)]
        num = "length" if length else "rad"
        out[s] = num + ("/time" + ("^2" if time == -2 else "") if time < 0 else "")
    return out


#: largest tilt (rad) at which the small-angle fidelities are declared valid, per model: there the first
#: spin reversal of ``reduced`` is within 0.1% of ``full`` (measured from the default state with the
#: spin rate raised until the tilt reaches the bound: single mode 0.06% at 0.199 rad, 0.02% at 0.209 rad,
#: but 0.7% at 0.217 rad and 2.4% at 0.29 rad; two mode 0.05% at 0.4 rad, 0.03% at 0.6 rad, 0.4% at 0.8 rad).
SMALL_TILT = {"single_mode": 0.21, "two_mode": 0.6}
VALIDITY_DESCRIPTION = (
    "small tilts: up to this bound the first spin reversal of the small-angle fidelities is within 0.1% of the "
    "full model's; the amplitude fidelity also needs the spin rate small against the tilt frequencies"
)
POSE_DESCRIPTION = "phi: heading of the bar; (x, y): position of the centre of the bar on the table"
# Defaults (below) are the paper's scenes (Figs. numerical and Numerical2): tilts 1e-3, rates 0,
# spin 0.1 sqrt(g/ell).


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
        pose_description=POSE_DESCRIPTION,
        units=units((x, y, theta, phi, g, ell, L, D)),
        defaults={g: 1.0, ell: 1.0, L: 1.0, D: 1.0, theta: 1e-3, phi_dot: 0.1},
        reversal_events=(phi_dot,),
        steady=(Steady("steady_spin", Omega, {phi_dot: Omega}, "upright steady spin theta = 0 at the rate Omega",
                       {"theta": "tilt", "theta_dot": "tilt", "A_theta": "tilt"}),),
        validity={"reduced": {theta: SMALL_TILT["single_mode"]}, "amplitude": {theta: SMALL_TILT["single_mode"]}},
        validity_description=VALIDITY_DESCRIPTION,
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
        pose_description=POSE_DESCRIPTION,
        units=units((x, y, theta1, theta2, phi, g, ell, L, D, alpha)),
        defaults={g: 1.0, ell: 1.0, L: 2.0, D: 0.5, alpha: sp.pi / 4, theta1: 1e-3, theta2: 1e-3, phi_dot: 0.1},
        reversal_events=(phi_dot,),
        steady=(Steady("steady_spin", Omega, {phi_dot: Omega},
                       "upright steady spin theta1 = theta2 = 0 at the rate Omega",
                       {"theta1": "theta1", "theta1_dot": "theta1", "A1": "theta1", "theta2": "theta2",
                        "theta2_dot": "theta2", "A2": "theta2"}),),
        validity={fid: {theta1: SMALL_TILT["two_mode"], theta2: SMALL_TILT["two_mode"]}
                  for fid in ("reduced", "amplitude")},
        validity_description=VALIDITY_DESCRIPTION,
        description=(
            "Two-mode knife edge (paper section III): tilts theta1, theta2; the contact is the "
            "lowest point of a circle of radius D whose plane makes the chiral angle alpha "
            "with the bar (Const22, Const23)."
        ),
    )


MODELS = {"single_mode": _single_mode(), "two_mode": _two_mode(), "chaplygin_sleigh": chaplygin_sleigh()}
