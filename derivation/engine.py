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

import keyword
import math
import random
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

import mpmath

import sympy as sp

from . import dag, input_slots, names
from .names import t


#: admissible values of a parameter, as written into the generated modules
PARAM_DOMAINS = ("positive", "real")
#: the fidelities a model may declare a validity domain for
_FIDELITY_NAMES = ("full", "reduced", "amplitude")


class ModelSpecError(ValueError):
    """A :class:`ModelSpec` violates its contract; the message lists every problem and where the spec was built."""


def _caller_location() -> str:
    """``file:line`` of the first frame outside this module (where a spec was constructed)."""
    frame = sys._getframe(1)
    here = (__file__, str(Path(__file__).with_name("multibody.py")))  # and the front end that builds specs
    while frame is not None and (frame.f_code.co_filename in (*here, "<string>")
                                 or frame.f_code.co_filename.endswith("dataclasses.py")):
        frame = frame.f_back
    if frame is None:
        return "<unknown>"
    return f"{frame.f_code.co_filename}:{frame.f_lineno}"


@dataclass(frozen=True, kw_only=True)
class ModelSpec:
    """A mechanical model as data: what :func:`derive` and the emitter need, nothing derived.

    The contract, checked when the spec is built (every violation is
    collected and raised once as :class:`ModelSpecError`, naming the file
    and line where the spec was constructed):

    1. ``name`` (str): an ASCII Python identifier, not a keyword; the
       generated modules are ``<name>_<fidelity>.py``.  The names of the
       symbols are data (:mod:`.names`): any printable name without quotes
       or backslashes works (``q``, ``t``, ``lambda``, ``a b``, ``κ``), the
       generated code writes a safe identifier for it and reports the name
       itself; two names equal after Unicode normalization (NFKC) are refused.
    2. ``coordinates``, ``velocities`` (tuples of SymPy symbols): the
       generalized coordinates ``q`` and their time derivatives ``q_dot``
       as plain symbols, one velocity per coordinate, all distinct.
       ``accelerations`` (optional): the second derivatives; default
       symbols ``<q>_ddot``.
    3. ``params`` (tuple of symbols): the parameters in the order of the
       parameter vector ``p``.  Their admissible values come from the SymPy
       assumptions (``positive=True`` -> ``"positive"``, otherwise
       ``"real"``), or from ``param_domains`` ({symbol: "positive"|"real"}).
    4. ``lagrangian`` (expression): the unconstrained Lagrangian (any
       consistent normalization, e.g. per unit mass), quadratic in the
       velocities.  Every symbol in it is a coordinate, a velocity, a
       parameter or the time ``knifeedge.derive.t`` ("every symbol
       declared").  The time may appear in the Lagrangian, the constraints,
       the forces and the dissipation: the generated right-hand side then
       reads the integrator's time, and ``energy``, ``multipliers``,
       ``pose_rates`` and the powers take it as a third argument
       (``TIME_DEPENDENT`` in the module); such a model has no small-angle
       fidelities.
    5. ``constraints`` (tuple of expressions, each equal to zero): affine
       in the velocities, ``sum_i a_ji(q, t) q_dot_i + b_j(q, t) = 0``
       (``b`` and a time in ``a`` make them rheonomic: a prescribed motion
       is one); ``constraint_labels`` name them (default ``c1, c2, ...``).
    6. ``dependent`` (tuple of coordinates): one per constraint and then
       one per holonomic constraint, whose velocities the constraints
       determine (the block of the constraint matrix on them must be
       invertible, at the representative point and along a run).
       ``holonomic`` (tuple of expressions ``f(q, t)``, each equal to zero;
       ``holonomic_labels``, default ``h1, h2, ...``): position constraints,
       entered as their time derivatives ``df/dq q_dot + df/dt = 0`` with a
       multiplier each (named after ``constraint_labels``); their coordinates
       must not be cyclic.  The constraints are held during a run by the
       rates of the dependent coordinates kept in the state, which solve
       ``df/dq q_dot + df/dt = -holonomic_rate * f`` (so ``f`` decays as
       ``exp(-holonomic_rate t)`` instead of drifting; on ``f = 0`` the
       equations are unchanged): ``holonomic_rate`` is a non-negative
       number or expression of the parameters, per unit of time (default
       1; choose about the model's slowest natural frequency, e.g.
       ``sqrt(g/l)``; far above its fastest one the equations become stiff;
       0 leaves ``f`` to drift).  ``holonomic_residual(s, p)`` gives ``f``
       along a run.
    7. ``cyclic`` ({coordinate: value}): coordinates the reduced dynamics
       does not depend on (the symmetry), with the representative value at
       which the equations are evaluated.  A dependent coordinate that is
       not cyclic stays in the closed state (after the tilts; its rate from
       the constraints).  :func:`check_symmetry` confirms the symmetry at a random
       general pose after the derivation (``knifeedge derive`` runs it).
    8. ``small`` (tuple of non-cyclic independent coordinates): the tilts,
       scaled as small by the ``reduced`` fidelity; a model with tilts also
       gets the ``amplitude`` fidelity when it has one spin rate and no
       non-conservative forces.
    9. ``pose`` (tuple of cyclic coordinates) and ``pose_description``: the
       coordinates integrated by quadrature when a pose is asked for, and
       what they mean.  A potential in a cyclic coordinate (the incline's
       ``g sin(alpha) x``: a constant force keeps the equations symmetric)
       is part of ``energy``, which then reads the pose-extended state
       (``ENERGY_NEEDS_POSE``); such a coordinate must be in ``pose``.
    10. ``units`` ({symbol or name: unit string}) for coordinates,
        parameters and quasi-velocities, ``time_unit`` (default ``"time"``);
        a rate has the unit ``<unit>/<time_unit>``.  Default ``"1"``.
    11. ``defaults`` ({symbol or name: number}): a default value for every
        parameter and every entry of the closed state (missing states default
        to 0; missing parameters are an error when any default is given).
    12. ``reversal_events`` (tuple of closed-state symbols or event names):
        the zero crossings reported as ``reversal_times`` (may be empty).
        ``events`` ({name: expression}) are scalar functions of the closed
        state and the parameters whose zero crossings may be events.
    13. ``validity`` ({fidelity: {state symbol or name: largest |value|}})
        and ``validity_description``: where each fidelity holds.
    14. ``dissipation`` (Rayleigh function ``R(q, q_dot) >= 0``, generalized
        force ``-dR/dq_dot``) and ``forces`` (one generalized force per
        coordinate): non-conservative forces.  The generated module then
        gives ``power_dissipated(s, p)``, the rate of loss of ``energy``
        (a driving force, e.g. a torque ``tau0 sin t``, makes it negative).
        A Lagrangian with the time or rheonomic constraints give
        ``power_input(s, p, t) = -dL/dt - lambda . b``, the rate of gain:
        ``energy(t) = energy(t0) + integral (power_input - power_dissipated)``.
    15. ``quasi_velocities``: ``(symbol, replaced_velocity, expression)``
        triples (see the module docstring of :mod:`.engine`); ``state_order``
        an optional permutation of the closed state.
    16. ``extra_source`` (str) and ``exports`` (names it defines): plain
        ``math``/``numpy``/``numba`` Python appended to every generated
        module of the model (model-specific helpers such as presets).
    17. ``drawing``: an optional :class:`~knifeedge.derive.drawing.Drawing`
        (how ``knifeedge animate`` draws the model).
    18. ``inputs`` (tuple of symbols): quantities given at run time
        (``simulate(..., inputs={"tau": value, samples or function})``), e.g.
        a control torque.  They may appear in the ``forces``, the
        ``dissipation`` and the ``constraints`` (not in the Lagrangian, the
        holonomic constraints or the events); a constraint holding one also
        reads its rate (:attr:`input_rates`).  The module is then
        ``TIME_DEPENDENT`` and its functions read the inputs from slots
        appended to ``p`` (``INPUT_NAMES``, :mod:`.inputs`).  The power of the
        input-dependent part of the forces is part of ``power_input``, not of
        ``power_dissipated``.
    19. ``elimination``: ``"symbolic"`` (the accelerations and multipliers in
        closed form), ``"numeric"`` (the emitted right-hand side solves
        ``[[M, -A^T], [A, 0]] [q_ddot, lambda] = [f, -c]`` at every call) or
        ``"auto"`` (numeric past :data:`NUMERIC_FROM` independent accelerations,
        see :func:`choose_elimination`).
    """

    name: str
    coordinates: tuple
    velocities: tuple
    lagrangian: sp.Expr
    constraints: tuple
    dependent: tuple
    params: tuple
    accelerations: tuple = ()
    constraint_labels: tuple = ()
    holonomic: tuple = ()
    holonomic_labels: tuple = ()
    holonomic_rate: object = 1
    cyclic: dict = field(default_factory=dict)
    small: tuple = ()
    pose: tuple = ()
    pose_description: str = ""
    description: str = ""
    units: dict = field(default_factory=dict)
    time_unit: str = "time"
    param_domains: dict = field(default_factory=dict)
    defaults: dict = field(default_factory=dict)
    reversal_events: tuple = ()
    events: dict = field(default_factory=dict)
    validity: dict = field(default_factory=dict)
    validity_description: str = ""
    dissipation: sp.Expr | None = None
    forces: tuple = ()
    quasi_velocities: tuple = ()
    state_order: tuple = ()
    extra_source: str = ""
    exports: tuple = ()
    drawing: object = None
    #: families of steady motions (:class:`~knifeedge.derive.steady.Steady`), written into the modules
    steady: tuple = ()
    elimination: str = "auto"
    inputs: tuple = ()
    #: ``file:line`` where the spec was constructed (set automatically; named in every error)
    defined_at: str = field(default="", init=False, compare=False)

    def __post_init__(self):
        set_ = lambda k, v: object.__setattr__(self, k, v)  # noqa: E731 (frozen dataclass)
        set_("defined_at", _caller_location())
        kinds = []
        for k in ("coordinates", "velocities", "constraints", "dependent", "params", "accelerations",
                  "constraint_labels", "holonomic", "holonomic_labels", "small", "pose", "reversal_events", "forces", "quasi_velocities",
                  "state_order", "exports", "inputs"):
            v = getattr(self, k)
            if isinstance(v, (list, sp.Matrix)):
                set_(k, tuple(v))
            elif not isinstance(v, tuple):
                one = f"; for one entry write `{k}=({v},)`" if isinstance(v, sp.Basic) else ""
                kinds.append(f"`{k}` must be a tuple or a list, got {type(v).__name__} {v!r}{one}")
        kinds += [f"`{k}` must be a dict, got {type(getattr(self, k)).__name__} {getattr(self, k)!r}"
                  for k in ("cyclic", "units", "param_domains", "defaults", "events", "validity")
                  if not isinstance(getattr(self, k), dict)]
        if kinds:
            raise ModelSpecError(self.error_message(kinds))
        if not self.accelerations and all(isinstance(q, sp.Symbol) for q in self.coordinates):
            set_("accelerations", tuple(sp.Symbol(f"{q}_ddot", real=True) for q in self.coordinates))
        if not self.constraint_labels:
            set_("constraint_labels", tuple(f"c{i + 1}" for i in range(len(self.constraints))))
        if not self.holonomic_labels:
            set_("holonomic_labels", tuple(f"h{i + 1}" for i in range(len(self.holonomic))))
        problems = _contract_problems(self)
        if problems:
            raise ModelSpecError(self.error_message(problems))

    def error_message(self, problems) -> str:
        """The message of a :class:`ModelSpecError`: every problem, numbered, and where the spec was built."""
        if isinstance(problems, str):
            problems = [problems]
        lines = [f"model {self.name!r} (ModelSpec built at {self.defined_at}): "
                 f"{len(problems)} problem{'s' if len(problems) > 1 else ''}"]
        lines += [f"  {i + 1}. {p}" for i, p in enumerate(problems)]
        return "\n".join(lines)

    @property
    def velocity_constraints(self) -> tuple:
        """``constraints``, then each holonomic constraint differentiated: ``df/dq q_dot + df/dt``."""
        return tuple(self.constraints) + tuple(
            sum((sp.diff(f, q) * v for q, v in zip(self.coordinates, self.velocities)), sp.diff(f, t))
            for f in self.holonomic)

    @property
    def input_rates(self) -> tuple:
        """The rate ``d(u)/dt`` of each input, as the emitter's own symbol ``_rate_<u>`` (read by constraints)."""
        return tuple(names.Own(f"_rate_{names.identifier(str(u))}", real=True) for u in self.inputs)

    def time_derivative(self, e: sp.Expr) -> sp.Expr:
        """The explicit time derivative of ``e``: ``de/dt + sum_u de/du du/dt`` over the :attr:`inputs`."""
        return sp.diff(e, t) + sum((sp.diff(e, u) * r for u, r in zip(self.inputs, self.input_rates)), sp.S.Zero)

    @property
    def multiplier_labels(self) -> tuple:
        """Labels of the multipliers: ``constraint_labels``, then ``holonomic_labels``."""
        return tuple(self.constraint_labels) + tuple(self.holonomic_labels)

    @property
    def kept(self) -> tuple:
        """Dependent coordinates that are not cyclic: they stay in the closed state, their rates from the constraints."""
        return tuple(q for q in self.dependent if q not in self.cyclic)

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
        return tilts + self.kept + tuple(self.velocity_of(q) for q in tilts) + tuple(
            self.velocity_of(q) for q in spins
        )

    @property
    def natural_state(self) -> tuple:
        """Closed state in the engine's order: :attr:`velocity_state` with the quasi-velocities in place."""
        replace_by = {old: new for new, old, _ in self.quasi_velocities}
        return tuple(replace_by.get(s, s) for s in self.velocity_state)

    @property
    def state(self) -> tuple:
        """Closed state: :attr:`natural_state`, in ``state_order`` when given."""
        return tuple(self.state_order) if self.state_order else self.natural_state

    @property
    def rate_pairs(self) -> tuple:
        """``(coordinate, rate)`` pairs of the closed state."""
        return tuple((q, self.velocity_of(q)) for q in self.independent if q not in self.cyclic)

    @property
    def dissipative(self) -> bool:
        return self.dissipation is not None or bool(self.forces)

    def lookup(self, mapping: dict, symbol, default=None):
        """``mapping[symbol]`` accepting keys given as symbols or as names."""
        name = str(symbol)
        for k, v in mapping.items():
            if str(k) == name:
                return v
        return default


