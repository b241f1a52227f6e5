"""Emitter: reduced systems -> plain Python modules of numba-jitted functions.

Each generated module documents the order of its state and parameter
vectors, carries a header (producer, source, SymPy version, input hash) and
holds only ``math``/``numpy``/``numba`` code.  Output is deterministic for a
given SymPy version (``PYTHONHASHSEED=0`` is set by ``make derive`` and the
staleness test; the generation itself sorts everything it iterates).

Refuses to emit an expression containing a symbol that is not a declared
state, pose coordinate or parameter.
"""
from __future__ import annotations

import hashlib
import inspect
from pathlib import Path

import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

from . import averaging, drawing, engine, models, truncation
from .averaging import AmplitudeSystem

GENERATOR = "derivation/emit.py (make derive)"

class _Printer(PythonCodePrinter):
    """Python printer with bare ``math`` names and small integer powers as products.

    A power printed as a product is always parenthesized, ``(L*L)``, so that
    it keeps its precedence wherever the printer of the enclosing expression
    places it (``x/(L*L)``, never ``x/L*L``).
    """

    def _print_Pow(self, expr, rational=False):
        b, e = expr.args
        if e.is_Integer and 1 < abs(int(e)) <= 4:
            product = "(" + "*".join([self.parenthesize(b, 100)] * abs(int(e))) + ")"
            return product if int(e) > 0 else f"(1.0/{product})"
        return super()._print_Pow(expr, rational=rational)

    def _print_Rational(self, expr):
        return f"({float(expr.p)!r}/{float(expr.q)!r})"


def _code(e: sp.Expr) -> str:
    return _Printer({"fully_qualified_modules": True, "standard": "python3"}).doprint(e)


def input_hash(spec: engine.ModelSpec, fidelity: str) -> str:
    """SHA-256 of what determines a module: the model data, the pipeline sources, SymPy's version."""
    h = hashlib.sha256()
    for part in (
        spec.name, fidelity, sp.__version__,
        sp.srepr(spec.lagrangian), *(sp.srepr(c) for c in spec.constraints),
        inspect.getsource(engine), inspect.getsource(truncation), inspect.getsource(models),
        Path(__file__).read_text(),
        *((inspect.getsource(averaging),) if fidelity == "amplitude" else ()),
        *(sp.srepr(e) for _, _, e in spec.quasi_velocities),
        *((drawing.source_text(),) if fidelity != "amplitude" else ()),
    ):
        h.update(part.encode())
        h.update(b"\0")
    return h.hexdigest()


def _cse_block(exprs, targets, allowed, indent="    "):
    """CSE ``exprs`` and assign them to ``targets``; returns (code lines, op count)."""
    bad = set().union(*(e.free_symbols for e in exprs)) - set(allowed)
    if bad:
        raise ValueError(f"refusing to emit: undeclared symbols {sorted(map(str, bad))}")
    subs, reduced_exprs = sp.cse(exprs, symbols=sp.numbered_symbols("_c"), order="canonical")
    lines = [f"{indent}{s} = {_code(v)}" for s, v in subs]
    lines += [f"{indent}{t} = {_code(v)}" for t, v in zip(targets, reduced_exprs)]
    ops = sum(sp.count_ops(v) for _, v in subs) + sum(sp.count_ops(v) for v in reduced_exprs)
    return lines, int(ops)


def hoist_parameters(exprs, params):
    """Replace the parameter-only subexpressions of ``exprs`` by symbols ``_k0, _k1, ...``.

    A subexpression is hoisted when it depends on parameters only and is
    more than a bare symbol or number; inside a sum or a product the
    parameter-only terms or factors are grouped and hoisted together
    (``4*D*g*theta/L**2`` -> ``_k0*theta``).  Returns ``(constants, new)``:
    the ``(symbol, expression)`` pairs in order of first appearance
    (a deterministic preorder walk of SymPy's canonical argument order) and
    the rewritten expressions.  Evaluating the constants once per
    integration and the rewritten expressions at every step gives the same
    values, computed with fewer operations per step.
    """
    params = set(params)
    memo: dict = {}

    def const(e):
        if e.is_Atom:
            return e
        if e not in memo:
            memo[e] = sp.Symbol(f"_k{len(memo)}")
        return memo[e]

    def walk(e):
        if e.is_Atom:
            return e
        if e.free_symbols <= params:
            return const(e)
        if e.is_Add or e.is_Mul:
            fixed = [a for a in e.args if a.free_symbols <= params]
            rest = [walk(a) for a in e.args if not a.free_symbols <= params]
            if len(fixed) > 1 or (fixed and not fixed[0].is_Atom):
                fixed = [const(e.func(*fixed))]
            return e.func(*fixed, *rest)
        return e.func(*[walk(a) for a in e.args])

    new = [walk(e) for e in exprs]
    return [(symbol, e) for e, symbol in memo.items()], new


