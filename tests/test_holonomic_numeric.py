"""Holonomic constraints held on a numeric-elimination model (issue 22, items 2-3).

The Cartesian pendulum of tests/test_holonomic.py, ``L = (x_dot^2 + y_dot^2)/2 - g y`` with the rod
``f = x^2 + y^2 - l^2 = 0`` and ``y`` kept in the state, forced to ``elimination="numeric"``: the compiled
right-hand side solves the dependent velocity from the constraint at every call (derivation/kkt_emit.py), and the
same solve gives ``y`` the rate under which ``df/dt = -holonomic_rate f``.  Checked against closed forms:
``f(t) = f0 exp(-rate t)`` from a start off the rod, the exact period ``T = 4 sqrt(l/g) K(sin^2(theta0/2))``
(Goldstein, *Classical Mechanics*, 3rd ed., section 3.2; ``scipy.special.ellipk`` takes m = k^2), and the
closed-form elimination of the same model (an independent derivation path: symbolic inverse of the constraint
block, engine.held_rates) at random states off the rod.
"""
import dataclasses

import numpy as np
import pytest
import sympy as sp
from scipy.special import ellipk

import knifeedge as ke
from knifeedge.derive import ModelSpec, emit
from knifeedge.derive.cli import derive_specs

g, l = sp.symbols("g l", positive=True)
x, y, x_dot, y_dot = sp.symbols("x y x_dot y_dot", real=True)
GV, LV = 9.81, 0.7
RATE = 2 * np.sqrt(GV / LV)


def pendulum(name: str, elimination: str) -> ModelSpec:
    return ModelSpec(name=name, coordinates=(x, y), velocities=(x_dot, y_dot),
                     lagrangian=(x_dot**2 + y_dot**2) / 2 - g * y, constraints=(), holonomic=(x**2 + y**2 - l**2,),
                     holonomic_labels=("rod",), dependent=(y,), params=(g, l), reversal_events=(x,),
                     holonomic_rate=2 * sp.sqrt(g / l), elimination=elimination)


@pytest.fixture(scope="module")
def pendulums(tmp_path_factory):
    out = tmp_path_factory.mktemp("holonomic_numeric")
    specs = [pendulum("rod_symbolic", "symbolic"), pendulum("rod_numeric", "numeric")]
    emit.write_all(out, derive_specs(specs), registry=False)
    return ke.load("rod_symbolic", path=out), ke.load("rod_numeric", path=out)


def test_the_header_says_the_rate(pendulums):
    _, numeric = pendulums
    assert numeric.module.ELIMINATION == "numeric"
    assert numeric.module.HOLONOMIC_RATE == "2*sqrt(g)/sqrt(l)"


def test_an_error_in_the_rod_decays_at_the_declared_rate(pendulums):
    """Started off the rod, f(t) = f0 exp(-rate t): the differentiated constraint alone would keep f = f0."""
    _, m = pendulums
    y0 = np.array([0.3, -np.sqrt(LV**2 - 0.09) * 1.001, 0.4])
    r = ke.simulate(m, y0, (0.0, 1.5), m.params(g=GV, l=LV), rtol=1e-12, atol=1e-14)
    assert r.success
    f = r.holonomic_residual[0]
    assert f[0] == pytest.approx((0.09 + (LV**2 - 0.09) * 1.001**2) - LV**2, rel=1e-12)
    np.testing.assert_allclose(f, f[0] * np.exp(-RATE * r.t), rtol=1e-7, atol=1e-9 * f[0])


def test_the_numeric_pendulum_has_the_exact_period_over_many_periods(pendulums):
    _, m = pendulums
    theta0 = 1.2
    period = 4 * np.sqrt(LV / GV) * ellipk(np.sin(theta0 / 2) ** 2)
    y0 = {"x": LV * np.sin(theta0), "y": -LV * np.cos(theta0), "x_dot": 0.0}
    r = ke.simulate(m, y0, (0.0, 100 * period), m.params(g=GV, l=LV), rtol=1e-12, atol=1e-14)
    assert r.success and r.reversal_times.size == 200
    # the n-th crossing of x = 0 is at (2n - 1) T / 4 from the turning point: right to 1e-10 over 100 periods
    # (measured 1.4e-11, as the closed-form model: the integrator's phase error, growing linearly)
    n = np.arange(1, 201)
    np.testing.assert_allclose(r.reversal_times, (2 * n - 1) * period / 4, rtol=1e-10, atol=0)
    assert np.max(np.abs(r.holonomic_residual)) < 1e-9 * LV**2
    assert np.ptp(r.energy) < 1e-9 * GV * LV


def _off_the_rod(n: int):
    rng = np.random.default_rng(3)
    for _ in range(n):
        yield np.array([rng.uniform(-0.5, 0.5), rng.uniform(-0.9, -0.5), rng.uniform(-2, 2)])


def test_closed_form_and_numeric_elimination_agree_off_the_rod(pendulums):
    """At random states (off the rod: the held rate of y differs from the exact one) every function agrees.  The
    Jacobians are compared as their Python bodies (``py_func``, as tests/test_jacobian.py does: compiling the
    numeric one costs ~4 s of CPU); the compiled ones in the slow tier, below."""
    symbolic, numeric = pendulums
    p = numeric.params(g=GV, l=LV)
    for s in _off_the_rod(20):
        np.testing.assert_allclose(numeric.module.rhs(0.0, s, p), symbolic.module.rhs(0.0, s, p),
                                   rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(numeric.module.multipliers(s, p), symbolic.module.multipliers(s, p),
                                   rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(numeric.module.jacobian.py_func(s, p), symbolic.module.jacobian.py_func(s, p),
                                   rtol=1e-11, atol=1e-11)


@pytest.mark.slow  # compiles the numeric model's Jacobian (~4 s of CPU); its Python body: the check above
def test_compiled_jacobians_agree_off_the_rod(pendulums):
    symbolic, numeric = pendulums
    p = numeric.params(g=GV, l=LV)
    for s in _off_the_rod(20):
        np.testing.assert_allclose(numeric.jacobian(s, p), symbolic.jacobian(s, p), rtol=1e-11, atol=1e-11)
