"""Generic non-holonomic engine: Lagrangian + linear velocity constraints -> reduced ODE.

Given a model (:class:`ModelSpec`): an unconstrained Lagrangian ``L(q, q_dot)``
per unit mass, constraints ``sum_i a_ji(q) q_dot_i = 0`` and the coordinates
that are cyclic (the dynamics does not depend on them), :func:`derive`

1. forms the Lagrange equations with multipliers
   ``M(q) q_ddot + h(q, q_dot) = A(q)^T lambda``,
2. differentiates the constraints, ``A q_ddot + c(q, q_dot) = 0``,
3. evaluates everything at a representative point of the cyclic coordinates
   (for the knife edges ``x = y = phi = 0``; valid after differentiation by the
   rotational and translational symmetry, which :func:`check_symmetry` tests),
4. solves the constraints for the dependent velocities and substitutes them,
5. eliminates the multipliers with the dependent equations,
   ``lambda = A_dep^{-T} (M q_ddot + h)_dep``, and the dependent accelerations
   with the differentiated constraints,
6. returns the reduced system on the smallest closed state: the non-cyclic
   independent coordinates (the tilts), their rates, and the rates of the
   independent cyclic coordinates (the spin rate).  The cyclic coordinates
   follow by quadrature from the pose rates.

The result carries the mass-matrix form ``M_red(s) a = f_red(s)`` (``a`` the
independent accelerations), the explicit form ``a = F(s)``, the multipliers
(contact forces per unit mass) as functions of the state, the energy, and the
pose rates at a general pose.
"""
from __future__ import annotations

import random

import mpmath
from dataclasses import dataclass, field

import sympy as sp


@dataclass(frozen=True)
class ModelSpec:
    """A mechanical model as data.

    Attributes
    ----------
    name : model name, e.g. ``"single_mode"``.
    coordinates : generalized coordinates ``q``.
    velocities : their time derivatives ``q_dot`` (plain symbols).
    accelerations : their second derivatives (plain symbols).
    lagrangian : unconstrained Lagrangian per unit mass, in ``q``, ``q_dot`` and
        the parameters.
    constraints : linear velocity constraints (expressions equal to zero),
        with ``constraint_labels`` naming them after the paper.
    dependent : coordinates whose velocities the constraints determine.
    cyclic : coordinates the reduced dynamics does not depend on, mapped to the
        representative value at which the equations are evaluated.
    small : coordinates scaled as small in the ``reduced`` truncation (tilts).
    params : parameter symbols in the order of the parameter vector.
    pose : cyclic coordinates reported as the pose (order of ``POSE_NAMES``).
    quasi_velocities : optional ``(symbol, replaced_velocity, expression)``
        triples: a velocity of a cyclic independent coordinate is replaced in
        the closed state by a quasi-velocity, ``expression`` linear in the
        velocities with coefficients depending on the coordinates (for a
        sleigh, the speed along its axis ``x_dot cos(phi) + y_dot sin(phi)``).
        Needed when the independent velocities of the cyclic coordinates are
        not invariant under the symmetry (translations in a body frame).
    """

    name: str
    coordinates: tuple
    velocities: tuple
    accelerations: tuple
    lagrangian: sp.Expr
    constraints: tuple
    constraint_labels: tuple
    dependent: tuple
    cyclic: dict
    small: tuple
    params: tuple
    pose: tuple
    description: str = ""
    param_units: dict = field(default_factory=dict)
    quasi_velocities: tuple = ()

    @property
    def independent(self) -> tuple:
        return tuple(q for q in self.coordinates if q not in self.dependent)

    def velocity_of(self, q):
        return self.velocities[self.coordinates.index(q)]

    def acceleration_of(self, q):
        return self.accelerations[self.coordinates.index(q)]

    @property
    def velocity_state(self) -> tuple:
        """Small coordinates, their rates, rates of cyclic independents (before quasi-velocities)."""
        tilts = tuple(q for q in self.independent if q not in self.cyclic)
        spins = tuple(q for q in self.independent if q in self.cyclic)
        return tilts + tuple(self.velocity_of(q) for q in tilts) + tuple(
            self.velocity_of(q) for q in spins
        )

    @property
    def state(self) -> tuple:
        """Closed state: :attr:`velocity_state` with the quasi-velocities in place of the velocities they replace."""
        replace_by = {old: new for new, old, _ in self.quasi_velocities}
        return tuple(replace_by.get(s, s) for s in self.velocity_state)