def _unpack(names, array, indent="    "):
    return [f"{indent}{n} = {array}[{i}]" for i, n in enumerate(names)]


def _dims(name: str, extra: dict | None = None) -> str:
    """Unit of a state or parameter, from :data:`derivation.models.DIMENSIONS` (or ``extra``)."""
    length, time = (extra or {}).get(name) or models.DIMENSIONS[name]
    num = {0: "", 1: "length"}[length]
    if time < 0:
        return (num or "rad") + "/time" + ("^2" if time == -2 else "")
    return num or "rad"


def _rhs_source(syms_state, syms_par, rates, syms_pose=(), pose_rates=()) -> tuple[str, dict]:
    """Source of the right-hand-side functions shared by every generated module.

    ``rhs_into(t, s, p, ds)`` and ``rhs(t, s, p)`` take the parameters;
    ``constants(p)`` returns ``q``: the parameters followed by the
    parameter-only subexpressions (:func:`hoist_parameters`), and
    ``rhs_q_into(t, s, q, ds)`` is the same right-hand side reading them
    from ``q``, which the compiled integrators call at every stage.  With a
    pose, ``rhs_pose_into``/``rhs_pose``/``rhs_pose_q_into`` likewise.
    Returns the source and the operation count of each function body.
    """
    nl = "\n"
    state, pose, params = [str(x) for x in syms_state], [str(x) for x in syms_pose], [str(x) for x in syms_par]
    n, npose = len(state), len(pose)
    allowed = set(syms_state) | set(syms_par)
    constants, hoisted = hoist_parameters(list(rates) + list(pose_rates), syms_par)
    k_names = [str(k) for k, _ in constants]
    q_names = list(params) + k_names
    const_lines, const_ops = _cse_block([v for _, v in constants], [f"q[{len(params) + i}]" for i in
                                                                    range(len(constants))], set(syms_par))
    allowed_q = set(syms_state) | set(syms_par) | {k for k, _ in constants}
    rhs_lines, rhs_ops = _cse_block(list(rates), [f"ds[{i}]" for i in range(n)], allowed)
    q_lines, q_ops = _cse_block(hoisted[:n], [f"ds[{i}]" for i in range(n)], allowed_q)
    out = f'''@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` ({rhs_ops} operations)."""
{nl.join(_unpack(state, "s"))}
{nl.join(_unpack(params, "p"))}
{nl.join(rhs_lines)}


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length {n}."""
    ds = np.empty({n})
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the {len(constants)} parameter-only subexpressions of the right-hand side ({const_ops} operations)."""
    q = np.empty({len(q_names)})
{nl.join(_unpack(params, "p"))}
{nl.join(f"    q[{i}] = {x}" for i, x in enumerate(params))}
{nl.join(const_lines)}
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` ({q_ops} operations)."""
{nl.join(_unpack(state, "s"))}
{nl.join(_unpack(q_names, "q"))}
{nl.join(q_lines)}
'''
    ops = {"rhs": rhs_ops, "constants": const_ops, "rhs_q": q_ops}
    if not npose:
        return out, ops
    allowed_pose = allowed | set(syms_pose)
    rhsp_lines, rhsp_ops = _cse_block(list(rates) + list(pose_rates), [f"ds[{i}]" for i in range(n + npose)],
                                      allowed_pose)
    qp_lines, qp_ops = _cse_block(hoisted, [f"ds[{i}]" for i in range(n + npose)], allowed_q | set(syms_pose))
    unpack_pose = [f"    {x} = s[{n + i}]" for i, x in enumerate(pose)]
    ops.update(rhs_pose=rhsp_ops, rhs_pose_q=qp_ops)
    return out + f'''

@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds`` ({rhsp_ops} operations)."""
{nl.join(_unpack(state, "s"))}
{nl.join(unpack_pose)}
{nl.join(_unpack(params, "p"))}
{nl.join(rhsp_lines)}


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length {n + npose}."""
    ds = np.empty({n + npose})
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p`` ({qp_ops} operations)."""
{nl.join(_unpack(state, "s"))}
{nl.join(unpack_pose)}
{nl.join(_unpack(q_names, "q"))}
{nl.join(qp_lines)}
''', ops


