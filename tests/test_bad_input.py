"""Bad input is refused before any work, with an error naming the argument in backticks.

Each case is what a demanding user tries: wrong types, NaN, inf, negative, huge,
empty, wrong shapes, unknown names.  The array and mapping forms of the state and
the parameters follow one rule: a real number is an int or a float (Python or
NumPy); ``bool``, complex and strings are refused in both forms.
"""
import math

import numpy as np
import pytest

import knifeedge as ke
from knifeedge.integrators import Status

P2 = dict(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4)
Y2 = dict(theta1=1e-3, theta2=1e-3, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1)


@pytest.fixture(scope="module")
def two():
    return ke.load("two_mode", "full")


def _call(m, **kw):
    args = dict(y0=Y2, t_span=(0.0, 10.0), p=P2)
    args.update(kw)
    return ke.simulate(m, args.pop("y0"), args.pop("t_span"), args.pop("p"), **args)


BAD_SIMULATE = [
    # (keyword arguments, exception, text the message must contain)
    # a fixed step below the resolution of t: its step count overflowed 64 bits and became one giant step
    (dict(method="RK4", h=1e-17, t_span=(0.0, 300.0)), ValueError, "`h`"),
    (dict(method="gauss4", h=1e-300), ValueError, "`h`"),
    (dict(method="RK4", h=1e-3, t_span=(1e15, 1e15 + 10)), ValueError, "`h`"),
    (dict(method="RK4", h=0.0), ValueError, "`h`"),
    (dict(method="RK4", h=-0.1), ValueError, "`h`"),
    (dict(method="RK4", h=math.nan), ValueError, "`h`"),
    (dict(method="RK4", h=math.inf), ValueError, "`h`"),
    (dict(method="RK4", h="0.1"), TypeError, "`h`"),
    (dict(method="RK4", h=True), TypeError, "`h`"),
    (dict(method="RK4", h=0.1j), TypeError, "`h`"),
    # tolerances of one or more: an error estimate means nothing there
    (dict(rtol=10), ValueError, "`rtol`"),
    (dict(rtol=1.0), ValueError, "`rtol`"),
    (dict(rtol=1e300), ValueError, "`rtol`"),
    (dict(rtol=math.inf), ValueError, "`rtol`"),
    (dict(rtol=math.nan), ValueError, "`rtol`"),
    (dict(rtol=1e-17), ValueError, "`rtol`"),
    (dict(rtol=-1e-6), ValueError, "`rtol`"),
    (dict(rtol="1e-6"), TypeError, "`rtol`"),
    (dict(rtol=1e-6 + 0j), TypeError, "`rtol`"),
    (dict(rtol=np.bool_(True)), TypeError, "`rtol`"),
    (dict(atol=1e300), ValueError, "`atol`"),
    (dict(atol=10.0), ValueError, "`atol`"),
    (dict(atol=1), ValueError, "`atol`"),
    (dict(atol=[1e-12] * 4 + [2.0]), ValueError, "`atol`"),
    (dict(atol=0.0), ValueError, "`atol`"),
    (dict(atol=[1e-12] * 4), ValueError, "`atol`"),
    (dict(atol=np.full(5, 1e-12 + 0j)), TypeError, "`atol`"),
    (dict(atol=np.ones(5, dtype=bool)), TypeError, "`atol`"),
    (dict(atol=["1e-12"] * 5), TypeError, "`atol`"),
    (dict(atol="1e-12"), TypeError, "`atol`"),
    (dict(atol=None), TypeError, "`atol`"),
    # the array form follows the mapping form's rule
    (dict(y0=np.array([1e-3 + 1j, 1e-3, 0, 0, 0.1])), TypeError, "`y0`"),
    (dict(y0=[True, 0, 0, 0, True]), TypeError, "`y0`"),
    (dict(y0=np.array([True, False, False, False, True])), TypeError, "`y0`"),
    (dict(y0=["1e-3", "1e-3", "0", "0", "0.1"]), TypeError, "`y0`"),
    (dict(y0="1e-3"), TypeError, "`y0`"),
    (dict(y0=[1e-3, 1e-3, 0, 0, None]), TypeError, "`y0`"),
    (dict(y0=[1e-3, 1e-3, 0, 0, 10**400]), ValueError, "`y0`"),
    (dict(y0=[1e-3, 1e-3, 0, 0, math.nan]), ValueError, "`y0`"),
    (dict(y0=[1e-3, 1e-3, 0, 0]), ValueError, "`y0`"),
    (dict(y0=[[1e-3, 1e-3, 0, 0, 0.1]]), ValueError, "`y0`"),
    (dict(y0=[]), ValueError, "`y0`"),
    (dict(y0={**Y2, "theta1": True}), TypeError, "`theta1`"),
    (dict(y0={**Y2, "theta1": 1e-3 + 0j}), TypeError, "`theta1`"),
    (dict(y0={**Y2, "theta1": "1e-3"}), TypeError, "`theta1`"),
    (dict(p=np.array([1, 1, 2, 0.5, 0.7 + 1j])), TypeError, "`p`"),
    (dict(p=["1", "1", "2", "0.5", "0.7"]), TypeError, "`p`"),
    (dict(p=[True, 1, 2, 0.5, 0.7]), TypeError, "`p`"),
    (dict(p={**P2, "D": True}), TypeError, "`D`"),
    (dict(p={**P2, "D": "0.5"}), TypeError, "`D`"),
    (dict(p={**P2, "D": -0.5}), ValueError, "`D`"),
    (dict(p=[1, 1, 2, -0.5, 0.7]), ValueError, "`D`"),
    (dict(p={**P2, "E": 1.0}), ValueError, "`p`"),
    # times and step budget
    (dict(t_span=(False, True)), TypeError, "`t_span`"),
    (dict(t_span=(0, 1j)), TypeError, "`t_span`"),
    (dict(t_span=("0", "10")), TypeError, "`t_span`"),
    (dict(t_span=(0.0, 1.0, 2.0)), TypeError, "`t_span`"),
    (dict(t_span=10.0), TypeError, "`t_span`"),
    (dict(t_span=(10.0, 0.0)), ValueError, "`t_span`"),
    (dict(t_span=(0.0, math.inf)), ValueError, "`t_span`"),
    (dict(t_eval=["1", "2"]), TypeError, "`t_eval`"),
    (dict(t_eval=[1.0, 2.0 + 1j]), TypeError, "`t_eval`"),
    (dict(t_eval=[[1.0, 2.0]]), ValueError, "`t_eval`"),
    (dict(t_eval=[2.0, 1.0]), ValueError, "`t_eval`"),
    (dict(t_eval=[1.0, 11.0]), ValueError, "`t_eval`"),
    (dict(t_eval=[1.0, math.nan]), ValueError, "`t_eval`"),
    (dict(t_eval="1"), TypeError, "`t_eval`"),
    (dict(max_steps=2**70), ValueError, "`max_steps`"),
    (dict(max_steps=0), ValueError, "`max_steps`"),
    (dict(max_steps=1e6), TypeError, "`max_steps`"),
    (dict(max_steps=True), TypeError, "`max_steps`"),
    (dict(max_step=0.0), ValueError, "`max_step`"),
    (dict(max_step=math.nan), ValueError, "`max_step`"),
    (dict(max_step="1"), TypeError, "`max_step`"),
    (dict(method="RK5"), ValueError, "`method`"),
    (dict(method=None), ValueError, "`method`"),
    (dict(method="RK4"), ValueError, "`h`"),
    (dict(method="scipy:RK45", h=0.1), ValueError, "`h`"),
    (dict(error_control="modes"), ValueError, "`error_control`"),
]