def _symbols_ok(values, what: str, problems: list) -> bool:
    bad = [v for v in values if not isinstance(v, sp.Symbol)]
    if bad:
        problems.append(f"`{what}` must be SymPy symbols; got {bad}")
        return False
    dup = sorted({str(v) for v in values if list(values).count(v) > 1})
    if dup:
        problems.append(f"`{what}` has repeated entries {dup}")
        return False
    return True


def _contract_problems(spec: ModelSpec) -> list:
    """Every violation of the :class:`ModelSpec` contract, as sentences.

    Three stages, each stopping the list when it finds problems (the next one relies on it): the name and the
    symbols with their counts; the declarations and equations on the coordinates; what refers to the closed state.
    """
    problems = _name_problems(spec)
    symbols = _symbol_problems(spec)
    if symbols is not None:
        return problems + symbols
    problems += _naming_problems(spec)
    problems += _option_problems(spec)
    problems += _text_problems(spec)
    problems += _lagrangian_problems(spec)
    problems += _constraint_problems(spec)
    problems += _holonomic_problems(spec)
    problems += _rate_problems(spec)
    problems += _dependent_problems(spec)
    problems += _cyclic_problems(spec)
    problems += _small_and_pose_problems(spec)
    problems += _param_domain_problems(spec)
    if problems:
        return problems
    # the closed state and what refers to it
    try:
        natural = spec.natural_state
    except Exception as exc:  # noqa: BLE001 -- reported with the others
        problems.append(f"cannot form the closed state: {exc}")
        return problems
    state_names = [str(s) for s in natural]
    problems += _state_order_and_unit_problems(spec, state_names)
    problems += _event_problems(spec, natural, state_names)
    problems += _default_problems(spec, state_names)
    problems += _validity_problems(spec, state_names)
    problems += _force_problems(spec)
    problems += _export_problems(spec)
    return problems


def _name_problems(spec: ModelSpec) -> list:
    """The model's ``name``: it names the generated modules, so an ASCII identifier and not a keyword."""
    if not isinstance(spec.name, str) or not spec.name.isidentifier() or not spec.name.isascii() \
            or keyword.iskeyword(spec.name):
        return [f"`name` must be an ASCII Python identifier and not a keyword (it names the generated "
                f"modules and their compiled code), got {spec.name!r}"]
    return []


