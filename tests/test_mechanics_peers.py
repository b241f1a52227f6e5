"""The field's own models, written with ``sympy.physics.mechanics``, run through knifeedge (slow tier).

Each model is written as its authors wrote it (the source is named where it is built),
converted by ``from_mechanics``, derived, compiled and run by knifeedge, and compared with
its authors' own equations: their ``mass_matrix_full`` and ``forcing_full`` through
``lambdify`` and ``scipy.integrate.solve_ivp`` at rtol 1e-12.

* the rolling disc of SymPy's ``test_kane5.py`` (Kane's method): ``tests/models/sympy_rolling_disc.py``;
  also against knifeedge's built-in ``rolling_disk`` and the equations of sympy#27631;
* the rolling disc of SymPy's ``test_lagrange.py`` (Lagrange's method) as written: its equations are
  those of the SymPy tutorial that sympy#27631 shows wrong (no rolling constraint, potential of the
  wrong sign); written with the constraints as #27631 asks, it is the rolling disc, and its
  multipliers settle the sign question of sympy#30215;
* the differential-drive robot of pydy#127: ``tests/models/differential_drive.py``.
"""
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from sympy.physics.mechanics import (LagrangesMethod, Lagrangian, Point, ReferenceFrame, RigidBody, dynamicsymbols,
                                     inertia)

import knifeedge as ke
from knifeedge import cli
from knifeedge.derive import MechanicsConversionError, derive, from_mechanics, load_specs
from test_rolling_disk import issue_27631, sympy_tutorial

pytestmark = pytest.mark.slow

MODELS = Path(__file__).resolve().parent / "models"
t = dynamicsymbols._t


