"""Emitter of the small-tilt fidelities of a rigid body (:mod:`derivation.rigid_small`): ``reduced``, ``amplitude``.

The modules have what every generated module has (``rhs``/``rhs_into``/
``constants``/``rhs_q_into``, ``energy``, ``multipliers`` -- none here) and
the rigid-body data the runtime reads generically (``PRESETS``,
``initial_state``, ``power_dissipated``); the amplitude module also has
``modes(p)`` and ``moffatt_tokieda(p)``.
"""
from __future__ import annotations

import hashlib
import inspect
import sys
from pathlib import Path

import sympy as sp

from . import codegen, jacobian, rigid, rigid_emit, rigid_small, steady
from .codegen import (Function, ModuleParts, const, expression_function, provenance, regenerate_hint,
                      rhs_functions, unpack)
from .rigid_emit import VERTICAL_CHECK, _dissipative

_DOC = {
    "reduced": ("small tilts, spin kept: rocking accelerations to first order in the tilts, spin acceleration to "
                "second order (derivation/rigid_small.py)"),
    "amplitude": ("first-order average over the two rocking modes (pitch, roll) of the reduced equations: tilt "
                  "amplitudes of the normal modes and the spin (derivation/rigid_small.py)"),
}

_REDUCED_INITIAL = '''

def initial_state(n0=(0.0, 0.0, 1.0), omega0=(0.0, 0.0, 0.0)):
    """State ``(n_x, n_y, omega_x, omega_y, omega_z)`` from the physical description.

    ``n0``: upward vertical in body axes (normalized here; ``n_z`` is not a state of this fidelity);
    ``omega0``: angular velocity in body axes [rad/s].
    """
''' + VERTICAL_CHECK + '''    return np.array([n0[0], n0[1], omega0[0], omega0[1], omega0[2]])
'''

_AMPLITUDE_INITIAL = '''

def _param_vector(p):
    if isinstance(p, dict):
        missing = [k for k in PARAM_NAMES if k not in p]
        if missing:
            raise ValueError(f"`p` lacks {missing}")
        p = [p[k] for k in PARAM_NAMES]
    p = np.array(p, dtype=float)
    if p.shape != (len(PARAM_NAMES),) or not np.isfinite(p).all():
        raise ValueError(f"`p` must be {len(PARAM_NAMES)} finite numbers in the order of PARAM_NAMES")
    return p


def initial_state(n0=(0.0, 0.0, 1.0), omega0=(0.0, 0.0, 0.0), p=None):
    """State ``(A_pitch, A_roll, omega_z)`` from the physical description and the parameters ``p``.

    The tilt ``q = (n_x, n_y)`` of ``n0`` (normalized) and its rate ``q_dot = (n_y omega_z - omega_y,
    omega_x - n_x omega_z)`` are projected on the rocking modes (``modes(p)``):
    ``y_k = v_k . q``, ``A_k = sqrt(y_k^2 + (v_k . q_dot / Omega_k)^2)``.
    """
    if p is None:
        raise ValueError("`p` (the parameters) is needed: the modes depend on them")
    p = _param_vector(p)
''' + VERTICAL_CHECK + '''    q = n0[:2]
    q_dot = np.array([n0[1] * omega0[2] - omega0[1], omega0[0] - n0[0] * omega0[2]])
    w2, u, v = modes(p)
    amps = [math.hypot(float(v[k] @ q), float(v[k] @ q_dot) / math.sqrt(w2[k])) for k in range(2)]
    return np.array([amps[0], amps[1], omega0[2]])
'''


def _project(w2, md, body, defaults, n0, w0) -> list:
    """The amplitude state of the default physical state at the default parameters (as ``initial_state``)."""
    at = {q: defaults[str(q)] for q in body.params if str(q) in defaults}
    at.update({q: 0 for q in body.params if str(q) not in defaults})

    def num(e):
        return float(sp.N(rigid_small.fill(e, body).xreplace(at)))

    q = (n0[0], n0[1])
    q_dot = (n0[1] * w0[2] - w0[1], w0[0] - n0[0] * w0[2])
    out = []
    for w, v in zip(w2, md.v):
        vv = [num(c) for c in v]
        y, y_dot = vv[0] * q[0] + vv[1] * q[1], vv[0] * q_dot[0] + vv[1] * q_dot[1]
        out.append((y**2 + y_dot**2 / num(w)) ** 0.5)
    return out + [w0[2]]


def input_hash(system, fidelity: str) -> str:
    body, spec = system.body, system.spec
    h = hashlib.sha256()
    model_file = sys.modules.get(body.source)
    for part in (spec.name, fidelity, sp.__version__, sp.srepr(spec.lagrangian), sp.srepr(sp.Matrix(body.inertia)),
                 sp.srepr(body.sigma), repr(sorted(body.presets.items())), inspect.getsource(rigid),
                 inspect.getsource(rigid_small), inspect.getsource(model_file) if model_file else "",
                 Path(__file__).read_text(), Path(codegen.__file__).read_text(), VERTICAL_CHECK,
                 repr(sorted(body.param_units.items())), repr(sorted(body.param_domains.items())), body.description):
        h.update(part.encode())
        h.update(b"\0")
    return h.hexdigest()


