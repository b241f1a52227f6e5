"""Models written with ``sympy.physics.mechanics``, converted to a :class:`~.engine.ModelSpec`.

:func:`from_mechanics` takes a ``LagrangesMethod``, a ``KanesMethod`` or a
``System`` as its author wrote it and returns the data knifeedge's own engine
derives (a Lagrangian, linear velocity constraints, generalized forces), so
the converted model gets the same elimination, checks, contact forces and
compiled modules as the built-in ones.

What is read from each source
-----------------------------
``LagrangesMethod``
    its Lagrangian, its coordinates, its non-holonomic constraints
    (``nonhol_coneqs``) and its force list, whose generalized forces are
    those ``LagrangesMethod`` itself forms (``F . dv/dq_dot`` with the
    velocities the author gave the points).
``KanesMethod`` and ``System``
    the bodies, the loads, the kinematic differential equations and the
    velocity constraints.  The Lagrangian is built anew from the *positions*:
    the velocity of each mass centre is the time derivative of its position
    from a point fixed in the inertial frame, and each body's angular velocity
    comes from the orientations (the direction cosine matrices) along the
    chain of frames to the inertial frame.  Velocities set by hand
    (``set_vel``, ``set_ang_vel``, ``v2pt_theory``) may already contain the
    constraints (the velocity of a rolling body's centre written as if the
    contact point were fixed); such a kinetic energy is the *constrained* one,
    and Lagrange's equations of it are wrong for a non-holonomic system
    (sympy#27631).  The author's velocities are instead compared with the
    ones from the positions on the constraint manifold (the generalized speeds
    replaced through the kinematic differential equations, the dependent rates
    from the constraints) at random points; a difference is refused with its
    reason.  Forces constant in the inertial frame (gravity) become a
    potential ``-F . r``; every other load becomes generalized forces.

The velocity constraints are expressed in the coordinates' rates (the
generalized speeds replaced through the kinematic differential equations);
they may be affine (terms free of the rates) and hold time.  SymPy's time
becomes the engine's :data:`~.names.t`.  Configuration constraints
(``hol_coneqs``; KanesMethod's ``configuration_constraints`` with its
``q_dependent``; a System's ``holonomic_constraints``) become the spec's
``holonomic``: the engine differentiates them itself, so of a KanesMethod's
velocity constraints (which include their time derivatives) as many are
dropped as are implied by them (checked by rank at a point of the constraint
manifold).  The dependent coordinates are those whose rates the dependent
speeds are (``u_dep = q_dot``), else chosen among the cyclic coordinates;
one per configuration constraint: the author's ``q_dependent``, else a
non-cyclic coordinate (the last ones first) whose block is nonsingular.

Specified quantities (dynamic symbols that are neither coordinates nor
speeds, e.g. a torque ``tau(t)``) become the model's ``inputs``, plain symbols
of the same name given at run time (``simulate(..., inputs={"tau": ...})``).

What is refused (with the reason)
---------------------------------
The rates of specified quantities, and what the engine refuses (an input in the
Lagrangian).  Each refusal is a :class:`MechanicsConversionError` (a
``ValueError``) that says why.
"""
from __future__ import annotations

import itertools
import random
import sys
from dataclasses import dataclass, field

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Particle, Point, ReferenceFrame, RigidBody,
                                     dynamicsymbols)

from .engine import ModelSpec
from .names import t as _engine_t

_t = dynamicsymbols._t

__all__ = ["from_mechanics", "MechanicsConversionError", "MechanicsModelSpec"]


@dataclass(frozen=True, kw_only=True)
class MechanicsModelSpec(ModelSpec):
    """A :class:`ModelSpec` converted by :func:`from_mechanics`.

    Its multipliers need not be invariant under the symmetry of its ``cyclic``
    coordinates: an author's constraints are often written in the inertial
    axes (the rolling disc's contact velocity along the table's ``x`` and
    ``y``), so their multipliers (the contact force in those axes) turn with
    the heading.  The generated ``multipliers(s, p)`` are then those of the
    motion carried by the symmetry to the representative pose (the values of
    ``cyclic``): for the disc with heading 0 there, the contact force along
    and across the heading.  :func:`~.engine.check_symmetry` compares the
    accelerations only.
    """

    multipliers_invariant: bool = False
    #: ``file:line`` of the ``from_mechanics`` call (named in errors instead of this module's line)
    converted_at: str = field(default="", compare=False)

    def __post_init__(self):
        super().__post_init__()
        if self.converted_at:
            object.__setattr__(self, "defined_at", self.converted_at)

    def error_message(self, problems) -> str:
        message = super().error_message(problems)
        return message.replace(self.defined_at, self.converted_at) if self.converted_at else message