@pytest.mark.parametrize("kw,exc,text", BAD_SIMULATE, ids=[repr(c[0])[:60] for c in BAD_SIMULATE])
def test_simulate_refuses_bad_input_naming_it(two, kw, exc, text):
    with pytest.raises(exc) as info:
        _call(two, **kw)
    assert text in str(info.value)


def test_array_and_mapping_forms_accept_the_same_numbers(two):
    """NumPy scalars, Python ints and 0-d arrays are numbers in both forms; the results agree."""
    names = two.state_names
    as_map = {n: np.float32(v) if i % 2 else np.array(v) for i, (n, v) in enumerate(Y2.items())}
    a = two.check_state(as_map)
    b = two.check_state([np.float32(Y2[n]) if i % 2 else np.array(Y2[n]) for i, n in enumerate(names)])
    np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(two.check_params([1, 1, 2, 0.5, np.float64(math.pi / 4)]),
                                  two.check_params({**P2, "g": 1, "ell": np.int64(1), "L": 2}))


def test_smallest_fixed_step_still_accepted_and_step_budget_reported(two):
    """A step just above the resolution of t is legal; a budget too small for it is a reported failure."""
    r = _call(two, method="RK4", h=1e-9, t_span=(0.0, 1.0), max_steps=1000)
    assert not r.success and r.outcome is Status.MAX_STEPS and r.nsteps == 1000
    assert r.t[-1] == pytest.approx(1e-6)


