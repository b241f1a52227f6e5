"""Run-time inputs: ``ModelSpec(inputs=...)`` and ``simulate(..., inputs=...)`` (issue 22, item 1).

The Chaplygin sleigh steered by a control torque ``tau`` given at run time
(``tests/models/controlled_sleigh.py``; Bloch, *Nonholonomic Mechanics and
Control*, section 1.7), with a viscous torque ``-c omega``, has per unit mass,
with ``v`` the speed of the contact point along the axis and ``omega`` the
turning rate,

    dv/dt = a omega^2,    (k^2 + a^2) d(omega)/dt = -a v omega - c omega + tau(t),

written here by hand and integrated with SciPy; the lateral force of the knife
edge (its multiplier) is the lateral acceleration of the centre of mass,
``a d(omega)/dt + v omega``.  The runs start at ``t0 = 1.3`` so that a method
that passed the time since the start, or an input read at the wrong time, is
wrong.
"""
import math
from pathlib import Path

import numpy as np
import pytest
from numba import njit
from scipy.integrate import solve_ivp

import knifeedge as ke
from knifeedge import cli

HERE = Path(__file__).resolve().parent
A, K, C = 0.5, 0.8, 0.1
T0, T1 = 1.3, 9.0
Y0 = np.array([0.1, 0.0])
#: sample times of the piecewise-linear input: uneven, covering [T0, T1]
SAMPLE_T = np.array([0.0, 1.0, 1.7, 2.2, 3.1, 4.0, 4.6, 5.5, 6.3, 7.2, 8.1, 9.5])
SAMPLE_U = np.array([0.0, 0.3, -0.2, 0.5, 0.1, -0.4, 0.0, 0.6, 0.2, -0.3, 0.4, 0.1])


def triangle(t: float) -> float:
    """The samples' piecewise-linear interpolant in closed form: on [t_j, t_j+1] the straight line."""
    j = min(max(np.searchsorted(SAMPLE_T, t, side="right") - 1, 0), SAMPLE_T.size - 2)
    t0, t1, u0, u1 = SAMPLE_T[j], SAMPLE_T[j + 1], SAMPLE_U[j], SAMPLE_U[j + 1]
    return u0 + (u1 - u0) * (t - t0) / (t1 - t0)


def by_hand(t, z, torque):
    v, w = z
    return [A * w * w, (-A * v * w - C * w + torque(t)) / (K * K + A * A)]


def reference(torque, t_eval, breaks=()):
    """The hand-written ODE integrated with SciPy, piece by piece between ``breaks`` (where the torque kinks)."""
    cuts = [T0, *[b for b in breaks if T0 < b < T1], T1]
    y, out = Y0, []
    for a, b in zip(cuts[:-1], cuts[1:]):
        sol = solve_ivp(by_hand, (a, b), y, args=(torque,), method="DOP853", rtol=1e-13, atol=1e-15,
                        dense_output=True)
        inside = t_eval[(t_eval >= a) & ((t_eval < b) | (b == T1))]
        out.append(sol.sol(inside) if inside.size else np.empty((2, 0)))
        y = sol.y[:, -1]
    return np.concatenate(out, axis=1)


@pytest.fixture(scope="module")
def model(tmp_path_factory):
    out = tmp_path_factory.mktemp("controlled")
    assert cli.main(["derive", str(HERE / "models" / "controlled_sleigh.py"), "--out", str(out)]) == 0
    return ke.load("controlled_sleigh", path=out)


@pytest.fixture(scope="module")
def p(model):
    return model.params(a=A, k=K, c=C)


T_EVAL = np.linspace(T0, T1, 41)


@pytest.fixture(scope="module")
def piecewise_reference():
    return reference(triangle, T_EVAL, SAMPLE_T)


def test_the_module_declares_its_inputs(model):
    assert model.input_names == ("tau",)
    assert model.param_names == ("a", "k", "c")  # the slots are not parameters
    assert model.time_dependent and model.has_power_input


# the fixed-step methods in the slow tier: each compiles a kernel for this model alone (RK4 ~3 s of CPU cold);
# the samples are read by the same interpolation on every compiled method (inputs.py)
METHODS = [("DOP853", {}), ("scipy:DOP853", {}),
           *(pytest.param(m, kw, marks=pytest.mark.slow) for m, kw in [
               ("RK4", {"h": 2e-3}), ("DP54", {}), ("Tsit5", {}), ("gauss4", {"h": 5e-3}), ("gauss6", {"h": 1e-2}),
               ("implicit_midpoint", {"h": 1e-3}), ("scipy:RK45", {}), ("scipy:LSODA", {}), ("scipy:Radau", {})])]


