"""A Chaplygin sleigh turned by a torque ``tau0 sin t``, written as a user writes a model file.

The sleigh of Bloch, *Nonholonomic Mechanics and Control*, section 1.7
(contact point at the knife edge, centre of mass a distance ``a`` ahead of it
on the axis, radius of gyration ``k`` about the centre of mass), driven by a
torque about the vertical that depends on the time explicitly: a generalized
force on the heading ``phi``.  Everything per unit mass.
"""
import sympy as sp

from knifeedge.derive import ModelSpec, t

a, k, tau0 = sp.symbols("a k tau0", positive=True)
x, y, phi = sp.symbols("x y phi", real=True)
x_dot, y_dot, phi_dot = sp.symbols("x_dot y_dot phi_dot", real=True)
v = sp.Symbol("v", real=True)

axis = sp.Matrix([sp.cos(phi), sp.sin(phi)])
across = sp.Matrix([-sp.sin(phi), sp.cos(phi)])
contact = sp.Matrix([x_dot, y_dot])
centre = contact + a * phi_dot * across

MODEL = ModelSpec(
    name="driven_sleigh",
    coordinates=(x, y, phi),
    velocities=(x_dot, y_dot, phi_dot),
    lagrangian=sp.Rational(1, 2) * (centre.dot(centre) + k**2 * phi_dot**2),
    constraints=(contact.dot(across),),
    constraint_labels=("knife_edge",),
    dependent=(y,),
    params=(a, k, tau0),
    cyclic={x: 0, y: 0, phi: 0},
    pose=(phi, x, y),
    quasi_velocities=((v, x_dot, contact.dot(axis)),),
    forces=(0, 0, tau0 * sp.sin(t)),
    defaults={a: 0.5, k: 0.8, tau0: 0.4, v: 0.1, phi_dot: 0.0},
    description="Chaplygin sleigh driven by the torque tau0 sin(t) about the vertical.",
)