def module_source(system, fidelity: str) -> str:
    """Source of the generated module of ``system`` (a reduced or an amplitude system)."""
    if isinstance(system, AmplitudeSystem):
        return amplitude_module_source(system, fidelity)
    from . import rigid, rigid_emit  # rigid bodies: derivation/rigid.py
    if isinstance(system, rigid.RollingSystem):
        return rigid_emit.module_source(system, fidelity)
    spec = system.spec
    state = [str(s) for s in system.state]
    pose = [str(q) for q in spec.pose]
    params = [str(p) for p in spec.params]
    n, npose = len(state), len(pose)
    rates = system.state_rhs()
    allowed = set(system.state) | set(spec.params)
    pose_exprs = [system.pose_rates[q] for q in spec.pose]
    pose_lines, pose_ops = _cse_block(pose_exprs, [f"out[{i}]" for i in range(npose)], allowed | set(spec.pose))
    rhs_src, rhs_ops = _rhs_source(system.state, spec.params, rates, spec.pose, pose_exprs)
    energy_lines, energy_ops = _cse_block([system.energy], ["energy"], allowed)
    lam = list(system.multipliers)
    lam_lines, lam_ops = _cse_block(lam, [f"out[{i}]" for i in range(len(lam))], allowed)
    labels = ", ".join(spec.constraint_labels)
    digest = input_hash(spec, fidelity)
    fid_doc = {
        "full": "exact consequences of the paper's Lagrangian and constraints, nothing dropped",
        "reduced": (f"degree-{truncation.ORDER} Taylor polynomial of the full vector field in the tilts "
                    "and tilt rates (tilt equations to O(theta), spin equation to O(theta^2))"),
    }[fidelity]
    state_doc = "\n".join(f"    s[{i}] = {nm:<12} [{_dims(nm)}]" for i, nm in enumerate(state))
    pose_doc = "\n".join(f"    s[{n + i}] = {nm:<12} [{_dims(nm)}]" for i, nm in enumerate(pose))
    par_doc = "\n".join(f"    p[{i}] = {nm:<12} [{_dims(nm)}]" for i, nm in enumerate(params))
    unpack_s = _unpack(state, "s")
    unpack_p = _unpack(params, "p")
    unpack_pose = [f"    {q} = s[{n + i}]" for i, q in enumerate(pose)]
    nl = "\n"
    return f'''"""{spec.name}, fidelity {fidelity}: {fid_doc}.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by {GENERATOR} from derivation/models.py (model {spec.name!r},
constraints {labels}) through derivation/engine.py{" and derivation/truncation.py" if fidelity != "full" else ""}.
SymPy {sp.__version__}; input hash sha256:{digest}

{spec.description}

State vector ``s`` (closed state; the pose follows by quadrature):
{state_doc}
Pose-extended state (``*_pose`` functions) appends:
{pose_doc}
Parameter vector ``p``:
{par_doc}
Multipliers are per unit mass (the mass M cancels), in the order {labels}.
Energy is per unit mass.
"""
import math

import numpy as np
from numba import njit

MODEL = {spec.name!r}
FIDELITY = {fidelity!r}
STATE_NAMES = {tuple(state)!r}
POSE_NAMES = {tuple(pose)!r}
PARAM_NAMES = {tuple(params)!r}
TILT_NAMES = {tuple(str(q) for q in spec.small)!r}
#: the spin rate, whose zero crossings are the spin reversals
SPIN_NAME = "phi_dot"
MULTIPLIER_NAMES = {tuple(spec.constraint_labels)!r}
INPUT_HASH = {digest!r}
SYMPY_VERSION = {sp.__version__!r}
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {dict(rhs_ops, pose_rates=pose_ops, energy=energy_ops, multipliers=lam_ops)!r}


{rhs_src}

@njit(cache=True)
def pose_rates(s, p):
    """Return (phi_dot, x_dot, y_dot) at the pose-extended state ``s`` ({pose_ops} operations)."""
    out = np.empty({npose})
{nl.join(unpack_s)}
{nl.join(unpack_pose)}
{nl.join(unpack_p)}
{nl.join(pose_lines)}
    return out


@njit(cache=True)
def energy(s, p):
    """Energy per unit mass ({energy_ops} operations)."""
{nl.join(unpack_s)}
{nl.join(unpack_p)}
{nl.join(energy_lines)}
    return energy


@njit(cache=True)
def multipliers(s, p):
    """Lagrange multipliers (contact forces per unit mass) {labels} ({lam_ops} operations)."""
    out = np.empty({len(lam)})
{nl.join(unpack_s)}
{nl.join(unpack_p)}
{nl.join(lam_lines)}
    return out
''' + drawing.module_source(system)