@dataclass
class ReducedSystem:
    """Reduced first-order system of a :class:`ModelSpec`.

    ``state`` is ``(tilts, tilt rates, spin rates)``; ``accelerations`` are the
    independent accelerations ``a`` (tilt accelerations, then spin
    accelerations); ``mass_matrix @ a = forcing`` and ``a = explicit``.
    ``multipliers`` are the Lagrange multipliers per unit mass, functions of the
    state (``explicit`` substituted).  ``energy`` is the Jacobi integral per
    unit mass on the constraint manifold.  ``pose_rates`` maps each pose
    coordinate to its rate, in the state and the pose.
    """

    spec: ModelSpec
    state: tuple
    accelerations: tuple
    mass_matrix: sp.Matrix
    forcing: sp.Matrix
    explicit: sp.Matrix
    multipliers: sp.Matrix
    multipliers_implicit: sp.Matrix
    energy: sp.Expr
    pose_rates: dict

    def state_rhs(self) -> list:
        """Right-hand side of ``d(state)/dt`` as a list of expressions."""
        spec = self.spec
        tilts = [q for q in spec.independent if q not in spec.cyclic]
        spins = [q for q in spec.independent if q in spec.cyclic]
        rates = [spec.velocity_of(q) for q in tilts]
        # ``explicit`` follows the order of ``spec.independent``, which may interleave tilts and spins
        return rates + [self.explicit[spec.independent.index(q)] for q in tilts + spins]


def _lagrange_terms(spec: ModelSpec):
    """Mass matrix ``M``, velocity/potential terms ``h`` and constraint data."""
    q, qd = sp.Matrix(spec.coordinates), sp.Matrix(spec.velocities)
    L = spec.lagrangian
    p_mom = sp.Matrix([sp.diff(L, v) for v in qd])
    M = p_mom.jacobian(qd)
    h = p_mom.jacobian(q) * qd - sp.Matrix([sp.diff(L, c) for c in q])
    if any(sp.diff(e, v) != 0 for e in M for v in qd):
        raise ValueError(f"{spec.name}: the Lagrangian must be quadratic in the velocities")
    cons = sp.Matrix(spec.constraints)
    A = cons.jacobian(qd)
    if sp.expand(cons - A * qd) != sp.zeros(len(spec.constraints), 1):
        raise ValueError(f"{spec.name}: the constraints must be linear and homogeneous in the velocities")
    c = (A * qd).jacobian(q) * qd  # d/dt(A) q_dot
    return M, h, A, c


def _split(spec: ModelSpec, A: sp.Matrix):
    dep = [spec.coordinates.index(q) for q in spec.dependent]
    ind = [spec.coordinates.index(q) for q in spec.independent]
    return dep, ind, A.extract(list(range(A.rows)), dep), A.extract(list(range(A.rows)), ind)


def dependent_velocities(spec: ModelSpec, at: dict | None = None) -> dict:
    """Solve the constraints for the dependent velocities (at ``at`` if given)."""
    A = sp.Matrix(spec.constraints).jacobian(sp.Matrix(spec.velocities))
    if at:
        A = A.subs(at)
    dep, ind, A_dep, A_ind = _split(spec, A)
    qd_ind = sp.Matrix([spec.velocities[i] for i in ind])
    sol = -A_dep.inv() * A_ind * qd_ind
    sol = sol.applyfunc(lambda e: sp.factor(sp.trigsimp(sp.expand(e))))
    return {spec.velocities[i]: sol[k] for k, i in enumerate(dep)}


def _trig_tidy(e: sp.Expr) -> sp.Expr:
    """Simplify a coefficient (parameters and trigonometric functions only)."""
    return sp.factor(sp.trigsimp(sp.factor(e)))


