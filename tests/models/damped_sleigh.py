"""A Chaplygin sleigh whose rotation is damped, written as a user writes a model file.

The sleigh of ``derivation/sleigh.py`` (Bloch, *Nonholonomic Mechanics and
Control*, section 1.7) with a viscous torque about the contact point, from the
Rayleigh dissipation function ``R = c phi_dot^2 / 2``.  Everything per unit mass.
"""
import sympy as sp

from knifeedge.derive import ModelSpec

a, k, c = sp.symbols("a k c", positive=True)
x, y, phi = sp.symbols("x y phi", real=True)
x_dot, y_dot, phi_dot = sp.symbols("x_dot y_dot phi_dot", real=True)
v = sp.Symbol("v", real=True)

axis = sp.Matrix([sp.cos(phi), sp.sin(phi)])
across = sp.Matrix([-sp.sin(phi), sp.cos(phi)])
contact = sp.Matrix([x_dot, y_dot])
centre = contact + a * phi_dot * across

MODEL = ModelSpec(
    name="damped_sleigh",
    coordinates=(x, y, phi),
    velocities=(x_dot, y_dot, phi_dot),
    lagrangian=sp.Rational(1, 2) * (centre.dot(centre) + k**2 * phi_dot**2),
    constraints=(contact.dot(across),),
    constraint_labels=("knife_edge",),
    dependent=(y,),
    params=(a, k, c),
    cyclic={x: 0, y: 0, phi: 0},
    pose=(phi, x, y),
    pose_description="phi: heading; (x, y): contact point",
    quasi_velocities=((v, x_dot, contact.dot(axis)),),
    dissipation=c * phi_dot**2 / 2,
    units={a: "m", k: "m", c: "1/s", x: "m", y: "m", phi: "rad", v: "m/s"},
    time_unit="s",
    defaults={a: 0.5, k: 0.8, c: 0.3, v: 0.1, phi_dot: 1.0},
    reversal_events=(phi_dot,),
    events={"heading_speed": phi_dot - v},
    extra_source='''
#: named parameter sets of this sleigh
PRESETS = {"light_damping": {"a": 0.5, "k": 0.8, "c": 0.05}}


def initial_state(speed, turn_rate):
    """Closed state (v, phi_dot) from the speed along the axis and the turning rate."""
    return np.array([float(speed), float(turn_rate)])
''',
    exports=("PRESETS", "initial_state"),
    description="Chaplygin sleigh with a viscous torque c*phi_dot about the contact point.",
)
