"""Several rigid bodies joined by pins and sliders, the first rolling on the table: a :class:`ModelSpec` from bodies.

A user writes each body as a :class:`~derivation.rigid.RigidBody` (its mass, its inertia tensor about its centre
of mass in its own axes, its shape; ``shape=None`` for a body that does not touch the table) and joins them::

    from knifeedge.derive.rigid import RigidBody, Circle
    from knifeedge.derive.multibody import assemble, Pin

    disk = RigidBody(name="disk", mass=1, inertia=sp.diag(r**2/4, r**2/2, r**2/4), shape=Circle(r, axis=(0, 1, 0)),
                     gravity=g, params=(g, r))
    bob = RigidBody(name="bob", mass=mu, inertia=sp.zeros(3), shape=None, gravity=g, params=(mu,))
    MODEL = assemble("disk_pendulum", disk, [Pin(disk, bob, point=(0, 0, 0), axis=(0, 1, 0), angle=q4,
                                                 child_point=(0, 0, l))], params=(g, r, l, mu), gravity=g, ...)

:func:`assemble` returns an ordinary :class:`~derivation.engine.ModelSpec` (so ``MODEL = assemble(...)`` works with
``knifeedge derive FILE --out DIR``); the engine then eliminates the multipliers of the rolling constraints as for
every model (numerically past :data:`~derivation.engine.NUMERIC_FROM` independent accelerations).

Coordinates
-----------
The first body (the *base*) has the horizontal position ``(x, y)`` of its centre of mass and the Euler angles of
:func:`derivation.rigid.euler_angle_maps`, ``R = Rz(psi) Rx(a1) Ry(a2)`` (body to table axes: heading ``psi``,
tilts ``a1`` about the body's ``x`` and ``a2`` about its ``y``; singular at ``a1 = +-pi/2``).  Its centre of mass
is at the height ``z(n) = -r(n).n`` above the table (``r(n)`` the shape's lowest point, ``n`` the upward vertical in
body axes: the holonomic contact, substituted).  It rolls without slipping: the contact point's velocity vanishes
along the table (two velocity constraints, ``dependent=(x, y)``); ``x, y, psi`` are symmetries (``cyclic``), and so may be
the angles named in ``symmetric`` (the spin of a disk about its axle).  Each joint adds one coordinate:

* :class:`Pin`: the child turns about ``axis`` (parent axes) by ``angle`` relative to the parent; the hinge is at
  ``point`` (parent axes, from the parent's centre of mass) and at ``child_point`` (child axes, from the child's
  centre of mass).  At ``angle = 0`` the child's axes are the parent's.
* :class:`Slider`: the child keeps the parent's axes and its centre of mass slides along ``axis`` (parent axes,
  normalized): it sits at ``point + coordinate * axis``; a spring of stiffness ``stiffness`` pulls it to
  ``coordinate = rest``.

Lagrangian
----------
``L = sum_i (m_i |v_i|^2 / 2 + omega_i . I_i omega_i / 2 - m_i g z_i) - sum_springs k (s - rest)^2 / 2``, each
``v_i`` the time derivative of the centre's position (``dr/dq q_dot``), each ``omega_i`` in the body's own axes
(``R_child = R_parent Rot(axis, angle)``, ``omega_child = Rot^T omega_parent + angle_dot axis``).  Nothing is
written by hand per model.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .engine import ModelSpec, ModelSpecError
from .rigid import RigidBody, a1, a1_dot, a2, a2_dot, euler_angle_maps, psi, psi_dot, x, x_dot, y, y_dot

#: the base's coordinates and velocities, in the order of the spec
BASE_COORDINATES = (x, y, psi, a1, a2)
BASE_VELOCITIES = (x_dot, y_dot, psi_dot, a1_dot, a2_dot)
BASE_UNITS = {x: "m", y: "m", psi: "rad", a1: "rad", a2: "rad"}


@dataclass(frozen=True)
class Pin:
    """A hinge: ``child`` turns by ``angle`` about ``axis`` (parent axes) through ``point`` of the parent.

    ``point``: the hinge from the parent's centre of mass (parent axes); ``child_point``: the hinge from the
    child's centre of mass (child axes; at ``angle = 0`` the child's axes are the parent's).
    """

    parent: RigidBody
    child: RigidBody
    point: tuple
    axis: tuple
    angle: sp.Symbol
    child_point: tuple = (0, 0, 0)
    unit = "rad"

    @property
    def coordinate(self) -> sp.Symbol:
        return self.angle


@dataclass(frozen=True)
class Slider:
    """A prismatic joint with a spring: ``child`` (the parent's axes) at ``point + coordinate * axis`` of the parent.

    ``axis`` (parent axes) is normalized; ``stiffness`` ``k`` and ``rest`` give the spring's potential
    ``k (coordinate - rest)^2 / 2`` (``stiffness=0``: a free slider).
    """

    parent: RigidBody
    child: RigidBody
    point: tuple
    axis: tuple
    coordinate: sp.Symbol
    stiffness: sp.Expr = 0
    rest: sp.Expr = 0
    unit = "m"


@dataclass(frozen=True)
class Torque:
    """A torque on ``body``: ``torque`` (three expressions, in the body's own axes) of the parameters, the
    coordinates and the model's ``inputs`` (a motor given at run time: ``assemble(..., inputs=(tau,))``).

    It enters as the generalized forces ``Q_j = torque . d omega / d q_dot_j`` (``omega`` the body's angular
    velocity in its axes); its power ``torque . omega`` is the model's ``power_input`` when it holds inputs.
    """

    body: RigidBody
    torque: tuple


def _unit(v, what: str) -> sp.Matrix:
    m = sp.Matrix(v)
    if m.shape != (3, 1):
        raise ValueError(f"`{what}` must be three numbers or expressions (a vector in the parent's axes), got {v!r}")
    norm2 = sp.simplify(m.dot(m))
    if norm2.is_zero:
        raise ValueError(f"`{what}` must be a non-zero vector, got {v!r}")
    return m if sp.simplify(norm2 - 1) == 0 else (m / sp.sqrt(norm2)).applyfunc(sp.simplify)


def rotation(axis: sp.Matrix, angle) -> sp.Matrix:
    """Right-handed rotation by ``angle`` about the unit vector ``axis`` (Rodrigues)."""
    k = sp.Matrix([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return sp.eye(3) + sp.sin(angle) * k + (1 - sp.cos(angle)) * k * k


def _vector(v, what: str) -> sp.Matrix:
    m = sp.Matrix(v)
    if m.shape != (3, 1):
        raise ValueError(f"`{what}` must be three numbers or expressions (a vector), got {v!r}")
    return m


def contact(base: RigidBody, n: sp.Matrix) -> sp.Matrix:
    """The base's lowest point ``r(n)`` (body axes), with ``|e|`` written ``e`` where ``e > 0`` at rest.

    The Euler angles' chart is ``|a1| < pi/2``; a circle's ``|n - (n.k) k|`` is then ``|cos(a1)|`` = ``cos(a1)``.
    """
    r = sp.Matrix(base.shape.lowest_point(n)).applyfunc(lambda e: sp.trigsimp(sp.powsimp(e)))

    def unsigned(e):
        if e.args[0].subs({a1: 0, a2: 0}).is_positive:
            return e.args[0]
        raise ValueError(f"the contact point of the base {base.name!r} holds |{e.args[0]}|, whose sign at rest "
                         f"(a1 = a2 = 0) is not known: give the shape's lowest point without absolute values")
    return r.applyfunc(lambda e: e.replace(lambda u: isinstance(u, sp.Abs), unsigned))


def _frames(base: RigidBody, joints, touch: sp.Matrix) -> list:
    """``(body, R, omega, centre, potential)`` per body: orientation (body -> table), body-axes angular velocity,
    centre of mass in table axes, spring potential of its joint (``touch``: the base's :func:`contact`)."""
    R, n, B = euler_angle_maps()
    omega = B * sp.Matrix([psi_dot, a1_dot, a2_dot])
    height = sp.trigsimp(-touch.dot(n))
    frames = {id(base): (base, R, omega, sp.Matrix([x, y, height]), sp.S.Zero)}
    order = [id(base)]
    for k, j in enumerate(joints):
        what = f"joints[{k}]"
        if id(j.parent) not in frames:
            raise ValueError(f"`{what}`: its parent {j.parent.name!r} is neither the base nor the child of an earlier "
                             f"joint; list the joints from the base outwards")
        if id(j.child) in frames:
            raise ValueError(f"`{what}`: its child {j.child.name!r} is already joined (a body has one parent; "
                             f"closed loops need a holonomic constraint: write the ModelSpec with `holonomic`)")
        _, Rp, wp, cp, _ = frames[id(j.parent)]
        axis = _unit(j.axis, f"{what}.axis")
        point = _vector(j.point, f"{what}.point")
        if isinstance(j, Pin):
            turn = rotation(axis, j.angle)
            Rc = (Rp * turn).applyfunc(sp.trigsimp)
            wc = turn.T * wp + sp.Symbol(f"{j.angle}_dot", real=True) * axis
            cc = cp + Rp * point - Rc * _vector(j.child_point, f"{what}.child_point")
            pot = sp.S.Zero
        else:
            Rc, wc = Rp, wp
            cc = cp + Rp * (point + j.coordinate * axis)
            pot = sp.sympify(j.stiffness) * (j.coordinate - sp.sympify(j.rest)) ** 2 / 2
        frames[id(j.child)] = (j.child, Rc, wc, cc, pot)
        order.append(id(j.child))
    return [frames[i] for i in order]


def reduce_trig(e: sp.Expr, angles) -> sp.Expr:
    """``e`` expanded with ``sin(q)^2`` written ``1 - cos(q)^2`` for each angle ``q`` (what cancels, cancels)."""
    e = sp.expand(e)
    for q in angles:
        if e.has(sp.sin(q)):
            e = sp.expand(e.subs(sp.sin(q) ** 2, 1 - sp.cos(q) ** 2))
    return e


def generalized_forces(base: RigidBody, joints, loads, velocities) -> tuple:
    """``Q_j = sum over loads of torque . d omega / d q_dot_j``, one per coordinate (``velocities`` in order)."""
    omega = {id(body): w for body, _, w, _, _ in _frames(base, joints, sp.zeros(3, 1))}
    Q = sp.zeros(len(velocities), 1)
    for k, load in enumerate(loads):
        if not isinstance(load, Torque) or id(load.body) not in omega:
            raise ValueError(f"`loads[{k}]` must be a Torque on the base or on a body of `joints`, got {load!r}")
        torque = _vector(load.torque, f"loads[{k}].torque")
        Q += omega[id(load.body)].jacobian(sp.Matrix(velocities)).T * torque
    return tuple(sp.expand(e) for e in Q)


def lagrangian(base: RigidBody, joints, gravity) -> tuple:
    """``(L, coordinates, velocities, rolling constraints)`` of the bodies (see the module docstring)."""
    extra = tuple(j.coordinate for j in joints)
    coordinates = BASE_COORDINATES + extra
    velocities = BASE_VELOCITIES + tuple(sp.Symbol(f"{q}_dot", real=True) for q in extra)
    qd = sp.Matrix(velocities)
    L = sp.S.Zero
    touch = contact(base, euler_angle_maps()[1])
    frames = _frames(base, joints, touch)
    angles = [q for q in coordinates if q not in (x, y)]
    for body, R, omega, centre, pot in frames:
        # each velocity component and the rotational energy tidied on their own (no product is expanded)
        v = (centre.jacobian(sp.Matrix(coordinates)) * qd).applyfunc(lambda e: reduce_trig(e, angles))
        spin = reduce_trig((omega.T * sp.Matrix(body.inertia) * omega)[0], angles)
        L += body.mass * v.dot(v) / 2 + spin / 2 - body.mass * gravity * centre[2] - pot
    _, R, omega, centre, _ = frames[0]
    v0 = centre.jacobian(sp.Matrix(coordinates)) * qd
    slip = v0 + R * omega.cross(touch)
    # along and across the heading: the multipliers (contact forces) do not turn with psi, a symmetry
    along = sp.cos(psi) * slip[0] + sp.sin(psi) * slip[1]
    across = -sp.sin(psi) * slip[0] + sp.cos(psi) * slip[1]
    return L, coordinates, velocities, (reduce_trig(along, angles), reduce_trig(across, angles))


def assemble(name: str, base: RigidBody, joints=(), *, params: tuple, gravity, symmetric: tuple = (), units: dict | None = None, loads: tuple = (), **spec_fields) -> ModelSpec:
    """The :class:`ModelSpec` of ``base`` rolling on its shape and of the bodies of ``joints``.

    ``params``: every parameter, in the order of the parameter vector; ``gravity``: ``g``; ``symmetric``: base
    angles (``a2``, ...) that are symmetries besides ``x, y, psi``; ``units``: units of the parameters and joint
    coordinates (the base's are set); ``loads``: :class:`Torque` on the bodies (their generalized forces are the
    spec's ``forces``); ``spec_fields``: any other :class:`ModelSpec` field (``inputs``, ``defaults``,
    ``description``, ``validity``, ``reversal_events``, ...).
    """
    if not isinstance(base, RigidBody) or base.shape is None:
        raise ValueError("`base` must be a RigidBody with a `shape` (the body that touches the table)")
    joints = tuple(joints)
    for k, j in enumerate(joints):
        if not isinstance(j, (Pin, Slider)):
            raise ValueError(f"`joints[{k}]` must be a Pin or a Slider, got {type(j).__name__}")
    bad = [s for s in symmetric if s not in (a1, a2)]
    if bad:
        raise ValueError(f"`symmetric` may name the base's tilts a1, a2 only (x, y, psi are always symmetries), "
                         f"got {bad}")
    L, coordinates, velocities, slip = lagrangian(base, joints, gravity)
    if loads:
        if "forces" in spec_fields:
            raise ValueError("give either `loads` (torques on the bodies) or `forces` (generalized forces), not both")
        spec_fields["forces"] = generalized_forces(base, joints, tuple(loads), velocities)
    fields = dict(
        name=name, coordinates=coordinates, velocities=velocities, lagrangian=L, params=tuple(params),
        constraints=slip, constraint_labels=("rolling_along", "rolling_across"), dependent=(x, y), cyclic={q: 0 for q in (x, y, psi, *symmetric)},
        pose=(psi, x, y),
        pose_description="heading psi of the base and the horizontal position (x, y) of its centre of mass",
        units={**BASE_UNITS, **{j.coordinate: j.unit for j in joints}, **(units or {})},
    )
    clash = set(fields) & set(spec_fields)
    if clash:
        raise ValueError(f"{sorted(clash)} are set by assemble from the bodies and joints; remove them")
    try:
        return ModelSpec(**fields, **spec_fields)
    except TypeError as exc:
        raise ValueError(f"assemble: {exc}; the keywords after `units` are ModelSpec fields") from None


__all__ = ["Pin", "Slider", "Torque", "assemble", "rotation", "lagrangian", "ModelSpecError"]
