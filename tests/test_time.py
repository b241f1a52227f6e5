"""The time in a model: ``knifeedge.derive.t`` (issue 22, item 1).

The Chaplygin sleigh driven by the torque ``tau0 sin t``
(``tests/models/driven_sleigh.py``; Bloch, *Nonholonomic Mechanics and
Control*, section 1.7) has, per unit mass, with ``v`` the speed of the
contact point along the axis and ``omega`` the turning rate, the equations

    dv/dt = a omega^2,    (k^2 + a^2) d(omega)/dt = -a v omega + tau0 sin t,

written here by hand and integrated with SciPy.  Every method must see the
integrator's true time: the runs start at ``t0 = 1.3``, so a method that
passed the time since the start, or none, would be wrong.
"""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import knifeedge as ke
from knifeedge import cli
from pathlib import Path

HERE = Path(__file__).resolve().parent
A, K, TAU0 = 0.5, 0.8, 0.4
T0, T1 = 1.3, 9.0
Y0 = np.array([0.1, 0.0])


def by_hand(t, z):
    v, w = z
    return [A * w * w, (-A * v * w + TAU0 * math.sin(t)) / (K * K + A * A)]


@pytest.fixture(scope="module")
def model(tmp_path_factory):
    out = tmp_path_factory.mktemp("driven")
    assert cli.main(["derive", str(HERE / "models" / "driven_sleigh.py"), "--out", str(out)]) == 0
    return ke.load("driven_sleigh", path=out)


@pytest.fixture(scope="module")
def reference():
    t = np.linspace(T0, T1, 41)
    sol = solve_ivp(by_hand, (T0, T1), Y0, method="DOP853", rtol=1e-13, atol=1e-15, t_eval=t)
    return t, sol.y


METHODS = [("DOP853", {}), ("scipy:DOP853", {}),
           *(pytest.param(m, kw, marks=pytest.mark.slow) for m, kw in [
               ("RK4", {"h": 2e-3}), ("DP54", {}), ("Tsit5", {}), ("gauss4", {"h": 5e-3}), ("gauss6", {"h": 1e-2}),
               ("implicit_midpoint", {"h": 1e-3}), ("scipy:RK45", {}), ("scipy:LSODA", {}), ("scipy:Radau", {})])]


@pytest.mark.parametrize("method, kw", METHODS)
def test_every_method_passes_the_true_time(model, reference, method, kw):
    t, want = reference
    r = ke.simulate(model, Y0, (T0, T1), model.params(a=A, k=K, tau0=TAU0), method=method, t_eval=t,
                    rtol=1e-11, atol=1e-13, **kw)
    assert r.success, r.message
    assert np.max(np.abs(r.y - want)) < (2e-8 if method != "implicit_midpoint" else 2e-5)
    assert np.max(np.abs(want[1])) > 0.3  # the torque turned the sleigh


def test_the_jacobians_read_the_time(model):
    """d rhs / d (v, omega) and d rhs / d tau0 of the equations written by hand above, at several times."""
    p = model.params(a=A, k=K, tau0=TAU0)
    v, w = Y0
    with pytest.raises(ValueError, match="pass `t`"):
        model.jacobian(Y0, p)
    for t in (0.0, 0.7, 2.0):
        want = np.array([[0.0, 2 * A * w], [-A * w / (K * K + A * A), -A * v / (K * K + A * A)]])
        assert np.allclose(model.jacobian(Y0, p, t=t), want, rtol=1e-14, atol=1e-16)
        d_tau0 = model.jacobian_p(Y0, p, t=t)[:, model.param_names.index("tau0")]
        assert np.allclose(d_tau0, [0.0, math.sin(t) / (K * K + A * A)], rtol=1e-14, atol=1e-16)


def test_generated_rhs_reads_the_time(model):
    p = model.params(a=A, k=K, tau0=TAU0)
    for t in (0.0, 0.7, 2.0):
        assert np.allclose(model.rhs(t, Y0, p), by_hand(t, Y0), rtol=1e-15, atol=1e-17)


def test_energy_changes_by_the_work_of_the_torque(model):
    """``E(t) + integral power_dissipated = E(t0)``; here ``power_dissipated = -omega tau0 sin t`` (the torque's work)."""
    p = model.params(a=A, k=K, tau0=TAU0)
    assert model.time_dependent and model.has_dissipation and not model.has_power_input

    def f(t, z):
        return np.append(model.rhs(t, z[:2], p), model.power_dissipated(z[:2], p, t))

    sol = solve_ivp(f, (T0, T1), np.append(Y0, 0.0), method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True)
    t = np.linspace(T0, T1, 101)
    z = sol.sol(t)
    e = model.energy(z[:2], p, t)
    assert np.ptp(e) > 0.05  # not conserved
    assert np.max(np.abs(e + z[2] - e[0])) < 1e-9 * np.max(np.abs(e))
    with pytest.raises(ValueError, match="depends on the time: pass `t`"):
        model.energy(Y0, p)
    r = ke.simulate(model, Y0, (T0, T1), p, t_eval=t, rtol=1e-11, atol=1e-13)
    assert np.allclose(r.energy, e, rtol=1e-8)