# -- SciPy methods honour `max_steps` -------------------------------------------
SCIPY = ["scipy:RK45", "scipy:DOP853", "scipy:LSODA", "scipy:Radau", "scipy:BDF"]


@pytest.mark.parametrize("method", SCIPY)
def test_scipy_methods_stop_at_max_steps_and_say_so(two, method):
    """`--t-end 1e12` with a SciPy method used to run until interrupted: the budget now ends it."""
    r = _call(two, method=method, t_span=(0.0, 1e12), max_steps=25)
    assert not r.success and r.outcome is Status.MAX_STEPS and r.status == Status.MAX_STEPS.code
    assert r.nsteps == 25 and r.t.size == 26 and r.t[-1] < 1e12
    assert np.isfinite(r.y).all()
    r = _call(two, method=method, t_span=(0.0, 1e12), max_steps=25, t_eval=[0.0, 1.0, 1e12])
    assert not r.success and r.nsteps == 25 and r.t[-1] < 1e12


# Radau and BDF (~2 s of CPU each) in the slow tier: LSODA takes the generated Jacobian as they do, RK45 and DOP853
# the explicit path
@pytest.mark.parametrize("method", [pytest.param(m, marks=pytest.mark.slow) if m in ("scipy:Radau", "scipy:BDF") else m
                                    for m in SCIPY])
def test_scipy_methods_stepped_here_agree_with_solve_ivp(method):
    """Stepping SciPy's solver ourselves gives solve_ivp's output and events (the same steps, the same
    dense output, the same root finder), with every step stored and at `t_eval`: the single-mode scene
    of the paper's Fig. 'numerical', whose spin reverses once near t = 106."""
    from scipy.integrate import solve_ivp

    m = ke.load("single_mode", "full")
    p, y0 = m.params(g=1.0, ell=1.0, L=1.0, D=1.0), m.state(theta=1e-3, theta_dot=0.0, phi_dot=0.1)
    k = m.index("phi_dot")
    rtol = 1e-6 if method in ("scipy:Radau", "scipy:BDF") else 1e-9
    # the implicit methods receive the generated Jacobian
    jac = {"jac": lambda t, y: m.jacobian(y, p)} if method in ("scipy:LSODA", "scipy:Radau", "scipy:BDF") else {}

    def spin(t, y):
        return y[k]

    fun = lambda t, y: m.rhs(t, y, p)  # noqa: E731
    for t_eval in (None, np.linspace(0.0, 150.0, 57)):
        ref = solve_ivp(fun, (0.0, 150.0), y0, method=method.split(":")[1], rtol=rtol, atol=1e-12,
                        t_eval=t_eval, events=spin, **jac)
        r = ke.simulate(m, y0, (0.0, 150.0), p, method=method, rtol=rtol, atol=1e-12, t_eval=t_eval)
        assert r.success and ref.status == 0
        assert r.reversal_times.size == 1 and ref.t_events[0].size == 1
        np.testing.assert_array_equal(r.t, ref.t)
        np.testing.assert_allclose(r.y, ref.y, rtol=0, atol=1e-15)
        np.testing.assert_allclose(r.reversal_times, ref.t_events[0], rtol=1e-14)
        assert r.nfev == ref.nfev