def tidy(e: sp.Expr, variables) -> sp.Expr:
    """Cheap normal form of a rational function of the state.

    The numerator and denominator are expanded as polynomials in
    ``variables`` (and in the trigonometric functions of them) and only their coefficients (small expressions in the
    parameters and in trigonometric functions of constant angles) are
    simplified.  Simplifying small pieces keeps the derivation fast.
    """
    num, den = sp.fraction(sp.together(e))
    out = []
    for part in (num, den):
        part = sp.expand(part)
        # trigonometric functions of the state (a lean angle inside sin/cos) are generators too
        trig = sorted((f for f in part.atoms(sp.sin, sp.cos, sp.tan) if f.free_symbols & set(variables)),
                      key=sp.default_sort_key)
        gens = list(variables) + trig
        poly = sp.Poly(part, *gens)
        out.append(sum((_trig_tidy(c) * sp.Mul(*(v**k for v, k in zip(gens, m))) for m, c in poly.terms()), sp.S.Zero))
    return sp.factor_terms(out[0]) / sp.factor_terms(out[1])


def derive(spec: ModelSpec) -> ReducedSystem:
    """Run the pipeline of the module docstring on ``spec``."""
    M, h, A, c = _lagrange_terms(spec)
    at = dict(spec.cyclic)
    M, h, A, c = (X.subs(at) for X in (M, h, A, c))
    dep, ind, A_dep, A_ind = _split(spec, A)
    A_dep_inv = A_dep.inv().applyfunc(sp.trigsimp)

    qd_ind = sp.Matrix([spec.velocities[i] for i in ind])
    qdd_ind = sp.Matrix([spec.accelerations[i] for i in ind])
    dep_vel = dict(zip((spec.velocities[i] for i in dep), sp.expand(-A_dep_inv * A_ind * qd_ind)))
    # dependent accelerations from the differentiated constraints
    dep_acc = dict(
        zip((spec.accelerations[i] for i in dep), sp.expand(-A_dep_inv * (A_ind * qdd_ind + c)))
    )

    qdd = sp.Matrix(spec.accelerations)
    residual = (M * qdd + h).subs(dep_acc).subs(dep_vel)
    residual = residual.applyfunc(sp.expand)
    r_dep = sp.Matrix([residual[i] for i in dep])
    r_ind = sp.Matrix([residual[i] for i in ind])
    lam = (A_dep_inv.T * r_dep).applyfunc(sp.expand)  # multipliers, implicit in q_ddot_ind
    reduced = (r_ind - A_ind.T * lam).applyfunc(sp.expand)

    variables = list(spec.velocity_state)
    mass = reduced.jacobian(qdd_ind).applyfunc(lambda e: tidy(e, variables))
    forcing = (-reduced.subs({a: 0 for a in qdd_ind})).applyfunc(lambda e: tidy(e, variables))
    leftover = set().union(*(e.free_symbols for e in reduced)) & (
        set(spec.cyclic) | {spec.velocity_of(q) for q in spec.dependent}
    )
    if leftover:
        raise ValueError(f"{spec.name}: reduced equations do not close; they contain {sorted(map(str, leftover))}")

    det = tidy(mass.det(), variables)
    adj = mass.adjugate()
    explicit = sp.Matrix([tidy((adj.row(k) * forcing)[0] / det, variables) for k in range(len(ind))])
    acc_sub = dict(zip(qdd_ind, explicit))
    lam = lam.applyfunc(lambda e: tidy(e, variables + list(qdd_ind)))
    multipliers = lam.subs(acc_sub).applyfunc(lambda e: tidy(e, variables))

    # energy (Jacobi integral) on the constraint manifold
    qd = sp.Matrix(spec.velocities)
    L = spec.lagrangian.subs(at)
    energy = sum(v * sp.diff(L, v) for v in qd) - L
    energy = tidy(energy.subs(dep_vel), variables)

    # pose rates at a general pose
    general = dependent_velocities(spec)
    pose_rates = {q: general.get(spec.velocity_of(q), spec.velocity_of(q)) for q in spec.pose}

    state = spec.state
    accelerations = tuple(qdd_ind)
    system = ReducedSystem(
        spec=spec,
        state=state,
        accelerations=accelerations,
        mass_matrix=mass,
        forcing=forcing,
        explicit=explicit,
        multipliers=multipliers,
        multipliers_implicit=lam,
        energy=energy,
        pose_rates=pose_rates,
    )
    if spec.quasi_velocities:
        system = _with_quasi_velocities(system, at, dep_vel, dep_acc, general)
    return system


