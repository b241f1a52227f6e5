"""A uniform thin disk rolling without slipping on a horizontal table.

This file is written the way a user of knifeedge writes a model of their own:
the disk's Lagrangian and its rolling constraints, nothing else; no equation
of motion is written here.  Derive it into a folder of compiled modules and
load them::

    knifeedge derive rolling_disk.py --out my_models

    import knifeedge as ke
    m = ke.load("rolling_disk", fidelity="full", path="my_models")

Coordinates (those of sympy issue #27631 and of the SymPy rolling-disc
tutorials): the disk is turned from the table's frame by a heading ``q1``
about the vertical, then leaned by ``q2`` about the new horizontal axis
(``q2 = 0`` upright), then rotated by ``q3`` about its axle; ``(x, y)`` is
the contact point on the table.  Everything is per unit mass (the mass
cancels): ``g`` is gravity, ``r`` the radius; the moments of inertia about
the centre are ``r**2/4`` about a diameter and ``r**2/2`` about the axle.

``MODEL`` holds two models: ``rolling_disk`` and ``rolling_disk_damped``,
the same disk with a viscous torque ``-c r**2 omega`` (per unit mass)
opposing its rotation, written as a Rayleigh dissipation function.
"""
import math

import sympy as sp

from knifeedge.derive import ModelSpec
from knifeedge.derive.drawing import Drawing, u
from knifeedge.derive.steady import Steady

g, r, c = sp.symbols("g r c", positive=True)
x, y, q1, q2, q3 = sp.symbols("x y q1 q2 q3", real=True)
x_dot, y_dot, q1_dot, q2_dot, q3_dot = sp.symbols("x_dot y_dot q1_dot q2_dot q3_dot", real=True)
coordinates = (x, y, q1, q2, q3)
velocities = (x_dot, y_dot, q1_dot, q2_dot, q3_dot)


def rotation(axis, angle):
    """Matrix of the right-handed rotation by ``angle`` about axis ``axis`` (0, 1, 2 for x, y, z)."""
    c_, s_ = sp.cos(angle), sp.sin(angle)
    i, j = (axis + 1) % 3, (axis + 2) % 3
    m = sp.eye(3)
    m[i, i], m[i, j], m[j, i], m[j, j] = c_, -s_, s_, c_
    return m


# The lean frame: heading q1 about the vertical, then lean q2 about the new x axis.
# Its columns, in the table's frame: e_x (a horizontal diameter, the direction of
# rolling), e_y (the axle), e_z (the diameter from the contact to the centre).
lean_frame = rotation(2, q1) * rotation(0, q2)
e_x, e_y, e_z = (lean_frame[:, k] for k in range(3))
vertical = sp.Matrix([0, 0, 1])

# Angular velocity of the disk: heading rate about the vertical, lean rate about
# e_x, rotation about the axle e_y.
omega = q1_dot * vertical + q2_dot * e_x + q3_dot * e_y

contact = sp.Matrix([x, y, 0])
centre = contact + r * e_z
centre_vel = sum((centre.diff(q) * v for q, v in zip(coordinates, velocities)), sp.zeros(3, 1))

# Kinetic energy per unit mass: translation of the centre plus rotation about it;
# the inertia is diag(r**2/4, r**2/2, r**2/4) in the lean frame, where it stays fixed.
w = lean_frame.T * omega
kinetic = (centre_vel.dot(centre_vel) + r**2 / 4 * (w[0]**2 + w[2]**2) + r**2 / 2 * w[1]**2) / 2
potential = g * centre[2]

# Rolling without slipping: the material point of the disk at the contact is at rest.
# Its vertical velocity vanishes already (the contact stays on the table); the two
# horizontal components, along the heading and across it, are the constraints.  Taken
# in the heading's frame, their multipliers (the friction force per unit mass along
# and across the heading) do not depend on where the disk is or which way it heads.
slip = centre_vel + omega.cross(contact - centre)
heading = sp.Matrix([sp.cos(q1), sp.sin(q1), 0])
across = vertical.cross(heading)

