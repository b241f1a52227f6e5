"""Lyapunov exponents (``knifeedge.lyapunov``, Benettin/QR on the emitted variational equations).

Checks with independent references:
- the sum of the exponents is the time average of the divergence of the vector field on the physical phase space
  (Liouville's formula: the volume of the tangent parallelepiped grows as exp of the integral of the trace),
  the trace taken here from ``m.jacobian`` on a separate DOP853 run;
- the exponents do not depend on how often the tangent vectors are re-orthonormalized (R of a product is the
  product of the R's, so the sums of log |R_jj| agree to round-off);
- at an asymptotically stable steady spin (the undamped Schömer celt, spinning in its stable direction: a
  non-holonomic system with conserved energy whose phase volume shrinks) the exponents are the real parts of
  the linearization's physical eigenvalues, each twice (a complex pair), and 0 along the family of spins.
"""
import importlib

import numpy as np
import pytest

import knifeedge as ke

st = importlib.import_module("knifeedge.stability")

#: one worker compiles the Benettin loop (its first compile, ~8 s of CPU cold) for every check of the default tier
pytestmark = pytest.mark.xdist_group("lyapunov")


def test_sum_of_exponents_is_the_time_averaged_divergence():
    m = ke.load("two_mode")
    p = m.params(m.default_params)
    y0 = m.state(theta1=0.02, theta2=0.01, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.3)
    res = ke.lyapunov(m, y0, p, 60.0, h=0.005, tau=0.05)
    t = np.linspace(0.0, 60.0, 24001)
    run = ke.simulate(m, y0, (0.0, 60.0), p, rtol=1e-11, atol=1e-13, t_eval=t)
    trace = np.array([np.trace(m.jacobian(run.y[:, i], p)) for i in range(t.size)])
    average = float(np.sum(0.5 * (trace[1:] + trace[:-1]) * np.diff(t))) / 60.0
    assert res.exponents.shape == (5,) and np.all(np.diff(res.exponents) <= 0)
    assert abs(res.exponents.sum() - average) <= 1e-7 * max(1.0, abs(average))
    np.testing.assert_allclose(res.y, run.y[:, -1], rtol=0, atol=1e-8)  # the same trajectory


def test_exponents_do_not_depend_on_the_renormalization_interval():
    m = ke.load("two_mode")
    p = m.params(m.default_params)
    y0 = m.state(theta1=0.02, theta2=0.01, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.3)
    a = ke.lyapunov(m, y0, p, 40.0, h=0.01, tau=0.1)
    b = ke.lyapunov(m, y0, p, 40.0, h=0.01, tau=0.5)
    assert a.h == b.h
    np.testing.assert_allclose(a.exponents, b.exponents, rtol=0, atol=1e-10)
    assert a.history.shape == (400, 5) and b.history.shape == (80, 5)


@pytest.mark.slow  # compiles the step-controlled loop (~7 s of CPU cold); its refusals: test_bad_arguments_are_named
def test_step_control_gives_the_fixed_steps_exponents():
    """Dormand-Prince 5(4) with the state's error controlled (``rtol``) and RK4 with a fine fixed step are two
    discretizations of the same variational equations: their exponents agree to the integration error, and the
    sum is the time-averaged divergence (Liouville's formula, as above)."""
    m = ke.load("two_mode")
    p = m.params(m.default_params)
    y0 = m.state(theta1=0.02, theta2=0.01, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.3)
    fixed = ke.lyapunov(m, y0, p, 40.0, h=0.005, tau=0.5)
    adaptive = ke.lyapunov(m, y0, p, 40.0, tau=0.5, rtol=1e-11)
    assert adaptive.method.startswith("DP54") and 0 < adaptive.steps < fixed.steps and adaptive.tau == 0.5
    np.testing.assert_allclose(adaptive.exponents, fixed.exponents, rtol=0, atol=1e-8)
    np.testing.assert_allclose(adaptive.y, fixed.y, rtol=0, atol=1e-9)
    with pytest.raises(ValueError, match="`atol`"):
        ke.lyapunov(m, y0, p, 1.0, h=0.01, atol=1e-9)
    with pytest.raises(ValueError, match="`rtol`"):
        ke.lyapunov(m, y0, p, 1.0, rtol=-1.0)
    with pytest.raises(RuntimeError, match="`max_steps`"):
        ke.lyapunov(m, y0, p, 40.0, tau=0.5, rtol=1e-11, max_steps=10)


