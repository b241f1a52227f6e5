"""The rigid-body front end and the classical rattleback ``celt``.

Expected values come from an independent formulation (``rigid_reference``:
Newton--Euler in body axes written directly in numpy, integrated by SciPy),
from invariants (energy; energy plus dissipated work) and from closed forms.
Sources: T. R. Kane and D. A. Levinson, Int. J. Non-Linear Mech. 17 (1982)
175-186 (the ``kane_levinson_1982`` preset and its initial condition);
A. Garcia and M. Hubbard, Proc. R. Soc. Lond. A 418 (1988) 165-197.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

import knifeedge as ke
import rigid_reference as ref
from derivation import rigid
from derivation.celt import celt

TILT = math.radians(0.5)
#: Kane & Levinson's initial vertical: al = be = 0.5 deg
N0 = (math.cos(TILT) * math.sin(TILT), math.sin(TILT), math.cos(TILT) * math.cos(TILT))


@pytest.fixture(scope="module")
def m():
    return ke.load("celt")


def _random_states(rng, k):
    for _ in range(k):
        n = rng.normal(size=3)
        n /= np.linalg.norm(n)
        w = rng.normal(size=3) * 5.0
        yield np.concatenate([n, w, [n @ w]])


@pytest.mark.parametrize("preset, sigma", [("kane_levinson_1982", 0.0), ("kane_levinson_1982", 1e-4),
                                           ("schoemer", 0.0)])
def test_rhs_and_energy_match_newton_euler(m, preset, sigma):
    """Generated right-hand side and energy against the independent Newton--Euler formulation at random states."""
    p = m.preset(preset, sigma=sigma)
    for s in _random_states(np.random.default_rng(7), 25):
        got = m.rhs(0.0, s, p)
        want = ref.rhs(0.0, s, p)
        np.testing.assert_allclose(got[:6], want, rtol=0, atol=1e-12 * np.abs(want).max())
        assert got[6] == pytest.approx(want[3:6] @ s[:3], rel=1e-12, abs=1e-12 * np.abs(want).max())
        assert m.energy(s, p) == pytest.approx(ref.energy(s, p), rel=1e-13)


def test_mass_matrix_and_closed_form_agree():
    """M(n) domega/dt = f(n, omega): the closed-form (Cramer) solution solves the system, at random points."""
    system = rigid.derive(celt())
    rng = np.random.default_rng(5)
    for _ in range(3):
        pt = {s: v for s, v in zip(system.spec.params, [0.2, 0.03, 0.02, 0.01, 1, 9.81, 2e-4, 1.6e-3, 1.7e-3,
                                                        2e-5, 3e-6, -4e-6, 1e-4])}
        pt.update(zip(rigid.N_VEC, rng.normal(size=3)))
        pt.update(zip(rigid.OMEGA, rng.normal(size=3)))
        M = np.array(system.mass_matrix.xreplace(pt).evalf(), dtype=float)
        f = np.array(system.forcing.xreplace(pt).evalf(), dtype=float).ravel()
        x = np.array(system.explicit.xreplace(pt).evalf(), dtype=float).ravel()
        np.testing.assert_allclose(M @ x, f, rtol=1e-12, atol=1e-12 * np.abs(f).max())


def test_contact_height_is_the_integral_of_the_vertical_rolling_constraint():
    """d/dt z(n) = V . n with V = -omega x r: the height and the rolling constraints are consistent."""
    parts = rigid.equations(celt())
    n, w = rigid.N_VEC, rigid.OMEGA
    z_dot = (sp.Matrix([parts["height"]]).jacobian(n) * n.cross(w))[0]
    vertical = parts["velocity"].dot(n)
    rng = np.random.default_rng(3)
    syms = celt().params
    for _ in range(5):
        nv = rng.normal(size=3)
        nv /= np.linalg.norm(nv)
        pt = {**dict(zip(n, nv)), **dict(zip(w, rng.normal(size=3))),
              **{s: v for s, v in zip(syms, [0.2, 0.03, 0.02, 0.01, 1, 9.81, 2e-4, 1.6e-3, 1.7e-3, 2e-5, 0, 0, 0])}}
        assert float((z_dot - vertical).subs(pt)) == pytest.approx(0.0, abs=1e-14)


def test_first_reversal_and_spin_against_independent_integration(m):
    """Kane & Levinson (1982) scene, Omega = +5 rad/s: crossings of omega.n and the spin after the reversal.

    Reference: the Newton--Euler formulation integrated by SciPy's DOP853 at rtol 1e-13.
    """
    p = m.preset("kane_levinson_1982")
    y0 = m.initial_state(n0=N0, omega0=(0.0, 0.0, 5.0))
    sol = ref.integrate(y0, (0.0, 4.0), p, rtol=1e-13, atol=1e-15)
    r = ke.simulate(m, y0, (0.0, 4.0), p, rtol=1e-10, atol=1e-12)
    assert r.success
    want = sol.t_events[0]
    assert len(want) >= 2 and abs(want[1] - want[0]) < 1e-3  # a reversal is a cluster of close crossings
    np.testing.assert_allclose(r.reversal_times, want, rtol=1e-6)
    end = np.asarray(sol.sol(4.0))
    assert r["omega_n"][-1] == pytest.approx(end[:3] @ end[3:6], rel=1e-6)
    assert r["omega_n"][-1] < 0  # spin reversed


@pytest.mark.parametrize("omega", [5.0, -5.0])
def test_energy_is_conserved_without_damping(m, omega):
    """Undamped rolling conserves the mechanical energy: 1e-9 relative over 20 s at rtol 1e-10."""
    p = m.preset("kane_levinson_1982")
    r = ke.simulate(m, m.initial_state(n0=N0, omega0=(0.0, 0.0, omega)), (0.0, 20.0), p, rtol=1e-10, atol=1e-12)
    assert r.success
    E = m.energy(r.y, p)
    assert np.max(np.abs(E - E[0])) <= 1e-9 * abs(E[0])
    assert len(r.reversal_times) > 0


def test_energy_plus_dissipated_work_is_constant(m):
    """sigma = 1e-4 N m s: E(t) + int_0^t sigma |omega|^2 dt = E(0) (Simpson on a fine output grid)."""
    from scipy.integrate import cumulative_simpson

    p = m.preset("kane_levinson_1982", sigma=1e-4)
    t = np.linspace(0.0, 10.0, 20001)
    r = ke.simulate(m, m.initial_state(n0=N0, omega0=(0.0, 0.0, -5.0)), (0.0, 10.0), p, rtol=1e-10, atol=1e-12,
                    t_eval=t)
    assert r.success
    E = m.energy(r.y, p)
    W = cumulative_simpson(m.dissipated_power(r.y, p), x=r.t, initial=0.0)
    assert W[-1] > 1e-4 * E[0]  # the damping does work
    assert np.max(np.abs(E + W - E[0])) <= 1e-9 * abs(E[0])


def test_presets_and_overrides(m):
    """The published parameter sets (Kane & Levinson 1982; Schoemer) as validated vectors."""
    p = m.preset("kane_levinson_1982", sigma=1e-4)
    values = dict(zip(m.param_names, p))
    assert values["I_xy"] == 2e-5 and values["sigma"] == 1e-4 and values["a"] == 0.2
    s = dict(zip(m.param_names, m.preset("schoemer")))
    assert s["a"] == pytest.approx((1 + math.sqrt(5)) / 2, rel=1e-15) and s["I_xy"] == -0.025
    with pytest.raises(ValueError, match="preset `name`"):
        m.preset("nope")
    with pytest.raises(ValueError, match="unknown parameters"):
        m.preset("schoemer", sigmaa=1.0)
    with pytest.raises(ValueError, match="`sigma` must be nonnegative"):
        m.preset("schoemer", sigma=-1.0)
    with pytest.raises(ValueError, match="`m` must be positive"):
        m.preset("schoemer", m=0.0)


def test_initial_state_normalizes_and_validates(m):
    y = m.initial_state(n0=(0.0, 0.0, 2.0), omega0=(0.01, -0.02, -2.0))
    np.testing.assert_array_equal(y, [0, 0, 1, 0.01, -0.02, -2.0, -2.0])
    y = m.initial_state(n0=(0.0, -1.0, 0.0), omega0=(1.0, 2.0, 3.0))  # on its side: still representable
    assert y[6] == -2.0
    with pytest.raises(ValueError, match="`n0`"):
        m.initial_state(n0=(0.0, 0.0), omega0=(0.0, 0.0, 1.0))
    with pytest.raises(ValueError, match="`n0`"):
        m.initial_state(n0=(0.0, 0.0, 0.0), omega0=(0.0, 0.0, 1.0))
    with pytest.raises(ValueError, match="`omega0`"):
        m.initial_state(n0=(0.0, 0.0, 1.0), omega0=(0.0, math.nan, 1.0))
    with pytest.raises(ValueError, match="`pose`"):
        m.initial_state(n0=(0.0, 0.0, 1.0), pose=(0.0, 0.0, 0.0))
    mp = ke.load("celt", pose=True)
    assert mp.initial_state(n0=(0.0, 0.0, 1.0), pose=(1.0, 2.0, 3.0))[-3:].tolist() == [1.0, 2.0, 3.0]


def test_pose_follows_the_rolling_constraint():
    """Pose rates: the centre of mass moves with V = -omega x r; heading rate of a spinning upright body.

    Upright (n = e_z) and spinning about the vertical, the contact is below the centre
    of mass, so the centre of mass does not move and psi_dot = omega_z.
    """
    mp = ke.load("celt", pose=True)
    p = mp.preset("kane_levinson_1982")
    s = mp.initial_state(n0=(0.0, 0.0, 1.0), omega0=(0.0, 0.0, 3.0), pose=(0.3, 0.0, 0.0))
    np.testing.assert_allclose(mp.pose_rates(s, p), [3.0, 0.0, 0.0], atol=1e-15)
    # pure rocking about the body y axis upright: V = -omega x r = (-omega_y r_z, 0, 0), r = (0, 0, h - c)
    s = mp.initial_state(n0=(0.0, 0.0, 1.0), omega0=(0.0, 2.0, 0.0), pose=(0.0, 0.0, 0.0))
    r_z = 0.01 - 0.02
    np.testing.assert_allclose(mp.pose_rates(s, p), [0.0, -2.0 * r_z, 0.0], atol=1e-15)


def test_front_end_collects_description_errors():
    a, q = sp.symbols("a q", positive=True)
    body = rigid.RigidBody(name="bad", mass=a, inertia=sp.Matrix([[a, 1, 0], [0, a, 0], [0, 0, a]]),
                           shape=rigid.Sphere(q), gravity=a, params=(a,))
    with pytest.raises(ValueError, match=r"symmetric.*not declared.*\['q'\]"):
        body.check()


def test_front_end_sphere_closed_form():
    """A ball whose centre of mass is its centre: rolling does not couple spin and tilt.

    For a homogeneous ball (I = (2/5) m R^2) the angular momentum about the
    contact point, (7/5) m R^2 omega_h + (2/5) m R^2 omega_v, is conserved
    (gravity and the normal force have no moment about it), so omega is
    constant in space; the body is isotropic, so d(omega)/dt = 0 in body
    axes as well.  Energy: T = m R^2 (|omega|^2 - (omega.n)^2)/2 + (1/5) m R^2 |omega|^2, U = m g R.
    """
    m_, R, g_ = sp.symbols("m R g", positive=True)
    body = rigid.RigidBody(name="ball", mass=m_, inertia=sp.Rational(2, 5) * m_ * R**2 * sp.eye(3),
                           shape=rigid.Sphere(R), gravity=g_, params=(m_, R, g_))
    system = rigid.derive(body)
    pt = {**dict(zip(rigid.N_VEC, (0.36, 0.48, 0.8))), **dict(zip(rigid.OMEGA, (1.0, -2.0, 0.5))),
          m_: 2.0, R: 0.3, g_: 9.81}
    for e in system.omega_dot:
        assert float(e.subs(pt)) == pytest.approx(0.0, abs=1e-13)
    assert float(system.energy.subs(pt)) == pytest.approx(
        0.5 * 2.0 * (2 / 5 + 1) * 0.09 * (1 + 4 + 0.25) - 0.5 * 2.0 * 0.09 * (0.36 - 0.96 + 0.4) ** 2
        + 2.0 * 9.81 * 0.3, rel=1e-12)


def test_celt_scene_one_way_bias_and_reports():
    """Scene ``celt``: with damping only one direction reverses (Kane & Levinson 1982; Garcia & Hubbard 1988)."""
    res = ke.scene("celt")()
    assert set(res.scene.reports) <= set(res.numbers)
    verdicts = {text: v for text, v, _ in res.claims}
    assert all(v == "supports" for v in verdicts.values()), res.summary()
    assert res.numbers["reversal_episodes_Omega-5_sigma0.0001"] == []
    assert len(res.numbers["reversal_episodes_Omega+5_sigma0.0001"]) == 1


def test_celt_schoemer_scene_against_independent_integration():
    """Scene ``celt_schoemer``: the reversal time and the spin at the end against the Newton--Euler reference."""
    res = ke.scene("celt_schoemer")()
    run = res.scene.run
    m = run.load()
    y0 = m.check_state(dict(run.y0))
    p = m.check_params(dict(run.params))
    sol = ref.integrate(y0, run.t_span, p, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(res.numbers["crossings"], sol.t_events[0], rtol=1e-6)
    end = sol.y[:, -1]
    assert res.numbers["spin_end"] == pytest.approx(end[:3] @ end[3:6], rel=1e-6)
    assert res.numbers["energy_balance"] < 1e-9


@pytest.mark.slow
def test_euler_angle_lagrangian_through_the_engine_gives_the_same_accelerations():
    """The same body handed to the generic engine in Euler angles (Lagrange multipliers, the DAE
    solved at 30 digits) gives the body-frame angular accelerations of the front end's closed form."""
    import dataclasses

    from derivation import engine

    body = dataclasses.replace(celt(), sigma=None)
    spec = rigid.euler_angle_spec(body)
    system = rigid.derive(body)
    _, n, B = rigid.euler_angle_maps()
    R = sp.Rational
    vals = {rigid.x: R(1, 10), rigid.y: R(-1, 5), rigid.psi: R(7, 10), rigid.a1: R(3, 10), rigid.a2: R(-2, 5),
            rigid.psi_dot: R(13, 10), rigid.a1_dot: R(-7, 10), rigid.a2_dot: R(21, 10)}
    pv = dict(zip(body.params, [R(1, 5), R(3, 100), R(1, 50), R(1, 100), 1, R(981, 100), R(2, 10**4),
                                R(16, 10**4), R(17, 10**4), R(2, 10**5), R(3, 10**6), R(-4, 10**6), 0]))
    acc, _ = engine.unreduced_accelerations(spec, {**vals, **pv})
    q = sp.Matrix([rigid.psi, rigid.a1, rigid.a2])
    qd = sp.Matrix([rigid.psi_dot, rigid.a1_dot, rigid.a2_dot])
    B_dot = sum((B.diff(c) * v for c, v in zip(q, qd)), sp.zeros(3, 3))
    omega_dot = (B * sp.Matrix(acc) + B_dot.subs(vals) * qd.subs(vals)).subs(vals)
    pt = {**dict(zip(rigid.N_VEC, n.subs(vals))), **dict(zip(rigid.OMEGA, (B * qd).subs(vals))), **pv}
    mine = system.explicit.xreplace(pt)
    err = max(abs(sp.N(a - b, 30)) for a, b in zip(omega_dot, mine))
    assert err < 1e-20 * max(abs(sp.N(b, 30)) for b in mine)


def test_docs_snippets_run(tmp_path, monkeypatch):
    """Every Python block of docs/rigid-bodies.md runs as pasted."""
    import re
    from pathlib import Path

    text = (Path(__file__).resolve().parent.parent / "docs" / "rigid-bodies.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 2
    monkeypatch.chdir(tmp_path)
    for code in blocks:
        exec(compile(code, "docs/rigid-bodies.md", "exec"), {})