@pytest.mark.parametrize("method, kw", METHODS)
def test_samples_are_the_piecewise_linear_input(model, p, piecewise_reference, method, kw):
    """Samples against the same input in closed form (the straight lines between them), on every method."""
    r = ke.simulate(model, Y0, (T0, T1), p, method=method, t_eval=T_EVAL, rtol=1e-11, atol=1e-13,
                    inputs={"tau": (SAMPLE_T, SAMPLE_U)}, **kw)
    assert r.success, r.message
    assert np.array_equal(r.t, T_EVAL)
    assert np.max(np.abs(r.y - piecewise_reference)) < (2e-9 if method != "implicit_midpoint" else 2e-5)
    assert np.max(np.abs(piecewise_reference[1])) > 0.2  # the torque turned the sleigh


def test_a_constant_input(model, p):
    want = reference(lambda t: 0.3, T_EVAL)
    for method, kw in (("DOP853", {}), ("scipy:DOP853", {})):
        r = ke.simulate(model, Y0, (T0, T1), p, method=method, t_eval=T_EVAL, rtol=1e-11, atol=1e-13,
                        inputs={"tau": 0.3}, **kw)
        assert np.max(np.abs(r.y - want)) < 2e-9, method


def test_a_numba_function_on_a_scipy_method(model, p):
    from numba import njit

    @njit
    def torque(t):
        return 0.4 * math.sin(t)

    want = reference(lambda t: 0.4 * math.sin(t), T_EVAL)
    r = ke.simulate(model, Y0, (T0, T1), p, method="scipy:DOP853", t_eval=T_EVAL, rtol=1e-11, atol=1e-13,
                    inputs={"tau": torque})
    assert np.max(np.abs(r.y - want)) < 2e-9


#: the driven sleigh's torque ``TAU0 sin t`` (a numba function of the time, as a user gives it)
TAU0 = 0.4


@njit
def sine_torque(t):
    return TAU0 * math.sin(t)


@pytest.fixture(scope="module")
def sine_reference():
    return reference(lambda t: TAU0 * math.sin(t), T_EVAL)


#: every compiled method (each compiles a kernel of its own, the right-hand side that calls the function: the slow
#: tier) with its step
FUNCTION_METHODS = {"DOP853": {}, "DP54": {}, "Tsit5": {}, "RK4": {"h": 2e-3}, "gauss4": {"h": 5e-3},
                    "gauss6": {"h": 1e-2}, "implicit_midpoint": {"h": 1e-3}}


def test_the_function_checks_cover_every_compiled_method():
    from knifeedge.integrators import COMPILED_METHODS

    assert set(FUNCTION_METHODS) == set(COMPILED_METHODS)


@pytest.mark.slow
@pytest.mark.parametrize("method", FUNCTION_METHODS)
def test_a_numba_function_on_a_compiled_method(model, p, sine_reference, method):
    """The torque ``TAU0 sin t`` as a numba function, called at the true time by the compiled right-hand side,
    against the hand-written ODE (SciPy, rtol 1e-13); the lateral force after the run reads the same torque."""
    r = ke.simulate(model, Y0, (T0, T1), p, method=method, t_eval=T_EVAL, rtol=1e-11, atol=1e-13,
                    inputs={"tau": sine_torque}, **FUNCTION_METHODS[method])
    assert r.success, r.message
    assert np.max(np.abs(r.y - sine_reference)) < (2e-9 if method != "implicit_midpoint" else 2e-5)
    assert np.max(np.abs(sine_reference[1])) > 0.2  # the torque turned the sleigh
    lam = model.multipliers(r.y, p, r.t, inputs=r.inputs)[0]
    rates = np.array([by_hand(t, z, lambda s: TAU0 * math.sin(s)) for t, z in zip(r.t, r.y.T)]).T
    assert np.allclose(lam, A * rates[1] + r.y[0] * r.y[1], rtol=1e-12, atol=1e-14)