# -- the command line: one line `error: ...`, exit status 2, never a traceback ----------------
from knifeedge.cli import main  # noqa: E402

BAD_CLI = [
    # what the command line would allocate is bounded, and the flag named
    (["simulate", "--n-eval", "100000000000"], "`--n-eval`"),
    (["simulate", "--n-eval", "1"], "`--n-eval`"),
    (["simulate", "--n-eval", "2.5"], "`--n-eval`"),
    (["simulate", "--n-eval", "x"], "`--n-eval`"),
    (["simulate", "--max-steps", "2**70"], "`--max-steps`"),
    (["simulate", "--max-steps", "0"], "`--max-steps`"),
    (["simulate", "--h", "0.1"], "`h`"),
    (["simulate", "--method", "RK4"], "`h`"),
    (["simulate", "--method", "RK4", "--h", "1e-17"], "`h`"),
    (["simulate", "--rtol", "10"], "`rtol`"),
    (["simulate", "--atol", "1e300"], "`atol`"),
    (["simulate", "--max-step", "-1"], "`max_step`"),
    (["simulate", "--t-start", "5", "--t-end", "5"], "`--t-end`"),
    (["simulate", "--set", "D=1", "--set", "D=2"], "`--set`"),
    (["simulate", "--set", "theta=1j"], "`--set theta`"),
    (["simulate", "--set", "D=10**400"], "`--set D`"),
    (["simulate", "--set", "method=DP54"], "`--set method`"),
    (["simulate", "--set", "E=1"], "`--set`"),
    (["simulate", "--set", "D=-1"], "`D`"),
    (["simulate", "--out", "x.txt"], "`--out`"),
    (["scene", "numerical", "--set", "n_eval=1e12"], "`--set n_eval`"),
    (["scene", "numerical", "--set", "n_eval=2.5"], "`--set n_eval`"),
    (["scene", "numerical", "--set", "max_steps=2**70"], "`--set max_steps`"),
    (["scene", "numerical", "--set", "pose=maybe"], "`--set pose`"),
    (["scene", "numerical", "--set", "method=", "t_end=1"], "`--set method`"),
    (["sweep", "numerical", "--grid", "D=1:2:1e12"], "`--grid D`"),
    (["sweep", "numerical", "--grid", "D=1:2:2.7"], "`--grid D`"),
    (["sweep", "numerical", "--grid", "D=1,2", "--grid", "D=3"], "`--grid`"),
    (["sweep", "numerical", "--grid", "D=1:2:3:4"], "`--grid D`"),
    (["sweep", "numerical", "--grid", "D=0:2:3"], "`--grid D`"),
    (["sweep", "numerical", "--grid", "method=a:b:3"], "`--grid method`"),
    (["sweep", "numerical", "--grid", "D=1:2:1000", "phi_dot=1:2:1000", "L=1:2:1000"], "`--grid`"),
    (["demo", "--out", "noext"], "`--out`"),
    (["animate", "numerical", "--magnify", "big"], "`--magnify`"),
    (["demo", "--t-end", "nan"], "--t-end"),
]