# How the disk draws itself (knifeedge animate): its rim, two perpendicular diameters
# that turn with it by q3 about the axle, the axle, the centre and the contact point.
spoke = sp.cos(q3) * e_z + sp.sin(q3) * e_x   # e_z turned by q3 about the axle e_y
across_spoke = sp.cos(q3) * e_x - sp.sin(q3) * e_z
drawing = Drawing(
    points={"C": tuple(contact), "centre": tuple(centre),
            "spoke_a": tuple(centre + r * spoke), "spoke_b": tuple(centre - r * spoke),
            "spoke_c": tuple(centre + r * across_spoke), "spoke_d": tuple(centre - r * across_spoke),
            "axle_a": tuple(centre + r / 3 * e_y), "axle_b": tuple(centre - r / 3 * e_y)},
    segments=(("spoke_a", "spoke_b"), ("spoke_c", "spoke_d"), ("axle_a", "axle_b")),
    contact="C", masses=("centre",), magnify=(q2.name,),
    outlines={"rim": tuple(centre + r * (sp.cos(u) * e_x + sp.sin(u) * e_z))},
    gauge=q1_dot.name,
    description="disk: its rim, two diameters turning with it, the axle, the centre and the contact point",
)

common = dict(
    coordinates=coordinates,
    velocities=velocities,
    lagrangian=kinetic - potential,
    constraints=(slip.dot(heading), slip.dot(across)),
    constraint_labels=("no_slip_along", "no_slip_across"),
    dependent=(x, y),
    cyclic={x: 0, y: 0, q1: 0, q3: 0},
    pose=(q1, q3, x, y),
    pose_description="heading q1, rotation q3 about the axle, contact point (x, y) on the table",
    time_unit="s",
    state_order=(q2, q1_dot, q2_dot, q3_dot),
    validity={"full": {q2: math.pi / 2}},
    validity_description="the disk lies flat on the table at |q2| = pi/2; beyond, it would pass through it",
    drawing=drawing,
    # upright rolling along a straight line (decaying under the damping torque of rolling_disk_damped)
    steady=(Steady("upright_rolling", sp.Symbol("Omega", real=True), {q3_dot: sp.Symbol("Omega", real=True)},
                   "upright rolling (q2 = 0) in a straight line at the axle rate Omega",
                   {"q2": "lean", "q2_dot": "lean"}),),
)

units = {x: "m", y: "m", q1: "rad", q2: "rad", q3: "rad", g: "m/s^2", r: "m"}

rolling_disk = ModelSpec(
    name="rolling_disk",
    params=(g, r),
    units=units,
    # a 10 cm disk on Earth, rolling at 0.8 m/s, leaned by 0.05 rad
    defaults={g: 9.81, r: 0.1, q2: 0.05, q1_dot: 0.0, q2_dot: 0.0, q3_dot: 8.0},
    description=("Uniform thin disk of radius r rolling without slipping on a horizontal table: heading q1, "
                 "lean q2 from the vertical, rotation q3 about the axle, contact point (x, y)."),
    **common,
)

# The same disk with a viscous torque opposing its rotation: the Rayleigh function
# R = c r**2 |omega|**2 / 2 gives the generalized forces -dR/dq_dot.
rolling_disk_damped = ModelSpec(
    name="rolling_disk_damped",
    params=(g, r, c),
    units={**units, c: "1/s"},
    defaults={g: 9.81, r: 0.1, c: 0.1, q2: 0.05, q1_dot: 0.0, q2_dot: 0.0, q3_dot: 8.0},
    dissipation=c * r**2 * omega.dot(omega) / 2,
    description=("Uniform thin disk of radius r rolling without slipping on a horizontal table, its rotation "
                 "resisted by a viscous torque -c r^2 omega per unit mass (Rayleigh function c r^2 |omega|^2/2)."),
    **common,
)

MODEL = [rolling_disk, rolling_disk_damped]