def _quasi_rates(spec: ModelSpec, at: dict, dep_vel: dict, dep_acc: dict, acc_sub: dict) -> dict:
    """``d(u)/dt`` of each quasi-velocity at the representative point, in the velocity state."""
    q, qd = spec.coordinates, spec.velocities
    out = {}
    for u, _, expr in spec.quasi_velocities:
        rate = sum((sp.diff(expr, v) * a for v, a in zip(qd, spec.accelerations)), sp.S.Zero)
        rate += sum((sp.diff(expr, c) * v for c, v in zip(q, qd)), sp.S.Zero)
        rate = sp.expand(rate.subs(at)).subs(dep_acc).subs(dep_vel).subs(acc_sub)
        out[u] = sp.expand(rate)
    return out


def _solve_quasi(spec: ModelSpec, dep_vel: dict, at: dict | None = None) -> dict:
    """Replaced velocities as functions of the quasi-velocities (at ``at`` if given, else at a general pose)."""
    eqs, unknowns = [], []
    for u, old, expr in spec.quasi_velocities:
        e = expr.subs(at) if at else expr
        eqs.append(sp.expand(e.subs(dep_vel)) - u)
        unknowns.append(old)
    sol = sp.solve(eqs, unknowns, dict=True)
    if len(sol) != 1:
        raise ValueError(f"{spec.name}: the quasi-velocities do not determine {unknowns} uniquely")
    return {k: sp.factor(sp.trigsimp(v)) for k, v in sol[0].items()}


def _with_quasi_velocities(system: ReducedSystem, at: dict, dep_vel: dict, dep_acc: dict,
                           general: dict) -> ReducedSystem:
    """Rewrite a reduced system on the quasi-velocities of its spec (see :class:`ModelSpec`)."""
    spec = system.spec
    variables = list(spec.state)
    acc_sub = dict(zip(system.accelerations, system.explicit))
    rates = _quasi_rates(spec, at, dep_vel, dep_acc, acc_sub)
    back = _solve_quasi(spec, dep_vel, at)
    new_acc = {old_a: sp.Symbol(f"{u}_dot", real=True) for u, old, _ in spec.quasi_velocities
               for old_a in [spec.acceleration_of(spec.coordinates[spec.velocities.index(old)])]}
    explicit = []
    for a, e in zip(system.accelerations, system.explicit):
        quasi = [u for u, old, _ in spec.quasi_velocities if spec.acceleration_of(
            spec.coordinates[spec.velocities.index(old)]) == a]
        e = rates[quasi[0]] if quasi else e
        explicit.append(tidy(e.subs(back), variables))
    explicit = sp.Matrix(explicit)
    multipliers = system.multipliers.applyfunc(lambda e: tidy(e.subs(back), variables))
    general_back = _solve_quasi(spec, general)
    pose_rates = {q: sp.factor(sp.trigsimp(sp.expand(v.subs(general_back))))
                  for q, v in system.pose_rates.items()}
    return ReducedSystem(
        spec=spec,
        state=spec.state,
        accelerations=tuple(new_acc.get(a, a) for a in system.accelerations),
        mass_matrix=sp.eye(len(explicit)),
        forcing=explicit,
        explicit=explicit,
        multipliers=multipliers,
        multipliers_implicit=multipliers,
        energy=tidy(system.energy.subs(back), variables),
        pose_rates=pose_rates,
    )


def _random_point(symbols, rng: random.Random) -> dict:
    return {s: sp.Rational(rng.randint(-900, 900), 1000) for s in symbols}