@pytest.mark.parametrize("argv,needle", BAD_CLI, ids=[" ".join(a)[:60] for a, _ in BAD_CLI])
def test_cli_refuses_bad_input_in_one_line(capsys, argv, needle):
    try:
        rc = main(argv)
    except SystemExit as exc:  # argparse's own refusals
        rc = exc.code
    out, err = capsys.readouterr()
    assert rc == 2, (out, err)
    assert "Traceback" not in err and err.count("\n") == 1 and "error:" in err
    assert needle in err


@pytest.mark.parametrize("argv,needle", [
    (["simulate", "--out", "{file}/x.csv"], "`--out` "),
    (["simulate", "--plot", "{file}/plots/x.png"], "`--plot` "),
    (["simulate", "--out", "{folder}"], "`--out` "),
    (["scene", "numerical", "--out", "{file}/x.png"], "`--out` "),
    (["demo", "--out", "{file}/x.png"], "`--out` "),
    (["figures", "--out", "{file}", "--only", "numerical"], "`--out` "),  # was "[Errno 17] File exists"
])
def test_cli_refuses_an_output_it_cannot_write_before_the_run(tmp_path, capsys, argv, needle):
    """A file where the output's folder should be, or an output naming a folder: one line naming the flag, before
    anything is integrated (it was an OSError's text, "[Errno 17] File exists", once the run was done)."""
    (tmp_path / "notes.txt").write_text("a file")
    (tmp_path / "old.csv").mkdir()
    argv = [a.format(file=tmp_path / "notes.txt", folder=tmp_path / "old.csv") for a in argv]
    rc = main(argv)
    out, err = capsys.readouterr()
    assert rc == 2 and out == "", (out, err)  # nothing run, nothing printed
    assert err.count("\n") == 1 and needle in err
    assert "is a file, not a folder" in err or "is a folder: give the name of a file" in err


def test_cli_takes_the_step_and_the_step_budget(capsys):
    """`--h` and `--max-steps` exist (the RK4 error asks for `h`); a spent budget is a reported failure (exit 1)."""
    # the full single-mode model: its RK4 kernel is the one the other checks compile
    assert main(["simulate", "--model", "single_mode", "--fidelity", "full", "--method", "RK4", "--h", "0.05",
                 "--t-end", "10"]) == 0
    out, _ = capsys.readouterr()
    assert "RK4, h=0.05: 200 steps" in out
    assert main(["simulate", "--method", "scipy:RK45", "--t-end", "1e12", "--max-steps", "20"]) == 1
    out, err = capsys.readouterr()
    assert "20 steps" in out and "maximum number of solver steps" in err


@pytest.mark.slow
def test_cli_set_takes_the_run_settings_its_help_lists(tmp_path, capsys):
    """`scene --set` says it takes method and fidelity: they are text, not numbers."""
    from knifeedge.cli import assignments, grid_assignments

    assert assignments(["method=DP54", "fidelity=full", "pose=true", "n_eval=1e3", "max_steps=2**20", "D=pi/4"]) == {
        "method": "DP54", "fidelity": "full", "pose": True, "n_eval": 1000, "max_steps": 2**20, "D": math.pi / 4}
    assert grid_assignments(["method=DP54,RK45", "D=1:4:3"]) == {"method": ["DP54", "RK45"], "D": [1.0, 2.0, 4.0]}
    png = tmp_path / "s.png"
    assert main(["scene", "numerical", "--set", "method=DP54", "fidelity=full", "--out", str(png)]) == 0
    out, _ = capsys.readouterr()
    assert "DP54" in out and "(full" in out and png.exists()


# -- reversal theory and the noisy loop: bounded work, named arguments, progress -----------------
from knifeedge.background import noisy_intervals, simulate_noisy  # noqa: E402
from knifeedge.reversal import MAX_INTERVALS, reversal_time  # noqa: E402


@pytest.fixture(scope="module")
def reduced2():
    return ke.load("two_mode", "reduced")


