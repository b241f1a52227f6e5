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
from .steady import Steady

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
        pose_description="phi: heading of the sleigh's axis; (x, y): position of the contact point on the plane",
        units={a: "length", k: "length", x: "length", y: "length", phi: "rad", v: "length/time"},
        defaults={a: 0.5, k: 0.8, v: 0.1, phi_dot: 0.5},
        reversal_events=(phi_dot,),
        steady=(Steady("straight", sp.Symbol("V", real=True), {v: sp.Symbol("V", real=True)},
                       "straight running at the speed V (phi_dot = 0)"),),
        description=(
            "Chaplygin sleigh: a rigid body on the plane with a knife edge at its rear contact point "
            "(x, y) that forbids sideways motion; heading phi, centre of mass at distance a ahead of "
            "the contact, radius of gyration k about the centre of mass; v is the speed along the axis."
        ),
        quasi_velocities=((v, x_dot, contact_vel.dot(axis)),),
    )


def amplitude_analogy(sleigh_system, amplitude_system) -> dict:
    """The exact map from the sleigh onto the single-mode amplitude equations (paper ``Chap3``).

    With the same time and ``v = -kappa A_phi``, ``phi_dot = mu A_theta``
    (sleigh speed and turning rate against the knife edge's spin rate and
    tilt amplitude), the sleigh's equations become the slow flow exactly
    when ``kappa`` and ``mu`` take the returned values.  The sign is forced:
    the sleigh's speed only grows (``dv/dt = a phi_dot^2``) while ``Chap1``
    makes ``A_phi`` only decrease.

    Parameters
    ----------
    sleigh_system : the derived ``chaplygin_sleigh`` (state ``(v, phi_dot)``).
    amplitude_system : a one-mode :class:`~derivation.averaging.AmplitudeSystem`.

    Returns
    -------
    dict
        ``{"kappa": expr, "mu": expr, "substitution": {v: ..., phi_dot: ...}}``
        with ``kappa``, ``mu`` in the parameters of both models.
    """
    if len(amplitude_system.amplitudes) != 1:
        raise ValueError("the sleigh analogy maps onto a single-mode amplitude system")
    kappa, mu = sp.symbols("kappa mu", positive=True)
    (A,), (S,) = amplitude_system.amplitudes, amplitude_system.spin_amplitudes
    v_sym, w_sym = sleigh_system.state
    sub = {v_sym: -kappa * S, w_sym: mu * A}
    f_v, f_w = (e.subs(sub, simultaneous=True) for e in sleigh_system.explicit)
    mapped = {S: -f_v / kappa, A: f_w / mu}
    target = dict(zip(amplitude_system.state, amplitude_system.rates))
    eqs = []
    for var in (A, S):
        num = sp.numer(sp.together(mapped[var] - target[var]))
        eqs += sp.Poly(sp.expand(num), A, S).coeffs()
    sol = sp.solve(eqs, [kappa, mu], dict=True)
    if len(sol) != 1:
        raise ValueError(f"no unique map of the sleigh onto the amplitude equations: {sol}")
    sol = {k_: sp.factor(v_) for k_, v_ in sol[0].items()}
    return {"kappa": sol[kappa], "mu": sol[mu],
            "substitution": {v_sym: -sol[kappa] * S, w_sym: sol[mu] * A}}