class MechanicsConversionError(ValueError):
    """A ``sympy.physics.mechanics`` model that knifeedge's engine cannot take (the message says why)."""


def _system_class():
    try:
        from sympy.physics.mechanics import System
    except ImportError:  # SymPy < 1.13
        return None
    return System


# ---------------------------------------------------------------- dynamic symbols -> plain symbols


class _Names:
    """The plain symbols of the coordinates ``q(t)``: ``q``, ``q_dot``, ``q_ddot`` (real)."""

    def __init__(self, coordinates):
        self.dynamic = tuple(coordinates)
        names = [_name(q) for q in self.dynamic]
        self.coordinates = tuple(sp.Symbol(n, real=True) for n in names)
        self.velocities = tuple(sp.Symbol(f"{n}_dot", real=True) for n in names)
        self.accelerations = tuple(sp.Symbol(f"{n}_ddot", real=True) for n in names)
        self.qdots = tuple(q.diff(_t) for q in self.dynamic)
        self.velocity_of = dict(zip(self.coordinates, self.velocities))
        self.replace = {}
        for q, s, v, a in zip(self.dynamic, self.coordinates, self.velocities, self.accelerations):
            self.replace[q.diff(_t, 2)] = a
            self.replace[q.diff(_t)] = v
            self.replace[q] = s

    def plain(self, e):
        """``e`` with ``q(t)``, its rate and acceleration replaced by the plain symbols."""
        return sp.sympify(e).xreplace(self.replace)

    def key(self, k):
        """A key given by the user (dynamic symbol, its derivative, plain symbol or name) as a plain symbol or name."""
        if isinstance(k, sp.Basic) and (k.has(_t)):
            out = self.plain(k)
            if not isinstance(out, sp.Symbol):
                raise ValueError(f"{k} is neither a coordinate of the model nor the rate of one")
            return out
        return k


def _name(q) -> str:
    if not isinstance(q, AppliedUndef) or q.args != (_t,):
        raise MechanicsConversionError(
            f"the coordinate {q} is not a dynamic symbol q(t) (sympy.physics.mechanics.dynamicsymbols)")
    return str(q.func)


# ---------------------------------------------------------------- kinematics from positions


def _fixed_point(point: Point, frame: ReferenceFrame, given: Point | None = None) -> Point:
    """A point fixed in ``frame`` (its velocity set to zero there) to which ``point`` is located: ``given``, else
    of those the farthest from ``point`` (the origin the positions are built from; a nearer one is a body's
    material point at a contact whose velocity the author set to zero because it does not slip, as PyDy's
    rattleback example sets its contact point's)."""
    seen, todo, found = {point}, [point], []
    while todo:
        p = todo.pop(0)
        if p is given:
            return p
        if given is None and frame in p._vel_dict and p._vel_dict[frame] == 0:
            found.append(p)
        for other in p._pos_dict:
            if other not in seen:
                seen.add(other)
                todo.append(other)
    if found:
        return found[-1]
    raise MechanicsConversionError(
        f"the point {point} is located relative to no point fixed in the inertial frame {frame}: set the velocity "
        f"of an origin to zero (`O.set_vel({frame}, 0)`) and locate the bodies from it")


def _position(point: Point, origin: Point, frame: ReferenceFrame) -> sp.Matrix:
    return point.pos_from(origin).to_matrix(frame)


def _angular_velocity(body_frame: ReferenceFrame, frame: ReferenceFrame) -> sp.Matrix:
    """Angular velocity of ``body_frame`` in ``frame``, components in ``body_frame``, from the orientations alone.

    Summed over the chain of frames oriented one from the next; each link's
    rate is read from its direction cosine matrix ``R`` (``R^T R_dot`` is the
    skew matrix of the link's angular velocity in the child's components),
    not from ``set_ang_vel``.
    """
    if body_frame == frame:
        return sp.zeros(3, 1)
    try:
        chain = body_frame._dict_list(frame, 0)
    except ValueError:
        raise MechanicsConversionError(
            f"the frame {body_frame} is not oriented relative to the inertial frame {frame}") from None
    omega = sp.zeros(3, 1)
    for child, parent in zip(chain, chain[1:]):
        link = _link_rate(child, parent)
        omega += link if child == body_frame else body_frame.dcm(child) * link
    return omega


def _link_rate(child: ReferenceFrame, parent: ReferenceFrame) -> sp.Matrix:
    """Angular velocity of ``child`` in ``parent`` (child's components) from their direction cosine matrix.

    The rate SymPy stored when the frames were oriented is taken when it equals
    ``R^T R_dot`` at random points (``R`` the direction cosine matrix); else
    (it was overwritten by ``set_ang_vel``) ``R^T R_dot`` itself, simplified.
    """
    R = parent._dcm_dict[child]  # columns: child's basis in parent's components
    W = R.T * R.diff(_t)
    exact = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
    stored = child._ang_vel_dict.get(parent)
    if stored is not None:
        stored = stored.to_matrix(child)
        if _numerically_equal(exact, stored):
            return stored
    return exact.applyfunc(sp.trigsimp)