BAD_REVERSAL = [
    (dict(n_intervals=10**7), ValueError, "`n_intervals`"),
    (dict(n_intervals=MAX_INTERVALS + 1), ValueError, "`n_intervals`"),
    (dict(n_intervals=1), ValueError, "`n_intervals`"),
    (dict(n_intervals=4.0), TypeError, "`n_intervals`"),
    (dict(n_intervals=True), TypeError, "`n_intervals`"),
    (dict(n_intervals="4"), TypeError, "`n_intervals`"),
    (dict(background=1e-6j), TypeError, "`background`"),
    (dict(background="1e-6"), TypeError, "`background`"),
    (dict(background=[True, 0]), TypeError, "`background`"),
    (dict(background=[1e-6]), ValueError, "`background`"),
    (dict(background=-1e-6), ValueError, "`background`"),
    (dict(background=math.nan), ValueError, "`background`"),
    (dict(progress="yes"), TypeError, "`progress`"),
    (dict(y0=[True, 0, 0, 0, 0.1]), TypeError, "`y0`"),
]


@pytest.mark.parametrize("kw,exc,text", BAD_REVERSAL, ids=[repr(c[0])[:50] for c in BAD_REVERSAL])
def test_reversal_time_refuses_bad_input(reduced2, kw, exc, text):
    kw = {"p": P2, "y0": Y2, **kw}
    with pytest.raises(exc) as info:
        reversal_time(reduced2, kw.pop("p"), kw.pop("y0"), **kw)
    assert text in str(info.value)


@pytest.mark.parametrize("fidelity", ["full", "amplitude"])
def test_reversal_time_refuses_a_model_without_the_knife_edges_theory(fidelity):
    """The celt has amplitude equations but not the knife edges' modes (no growth and drive rates): a clear
    `model` error before any work (it was an AttributeError from inside the generated module)."""
    m = ke.load("celt", fidelity)
    with pytest.raises(ValueError, match="`model` celt: its amplitude equations define no frequencies"):
        reversal_time(m, m.default_params, m.default_state)


def test_reversal_time_reports_progress_of_many_intervals(reduced2):
    """`n_intervals` up to the bound is computed, and a callback sees every interval; with a background
    the intervals alternate between two values (module docstring of knifeedge.reversal)."""
    seen = []
    r = reversal_time(reduced2, P2, Y2, background=1e-6, n_intervals=50, progress=lambda d, n: seen.append((d, n)))
    assert seen == [(i, 50) for i in range(1, 51)]
    assert r.intervals.shape == (50,)
    np.testing.assert_allclose(r.intervals[2::2], r.intervals[0], rtol=1e-9)
    np.testing.assert_allclose(r.intervals[3::2], r.intervals[1], rtol=1e-9)


@pytest.mark.parametrize("kw,exc,text", [
    (dict(t_end=1e12), ValueError, "`t_end`"),
    (dict(t_end=1e6, h=1e-12), ValueError, "`h`"),
    (dict(t_end="10"), TypeError, "`t_end`"),
    (dict(sigma="1e-6"), TypeError, "`sigma`"),
    (dict(sigma=-1.0), ValueError, "`sigma`"),
    (dict(seed=-1), ValueError, "`seed`"),
    (dict(seed=1.5), TypeError, "`seed`"),
    (dict(max_reversals=0), ValueError, "`max_reversals`"),
    (dict(max_reversals=10**12), ValueError, "`max_reversals`"),
])
def test_noisy_loop_refuses_unbounded_or_bad_input(kw, exc, text):
    """The noisy RK4 loop is one compiled call: its work is bounded before it starts (at most
    MAX_NOISY_STEPS steps), and a step below the resolution of t (which never advanced t) is refused."""
    m = ke.load("two_mode", "full")
    kw = {"t_end": 10.0, "sigma": 1e-6, **kw}
    with pytest.raises(exc) as info:
        simulate_noisy(m, Y2, kw.pop("t_end"), P2, kw.pop("sigma"), **kw)
    assert text in str(info.value)


