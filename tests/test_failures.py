"""Where the integrators fail, and that they say so in the result.

Single-mode scene of the paper's Fig. 'numerical' (g = ell = L = D = 1,
theta(0) = 1e-3, phi_dot(0) = 0.1): small oscillations of angular frequency
sqrt(g/ell) = 1, so the step h is in units of 1/(2 pi) of the period.
"""
import numpy as np
import pytest

import knifeedge as ke
from knifeedge.integrators import Status

SINGLE = dict(g=1.0, ell=1.0, L=1.0, D=1.0)
Y0 = dict(theta=1e-3, theta_dot=0.0, phi_dot=0.1)


@pytest.fixture(scope="module")
def single():
    m = ke.load("single_mode", "full")
    return m, m.params(**SINGLE)


def _check_failed(r, outcome):
    assert not r.success
    assert r.outcome is outcome and r.status == outcome.code and r.message.startswith(outcome.value)
    assert np.all(np.isfinite(r.y)), "a failed run must not return non-finite states"
    assert r.t[-1] < 300.0


def test_rk4_beyond_its_stability_interval_blows_up_and_says_so(single):
    """RK4's stability region meets the imaginary axis at |h w| = 2.83; at h w = 3.5 the
    oscillation grows without bound: reported as a non-finite state, arrays cut at the last good step."""
    m, p = single
    r = ke.simulate(m, Y0, (0.0, 300.0), p, method="RK4", h=3.5)
    _check_failed(r, Status.NON_FINITE)


def test_rk4_inside_its_stability_interval_can_be_silently_wrong(single):
    """The dangerous failure: at h w = 2.5 RK4 is stable and finishes, but misses the reversal that
    happens at t = 106.36 (the oscillation is damped numerically).  A fixed-step method cannot detect
    this itself; the benchmark's stability map charts where it happens."""
    m, p = single
    r = ke.simulate(m, Y0, (0.0, 300.0), p, method="RK4", h=2.5)
    assert r.success and r.reversal_times.size == 0
    assert ke.simulate(m, Y0, (0.0, 300.0), p, method="RK4", h=0.1).reversal_times.size == 1


def test_max_steps_reached_is_reported(single):
    m, p = single
    r = ke.simulate(m, Y0, (0.0, 300.0), p, method="DOP853", max_steps=10)
    _check_failed(r, Status.MAX_STEPS)
    assert r.nsteps == 10 and r.t.size == 11
    r = ke.simulate(m, Y0, (0.0, 300.0), p, method="RK4", h=0.1, max_steps=100)
    _check_failed(r, Status.MAX_STEPS)
    assert r.t[-1] == pytest.approx(10.0)


@pytest.mark.parametrize("method", ["DOP853", pytest.param("DP54", marks=pytest.mark.slow)])  # DP54: slow tier
@pytest.mark.xdist_group("dp54_tsit5")  # one worker compiles the DP54 and Tsit5 integrators for all such tests
def test_step_size_underflow_is_reported(single, method):
    """An overflowing state makes every error estimate non-finite: the step shrinks to the
    resolution of t and the run stops with that failure instead of returning garbage."""
    m, p = single
    r = ke.simulate(m, dict(theta=1e-3, theta_dot=1e200, phi_dot=0.1), (0.0, 300.0), p, method=method)
    _check_failed(r, Status.STEP_SIZE_UNDERFLOW)


@pytest.mark.xdist_group("gauss6_two_mode")  # one worker compiles gauss6 on the full two-mode model for these checks
def test_implicit_stage_solver_failure_is_reported():
    """The Gauss stage equations are solved by fixed-point iteration, which converges only while h times
    the Lipschitz constant times the spectral radius of the method's A is below 1; at h = 5 (the two-mode model
    with g = ell = 1: rocking frequencies near 1) gauss6 diverges, and the run says so (gauss6 on this model: the
    kernel the energy and order checks compile; the Gauss methods share the iteration)."""
    m = ke.load("two_mode", "full")
    p = m.params(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=np.pi / 4)
    y0 = dict(theta1=1e-3, theta2=1e-3, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1)
    r = ke.simulate(m, y0, (0.0, 300.0), p, method="gauss6", h=5.0)
    _check_failed(r, Status.IMPLICIT_NOT_CONVERGED)


def test_tolerance_below_round_off_is_refused(single):
    """Below 100 machine epsilons the error estimate is round-off: refused before any work."""
    m, p = single
    with pytest.raises(ValueError, match="`rtol` must be at least"):
        ke.simulate(m, Y0, (0.0, 300.0), p, method="DOP853", rtol=1e-15)


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # SciPy's own overflow warnings, provoked on purpose
def test_scipy_non_finite_state_is_cut_and_reported(single):
    m, p = single
    r = ke.simulate(m, dict(theta=1e100, theta_dot=1e100, phi_dot=1e100), (0.0, 10.0), p, method="scipy:DOP853")
    assert not r.success and np.all(np.isfinite(r.y))
