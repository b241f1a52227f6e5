"""Emitter of rigid-body modules (:mod:`derivation.rigid`): the common right-hand side plus rigid-body data.

A rigid module has what every generated module has (``rhs``/``rhs_into``/
``constants``/``rhs_q_into`` and the pose variants, ``pose_rates``,
``energy``, ``multipliers``) and, as data and plain functions the runtime
reads generically: units (``STATE_UNITS``, ``PARAM_UNITS``), admissible
parameter values (``PARAM_DOMAINS``), named parameter sets (``PRESETS`` with
``PRESET_SOURCES``), ``initial_state(n0, omega0)`` from the physical
description, and ``power_dissipated(s, p)``.
"""
from __future__ import annotations

import hashlib
import inspect
import sys
from pathlib import Path

import sympy as sp

from . import codegen, drawing, input_slots, jacobian, rigid, steady
from .names import t as _t
from .codegen import (USER_MODULE_PREFIX, Constant, ModuleParts, const, cse_block, expression_function,
                      provenance, regenerate_hint, rhs_functions, unpack)


def input_hash(system: rigid.RollingSystem, fidelity: str) -> str:
    """SHA-256 of the body's description, the front end's and emitters' sources and SymPy's version."""
    body, spec = system.body, system.spec
    h = hashlib.sha256()
    model_file = sys.modules.get(body.source)
    for part in (
        spec.name, fidelity, sp.__version__, sp.srepr(spec.lagrangian), *(sp.srepr(c) for c in spec.constraints),
        sp.srepr(sp.Matrix(body.inertia)), sp.srepr(body.sigma), repr(sorted(body.presets.items())),
        inspect.getsource(rigid), inspect.getsource(model_file) if model_file else "", Path(__file__).read_text(),
        Path(codegen.__file__).read_text(), drawing.source_text(), repr(sorted(body.param_units.items())),
        repr(sorted(body.param_domains.items())), body.description,
        *((inspect.getsource(input_slots), *(sp.srepr(sp.sympify(c)) for c in body.torque), *map(sp.srepr, body.inputs))
          if body.torque is not None else ()),
    ):
        h.update(part.encode())
        h.update(b"\0")
    return h.hexdigest()


def source_label(body: rigid.RigidBody) -> str:
    """The file that defines ``body``, as the header names it: ``derivation/celt.py`` or the user's file name."""
    source = body.source or ""
    if source.startswith(("knifeedge.derive.", "derivation.")):
        return f"derivation/{source.rsplit('.', 1)[1]}.py"
    if source.startswith(USER_MODULE_PREFIX):
        return source[len(USER_MODULE_PREFIX):] + ".py"
    return "MODEL_FILE.py"


#: lines of a generated ``initial_state`` that check ``n0`` and ``omega0`` and normalize ``n0`` (every rigid
#: module's, whatever its state)
VERTICAL_CHECK = '''    for name, value in (("n0", n0), ("omega0", omega0)):
        try:  # no strings, complex numbers (their imaginary part would be lost), bools or other objects
            items = [] if isinstance(value, (str, bytes)) else np.asarray(value, dtype=object).ravel().tolist()
        except (TypeError, ValueError):  # ragged
            items = []
        if not items or not all(isinstance(x, (int, float, np.integer, np.floating))
                                and not isinstance(x, (bool, np.bool_)) for x in items):
            raise TypeError(f"`{name}` must be 3 real numbers, got {value!r}")
    n0 = np.array(n0, dtype=float)
    omega0 = np.array(omega0, dtype=float)
    if n0.shape != (3,) or not np.isfinite(n0).all():
        raise ValueError(f"`n0` must be 3 finite numbers (the upward vertical in body axes), got {n0!r}")
    if omega0.shape != (3,) or not np.isfinite(omega0).all():
        raise ValueError(f"`omega0` must be 3 finite numbers (angular velocity in body axes), got {omega0!r}")
    norm = math.sqrt(float(n0 @ n0))
    if not norm > 0:
        raise ValueError("`n0` must not be the zero vector")
    n0 = n0 / norm
'''

