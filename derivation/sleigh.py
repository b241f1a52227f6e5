"""The Chaplygin sleigh as data (paper section II.C, the analogy of ``Chap3``).

A rigid body on the plane, supported at its rear by a knife edge that forbids
motion across its axis (Chaplygin 1911; Bloch, *Nonholonomic Mechanics and
Control*, section 1.7).  Coordinates: the contact point ``(x, y)`` and the
heading ``phi`` of the axis; the centre of mass lies on the axis at distance
``a`` ahead of the contact; ``k`` is the radius of gyration about the centre of
mass (moment of inertia ``I = m k^2``).  Everything is per unit mass.

One constraint for three coordinates leaves two independent velocities.  The
contact velocity across the axis vanishes, so ``y`` is taken as dependent and
``x`` and ``phi`` as independent; all three are cyclic.  The speed along the
axis, ``v = x_dot cos(phi) + y_dot sin(phi)``, is a quasi-velocity: it equals
``x_dot`` at the representative pose ``phi = 0`` and, unlike ``x_dot``, is
invariant under rotations, so the closed state is ``(v, phi_dot)``.
"""
from __future__ import annotations

import sympy as sp

from .engine import ModelSpec

a, k = sp.symbols("a k", positive=True)
x, y, phi = sp.symbols("x y phi", real=True)
x_dot, y_dot, phi_dot = sp.symbols("x_dot y_dot phi_dot", real=True)
x_ddot, y_ddot, phi_ddot = sp.symbols("x_ddot y_ddot phi_ddot", real=True)
#: speed of the contact point along the sleigh's axis
v = sp.Symbol("v", real=True)

#: (length exponent, time exponent) of the sleigh's own symbols
DIMENSIONS = {"a": (1, 0), "k": (1, 0), "v": (1, -1), "v_dot": (1, -2)}


def chaplygin_sleigh() -> ModelSpec:
    """The sleigh's Lagrangian (kinetic energy per unit mass) and its knife-edge constraint."""
    axis = sp.Matrix([sp.cos(phi), sp.sin(phi)])
    across = sp.Matrix([-sp.sin(phi), sp.cos(phi)])
    contact_vel = sp.Matrix([x_dot, y_dot])
    centre_vel = contact_vel + a * phi_dot * across
    lag = sp.Rational(1, 2) * (centre_vel.dot(centre_vel) + k**2 * phi_dot**2)
    return ModelSpec(
        name="chaplygin_sleigh",
        coordinates=(x, y, phi),
        velocities=(x_dot, y_dot, phi_dot),
        accelerations=(x_ddot, y_ddot, phi_ddot),
        lagrangian=lag,
        constraints=(contact_vel.dot(across),),
        constraint_labels=("knife_edge",),
        dependent=(y,),
        cyclic={x: 0, y: 0, phi: 0},
        small=(),
        params=(a, k),
        pose=(phi, x, y),
        description=(
            "Chaplygin sleigh: a rigid body on the plane with a knife edge at its rear contact point "
            "(x, y) that forbids sideways motion; heading phi, centre of mass at distance a ahead of "
            "the contact, radius of gyration k about the centre of mass; v is the speed along the axis."
        ),
        quasi_velocities=((v, x_dot, contact_vel.dot(axis)),),
    )