@pytest.mark.slow  # the DOP853 kernel of the function input (shared with the test above)
def test_samples_of_the_function_agree_to_the_interpolation_error(model, p):
    """The same torque given as samples every ``H`` (piecewise linear: off by at most ``TAU0 H^2 / 8``) moves the
    state by about that error times the run's length over the inertia ``k^2 + a^2``: no more, and not much less
    (the function, not the samples, drove the first run)."""
    h = 0.01
    ts = np.arange(0.0, T1 + h, h)
    runs = [ke.simulate(model, Y0, (T0, T1), p, t_eval=T_EVAL, rtol=1e-11, atol=1e-13, inputs={"tau": given})
            for given in (sine_torque, (ts, TAU0 * np.sin(ts)))]
    bound = TAU0 * h * h / 8 * (T1 - T0) / (K * K + A * A)
    diff = np.max(np.abs(runs[0].y - runs[1].y))
    assert 1e-3 * bound < diff < bound, (diff, bound)


def _function_module(folder, name: str, amplitude: float):
    """A user's file defining the numba function ``torque`` (``amplitude sin t``), imported as ``name``."""
    import importlib.util
    import sys

    path = folder / f"{name}.py"
    path.write_text(f"import math\nfrom numba import njit\n\n\n@njit\ndef torque(t):\n"
                    f"    return {amplitude!r} * math.sin(t)\n")
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def test_the_kernel_is_named_after_the_function(model, tmp_path):
    """The compiled right-hand side that calls a function input is cached under a name that stands for the
    function's file (its SHA-256) or, typed in a session, its code: a changed function gets another name on
    every compiled method (and so is compiled, not loaded); the same function the same name."""
    from knifeedge.inputs import Inputs
    from knifeedge.integrators import kernel_module
    from knifeedge.simulate import driven_model

    def names(f):
        m = driven_model(model, Inputs(("tau",), ("function",), ((f, None),)))
        return (kernel_module(m, "DOP853").path.name, kernel_module(m, "RK4").solve.py_func.__knifeedge_cache__[1])

    first = names(_function_module(tmp_path, "user_torque", 0.4).torque)
    assert names(_function_module(tmp_path, "user_torque", 0.4).torque) == first
    changed = names(_function_module(tmp_path, "user_torque", 0.5).torque)
    assert changed[0] != first[0] and changed[1] != first[1]
    typed = []
    for amplitude in (0.4, 0.5, 0.4):
        space: dict = {"njit": njit, "math": math}
        exec(f"@njit\ndef torque(t):\n    return {amplitude} * math.sin(t)\n", space)
        typed.append(names(space["torque"]))
    assert typed[0] != typed[1] and typed[0] == typed[2]


@pytest.mark.slow  # compiles the RK4 kernel twice
def test_a_changed_function_is_compiled_again(model, p, tmp_path):
    """The file of the function input is changed between two runs: the second run reads the new function."""
    t_eval = np.linspace(T0, T1, 9)
    for amplitude in (0.4, 0.7):
        torque = _function_module(tmp_path, "user_torque_run", amplitude).torque
        r = ke.simulate(model, Y0, (T0, T1), p, method="RK4", h=2e-3, t_eval=t_eval, inputs={"tau": torque})
        want = reference(lambda t: amplitude * math.sin(t), t_eval)
        assert np.max(np.abs(r.y - want)) < 1e-9, amplitude


def test_function_inputs_the_compiled_methods_cannot_call_are_refused(model, p):
    """A Python function (not compiled by numba) on every compiled method, and a function without its rate
    where the model reads the rate, are refused before any work, saying what to do."""
    from knifeedge.inputs import Inputs, check_compiled

    for method, kw in (("DOP853", {}), ("RK4", {"h": 0.1}), ("gauss6", {"h": 0.1})):
        with pytest.raises(ValueError, match=r"`inputs\['tau'\]` is a Python function \('<lambda>'\): the compiled "
                                             r"method .*Decorate it with @numba.njit.*sample it.*SciPy method"):
            ke.simulate(model, Y0, (T0, T1), p, method=method, inputs={"tau": lambda t: 0.4 * math.sin(t)}, **kw)
    reads = Inputs(("tau",), ("function",), ((sine_torque, None),), rates_read=("tau",))
    with pytest.raises(ValueError, match=r"reads the rate dtau/dt .*inputs=\{'tau': \(u, du_dt\)\}"):
        check_compiled(model, reads, "DOP853")


