"""A rolling disk carrying a pendulum on its axle: two bodies, written as a user would.

The disk is the one of ``rolling_disk.py`` (heading ``q1``, lean ``q2``, rotation
``q3`` about the axle, contact point ``(x, y)``).  A point bob of mass ``mu``
(per unit mass of the disk) hangs on a massless rod of length ``l`` from the
disk's centre and swings about the axle, free of the disk's rotation: its
angle ``q4`` is measured in the disk's plane from the diameter that points down
to the contact.  Each body's kinetic energy is written from its own frame and
the two are summed.  Derive it with ``knifeedge derive disk_pendulum.py --out DIR``.
"""
import math

import sympy as sp

from knifeedge.derive import ModelSpec

g, r, l, mu = sp.symbols("g r l mu", positive=True)
x, y, q1, q2, q3, q4 = sp.symbols("x y q1 q2 q3 q4", real=True)
x_dot, y_dot, q1_dot, q2_dot, q3_dot, q4_dot = sp.symbols("x_dot y_dot q1_dot q2_dot q3_dot q4_dot", real=True)
coordinates = (x, y, q1, q2, q3, q4)
velocities = (x_dot, y_dot, q1_dot, q2_dot, q3_dot, q4_dot)


def rotation(axis, angle):
    """Matrix of the right-handed rotation by ``angle`` about axis ``axis`` (0, 1, 2 for x, y, z)."""
    c_, s_ = sp.cos(angle), sp.sin(angle)
    i, j = (axis + 1) % 3, (axis + 2) % 3
    m = sp.eye(3)
    m[i, i], m[i, j], m[j, i], m[j, j] = c_, -s_, s_, c_
    return m


def velocity(point):
    """Velocity of a point given in the table's frame as a function of the coordinates."""
    return sum((point.diff(q) * v for q, v in zip(coordinates, velocities)), sp.zeros(3, 1))


vertical = sp.Matrix([0, 0, 1])
# The disk: lean frame (heading q1, then lean q2); its columns e_x (rolling direction), e_y (axle), e_z.
lean_frame = rotation(2, q1) * rotation(0, q2)
e_x, e_y, e_z = (lean_frame[:, k] for k in range(3))
omega = q1_dot * vertical + q2_dot * e_x + q3_dot * e_y
centre = sp.Matrix([x, y, 0]) + r * e_z
w = lean_frame.T * omega                       # the disk's angular velocity in its own frame
disk_kinetic = (velocity(centre).dot(velocity(centre))
                + r**2 / 4 * (w[0]**2 + w[2]**2) + r**2 / 2 * w[1]**2) / 2
disk_potential = g * centre[2]

# The pendulum: its own frame is the lean frame turned by q4 about the axle; the bob hangs along -e_z there.
pendulum_frame = lean_frame * rotation(1, q4)
bob = centre - l * pendulum_frame[:, 2]
pendulum_kinetic = mu * velocity(bob).dot(velocity(bob)) / 2
pendulum_potential = mu * g * bob[2]

# Rolling without slipping: the disk's material point at the contact is at rest (along and across the heading).
slip = velocity(centre) + omega.cross(sp.Matrix([x, y, 0]) - centre)
heading = sp.Matrix([sp.cos(q1), sp.sin(q1), 0])

MODEL = ModelSpec(
    name="disk_pendulum",
    coordinates=coordinates,
    velocities=velocities,
    params=(g, r, l, mu),
    lagrangian=disk_kinetic + pendulum_kinetic - disk_potential - pendulum_potential,
    constraints=(slip.dot(heading), slip.dot(vertical.cross(heading))),
    constraint_labels=("no_slip_along", "no_slip_across"),
    dependent=(x, y),
    cyclic={x: 0, y: 0, q1: 0, q3: 0},
    pose=(q1, q3, x, y),
    units={x: "m", y: "m", q1: "rad", q2: "rad", q3: "rad", q4: "rad", g: "m/s^2", r: "m", l: "m", mu: "1"},
    defaults={g: 9.81, r: 0.1, l: 0.05, mu: 0.3, q2: 0.05, q4: 0.1, q1_dot: 0.0, q2_dot: 0.0, q3_dot: 8.0,
              q4_dot: 0.0},
    time_unit="s",
    validity={"full": {q2: math.pi / 2}},
    validity_description="the disk lies flat on the table at |q2| = pi/2",
    description=("Uniform thin disk of radius r rolling without slipping on a table, with a bob of mass mu "
                 "(per unit disk mass) on a rod of length l swinging about its axle (angle q4 in the disk's plane)."),
)