def _symbol_problems(spec: ModelSpec) -> list | None:
    """The declared symbols and their counts; ``None`` when they are sound (the checks after rely on them)."""
    problems: list = []
    ok = _symbols_ok(spec.coordinates, "coordinates", problems)
    ok &= _symbols_ok(spec.velocities, "velocities", problems)
    ok &= _symbols_ok(spec.params, "params", problems)
    ok &= _symbols_ok(spec.accelerations, "accelerations", problems)
    ok &= _symbols_ok(spec.inputs, "inputs", problems)
    if not ok:
        return problems
    n = len(spec.coordinates)
    if len(spec.velocities) != n or len(spec.accelerations) != n:
        return [f"`velocities` and `accelerations` need one entry per coordinate ({n}); got "
                f"{len(spec.velocities)} and {len(spec.accelerations)}"]
    return None


def _naming_problems(spec: ModelSpec) -> list:
    """Names used twice, names the generated code cannot take, and names of the inputs' parameter slots."""
    problems: list = []
    names_ = [str(s) for s in spec.coordinates + spec.velocities + spec.params + tuple(u for u, _, _ in spec.quasi_velocities)
              + spec.inputs]
    clash = sorted({x for x in names_ if names_.count(x) > 1})
    if clash:
        problems.append(f"the names {clash} are used by more than one coordinate, velocity, parameter or input")
    problems += names.problems(names_)
    taken = sorted(set(names_) & set(input_slots.slot_names(spec.inputs))) if spec.inputs else []
    if taken:
        problems.append(f"the names {taken} are those of the inputs' parameter slots in the generated code; "
                        f"rename them")
    return problems


def _option_problems(spec: ModelSpec) -> list:
    """The ``elimination`` option, and its combination with ``quasi_velocities``."""
    if spec.elimination not in ("auto", "symbolic", "numeric"):
        return [f"`elimination` must be 'auto', 'symbolic' or 'numeric', got {spec.elimination!r}"]
    if spec.elimination == "numeric" and spec.quasi_velocities:
        return ["`elimination='numeric'` does not take `quasi_velocities` (they are written in closed form); "
                "drop one of the two"]
    return []


def _text_problems(spec: ModelSpec) -> list:
    """Descriptions, labels and units the generated module's documentation cannot show."""
    texts = {"description": spec.description, "pose_description": spec.pose_description,
             **{f"label {x!r}": x for x in (*spec.constraint_labels, *spec.holonomic_labels)},
             **{f"unit of {k}": u for k, u in spec.units.items()}}
    bad = sorted(k for k, x in texts.items() if isinstance(x, str) and ('"""' in x or "\\" in x))
    if bad:
        return [f"the texts {bad} hold triple quotes or a backslash, which the generated module's "
                f"documentation cannot show; remove them"]
    return []


def _declared(spec: ModelSpec) -> set:
    """The symbols an equation may hold: the coordinates, velocities, parameters and the time."""
    return set(spec.coordinates) | set(spec.velocities) | set(spec.params) | {t}


def _driven(spec: ModelSpec) -> set:
    """The symbols of the equations where the inputs may appear: :func:`_declared` and the inputs."""
    return _declared(spec) | set(spec.inputs)


def _expression_problem(spec: ModelSpec, e, what: str, allowed: set | None = None) -> str | None:
    """The problem of expression ``e`` (named ``what``) holding symbols outside ``allowed``, or ``None``.

    ``allowed`` defaults to :func:`_declared`, and then an input is refused with its own sentence.
    """
    check_inputs = allowed is None
    if allowed is None:
        allowed = _declared(spec)
    if not isinstance(e, sp.Basic):
        return f"{what} must be a SymPy expression, got {type(e).__name__}"
    if check_inputs and e.free_symbols & set(spec.inputs):
        return (f"{what} contains the inputs {sorted(map(str, e.free_symbols & set(spec.inputs)))}; "
                f"an input may appear in the `forces`, the `dissipation` and the `constraints` only "
                f"(write a potential that depends on it as a generalized force)")
    extra = e.free_symbols - allowed
    if extra:
        hint = ("; the time is `knifeedge.derive.t`" if "t" in map(str, extra) and t in allowed
                else "; only the right-hand side, the forces, the Lagrangian and the constraints may depend on "
                     "the time" if t in e.free_symbols else "")
        return (f"{what} contains undeclared symbols {sorted(map(str, extra))} "
                f"(declare them as coordinates, velocities or params{hint})")
    if e.atoms(sp.Derivative) or any(isinstance(f, sp.core.function.AppliedUndef) for f in e.atoms(sp.Function)):
        return f"{what} contains functions of time or derivatives; use plain symbols for q and q_dot"
    return None


def _lagrangian_problems(spec: ModelSpec) -> list:
    """The Lagrangian: declared symbols only, and at most quadratic in the velocities."""
    bad = _expression_problem(spec, spec.lagrangian, "the `lagrangian`")
    if bad is not None:
        return [bad]
    if _velocity_degree(spec.lagrangian, set(spec.velocities)) > 2:
        hess = [sp.diff(spec.lagrangian, v, w) for v in spec.velocities for w in spec.velocities]
        if any(sp.diff(e, v) != 0 for e in hess for v in spec.velocities):
            return ["the `lagrangian` must be at most quadratic in the velocities "
                    "(its mass matrix d2L/dq_dot2 may depend on the coordinates only)"]
    return []


def _constraint_problems(spec: ModelSpec) -> list:
    """The velocity constraints: affine in the velocities, one label each."""
    problems: list = []
    qd = sp.Matrix(spec.velocities)
    for j, c in enumerate(spec.constraints):
        label = spec.constraint_labels[j] if j < len(spec.constraint_labels) else f"c{j + 1}"
        bad = _expression_problem(spec, c, f"constraint {label!r}", allowed=_driven(spec))
        if bad is not None:
            problems.append(bad)
            continue
        lin = sp.Matrix([c]).jacobian(qd)
        if sp.expand(c - (lin * qd)[0]).free_symbols & set(spec.velocities) or any(
                e.free_symbols & set(spec.velocities) for e in lin):
            problems.append(f"constraint {label!r} must be affine in the velocities, a(q, t) q_dot + b(q, t) = 0; "
                            f"got {c}")
    if len(spec.constraint_labels) != len(spec.constraints):
        problems.append(f"`constraint_labels` needs one label per constraint ({len(spec.constraints)})")
    return problems


def _holonomic_problems(spec: ModelSpec) -> list:
    """The holonomic constraints: functions of the kept coordinates and the time, one label each."""
    problems: list = []
    for j, f in enumerate(spec.holonomic):
        label = spec.holonomic_labels[j] if j < len(spec.holonomic_labels) else f"h{j + 1}"
        bad = _expression_problem(spec, f, f"holonomic constraint {label!r}")
        if bad is not None:
            problems.append(bad)
            continue
        if f.free_symbols & set(spec.velocities):
            problems.append(f"holonomic constraint {label!r} must be a function f(q, t) of the coordinates (and the "
                            f"time) equal to zero; it holds velocities: write it in `constraints` instead")
        elif f.free_symbols & set(spec.cyclic):
            problems.append(f"holonomic constraint {label!r} holds the cyclic coordinates "
                            f"{sorted(map(str, f.free_symbols & set(spec.cyclic)))}, which the closed state does not "
                            f"keep; remove them from `cyclic`")
    if len(spec.holonomic_labels) != len(spec.holonomic):
        problems.append(f"`holonomic_labels` needs one label per holonomic constraint ({len(spec.holonomic)})")
    return problems


def _dependent_problems(spec: ModelSpec) -> list:
    """The ``dependent`` coordinates: coordinates, one per constraint, and at least one left independent."""
    not_coord = [q for q in spec.dependent if q not in spec.coordinates]
    if not_coord:
        return [f"`dependent` entries {not_coord} are not coordinates"]
    if len(spec.dependent) != len(spec.constraints) + len(spec.holonomic):
        return [f"`dependent` must name one coordinate per constraint and holonomic constraint "
                f"({len(spec.constraints) + len(spec.holonomic)}), "
                f"got {len(spec.dependent)}"]
    if not spec.independent:
        return [f"every velocity is constrained ({len(spec.constraints)} constraints on {len(spec.coordinates)} "
                f"coordinates, all `dependent`): nothing is left to move; a model needs at least one independent "
                f"coordinate (fewer constraints than coordinates)"]
    return []


def _cyclic_problems(spec: ModelSpec) -> list:
    """The ``cyclic`` mapping: coordinates to their representative values."""
    if not isinstance(spec.cyclic, dict):
        return ["`cyclic` must be a mapping {coordinate: representative value}"]
    bad = [q for q in spec.cyclic if q not in spec.coordinates]
    if bad:
        return [f"`cyclic` entries {bad} are not coordinates"]
    return []


