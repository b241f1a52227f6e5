"""A model of the user's own, outside the package: ModelSpec contract, `knifeedge derive`, `load(path=)`.

The model is a Chaplygin sleigh with a viscous torque (``tests/models/damped_sleigh.py``,
Rayleigh function ``R = c phi_dot^2/2``).  Its dissipated power is ``2R = c phi_dot^2``
(Rayleigh's function is homogeneous of degree two in the velocities: Goldstein,
*Classical Mechanics*, section 1.5), and ``energy + dissipated work`` is constant
along a run, checked against an independent integrator (SciPy, augmented state).
"""
import math
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import knifeedge as ke
from knifeedge import cli
from knifeedge.derive import ModelSpec, ModelSpecError
from knifeedge.integrators import COMPILED_METHODS

HERE = Path(__file__).resolve().parent
MODEL_FILE = HERE / "models" / "damped_sleigh.py"


@pytest.fixture(scope="module")
def derived(tmp_path_factory):
    out = tmp_path_factory.mktemp("my_models")
    assert cli.main(["derive", str(MODEL_FILE), "--out", str(out)]) == 0
    return out


def test_derive_writes_deterministic_modules_with_header(derived, tmp_path):
    text = (derived / "damped_sleigh_full.py").read_text()
    assert "DO NOT EDIT BY HAND" in text and "input hash sha256:" in text and "OP_COUNTS" in text
    assert "from tests/models/damped_sleigh.py" in text or "from damped_sleigh.py" in text
    subprocess.run([sys.executable, "-m", "knifeedge.derive", "--out", str(tmp_path), str(MODEL_FILE)],
                   check=True, capture_output=True, env={"PYTHONHASHSEED": "7", "PATH": ""})
    assert (tmp_path / "damped_sleigh_full.py").read_bytes() == (derived / "damped_sleigh_full.py").read_bytes()


def test_loaded_model_reads_everything_from_its_module(derived):
    m = ke.load("damped_sleigh", fidelity="full", path=derived)
    assert m.state_names == ("v", "phi_dot") and m.state_units == ("m/s", "rad/s")
    assert m.param_names == ("a", "k", "c") and m.param_domains == ("positive",) * 3
    assert m.default_params == {"a": 0.5, "k": 0.8, "c": 0.3} and m.reversal_events == ("phi_dot",)
    assert m.has_dissipation and m.source_path == (derived / "damped_sleigh_full.py").resolve()
    assert ke.load("damped_sleigh", path=str(derived)) is m
    with pytest.raises(ValueError, match="no module for model"):
        ke.load("damped_sleigh", fidelity="reduced", path=derived)
    with pytest.raises(ValueError, match="`c` must be positive"):
        m.params(a=0.5, k=0.8, c=-1.0)


def test_power_is_twice_the_rayleigh_function(derived):
    m = ke.load("damped_sleigh", path=derived)
    rng = np.random.default_rng(3)
    for _ in range(5):
        y, p = rng.uniform(-2, 2, 2), rng.uniform(0.2, 2, 3)
        assert m.power_dissipated(y, p) == pytest.approx(p[2] * y[1] ** 2, rel=1e-14)


def test_energy_plus_dissipated_work_is_constant(derived):
    """Along an independent SciPy run of (state, work): E(t) + W(t) = E(0), with W' = power."""
    from scipy.integrate import solve_ivp

    m = ke.load("damped_sleigh", path=derived)
    p = m.params(m.default_params)
    y0 = m.state(m.default_state)

    def f(t, z):
        return np.append(m.rhs(t, z[:2], p), m.power_dissipated(z[:2], p))

    sol = solve_ivp(f, (0, 20), np.append(y0, 0.0), method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True)
    t = np.linspace(0, 20, 201)
    z = sol.sol(t)
    balance = m.energy(z[:2], p) + z[2]
    assert np.max(np.abs(balance - m.energy(y0, p))) < 1e-10 * m.energy(y0, p)
    assert z[2, -1] > 0.5 * m.energy(y0, p)  # the damping matters: most of the energy is gone
    # the package's own integrator and quadrature agree with it
    r = ke.simulate(m, y0, (0, 20), p, t_eval=np.linspace(0, 20, 20001))
    work = m.dissipated_work(r.t, r.y, p)
    assert np.max(np.abs(r.energy + work - m.energy(y0, p))) < 1e-7


