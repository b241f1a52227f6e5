"""A rattleback carrying a mass on a spring: an ellipsoid and a slider, written as a user would.

The base is the rattleback of ``knifeedge.derive.celt`` without its dissipation: an ellipsoidal bottom (semi-axes
``a, b, c`` along its axes ``x, y, z``), its centre of mass a distance ``h`` below the ellipsoid's centre, the
product of inertia ``I_xy`` turning its principal axes about ``z`` (the chirality).  A point mass ``mu`` slides
along the base's ``z`` axis through its centre of mass, at the height ``s`` above it, held by a spring of stiffness
``k`` whose rest position is ``s = d``.  The front end (``knifeedge.derive.multibody``) builds the Lagrangian and the
rolling constraints; the multipliers are eliminated numerically (four independent accelerations).  Derive it with
``knifeedge derive rattleback_spring.py --out DIR``.
"""
import math

import sympy as sp

from knifeedge.derive.multibody import Slider, assemble
from knifeedge.derive.rigid import Ellipsoid, RigidBody

a, b, c, h, m, g = sp.symbols("a b c h m g", positive=True)
I_xx, I_yy, I_zz = sp.symbols("I_xx I_yy I_zz", positive=True)
I_xy = sp.Symbol("I_xy", real=True)
mu, k, d = sp.symbols("mu k d", positive=True)
s = sp.Symbol("s", real=True)

shell = RigidBody(name="shell", mass=m, inertia=sp.Matrix([[I_xx, I_xy, 0], [I_xy, I_yy, 0], [0, 0, I_zz]]),
                  shape=Ellipsoid(a, b, c, centre=(0, 0, h)), gravity=g, params=(a, b, c, h, m, g))
bob = RigidBody(name="bob", mass=mu, inertia=sp.zeros(3), shape=None, gravity=g, params=(mu,))

MODEL = assemble(
    "rattleback_spring", shell,
    [Slider(parent=shell, child=bob, point=(0, 0, 0), axis=(0, 0, 1), coordinate=s, stiffness=k, rest=d)],
    params=(a, b, c, h, m, g, I_xx, I_yy, I_zz, I_xy, mu, k, d), gravity=g,
    units={a: "m", b: "m", c: "m", h: "m", m: "kg", g: "m/s^2", I_xx: "kg m^2", I_yy: "kg m^2", I_zz: "kg m^2",
           I_xy: "kg m^2", mu: "kg", k: "N/m", d: "m"},
    param_domains={I_xy: "real"},
    # the rattleback of Kane & Levinson (1982) with a tenth of its mass on a stiff spring
    defaults={a: 0.20, b: 0.03, c: 0.02, h: 0.01, m: 1.0, g: 9.81, I_xx: 2e-4, I_yy: 1.6e-3, I_zz: 1.7e-3,
              I_xy: 2e-5, mu: 0.1, k: 400.0, d: 0.005, "a1": 0.01, "a2": 0.01, "psi_dot": -3.0},
    time_unit="s",
    validity={"full": {"a1": math.pi / 2}},
    validity_description="the Euler angles are singular at |a1| = pi/2",
    description="A rattleback carrying a mass on a spring along its axis (knifeedge.derive.multibody).",
)
