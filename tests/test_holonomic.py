"""Holonomic constraints and dependent coordinates kept in the state (issue 22, item 2).

A pendulum written in Cartesian coordinates, ``L = (x_dot^2 + y_dot^2)/2 - g y``
with the rod ``x^2 + y^2 - l^2 = 0`` and ``y`` dependent (not a symmetry: it
stays in the state).  Its period from the amplitude ``theta0`` is exactly
``T = 4 sqrt(l/g) K(sin^2(theta0/2))`` (Goldstein, *Classical Mechanics*,
3rd ed., section 3.2 exercise; K the complete elliptic integral of the first
kind, ``scipy.special.ellipk`` with the parameter m = k^2).  The run integrates
the differentiated constraint; the constraint's value is reported along it.
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