_INITIAL_STATE = '''

def initial_state(n0=(0.0, 0.0, 1.0), omega0=(0.0, 0.0, 0.0), pose=None):
    """Closed state (or pose-extended state) from the physical description.

    Parameters
    ----------
    n0 : upward vertical in body axes (normalized here); for tilts ``al``
        (about the body x axis) and ``be`` (about the body y axis),
        ``n0 = (cos(al) sin(be), sin(al), cos(al) cos(be))``.  Any direction
        is accepted (these coordinates have no singular orientation).
    omega0 : angular velocity in body axes [rad/s].
    pose : optional ``(psi, x, y)`` (heading [rad], centre of mass [m]); when
        given the pose-extended state is returned.

    Returns
    -------
    ndarray of shape ({n},) (or ({n_pose},) with ``pose``) in the order of
    ``STATE_NAMES`` (+ ``POSE_NAMES``); ``omega_n = omega0 . n0``.
    """
{VERTICAL}    s = np.concatenate([n0, omega0, [float(omega0 @ n0)]])
    if pose is None:
        return s
    pose = np.array(pose, dtype=float)
    if pose.shape != (3,) or not np.isfinite(pose).all():
        raise ValueError(f"`pose` must be 3 finite numbers (psi, x, y), got {{pose!r}}")
    return np.concatenate([s, pose])
'''


def body_values_source(body: rigid.RigidBody, params) -> str:
    """``body_values(p)``: the numbers :func:`knifeedge.bodies.problems` checks, at a parameter vector ``p`` of the
    parameters ``params`` (those of the body a fidelity leaves out are zero); plain Python, in every rigid module:
    the runtime checks every parameter set with it."""
    mass, gravity, sigma, inertia, height = rigid.body_values(body)
    dropped = {q: 0 for q in body.params if q not in params}
    exprs = [sp.sympify(e).subs(dropped) for e in (mass, gravity, sigma, *inertia, height if height is not None else 0)]
    lines, _ = cse_block(exprs, [f"out[{i}]" for i in range(len(exprs))], set(params))
    nl = "\n"
    return f'''

def body_values(p):
    """``(mass, gravity, sigma, inertia, height)`` of the body at the parameters ``p``: what
    ``knifeedge.bodies.problems`` checks (``height``: of the centre of mass above the table at rest; ``None`` for
    a body that hangs below the edge it balances on)."""
    out = [0.0] * {len(exprs)}
{nl.join(unpack([str(q) for q in params], "p"))}
{nl.join(lines)}
    return (out[0], out[1], out[2], (out[3:6], out[6:9], out[9:12]), {"out[12]" if height is not None else "None"})
'''


def _rigid_defaults(body: rigid.RigidBody, params: list, state: list) -> tuple:
    """``(DEFAULT_PARAMS, DEFAULT_STATE)``: the body's defaults (else its first preset) and its default physical
    state as the closed state."""
    presets = {k: {p: float(v[p]) for p in params} for k, v in sorted(body.presets.items())}
    if body.defaults:
        defaults = {p: float(body.defaults[p]) for p in params}
    else:
        defaults = presets[sorted(body.presets)[0]] if body.presets else {}
    n0 = body.default_state.get("n0", (0.0, 0.0, 1.0))
    omega0 = body.default_state.get("omega0", (0.0, 0.0, 1.0))
    nrm = sum(float(c) ** 2 for c in n0) ** 0.5
    n0 = [float(c) / nrm for c in n0]
    omega0 = [float(c) for c in omega0]
    return defaults, dict(zip(state, n0 + omega0 + [sum(a * b for a, b in zip(n0, omega0))]))