def _small_and_pose_problems(spec: ModelSpec) -> list:
    """The ``small`` coordinates (time-independent equations, independent non-cyclic coordinates) and the
    ``pose`` (cyclic coordinates)."""
    problems: list = []
    timed = [what for what, e in (("lagrangian", spec.lagrangian), ("constraints", spec.velocity_constraints),
                                  ("forces", spec.forces), ("dissipation", spec.dissipation))
             if any(isinstance(x, sp.Basic) and x.has(t) for x in (e if isinstance(e, tuple) else (e,)))]
    if spec.inputs:
        timed.append("inputs")
    if timed and spec.small:
        problems.append(f"the small-angle fidelities (`small`) need equations that do not depend on the time; the "
                        f"{', '.join(timed)} do: leave `small` empty")
    bad = [q for q in spec.small if q not in spec.coordinates or q in spec.cyclic or q in spec.dependent]
    if bad:
        problems.append(f"`small` entries {bad} must be independent, non-cyclic coordinates")
    bad = [q for q in spec.pose if q not in spec.cyclic]
    if bad:
        problems.append(f"`pose` entries {bad} must be cyclic coordinates")
    return problems


def _param_domain_problems(spec: ModelSpec) -> list:
    """The ``param_domains``: each one of :data:`PARAM_DOMAINS`."""
    problems: list = []
    for q in spec.params:
        dom = spec.lookup(spec.param_domains, q)
        if dom is not None and dom not in PARAM_DOMAINS:
            problems.append(f"`param_domains` of {q} must be one of {PARAM_DOMAINS}, got {dom!r}")
    return problems


def _state_order_and_unit_problems(spec: ModelSpec, state_names: list) -> list:
    """The ``state_order`` (a permutation of the closed state) and the ``units`` (strings, of known names)."""
    problems: list = []
    if spec.state_order and sorted(map(str, spec.state_order)) != sorted(state_names):
        problems.append(f"`state_order` must be a permutation of the closed state {tuple(state_names)}, "
                        f"got {tuple(map(str, spec.state_order))}")
    known = set(map(str, spec.coordinates + spec.velocities + spec.params)) | set(state_names)
    bad = sorted(str(k) for k in spec.units if str(k) not in known)
    if bad:
        problems.append(f"`units` names {bad} that are not coordinates, states or parameters")
    bad = [k for k, u in spec.units.items() if not isinstance(u, str)]
    if bad:
        problems.append(f"`units` must be strings; not for {bad}")
    return problems


def _event_problems(spec: ModelSpec, natural, state_names: list) -> list:
    """The ``events`` (functions of the closed state and the parameters) and the ``reversal_events``."""
    problems: list = []
    allowed = set(natural) | set(spec.params)
    for name, e in spec.events.items():
        if not str(name).isidentifier():
            problems.append(f"event name {name!r} must be an identifier")
        bad = _expression_problem(spec, e, f"event {name!r}", allowed=allowed)
        if bad is not None:
            problems.append(bad)
    for ev in spec.reversal_events:
        if str(ev) not in state_names and str(ev) not in map(str, spec.events):
            problems.append(f"`reversal_events` entry {ev} is neither a closed-state variable {tuple(state_names)} "
                            f"nor an event of `events`")
    return problems


def _default_problems(spec: ModelSpec, state_names: list) -> list:
    """The ``defaults``: of known names, every parameter, finite numbers, positive in a positive domain."""
    if not spec.defaults:
        return []
    problems: list = []
    p_names = [str(q) for q in spec.params]
    bad = sorted(str(k) for k in spec.defaults if str(k) not in p_names + state_names)
    if bad:
        problems.append(f"`defaults` names {bad} that are neither parameters nor closed-state variables")
    missing = [n_ for n_ in p_names if n_ not in map(str, spec.defaults)]
    if missing:
        problems.append(f"`defaults` lacks the parameters {missing}")
    for k, v in spec.defaults.items():
        try:
            fv = float(v)
        except (TypeError, ValueError):
            problems.append(f"default of {k} must be a number, got {v!r}")
            continue
        if not math.isfinite(fv):
            problems.append(f"default of {k} must be finite, got {v!r}")
            continue
        if str(k) in p_names and _param_domain(spec, sp.Symbol(str(k))) == "positive" and not fv > 0:
            problems.append(f"default of {k} must be positive (its domain), got {v!r}")
    return problems


def _validity_problems(spec: ModelSpec, state_names: list) -> list:
    """The ``validity`` bounds: per fidelity, finite positive bounds of closed-state variables."""
    problems: list = []
    for fid, bounds in spec.validity.items():
        if fid not in _FIDELITY_NAMES:
            problems.append(f"`validity` key {fid!r} is not a fidelity {_FIDELITY_NAMES}")
            continue
        bad = sorted(str(k) for k in bounds if str(k) not in state_names)
        if bad:
            problems.append(f"`validity[{fid!r}]` names {bad} that are not closed-state variables")
        bad = sorted(str(k) for k, v in bounds.items() if not _finite_positive(v))
        if bad:
            problems.append(f"`validity[{fid!r}]` bounds of {bad} must be finite positive numbers (leave a state "
                            f"out for no bound)")
    return problems


def _force_problems(spec: ModelSpec) -> list:
    """The ``dissipation`` function and the generalized ``forces`` (one per coordinate); both may hold inputs."""
    problems: list = []
    if spec.dissipation is not None:
        bad = _expression_problem(spec, spec.dissipation, "the `dissipation` function", allowed=_driven(spec))
        if bad is not None:
            problems.append(bad)
    if spec.forces:
        n = len(spec.coordinates)
        if len(spec.forces) != n:
            problems.append(f"`forces` needs one generalized force per coordinate ({n}), got {len(spec.forces)}")
        for q, f in zip(spec.coordinates, spec.forces):
            bad = _expression_problem(spec, sp.sympify(f), f"the generalized force on {q}", allowed=_driven(spec))
            if bad is not None:
                problems.append(bad)
    return problems


def _export_problems(spec: ModelSpec) -> list:
    """The ``exports``: helpers defined at the top level of ``extra_source``."""
    problems: list = []
    if spec.exports and not spec.extra_source:
        problems.append("`exports` names helpers but `extra_source` is empty")
    for name in spec.exports:
        if spec.extra_source and not re.search(rf"^(def |class )?{re.escape(name)}\b", spec.extra_source, re.M):
            problems.append(f"`exports` entry {name!r} is not defined at the top level of `extra_source`")
    return problems


def _velocity_degree(e: sp.Expr, velocities: set) -> float:
    """An upper bound of the degree of ``e`` as a polynomial in ``velocities`` (``inf`` where they enter otherwise).

    One pass over the expression tree: sums take the largest degree, products the sum, integer powers the
    multiple.  A bound of 2 proves a Lagrangian quadratic without differentiating it (the Whipple bicycle's 512
    third derivatives took about a minute); above 2 the caller checks exactly (terms may cancel).
    """
    memo: dict = {}

    def degree(x):
        if x in memo:
            return memo[x]
        if x.is_Symbol:
            out = 1 if x in velocities else 0
        elif x.is_Atom:
            out = 0
        elif x.is_Add:
            out = max(degree(a) for a in x.args)
        elif x.is_Mul:
            out = sum(degree(a) for a in x.args)
        elif x.is_Pow and x.exp.is_Integer and x.exp >= 0:
            out = degree(x.base) * int(x.exp)
        else:
            out = math.inf if any(degree(a) for a in x.args) else 0
        memo[x] = out
        return out

    return degree(sp.sympify(e))


def _rate_problems(spec: ModelSpec) -> list:
    """``holonomic_rate``: a real number >= 0 or an expression of the parameters that is not negative."""
    try:
        rate = sp.sympify(spec.holonomic_rate, strict=True)
    except (sp.SympifyError, TypeError):
        rate = None
    if rate is None or not isinstance(rate, sp.Expr) or rate.free_symbols - set(spec.params) \
            or rate.is_extended_real is False or rate.is_negative or rate.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        return [f"`holonomic_rate` must be a number >= 0 or an expression of the parameters (a rate per unit of "
                f"time, e.g. `sqrt(g/l)`), got {spec.holonomic_rate!r}; write it with the symbols of `params`"]
    return []