def _numerically_equal(a: sp.Matrix, b: sp.Matrix, trials: int = 2) -> bool:
    """``a == b`` at random values of every function of time, its rates and every symbol."""
    rng = random.Random(3)
    for _ in range(trials):
        values = {}
        for e in (a, b):
            for d in sorted(e.atoms(sp.Derivative), key=lambda d: -d.derivative_count):
                values.setdefault(d, sp.Float(rng.uniform(-1, 1), 30))
        pt = {d: v for d, v in values.items()}
        a1, b1 = a.xreplace(pt), b.xreplace(pt)
        rest = {f: sp.Float(rng.uniform(-1, 1), 30) for e in (a1, b1) for f in e.atoms(AppliedUndef)}
        rest.update({s: sp.Float(rng.uniform(0.5, 1.5), 30) for e in (a1, b1) for s in e.free_symbols - {_t}})
        diff = (a1.xreplace(rest) - b1.xreplace(rest)).evalf(30)
        if any(abs(complex(x)) > 1e-20 for x in diff):
            return False
    return True


def _vector(components: sp.Matrix, frame: ReferenceFrame):
    return components[0] * frame.x + components[1] * frame.y + components[2] * frame.z


# ---------------------------------------------------------------- sources


class _Source:
    """What :func:`from_mechanics` reads of a model, in dynamic symbols (``q(t)``)."""

    kind: str
    frame: ReferenceFrame
    q: tuple
    u_of_qdot: dict           # generalized speed -> expression in q, q_dot (Kane, System)
    bodies: tuple
    loads: tuple
    constraints: tuple        # velocity constraints in q, q_dot
    dependent_speeds: tuple
    lagrangian: sp.Expr | None = None
    forces: tuple = ()         # generalized forces (LagrangesMethod)
    potential: sp.Expr = sp.S.Zero
    fixed_point: Point | None = None
    holonomic: tuple = ()      # configuration constraints f(q, t) = 0 (dynamic symbols)
    dependent_coordinates: tuple = ()  # KanesMethod's q_dependent, one per configuration constraint


def _from_lagrange(lm: LagrangesMethod) -> _Source:
    src = _Source()
    src.kind = "LagrangesMethod"
    src.frame = lm.inertial
    src.q = tuple(lm.q)
    src.u_of_qdot = {}
    src.bodies, src.loads = (), ()
    src.holonomic = tuple(lm._hol_coneqs)
    src.constraints = tuple(lm.coneqs)[len(src.holonomic):]  # coneqs: d(hol_coneqs)/dt, then nonhol_coneqs
    src.dependent_speeds = ()
    src.lagrangian = lm._L[0]
    qdots = [q.diff(_t) for q in src.q]
    if lm.forcelist:
        if src.frame is None:
            raise MechanicsConversionError("the LagrangesMethod has a `forcelist` but no inertial `frame`; pass "
                                           "`frame=N` to LagrangesMethod")
        pairs = _load_pairs(lm.forcelist, lambda p: p.vel(src.frame), lambda f: f.ang_vel_in(src.frame))
        src.forces = tuple(sum((v.diff(qd, src.frame).dot(f) for v, f in pairs), sp.S.Zero) for qd in qdots)
    return src


def _load_pairs(loads, velocity, angular_velocity) -> list:
    """``(velocity, vector)`` of each load: the point's velocity for a force, the frame's angular velocity for a torque."""
    pairs = []
    for load in loads:
        where, vector = load[0], load[1]
        if isinstance(where, Point):
            pairs.append((velocity(where), vector))
        elif isinstance(where, ReferenceFrame):
            pairs.append((angular_velocity(where), vector))
        else:
            raise MechanicsConversionError(f"a load acts on {where!r}, neither a Point nor a ReferenceFrame")
    return pairs