def module_parts(system: rigid.RollingSystem) -> ModuleParts:
    """What the generated module of a derived rigid body (fidelity ``full``) holds.

    A body with ``inputs`` reads them from parameter slots after its parameters, as every model does
    (:func:`.input_slots.lowered`); its functions then take the time ``(s, p, t)``."""
    if system.spec.inputs:
        system = input_slots.lowered(system)
    spec, body = system.spec, system.body
    state, pose, params = [str(s) for s in system.state], [str(q) for q in spec.pose], [str(p) for p in body.params]
    n = len(state)
    digest = input_hash(system, "full")
    units = {**rigid.STATE_UNITS, **{str(k): v for k, v in body.param_units.items()}}
    domains = {p: body.param_domains.get(p, "positive") for p in params}
    state_doc = "\n".join(f"    s[{i}] = {nm:<12} [{units.get(nm, '?')}]" for i, nm in enumerate(state))
    pose_doc = "\n".join(f"    s[{n + i}] = {nm:<12} [{units.get(nm, '?')}]" for i, nm in enumerate(pose))
    par_doc = "\n".join(f"    p[{i}] = {nm:<12} [{units.get(nm, '?')}] {domains[nm]}" for i, nm in enumerate(params))
    preset_doc = "\n".join(f"    {k}: {body.preset_sources.get(k, '')}" for k in sorted(body.presets))
    return ModuleParts(
        title=f"{spec.name}, fidelity full: rigid body rolling without slipping, nothing dropped.",
        hint=regenerate_hint(source_label(body)),
        produced=f"Produced by derivation/rigid_emit.py (make derive) from the rigid body {spec.name!r}\n"
                 "through derivation/rigid.py (Lagrange-d'Alembert in body quasi-velocities).",
        digest=digest,
        doc=f"{spec.description}\n\nState vector ``s`` (closed state; the pose follows by quadrature):\n{state_doc}\n"
            f"Pose-extended state (``*_pose`` functions) appends:\n{pose_doc}\nParameter vector ``p``:\n{par_doc}\n"
            f"Presets:\n{preset_doc}\n"
            f"Multipliers: the contact force on the body in body axes, {', '.join(spec.constraint_labels)}.\n"
            "Energy and ``power_dissipated`` in the units of the parameters (J and W for SI parameters).",
        constants=_constants(system, units, domains, digest),
        body=_body(system))


def _constants(system: rigid.RollingSystem, units: dict, domains: dict, digest: str) -> tuple:
    """The metadata of a rigid body's module."""
    spec, body = system.spec, system.body
    state, pose, params = [str(s) for s in system.state], [str(q) for q in spec.pose], [str(p) for p in body.params]
    defaults, default_state = _rigid_defaults(body, params, state)
    presets = {k: {p: float(v[p]) for p in params} for k, v in sorted(body.presets.items())}
    return (
        const("MODEL", spec.name), const("FIDELITY", "full"),
        Constant("FIDELITY_DOC", '"rigid body rolling without slipping, exact in the orientation (derivation/rigid.py)"',
                 "what this fidelity is"),
        const("STATE_NAMES", tuple(state)), const("STATE_UNITS", tuple(units[k] for k in state), "unit of each state"),
        const("POSE_NAMES", tuple(pose)), const("POSE_UNITS", tuple(units[k] for k in pose)),
        Constant("POSE_DOC", f'"psi: heading of the horizontal projection of the body axis {tuple(body.heading_axis)}; '
                 '(x, y): centre of mass"', "what the pose coordinates mean"),
        const("PARAM_NAMES", tuple(params)), const("PARAM_UNITS", tuple(units[k] for k in params)),
        const("PARAM_DOMAINS", tuple(domains[k] for k in params), "admissible values of each parameter: 'positive' "
              "(> 0), 'nonnegative' (>= 0) or 'real' (any finite value)"),
        const("DEFAULT_PARAMS", defaults, "default parameter set and initial state (the CLI's defaults)"),
        const("DEFAULT_STATE", default_state),
        const("RATE_PAIRS", (), "(coordinate, rate) pairs of the state: none (n and omega are not coordinate and "
              "rate)"),
        const("TILT_NAMES", ()),
        const("REVERSAL_EVENTS", ("omega_n",), "the vertical spin omega . n (carried as a state), whose zero "
              "crossings are the spin reversals"),
        const("EVENT_NAMES", ()),
        const("VALIDITY", {}, "largest |value| of each named state where this fidelity holds (empty: everywhere)"),
        const("VALIDITY_DOC", ""), const("MULTIPLIER_NAMES", tuple(spec.constraint_labels)),
        const("HAS_DISSIPATION", _dissipative(body), "non-conservative forces (the torque -sigma omega): the "
              "module has ``power_dissipated(s, p)``"),
        const("EXPORTS", ("PRESETS", "PRESET_SOURCES", "initial_state"), "model-specific helpers: named parameter "
              "sets and the initial state from the physical description"),
        const("PRESETS", presets, "named parameter sets (SI units); sources in PRESET_SOURCES"),
        const("PRESET_SOURCES", dict(sorted(body.preset_sources.items()))),
        const("SOURCE", body.source, "the model file the body comes from"),
        *_driven_metadata(system),
        *provenance(digest))