def _block(name: str, exprs, targets, args: str, unpacked: list, doc: str, allowed, ret: str, head=()) -> Function:
    return expression_function(name, args, doc, exprs, targets, allowed, (unpacked,), ret, head)


#: ``(TILT_NAMES, VALIDITY, VALIDITY_DOC)`` of each small-tilt fidelity
_VALIDITY = {
    "reduced": (("n_x", "n_y"), {"n_x": 0.003, "n_y": 0.03},
                "small tilts (terms of third order dropped): the expansion parameters are (a/c)^2 |n_x| and "
                "(b/c)^2 |n_y| for an ellipsoid; the bounds suit the Kane-Levinson celt (a/c = 10, b/c = 1.5), "
                "whose rocking accelerations are then within about 1 % of the full model's; the upright spin "
                "must be an equilibrium (I_xz = I_yz = 0)"),
    "amplitude": (("A_pitch", "A_roll"), {"A_pitch": 0.003, "A_roll": 0.03},
                  "small tilt amplitudes (the bounds of the reduced fidelity), non-resonant rocking modes, and a "
                  "spin slow against the rocking frequencies (first-order averaging)"),
}


def _presets(system, fidelity: str) -> dict:
    """The body's presets restricted to this fidelity's parameters; refuses one that sets a dropped one."""
    spec, body = system.spec, system.body
    params = [str(p) for p in spec.params]
    dropped = {str(k) for k in system.dropped}
    presets = {}
    for k, v in sorted(body.presets.items()):
        bad = [d for d in dropped if float(v.get(d, 0.0)) != 0.0]
        if bad:
            raise ValueError(f"{spec.name}: preset {k!r} has nonzero {bad}, which the {fidelity} fidelity drops")
        presets[k] = {p: float(v[p]) for p in params}
    return presets


def _default_physical(body) -> tuple:
    """``(n0, omega0)``: the body's default physical state inside this fidelity's domain (``n0`` normalized)."""
    physical = body.default_state.get("small", body.default_state)
    n0 = [float(c) for c in physical.get("n0", (0.0, 0.0, 1.0))]
    nrm = sum(c * c for c in n0) ** 0.5
    return [c / nrm for c in n0], [float(c) for c in physical.get("omega0", (0.0, 0.0, 1.0))]


def _amplitude_functions(system) -> tuple:
    """``modes(p)`` and ``moffatt_tokieda(p)`` of the amplitude fidelity."""
    spec, body = system.spec, system.body
    params = [str(p) for p in spec.params]
    md = system.coefficients["modes"]
    fill = lambda e: rigid_small.fill(e, body)  # noqa: E731
    w2 = [fill(w) for w in md.omega2]
    u = [fill(c) for vec in md.u for c in vec]
    v = [fill(c) for vec in md.v for c in vec]
    mt = rigid_small.moffatt_tokieda(system)
    return (
        _block("modes", w2 + u + v, [f"out[{i}]" for i in range(10)], "p", unpack(params, "p"),
               "Rocking modes without spin and damping: squared frequencies (pitch, roll), unit shapes u_k and left "
               "vectors v_k (v_k . u_k = 1) of W0 in the tilt (n_x, n_y)", set(spec.params), "out[:2], "
               "out[2:6].reshape(2, 2), out[6:10].reshape(2, 2)", head=("    out = np.empty(10)",)),
        _block("moffatt_tokieda", [mt["lambda"], mt["mu"], mt["p2"], mt["r2"]], [f"out[{i}]" for i in range(4)], "p",
               unpack(params, "p"),
               "Moffatt & Tokieda's (lambda, mu) and the squared scalings (p^2, r^2) with P = p A_pitch, R = r A_roll, "
               "n = omega_z", set(spec.params), "out", head=("    out = np.empty(4)",)))


def _default_state(system, fidelity: str, defaults: dict) -> dict:
    """The default state: the body's default physical state, projected on the modes at the amplitude fidelity."""
    state = [str(s) for s in system.state]
    n0, w0 = _default_physical(system.body)
    if fidelity == "reduced":
        return dict(zip(state, [n0[0], n0[1], *w0]))
    md = system.coefficients["modes"]
    w2 = [rigid_small.fill(w, system.body) for w in md.omega2]
    return dict(zip(state, _project(w2, md, system.body, defaults, n0, w0)))