def _speeds_of_rates(kdes: list, q: tuple, u: tuple) -> dict:
    """Generalized speeds as functions of ``q`` and ``q_dot`` from the kinematic differential equations."""
    u = list(u)
    kdes = sp.Matrix(kdes)
    K = kdes.jacobian(u)
    rest = kdes.xreplace(dict.fromkeys(u, 0))
    if len(kdes) < len(u):
        free = [s for j, s in enumerate(u) if all(e == 0 for e in K.col(j))]
        raise MechanicsConversionError(
            f"the speeds {free or u} have no kinematic differential equation ({len(kdes)} equations for {len(u)} "
            f"speeds): their coordinates (e.g. a wheel's rotation angle) are left out, and a Lagrangian needs "
            f"them. Add each such coordinate with its equation `q.diff() - u` (and, if a contact point is set "
            f"fixed, its coordinates on the ground with the rolling condition as velocity constraints)")
    if K.has(*u) or K.shape[0] != len(u):
        raise MechanicsConversionError("the kinematic differential equations must be linear in the generalized "
                                       "speeds, one per speed")
    if K.is_diagonal():
        sol = sp.Matrix([-rest[i] / K[i, i] for i in range(len(u))])
    else:
        sol = (-K.LUsolve(rest)).applyfunc(sp.trigsimp)
    return dict(zip(u, sol.applyfunc(sp.expand)))


def _from_kane(km: KanesMethod) -> _Source:
    src = _Source()
    src.kind = "KanesMethod"
    src.holonomic, src.dependent_coordinates = tuple(km._f_h), tuple(km._qdep)
    src.frame = km._inertial
    src.q = tuple(km.q)
    kdes = km._k_kqdot_implicit * sp.Matrix(src.q).diff(_t) + km._k_ku_implicit * km.u + km._f_k_implicit
    src.u_of_qdot = _speeds_of_rates(list(kdes), src.q, tuple(km.u))
    aux = dict.fromkeys(km._uaux, 0)
    src.u_of_qdot.update(aux)
    src.bodies = tuple(km.bodies or ())
    src.loads = tuple(km.loads or ())
    constraints = []
    if len(km._k_nh):
        constraints = list(km._k_nh * km.u + km._f_nh)
    src.constraints = tuple(constraints)
    src.dependent_speeds = tuple(km._udep)
    return src


def _from_system(system) -> _Source:
    if system.eom_method is None:
        system.form_eoms()
    kane = system.eom_method
    if not isinstance(kane, KanesMethod):
        return _from_lagrange(kane)
    src = _from_kane(kane)
    src.kind = "System"
    src.fixed_point = system.fixed_point
    return src


# ---------------------------------------------------------------- the Lagrangian of the bodies


def _body_terms(src: _Source) -> tuple:
    """Kinetic energy, potential, generalized forces (dynamic symbols) and the velocity check's pairs."""
    N, qdots = src.frame, [q.diff(_t) for q in src.q]
    origin = None
    T, V = sp.S.Zero, sp.S.Zero
    checks = []  # (what, ours, author's), as N-components
    positions, omegas = {}, {}

    def position(point):
        nonlocal origin
        if point not in positions:
            origin = origin or _fixed_point(point, N, src.fixed_point)
            positions[point] = _position(point, origin, N)
        return positions[point]

    def omega(frame):
        """Angular velocity of ``frame``, components in ``frame``."""
        if frame not in omegas:
            omegas[frame] = _angular_velocity(frame, N)
        return omegas[frame]

    for body in src.bodies:
        if isinstance(body, RigidBody):
            point, mass = body.masscenter, body.mass
        elif isinstance(body, Particle):
            point, mass = body.point, body.mass
        else:
            raise MechanicsConversionError(f"the body {body} is neither a RigidBody nor a Particle")
        v = position(point).diff(_t)
        T += mass * v.dot(v) / 2
        checks.append((f"the velocity of {point}", v, point.vel(N).to_matrix(N)))
        if isinstance(body, RigidBody) and body.frame is not None:
            w = omega(body.frame)
            I = body.central_inertia.to_matrix(body.frame)
            T += (w.T * I * w)[0] / 2
            checks.append((f"the angular velocity of {body.frame}", w,
                           body.frame.ang_vel_in(N).to_matrix(body.frame)))
        if getattr(body, "potential_energy", 0):
            V += body.potential_energy
    forces = [sp.S.Zero] * len(qdots)
    for load in src.loads:
        where, vector = load[0], load[1]
        F = vector.to_matrix(N)
        if isinstance(where, Point):
            if not F.has(_t):  # constant in the inertial frame: a potential
                V -= F.dot(position(where))
                continue
            rate = position(where).diff(_t)
        elif isinstance(where, ReferenceFrame):
            rate, F = omega(where), vector.to_matrix(where)
        else:
            raise MechanicsConversionError(f"a load acts on {where!r}, neither a Point nor a ReferenceFrame")
        forces = [f + F.dot(rate.diff(qd)) for f, qd in zip(forces, qdots)]
    return T, V, forces, checks