def held_rates(spec: ModelSpec, at: dict, dep_vel: dict, A_dep_inv: sp.Matrix, variables) -> dict:
    """Rates of the kept dependent coordinates: ``df/dq q_dot + df/dt = -holonomic_rate f`` for the holonomic rows.

    ``dep_vel`` solves the velocity constraints (``f`` constant); the correction ``-A_dep^-1 [0, rate f]``
    makes ``f`` decay along the run and vanishes on ``f = 0``.  Holonomic constraints hold no cyclic
    coordinate, so only the kept rates are corrected.
    """
    rate = sp.sympify(spec.holonomic_rate)
    out = {q: dep_vel[spec.velocity_of(q)] for q in spec.kept}
    if spec.holonomic and rate != 0:
        e = sp.Matrix([0] * len(spec.constraints) + [rate * f.subs(at) for f in spec.holonomic])
        delta = -A_dep_inv * e
        for k, q in enumerate(spec.dependent):
            if q in out:
                out[q] += delta[k]
    return {q: tidy(e, variables) for q, e in out.items()}


def _finite_positive(v) -> bool:
    try:
        return math.isfinite(float(v)) and float(v) > 0
    except (TypeError, ValueError):
        return False


def _param_domain(spec: ModelSpec, q) -> str:
    """``"positive"`` or ``"real"``: ``param_domains`` if given, else the symbol's SymPy assumptions."""
    dom = spec.lookup(spec.param_domains, q)
    if dom is not None:
        return dom
    sym = next((s for s in spec.params if str(s) == str(q)), q)
    return "positive" if sym.is_positive else "real"


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
    #: rate of loss of ``energy`` by the non-conservative forces, ``-q_dot . Q`` (``None`` if conservative)
    power: sp.Expr | None = None
    #: rate of gain of ``energy`` by the explicit time and the rheonomic constraints (``None`` if neither)
    power_input: sp.Expr | None = None
    #: rate of each dependent coordinate kept in the state (``spec.kept``), from the constraints
    dependent_rates: dict = field(default_factory=dict)
    #: ``None`` (closed form), or the :class:`Kkt` the emitted right-hand side solves at every call; ``explicit``
    #: then holds the acceleration symbols themselves and ``multipliers`` placeholder symbols
    kkt: "Kkt | None" = None

    @property
    def time_dependent(self) -> bool:
        """The equations depend on the time explicitly (``knifeedge.derive.t``)."""
        exprs = [*self.explicit, *self.multipliers, *(self.kkt.exprs() if self.kkt else ()), self.energy,
                 *self.pose_rates.values(),
                 *self.dependent_rates.values(), *self.spec.holonomic,
                 *([self.power] if self.power is not None else [])]
        return self.power_input is not None or any(sp.sympify(e).has(t) for e in exprs)

    def state_rhs(self) -> list:
        """Right-hand side of ``d(state)/dt`` as a list of expressions, aligned with :attr:`state`."""
        spec = self.spec
        tilts = [q for q in spec.independent if q not in spec.cyclic]
        spins = [q for q in spec.independent if q in spec.cyclic]
        rates = [spec.velocity_of(q) for q in tilts] + [self.dependent_rates[q] for q in spec.kept]
        # ``explicit`` follows the order of ``spec.independent``, which may interleave tilts and spins
        natural = rates + [self.explicit[spec.independent.index(q)] for q in tilts + spins]
        by_name = dict(zip(map(str, spec.natural_state), natural))
        return [by_name[str(s)] for s in self.state]


def _lagrange_terms(spec: ModelSpec, fast: bool = False):
    """Mass matrix ``M``, velocity/potential terms ``h`` and constraint data.

    ``fast``: differentiate the Lagrangian by :func:`.dag.derivative` (equal, not always in ``sp.diff``'s form:
    for a numeric elimination, whose code is not the paper's closed form)."""
    q, qd = sp.Matrix(spec.coordinates), sp.Matrix(spec.velocities)
    L = spec.lagrangian
    if fast:
        p_mom = sp.Matrix(dag.gradient(L, qd))
        M = dag.jacobian(p_mom, qd)
        h = dag.jacobian(p_mom, q) * qd - sp.Matrix(dag.gradient(L, q))
    else:
        p_mom = sp.Matrix([sp.diff(L, v) for v in qd])
        M = p_mom.jacobian(qd)
        h = p_mom.jacobian(q) * qd - sp.Matrix([sp.diff(L, c) for c in q])
    if L.has(t):  # d/dt of the momenta holds their explicit time derivative
        h += p_mom.diff(t)
    h -= generalized_forces(spec)
    cons = sp.Matrix(spec.velocity_constraints)
    A = cons.jacobian(qd)
    c = (A * qd).jacobian(q) * qd  # d/dt(A) q_dot
    b = affine_terms(spec)
    if b.has(t) or A.has(t) or any(e != 0 for e in b) or any(A.has(u) for u in spec.inputs):
        # rheonomic: + d(b)/dq q_dot + d(A q_dot + b)/dt (the inputs' rates included)
        c += b.jacobian(q) * qd + (A * qd + b).applyfunc(spec.time_derivative)
    return M, h, A, c


def affine_terms(spec: ModelSpec) -> sp.Matrix:
    """``b(q, t)`` of the constraints ``A(q, t) q_dot + b(q, t) = 0`` (zero for homogeneous constraints)."""
    cons = sp.Matrix(spec.velocity_constraints)
    if not cons:
        return sp.zeros(0, 1)
    return (cons - cons.jacobian(sp.Matrix(spec.velocities)) * sp.Matrix(spec.velocities)).applyfunc(sp.expand)


def generalized_forces(spec: ModelSpec) -> sp.Matrix:
    """Non-conservative generalized forces ``Q = forces - dR/dq_dot`` (zero for a conservative model)."""
    Q = sp.zeros(len(spec.coordinates), 1)
    if spec.forces:
        Q += sp.Matrix([sp.sympify(f) for f in spec.forces])
    if spec.dissipation is not None:
        Q -= sp.Matrix([sp.diff(spec.dissipation, v) for v in spec.velocities])
    return Q


def _split(spec: ModelSpec, A: sp.Matrix):
    dep = [spec.coordinates.index(q) for q in spec.dependent]
    ind = [spec.coordinates.index(q) for q in spec.independent]
    return dep, ind, A.extract(list(range(A.rows)), dep), A.extract(list(range(A.rows)), ind)


def dependent_velocities(spec: ModelSpec, at: dict | None = None) -> dict:
    """Solve the constraints for the dependent velocities (at ``at`` if given)."""
    A = sp.Matrix(spec.velocity_constraints).jacobian(sp.Matrix(spec.velocities))
    b = affine_terms(spec)
    if at:
        A, b = A.subs(at), b.subs(at)
    dep, ind, A_dep, A_ind = _split(spec, A)
    qd_ind = sp.Matrix([spec.velocities[i] for i in ind])
    sol = -A_dep.inv() * A_ind * qd_ind
    if any(e != 0 for e in b):
        sol -= A_dep.inv() * b
    sol = sol.applyfunc(lambda e: sp.factor(sp.trigsimp(sp.expand(e))))
    return {spec.velocities[i]: sol[k] for k, i in enumerate(dep)}


def _trig_tidy(e: sp.Expr) -> sp.Expr:
    """Simplify a coefficient (parameters and trigonometric functions only)."""
    return sp.factor(sp.trigsimp(sp.factor(e)))


def tidy(e: sp.Expr, variables) -> sp.Expr:
    """Cheap normal form of a rational function of the state.

    The numerator and denominator are expanded as polynomials in
    ``variables`` and only their coefficients (small expressions in the
    parameters and in trigonometric functions of constant angles) are
    simplified.  Simplifying small pieces keeps the derivation fast.
    """
    num, den = sp.fraction(sp.together(e))
    out = []
    for part in (num, den):
        part = sp.expand(part)
        # functions of the state (sin/cos of a coordinate) are generators too, not coefficients
        functions = sorted({f for f in part.atoms(sp.sin, sp.cos, sp.tan, sp.exp, sp.sqrt, sp.Pow)
                            if not f.is_Symbol and not (f.is_Pow and f.exp.is_Integer and f.exp > 0)
                            and f.free_symbols & set(variables)}, key=sp.default_sort_key)
        gens = list(variables) + functions
        poly = sp.Poly(part, *gens)
        out.append(sum((_trig_tidy(c) * sp.Mul(*(v**k for v, k in zip(gens, m))) for m, c in poly.terms()), sp.S.Zero))
    return sp.factor_terms(out[0]) / sp.factor_terms(out[1])


