"""Holonomic constraints and dependent coordinates kept in the state (issue 22, item 2).

A pendulum written in Cartesian coordinates, ``L = (x_dot^2 + y_dot^2)/2 - g y``
with the rod ``x^2 + y^2 - l^2 = 0`` and ``y`` dependent (not a symmetry: it
stays in the state).  Its period from the amplitude ``theta0`` is exactly
``T = 4 sqrt(l/g) K(sin^2(theta0/2))`` (Goldstein, *Classical Mechanics*,
3rd ed., section 3.2 exercise; K the complete elliptic integral of the first
kind, ``scipy.special.ellipk`` with the parameter m = k^2).  The run integrates
the differentiated constraint, with the rate of ``y`` corrected so that the
rod's value ``f`` obeys ``df/dt = -holonomic_rate f`` (it decays instead of
drifting); its value is reported along the run.
"""
import numpy as np
import pytest
import sympy as sp
from scipy.special import ellipk

import knifeedge as ke
from knifeedge.derive import ModelSpec, ModelSpecError, emit
from knifeedge.derive.cli import derive_specs

g, l = sp.symbols("g l", positive=True)
x, y, x_dot, y_dot = sp.symbols("x y x_dot y_dot", real=True)


def pendulum(**overrides) -> ModelSpec:
    kw = dict(name="cartesian_pendulum", coordinates=(x, y), velocities=(x_dot, y_dot),
              lagrangian=(x_dot**2 + y_dot**2) / 2 - g * y, constraints=(), holonomic=(x**2 + y**2 - l**2,),
              holonomic_labels=("rod",), dependent=(y,), params=(g, l), reversal_events=(x,))
    kw.update(overrides)
    return ModelSpec(**kw)


@pytest.fixture(scope="module")
def model(tmp_path_factory):
    out = tmp_path_factory.mktemp("holonomic")
    emit.write_all(out, derive_specs([pendulum()]), registry=False)
    return ke.load("cartesian_pendulum", path=out)


# below the horizontal: y = 0, where the rod does not determine y_dot (the block d f/d y = 2 y vanishes), is
# never reached (a swing above it passes there: choose the dependent coordinate where its block stays invertible)
@pytest.mark.parametrize("theta0", [0.3, 1.0, 1.5])
def test_cartesian_pendulum_has_the_exact_period(model, theta0):
    assert model.state_names == ("x", "y", "x_dot") and model.multiplier_names == ("rod",)
    gv, lv = 9.81, 0.7
    y0 = {"x": lv * np.sin(theta0), "y": -lv * np.cos(theta0), "x_dot": 0.0}
    r = ke.simulate(model, y0, (0.0, 20.0), model.params(g=gv, l=lv), rtol=1e-11, atol=1e-13)
    assert r.success
    period = 4 * np.sqrt(lv / gv) * ellipk(np.sin(theta0 / 2) ** 2)
    half_periods = np.diff(r.reversal_times)  # x crosses zero twice a period
    assert len(half_periods) >= 5
    assert np.max(np.abs(2 * half_periods / period - 1)) < 1e-9
    assert np.max(np.abs(r.holonomic_residual)) < 1e-9 * lv**2
    assert np.ptp(r.energy) < 1e-9 * gv * lv


def test_the_rod_is_held_along_a_long_run(model):
    """200 periods at rtol 1e-8: the differentiated constraint alone drifts to |f| ~ 4e-7 l^2 (benchmarks/
    holonomic_drift.py, ``holonomic_rate`` 0); held, |f| stays at the integrator's local error."""
    gv, lv, theta0 = 9.81, 0.7, 1.0
    period = 4 * np.sqrt(lv / gv) * ellipk(np.sin(theta0 / 2) ** 2)
    y0 = {"x": lv * np.sin(theta0), "y": -lv * np.cos(theta0), "x_dot": 0.0}
    r = ke.simulate(model, y0, (0.0, 200 * period), model.params(g=gv, l=lv), rtol=1e-8, atol=1e-10)
    assert r.success and r.reversal_times.size == 400
    assert np.max(np.abs(r.holonomic_residual)) < 2e-8 * lv**2


def test_an_error_in_the_rod_decays_at_the_declared_rate(tmp_path):
    """Started off the rod (f0 = (1.001^2 - 1) l^2), f(t) = f0 exp(-rate t) exactly: df/dt = -rate f."""
    emit.write_all(tmp_path, derive_specs([pendulum(holonomic_rate=2 * sp.sqrt(g / l))]), registry=False)
    m = ke.load("cartesian_pendulum", path=tmp_path)
    gv, lv = 9.81, 0.7
    rate = 2 * np.sqrt(gv / lv)
    y0 = np.array([0.3, -np.sqrt(lv**2 - 0.09) * 1.001, 0.4])
    r = ke.simulate(m, y0, (0.0, 1.5), m.params(g=gv, l=lv), rtol=1e-12, atol=1e-14)
    f = r.holonomic_residual[0]
    assert f[0] == pytest.approx((0.09 + (lv**2 - 0.09) * 1.001**2) - lv**2, rel=1e-12)
    np.testing.assert_allclose(f, f[0] * np.exp(-rate * r.t), rtol=1e-7, atol=1e-9 * f[0])


def test_the_rod_tension_is_the_multiplier(model):
    """At the bottom (y = -l) with speed u the rod pulls up with g + u^2/l per unit mass: lambda grad f = (0, -2 l lambda)."""
    gv, lv, u = 9.81, 0.7, 1.3
    lam = model.multipliers([0.0, -lv, u], model.params(g=gv, l=lv))[0]
    assert -2 * lv * lam == pytest.approx(gv + u * u / lv, rel=1e-14)


def test_holonomic_constraints_that_cannot_be_kept_are_refused():
    with pytest.raises(ModelSpecError, match="holds velocities: write it in `constraints`"):
        pendulum(holonomic=(x * x_dot + y * y_dot,))
    with pytest.raises(ModelSpecError, match="which the closed state does not keep; remove them from `cyclic`"):
        pendulum(cyclic={x: 0})
    with pytest.raises(ModelSpecError, match="one coordinate per constraint and holonomic constraint"):
        pendulum(dependent=())
    for bad in (-1, sp.Symbol("k"), "fast", x):
        with pytest.raises(ModelSpecError, match="`holonomic_rate` must be a number >= 0 or an expression of the "
                                                 "parameters .* write it with the symbols of `params`"):
            pendulum(holonomic_rate=bad)
