"""The Whipple bicycle benchmark (issue 23): Meijaard, Papadopoulos, Ruina & Schwab 2007, *Linearized dynamics
equations for the balance and steer of a bicycle: a benchmark and review*, Proc. R. Soc. A 463, 1955-1982.

The model is sympy's ``test_kane3.py`` bicycle with the coordinates a Lagrangian needs
(tests/models/whipple_bicycle.py), converted by ``from_mechanics`` and derived with the numeric elimination of
the multipliers.  The expected numbers are the benchmark's, as sympy's ``test_kane3.py::test_bicycle`` holds
them: its lean/steer matrix ``Res`` (the benchmark's ``M^-1 [K0 g + K2 v^2, C1 v]``, 15 digits) and the weave and
capsize speeds of the paper's section 4 (Table 2: 4.29238253634111 and 6.02426201538837 m/s).
"""
import importlib.util
from pathlib import Path

import numpy as np
import pytest

import knifeedge as ke
from knifeedge.stability import steady_state

MODELS = Path(__file__).resolve().parent / "models"

#: sympy test_kane3.py ``Res``: rows d(lean, steer, lean rate, steer rate)/dt, columns (lean, steer, lean rate,
#: steer rate), at forward speed v (the benchmark's linearized equations, Meijaard et al. 2007 eq. (A 20) values)
def benchmark_matrix(v: float) -> np.ndarray:
    return np.array([
        [0, 0, 1.0, 0],
        [0, 0, 0, 1.0],
        [9.48977444677355, -0.891197738059089 * v**2 - 0.571523173729245, -0.105522449805691 * v,
         -0.330515398992311 * v],
        [11.7194768719633, -1.97171508499972 * v**2 + 30.9087533932407, 3.67680523332152 * v,
         -3.08486552743311 * v]])


#: Meijaard et al. 2007, section 4 (Table 2): the weave and capsize speeds of the benchmark bicycle [m/s]
WEAVE, CAPSIZE = 4.29238253634111, 6.02426201538837