def _body(system, fidelity: str) -> tuple:
    """The functions of a small-tilt module, in order."""
    spec, body = system.spec, system.body
    allowed = set(system.state) | set(spec.params)
    unpack_sp = unpack([str(s) for s in system.state], "s") + unpack([str(p) for p in spec.params], "p")
    power = (_block("power_dissipated", [system.power], ["power"], "s, p", unpack_sp,
                    "Power removed by the damping torque, to the order of this fidelity", allowed, "power"),)
    return (
        *rhs_functions(system.state, spec.params, system.rates),
        _block("energy", [system.energy], ["energy"], "s, p", unpack_sp,
               "Mechanical energy to the order of this fidelity", allowed, "energy"),
        *(power if _dissipative(body) else ()),
        Function("multipliers", "s, p", "No multipliers at this fidelity (the contact force is not kept).",
                 ("    return np.empty(0)",)),
        *(_amplitude_functions(system) if fidelity == "amplitude" else ()),
        _REDUCED_INITIAL if fidelity == "reduced" else _AMPLITUDE_INITIAL,
        rigid_emit.body_values_source(body, spec.params),
        jacobian.block_source(system.rates, system.state, spec.params),
        steady.block_source(body.steady, system.state, spec.params))


def module_parts(system: rigid_small.SmallTiltSystem, fidelity: str) -> ModuleParts:
    """What the generated module of a small-tilt fidelity of a rigid body holds."""
    spec, body = system.spec, system.body
    state, params = [str(s) for s in system.state], [str(p) for p in spec.params]
    units = {**rigid.STATE_UNITS, **rigid_small.UNITS, **{str(k): v for k, v in body.param_units.items()}}
    domains = {p: body.param_domains.get(p, "positive") for p in params}
    presets = _presets(system, fidelity)
    defaults = {p: float(body.defaults[p]) for p in params} if body.defaults else presets[sorted(presets)[0]]
    tilt_names, validity, validity_doc = _VALIDITY[fidelity]
    digest = input_hash(system, fidelity)
    state_doc = "\n".join(f"    s[{i}] = {nm:<12} [{units.get(nm, '?')}]" for i, nm in enumerate(state))
    par_doc = "\n".join(f"    p[{i}] = {nm:<12} [{units.get(nm, '?')}] {domains[nm]}" for i, nm in enumerate(params))
    preset_doc = "\n".join(f"    {k}: {body.preset_sources.get(k, '')}" for k in sorted(presets))
    exports = ("PRESETS", "PRESET_SOURCES", "initial_state") + (("modes", "moffatt_tokieda")
                                                                 if fidelity == "amplitude" else ())
    return ModuleParts(
        title=f"{spec.name}, fidelity {fidelity}: {_DOC[fidelity]}.",
        hint=regenerate_hint(rigid_emit.source_label(body)),
        produced=f"Produced by derivation/rigid_small_emit.py (make derive) from the rigid body {spec.name!r}\n"
                 "through derivation/rigid.py and derivation/rigid_small.py.",
        digest=digest,
        doc=f"{spec.description}\n\nParameters set to zero at this fidelity (the upright spin must be an "
            f"equilibrium): {', '.join(sorted(str(k) for k in system.dropped)) or 'none'}.\n\n"
            f"State vector ``s``:\n{state_doc}\nParameter vector ``p``:\n{par_doc}\nPresets:\n{preset_doc}",
        constants=(
            const("MODEL", spec.name), const("FIDELITY", fidelity),
            const("FIDELITY_DOC", _DOC[fidelity], "what this fidelity is"),
            const("STATE_NAMES", tuple(state)), const("STATE_UNITS", tuple(units[k] for k in state)),
            const("POSE_NAMES", ()), const("POSE_UNITS", ()), const("POSE_DOC", ""),
            const("PARAM_NAMES", tuple(params)), const("PARAM_UNITS", tuple(units[k] for k in params)),
            const("PARAM_DOMAINS", tuple(domains[k] for k in params), "admissible values of each parameter: "
                  "'positive' (> 0), 'nonnegative' (>= 0) or 'real' (any finite value)"),
            const("DEFAULT_PARAMS", defaults), const("DEFAULT_STATE", _default_state(system, fidelity, defaults)),
            const("RATE_PAIRS", ()), const("TILT_NAMES", tilt_names),
            const("REVERSAL_EVENTS", ("omega_z",), "the vertical spin (omega_z: omega . n to second order in the "
                  "tilts), whose zero crossings are the reversals"),
            const("EVENT_NAMES", ()),
            const("VALIDITY", validity, "largest |value| of each named state where this fidelity holds"),
            const("VALIDITY_DOC", validity_doc), const("MULTIPLIER_NAMES", ()),
            const("HAS_DISSIPATION", _dissipative(body)), const("EXPORTS", exports), const("PRESETS", presets),
            const("PRESET_SOURCES", dict(sorted((k, body.preset_sources.get(k, "")) for k in presets))),
            const("SOURCE", body.source), *provenance(digest)),
        body=_body(system, fidelity))