def test_noisy_intervals_bounded(reduced2):
    with pytest.raises(ValueError, match="`n_intervals`"):
        noisy_intervals(ke.load("two_mode", "full"), P2, Y2, 1e-6, 10**6)


# -- Model's compiled quantities: the compiled functions do not check bounds, so the wrappers do ----------
@pytest.mark.parametrize("call,exc,text", [
    (lambda m, mp, p: m.energy([1e-3, 0.1], p), ValueError, "`y`"),  # read past the end before
    (lambda m, mp, p: m.energy("abc", p), TypeError, "`y`"),
    (lambda m, mp, p: m.energy([True] * 5, p), TypeError, "`y`"),
    (lambda m, mp, p: m.energy(np.zeros((5, 2, 2)), p), ValueError, "`y`"),
    (lambda m, mp, p: m.energy(np.full(5, np.nan), p), ValueError, "`y`"),
    (lambda m, mp, p: m.energy(np.zeros(5), [1.0, 2.0]), ValueError, "`p`"),
    (lambda m, mp, p: m.multipliers([1e-3, 0.1], p), ValueError, "`y`"),
    (lambda m, mp, p: m.multipliers(np.zeros(5), "p"), TypeError, "`p`"),
    (lambda m, mp, p: mp.pose_rates(np.zeros(5), p), ValueError, "`y`"),  # returned uninitialized memory before
    (lambda m, mp, p: mp.pose_rates(np.zeros((8, 3)), p), ValueError, "`y`"),
    (lambda m, mp, p: m.params([1, 1, 2, 0.5, 0.7]), TypeError, "`p`"),
    (lambda m, mp, p: m.state([0, 0, 0, 0, 0.1]), TypeError, "`y0`"),
    # a mapping, as simulate takes: was "every element of `y` must be a real number, got dict"
    (lambda m, mp, p: m.energy(Y2, p), TypeError, "for a mapping of names to values use model.state"),
    (lambda m, mp, p: ke.linearize(m, Y2, p), TypeError, "for a mapping of names to values use model.state"),
    # the scans' grids: one rule for numbers, and a bound (a point costs ~0.2 ms: 10**9 of them ran for days)
    (lambda m, mp, p: ke.stability(m, p, "steady_spin", ["0.1"]), TypeError, "`values`"),  # was float("0.1")
    (lambda m, mp, p: ke.stability(m, p, "steady_spin", True), TypeError, "`values`"),  # was 1.0
    (lambda m, mp, p: ke.stability_boundaries(m, p, "steady_spin", (0.1, 1.0), n_grid=10**9), ValueError,
     "`n_grid` must be an integer from 2 to 100000"),
    # the fixed-step Lyapunov loop: its steps bounded by `max_steps` before anything compiles
    (lambda m, mp, p: ke.lyapunov(m, np.array([1e-3, 1e-3, 0, 0, 0.1]), p, 1e300, h=0.01), ValueError, "`max_steps`"),
    (lambda m, mp, p: ke.lyapunov(m, np.array([1e-3, 1e-3, 0, 0, 0.1]), p, 100.0, h=0.01, max_steps=1000),
     ValueError, "takes 1e+04 steps of `h` = 0.01, more than `max_steps` = 1000"),
])
def test_model_functions_refuse_wrong_shapes_and_types(call, exc, text):
    m, mp = ke.load("two_mode"), ke.load("two_mode", pose=True)
    with pytest.raises(exc) as info:
        call(m, mp, m.params(**P2))
    assert text in str(info.value)


def test_model_functions_accept_the_closed_state_of_a_pose_model():
    """Energy of a pose-extended model ignores the pose: the closed state alone gives the same number."""
    m, mp = ke.load("two_mode"), ke.load("two_mode", pose=True)
    p, y = m.params(**P2), m.state(**Y2)
    assert mp.energy(y, p) == mp.energy(np.r_[y, 0.3, 1.0, -2.0], p) == m.energy(y, p)