def derive(spec: ModelSpec) -> ReducedSystem:
    """Run the pipeline of the module docstring on ``spec``."""
    at = dict(spec.cyclic)
    if choose_elimination(spec, len(spec.independent), affine_terms(spec).subs(at)) == "numeric":
        return _numeric_system(spec, at, *_lagrange_terms(spec, fast=True))
    M, h, A, c = _lagrange_terms(spec)
    M, h, A, c = (X.subs(at) for X in (M, h, A, c))
    dep, ind, A_dep_inv, A_ind = _dependent_block(spec, A, at)
    qdd_ind = sp.Matrix([spec.accelerations[i] for i in ind])
    b = affine_terms(spec).subs(at)
    dep_vel, dep_acc = _dependent_motion(spec, dep, ind, A_dep_inv, A_ind, b, c)
    lam, reduced = _reduced_equations(spec, M, h, dep, ind, A_dep_inv, A_ind, dep_vel, dep_acc)

    variables = list(spec.velocity_state)
    mass, forcing = _mass_and_forcing(spec, reduced, qdd_ind, variables)
    explicit, lam, multipliers = _explicit_accelerations(mass, forcing, lam, qdd_ind, variables)

    L = spec.lagrangian.subs(at)
    energy = _energy(spec, at, L, dep_vel, variables)
    power = _dissipated_power(spec, at, dep_vel, variables)
    power_input = _power_input(spec, L, b, multipliers, dep_vel, variables, at)

    # pose rates at a general pose
    general = dependent_velocities(spec)
    pose_rates = {q: general.get(spec.velocity_of(q), spec.velocity_of(q)) for q in spec.pose}

    system = ReducedSystem(
        spec=spec,
        state=spec.state,
        accelerations=tuple(qdd_ind),
        mass_matrix=mass,
        forcing=forcing,
        explicit=explicit,
        multipliers=multipliers,
        multipliers_implicit=lam,
        energy=energy,
        pose_rates=pose_rates,
        power=power,
        power_input=power_input,
        dependent_rates=held_rates(spec, at, dep_vel, A_dep_inv, variables),
    )
    if spec.quasi_velocities:
        system = _with_quasi_velocities(system, at, dep_vel, dep_acc, general)
    return system


def _dependent_block(spec: ModelSpec, A: sp.Matrix, at: dict) -> tuple:
    """``(dep, ind, A_dep_inv, A_ind)``: the indices of the dependent and independent coordinates, the inverse
    of the constraint matrix's dependent block (trig-simplified) and its independent block, at ``at``.

    Raises :class:`ModelSpecError` when the dependent block is singular at the representative point.
    """
    dep, ind, A_dep, A_ind = _split(spec, A)
    if A_dep.det() == 0:
        raise ModelSpecError(spec.error_message(
            f"the constraints do not determine the velocities of `dependent` {spec.dependent} at the representative "
            f"point {at} (their block of the constraint matrix is singular); choose other dependent coordinates"))
    return dep, ind, A_dep.inv().applyfunc(sp.trigsimp), A_ind


def _dependent_motion(spec: ModelSpec, dep: list, ind: list, A_dep_inv: sp.Matrix, A_ind: sp.Matrix,
                      b: sp.Matrix, c: sp.Matrix) -> tuple:
    """``(dep_vel, dep_acc)``: the dependent velocities from the constraints ``A q_dot + b = 0`` and the
    dependent accelerations from the differentiated constraints (whose velocity terms are ``c``), each a
    dict from the dependent symbol to its expression in the independent ones."""
    qd_ind = sp.Matrix([spec.velocities[i] for i in ind])
    qdd_ind = sp.Matrix([spec.accelerations[i] for i in ind])
    dep_vel = dict(zip((spec.velocities[i] for i in dep), sp.expand(
        -A_dep_inv * A_ind * qd_ind if all(e == 0 for e in b) else -A_dep_inv * (A_ind * qd_ind + b))))
    dep_acc = dict(
        zip((spec.accelerations[i] for i in dep), sp.expand(-A_dep_inv * (A_ind * qdd_ind + c)))
    )
    return dep_vel, dep_acc


def _reduced_equations(spec: ModelSpec, M: sp.Matrix, h: sp.Matrix, dep: list, ind: list, A_dep_inv: sp.Matrix,
                       A_ind: sp.Matrix, dep_vel: dict, dep_acc: dict) -> tuple:
    """``(lam, reduced)``: the multipliers, implicit in the independent accelerations, from the dependent rows
    of ``M q_ddot + h``, and the independent rows with the multipliers eliminated (both expanded)."""
    qdd = sp.Matrix(spec.accelerations)
    residual = (M * qdd + h).subs(dep_acc).subs(dep_vel)
    residual = residual.applyfunc(sp.expand)
    r_dep = sp.Matrix([residual[i] for i in dep])
    r_ind = sp.Matrix([residual[i] for i in ind])
    lam = (A_dep_inv.T * r_dep).applyfunc(sp.expand)  # multipliers, implicit in q_ddot_ind
    reduced = (r_ind - A_ind.T * lam).applyfunc(sp.expand)
    return lam, reduced


def _mass_and_forcing(spec: ModelSpec, reduced: sp.Matrix, qdd_ind: sp.Matrix, variables: list) -> tuple:
    """``(mass, forcing)`` of the reduced equations ``mass q_ddot_ind = forcing``, tidied.

    Raises :class:`ModelSpecError` when the reduced equations still hold a cyclic coordinate or a dependent
    velocity (the ``cyclic`` coordinates are then not all symmetries).
    """
    mass = reduced.jacobian(qdd_ind).applyfunc(lambda e: tidy(e, variables))
    forcing = (-reduced.subs({a: 0 for a in qdd_ind})).applyfunc(lambda e: tidy(e, variables))
    leftover = set().union(*(e.free_symbols for e in reduced)) & (
        set(spec.cyclic) | {spec.velocity_of(q) for q in spec.dependent}
    )
    if leftover:
        raise ModelSpecError(spec.error_message(
            f"the reduced equations do not close: they still contain {sorted(map(str, leftover))}; the coordinates "
            f"declared `cyclic` are not all symmetries of the Lagrangian and constraints"))
    return mass, forcing


def _explicit_accelerations(mass: sp.Matrix, forcing: sp.Matrix, lam: sp.Matrix, qdd_ind: sp.Matrix,
                            variables: list) -> tuple:
    """``(explicit, lam, multipliers)``: the independent accelerations by the adjugate over the determinant,
    the implicit multipliers tidied, and the multipliers with the explicit accelerations put in."""
    det = tidy(mass.det(), variables)
    adj = mass.adjugate()
    explicit = sp.Matrix([tidy((adj.row(k) * forcing)[0] / det, variables) for k in range(len(qdd_ind))])
    acc_sub = dict(zip(qdd_ind, explicit))
    lam = lam.applyfunc(lambda e: tidy(e, variables + list(qdd_ind)))
    multipliers = lam.subs(acc_sub).applyfunc(lambda e: tidy(e, variables))
    return explicit, lam, multipliers


def _energy(spec: ModelSpec, at: dict, L: sp.Expr, dep_vel: dict, variables: list) -> sp.Expr:
    """The energy (Jacobi integral) of the Lagrangian ``L`` on the constraint manifold, with the potential
    dropped by the representative point added back."""
    qd = sp.Matrix(spec.velocities)
    energy = sum(v * sp.diff(L, v) for v in qd) - L
    energy = tidy(energy.subs(dep_vel), variables)
    dropped = _dropped_potential(spec, at)
    if dropped != 0:
        energy = energy + dropped
    return energy


def _dissipated_power(spec: ModelSpec, at: dict, dep_vel: dict, variables: list) -> sp.Expr | None:
    """The power the generalized forces (the inputs left out) take from the system; ``None`` without
    dissipation."""
    if not spec.dissipative:
        return None
    qd = sp.Matrix(spec.velocities)
    power = -(qd.T * _without_inputs(spec, generalized_forces(spec)).subs(at))[0]
    return tidy(sp.expand(power.subs(dep_vel)), variables)


#: ``elimination="auto"`` solves the multipliers numerically from this many independent accelerations on (measured
#: in docs/performance.md, "Numeric elimination of the multipliers": the disk, 3, derives in ~6 s with a closed form
#: of ~130 operations; the disk with a pendulum, 4, took 193 s and 7,312 operations in closed form)
NUMERIC_FROM = 4