@pytest.mark.parametrize("method", [m if m == "DOP853" or m.startswith("scipy:") else pytest.param(m, marks=pytest.mark.slow)
                                    for m in sorted(ke.METHODS)])
def test_every_method_runs_a_model_from_a_path(derived, method):
    m = ke.load("damped_sleigh", path=derived, pose=True)
    fixed = method in COMPILED_METHODS and COMPILED_METHODS[method].fixed_step
    r = ke.simulate(m, {**m.default_state, "phi": 0.0, "x": 0.0, "y": 0.0}, (0, 5), m.default_params,
                    method=method, **({"h": 1e-3} if fixed else {"rtol": 1e-8}))
    assert r.success, r.message
    ref = ke.simulate(m, {**m.default_state, "phi": 0.0, "x": 0.0, "y": 0.0}, (0, 5), m.default_params,
                      rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(r.y[:, -1], ref.y[:, -1], rtol=1e-4, atol=1e-6)


def test_cli_simulates_a_model_from_a_path_with_its_defaults(derived, capsys, tmp_path):
    rc = cli.main(["simulate", "--model", "damped_sleigh", "--path", str(derived), "--t-end", "5",
                   "--out", str(tmp_path / "run.csv")])
    out = capsys.readouterr().out
    assert rc == 0 and "a=0.5, k=0.8, c=0.3" in out and "v=0.1, phi_dot=1" in out
    assert (tmp_path / "run.csv").read_text().startswith("t,v,phi_dot")


@pytest.mark.slow
def test_cli_simulates_every_builtin_model_from_its_defaults(capsys):
    """`knifeedge simulate --model NAME` needs nothing but the module's defaults, for every registered model."""
    for name in ke.MODEL_NAMES:
        assert cli.main(["simulate", "--model", name, "--t-end", "1", "--n-eval", "3"]) == 0, name
    capsys.readouterr()


def test_derive_without_sympy_says_how_to_get_it(tmp_path):
    code = ("import sys; sys.modules['sympy'] = None\n"
            "from knifeedge import cli\n"
            f"sys.exit(cli.main(['derive', {str(MODEL_FILE)!r}, '--out', {str(tmp_path)!r}]))\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 2 and "pip install 'knifeedge[derive]'" in r.stderr


# -- the ModelSpec contract --------------------------------------------------------------
x, y, th = sp.symbols("x y theta", real=True)
xd, yd, thd = sp.symbols("x_dot y_dot theta_dot", real=True)
g = sp.Symbol("g", positive=True)


def _spec(**kw):
    base = dict(name="toy", coordinates=(x, y, th), velocities=(xd, yd, thd),
                lagrangian=(xd**2 + yd**2 + thd**2) / 2 - g * sp.cos(th), constraints=(xd * sp.sin(th) - yd * sp.cos(th),),
                dependent=(y,), cyclic={x: 0, y: 0}, params=(g,))
    base.update(kw)
    return ModelSpec(**base)


def test_spec_problems_are_collected_and_name_the_users_line():
    here = f"{Path(__file__).name}:"
    m = sp.Symbol("m", positive=True)
    with pytest.raises(ModelSpecError) as err:
        _spec(lagrangian=m * (xd**2 + yd**2 + thd**2) / 2, constraints=(xd**2 - yd,), small=(x,))
    msg = str(err.value)
    assert "3 problems" in msg and here in msg
    assert "undeclared symbols ['m']" in msg
    assert "must be affine in the velocities" in msg
    assert "`small` entries [x]" in msg


def test_spec_refuses_unknown_reversal_events_units_and_defaults():
    with pytest.raises(ModelSpecError) as err:
        _spec(reversal_events=(x,), units={"q9": "m"}, defaults={g: -1.0})
    msg = str(err.value)
    assert "`reversal_events` entry x" in msg and "`units` names ['q9']" in msg and "default of g must be positive" in msg


def test_a_false_symmetry_is_reported_with_the_spec_line(tmp_path):
    """theta is not cyclic here (gravity depends on it): the derivation says so, naming the model file's line."""
    f = tmp_path / "bad_model.py"
    f.write_text("import sympy as sp\nfrom knifeedge.derive import ModelSpec\n"
                 "x, y, th = sp.symbols('x y theta', real=True)\n"
                 "xd, yd, thd = sp.symbols('x_dot y_dot theta_dot', real=True)\n"
                 "g = sp.Symbol('g', positive=True)\n"
                 "MODEL = ModelSpec(name='bad', coordinates=(x, y, th), velocities=(xd, yd, thd),\n"
                 "    lagrangian=(xd**2 + yd**2 + thd**2) / 2 - g * sp.cos(th),\n"
                 "    constraints=(xd * sp.sin(th) - yd * sp.cos(th),), dependent=(y,),\n"
                 "    cyclic={x: 0, y: 0, th: 0}, params=(g,))\n")
    with pytest.raises(ValueError) as err:
        from knifeedge.derive import derive_files
        derive_files([f], tmp_path / "out")
    assert "bad_model.py:6" in str(err.value) and "symmetr" in str(err.value)


def test_reduced_fidelity_outside_its_domain_warns_and_says_so():
    """Issue 11 item 4: reduced single mode from theta = 3.1 (far outside small tilts)."""
    m = ke.load("single_mode", fidelity="reduced")
    y0 = {**m.default_state, "theta": 3.1}
    with pytest.warns(ke.ValidityWarning, match="theta"):
        r = ke.simulate(m, y0, (0, 10), m.default_params)
    assert not r.in_validity_domain and "|theta| reached" in r.validity_message
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        inside = ke.simulate(m, m.default_state, (0, 10), m.default_params)
    assert inside.in_validity_domain and inside.validity_message == ""
    full = ke.simulate(ke.load("single_mode"), y0, (0, 10), m.default_params)
    assert full.in_validity_domain


@pytest.mark.slow  # two derivations in subprocesses (~4 s of CPU), as `make check-generated` runs them
def test_check_reports_a_hand_edit_and_never_overwrites_it(derived, tmp_path):
    """Issue 11 item 5: `make check-generated` (python -m knifeedge.derive --check) derives into a temporary
    folder and compares; a hand edit of the checked-in folder is reported and left in place."""
    import shutil

    target = tmp_path / "checked_in"
    shutil.copytree(derived, target)
    cmd = [sys.executable, "-m", "knifeedge.derive", "--check", "--out", str(target), str(MODEL_FILE)]
    assert subprocess.run(cmd, capture_output=True).returncode == 0
    module = target / "damped_sleigh_full.py"
    edited = module.read_text().replace("DEFAULT_PARAMS = {'a': 0.5", "DEFAULT_PARAMS = {'a': 0.6")
    module.write_text(edited)
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 1 and "'a': 0.6" in r.stderr and "run make derive" in r.stderr
    assert module.read_text() == edited


def test_reversal_prediction_outside_small_tilts_warns_and_says_so():
    """Issue 11 item 4: the averaged prediction from theta = 3.1 is flagged, from the default state it is not."""
    m = ke.load("single_mode", fidelity="reduced")
    with pytest.warns(ke.ValidityWarning, match="A_theta"):
        far = ke.reversal_time(m, m.default_params, {**m.default_state, "theta": 3.1})
    assert not far.in_validity_domain and "amplitude equations" in far.validity_message
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        near = ke.reversal_time(m, m.default_params, m.default_state)
    assert near.in_validity_domain


def test_model_specific_helpers_and_event_functions_reach_the_runtime(derived):
    """`extra_source`/`exports` (presets, a state builder) and `events` (scalar functions of the state)."""
    m = ke.load("damped_sleigh", path=derived)
    assert m.exports == ("PRESETS", "initial_state")
    assert m.module.PRESETS["light_damping"]["c"] == 0.05
    np.testing.assert_array_equal(m.module.initial_state(0.2, 1.5), [0.2, 1.5])
    assert m.event_names == ("heading_speed",)
    assert m.event_values(np.array([0.2, 1.5]), m.params(m.default_params)) == pytest.approx([1.3])
