"""Rigid bodies rolling without slipping on a horizontal table: a public front end.

A user describes a body by its mass ``m``, its inertia tensor about the centre
of mass in a body frame (all six components), a convex contact shape fixed in
the body whose lowest point has a closed form (:class:`Ellipsoid`,
:class:`Sphere`, :class:`Circle` -- the edge of a disk), gravity ``g``, an
optional dissipation torque ``-sigma * omega`` and an optional applied torque
(a motor: ``torque=(0, tau, 0)`` with ``inputs=(tau,)`` given at run time)::

    from derivation.rigid import RigidBody, Ellipsoid, derive
    body = RigidBody(name="celt", mass=m, inertia=I, shape=Ellipsoid(a, b, c, centre=(0, 0, h)),
                     gravity=g, params=(a, b, c, h, m, g, ...), sigma=sigma)
    system = derive(body)          # a reduced system the emitter writes like every other model

Coordinates (see ``docs/rigid-bodies.md``)
-----------------------------------------
The closed state is the upward vertical ``n = (n_x, n_y, n_z)`` in body axes
and the body angular velocity ``omega = (omega_x, omega_y, omega_z)`` in body
axes (quasi-velocities), followed by the vertical spin ``omega_n = omega . n``
carried as an observer so that its zero crossings (the reversals) are located
on the integrator's dense output.  ``n`` is a unit vector (``|n|`` is an exact
invariant of ``dn/dt = n x omega``); no orientation is singular in these
coordinates.  The only singular configurations are the shape's own: the
lowest point of a :class:`Circle` is undefined when its plane is horizontal
(``n`` parallel to its axis).  The pose is the heading ``psi`` (azimuth of the
horizontal projection of a body axis, by default ``x``; singular only when
that axis is vertical) and the horizontal position ``(x, y)`` of the centre
of mass.  Euler angles, by contrast, are singular at the upright state of a
body whose symmetry axis is vertical, and carried about 100 times the global
error on the rattleback at equal tolerance (measured in
``benchmarks/rigid_coordinates.py``).

Derivation
----------
The Lagrangian is ``L = T(V, omega) - m g z`` with ``T = m V.V/2 +
omega.I omega/2`` (``V`` the velocity of the centre of mass in body axes) and
``z`` the height of the centre of mass.  The contact point ``r(n)`` (from the
centre of mass, body axes) is the lowest point of the shape; the holonomic
constraint is ``z = -r(n).n`` and rolling without slipping is
``V + omega x r = 0`` (two horizontal components; the vertical one is the
time derivative of the holonomic constraint because ``dr/dt`` is tangent to
the surface).  The equations of Lagrange and d'Alembert in the body
quasi-velocities (Hamel's equations on SE(3); they are the Newton--Euler
equations with the contact force ``F`` as multiplier) are::

    d/dt(dT/dV)     + omega x dT/dV                 = F - m g n
    d/dt(dT/domega) + omega x dT/domega + V x dT/dV = r x F - sigma omega + torque
    dn/dt = n x omega

with the momenta taken from the Lagrangian by differentiation.  Eliminating
``F`` with the differentiated rolling constraint gives ``M(n) domega/dt =
f(n, omega)``, solved in closed form (Cramer's rule on the 3x3 system, whose
shared subexpressions the emitter's CSE keeps).  Nothing is simplified
symbolically, so the derivation takes seconds.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import sympy as sp

from knifeedge import bodies

from .engine import ModelSpec, ReducedSystem
from .names import Own, identifier

#: state symbols: upward vertical in body axes, body angular velocity, vertical spin
n_x, n_y, n_z = sp.symbols("n_x n_y n_z", real=True)
omega_x, omega_y, omega_z = sp.symbols("omega_x omega_y omega_z", real=True)
omega_n = sp.Symbol("omega_n", real=True)
#: pose symbols: heading and position of the centre of mass
psi, x, y = sp.symbols("psi x y", real=True)
N_VEC = sp.Matrix([n_x, n_y, n_z])
OMEGA = sp.Matrix([omega_x, omega_y, omega_z])
_V = sp.Matrix(sp.symbols("V_x V_y V_z", real=True))
_OMEGA_DOT = sp.Matrix(sp.symbols("omega_x_dot omega_y_dot omega_z_dot", real=True))

STATE = (n_x, n_y, n_z, omega_x, omega_y, omega_z, omega_n)
POSE = (psi, x, y)
#: units of the state and pose
STATE_UNITS = {"n_x": "1", "n_y": "1", "n_z": "1", "omega_x": "rad/s", "omega_y": "rad/s", "omega_z": "rad/s",
               "omega_n": "rad/s", "psi": "rad", "x": "m", "y": "m"}
MULTIPLIER_LABELS = ("contact_force_x", "contact_force_y", "contact_force_z")


def _vec(v) -> sp.Matrix:
    m = sp.Matrix(v)
    if m.shape != (3, 1):
        raise ValueError(f"expected a 3-vector, got shape {m.shape}")
    return m


@dataclass(frozen=True)
class Ellipsoid:
    """Ellipsoid with semi-axes ``a, b, c`` along the body axes ``x, y, z``, centred at ``centre``.

    Lowest point for the upward vertical ``n``: ``centre - E n / sqrt(n.E n)``
    with ``E = diag(a^2, b^2, c^2)`` (the point whose outward normal is ``-n``).
    Defined for every orientation.
    """

    a: sp.Expr
    b: sp.Expr
    c: sp.Expr
    centre: tuple = (0, 0, 0)

    def lowest_point(self, n: sp.Matrix) -> sp.Matrix:
        e = sp.Matrix([self.a**2 * n[0], self.b**2 * n[1], self.c**2 * n[2]])
        return _vec(self.centre) - e / sp.sqrt(n.dot(e))

    singular = "nowhere"


@dataclass(frozen=True)
class Sphere:
    """Sphere of radius ``radius`` centred at ``centre``; lowest point ``centre - radius n``."""

    radius: sp.Expr
    centre: tuple = (0, 0, 0)

    def lowest_point(self, n: sp.Matrix) -> sp.Matrix:
        return _vec(self.centre) - self.radius * n

    singular = "nowhere"


@dataclass(frozen=True)
class Circle:
    """Circle (edge of a disk) of radius ``radius`` centred at ``centre`` in the plane normal to ``axis``.

    ``axis`` is the disk's normal (body axes), normalized when it is built (a zero axis is refused).  Lowest point:
    ``centre - radius (n - (n.k) k) / |n - (n.k) k|``; undefined when the
    disk lies flat (``n`` parallel to ``k``).
    """

    radius: sp.Expr
    axis: tuple = (0, 0, 1)
    centre: tuple = (0, 0, 0)

    def __post_init__(self):
        k = _vec(self.axis)
        norm2 = sp.simplify(k.dot(k))
        if norm2.is_zero or (norm2.is_number and not float(norm2) > 0):
            raise ValueError(f"`axis` of a Circle must be a non-zero vector (the normal of the disk), got {self.axis}")
        if sp.simplify(norm2 - 1) != 0:  # a direction: normalized, so that the lowest point is on the circle
            object.__setattr__(self, "axis", tuple(sp.simplify(c / sp.sqrt(norm2)) for c in k))

    def lowest_point(self, n: sp.Matrix) -> sp.Matrix:
        k = _vec(self.axis)
        u = n - n.dot(k) * k
        return _vec(self.centre) - self.radius * u / sp.sqrt(u.dot(u))

    singular = "where the disk lies flat (n parallel to the axis)"


@dataclass(frozen=True)
class RigidBody:
    """A rigid body rolling without slipping on a horizontal table, as data.

    Attributes
    ----------
    name : model name.
    mass : the mass ``m`` (a parameter symbol or an expression of parameters).
    inertia : 3x3 symmetric inertia tensor about the centre of mass in body
        axes (matrix entries; ``inertia[0, 1]`` is the ``xy`` entry).
    shape : :class:`Ellipsoid`, :class:`Sphere`, :class:`Circle` or any object
        with ``lowest_point(n) -> 3x1 Matrix`` (position of the contact point
        relative to the centre of mass, body axes, for the upward vertical ``n``).
    gravity : ``g``.
    params : parameter symbols in the order of the parameter vector.
    sigma : optional dissipation coefficient: torque ``-sigma * omega`` about the centre of mass.
    torque : optional applied torque about the centre of mass, three expressions in body axes of the
        parameters, the state (``n``, ``omega``) and ``inputs``; its power ``torque . omega`` is the
        module's ``power_input``.
    inputs : symbols given at run time (``simulate(..., inputs={"tau": ...})``, as a ``ModelSpec``'s
        ``inputs``); they may appear in ``torque`` only.  A body with inputs has fidelity ``full`` only.
    param_units : unit string of each parameter (``{"m": "kg", ...}``).
    param_domains : ``{name: "real" | "nonnegative"}`` for parameters that need
        not be positive (products of inertia, ``sigma``).
    heading_axis : body axis whose horizontal projection defines the heading ``psi``.
    small : state names scaled as small by truncations (reserved).
    description : one paragraph for the generated module.
    presets : ``{preset name: {parameter name: value}}`` with their sources in ``preset_sources``.
    defaults : default parameter values (the CLI's) -- by default the first preset -- and
        ``default_state``: ``{"n0": ..., "omega0": ...}`` for ``initial_state``.
    source : name of the module that defines the body (its text enters the input hash).
    hangs : the centre of mass may lie below the contact (a body balanced on an edge over a narrow support,
        as the paper's knife edge); otherwise it must be above the table.

    :meth:`check` (run by :func:`derive`) refuses a body that cannot exist: a mass or gravity that is not
    positive, a negative ``sigma``, an inertia with a negative principal moment or whose principal moments
    break the triangle inequality ``I1 + I2 >= I3`` (a zero moment only for mass on a line), a centre of
    mass at or below the table at the rest orientation (``default_state["n0"]``, else upright), a parameter
    without a unit, an ``n0`` that is not three real numbers.  Numbers are checked at every preset and at
    ``defaults``, and symbolically where SymPy can decide the sign.
    """

    name: str
    mass: sp.Expr
    inertia: sp.Matrix
    shape: object
    gravity: sp.Expr
    params: tuple
    sigma: sp.Expr | None = None
    param_units: dict = field(default_factory=dict)
    param_domains: dict = field(default_factory=dict)
    heading_axis: tuple = (1, 0, 0)
    small: tuple = ()
    description: str = ""
    presets: dict = field(default_factory=dict)
    preset_sources: dict = field(default_factory=dict)
    source: str = ""
    defaults: dict = field(default_factory=dict)
    default_state: dict = field(default_factory=dict)
    hangs: bool = False
    #: families of steady motions (:class:`~knifeedge.derive.steady.Steady`)
    steady: tuple = ()
    torque: tuple | None = None
    inputs: tuple = ()

    def check(self) -> None:
        """Collect every problem of the description and raise one ``ValueError``."""
        problems = []
        inertia = sp.Matrix(self.inertia)
        if inertia.shape != (3, 3):
            problems.append(f"`inertia` must be 3x3, got {inertia.shape}")
        elif any(sp.simplify(inertia[i, j] - inertia[j, i]) != 0 for i in range(3) for j in range(i)):
            problems.append("`inertia` must be symmetric")
        declared = set(self.params)
        used = set()
        for part in (self.mass, self.gravity, self.sigma or sp.S.Zero, *inertia,
                     *self.shape.lowest_point(N_VEC)):
            used |= sp.sympify(part).free_symbols
        undeclared = used - declared - set(N_VEC)
        if undeclared:
            problems.append(f"symbols not declared in `params`: {sorted(map(str, undeclared))}")
        problems += _torque_problems(self)
        names = [str(p) for p in self.params]
        if len(set(names)) != len(names):
            problems.append("`params` has repeated names")
        clash = set(names) & (set(STATE_UNITS) | {"t"})
        if clash:
            problems.append(f"parameter names clash with state names: {sorted(clash)}")
        for preset, values in self.presets.items():
            missing = [p for p in names if p not in values]
            extra = [p for p in values if p not in names]
            if missing or extra:
                problems.append(f"preset {preset!r}: missing {missing}, unknown {extra}")
        no_unit = [p for p in names if p not in {str(k) for k in self.param_units}]
        if no_unit:
            problems.append(f"parameters without a unit in `param_units`: {no_unit} (e.g. {{{no_unit[0]!r}: 'm'}}; "
                            f"'1' for a dimensionless one)")
        if not problems:
            problems += _physical_problems(self, inertia)
        if problems:
            raise ValueError(f"{self.name}: " + "; ".join(problems))


def _torque_problems(body: RigidBody) -> list:
    """What is wrong with ``body.torque`` and ``body.inputs``."""
    from .input_slots import slot_names

    problems = []
    inputs = tuple(body.inputs)
    if inputs and body.torque is None:
        problems.append(f"`inputs` {[str(u) for u in inputs]} must appear in `torque` (the applied torque)")
    if body.torque is not None:
        try:
            torque = _vec(body.torque)
        except ValueError:
            return [f"`torque` must be three expressions (body axes), got {body.torque!r}"]
        allowed = set(body.params) | set(inputs) | set(N_VEC) | set(OMEGA)
        bad = set().union(*(sp.sympify(c).free_symbols for c in torque)) - allowed
        if bad:
            problems.append(f"`torque` holds symbols that are not parameters, inputs, n_x..n_z or omega_x..omega_z: "
                            f"{sorted(map(str, bad))} (declare run-time quantities in `inputs`)")
    taken = {str(q) for q in body.params} | set(STATE_UNITS) | {"t"} | set(slot_names(inputs))
    clash = sorted({str(u) for u in inputs} & taken)
    if clash:
        problems.append(f"`inputs` names clash with parameter, state or slot names: {clash}; rename them")
    if inputs and body.small:
        problems.append("a body with `inputs` has fidelity 'full' only: the small-tilt fidelities (`small`) expand "
                        "about a free spin, which an applied torque does not keep; leave `small` empty")
    return problems


def _rest_vertical(body: RigidBody, problems: list):
    """``default_state["n0"]`` as a unit 3-vector of floats (upright if absent); ``None`` after a problem."""
    n0 = body.default_state.get("n0", (0.0, 0.0, 1.0))
    try:
        ok = not isinstance(n0, (str, bytes)) and len(n0) == 3 and all(
            isinstance(sp.sympify(c), sp.Expr) and sp.sympify(c).is_extended_real and sp.sympify(c).is_finite
            for c in n0)
    except (TypeError, sp.SympifyError):
        ok = False
    norm = math.sqrt(sum(float(c) ** 2 for c in n0)) if ok else 0.0
    if not norm > 0:
        problems.append(f"`default_state['n0']` must be three finite real numbers, not all zero (the upward "
                        f"vertical in body axes), got {n0!r}")
        return None
    return sp.Matrix([float(c) / norm for c in n0])


def _physical_problems(body: RigidBody, inertia: sp.Matrix) -> list:
    """What makes ``body`` impossible (:func:`knifeedge.bodies.problems`), at each numeric parameter set, and
    symbolically where SymPy can tell the sign."""
    problems: list = []
    n0 = _rest_vertical(body, problems)
    height = None if n0 is None or body.hangs else sp.sympify(-body.shape.lowest_point(n0).dot(n0))
    scalars = [sp.sympify(body.mass), sp.sympify(body.gravity), sp.sympify(body.sigma or 0)]
    sets = [(f"preset {k!r}", v) for k, v in sorted(body.presets.items())]
    sets += [("`defaults`", body.defaults)] if body.defaults else []
    free = set().union(inertia.free_symbols, *(e.free_symbols for e in scalars))
    if not sets and not free | (height.free_symbols if height is not None else set()):
        sets = [("its numbers", {})]
    for label, values in sets:
        try:
            at = {q: float(values[str(q)]) for q in body.params if str(q) in values}
        except (TypeError, ValueError):
            problems.append(f"the values of {label} must be real numbers, got {values!r}")
            continue
        numbers = [e.subs(at) for e in scalars] + [inertia.subs(at)] + ([height.subs(at)] if height is not None else [])
        if any(e.free_symbols for e in numbers):
            continue
        found = bodies.problems(*(float(e) for e in numbers[:3]), numbers[3].tolist(),
                                float(numbers[4]) if height is not None else None)
        hint = " (the shape must enclose it, or set `hangs=True` for a body balanced on an edge over a support)"
        problems += [f"{p} at {label}" + (hint if "centre of mass" in p else "") for p in found]
    if scalars[0].is_nonpositive:
        problems.append(f"`mass` must be positive, got {scalars[0]}")
    if height is not None and height.is_nonpositive:
        problems.append(f"the centre of mass must be above the table at rest (height {height})")
    return problems


def body_values(body: RigidBody) -> tuple:
    """``(mass, gravity, sigma, inertia, height)`` as expressions of the parameters (``height``: of the centre of
    mass at the rest orientation; ``None`` for a body that hangs): what :func:`knifeedge.bodies.problems` checks,
    written into every rigid module as ``body_values(p)``."""
    n0 = _rest_vertical(body, [])
    height = None if body.hangs or n0 is None else -body.shape.lowest_point(n0).dot(n0)
    return body.mass, body.gravity, body.sigma or sp.S.Zero, sp.Matrix(body.inertia), height


@dataclass
class RollingSystem(ReducedSystem):
    """A derived :class:`RigidBody`: a :class:`~derivation.engine.ReducedSystem` plus rigid-body data.

    Extra attributes: ``body``; ``contact`` (``r(n)``); ``height`` (``z(n)``);
    ``power`` (power dissipated,
    ``sigma |omega|^2``); ``omega_dot`` (the closed-form solution).  As in
    every reduced system, ``mass_matrix @ explicit = forcing`` with
    ``accelerations`` the symbols of ``domega/dt``; :meth:`state_rhs` adds
    ``dn/dt = n x omega`` and the rate of the vertical spin ``omega_n``
    (``omega . dn/dt = 0``, so it is ``domega/dt . n``).
    """

    body: RigidBody | None = None
    contact: sp.Matrix | None = None
    height: sp.Expr | None = None
    power: sp.Expr = sp.S.Zero
    omega_dot: sp.Matrix | None = None

    def state_rhs(self) -> list:
        """Rates of the closed state: ``dn/dt = n x omega``, ``domega/dt``, ``d(omega.n)/dt = domega/dt . n``."""
        return [*N_VEC.cross(OMEGA), *self.explicit, self.explicit.dot(N_VEC)]


def _solve3(A: sp.Matrix, b: sp.Matrix) -> sp.Matrix:
    """Cramer's rule for a 3x3 system, built on placeholders and then filled in (no expansion)."""
    a = sp.Matrix(3, 3, sp.symbols("_a0:9"))
    f = sp.Matrix(sp.symbols("_f0:3"))
    det = a.det(method="berkowitz")
    sol = a.adjugate(method="berkowitz") * f
    fill = {**dict(zip(a, A)), **dict(zip(f, b))}
    d = sp.Symbol("_det")
    return sp.Matrix([(e / d).xreplace(fill).xreplace({d: det.xreplace(fill)}) for e in sol])


def equations(body: RigidBody) -> dict:
    """The pieces of the derivation (for tests and documentation).

    Returns ``contact`` r(n), ``height`` z(n), ``lagrangian`` in ``(V, omega,
    z)`` with the symbols of this module, ``constraints`` (``V + omega x r``),
    ``mass_matrix`` ``M(n)`` and ``forcing`` ``f(n, omega)`` with
    ``M domega/dt = f``, and the contact force as a function of
    ``domega/dt`` (``force``).
    """
    m, g = body.mass, body.gravity
    I = sp.Matrix(body.inertia)
    n, w, V, wd = N_VEC, OMEGA, _V, _OMEGA_DOT
    z = sp.Symbol("z", real=True)
    r = body.shape.lowest_point(n)
    height = -r.dot(n)
    T = m * V.dot(V) / 2 + (w.T * I * w)[0] / 2
    lagrangian = T - m * g * z
    P = sp.Matrix([sp.diff(T, s) for s in V])
    K = sp.Matrix([sp.diff(T, s) for s in w])
    constraints = V + w.cross(r)
    n_dot = n.cross(w)
    v_sub = dict(zip(V, -w.cross(r)))
    r_dot = r.jacobian(n) * n_dot
    V_dot = -wd.cross(r) - w.cross(r_dot)

    def rate(X):
        """d/dt of a body-frame function of (V, omega, n) along the constrained motion."""
        return X.jacobian(V) * V_dot + X.jacobian(w) * wd + X.jacobian(n) * n_dot

    force = (rate(P) + w.cross(P) + m * g * n).xreplace(v_sub)
    torque = -(body.sigma or 0) * w + (_vec(body.torque) if body.torque is not None else sp.zeros(3, 1))
    residual = (rate(K) + w.cross(K) + V.cross(P)).xreplace(v_sub) - r.cross(force) - torque
    M = residual.jacobian(wd)
    f = -residual.xreplace(dict.fromkeys(wd, 0))
    return {"contact": r, "height": height, "lagrangian": lagrangian, "constraints": constraints,
            "mass_matrix": M, "forcing": f, "force": force, "omega_dot_symbols": wd, "velocity": -w.cross(r),
            "kinetic": T.xreplace(v_sub)}


def heading_rates(body: RigidBody, velocity: sp.Matrix) -> tuple:
    """``(psi_dot, x_dot, y_dot)``: heading rate and horizontal velocity of the centre of mass.

    ``psi`` is the azimuth of the horizontal projection of ``body.heading_axis``
    ``e``: ``psi_dot = (omega.n - (omega.e)(e.n)) / (|n|^2 - (e.n)^2)``, singular
    only when ``e`` is vertical.
    """
    n, w = N_VEC, OMEGA
    e = _vec(body.heading_axis)
    en = e.dot(n)
    horiz2 = n.dot(n) - en**2
    psi_dot = (w.dot(n) - w.dot(e) * en) / horiz2
    X = (e - en * n) / sp.sqrt(horiz2)
    Y = n.cross(X)
    vx, vy = velocity.dot(X), velocity.dot(Y)
    return psi_dot, sp.cos(psi) * vx - sp.sin(psi) * vy, sp.sin(psi) * vx + sp.cos(psi) * vy


@dataclass(frozen=True)
class RigidSpec:
    """What the emitter reads of a rigid body (the engine's :class:`ModelSpec` fields it uses)."""

    name: str
    lagrangian: sp.Expr
    constraints: tuple
    constraint_labels: tuple
    small: tuple
    params: tuple
    pose: tuple
    description: str
    param_units: dict
    quasi_velocities: tuple = ()
    drawing: object = None
    #: run-time inputs (:attr:`RigidBody.inputs`) and their rates' symbols (never read: a torque is not
    #: differentiated), as :class:`~derivation.engine.ModelSpec` has them
    inputs: tuple = ()
    input_rates: tuple = ()


def spec_of(body: RigidBody, parts: dict) -> RigidSpec:
    """The emitter's view of a rigid body (name, parameters, pose, labels, hash input)."""
    return RigidSpec(
        name=body.name,
        lagrangian=parts["lagrangian"] + sp.Symbol("_height") * parts["height"],
        constraints=tuple(parts["constraints"]),
        constraint_labels=MULTIPLIER_LABELS,
        small=body.small,
        params=tuple(body.params),
        pose=POSE,
        description=body.description,
        param_units={**STATE_UNITS, **{str(k): v for k, v in body.param_units.items()}},
        inputs=tuple(body.inputs),
        input_rates=tuple(Own(f"_rate_{identifier(str(u))}", real=True) for u in body.inputs),
    )


def derive(body: RigidBody) -> RollingSystem:
    """Derive the closed equations of motion of ``body`` (see the module docstring)."""
    body.check()
    parts = equations(body)
    M, f = parts["mass_matrix"], parts["forcing"]
    omega_dot = _solve3(M, f)
    wd = parts["omega_dot_symbols"]
    force = parts["force"].xreplace(dict(zip(wd, omega_dot)))
    energy = parts["kinetic"] + body.mass * body.gravity * parts["height"]
    psi_dot, x_dot, y_dot = heading_rates(body, parts["velocity"])
    spec = spec_of(body, parts)
    return RollingSystem(
        spec=spec,
        state=STATE,
        accelerations=tuple(wd),
        mass_matrix=M,
        forcing=f,
        explicit=omega_dot,
        multipliers=force,
        multipliers_implicit=parts["force"],
        energy=energy,
        pose_rates={psi: psi_dot, x: x_dot, y: y_dot},
        body=body,
        contact=parts["contact"],
        height=parts["height"],
        power=(body.sigma or sp.S.Zero) * OMEGA.dot(OMEGA),
        power_input=_vec(body.torque).dot(OMEGA) if body.torque is not None else None,
        omega_dot=omega_dot,
    )


#: Euler angles of :func:`euler_angle_spec`: R = Rz(psi) Rx(a1) Ry(a2) (body to space)
a1, a2 = sp.symbols("a1 a2", real=True)
psi_dot, a1_dot, a2_dot, x_dot, y_dot = sp.symbols("psi_dot a1_dot a2_dot x_dot y_dot", real=True)
psi_ddot, a1_ddot, a2_ddot, x_ddot, y_ddot = sp.symbols("psi_ddot a1_ddot a2_ddot x_ddot y_ddot", real=True)


def euler_angle_maps() -> tuple:
    """``(R, n, B)`` for the angles of :func:`euler_angle_spec`: rotation body -> space, the upward
    vertical in body axes and ``B`` with ``omega = B (psi_dot, a1_dot, a2_dot)`` (body axes).

    ``n = (-sin(a2) cos(a1), sin(a1), cos(a2) cos(a1))``; ``B`` is singular at ``a1 = +-pi/2``.
    """
    def rx(q):
        return sp.Matrix([[1, 0, 0], [0, sp.cos(q), -sp.sin(q)], [0, sp.sin(q), sp.cos(q)]])

    def ry(q):
        return sp.Matrix([[sp.cos(q), 0, sp.sin(q)], [0, 1, 0], [-sp.sin(q), 0, sp.cos(q)]])

    def rz(q):
        return sp.Matrix([[sp.cos(q), -sp.sin(q), 0], [sp.sin(q), sp.cos(q), 0], [0, 0, 1]])

    ez, ex, ey = sp.Matrix([0, 0, 1]), sp.Matrix([1, 0, 0]), sp.Matrix([0, 1, 0])
    R = rz(psi) * rx(a1) * ry(a2)
    n = ry(a2).T * rx(a1).T * ez
    B = sp.Matrix.hstack(ry(a2).T * rx(a1).T * ez, ry(a2).T * ex, ey)
    return R, n, B


def euler_angle_spec(body: RigidBody) -> ModelSpec:
    """The same body as an engine :class:`ModelSpec` in Euler angles (Lagrange multipliers).

    Coordinates ``(x, y, psi, a1, a2)``: the horizontal position of the centre
    of mass and the angles of :func:`euler_angle_maps`.  The height of the
    centre of mass is the holonomic ``z(n(a)) = -r.n``, substituted into the
    Lagrangian ``L = m |v|^2/2 + omega.I omega/2 - m g z``; the rolling
    constraints are the horizontal components of ``v + omega x r = 0`` in
    space axes.  :func:`derivation.engine.unreduced_accelerations` solves its
    Lagrange equations with multipliers at a numeric point: an independent
    route to the accelerations of :func:`derive` (the tests compare them).
    Dissipation is not included (``sigma`` must be ``None`` or zero).
    """
    if body.sigma not in (None, 0):
        raise ValueError("euler_angle_spec: conservative bodies only (sigma = 0)")
    R, n, B = euler_angle_maps()
    q_ang = sp.Matrix([psi, a1, a2])
    qd_ang = sp.Matrix([psi_dot, a1_dot, a2_dot])
    w = B * qd_ang
    r = body.shape.lowest_point(n)
    z = -r.dot(n)
    z_dot = (sp.Matrix([z]).jacobian(q_ang) * qd_ang)[0]
    I = sp.Matrix(body.inertia)
    m, g = body.mass, body.gravity
    lag = m * (x_dot**2 + y_dot**2 + z_dot**2) / 2 + (w.T * I * w)[0] / 2 - m * g * z
    slip = R * w.cross(r)  # velocity of the contact point relative to the centre of mass, space axes
    constraints = (x_dot + slip[0], y_dot + slip[1])
    return ModelSpec(
        name=f"{body.name}_euler",
        coordinates=(x, y, psi, a1, a2),
        velocities=(x_dot, y_dot, psi_dot, a1_dot, a2_dot),
        accelerations=(x_ddot, y_ddot, psi_ddot, a1_ddot, a2_ddot),
        lagrangian=lag,
        constraints=constraints,
        constraint_labels=("rolling_x", "rolling_y"),
        dependent=(x, y),
        cyclic={x: 0, y: 0, psi: 0},
        small=(a1, a2),
        params=tuple(body.params),
        pose=(psi, x, y),
        description=f"{body.name} in Euler angles (Lagrange multipliers), for cross-checks",
    )