def choose_elimination(spec: ModelSpec, n_independent: int, b: sp.Matrix) -> str:
    """``"symbolic"`` or ``"numeric"``: ``spec.elimination`` unless ``"auto"``, then by :data:`NUMERIC_FROM`.

    Affine (rheonomic) constraints, quasi-velocities and ``small`` coordinates need the closed form (the power of
    the constraints, the quasi-velocity rates, the truncated fidelities), so ``"auto"`` keeps them symbolic and
    ``"numeric"`` is refused.
    """
    closed_only = bool(spec.quasi_velocities) or bool(spec.small) or any(e != 0 for e in b)
    if spec.elimination == "numeric" and closed_only:
        raise ModelSpecError(spec.error_message(
            "`elimination='numeric'` does not take affine (rheonomic or holonomic time-dependent) constraints, "
            "`quasi_velocities` or `small` coordinates (their power, rates and truncated fidelities need the "
            "closed form); use `elimination='symbolic'`"))
    if spec.elimination != "auto":
        return spec.elimination
    return "numeric" if n_independent >= NUMERIC_FROM and not closed_only else "symbolic"


@dataclass
class Kkt:
    """The linear system ``[[M, -A^T], [A, 0]] [q_ddot, lambda] = [f, -c]`` in the closed state.

    ``mass`` ``M`` (n x n), ``forcing`` ``f = Q - h`` (n), ``constraint`` ``A`` (m x n) and ``bias``
    ``c = d(A q_dot)/dt - A q_ddot`` (m), the cyclic coordinates at their representative values; ``f`` and ``c``
    hold the dependent velocities (``velocities[i]`` for ``i`` in ``dependent``), which the emitted code solves
    from ``A_dep v_dep = -A_ind v_ind`` first (:mod:`.kkt_emit`); ``independent``, ``dependent``: indices among the
    n coordinates.  ``constraint_general`` is ``A`` at a general pose, whose dependent velocities (the symbols
    ``general_velocities``) the pose rates are.
    """

    mass: sp.Matrix
    forcing: sp.Matrix
    constraint: sp.Matrix
    bias: sp.Matrix
    independent: tuple
    dependent: tuple
    velocities: tuple
    constraint_general: sp.Matrix
    general_velocities: tuple
    #: the unreduced ``(M, h, A, c)`` at a general pose (what :func:`check_symmetry` compares with)
    unreduced: tuple = ()
    #: ``[0, holonomic_rate f]`` per row of ``A`` (empty without held holonomic constraints): the kept dependent
    #: coordinates' rates ``held_velocities`` solve ``A_dep v = -A_ind v_ind - holonomic_rhs``, so ``f`` decays as
    #: ``exp(-holonomic_rate t)`` (:func:`held_rates` of the closed form)
    holonomic_rhs: tuple = ()
    held_velocities: tuple = ()

    def exprs(self) -> list:
        return [*self.mass, *self.forcing, *self.constraint, *self.bias]

    def matrix(self) -> tuple:
        """``(K, r)``: the matrix and right-hand side of the system, as SymPy matrices."""
        n, m = self.mass.rows, self.constraint.rows
        K = sp.zeros(n + m, n + m)
        K[:n, :n], K[:n, n:], K[n:, :n] = self.mass, -self.constraint.T, self.constraint
        return K, sp.Matrix.vstack(self.forcing, -self.bias)


def _numeric_system(spec: ModelSpec, at: dict, M, h, A, c) -> ReducedSystem:
    """The :class:`ReducedSystem` of ``spec`` with its dependent velocities, accelerations and multipliers left to
    a numeric solve: nothing here inverts or expands the constraint block (the Whipple bicycle's is 5 x 5 of entries
    up to 771 operations, and its symbolic inverse did not finish in 12 minutes)."""
    at = {k: sp.sympify(v) for k, v in at.items()}
    variables = list(spec.velocity_state)
    dep = tuple(spec.coordinates.index(q) for q in spec.dependent)
    general = tuple(names.Own(f"_vg{i}", real=True) for i in range(len(dep)))
    kkt = Kkt(mass=M.xreplace(at), forcing=(-h).xreplace(at), constraint=A.xreplace(at), bias=c.xreplace(at),
              independent=tuple(spec.coordinates.index(q) for q in spec.independent), dependent=dep,
              velocities=tuple(spec.velocities), constraint_general=A, general_velocities=general,
              unreduced=(M, h, A, c))
    dep_v = {spec.velocities[i] for i in dep}
    allowed = set(variables) | set(spec.params) | {t} | set(spec.inputs) | set(spec.input_rates)
    leftover = set().union(*(e.free_symbols for e in kkt.exprs())) - allowed - dep_v
    if leftover:
        raise ModelSpecError(spec.error_message(
            f"the equations do not close: they still contain {sorted(map(str, leftover))}; the coordinates "
            f"declared `cyclic` are not all symmetries of the Lagrangian and constraints"))
    _check_dependent_block(spec, kkt)
    qd = sp.Matrix(spec.velocities)
    L = spec.lagrangian.xreplace(at)
    energy = sum((v * d for v, d in zip(qd, dag.gradient(L, qd))), -L) + _dropped_potential(spec, at)
    power = None
    if spec.dissipative:
        power = -(qd.T * _without_inputs(spec, generalized_forces(spec)).xreplace(at))[0]
    kkt.holonomic_rhs, kkt.held_velocities = _held_terms(spec, at, len(dep))
    held = dict(zip(spec.dependent, kkt.held_velocities))
    lam = sp.Matrix([names.Own(f"_lambda{i}", real=True) for i in range(A.rows)])
    accelerations = tuple(spec.accelerations[i] for i in kkt.independent)
    by_rate = dict(zip((spec.velocities[i] for i in dep), general))
    return ReducedSystem(
        spec=spec, state=spec.state, accelerations=accelerations, mass_matrix=sp.eye(len(accelerations)),
        forcing=sp.Matrix(accelerations), explicit=sp.Matrix(accelerations), multipliers=lam,
        multipliers_implicit=lam, energy=energy,
        pose_rates={q: by_rate.get(spec.velocity_of(q), spec.velocity_of(q)) for q in spec.pose},
        power=power, power_input=_numeric_power_input(spec, L, at),
        dependent_rates={q: held.get(q, spec.velocity_of(q)) for q in spec.kept}, kkt=kkt)


def _held_terms(spec: ModelSpec, at: dict, n_dependent: int) -> tuple:
    """``(holonomic_rhs, held_velocities)`` of a numeric-elimination :class:`Kkt` (both empty without holonomic
    constraints or with ``holonomic_rate`` 0): the numeric form of :func:`held_rates`."""
    rate = sp.sympify(spec.holonomic_rate)
    if not spec.holonomic or rate == 0:
        return (), ()
    rhs = (sp.S.Zero,) * len(spec.constraints) + tuple(rate * f.xreplace(at) for f in spec.holonomic)
    return rhs, tuple(names.Own(f"_vh{k}", real=True) for k in range(n_dependent))


def _check_dependent_block(spec: ModelSpec, kkt: Kkt) -> None:
    """Refuse a constraint block of the dependent velocities that is singular at a random state (numerically)."""
    rng = random.Random(5)
    A = kkt.constraint.extract(list(range(kkt.constraint.rows)), list(kkt.dependent))
    pt = {s: sp.Float(rng.uniform(-0.9, 0.9), 30) for s in A.free_symbols}
    with mpmath.workdps(30):
        value = mpmath.det(_matrices_at([A], pt)[0])
    if abs(value) < 1e-20:
        raise ModelSpecError(spec.error_message(
            f"the constraints do not determine the velocities of `dependent` {spec.dependent} (their block of the "
            f"constraint matrix is singular at a random state); choose other dependent coordinates"))


def _floats(values: dict) -> dict:
    """``values`` as 30-digit floats."""
    return {k: sp.Float(sp.sympify(v), 30) for k, v in values.items()}


def _matrices_at(matrices, values: dict) -> list:
    """Each SymPy matrix at ``values`` as an ``mpmath.matrix`` (30 digits; call inside ``mpmath.workdps(30)``),
    every subexpression shared among them evaluated once (:func:`.dag.values`)."""
    matrices = [sp.Matrix(X) for X in matrices]
    flat = dag.values([e for X in matrices for e in X], values)
    out, k = [], 0
    for X in matrices:
        out.append(mpmath.matrix(X.rows, X.cols))
        for i in range(X.rows):
            for j in range(X.cols):
                out[-1][i, j] = flat[k]
                k += 1
    return out


def _numeric_velocities(A, b, dep: list, ind: list, values: dict) -> dict:
    """``{index: value}`` of the dependent velocities from ``A q_dot + b = 0`` at ``values`` (30 digits)."""
    with mpmath.workdps(30):
        An, bn = _matrices_at([A, b], values)
        v = dag.values([k for _, k in ind], values)
        rhs = [-(bn[r] + sum(An[r, i] * vk for (i, _), vk in zip(ind, v))) for r in range(A.rows)]
        sol = mpmath.lu_solve(mpmath.matrix([[An[r, i] for i in dep] for r in range(A.rows)]), mpmath.matrix(rhs))
    return {i: sp.Float(sol[j], 30) for j, i in enumerate(dep)}