def _module(name):
    import importlib.util
    spec = importlib.util.spec_from_file_location(f"_peer_{name}", MODELS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def derived(tmp_path_factory):
    out = tmp_path_factory.mktemp("peers")
    for name in ("sympy_rolling_disc", "differential_drive", "pulsing_pendulum"):
        assert cli.main(["derive", str(MODELS / f"{name}.py"), "--out", str(out)]) == 0
    return out


def _authors_rhs(method, coordinates, speeds, params, values, n):
    """The authors' equations: ``mass_matrix_full \\ forcing_full`` (first ``n`` rows) through lambdify."""
    f = sp.lambdify((coordinates, speeds, params), (method.mass_matrix_full, method.forcing_full), cse=True)

    def rhs(_t, z):
        M, F = f(z[:len(coordinates)], z[len(coordinates):], values)
        return np.linalg.solve(np.asarray(M, float), np.asarray(F, float).ravel())[:n]
    return rhs


# ---------------------------------------------------------------- SymPy's test_kane5.py rolling disc

def test_kane_rolling_disc_runs_as_sympys_own_equations(derived):
    disc = _module("sympy_rolling_disc")
    km = disc.KANE
    m = ke.load("sympy_rolling_disc", path=derived, pose=True)
    P = {"g": 9.81, "r": 0.26, "m": 3.43}  # test_kane5.py's values
    p = m.params(P)
    # rolling at 8 rad/s, leaned, turning; q3 away from 0, where test_kane5's LU form divides by sin(q3)
    y0 = m.state({"q2": 0.1, "q2_dot": 0.2, "q1_dot": 0.5, "q3_dot": 8.0,
                  "q1": 0.3, "q3": 1.97, "q4": -0.35, "q5": 2.27})
    x_dot, y_dot = m.pose_rates(y0, p)[2:]
    q, u, qd = list(km.q), list(km.u), [c.diff(t) for c in km.q]
    q0, qd0 = [0.3, 0.1, 1.97, -0.35, 2.27], [0.5, 0.2, 8.0, x_dot, y_dot]
    speeds = sp.lambdify((q, qd, [disc.g, disc.r, disc.m]), [e + s for e, s in zip(disc.kdes, u)])
    values = [P["g"], P["r"], P["m"]]
    ref = solve_ivp(_authors_rhs(km, q, u, [disc.g, disc.r, disc.m], values, 10), (0, 5),
                    q0 + list(speeds(q0, qd0, values)), method="DOP853", rtol=1e-12, atol=1e-12)
    rates = sp.lambdify((q, u, [disc.g, disc.r, disc.m]), [km.kindiffdict()[c] for c in qd])
    theirs = np.r_[ref.y[:5, -1], np.asarray(rates(ref.y[:5, -1], ref.y[5:, -1], values), float)[:3]]
    r = ke.simulate(m, y0, (0, 5), p, rtol=1e-12, atol=1e-12)
    assert r.success, r.message
    ours = dict(zip(m.state_names, r.y[:, -1]))
    ours = np.array([ours[n] for n in ("q1", "q2", "q3", "q4", "q5", "q1_dot", "q2_dot", "q3_dot")])
    np.testing.assert_allclose(ours, theirs, rtol=1e-10, atol=1e-9)


def test_kane_rolling_disc_runs_as_the_builtin_rolling_disk(derived):
    """The same disc, knifeedge's own model (examples/rolling_disk.py, same angles; contact point x, y)."""
    m = ke.load("sympy_rolling_disc", path=derived, pose=True)
    builtin = ke.load("rolling_disk", pose=True)
    start = {"q2": 0.3, "q2_dot": -0.4, "q1_dot": 1.1, "q3_dot": 6.0, "q1": 0.7, "q3": 0.2}
    ours = ke.simulate(m, m.state({**start, "q4": 0.5, "q5": -0.2}), (0, 8), m.params(g=9.81, r=0.26, m=3.43),
                       rtol=1e-12, atol=1e-12)
    base = ke.simulate(builtin, builtin.state({**start, "x": 0.5, "y": -0.2}), (0, 8),
                       builtin.params(g=9.81, r=0.26), rtol=1e-12, atol=1e-12)
    a = dict(zip(m.state_names, ours.y[:, -1]))
    b = dict(zip(builtin.state_names, base.y[:, -1]))
    names = ("q1", "q2", "q3", "q1_dot", "q2_dot", "q3_dot")
    np.testing.assert_allclose([a[n] for n in names] + [a["q4"], a["q5"]],
                               [b[n] for n in names] + [b["x"], b["y"]], rtol=1e-9, atol=1e-9)


def test_kane_rolling_disc_reduces_to_the_equations_of_issue_27631():
    spec = load_specs(MODELS / "sympy_rolling_disc.py")[0]
    system = derive(spec)
    g, m, r = spec.params
    f = sp.lambdify([system.state, (g, m, r)], system.state_rhs())
    rng = np.random.default_rng(27631)
    for _ in range(20):
        gv, rv, q2 = rng.uniform(1, 20), rng.uniform(0.05, 2), rng.uniform(-1.4, 1.4)
        q1d, q2d, q3d = rng.uniform(-5, 5, 3)
        out = f([q2, q2d, q1d, q3d], (gv, 1.3, rv))
        np.testing.assert_allclose([out[2], out[1], out[3]], issue_27631(gv, rv, q2, q1d, q2d, q3d),
                                   rtol=1e-11, atol=1e-11)


# ---------------------------------------------------------------- SymPy's test_lagrange.py rolling disc

def _lagrange_disc(constrained: bool):
    """``test_rolling_disc`` of sympy/physics/mechanics/tests/test_lagrange.py (SymPy 1.14.0).

    ``constrained=False``: as written there (and in SymPy's tutorial): the contact point C fixed in N,
    the potential ``-m g r cos(q2)``.  ``constrained=True``: as sympy#27631 asks: the contact point at
    ``(x, y)``, the disc's velocity from its position, the potential ``+m g r cos(q2)`` (the centre is
    at height ``r cos(q2)``) and the rolling condition as two non-holonomic constraints.
    """
    q1, q2, q3 = dynamicsymbols('q1 q2 q3')
    r, m, g = sp.symbols('r m g')
    N = ReferenceFrame('N')
    Y = N.orientnew('Y', 'Axis', [q1, N.z])
    L = Y.orientnew('L', 'Axis', [q2, Y.x])
    R = L.orientnew('R', 'Axis', [q3, L.y])
    if not constrained:
        C = Point('C')
        C.set_vel(N, 0)
        Dmc = C.locatenew('Dmc', r * L.z)
        Dmc.v2pt_theory(C, N, R)
    else:
        x, y = dynamicsymbols('x y')
        O = Point('O')
        O.set_vel(N, 0)
        C = O.locatenew('C', x * N.x + y * N.y)
        Dmc = C.locatenew('Dmc', r * L.z)
        Dmc.set_vel(N, Dmc.pos_from(O).dt(N))
    I = inertia(L, m/4 * r**2, m/2 * r**2, m/4 * r**2)
    BodyD = RigidBody('BodyD', Dmc, R, m, (I, Dmc))
    BodyD.potential_energy = (1 if constrained else -1) * m * g * r * sp.cos(q2)
    Lag = Lagrangian(N, BodyD)
    if not constrained:
        return LagrangesMethod(Lag, [q1, q2, q3]), (q1, q2, q3), (g, r, m)
    slip = Dmc.vel(N) + R.ang_vel_in(N).cross(C.pos_from(Dmc))  # velocity of the disc's point at C
    lm = LagrangesMethod(Lag, [q1, q2, q3, x, y], nonhol_coneqs=[slip.dot(N.x), slip.dot(N.y)], frame=N)
    return lm, (q1, q2, q3, x, y), (g, r, m), Dmc.pos_from(O).to_matrix(N)


def test_lagrange_rolling_disc_as_written_is_the_wrong_tutorial_one():
    """Its own equations are the tutorial's that sympy#27631 shows wrong, not the rolling disc's; knifeedge
    refuses the model (no velocity constraint) and says why."""
    lm, q, p = _lagrange_disc(constrained=False)
    lm.form_lagranges_equations()
    qd = [c.diff(t) for c in q]
    rng = np.random.default_rng(1)
    for _ in range(10):
        gv, rv, q2 = rng.uniform(1, 20), rng.uniform(0.05, 2), rng.uniform(-1.4, 1.4)
        q1d, q2d, q3d = rng.uniform(-5, 5, 3)
        f = _authors_rhs(lm, q, qd, p, (gv, rv, 1.0), 6)
        acc = f(0, [0.3, q2, 0.1, q1d, q2d, q3d])[3:]
        np.testing.assert_allclose(acc, sympy_tutorial(gv, rv, q2, q1d, q2d, q3d), rtol=1e-10, atol=1e-10)
        assert np.max(np.abs(acc - np.array(issue_27631(gv, rv, q2, q1d, q2d, q3d)))) > 1e-3
    with pytest.raises(MechanicsConversionError, match="no velocity constraint.*sympy#27631"):
        from_mechanics(lm, name="tutorial_disc", cyclic={q[0]: 0, q[2]: 0})


@pytest.fixture(scope="module")
def lagrange_disc():
    lm, q, p, centre = _lagrange_disc(constrained=True)
    lm.form_lagranges_equations()
    spec = from_mechanics(lm, name="lagrange_disc", cyclic={q[0]: 0, q[2]: 0, q[3]: 0, q[4]: 0})
    return lm, q, p, centre, spec, derive(spec)


def _on_the_manifold(lm, q, p, values, rng):
    """A random state (q, q_dot) with the contact point's rates from the constraints."""
    qv = np.r_[0.0, rng.uniform(-1.2, 1.2), rng.uniform(-3, 3), rng.uniform(-1, 1, 2)]
    ind = rng.uniform(-4, 4, 3)
    qd = [c.diff(t) for c in q]
    A = sp.lambdify((q, p), sp.Matrix(lm.coneqs).jacobian(qd))
    Av = np.asarray(A(qv, values), float)
    dep = np.linalg.solve(Av[:, 3:], -Av[:, :3] @ ind)
    return qv, np.r_[ind, dep]


def test_lagrange_rolling_disc_with_its_constraints_is_the_rolling_disc(lagrange_disc):
    """Written as sympy#27631 asks, the disc by LagrangesMethod, knifeedge's derivation of it and the
    issue's equations agree at random states."""
    lm, q, p, centre, spec, system = lagrange_disc
    assert [str(c) for c in spec.dependent] == ["x", "y"]
    f = sp.lambdify([system.state, spec.params], system.state_rhs())
    rng = np.random.default_rng(30215)
    for _ in range(10):
        values = (rng.uniform(1, 20), rng.uniform(0.05, 2), rng.uniform(0.5, 3))  # g, r, m
        qv, qdv = _on_the_manifold(lm, q, p, values, rng)
        theirs = _authors_rhs(lm, q, [c.diff(t) for c in q], p, values, 10)(0, np.r_[qv, qdv])[5:8]
        pv = [dict(zip(map(str, p), values))[str(s)] for s in spec.params]
        ours = f([qv[1], qdv[1], qdv[0], qdv[2]], pv)
        np.testing.assert_allclose([ours[2], ours[1], ours[3]], theirs, rtol=1e-10, atol=1e-10)
        np.testing.assert_allclose(theirs, issue_27631(values[0], values[1], qv[1], *qdv[:3]), rtol=1e-10,
                                   atol=1e-10)


def test_lagrange_multipliers_are_the_contact_force_with_the_sign_of_issue_30215(lagrange_disc):
    """Newton for the centre of mass: the horizontal contact force is m a_G (no other horizontal force).

    The constraints are the contact point's velocity along N.x and N.y, so the contact force F enters
    Lagrange's equations as A^T F.  The multipliers of ``mass_matrix_full`` / ``forcing_full`` (what
    ``rhs()`` and ``solve_multipliers`` return) are F, and so are knifeedge's (heading 0, its
    representative pose); but ``LagrangesMethod.eom`` holds the opposite sign: it vanishes with -F, not F
    (sympy#30215: LagrangesMethod stores the negative of the constraint Jacobian).
    """
    lm, q, p, centre, spec, system = lagrange_disc
    qd, qdd = [c.diff(t) for c in q], [c.diff(t, 2) for c in q]
    acc_centre = sp.lambdify((q, qd, qdd, p), centre.diff(t, 2)[:2])
    eom = sp.lambdify((q, qd, qdd, list(lm.lam_vec), p), list(lm.eom))
    lam_ours = sp.lambdify([system.state, spec.params], list(system.multipliers))
    rng = np.random.default_rng(7)
    for _ in range(5):
        values = (rng.uniform(1, 20), rng.uniform(0.05, 2), rng.uniform(0.5, 3))
        qv, qdv = _on_the_manifold(lm, q, p, values, rng)
        full = _authors_rhs(lm, q, qd, p, values, 12)(0, np.r_[qv, qdv])
        qddv, lam = full[5:10], full[10:12]
        force = values[2] * np.asarray(acc_centre(qv, qdv, qddv, values), float)
        np.testing.assert_allclose(lam, force, rtol=1e-10, atol=1e-10)
        pv = [dict(zip(map(str, p), values))[str(s)] for s in spec.params]
        np.testing.assert_allclose(lam_ours([qv[1], qdv[1], qdv[0], qdv[2]], pv), force, rtol=1e-10, atol=1e-10)
        assert np.max(np.abs(eom(qv, qdv, qddv, -force, values))) < 1e-9
        assert np.max(np.abs(eom(qv, qdv, qddv, force, values))) > 1e-3


# ---------------------------------------------------------------- pydy#127: the differential-drive robot

@pytest.mark.parametrize("d", [0.0, 0.1])  # the notebook's d = 0, and its centre of mass ahead of the axle
def test_differential_drive_runs_as_its_authors_equations(derived, d):
    robot = _module("differential_drive")
    lm = robot.LAGRANGE
    lm.form_lagranges_equations()
    m = ke.load("differential_drive", path=derived, pose=True)
    P = dict(Izz=5.0, t_w=0.15, m_w=2.0, r=0.15, m_b=50.0, w=0.6, d=d, tau_1=1.2, tau_2=1.0)
    p = m.params(P)
    y0 = m.state({"phi_1_dot": 0.3, "phi_2_dot": -0.1, "x": 0.2, "y": -0.1, "theta": 0.4})
    dep = m.pose_rates(y0, p)[:3]
    symbols = [robot.Izz, robot.t_w, robot.m_w, robot.r, robot.m_b, robot.w, robot.d, robot.T1, robot.T2]
    rhs = _authors_rhs(lm, list(robot.q), list(robot.dq), symbols, [P[str(s)] for s in symbols], 10)
    ref = solve_ivp(rhs, (0, 10), [0.2, -0.1, 0.4, 0, 0, *dep, 0.3, -0.1], method="DOP853", rtol=1e-12,
                    atol=1e-12)
    r = ke.simulate(m, y0, (0, 10), p, rtol=1e-12, atol=1e-12)
    assert r.success, r.message
    ours = dict(zip(m.state_names, r.y[:, -1]))
    names = ("x", "y", "theta", "phi_1", "phi_2", "phi_1_dot", "phi_2_dot")
    theirs = np.r_[ref.y[:5, -1], ref.y[8:, -1]]
    np.testing.assert_allclose([ours[n] for n in names], theirs, rtol=1e-10, atol=1e-9)
    assert abs(ours["theta"] - 0.4) > 0.5 and np.hypot(ours["x"] - 0.2, ours["y"] + 0.1) > 0.3  # it drove, turned


# ---------------------------------------------------------------- a configuration constraint that holds time

def test_pulsing_pendulum_runs_as_its_authors_equations(derived):
    """SymPy's Cartesian pendulum (test_lagrange.py) with a rod of length L (1 + e sin(w t)):
    ``hol_coneqs`` and explicit time, against LagrangesMethod's own equations through lambdify."""
    model = _module("pulsing_pendulum")
    lm = model.LAGRANGE
    lm.form_lagranges_equations()
    m = ke.load("pulsing_pendulum", path=derived)
    P = dict(L=1.3, m=2.1, e=0.1, w=3.0)
    p = m.params(P)
    q1, q2 = lm.q
    symbols = [model.L, model.m, model.e, model.w]
    values = [P[str(s)] for s in symbols]
    f = sp.lambdify((t, list(lm.q), list(lm.q.diff(t)), symbols), (lm.mass_matrix_full, lm.forcing_full), cse=True)

    def rhs(time, z):
        M, F = f(time, z[:2], z[2:4], values)
        return np.linalg.solve(np.asarray(M, float), np.asarray(F, float).ravel())[:4]

    t0 = 0.4  # the rod's rate is not zero there
    length = P["L"] * (1 + P["e"] * np.sin(P["w"] * t0))
    rate = P["L"] * P["e"] * P["w"] * np.cos(P["w"] * t0)
    y2, y2d = 0.6, 0.9
    y1 = np.sqrt(length**2 - y2**2)
    y1d = (length * rate - y2 * y2d) / y1
    ref = solve_ivp(rhs, (t0, t0 + 10), [y1, y2, y1d, y2d], method="DOP853", rtol=1e-12, atol=1e-12)
    y0 = m.state({"q1": y1, "q2": y2, "q2_dot": y2d})
    r = ke.simulate(m, y0, (t0, t0 + 10), p, rtol=1e-12, atol=1e-12)
    assert r.success, r.message
    ours = dict(zip(m.state_names, r.y[:, -1]))
    np.testing.assert_allclose([ours["q1"], ours["q2"], ours["q2_dot"]], ref.y[[0, 1, 3], -1], rtol=1e-9,
                               atol=1e-9)
    assert abs(m.holonomic_residual(r.y[:, -1], p, r.t[-1])[0]) < 1e-9
    assert np.ptp(r.y[m.state_names.index("q2")]) > 0.5  # it swung


# ---------------------------------------------------------------- SymPy's test_kane3.py Whipple bicycle

def test_sympys_whipple_bicycle_as_written_is_refused_with_the_reason():
    """test_kane3.py's bicycle fixes the rear contact point in N and leaves the wheels' angles out (u3, u6
    have no coordinates): its velocities already obey the rolling constraints, so there is no Lagrangian
    to build from it.  The model is run as SymPy's own test builds it (its source, up to the benchmark's
    numbers); ``tests/models/whipple_bicycle.py`` is the same bicycle with those coordinates."""
    import inspect
    import textwrap

    from sympy.physics.mechanics.tests import test_kane3
    body = textwrap.dedent(inspect.getsource(test_kane3.test_bicycle).split("\n", 2)[2])
    namespace = {}
    exec("from sympy import *\nfrom sympy.physics.mechanics import *\n" + body[:body.index("PaperRadRear")],
         namespace)
    with pytest.raises(MechanicsConversionError, match=r"speeds \[u3\(t\), u6\(t\)\] have no kinematic"):
        from_mechanics(namespace["KM"], name="whipple", cyclic={namespace["q1"]: 0})


def test_the_peer_benchmark_matches_errors_not_tolerances():
    """benchmarks/mechanics_peers.py compares knifeedge and PyDy at equal error: the tolerance of knifeedge whose
    error is nearest PyDy's (in ratio), not the same nominal rtol (at rtol 1e-10 knifeedge's max-norm control is
    20x more accurate than SciPy's RMS-norm DOP853 on the bicycle)."""
    from benchmarks.mechanics_peers import matched

    errors = {1e-10: 5.7e-14, 1e-9: 4.9e-13, 2e-9: 1.1e-12, 1e-8: 4.9e-12}
    assert matched(errors, 1.6e-12) == 2e-9
    assert matched(errors, 5.1e-14) == 1e-10
    assert matched(errors, 3.5e-12) == 1e-8  # 1.4x from 4.9e-12, 3.2x from 1.1e-12