@pytest.fixture(scope="module")
def turned_sleigh(tmp_path_factory):
    """The sleigh's heading turned at the prescribed rate ``Omega(t) = w0 sin t`` (the affine constraint
    ``phi_dot - w0 sin t = 0``)."""
    import sympy as sp

    from knifeedge.derive import ModelSpec, emit, t
    from knifeedge.derive.cli import derive_specs

    a, k, w0 = sp.symbols("a k w0", positive=True)
    x, y, phi, x_dot, y_dot, phi_dot, v = sp.symbols("x y phi x_dot y_dot phi_dot v", real=True)
    axis, across = sp.Matrix([sp.cos(phi), sp.sin(phi)]), sp.Matrix([-sp.sin(phi), sp.cos(phi)])
    contact = sp.Matrix([x_dot, y_dot])
    centre = contact + a * phi_dot * across
    spec = ModelSpec(
        name="turned_sleigh", coordinates=(x, y, phi), velocities=(x_dot, y_dot, phi_dot),
        lagrangian=sp.Rational(1, 2) * (centre.dot(centre) + k**2 * phi_dot**2),
        constraints=(contact.dot(across), phi_dot - w0 * sp.sin(t)), constraint_labels=("knife_edge", "turn"),
        dependent=(y, phi), params=(a, k, w0), cyclic={x: 0, y: 0, phi: 0}, pose=(phi, x, y),
        quasi_velocities=((v, x_dot, contact.dot(axis)),))
    out = tmp_path_factory.mktemp("turned")
    emit.write_all(out, derive_specs([spec]), registry=False)
    return ke.load("turned_sleigh", path=out)


def _turned_speed(tt, w):
    """``v(t) = v(t0) + a w0^2 [t/2 - sin(2t)/4]_{t0}^{t}``, from ``dv/dt = a Omega^2`` with ``v(t0) = 0.1``."""
    prim = lambda s: s / 2 - math.sin(2 * s) / 4  # noqa: E731
    return 0.1 + A * w * w * (np.array([prim(s) for s in tt]) - prim(T0))


# the RK4 case compiles a fixed-step kernel for this model alone: slow tier
@pytest.mark.parametrize("method, kw", [("DOP853", {}), ("scipy:DOP853", {}),
                                        pytest.param("RK4", {"h": 2e-3}, marks=pytest.mark.slow)])
def test_prescribed_turning_rate_is_a_rheonomic_constraint(turned_sleigh, method, kw):
    """The sleigh's heading turned at the prescribed rate ``Omega(t) = w0 sin t``.  From the equations above with
    ``omega = Omega(t)``: ``dv/dt = a Omega^2``, so ``v(t) = v(t0) + a w0^2 [t/2 - sin(2t)/4]_{t0}^{t}``."""
    m = turned_sleigh
    assert m.state_names == ("v",) and m.time_dependent and m.has_power_input
    w = 1.1
    p = m.params(a=A, k=K, w0=w)
    tt = np.linspace(T0, T1, 21)
    v_exact = _turned_speed(tt, w)
    r = ke.simulate(m, [0.1], (T0, T1), p, method=method, t_eval=tt, rtol=1e-11, atol=1e-13, **kw)
    assert np.max(np.abs(r.y[0] - v_exact)) < 1e-9 * np.max(np.abs(v_exact)), method


def test_prescribed_turning_rate_is_held_by_a_torque_whose_power_is_the_energys_rate(turned_sleigh):
    """The torque that enforces ``phi_dot = w0 sin t`` is the multiplier ``(k^2 + a^2) Omega' + a v Omega``, and
    its power ``Omega * torque`` is the energy's rate of change."""
    m = turned_sleigh
    w = 1.1
    p = m.params(a=A, k=K, w0=w)
    tt = np.linspace(T0, T1, 21)
    v_exact = _turned_speed(tt, w)
    omega, omega_dot = w * np.sin(tt), w * np.cos(tt)
    torque = (K * K + A * A) * omega_dot + A * v_exact * omega
    assert np.allclose(m.multipliers(v_exact[None, :], p, tt)[1], torque, rtol=1e-12, atol=1e-14)
    assert np.allclose(m.power_input(v_exact[None, :], p, tt), omega * torque, rtol=1e-12, atol=1e-14)
    energy = 0.5 * v_exact**2 + 0.5 * (K * K + A * A) * omega**2
    assert np.allclose(m.energy(v_exact[None, :], p, tt), energy, rtol=1e-13)


def test_a_time_symbol_of_ones_own_is_refused_with_the_fix():
    """Before: a user's ``t`` declared as a parameter was written ``t = p[3]`` over the integrator's time."""
    import sympy as sp

    from knifeedge.derive import ModelSpec, ModelSpecError

    x, x_dot, t_own = sp.symbols("x x_dot t", real=True)
    with pytest.raises(ModelSpecError, match=r"undeclared symbols \['t'\].*the time is `knifeedge.derive.t`"):
        ModelSpec(name="clock", coordinates=(x,), velocities=(x_dot,), lagrangian=x_dot**2 / 2,
                  constraints=(), dependent=(), params=(), forces=(sp.sin(t_own),))
