"""The rolling disk of ``examples/rolling_disk.py`` rebuilt with the rigid-body front end.

Only the body: a uniform thin disk of mass ``m`` and radius ``r`` (moments of
inertia ``m r^2/4`` about a diameter and ``m r^2/2`` about the axle), its edge a
circle of radius ``r`` about the centre of mass, its axle along the body ``y``
axis (as the lean frame of ``rolling_disk.py``), rolling on the table under
gravity ``g``.  No Lagrangian and no constraint is written here: the front end
builds them (``derivation.rigid``).
"""
import sympy as sp

from knifeedge.derive.rigid import Circle, RigidBody

g, r, m = sp.symbols("g r m", positive=True)

BODY = RigidBody(
    name="rolling_disk_rigid",
    mass=m,
    inertia=sp.diag(m * r**2 / 4, m * r**2 / 2, m * r**2 / 4),
    shape=Circle(r, axis=(0, 1, 0)),
    gravity=g,
    params=(g, r, m),
    param_units={"g": "m/s^2", "r": "m", "m": "kg"},
    description="Uniform thin disk (axle along body y) rolling without slipping, built with derivation.rigid.",
    heading_axis=(0, 1, 0),
    source=__name__,
)

MODEL = BODY  # what `knifeedge derive` reads: a RigidBody is a model too