@pytest.mark.slow  # numba compiles each function (a second each on a loaded machine)
def test_numba_functions_that_are_not_of_the_time_are_refused(model, p):
    """A numba function of two arguments, or returning an array, is refused before the kernel compiles."""
    from knifeedge.inputs import Inputs, check_compiled

    for bad, said in ((njit(lambda t, x: t), "numba cannot compile '<lambda>' as a function of the time t"),
                      (njit(lambda t: np.array([t, t])), "'<lambda>' returns array.* it must return one real number")):
        with pytest.raises(ValueError, match=rf"`inputs\['tau'\]`: {said}"):
            ke.simulate(model, Y0, (T0, T1), p, method="RK4", h=0.1, inputs={"tau": bad})
    check_compiled(model, Inputs(("tau",), ("function",), ((sine_torque, sine_torque),), ("tau",)), "DOP853")


def test_a_module_whose_constants_mix_the_slots_is_refused(model):
    """``constants(p)`` must hold the slots as ``p`` and nothing made of them (as ``derive`` now writes): a
    module derived before, whose constants held ``-input_t0``, is refused with the way out."""
    import types

    from knifeedge.inputs import Inputs, check_compiled

    old = types.SimpleNamespace(PARAM_NAMES=("a",), INPUT_NAMES=("u",), __file__="old.py",
                                constants=njit(lambda p: np.array([p[0], p[1], p[2], p[3], -p[1]])))
    fake = types.SimpleNamespace(name="old_model", module=old)
    with pytest.raises(ValueError, match=r"was written before its constants\(p\) held the input slots.*derive it "
                                         r"again"):
        check_compiled(fake, Inputs(("u",), ("function",), ((sine_torque, None),)), "RK4")
    held = model.module.constants.py_func(np.array([0.5, 0.8, 0.1, 1.0, 2.0, 3.0]))
    assert np.array_equal(held[3:6], [1.0, 2.0, 3.0])


def test_every_step_output_has_each_time_once(model, p):
    r = ke.simulate(model, Y0, (T0, T1), p, rtol=1e-10, inputs={"tau": (SAMPLE_T, SAMPLE_U)})
    assert r.success and r.t[0] == T0 and r.t[-1] == T1
    assert (np.diff(r.t) > 0).all()
    inside = SAMPLE_T[(SAMPLE_T > T0) & (SAMPLE_T < T1)]
    assert np.isin(inside, r.t).all()  # every interval ends at a sample time


def test_multipliers_are_the_lateral_force(model, p):
    """The knife edge's force: ``a d(omega)/dt + v omega`` of the hand-written equations."""
    r = ke.simulate(model, Y0, (T0, T1), p, t_eval=T_EVAL, rtol=1e-11, atol=1e-13,
                    inputs={"tau": (SAMPLE_T, SAMPLE_U)})
    lam = model.multipliers(r.y, p, r.t, inputs=r.inputs)[0]
    rates = np.array([by_hand(t, z, triangle) for t, z in zip(r.t, r.y.T)]).T
    assert np.allclose(lam, A * rates[1] + r.y[0] * r.y[1], rtol=1e-12, atol=1e-14)


def test_the_jacobians_with_inputs(model, p):
    """d rhs / d (v, omega) and d rhs / d c of the hand-written equations (the torque is not a parameter)."""
    y = np.array([0.3, -0.7])
    with pytest.raises(ValueError, match="pass `inputs`"):
        model.jacobian(y, p, t=2.0)
    v, w = y
    want = np.array([[0.0, 2 * A * w], [-A * w / (K * K + A * A), -(A * v + C) / (K * K + A * A)]])
    got = model.jacobian(y, p, t=2.0, inputs={"tau": (SAMPLE_T, SAMPLE_U)})
    assert np.allclose(got, want, rtol=1e-14, atol=1e-16)
    d_p = model.jacobian_p(y, p, t=2.0, inputs={"tau": 0.5})
    assert d_p.shape == (2, 3) and np.isclose(d_p[1, 2], -w / (K * K + A * A), rtol=1e-14)


def _simpson(f, t):
    """Integral of the samples ``f`` at the evenly spaced ``t`` (an odd number of points), Simpson's rule."""
    h = t[1] - t[0]
    return h / 3 * (f[0] + f[-1] + 4 * f[1:-1:2].sum() + 2 * f[2:-1:2].sum())


