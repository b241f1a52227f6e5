"""The disk with a pendulum of ``disk_pendulum.py``, written as two bodies and a pin: no kinetic energy by hand.

The disk (mass 1, radius ``r``, axle along its ``y`` axis) rolls on the table; a bob of mass ``mu`` hangs on a
massless rod of length ``l`` from a pin on the axle at the disk's centre.  The front end
(``knifeedge.derive.multibody``) builds the Lagrangian from both bodies and the rolling constraints from the disk's
shape.  Coordinates: the Euler angles of the disk (heading ``psi``, lean ``a1``, rotation ``a2`` about the axle) and
the pin's angle ``phi`` of the rod relative to the disk (``disk_pendulum.py``'s ``q4``, measured from the lean frame,
is ``a2 + phi``).  Derive it with ``knifeedge derive disk_pendulum_bodies.py --out DIR``.
"""
import math

import sympy as sp

from knifeedge.derive.multibody import Pin, assemble
from knifeedge.derive.rigid import Circle, RigidBody

g, r, l, mu = sp.symbols("g r l mu", positive=True)
phi = sp.Symbol("phi", real=True)

disk = RigidBody(name="disk", mass=1, inertia=sp.diag(r**2 / 4, r**2 / 2, r**2 / 4), shape=Circle(r, axis=(0, 1, 0)),
                 gravity=g, params=(g, r))
bob = RigidBody(name="bob", mass=mu, inertia=sp.zeros(3), shape=None, gravity=g, params=(mu,))

MODEL = assemble(
    "disk_pendulum_bodies", disk,
    [Pin(parent=disk, child=bob, point=(0, 0, 0), axis=(0, 1, 0), angle=phi, child_point=(0, 0, l))],
    params=(g, r, l, mu), gravity=g,
    units={g: "m/s^2", r: "m", l: "m", mu: "1"},
    defaults={g: 9.81, r: 0.1, l: 0.05, mu: 0.3, "a1": 0.05, "phi": 0.1, "a2_dot": 8.0},
    time_unit="s",
    validity={"full": {"a1": math.pi / 2}},
    validity_description="the disk lies flat on the table at |a1| = pi/2",
    description="A rolling disk with a pendulum on its axle, as two bodies and a pin (knifeedge.derive.multibody).",
)