def _check_velocities(src: _Source, names: _Names, checks: list, constraints: list, dependent: tuple,
                      params: set, seed: int = 1) -> None:
    """Refuse when the author's velocities differ from the positions' time derivatives on the constraint manifold."""
    if not checks:
        return
    rng = random.Random(seed)
    ind_rates = [v for q, v in zip(names.coordinates, names.velocities) if q not in dependent]
    dep_rates = [names.velocity_of[q] for q in dependent]
    for trial in range(2):
        pt = {s: sp.Float(rng.uniform(-1.0, 1.0), 30) for s in names.coordinates + tuple(ind_rates)}
        pt.update({p: sp.Float(rng.uniform(0.5, 1.5), 30) for p in params})
        pt[_engine_t] = pt[_t] = sp.Float(rng.uniform(0.0, 1.0), 30)
        if dep_rates:
            A = sp.Matrix(constraints).jacobian(dep_rates)
            b = sp.Matrix(constraints).xreplace(dict.fromkeys(dep_rates, 0))
            pt.update(zip(dep_rates, (-A.xreplace(pt)).LUsolve(b.xreplace(pt))))
        for what, ours, theirs in checks:
            ours = names.plain(ours).xreplace(pt).evalf(30)
            theirs = names.plain(theirs.xreplace(src.u_of_qdot)).xreplace(pt).evalf(30)
            diff = max(abs(complex(a - b)) for a, b in zip(ours, theirs))
            scale = 1 + max(abs(complex(a)) for a in ours)
            if diff > 1e-12 * scale:
                raise MechanicsConversionError(
                    f"{what} as the model sets it is not the time derivative of its position (from a point fixed "
                    f"in {src.frame}), even on the constraint manifold (they differ by {float(diff):.3g} at a "
                    f"random state): the kinematics already contain constraints that the model does not state as "
                    f"velocity constraints (e.g. a contact point set fixed while the body rolls), and a Lagrangian "
                    f"needs the unconstrained velocities. Give the contact point coordinates of its own and the "
                    f"rolling condition as velocity constraints (as sympy's test_kane5.py rolling disc does)")


# ---------------------------------------------------------------- dependent coordinates


def _choose_dependent(constraints: list, names: _Names, cyclic: set, given, dependent_speeds, src,
                      exclude=frozenset()) -> tuple:
    m = len(constraints)
    if given is not None:
        return tuple(_coordinate(q, names) for q in given)
    if m == 0:
        return ()
    by_speed = []
    for u in dependent_speeds:
        rate = names.plain(src.u_of_qdot.get(u, sp.S.Zero))
        hit = [q for q, v in zip(names.coordinates, names.velocities) if rate == v]
        by_speed.append(hit[0] if hit else None)
    by_speed = [q for q in by_speed if q not in exclude]
    if len(by_speed) == m and None not in by_speed:
        return tuple(by_speed)
    A = sp.Matrix(constraints).jacobian(names.velocities)
    rng = random.Random(0)
    pt = {s: rng.uniform(-1, 1) for s in A.free_symbols}
    candidates = [q for q in names.coordinates if q in cyclic]
    best, best_score = None, -1
    for combo in itertools.combinations(candidates, m):
        cols = [names.coordinates.index(q) for q in combo]
        block = A.extract(list(range(m)), cols)
        if abs(block.xreplace(pt).evalf().det()) < 1e-9:
            continue
        score = sum(1 for j in range(m) if not block.col(j).free_symbols & set(names.coordinates))
        if score > best_score:
            best, best_score = combo, score
    if best is None:
        raise MechanicsConversionError(
            f"no choice of {m} cyclic coordinates has its rates determined by the {m} velocity constraints; give "
            f"`dependent` (one coordinate per constraint) and make them `cyclic`")
    return best


def _coordinate(q, names: _Names):
    return names.key(q) if not isinstance(q, str) else sp.Symbol(q, real=True)


def _rate_of(f: sp.Expr, names: _Names) -> sp.Expr:
    """``df/dt`` along the motion: ``df/dq q_dot + df/dt`` (as :attr:`ModelSpec.velocity_constraints` forms it)."""
    return sum((sp.diff(f, q) * v for q, v in zip(names.coordinates, names.velocities)), sp.diff(f, _engine_t))


def _holonomic_dependent(holonomic: list, names: _Names, src, given, n_velocity: int, cyclic: set) -> tuple:
    """One coordinate per configuration constraint: given (after the velocity constraints' ones), the author's
    ``q_dependent``, else the last non-cyclic coordinates whose block of ``df/dq`` is nonsingular."""
    h = len(holonomic)
    if given is not None:
        given = tuple(given)
        return tuple(_coordinate(q, names) for q in given[len(given) - h:])
    if len(src.dependent_coordinates) == h:
        return tuple(names.plain(q) for q in src.dependent_coordinates)
    J = sp.Matrix(holonomic).jacobian(names.coordinates)
    rng = random.Random(0)
    pt = {s: rng.uniform(0.3, 1.2) for s in J.free_symbols}
    candidates = [q for q in reversed(names.coordinates) if q not in cyclic]
    for combo in itertools.combinations(candidates, h):
        block = J.extract(list(range(h)), [names.coordinates.index(q) for q in combo])
        if abs(block.xreplace(pt).evalf().det()) > 1e-9:
            return tuple(reversed(combo))
    raise MechanicsConversionError(
        f"no choice of {h} non-cyclic coordinates is fixed by the configuration constraints {holonomic}; give "
        f"`dependent` (one coordinate per velocity constraint, then one per configuration constraint)")


