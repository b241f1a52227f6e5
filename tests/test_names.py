"""A user's names are data, not code (issue 26, root 1).

The damped Chaplygin sleigh (Bloch, *Nonholonomic Mechanics and Control*,
section 1.7; ``tests/models/damped_sleigh.py``) is written twice by a user:
with plain names, and with names that the generated code itself uses or
that are no Python identifiers (``_k0``, the emitter's first hoisted
constant; ``q``, ``p``, ``s``, ``t``, ``ds``, ``np``, ``math``; the keyword
``lambda``; a space; a Greek letter).  The physics is the same, so the
generated functions must give the same numbers bit for bit, while the
module reports the user's names.  What cannot be made safe (two names equal
after Unicode normalization, non-finite defaults, a model name that cannot
name compiled code) is refused when the spec is built.
"""
import math

import numpy as np
import pytest
import sympy as sp

import knifeedge as ke
from knifeedge.derive import ModelSpec, ModelSpecError, emit
from knifeedge.derive.cli import derive_specs

PLAIN = {"a": "a", "k": "k", "c": "c", "x": "x", "y": "y", "phi": "phi", "x_dot": "x_dot", "y_dot": "y_dot",
         "phi_dot": "phi_dot", "v": "v"}
HOSTILE = {"a": "_k0", "k": "lambda", "c": "np", "x": "s", "y": "ds", "phi": "math", "x_dot": "q", "y_dot": "p",
           "phi_dot": "κ rate", "v": "t"}


def sleigh(name: str, names: dict, **overrides) -> ModelSpec:
    """The damped sleigh of ``tests/models/damped_sleigh.py`` with the symbol names ``names``."""
    S = lambda key, **kw: sp.Symbol(names[key], **kw)  # noqa: E731
    a, k, c = (S(n, positive=True) for n in ("a", "k", "c"))
    x, y, phi, x_dot, y_dot, phi_dot, v = (S(n, real=True) for n in ("x", "y", "phi", "x_dot", "y_dot", "phi_dot",
                                                                     "v"))
    axis, across = sp.Matrix([sp.cos(phi), sp.sin(phi)]), sp.Matrix([-sp.sin(phi), sp.cos(phi)])
    contact = sp.Matrix([x_dot, y_dot])
    centre = contact + a * phi_dot * across
    kw = dict(
        name=name, coordinates=(x, y, phi), velocities=(x_dot, y_dot, phi_dot),
        lagrangian=sp.Rational(1, 2) * (centre.dot(centre) + k**2 * phi_dot**2),
        constraints=(contact.dot(across),), dependent=(y,), params=(a, k, c), cyclic={x: 0, y: 0, phi: 0},
        pose=(phi, x, y), quasi_velocities=((v, x_dot, contact.dot(axis)),), dissipation=c * phi_dot**2 / 2,
        defaults={a: 0.5, k: 0.8, c: 0.3, v: 0.1, phi_dot: 1.0}, reversal_events=(phi_dot,),
        events={"heading_speed": phi_dot - v})
    kw.update(overrides)
    return ModelSpec(**kw)


@pytest.fixture(scope="module")
def pair(tmp_path_factory):
    out = tmp_path_factory.mktemp("names")
    systems = derive_specs([sleigh("plain_sleigh", PLAIN), sleigh("hostile_sleigh", HOSTILE)])
    emit.write_all(out, systems, registry=False)
    return ke.load("plain_sleigh", path=out), ke.load("hostile_sleigh", path=out)


@pytest.mark.parametrize("form", ["python", pytest.param("compiled", marks=pytest.mark.slow)])
def test_hostile_names_give_the_same_numbers_bit_for_bit(pair, form):
    """Every generated function of both modules at random states: as Python (``py_func``: a name that shadows
    the generated code's own, ``np`` or ``math``, breaks it as it would the compiled one; nothing to compile) and,
    in the slow tier, compiled (16 functions, ~5 s of CPU)."""
    plain, hostile = pair
    assert hostile.state_names == ("t", "κ rate") and hostile.param_names == ("_k0", "lambda", "np")
    assert hostile.pose_names == ("math", "s", "ds")

    def both(name, *args):
        return [getattr(getattr(m.module, name), "py_func" if form == "python" else "__call__")(*args)
                for m in pair]

    rng = np.random.default_rng(5)
    for _ in range(5):
        y, p = rng.uniform(-2, 2, 2), rng.uniform(0.2, 2, 3)
        yp = np.append(y, rng.uniform(-2, 2, 3))
        for name, args in (("rhs", (0.3, y, p)), ("rhs_pose", (0.3, yp, p)), ("energy", (y, p)),
                           ("power_dissipated", (y, p)), ("multipliers", (y, p)), ("event_values", (y, p)),
                           ("jacobian", (y, p)), ("jacobian_p", (y, p))):
            a, b = both(name, *args)
            assert np.array_equal(a, b), name
            assert np.all(np.isfinite(a)), name


@pytest.mark.parametrize("method", ["DOP853", "scipy:DOP853"])
def test_hostile_names_run_the_same_trajectory(pair, method):
    """The compiled integrators (LLVM IR of the generated code) and SciPy see the same model."""
    plain, hostile = pair
    runs = [ke.simulate(m, m.state(m.default_state), (0.0, 5.0), m.params(m.default_params), method=method)
            for m in pair]
    assert runs[0].success and runs[1].success
    assert np.array_equal(runs[0].y, runs[1].y)
    assert hostile.params({"_k0": 0.5, "lambda": 0.8, "np": 0.3}).tolist() == [0.5, 0.8, 0.3]