# -- scenes' runs and sweeps: the same rules, before any work --------------------------------------
@pytest.mark.parametrize("kw,exc,text", [
    (dict(D="0.5"), TypeError, "`D`"),  # was float("0.5"): accepted
    (dict(D=True), TypeError, "`D`"),  # was 1.0
    (dict(phi_dot=math.nan), ValueError, "`phi_dot`"),
    (dict(t_end="5"), TypeError, "`t_end`"),
    (dict(n_eval=2.5), TypeError, "`n_eval`"),  # was int(2.5) = 2
    (dict(n_eval=10**12), ValueError, "`n_eval`"),  # was a MemoryError in np.linspace
    (dict(max_steps=2**70), ValueError, "`max_steps`"),
])
def test_scene_runs_refuse_bad_values(kw, exc, text):
    from knifeedge.scenes import get_scene

    with pytest.raises(exc) as info:
        get_scene("numerical", **kw)
    assert text in str(info.value)


@pytest.mark.parametrize("grid,text", [
    ({"rtol": [1e-8, 10.0]}, "`rtol`"),  # was one failed run among the results
    ({"atol": [1e300]}, "`atol`"),
    ({"max_steps": [2**70]}, "`max_steps`"),
    ({"method": ["RK4"]}, "`h`"),
    ({"D": [0.5, "1"]}, "`D`"),
])
def test_sweep_checks_every_run_as_simulate_does_before_any_work(grid, text):
    from knifeedge.scenes import get_scene
    from knifeedge.sweep import sweep

    with pytest.raises((ValueError, TypeError)) as info:
        sweep(get_scene("numerical"), grid)
    assert text in str(info.value)


@pytest.mark.parametrize("kw,exc,text", [
    (dict(t_span=10.0), TypeError, "`t_span` must be a pair"),  # was "'float' object is not iterable"
    (dict(t_span=(0.0, 5.0, 10.0)), TypeError, "`t_span` must be a pair"),
    (dict(params=[1.0, 1.0, 1.0, 1.0]), TypeError, "`params` of a scene"),  # was "'list' ... no attribute 'items'"
    (dict(y0=np.array([1e-3, 0.0, 0.1])), TypeError, "`y0` of a scene"),
    (dict(method="RK5"), ValueError, "unknown `method` 'RK5' \\(the argument"),  # said "in `grid`"
])
def test_sweep_of_a_scene_refuses_bad_settings_naming_them(kw, exc, text):
    from knifeedge.sweep import sweep

    with pytest.raises(exc, match=text):
        sweep("numerical", {"D": [1.0]}, executor="serial", progress=False, **kw)


def test_cli_sweep_refuses_a_name_in_both_set_and_grid(capsys):
    assert main(["sweep", "numerical", "--set", "D=2", "--grid", "D=1,3"]) == 2
    assert "`--set` and `--grid` both give 'D'" in capsys.readouterr().err


def test_cli_simulate_runs_the_sleigh_from_its_module_defaults(capsys):
    # issue 9: the CLI takes default parameters and state from the generated module, for every model
    assert main(["simulate", "--model", "chaplygin_sleigh", "--fidelity", "full", "--t-end", "5"]) == 0
    assert "error" not in capsys.readouterr().err


def test_sweep_grid_bounded_before_it_is_expanded():
    """A grid of 1e8 points was expanded into memory (gigabytes) before any check."""
    from knifeedge.scenes import get_scene
    from knifeedge.sweep import MAX_RUNS, sweep

    side = list(np.linspace(1.0, 2.0, 10_000))
    with pytest.raises(ValueError, match="`grid` makes 1e\\+08 runs"):
        sweep(get_scene("numerical"), {"D": side, "L": side})
    assert 10_000 < MAX_RUNS < 10**8


def test_scene_progress_must_be_callable():
    from knifeedge.scenes import get_scene

    with pytest.raises(TypeError, match="`progress`"):
        get_scene("numerical")(progress=3)