def test_a_looser_tangent_tolerance_takes_fewer_steps_for_nearly_the_same_exponents():
    """``tangent_rtol`` weighs the tangent vectors' errors apart from the state's: looser, fewer steps, and the
    exponents move by about the looser tolerance (not by the exponents' size, as controlling the state alone did);
    the re-orthonormalizations fall at the ends of the steps at or past each multiple of ``tau``, the last at the
    end of the span."""
    m = ke.load("two_mode")
    p = m.params(m.default_params)
    y0 = m.state(theta1=0.02, theta2=0.01, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.3)
    tight = ke.lyapunov(m, y0, p, 40.0, tau=0.5, rtol=1e-10)
    loose = ke.lyapunov(m, y0, p, 40.0, tau=0.5, rtol=1e-10, tangent_rtol=1e-6)
    assert loose.steps < tight.steps
    np.testing.assert_allclose(loose.exponents, tight.exponents, rtol=0, atol=1e-5)
    assert np.abs(loose.exponents - tight.exponents).max() > 1e-12  # the tangents' steps did change
    t = tight.history_t
    assert t[-1] == 40.0 and np.all(np.diff(t) > 0) and len(t) <= 80
    assert np.all(np.floor(t[:-1] / 0.5 + 1e-9) < np.floor(t[1:] / 0.5 + 1e-9))  # one per multiple of tau passed
    with pytest.raises(ValueError, match="`tangent_rtol`"):
        ke.lyapunov(m, y0, p, 1.0, rtol=1e-8, tangent_rtol=0.0)
    with pytest.raises(ValueError, match="`tangent_rtol` need `rtol`"):
        ke.lyapunov(m, y0, p, 1.0, h=0.01, tangent_rtol=1e-6)


def test_one_compiled_loop_serves_every_model():
    """The Benettin loop is compiled for the first-class function types of ``jvp_into``/``invariant_gradients``, not
    for one module's functions: a second model adds no compilation, and numba can keep the loop in its disk cache (a
    closure per module, the earlier design, compiled again in every process)."""
    ly = importlib.import_module("knifeedge.lyapunov")
    for name in ("single_mode", "two_mode"):
        m = ke.load(name, "reduced")
        p = m.params(m.default_params)
        ke.lyapunov(m, m.state(m.module.DEFAULT_STATE), p, 1.0, h=0.01, tau=0.1)
    assert ly._benettin.signatures == [ly._SIGNATURE]
    assert type(ly._benettin._cache).__name__ != "NullCache"


def test_bad_arguments_are_named():
    m = ke.load("single_mode")
    p = m.params(m.default_params)
    y0 = m.state(theta=0.01, theta_dot=0.0, phi_dot=0.1)
    with pytest.raises(ValueError, match="`k`"):
        ke.lyapunov(m, y0, p, 1.0, k=4)
    with pytest.raises(ValueError, match="`tau`"):
        ke.lyapunov(m, y0, p, 1.0, h=0.1, tau=0.01)
    with pytest.raises(ValueError, match="`t_end`"):
        ke.lyapunov(m, y0, p, -1.0)
    with pytest.raises(ValueError, match="`atol`"):  # the step-controlled loop's arguments, before it compiles
        ke.lyapunov(m, y0, p, 1.0, h=0.01, atol=1e-9)
    with pytest.raises(ValueError, match="`rtol`"):
        ke.lyapunov(m, y0, p, 1.0, rtol=-1.0)


@pytest.mark.slow
def test_at_an_asymptotically_stable_steady_spin_the_exponents_are_the_eigenvalues_real_parts():
    m = ke.load("celt")
    p = m.preset("schoemer", sigma=0.0)
    y0 = st.steady_state(m, p, "steady_spin", 5.0)
    lin = ke.linearize(m, y0, p)
    expected = np.sort(np.concatenate([lin.physical_eigenvalues.real, [0.0]]))[::-1]
    assert expected[1] < 0  # asymptotically stable in the physical directions
    res = ke.lyapunov(m, y0, p, 4000.0, tau=1.0)
    # the exponents approach their limits like log(transient)/T
    np.testing.assert_allclose(res.exponents, expected, rtol=0, atol=2e-3)


@pytest.mark.slow
def test_on_an_integrable_body_the_exponents_fall_like_log_t_over_t():
    """The rolling disk is integrable (Chaplygin; Appell and Korteweg): near stable upright rolling its motion is
    quasi-periodic, every exponent is 0, and the finite-time estimates fall like log(T)/T."""
    m = ke.load("rolling_disk")
    p = m.params(g=9.81, r=0.1)
    y0 = m.state(q2=0.05, q1_dot=0.0, q2_dot=0.0, q3_dot=8.0)  # above the critical 5.72 rad/s
    largest = {}
    for t_end in (1e3, 1e4):
        res = ke.lyapunov(m, y0, p, t_end)
        largest[t_end] = float(np.abs(res.exponents).max())
        assert 0.3 < largest[t_end] * t_end / np.log(t_end) < 3.0
    expected = (np.log(1e4) / 1e4) / (np.log(1e3) / 1e3)  # 0.133
    assert largest[1e4] / largest[1e3] == pytest.approx(expected, rel=0.3)