def test_generated_code_keeps_user_names_out_of_its_own_namespace():
    from knifeedge.derive.names import identifier

    assert identifier("theta1_dot") == "theta1_dot"
    idents = {identifier(n) for n in ("_k0", "_c0", "q", "t", "lambda", "a b", "κ", "k")}
    assert len(idents) == 8 and all(i.isidentifier() and i.isascii() for i in idents)
    assert not {"_k0", "_c0", "q", "t", "lambda"} & idents


def _names_of(fn) -> tuple:
    """``(unpacked, outer)`` of the function ``fn`` (an ``ast.FunctionDef``), in one walk: the locals it binds
    from an array element (``x = s[0]``), and its arguments with the globals it reads."""
    import ast

    stored, read, unpacked = set(), set(), set()
    for n in ast.walk(fn):
        if isinstance(n, ast.Name):
            (stored if isinstance(n.ctx, ast.Store) else read).add(n.id)
        elif isinstance(n, ast.Assign) and isinstance(n.targets[0], ast.Name) and isinstance(n.value, ast.Subscript):
            unpacked.add(n.targets[0].id)
    return unpacked, {a.arg for a in fn.args.args + fn.args.kwonlyargs} | (read - stored)


def test_no_users_name_can_shadow_what_a_generated_function_reads():
    """In every checked-in module (the emitter's output for every kind of module), a function that unpacks
    users' names (``x = s[0]``) reads no argument or global that a user's name could be: each is a name
    :func:`identifier` never hands to a user's name (``_``-prefixed, :data:`RESERVED`, or a builtin).
    ``jvp_into``'s directions were ``V``: a model with a parameter ``V`` would have overwritten them."""
    import ast
    from pathlib import Path

    from knifeedge.derive.names import identifier, is_plain

    root = Path(__file__).resolve().parents[1] / "generated"
    files = [f for f in (*root.glob("*.py"), *root.glob("linear/*.py")) if f.name not in ("__init__.py", "stages.py")]
    assert len(files) >= 14
    seen = set()
    for f in files:
        tree = ast.parse(f.read_text())
        users = {identifier(x) for n in tree.body if isinstance(n, ast.Assign) and len(n.targets) == 1
                 and getattr(n.targets[0], "id", "").endswith("_NAMES") for x in ast.literal_eval(n.value)}
        for fn in (n for n in tree.body if isinstance(n, ast.FunctionDef)):
            unpacked, outer = _names_of(fn)
            if not users & unpacked:
                continue  # unpacks no user's name from an array (fixed helpers such as ``initial_state``)
            seen.add(fn.name)
            open_to_users = {x for x in outer if is_plain(x)}
            assert not open_to_users, f"{f.name}: {fn.name} reads {sorted(open_to_users)}"
    assert {"jvp_into", "jvp1_into", "rhs_into", "jacobian", "energy"} <= seen
    assert identifier("V") == "V"  # a user's name, so no generated function may read it from outside


@pytest.mark.parametrize("overrides, message", [
    ({"params": (sp.Symbol("k"), sp.Symbol("\U0001d458"), sp.Symbol("c"))}, "Unicode normalization"),
    ({"name": "schlitten_ä"}, "ASCII Python identifier"),
    ({"name": "lambda"}, "not a keyword"),
    ({"params": (sp.Symbol("k"), sp.Symbol('k"""'), sp.Symbol("c\\n"))}, "a quote, a backslash"),
])
def test_names_that_cannot_be_made_safe_are_refused(overrides, message):
    if "params" in overrides:  # a Lagrangian in the two look-alike parameters
        k1, k2, c = overrides["params"]
        x, x_dot = sp.symbols("x x_dot", real=True)
        overrides = dict(overrides, coordinates=(x,), velocities=(x_dot,), constraints=(), dependent=(),
                         cyclic={x: 0}, pose=(), quasi_velocities=(), dissipation=None, reversal_events=(),
                         events={}, defaults={}, lagrangian=(k1 + k2 + c) * x_dot**2)
    name = overrides.pop("name", "s1")
    with pytest.raises(ModelSpecError, match=message):
        sleigh(name, PLAIN, **overrides)


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
def test_non_finite_defaults_and_bounds_are_refused(value):
    a = sp.Symbol("a", positive=True)
    spec = sleigh("s1", PLAIN)
    with pytest.raises(ModelSpecError, match="default of a must be finite"):
        sleigh("s1", PLAIN, defaults={**spec.defaults, a: value})
    with pytest.raises(ModelSpecError, match="finite positive numbers"):
        sleigh("s1", PLAIN, validity={"full": {spec.state[0]: value}})


def test_texts_written_into_the_module_documentation_are_checked():
    with pytest.raises(ModelSpecError, match="triple quotes or a backslash"):
        sleigh("s1", PLAIN, description='a """ sleigh')
    with pytest.raises(ModelSpecError, match="triple quotes or a backslash"):
        sleigh("s1", PLAIN, constraint_labels=("knife\\edge",))
