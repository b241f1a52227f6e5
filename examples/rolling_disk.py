"""A uniform thin disk rolling without slipping on a horizontal table.

This file is written the way a user of knifeedge writes a model of their own:
the disk's Lagrangian and its rolling constraints, nothing else.  Derive it
into a folder of generated modules and load it::

    knifeedge derive examples/rolling_disk.py --out my_models
    python -c "import knifeedge as ke; print(ke.load('rolling_disk', path='my_models'))"

Coordinates (those of sympy issue #27631 and of the SymPy rolling-disc
tutorials): the disk is turned from the table frame by a heading ``q1`` about
the vertical, then a lean ``q2`` about the new horizontal axis (``q2 = 0``
upright), then a rotation ``q3`` about its axle; ``(x, y)`` is the contact
point on the table.  Everything is per unit mass (the mass cancels):
``g`` is gravity, ``r`` the radius; the disk's moments of inertia about its
centre are ``r**2/4`` about a diameter and ``r**2/2`` about the axle.
"""
import sympy as sp

from knifeedge.derive import ModelSpec

g, r = sp.symbols("g r", positive=True)
x, y, q1, q2, q3 = sp.symbols("x y q1 q2 q3", real=True)
x_dot, y_dot, q1_dot, q2_dot, q3_dot = sp.symbols("x_dot y_dot q1_dot q2_dot q3_dot", real=True)
x_ddot, y_ddot, q1_ddot, q2_ddot, q3_ddot = sp.symbols("x_ddot y_ddot q1_ddot q2_ddot q3_ddot", real=True)


def rot_z(a):
    """Columns: the rotated frame's axes in the table frame (rotation by ``a`` about z)."""
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def rot_x(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])


# The lean frame: heading q1 about the vertical, then lean q2 about the heading's x axis.
# Its y axis is the disk's axle, its x and z axes are diameters (z points from the
# contact to the centre).
lean_frame = rot_z(q1) * rot_x(q2)
e_x, e_y, e_z = (lean_frame[:, k] for k in range(3))

# Angular velocity of the disk: heading rate about the vertical, lean rate about
# e_x, spin about the axle e_y.
omega = q1_dot * sp.Matrix([0, 0, 1]) + q2_dot * e_x + q3_dot * e_y

contact = sp.Matrix([x, y, 0])
centre = contact + r * e_z
centre_vel = sum((centre.diff(c) * v for c, v in
                  zip((x, y, q1, q2, q3), (x_dot, y_dot, q1_dot, q2_dot, q3_dot))), sp.zeros(3, 1))

# Kinetic energy per unit mass: translation of the centre, rotation about the centre
# (inertia diag(r^2/4, r^2/2, r^2/4) in the lean frame, where it does not change).
w = lean_frame.T * omega
kinetic = (centre_vel.dot(centre_vel)
           + r**2 / 4 * (w[0]**2 + w[2]**2) + r**2 / 2 * w[1]**2) / 2
potential = g * centre[2]

# Rolling without slipping: the material point of the disk at the contact is at rest.
# Its vertical velocity vanishes with the contact on the table; the two horizontal
# components, along the heading and across it, are the constraints (taken in the
# heading frame, their multipliers are the friction force along and across the
# heading, which do not depend on where the disk is or which way it heads).
slip = centre_vel + omega.cross(contact - centre)
heading = sp.Matrix([sp.cos(q1), sp.sin(q1), 0])
across = sp.Matrix([-sp.sin(q1), sp.cos(q1), 0])

MODEL = ModelSpec(
    name="rolling_disk",
    coordinates=(x, y, q1, q2, q3),
    velocities=(x_dot, y_dot, q1_dot, q2_dot, q3_dot),
    accelerations=(x_ddot, y_ddot, q1_ddot, q2_ddot, q3_ddot),
    lagrangian=kinetic - potential,
    constraints=(slip.dot(heading), slip.dot(across)),
    constraint_labels=("no_slip_along", "no_slip_across"),
    dependent=(x, y),
    cyclic={x: 0, y: 0, q1: 0, q3: 0},
    small=(q2,),
    params=(g, r),
    pose=(q1, q3, x, y),
    pose_description="q1: heading; q3: rotation about the axle; (x, y): contact point on the table",
    units={g: "length/time^2", r: "length", x: "length", y: "length", q1: "rad", q2: "rad", q3: "rad"},
    # upright rolling at spin 2 sqrt(g/r), above the stability threshold sqrt(g/(3r)), slightly leaned
    defaults={g: 1.0, r: 1.0, q2: 0.1, q3_dot: 2.0},
    description=(
        "Uniform thin disk of radius r rolling without slipping on a horizontal table: heading q1, "
        "lean q2 from the vertical, rotation q3 about the axle, contact point (x, y)."
    ),
)
