"""A Chaplygin sleigh steered by a control torque given at run time, written as a user writes a model file.

The sleigh of Bloch, *Nonholonomic Mechanics and Control*, section 1.7
(contact point at the knife edge, centre of mass a distance ``a`` ahead of it
on the axis, radius of gyration ``k`` about the centre of mass), with a
viscous torque ``-c phi_dot`` about the vertical and a control torque ``tau``
that is an input: its values are given to ``knifeedge.simulate`` at run time.
Everything per unit mass.
"""
import sympy as sp

from knifeedge.derive import ModelSpec

a, k = sp.symbols("a k", positive=True)
c = sp.Symbol("c", nonnegative=True)
tau = sp.Symbol("tau", real=True)
x, y, phi = sp.symbols("x y phi", real=True)
x_dot, y_dot, phi_dot = sp.symbols("x_dot y_dot phi_dot", real=True)
v = sp.Symbol("v", real=True)

axis = sp.Matrix([sp.cos(phi), sp.sin(phi)])
across = sp.Matrix([-sp.sin(phi), sp.cos(phi)])
contact = sp.Matrix([x_dot, y_dot])
centre = contact + a * phi_dot * across

MODEL = ModelSpec(
    name="controlled_sleigh",
    coordinates=(x, y, phi),
    velocities=(x_dot, y_dot, phi_dot),
    lagrangian=sp.Rational(1, 2) * (centre.dot(centre) + k**2 * phi_dot**2),
    constraints=(contact.dot(across),),
    constraint_labels=("knife_edge",),
    dependent=(y,),
    params=(a, k, c),
    param_domains={c: "real"},
    inputs=(tau,),
    cyclic={x: 0, y: 0, phi: 0},
    pose=(phi, x, y),
    quasi_velocities=((v, x_dot, contact.dot(axis)),),
    forces=(0, 0, tau - c * phi_dot),
    defaults={a: 0.5, k: 0.8, c: 0.1, v: 0.1, phi_dot: 0.0},
    description="Chaplygin sleigh steered by a control torque tau given at run time, with a viscous torque.",
)