def _manifold_point(holonomic: list, dep: tuple, names: _Names, params: set, seed: int = 2) -> dict:
    """A point with every configuration constraint satisfied (the dependent coordinates solved by Newton)."""
    rng = random.Random(seed)
    for _ in range(20):
        pt = {s: sp.Float(rng.uniform(0.5, 1.5), 30) for s in params}
        pt[_engine_t] = sp.Float(rng.uniform(0, 1), 30)
        pt.update({q: sp.Float(rng.uniform(-0.5, 0.5), 30) for q in names.coordinates if q not in dep})
        pt.update({v: sp.Float(rng.uniform(-1, 1), 30) for v in names.velocities})
        try:
            sol = sp.nsolve([f.xreplace(pt) for f in holonomic], list(dep), [rng.uniform(-0.5, 0.5) for _ in dep],
                            prec=30)
        except (ValueError, ZeroDivisionError, TypeError):
            continue
        pt.update(zip(dep, sol))
        return pt
    raise MechanicsConversionError(f"found no configuration satisfying the configuration constraints {holonomic}")


def _nonholonomic_part(constraints: list, holonomic: list, dep_h: tuple, names: _Names, params: set,
                       kind: str) -> list:
    """The velocity constraints without those the configuration constraints' rates imply.

    ``KanesMethod`` takes every velocity constraint, the configuration
    constraints' time derivatives among them; the engine differentiates the
    configuration constraints itself, so ``h`` of the author's velocity
    constraints are dropped: the first set whose remainder, together with the
    derivatives, keeps the full rank at a point on the constraint manifold.
    """
    m, h = len(constraints), len(holonomic)
    if kind == "LagrangesMethod" or m == 0:
        return list(constraints)
    keep = m - h
    if keep < 0:
        raise MechanicsConversionError(f"{h} configuration constraints but only {m} velocity constraints: the "
                                       f"{kind}'s velocity constraints must include their time derivatives")
    pt = _manifold_point(holonomic, dep_h, names, params)
    A = sp.Matrix(constraints).jacobian(names.velocities).xreplace(pt).evalf(30)
    H = sp.Matrix([_rate_of(f, names) for f in holonomic]).jacobian(names.velocities).xreplace(pt).evalf(30)
    full = np.linalg.matrix_rank(np.array(A.col_join(H).tolist(), dtype=float), tol=1e-9)
    for rows in itertools.combinations(range(m), keep):
        block = A.extract(list(rows), list(range(A.cols))).col_join(H)
        if np.linalg.matrix_rank(np.array(block.tolist(), dtype=float), tol=1e-9) == full == m:
            return [constraints[i] for i in rows]
    raise MechanicsConversionError(
        f"the {kind}'s velocity constraints do not contain the time derivatives of its configuration constraints "
        f"(rank {full} of {m} + {h} at a point of the constraint manifold); state them among the velocity "
        f"constraints, as KanesMethod expects")


# ---------------------------------------------------------------- the conversion


def _source(method_or_system) -> _Source:
    System = _system_class()
    if isinstance(method_or_system, LagrangesMethod):
        return _from_lagrange(method_or_system)
    if isinstance(method_or_system, KanesMethod):
        if method_or_system.bodies is None:
            raise MechanicsConversionError("the KanesMethod has no bodies: call `kanes_equations(bodies, loads)` "
                                           "first or pass `bodies=` and `forcelist=` to KanesMethod")
        return _from_kane(method_or_system)
    if System is not None and isinstance(method_or_system, System):
        return _from_system(method_or_system)
    raise TypeError(f"`method_or_system` must be a sympy.physics.mechanics LagrangesMethod, KanesMethod or System, "
                    f"got {type(method_or_system).__name__}")