def _driven_metadata(system: rigid.RollingSystem) -> tuple:
    """The constants of a body with an applied torque (none without): its inputs, and that its functions take
    the time."""
    if system.power_input is None:
        return ()
    return (*input_slots.metadata(system.spec),
            const("TIME_DEPENDENT", True, "an applied torque: energy, multipliers, pose_rates, power_dissipated and "
                  "power_input take the time\nas a third argument ``(s, p, t)``; energy(t) = energy(0) + integral of "
                  "(power_input - power_dissipated)"),
            const("HAS_POWER_INPUT", True))


def _dissipative(body: rigid.RigidBody) -> bool:
    return body.sigma is not None and body.sigma != 0


def _body(system: rigid.RollingSystem) -> tuple:
    """The functions of a rigid body's module, in order."""
    spec, body = system.spec, system.body
    n, npose = len(system.state), len(spec.pose)
    rates = system.state_rhs()
    driven = system.power_input is not None
    args = "s, p, t" if driven else "s, p"
    allowed = set(system.state) | set(spec.params) | ({_t} if driven else set())
    unpack_s, unpack_p = unpack([str(s) for s in system.state], "s"), unpack([str(p) for p in spec.params], "p")
    pose_exprs = [system.pose_rates[q] for q in spec.pose]
    lam = list(system.multipliers)
    power = (expression_function("power_dissipated", args, "Power dissipated by the damping torque",
                                 [sp.sympify(system.power)], ["power"], allowed, (unpack_s, unpack_p), "power"),)
    power += (expression_function("power_input", args, "Power of the applied torque, torque . omega",
                                  [sp.sympify(system.power_input)], ["power"], allowed, (unpack_s, unpack_p), "power"),
              ) if driven else ()
    return (
        *rhs_functions(system.state, spec.params, rates, spec.pose, pose_exprs),
        expression_function("pose_rates", args, "Return (psi_dot, x_dot, y_dot) at the pose-extended state ``s``",
                            pose_exprs, [f"out[{i}]" for i in range(npose)], allowed | set(spec.pose),
                            (unpack_s, unpack([str(q) for q in spec.pose], "s", start=n), unpack_p), "out",
                            (f"    out = np.empty({npose})",)),
        expression_function("energy", args, "Mechanical energy", [system.energy], ["energy"], allowed,
                            (unpack_s, unpack_p), "energy"),
        *(power if _dissipative(body) else power[1:]),
        expression_function("multipliers", args, "Contact force on the body in body axes", lam,
                            [f"out[{i}]" for i in range(len(lam))], allowed, (unpack_s, unpack_p), "out",
                            (f"    out = np.empty({len(lam)})",)),
        _INITIAL_STATE.format(n=n, n_pose=n + npose, VERTICAL=VERTICAL_CHECK),
        body_values_source(body, body.params), drawing.module_source(system),
        jacobian.block_source(rates, system.state, spec.params),
        steady.block_source(body.steady, system.state, spec.params, steady.rigid_invariants(system.state)))