def unreduced_accelerations(spec: ModelSpec, values: dict, everything: bool = False) -> tuple:
    """Independent accelerations and multipliers from the full DAE at a numeric point.

    Solves ``[[M, -A^T], [A, 0]] [q_ddot, lambda] = [-h, -c]`` at the
    configuration ``values`` (which must fix every coordinate, including the
    cyclic ones, every parameter, and the independent velocities; the
    dependent velocities are taken from the constraints).  Used to test the
    elimination and the symmetry assumption at arbitrary poses.  With
    ``everything`` the first item holds every acceleration (in the order of
    ``spec.accelerations``) and a third item the dependent velocities.
    """
    M, h, A, c = _lagrange_terms(spec)
    dep_vel = dependent_velocities(spec, at={k: v for k, v in values.items() if k in spec.coordinates})
    dep_vel = {k: v.subs(values) for k, v in dep_vel.items()}
    pt = {**values, **dep_vel}
    n, m = len(spec.coordinates), len(spec.constraints)
    K = sp.zeros(n + m, n + m)
    K[:n, :n] = M.subs(pt)
    K[:n, n:] = -A.T.subs(pt)
    K[n:, :n] = A.subs(pt)
    rhs = sp.Matrix.vstack(-h.subs(pt), -c.subs(pt))
    with mpmath.workdps(30):
        sol = mpmath.lu_solve(mpmath.matrix(K.evalf(30).tolist()), mpmath.matrix(rhs.evalf(30).tolist()))
        sol = [sp.Float(v, 30) for v in sol]
    if everything:
        return sol[:n], list(sol[n:]), dep_vel
    ind = [spec.coordinates.index(q) for q in spec.independent]
    return [sol[i] for i in ind], list(sol[n:])


def check_symmetry(system: ReducedSystem, seed: int = 0, tol: float = 1e-20) -> float:
    """Compare the reduced equations with the unreduced DAE at a random general pose.

    Returns the largest absolute difference of accelerations and multipliers;
    raises ``ValueError`` above ``tol`` (the cyclic coordinates would then not
    be cyclic, or the elimination would be wrong).
    """
    spec = system.spec
    rng = random.Random(seed)
    pt = _random_point(spec.coordinates + tuple(spec.velocity_of(q) for q in spec.independent), rng)
    pt.update({s: sp.Rational(rng.randint(300, 1500), 1000) for s in spec.params})
    if spec.quasi_velocities:
        acc, lam, pt = _quasi_point(spec, pt)
    else:
        acc, lam = unreduced_accelerations(spec, pt)
    red_acc = [e.subs(pt).evalf(30) for e in system.explicit]
    red_lam = [e.subs(pt).evalf(30) for e in system.multipliers]
    err = max(abs(a - b) for a, b in zip(acc + lam, red_acc + red_lam))
    if err > tol:
        raise ValueError(f"{spec.name}: reduced equations differ from the unreduced ones at a general pose by {err}")
    return float(err)


def _quasi_point(spec: ModelSpec, pt: dict) -> tuple:
    """Unreduced quasi-velocity rates at a general pose; ``pt`` gains the quasi-velocity values."""
    acc_all, lam, dep_vel = unreduced_accelerations(spec, pt, everything=True)
    full_pt = {**pt, **dep_vel, **dict(zip(spec.accelerations, acc_all))}
    out = dict(pt)
    quasi_rate = {}
    for u, old, expr in spec.quasi_velocities:
        out[u] = expr.subs(full_pt).evalf(30)
        rate = sum((sp.diff(expr, vel) * acc for vel, acc in zip(spec.velocities, spec.accelerations)), sp.S.Zero)
        rate += sum((sp.diff(expr, c) * vel for c, vel in zip(spec.coordinates, spec.velocities)), sp.S.Zero)
        quasi_rate[spec.acceleration_of(spec.coordinates[spec.velocities.index(old)])] = rate.subs(full_pt).evalf(30)
    ind = [spec.coordinates.index(q) for q in spec.independent]
    acc = [quasi_rate.get(spec.accelerations[i], acc_all[i]) for i in ind]
    return acc, lam, out