def test_energy_balance_with_inputs(model, p):
    """``energy(t) = energy(t0) + input work - dissipated work`` along a run at rtol 1e-11, to 1e-9 relative.

    The works are integrated by Simpson's rule interval by interval of the samples (the input's rate jumps
    at the sample times), on the run's own output.
    """
    cuts = np.concatenate([[T0], SAMPLE_T[(SAMPLE_T > T0) & (SAMPLE_T < T1)], [T1]])
    grids = [np.linspace(a, b, 401) for a, b in zip(cuts[:-1], cuts[1:])]
    t_eval = np.unique(np.concatenate(grids))
    r = ke.simulate(model, Y0, (T0, T1), p, t_eval=t_eval, rtol=1e-11, atol=1e-13,
                    inputs={"tau": (SAMPLE_T, SAMPLE_U)})
    with pytest.raises(ValueError, match="pass `inputs`"):
        model.energy(r.y, p, r.t)
    energy = r.energy
    power = (model.power_input(r.y, p, r.t, inputs=r.inputs)
             - model.power_dissipated(r.y, p, r.t, inputs=r.inputs))
    assert np.allclose(model.power_dissipated(r.y, p, r.t, inputs=r.inputs), C * r.y[1] ** 2, rtol=1e-13)
    work, total = [0.0], 0.0
    for g in grids:
        sel = np.isin(r.t, g)
        total += _simpson(power[sel], r.t[sel])
        work.append(total)
    at_cuts = energy[np.isin(r.t, cuts)]
    assert np.ptp(energy) > 0.01  # not conserved
    assert np.max(np.abs(at_cuts - (energy[0] + np.array(work)))) < 1e-9 * np.max(np.abs(energy))


def test_bad_inputs_are_refused_naming_inputs(model, p):
    run = lambda **kw: ke.simulate(model, Y0, (T0, T1), p, **kw)  # noqa: E731
    with pytest.raises(ValueError, match=r"has inputs \('tau',\): pass `inputs`"):
        run()
    with pytest.raises(ValueError, match=r"`inputs` of controlled_sleigh: missing \['tau'\]"):
        run(inputs={})
    with pytest.raises(ValueError, match=r"`inputs` of controlled_sleigh: unknown \['u'\]"):
        run(inputs={"tau": 1.0, "u": 2.0})
    with pytest.raises(ValueError, match=r"`inputs\['tau'\]` samples must be two 1-D arrays"):
        run(inputs={"tau": ([0.0, 10.0], [1.0, 2.0, 3.0])})
    with pytest.raises(ValueError, match=r"`inputs\['tau'\]` sample times must be strictly increasing"):
        run(inputs={"tau": ([0.0, 10.0, 5.0], [1.0, 2.0, 3.0])})
    with pytest.raises(ValueError, match=r"`inputs\['tau'\]`: its samples cover \[2, 10\], the run's `t_span`"):
        run(inputs={"tau": ([2.0, 10.0], [1.0, 2.0])})
    with pytest.raises(ValueError, match=r"`inputs\['tau'\]` must be a number, samples"):
        run(inputs={"tau": "0.5"})
    with pytest.raises(ValueError, match=r"`inputs\['tau'\]` is a Python function \('sin'\): the compiled "
                                         r"method 'DOP853'.*@numba.njit.*method='scipy:DOP853'"):
        run(inputs={"tau": math.sin})
    with pytest.raises(ValueError, match=r"`inputs`: .* declares no inputs"):
        ke.simulate(ke.load("chaplygin_sleigh"), [0.1, 0.0], (0, 1), ke.load("chaplygin_sleigh").default_params,
                    inputs={"tau": 1.0})