def _coefficient_block(name: str, exprs, params, doc: str) -> tuple[str, int]:
    """A jitted ``name(p)`` returning the parameter-only expressions ``exprs`` as an array."""
    lines, ops = _cse_block(list(exprs), [f"out[{i}]" for i in range(len(exprs))], set(params))
    nl = "\n"
    return f'''

@njit(cache=True)
def {name}(p):
    """{doc} ({ops} operations)."""
    out = np.empty({len(exprs)})
{nl.join(_unpack([str(q) for q in params], "p"))}
{nl.join(lines)}
    return out
''', ops


def amplitude_module_source(system: AmplitudeSystem, fidelity: str) -> str:
    """Source of an ``amplitude`` module: slow flow, invariants and its coefficients; no pose, no multipliers."""
    spec = system.spec
    state = [str(s) for s in system.state]
    params = [str(p) for p in spec.params]
    n, n_tilt = len(state), len(system.amplitudes)
    allowed = set(system.state) | set(spec.params)
    rhs_src, rhs_ops = _rhs_source(system.state, spec.params, system.rates)
    inv_names = list(system.invariants)
    inv_lines, inv_ops = _cse_block(list(system.invariants.values()), [f"out[{i}]" for i in range(len(inv_names))],
                                    allowed)
    energy_lines, energy_ops = _cse_block([system.energy], ["energy"], allowed)
    freq_src, freq_ops = _coefficient_block(
        "frequencies", system.frequencies, spec.params,
        "Angular frequencies omega_i of the tilts " + ", ".join(map(str, system.tilts)) + " at zero spin")
    extra_src, extra_ops = "", {}
    if system.growth is not None:
        spin = system.spin_amplitudes[0]
        drive = sp.Poly(sp.expand(system.rates[n_tilt]), *system.amplitudes)
        if drive.is_homogeneous and drive.total_degree() == 2 and all(
                sum(1 for k in m if k) == 1 for m in drive.monoms()):
            k_i = [sp.factor(drive.coeff_monomial(a**2)) for a in system.amplitudes]
            src1, ops1 = _coefficient_block(
                "growth_rates", system.growth, spec.params,
                f"c_i in d(A_i)/dt = c_i {spin} A_i [dimensionless]")
            src2, ops2 = _coefficient_block(
                "drive_rates", k_i, spec.params,
                f"k_i in d({spin})/dt = sum_i k_i A_i^2 [1/time^2]")
            extra_src, extra_ops = src1 + src2, {"growth_rates": ops1, "drive_rates": ops2}
    digest = input_hash(spec, fidelity)
    dims = system.dimensions
    state_doc = "\n".join(f"    s[{i}] = {nm:<12} [{_dims(nm, dims)}]" for i, nm in enumerate(state))
    par_doc = "\n".join(f"    p[{i}] = {nm:<12} [{_dims(nm)}]" for i, nm in enumerate(params))
    flow_doc = "\n".join(f"    d{nm}/dt = {r}" for nm, r in zip(state, system.rates))
    inv_doc = "\n".join(f"    {k}: {v}" for k, v in system.invariants.items())
    phase_doc = ", ".join(f"d(beta_{i + 1})/dt = {r}" for i, r in enumerate(system.phase_rates))
    ops = {**rhs_ops, "energy": energy_ops, "invariants": inv_ops, "frequencies": freq_ops, **extra_ops}
    nl = "\n"
    return f'''"""{spec.name}, fidelity {fidelity}: first-order averaged slow flow of the reduced equations.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by {GENERATOR} from derivation/models.py (model {spec.name!r})
through derivation/engine.py, derivation/truncation.py and derivation/averaging.py.
SymPy {sp.__version__}; input hash sha256:{digest}

{spec.description}

Tilts theta_i = A_i cos(psi_i), theta_i_dot = -omega_i A_i sin(psi_i), averaged
over independent fast phases psi_i, leading order in (spin rate)/omega.
Averaged phase drifts: {phase_doc} (the phases do not enter the slow flow).

State vector ``s``:
{state_doc}
Parameter vector ``p``:
{par_doc}
Slow flow:
{flow_doc}
Invariants (conserved by the slow flow):
{inv_doc}
No pose and no multipliers at this fidelity.
"""
import math

import numpy as np
from numba import njit

MODEL = {spec.name!r}
FIDELITY = {fidelity!r}
STATE_NAMES = {tuple(state)!r}
POSE_NAMES = ()
PARAM_NAMES = {tuple(params)!r}
TILT_NAMES = {tuple(str(a) for a in system.amplitudes)!r}
#: the slow spin rate, whose zero crossings are the spin reversals
SPIN_NAME = {str(system.spin_amplitudes[0])!r}
MULTIPLIER_NAMES = ()
#: conserved quantities returned by ``invariants`` (``energy`` is the averaged energy per unit mass)
INVARIANT_NAMES = {tuple(inv_names)!r}
INPUT_HASH = {digest!r}
SYMPY_VERSION = {sp.__version__!r}
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {ops!r}


{rhs_src}

@njit(cache=True)
def energy(s, p):
    """Averaged energy per unit mass, a conserved quantity of the slow flow ({energy_ops} operations)."""
{nl.join(_unpack(state, "s"))}
{nl.join(_unpack(params, "p"))}
{nl.join(energy_lines)}
    return energy


@njit(cache=True)
def invariants(s, p):
    """Conserved quantities {inv_names} ({inv_ops} operations)."""
    out = np.empty({len(inv_names)})
{nl.join(_unpack(state, "s"))}
{nl.join(_unpack(params, "p"))}
{nl.join(inv_lines)}
    return out
{freq_src}{extra_src}'''