def _numeric_power_input(spec: ModelSpec, L: sp.Expr, at: dict):
    """:func:`_power_input` of a numeric-elimination model (its velocity constraints are homogeneous, ``b = 0``),
    left in the dependent velocities, which its functions solve for first."""
    if not (L.has(t) or spec.inputs):
        return None
    power = -sp.diff(L, t)
    if spec.inputs:
        Q = generalized_forces(spec)
        power += (sp.Matrix(spec.velocities).T * (Q - _without_inputs(spec, Q)).xreplace(at))[0]
    return power


def kkt_solution(system: ReducedSystem, values: dict) -> tuple:
    """Independent accelerations and multipliers of a numeric-elimination ``system`` at a point (30 digits)."""
    kkt = system.kkt
    spec = system.spec
    values = _floats(values)
    ind = [(i, spec.velocities[i]) for i in kkt.independent]
    vel = _numeric_velocities(kkt.constraint, sp.zeros(kkt.constraint.rows, 1), list(kkt.dependent), ind, values)
    values = {**values, **{spec.velocities[i]: v for i, v in vel.items()}}
    K, r = kkt.matrix()
    with mpmath.workdps(30):
        sol = mpmath.lu_solve(*_matrices_at([K, r], values))
        sol = [sp.Float(v, 30) for v in sol]
    n = kkt.mass.rows
    return [sol[i] for i in kkt.independent], sol[n:]


def _dropped_potential(spec: ModelSpec, at: dict) -> sp.Expr:
    """The part of ``energy`` in the cyclic coordinates that their representative values leave out.

    A potential such as ``-g sin(alpha) x`` on an incline keeps the equations symmetric under translation
    (its force is constant) but not the energy: ``-(L0 - L0 at the representative point)``, ``L0`` the part of
    the Lagrangian without velocities.  Its coordinates must be in ``pose`` (the energy then reads them from the
    pose-extended state); else the model is refused rather than given a wrong energy.
    """
    L0 = spec.lagrangian.subs({v: 0 for v in spec.velocities})
    dropped = sp.expand(L0.subs(at) - L0)
    missing = sorted(map(str, dropped.free_symbols & (set(spec.cyclic) - set(spec.pose))))
    if missing:
        raise ModelSpecError(spec.error_message(
            f"the energy holds the potential {dropped} of the cyclic coordinates {missing}, which the closed state "
            f"does not keep; add them to `pose` (the energy then reads them from the pose-extended state)"))
    return dropped


def _without_inputs(spec: ModelSpec, e):
    """``e`` with every input set to zero."""
    return e.subs({u: 0 for u in spec.inputs}) if spec.inputs else e


def _power_input(spec: ModelSpec, L: sp.Expr, b: sp.Matrix, multipliers: sp.Matrix, dep_vel: dict, variables,
                 at: dict):
    """Rate of gain of ``energy`` by the explicit time and the inputs (``None`` if neither).

    With ``M q_ddot + h = A^T lambda`` and ``A q_dot + b = 0``, the Jacobi integral
    ``E = q_dot . dL/dq_dot - L`` changes at the rate ``-dL/dt + q_dot . Q + lambda . A q_dot``,
    that is ``power_input - power_dissipated`` (Goldstein, *Classical Mechanics*, section 8.2), with
    ``power_input = -dL/dt - lambda . b + q_dot . Q_u``, ``Q_u`` the part of the forces ``Q`` that the
    inputs add (``Q - Q`` at zero inputs; the rest is ``power_dissipated``).
    """
    if not (L.has(t) or any(e != 0 for e in b) or spec.inputs):
        return None
    power = -sp.diff(L, t) - sum((lam * e for lam, e in zip(multipliers, b)), sp.S.Zero)
    if spec.inputs:
        Q = generalized_forces(spec)
        power += (sp.Matrix(spec.velocities).T * (Q - _without_inputs(spec, Q)).subs(at))[0]
    return tidy(sp.expand(sp.sympify(power).subs(dep_vel)), variables)


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
        raise ModelSpecError(spec.error_message(f"the quasi-velocities do not determine {unknowns} uniquely"))
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
        power=None if system.power is None else tidy(system.power.subs(back), variables),
        power_input=None if system.power_input is None else tidy(system.power_input.subs(back), variables),
        dependent_rates={q: tidy(e.subs(back), variables) for q, e in system.dependent_rates.items()},
    )


def _random_point(symbols, rng: random.Random) -> dict:
    return {s: sp.Rational(rng.randint(-900, 900), 1000) for s in symbols}


def unreduced_accelerations(spec: ModelSpec, values: dict, everything: bool = False, terms: tuple = ()) -> tuple:
    """Independent accelerations and multipliers from the full DAE at a numeric point.

    Solves ``[[M, -A^T], [A, 0]] [q_ddot, lambda] = [-h, -c]`` at the
    configuration ``values`` (which must fix every coordinate, including the
    cyclic ones, every parameter, and the independent velocities; the
    dependent velocities are taken from the constraints, solved in 30 digits).
    Used to test the elimination and the symmetry assumption at arbitrary
    poses.  With ``everything`` the first item holds every acceleration (in
    the order of ``spec.accelerations``) and a third item the dependent
    velocities.  ``terms``: ``(M, h, A, c)`` of :func:`_lagrange_terms` if
    already formed.
    """
    M, h, A, c = terms or _lagrange_terms(spec)
    values = _floats(values)
    ind = [(i, spec.velocities[i]) for i in (spec.coordinates.index(q) for q in spec.independent)]
    dep = [spec.coordinates.index(q) for q in spec.dependent]
    vel = _numeric_velocities(A, affine_terms(spec), dep, ind, values)
    dep_vel = {spec.velocities[i]: v for i, v in vel.items()}
    pt = {**values, **dep_vel}
    n, m = len(spec.coordinates), len(spec.velocity_constraints)
    K = sp.zeros(n + m, n + m)
    K[:n, :n] = M
    K[:n, n:] = -A.T
    K[n:, :n] = A
    rhs = sp.Matrix.vstack(-h, -c)
    with mpmath.workdps(30):
        sol = mpmath.lu_solve(*_matrices_at([K, rhs], pt))
        sol = [sp.Float(v, 30) for v in sol]
    if everything:
        return sol[:n], list(sol[n:]), dep_vel
    return [sol[i] for i, _ in ind], list(sol[n:])


def check_symmetry(system: ReducedSystem, seed: int = 0, tol: float = 1e-20) -> float:
    """Compare the reduced equations with the unreduced DAE at a random general pose.

    Returns the largest absolute difference of accelerations and multipliers
    (accelerations only for a spec whose ``multipliers_invariant`` is false);
    raises ``ValueError`` above ``tol`` (the cyclic coordinates would then not
    be cyclic, or the elimination would be wrong).
    """
    spec = system.spec
    rng = random.Random(seed)
    pt = _random_point(spec.coordinates + tuple(spec.velocity_of(q) for q in spec.independent), rng)
    pt.update({s: sp.Rational(rng.randint(300, 1500), 1000) for s in spec.params})
    pt[t] = sp.Rational(37, 100)
    pt.update(_random_point(spec.inputs + spec.input_rates, rng))
    if spec.quasi_velocities:
        acc, lam, pt = _quasi_point(spec, pt)
    else:
        acc, lam = unreduced_accelerations(spec, pt, terms=system.kkt.unreduced if system.kkt else ())
    if system.kkt is not None:  # the reduced state at the general pose: the cyclic coordinates at their values
        red_acc, red_lam = kkt_solution(system, {k: v for k, v in pt.items() if k not in spec.cyclic})
    else:
        red_acc = [e.subs(pt).evalf(30) for e in system.explicit]
        red_lam = [e.subs(pt).evalf(30) for e in system.multipliers]
    if not getattr(spec, "multipliers_invariant", True):  # e.g. forces in the table's axes, the heading cyclic
        lam, red_lam = [], []
    err = max(abs(a - b) for a, b in zip(acc + lam, red_acc + red_lam))
    if err > tol:
        raise ModelSpecError(spec.error_message(
            f"the reduced equations differ from the unreduced ones at a general pose by {err}: the coordinates "
            f"declared `cyclic` are not symmetries of the model"))
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