def test_the_cli_takes_a_constant_and_a_samples_file(model, tmp_path, capsys):
    """``knifeedge simulate --input tau=0.3`` and ``--input tau=FILE.csv`` against the hand-written equations."""
    folder = str(model.source_path.parent)
    common = ["simulate", "--path", folder, "--model", "controlled_sleigh", "--t-start", str(T0), "--t-end", str(T1),
              "--n-eval", "41", "--rtol", "1e-11", "--atol", "1e-13", "--set", f"a={A}", f"k={K}", f"c={C}"]
    samples = tmp_path / "tau.csv"
    samples.write_text("t,tau\n" + "".join(f"{a!r},{b!r}\n" for a, b in zip(SAMPLE_T.tolist(), SAMPLE_U.tolist())))
    for given, torque, breaks in (("tau=0.3", lambda t: 0.3, ()), (f"tau={samples}", triangle, SAMPLE_T)):
        out = tmp_path / "run.csv"
        assert cli.main([*common, "--input", given, "--out", str(out)]) == 0
        table = np.loadtxt(out, delimiter=",", skiprows=1)
        assert np.max(np.abs(table[:, 1:].T - reference(torque, table[:, 0], breaks))) < 2e-9, given
    assert "inputs: tau: 12 samples (piecewise linear)" in capsys.readouterr().out
    assert cli.main([*common]) == 2
    assert "missing ['tau']" in capsys.readouterr().err
    assert cli.main([*common, "--set", "tau=0.3"]) == 2
    assert "give the inputs ['tau'] with `--input NAME=VALUE`" in capsys.readouterr().err
    assert cli.main([*common, "--input", f"tau={tmp_path / 'none.csv'}"]) == 2
    assert "does not exist" in capsys.readouterr().err


@pytest.mark.slow  # derives and compiles the doc's model: the slow tier, as the other doc sections
def test_doc_section_on_inputs_runs(tmp_path, monkeypatch):
    """docs/your-own-model.md section 10 as written (tags ``inputs-file=``, ``sh inputs-example``,
    ``python inputs-example``), the example blocks in the order of the text."""
    import re
    import shlex

    import docs_blocks
    from test_your_own_model import DOC

    monkeypatch.chdir(tmp_path)
    text = DOC.read_text()
    files = re.findall(r"```python inputs-file=(\w+\.py)\n(.*?)```", text, flags=re.S)
    assert [name for name, _ in files] == ["steered_sleigh.py"]
    (tmp_path / "steered_sleigh.py").write_text(files[0][1])
    blocks = re.findall(r"```(sh|python) inputs-example\n(.*?)```", text, flags=re.S)
    assert [kind for kind, _ in blocks].count("sh") == 2
    namespace: dict = {}
    for kind, code in blocks:
        if kind == "sh":
            for line in (ln for ln in code.splitlines() if ln.startswith("knifeedge ")):
                assert cli.main(shlex.split(line)[1:]) == 0, line
            continue
        docs_blocks.run(code, str(DOC), namespace)
    sampled = np.loadtxt(tmp_path / "sampled.csv", delimiter=",", skiprows=1)
    assert sampled[-1, 0] == 10.0 and np.allclose(sampled[-1, 1:], namespace["z"], rtol=1e-8, atol=1e-10)


def test_an_input_in_a_constraint_reads_its_rate(tmp_path):
    """The sleigh's heading turned at a rate ``w(t)`` given at run time (the constraint ``phi_dot - w = 0``).
    From the hand-written equations with ``omega = w``: ``dv/dt = a w^2``, so over an interval where
    ``w = w0 + s (t - ta)``, ``v`` gains ``a (w0^2 d + w0 s d^2 + s^2 d^3 / 3)`` (d = t - ta); the torque
    that enforces the turn is the multiplier ``(k^2 + a^2) dw/dt + a v w`` (it reads the input's rate ``s``),
    and its power ``w * torque`` is ``power_input``."""
    m = _turned_by_input(tmp_path)
    assert m.state_names == ("v",) and m.module.INPUT_RATES_READ == ("w",)
    p = m.params(a=A, k=K)
    t_eval = np.linspace(T0, T1, 31)
    gained = []
    for t in t_eval:  # a * integral of w^2 from T0 to t, interval by interval, in closed form
        total, lo = 0.0, T0
        for ta, tb in zip(SAMPLE_T[:-1], SAMPLE_T[1:]):
            a_, b_ = max(ta, lo), min(tb, t)
            if b_ > a_:
                s = (SAMPLE_U[np.searchsorted(SAMPLE_T, tb)] - SAMPLE_U[np.searchsorted(SAMPLE_T, ta)]) / (tb - ta)
                w0, d = triangle(a_), b_ - a_
                total += w0 * w0 * d + w0 * s * d * d + s * s * d**3 / 3
        gained.append(A * total)
    v_exact = 0.1 + np.array(gained)
    for method, kw in (("DOP853", {}), ("scipy:DOP853", {})):
        r = ke.simulate(m, [0.1], (T0, T1), p, method=method, t_eval=t_eval, rtol=1e-11, atol=1e-13,
                        inputs={"w": (SAMPLE_T, SAMPLE_U)}, **kw)
        assert np.max(np.abs(r["v"] - v_exact)) < 1e-9 * np.max(np.abs(v_exact)), method
    inside = (t_eval[:-1] + t_eval[1:]) / 2  # away from the samples, where the rate jumps
    j = np.searchsorted(SAMPLE_T, inside, side="right") - 1
    rate = (SAMPLE_U[j + 1] - SAMPLE_U[j]) / (SAMPLE_T[j + 1] - SAMPLE_T[j])
    w_in = np.array([triangle(t) for t in inside])
    r = ke.simulate(m, [0.1], (T0, T1), p, t_eval=inside, rtol=1e-11, atol=1e-13, inputs={"w": (SAMPLE_T, SAMPLE_U)})
    torque = (K * K + A * A) * rate + A * r["v"] * w_in
    assert np.allclose(m.multipliers(r.y, p, r.t, inputs=r.inputs)[1], torque, rtol=1e-12, atol=1e-14)
    assert np.allclose(m.power_input(r.y, p, r.t, inputs=r.inputs), w_in * torque, rtol=1e-12, atol=1e-14)