def build_all() -> dict:
    """Derive every model at every fidelity: ``{(model, fidelity): ReducedSystem}``."""
    out = {}
    for name in sorted(models.MODELS):
        spec = models.MODELS[name]
        full = engine.derive(spec)
        out[(name, "full")] = full
        if spec.small:
            out[(name, "reduced")] = truncation.reduced(full)
            out[(name, "amplitude")] = averaging.average(out[(name, "reduced")])
    from . import rigid, rigid_models  # rigid bodies built with the front end
    for name, body in sorted(rigid_models.MODELS.items()):
        out[(name, "full")] = rigid.derive(body)
    return out


def registry_source(systems: dict) -> str:
    entries = "\n".join(
        f"    ({m!r}, {f!r}): {m + '_' + f!r}," for (m, f) in sorted(systems)
    )
    return f'''"""Registry of the generated model modules.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by {GENERATOR}; SymPy {sp.__version__}.
"""

#: (model, fidelity) -> module name inside this package
MODULES = {{
{entries}
}}
'''


def write_all(out_dir: Path, systems: dict | None = None) -> list[Path]:
    """Write every module (and the registry) into ``out_dir``; return the paths."""
    systems = systems if systems is not None else build_all()
    out_dir.mkdir(parents=True, exist_ok=True)
    paths = []
    for (name, fidelity), system in sorted(systems.items()):
        path = out_dir / f"{name}_{fidelity}.py"
        path.write_text(module_source(system, fidelity))
        paths.append(path)
    reg = out_dir / "__init__.py"
    reg.write_text(registry_source(systems))
    paths.append(reg)
    return paths