def _specified_as_inputs(e: sp.Expr, inputs: dict) -> sp.Expr:
    """``e`` (coordinates already plain) with SymPy's time as the engine's :data:`~.names.t` and each specified
    quantity ``f(t)`` (a dynamic symbol that is neither a coordinate nor a speed) as the plain symbol ``f``,
    recorded in ``inputs`` (``{f(t): f}``): the model's ``inputs``, given at run time.

    A derivative of a specified quantity is refused (the run gives an input's values, not its rates there).
    """
    rates = sorted(map(str, {d.expr for d in e.atoms(sp.Derivative)}))
    if rates:
        raise MechanicsConversionError(
            f"the model holds the rates of the specified quantities {rates}; knifeedge's `inputs` are given at "
            f"run time by their values only. Make the rate itself the specified quantity (a new dynamic "
            f"symbol), or write it as an explicit function of time")
    for f in e.atoms(AppliedUndef):
        if f.has(_t):
            inputs.setdefault(f, sp.Symbol(str(f.func), real=True))
    return e.xreplace(inputs).xreplace({_t: _engine_t})


def _exact(e: sp.Expr) -> sp.Expr:
    """``e`` with its decimal numbers (``g = 9.8``) as the exact decimals they print as.

    A float carries 15 digits into every expression it meets; the engine's checks compare the reduced and
    unreduced equations to 1e-20 and would see its rounding as a broken symmetry.
    """
    return e.xreplace({f: sp.Rational(str(f)) for f in e.atoms(sp.Float)})


def _tidy(e: sp.Expr, velocities) -> sp.Expr:
    """``e`` as a polynomial in the rates whose coefficients (functions of the coordinates) are simplified."""
    e = sp.expand(e)
    if not e.free_symbols & set(velocities):
        return _tidy_coefficient(e)
    poly = sp.Poly(e, *velocities)
    return sum((_tidy_coefficient(c) * sp.Mul(*(v**k for v, k in zip(velocities, m)))
                for m, c in poly.terms()), sp.S.Zero)


#: coefficients larger than this (``count_ops``) are left expanded: factoring the Whipple bicycle's
#: (14,843 operations in its Lagrangian) ran for more than 3 CPU minutes without finishing one term
TIDY_OPS = 400
#: a model whose Lagrangian has more nodes than this is kept as its bodies compose it (nothing expanded or
#: simplified): the Whipple bicycle's has 2,419 nodes (1,654 operations) as composed and 14,843 operations
#: expanded, whose derivatives (the mass matrix, the velocity terms, the constraints' rates: 97,000 operations)
#: the numeric elimination would only share again by CSE; simplifying its coefficients took minutes.  The
#: sympy rolling disc has 113 nodes, the differential-drive robot 168
TIDY_NODES = 1000


def _nodes(e: sp.Expr) -> int:
    """Number of nodes of the expression tree of ``e`` (a shared subtree counts once per occurrence)."""
    return sum(1 for _ in sp.preorder_traversal(e))


def _tidy_coefficient(c: sp.Expr) -> sp.Expr:
    if sp.count_ops(c) > TIDY_OPS:
        return c
    return sp.factor(sp.trigsimp(sp.factor(c)))


def _user_location() -> str:
    """``file:line`` of the first frame outside this module (the ``from_mechanics`` call)."""
    frame = sys._getframe(1)
    while frame is not None and frame.f_code.co_filename == __file__:
        frame = frame.f_back
    return "<unknown>" if frame is None else f"{frame.f_code.co_filename}:{frame.f_lineno}"