def _turned_by_input(folder):
    """The sleigh whose heading turns at the rate ``w`` given at run time (``phi_dot - w = 0``), derived into
    ``folder`` and loaded."""
    import sympy as sp

    from knifeedge.derive import ModelSpec, emit
    from knifeedge.derive.cli import derive_specs

    a, k = sp.symbols("a k", positive=True)
    x, y, phi, x_dot, y_dot, phi_dot, v, w = sp.symbols("x y phi x_dot y_dot phi_dot v w", real=True)
    across, along = sp.Matrix([-sp.sin(phi), sp.cos(phi)]), sp.Matrix([sp.cos(phi), sp.sin(phi)])
    contact = sp.Matrix([x_dot, y_dot])
    centre = contact + a * phi_dot * across
    spec = ModelSpec(
        name="turned_by_input", coordinates=(x, y, phi), velocities=(x_dot, y_dot, phi_dot),
        lagrangian=sp.Rational(1, 2) * (centre.dot(centre) + k**2 * phi_dot**2),
        constraints=(contact.dot(across), phi_dot - w), constraint_labels=("knife_edge", "turn"),
        dependent=(y, phi), params=(a, k), inputs=(w,), cyclic={x: 0, y: 0, phi: 0}, pose=(phi, x, y),
        quasi_velocities=((v, x_dot, contact.dot(along)),))
    emit.write_all(folder, derive_specs([spec]), registry=False)
    return ke.load("turned_by_input", path=folder)


@njit
def turn_rate(t):
    return 0.3 * math.sin(t)


@njit
def turn_acceleration(t):
    return 0.3 * math.cos(t)


@pytest.mark.slow  # derives a model and compiles its kernel
def test_a_function_and_its_rate_on_a_compiled_method(tmp_path):
    """The heading turned at ``w = 0.3 sin t`` given with its rate as numba functions: ``dv/dt = a w^2`` gives
    ``v = 0.1 + 0.09 a ((t - T0)/2 - (sin 2t - sin 2T0)/4)``; the torque that turns the sleigh (the multiplier
    ``(k^2 + a^2) dw/dt + a v w``) reads the rate.  Without the rate the compiled method refuses the input."""
    m = _turned_by_input(tmp_path)
    p = m.params(a=A, k=K)
    t_eval = np.linspace(T0, T1, 31)
    with pytest.raises(ValueError, match=r"reads the rate dw/dt"):
        ke.simulate(m, [0.1], (T0, T1), p, inputs={"w": turn_rate})
    r = ke.simulate(m, [0.1], (T0, T1), p, t_eval=t_eval, rtol=1e-11, atol=1e-13,
                    inputs={"w": (turn_rate, turn_acceleration)})
    v = 0.1 + 0.09 * A * ((t_eval - T0) / 2 - (np.sin(2 * t_eval) - np.sin(2 * T0)) / 4)
    assert np.max(np.abs(r["v"] - v)) < 1e-9 * np.max(np.abs(v))
    torque = (K * K + A * A) * 0.3 * np.cos(t_eval) + A * v * 0.3 * np.sin(t_eval)
    assert np.allclose(m.multipliers(r.y, p, r.t, inputs=r.inputs)[1], torque, rtol=1e-9, atol=1e-12)