def model_file():
    spec = importlib.util.spec_from_file_location("_whipple_bicycle", MODELS / "whipple_bicycle.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="session")
def bicycle(tmp_path_factory):
    """The bicycle derived once per session (``knifeedge derive``, which also checks it at a general pose)."""
    from knifeedge import cli

    out = tmp_path_factory.mktemp("whipple_bicycle") / "bikes"  # the folder docs/from-sympy.md names
    assert cli.main(["derive", str(MODELS / "whipple_bicycle.py"), "--out", str(out)]) == 0
    return ke.load("whipple_bicycle", path=out)


@pytest.mark.slow  # derives the bicycle (about a minute of CPU): the slow tier
def test_numeric_elimination_and_state(bicycle):
    assert bicycle.module.ELIMINATION == "numeric"
    assert bicycle.state_names == ("q2", "q5", "q4", "q2_dot", "q5_dot", "q3_dot")
    assert bicycle.module.HOLONOMIC_NAMES == ("h1",)


@pytest.mark.slow
def test_the_right_hand_side_is_ir_with_its_pivoting(bicycle):
    """The bicycle's right-hand side solves its dependent velocities by an LU whose pivot choices are selects;
    the module carries it as IR (the integrators inline it into their stages instead of calling numba's
    compilation), numba's bits (tests/test_ir_emit.py)."""
    from test_ir_emit import check_module_ir

    for name in ("rhs_q_into", "rhs_pose_q_into"):
        assert "select i1" in bicycle.module.LLVM_IR[name]
    check_module_ir(bicycle.module, "whipple_bicycle", rounds=2)


@pytest.mark.slow
def test_lean_steer_matrix_equals_the_benchmark(bicycle):
    """The linearization about straight running, lean/steer block, equals the benchmark's matrix at 0..10 m/s."""
    p = bicycle.params(bicycle.default_params)
    keep = [0, 1, 3, 4]  # q2 (lean), q5 (steer), their rates
    for v in np.arange(0.0, 10.5, 0.5):
        y = steady_state(bicycle, p, "straight_running", v)
        lin = ke.linearize(bicycle, y, p, family="straight_running")
        A = lin.A[np.ix_(keep, keep)]
        np.testing.assert_allclose(A, benchmark_matrix(v), rtol=0, atol=1e-10, err_msg=f"v = {v}")
        assert len(lin.modes) == 4  # the pitch (holonomic constraint) and the speed are not physical directions
        np.testing.assert_allclose(np.sort_complex(lin.physical_eigenvalues),
                                   np.sort_complex(np.linalg.eigvals(benchmark_matrix(v))), rtol=1e-9, atol=1e-9)


@pytest.mark.slow
def test_weave_and_capsize_speeds(bicycle):
    """The self-stable speed range of the benchmark: weave 4.29238253634111, capsize 6.02426201538837 m/s."""
    p = bicycle.params(bicycle.default_params)
    speeds = ke.stability_boundaries(bicycle, p, "straight_running", (0.5, 10.0))
    np.testing.assert_allclose(speeds, [WEAVE, CAPSIZE], rtol=0, atol=1e-9)


@pytest.mark.slow
def test_the_docs_bicycle_section_runs(bicycle, monkeypatch):
    """docs/from-sympy.md section 6 (blocks ``sh bicycle``, ``python bicycle``) as written, in the folder the
    fixture derived into with the command the doc gives."""
    import re
    import shlex

    import docs_blocks

    doc = (Path(__file__).resolve().parents[1] / "docs" / "from-sympy.md").read_text()
    (command,) = re.findall(r"```sh bicycle\n(.*?)```", doc, flags=re.S)
    assert shlex.split(command) == ["knifeedge", "derive", "tests/models/whipple_bicycle.py", "--out", "bikes"]
    monkeypatch.chdir(Path(bicycle.module.__file__).parent.parent)
    for code in re.findall(r"```python bicycle\n(.*?)```", doc, flags=re.S):
        docs_blocks.run(code, "docs/from-sympy.md", {})


def _run(bicycle, v: float, lean_rate: float, t_end: float):
    p = bicycle.params(bicycle.default_params)
    y0 = steady_state(bicycle, p, "straight_running", v)
    y0[bicycle.state_names.index("q2_dot")] = lean_rate  # on the constraint manifold: lean, steer, pitch zero
    r = ke.simulate(bicycle, y0, (0.0, t_end), p, rtol=1e-10, atol=1e-12, t_eval=np.linspace(0.0, t_end, 501))
    assert r.success, r.message
    return r, p


@pytest.mark.slow
def test_self_stable_at_5_m_per_s(bicycle):
    """Between the weave and capsize speeds a lean perturbation decays (Meijaard et al. 2007, section 4: at 5 m/s
    the slowest mode, capsize, decays at 0.32 1/s); no dissipation: the energy holds; the holonomic constraint's
    residual (the front contact's height) stays at the integrator's error."""
    r, p = _run(bicycle, 5.0, 0.5, 10.0)
    lean = np.abs(r["q2"])
    assert lean[r.t >= 9.0].max() < 0.1 * lean[r.t <= 2.0].max()
    e = r.energy
    assert np.max(np.abs(e - e[0])) < 1e-9 * abs(e[0])
    residual = max(abs(bicycle.module.holonomic_residual(r.y[:, i], p)[0]) for i in range(r.t.size))
    assert residual < 1e-9


@pytest.mark.slow
def test_falls_at_3_m_per_s(bicycle):
    """Below the weave speed the weave mode grows (1.71 1/s at 3 m/s, from the benchmark's matrix): it falls."""
    r, _ = _run(bicycle, 3.0, 0.05, 2.5)
    lean = np.abs(r["q2"])
    assert lean[r.t >= 2.0].max() > 5 * lean[r.t <= 0.5].max()
    assert lean.max() > 0.2
    e = r.energy
    assert np.max(np.abs(e - e[0])) < 1e-9 * abs(e[0])


@pytest.mark.slow  # SymPy forms the bicycle's Lagrange equations in about a minute
def test_nonlinear_run_matches_sympys_lagranges_method(bicycle):
    """The same bicycle by SymPy's own LagrangesMethod, integrated independently: sympy's Lagrangian of the four
    bodies (``Lagrangian(N, *bodies)``, gravity as their ``potential_energy``), the four rolling conditions as
    ``nonhol_coneqs``, the front contact on the ground as ``hol_coneqs``; its multipliers kept
    (``mass_matrix_full``, ``forcing_full`` through lambdify, solved by numpy at each step) and DOP853 at
    rtol 1e-12.  3 s at 5 m/s from a lean rate of 0.5 rad/s."""
    import sympy as sp
    from scipy.integrate import solve_ivp
    from sympy.physics.mechanics import Lagrangian, LagrangesMethod

    W = model_file()
    qs = [W.q1, W.q2, W.q3, W.q4, W.q5, W.q6, W.x, W.y]
    us = [W.u1, W.u2, W.u3, W.u4, W.u5, W.u6, W.ux, W.uy]
    qd = [q.diff(W.t) for q in qs]
    to_qd = dict(zip(us, qd))
    for body in W.BL:
        body.potential_energy = body.mass * W.g * (body.masscenter.pos_from(W.O) & W.N.z)
    L = Lagrangian(W.N, *W.BL).xreplace(to_qd)
    nonhol = [c.xreplace(to_qd) for c in W.conlist_speed[:4]]
    lm = LagrangesMethod(L, qs, hol_coneqs=W.conlist_coord, nonhol_coneqs=nonhol, frame=W.N)
    lm.form_lagranges_equations()
    params = sorted(set().union(L.free_symbols, *(c.free_symbols for c in nonhol + W.conlist_coord)) - {W.t},
                    key=str)
    values = [W.BENCHMARK[str(s)] for s in params]
    f = sp.lambdify((qs, qd, params), (lm.mass_matrix_full, lm.forcing_full), cse=True)
    rates = sp.Matrix(nonhol + [sum(sp.diff(W.conlist_coord[0], q) * v for q, v in zip(qs, qd))])
    A = np.asarray(sp.lambdify((qs, params), rates.jacobian(qd))(np.zeros(8), values), float)
    qd0 = np.zeros(8)
    qd0[[1, 2]] = 0.5, 5.0 / W.BENCHMARK["WRrad"]  # lean rate, rear wheel rate; the rest from the constraints
    ind, dep = [1, 2, 4], [0, 3, 5, 6, 7]
    qd0[dep] = np.linalg.solve(A[:, dep], -A[:, ind] @ qd0[ind])

    def rhs(_t, z):
        M, F = f(z[:8], z[8:], values)
        return np.linalg.solve(np.asarray(M, float), np.asarray(F, float).ravel())[:16]

    ref = solve_ivp(rhs, (0.0, 3.0), np.r_[np.zeros(8), qd0], method="DOP853", rtol=1e-12, atol=1e-12)
    assert ref.success
    theirs = ref.y[[1, 4, 3, 9, 12, 10], -1]  # q2, q5, q4, their rates and q3's, as the closed state
    p = bicycle.params(bicycle.default_params)
    y0 = steady_state(bicycle, p, "straight_running", 5.0)
    y0[bicycle.state_names.index("q2_dot")] = 0.5
    r = ke.simulate(bicycle, y0, (0.0, 3.0), p, rtol=1e-12, atol=1e-12)
    assert r.success, r.message
    ours = r.y[[bicycle.state_names.index(n) for n in ("q2", "q5", "q4", "q2_dot", "q5_dot", "q3_dot")], -1]
    np.testing.assert_allclose(ours, theirs, rtol=0, atol=1e-9)
    assert abs(theirs[0]) > 1e-3  # it leaned


@pytest.mark.slow
def test_the_linear_module_is_this_derivations(bicycle):
    """generated/linear/whipple_bicycle.py (``make bicycle-linear``, the scene ``bicycle_stability``'s model) holds
    the lean/steer block of this derivation's Jacobian: the coefficients taken again from the fixture's module."""
    from knifeedge.derive import bicycle_linear
    from knifeedge.generated.linear import whipple_bicycle as checked_in

    blocks = bicycle_linear.jacobian_blocks(Path(bicycle.module.__file__), bicycle_linear.SPEEDS)
    for fresh, name in zip(bicycle_linear.coefficients(blocks), ("A0", "A1", "A2")):
        np.testing.assert_allclose(fresh, getattr(checked_in, name), rtol=0, atol=1e-12, err_msg=name)