def _spec_keys(value, names: _Names):
    """Entries of a ModelSpec field given with dynamic symbols, as plain symbols (recursively for dicts/tuples)."""
    if isinstance(value, dict):
        return {names.key(k): _spec_keys(v, names) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return type(value)(names.key(v) for v in value)
    return value


def from_mechanics(method_or_system, *, name: str, cyclic: dict, units: dict | None = None,
                   defaults: dict | None = None, dependent=None, params=None, description: str = "",
                   **spec_fields) -> ModelSpec:
    """A :class:`~knifeedge.derive.ModelSpec` from a ``sympy.physics.mechanics`` model.

    Parameters
    ----------
    method_or_system : ``LagrangesMethod``, ``KanesMethod`` (after ``kanes_equations``) or ``System``.
    name : the model's name (names the generated modules).
    cyclic : ``{coordinate: value}``, the coordinates the dynamics does not depend on (every dependent
        coordinate among them), with the value at which the engine evaluates the equations.  Keys may be
        the dynamic symbols ``q(t)``, plain symbols or names.
    units, defaults : as in :class:`ModelSpec`; keys may be dynamic symbols or their derivatives
        (``q(t).diff()`` stands for the state ``q_dot``), symbols or names.
    dependent : the coordinates whose rates the velocity constraints fix (default: those the dependent
        speeds are the rates of, else a choice among the cyclic coordinates), then one per configuration
        constraint (default: KanesMethod's ``q_dependent``, else a non-cyclic coordinate).
    params : the parameters in the order of the parameter vector (default: every other symbol, by name).
    description : one paragraph for the generated modules.
    spec_fields : any other :class:`ModelSpec` field (``small``, ``pose``, ``state_order``, ``validity``,
        ``param_domains``, ``constraint_labels``, ``time_unit``, ...), keys and entries as for ``units``.

    Returns
    -------
    ModelSpec whose coordinates are the plain symbols ``q``, velocities ``q_dot`` (real); the
    Lagrangian ``T - V`` of the bodies and conservative loads (``LagrangesMethod``: its own), the
    velocity constraints in the rates, the other loads as ``forces``; ``pose`` defaults to the
    cyclic coordinates.

    Raises
    ------
    MechanicsConversionError
        what cannot be converted, with the reason (rates of specified quantities, kinematics that
        already contain unstated constraints).
    """
    if not isinstance(name, str) or not name.isidentifier():
        raise ValueError(f"`name` must be a Python identifier (it names the generated modules), got {name!r}")
    if not isinstance(cyclic, dict):
        raise ValueError("`cyclic` must be a mapping {coordinate: representative value}")
    src = _source(method_or_system)
    names = _Names(src.q)
    if src.lagrangian is not None:
        lagrangian, forces, checks = src.lagrangian, list(src.forces), []
    else:
        T, V, forces, checks = _body_terms(src)
        lagrangian = T - V
    specified: dict = {}  # f(t) -> f: the inputs
    plain = lambda e: _exact(_specified_as_inputs(names.plain(sp.sympify(e).xreplace(src.u_of_qdot)),  # noqa: E731
                                                  specified))
    lagrangian = plain(lagrangian)
    if _nodes(lagrangian) > TIDY_NODES:  # a large model is kept as its bodies compose it
        tidy, simplify = (lambda e: e), (lambda e: e)
    else:
        tidy, simplify = (lambda e: _tidy(e, names.velocities)), (lambda e: sp.factor(sp.trigsimp(e)))
    lagrangian = tidy(lagrangian)
    forces = [tidy(plain(f)) for f in forces]
    constraints = [tidy(plain(c)) for c in src.constraints]
    holonomic = [simplify(plain(f)) for f in src.holonomic]
    cyclic = {names.key(k) if not isinstance(k, str) else sp.Symbol(k, real=True): v for k, v in cyclic.items()}
    inputs = tuple(sorted(set(specified.values()), key=str))
    declared = set(names.coordinates) | set(names.velocities) | {_engine_t} | set(inputs)
    found = set().union(*(e.free_symbols for e in [lagrangian, *forces, *constraints, *holonomic])) - declared
    params = tuple(params) if params is not None else tuple(sorted(found, key=str))
    all_constraints = list(constraints)
    if holonomic:
        dep_h = _holonomic_dependent(holonomic, names, src, dependent, len(constraints), set(cyclic))
        constraints = _nonholonomic_part(constraints, holonomic, dep_h, names, set(params), src.kind)
        all_constraints = constraints + [_rate_of(f, names) for f in holonomic]
        given = None if dependent is None else tuple(dependent)[:len(constraints)]
        dep_nh = _choose_dependent(constraints, names, set(cyclic) - set(dep_h), given, src.dependent_speeds, src,
                                   exclude=set(dep_h))
        dependent = tuple(dep_nh) + tuple(dep_h)
    else:
        dependent = _choose_dependent(constraints, names, set(cyclic), dependent, src.dependent_speeds, src)
    _check_velocities(src, names, checks, all_constraints, dependent, set(params))
    if not constraints and not holonomic:
        raise MechanicsConversionError(
            f"the {src.kind} states no velocity constraint; knifeedge's engine derives non-holonomic systems and "
            f"needs at least one (a model without constraints is not yet taken). If the system rolls or slides "
            f"on a knife edge, its constraints are missing: a Lagrangian with the rolling condition substituted "
            f"into it gives wrong equations (sympy#27631); state them as `nonhol_coneqs` / `velocity_constraints`")
    fields = {k: _spec_keys(v, names) for k, v in spec_fields.items()}
    fields.setdefault("pose", tuple(q for q in names.coordinates if q in cyclic))
    return MechanicsModelSpec(
        name=name,
        coordinates=names.coordinates,
        velocities=names.velocities,
        accelerations=names.accelerations,
        lagrangian=lagrangian,
        constraints=tuple(constraints),
        holonomic=tuple(holonomic),
        dependent=tuple(dependent),
        params=params,
        cyclic=cyclic,
        forces=tuple(forces) if any(f != 0 for f in forces) else (),
        inputs=inputs,
        units=_spec_keys(dict(units or {}), names),
        defaults=_spec_keys(dict(defaults or {}), names),
        description=description or f"Converted by knifeedge.derive.from_mechanics from a sympy {src.kind}.",
        converted_at=_user_location(),
        **fields,
    )