@pytest.mark.slow  # derives and compiles two more models
def test_numeric_elimination_reads_the_inputs_as_the_closed_form(tmp_path):
    """The same steered sleigh (no quasi-velocity) with the multipliers eliminated symbolically and numerically
    (``elimination=``): the same run, multipliers and input power with the same sampled torque."""
    import sympy as sp

    from knifeedge.derive import ModelSpec, emit
    from knifeedge.derive.cli import derive_specs

    a, k, c = sp.symbols("a k c", positive=True)
    tau = sp.Symbol("tau", real=True)
    x, y, phi, x_dot, y_dot, phi_dot = sp.symbols("x y phi x_dot y_dot phi_dot", real=True)
    across = sp.Matrix([-sp.sin(phi), sp.cos(phi)])
    contact = sp.Matrix([x_dot, y_dot])
    centre = contact + a * phi_dot * across
    kw = dict(coordinates=(x, y, phi), velocities=(x_dot, y_dot, phi_dot),
              lagrangian=sp.Rational(1, 2) * (centre.dot(centre) + k**2 * phi_dot**2),
              constraints=(contact.dot(across),), dependent=(y,), params=(a, k, c), inputs=(tau,),
              cyclic={x: 0, y: 0, phi: 0}, forces=(0, 0, tau - c * phi_dot))
    specs = [ModelSpec(name="closed_in", elimination="symbolic", **kw),
             ModelSpec(name="solved_in", elimination="numeric", **kw)]
    # check=False: x_dot (not the forward speed) is not symmetric under the heading; the equations at phi = 0 are
    emit.write_all(tmp_path, derive_specs(specs, check=False), registry=False)
    closed, solved = (ke.load(n, path=tmp_path) for n in ("closed_in", "solved_in"))
    assert solved.module.ELIMINATION == "numeric"
    p = closed.params(a=A, k=K, c=C)
    given = {"tau": (SAMPLE_T, SAMPLE_U)}
    runs = [ke.simulate(m, Y0, (T0, T1), p, t_eval=T_EVAL, inputs=given, rtol=1e-11, atol=1e-13)
            for m in (closed, solved)]
    assert np.max(np.abs(runs[0].y - piecewise_reference_of(T_EVAL))) < 2e-9
    assert np.max(np.abs(runs[0].y - runs[1].y)) < 1e-12
    for f in ("multipliers", "power_input"):
        one, two = (getattr(m, f)(r.y, p, r.t, inputs=r.inputs) for m, r in zip((closed, solved), runs))
        assert np.allclose(one, two, rtol=1e-12, atol=1e-15), f


def piecewise_reference_of(t_eval):
    return reference(triangle, t_eval, SAMPLE_T)


def test_two_inputs_sampled_at_different_times_are_affine_on_every_interval():
    """The intervals are cut at the samples of every input; on each, ``value + rate (t - t0)`` of each input is
    its piecewise-linear interpolant (``np.interp``) at both ends and the middle."""
    from knifeedge.inputs import Inputs

    u = (np.array([0.0, 1.0, 3.0, 4.0]), np.array([1.0, -1.0, 2.0, 0.5]))
    w = (np.array([-1.0, 0.5, 2.5, 5.0]), np.array([0.0, 3.0, 1.0, -2.0]))
    inp = Inputs(("u", "c", "w"), ("samples", "constant", "samples"), (u, 0.7, w))
    cuts = inp.breakpoints(0.2, 3.5)
    assert np.array_equal(cuts, [0.2, 0.5, 1.0, 2.5, 3.0, 3.5])
    slots = inp.slots(cuts[:-1])
    for (ta, tb), row in zip(zip(cuts[:-1], cuts[1:]), slots):
        assert row[0] == ta
        for t in (ta, (ta + tb) / 2, tb):
            got = row[1::2] + row[2::2] * (t - row[0])
            assert np.allclose(got, [np.interp(t, *u), 0.7, np.interp(t, *w)], rtol=1e-14, atol=1e-15)
    at = inp.at(1.7)
    assert np.allclose(at, [1.7, np.interp(1.7, *u), 1.5, 0.7, 0.0, np.interp(1.7, *w), -1.0], rtol=1e-14)
