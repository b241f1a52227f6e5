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
    """Step control (``rtol``: Dormand-Prince 5(4) for the state with Magnus tangents, the spectrum's default;
    DOP853 for the state and the tangents together, the largest exponent's) and RK4 with a fine fixed step are
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
    for kw in ({"k": 1}, {"tangents": "rk"}):
        both = ke.lyapunov(m, y0, p, 40.0, tau=0.5, rtol=1e-11, **kw)
        rk4 = ke.lyapunov(m, y0, p, 40.0, h=0.005, tau=0.5, **{key: v for key, v in kw.items() if key == "k"})
        assert both.method.startswith("DOP853") and 0 < both.steps < adaptive.steps and both.tau == 0.5
        np.testing.assert_allclose(both.exponents, rk4.exponents, rtol=0, atol=1e-8)
        np.testing.assert_allclose(both.y, rk4.y, rtol=0, atol=1e-9)
    with pytest.raises(RuntimeError, match="`max_steps`"):
        ke.lyapunov(m, y0, p, 40.0, k=1, tau=0.5, rtol=1e-11, max_steps=10)
    with pytest.raises(ValueError, match="`atol`"):
        ke.lyapunov(m, y0, p, 1.0, h=0.01, atol=1e-9)
    with pytest.raises(ValueError, match="`rtol`"):
        ke.lyapunov(m, y0, p, 1.0, rtol=-1.0)
    with pytest.raises(RuntimeError, match="`max_steps`"):
        ke.lyapunov(m, y0, p, 40.0, tau=0.5, rtol=1e-11, max_steps=10)


def _linear_flow(n):
    """``rhs_into``, ``jvp_into``, ``invariant_gradients`` of ``dy/dt = A y`` in the generated modules' calling
    convention, ``A`` (n x n) given as the parameters (row by row); no invariants."""
    from numba import njit

    @njit
    def rhs_into(t, s, p, ds):
        for i in range(n):
            ds[i] = 0.0
            for j in range(n):
                ds[i] += p[i * n + j] * s[j]

    @njit
    def jvp_into(s, p, V, ds, out):
        rhs_into(0.0, s, p, ds)
        for i in range(n):
            for c in range(V.shape[1]):
                out[i, c] = 0.0
                for j in range(n):
                    out[i, c] += p[i * n + j] * V[j, c]

    @njit
    def gradients(s, p):
        return np.zeros((0, n))

    return rhs_into, jvp_into, gradients


@pytest.mark.slow  # the step-controlled Magnus loop (~12 s of CPU cold); refusals: test_bad_arguments_are_named
def test_a_looser_tangent_tolerance_takes_fewer_steps_for_nearly_the_same_exponents():
    """``tangent_rtol`` weighs the tangent vectors' errors apart from the state's: looser, fewer tangent steps, and the
    exponents move by about the looser tolerance (not by the exponents' size, as controlling the state alone did);
    the re-orthonormalizations fall at the ends of the steps at or past each multiple of ``tau``, the last at the
    end of the span."""
    m = ke.load("two_mode")
    p = m.params(m.default_params)
    y0 = m.state(theta1=0.02, theta2=0.01, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.3)
    tight = ke.lyapunov(m, y0, p, 40.0, tau=0.5, rtol=1e-10)
    loose = ke.lyapunov(m, y0, p, 40.0, tau=0.5, rtol=1e-10, tangent_rtol=1e-6)
    assert loose.tangent_steps < tight.tangent_steps and loose.steps == tight.steps  # the state's steps are its own
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
    with pytest.raises(ValueError, match="`tangents`"):
        ke.lyapunov(m, y0, p, 1.0, rtol=1e-8, tangents="euler")


def test_a_module_without_the_product_of_one_vector_is_to_be_regenerated(monkeypatch):
    """The largest exponent's step-controlled loop calls ``jvp1_into``, which a module written by an older knifeedge
    lacks: it says so, before anything is compiled."""
    m = ke.load("single_mode")
    p = m.params(m.default_params)
    y0 = m.state(theta=0.01, theta_dot=0.0, phi_dot=0.1)
    monkeypatch.delattr(m.module, "jvp1_into")
    with pytest.raises(ValueError, match="jvp1_into.*regenerate it"):
        ke.lyapunov(m, y0, p, 1.0, k=1, h=0.01, rtol=1e-8)


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


@pytest.fixture(params=[pytest.param("compiled", marks=pytest.mark.slow), "python"])
def magnus(request, monkeypatch):
    """``knifeedge.magnus`` compiled (slow tier), or with every compiled function replaced by its Python body (the
    same code; the default tier then compiles none of it, ~6 s of CPU cold: the compiled functions also run in
    the slow tier's Magnus-loop checks)."""
    module = importlib.import_module("knifeedge.magnus")
    if request.param == "python":
        for name, f in list(vars(module).items()):
            if hasattr(f, "py_func"):
                monkeypatch.setattr(module, name, f.py_func)
    return module


def test_the_matrix_exponential_is_scipys(magnus):
    """``magnus.expm`` (scaling and squaring, [13/13] Pade, after balancing by powers of 2) against
    ``scipy.linalg.expm`` on matrices from the round-off scale to norms of hundreds, and on a badly scaled one like
    the celt's Jacobian (tilts against rates)."""
    from scipy.linalg import expm as scipy_expm

    rng = np.random.default_rng(3)
    out, W, d = np.empty((7, 7)), np.empty((6, 7, 7)), np.empty(7)
    scaling = np.diag(2.0 ** np.arange(-4, 3))
    for norm in (1e-6, 0.1, 1.0, 5.0, 20.0, 100.0):
        for A in (rng.standard_normal((7, 7)), scaling @ rng.standard_normal((7, 7)) @ np.linalg.inv(scaling)):
            A = A * norm / np.abs(A).sum(axis=0).max()
            expected = scipy_expm(A)
            magnus.expm(A, out, W)
            assert np.abs(out - expected).max() <= 1e-12 * np.abs(expected).max(), norm
            B = A.copy()
            magnus.balance(B, d)  # D^-1 A D, D = diag(d) exactly
            np.testing.assert_array_equal(B, A / d[:, None] * d[None, :])


def test_the_magnus_step_is_of_sixth_order_with_a_fifth_order_error_estimate(magnus):
    """One step of ``dV/dt = A(t) V`` (a smooth, non-commuting A(t)) against SciPy's DOP853 at rtol 1e-13: halving
    the step divides the error by about 2^7 (local error of a sixth-order method) and the estimate (Omega6 -
    Omega4) V by about 2^5 (the fourth-order method's local error), Blanes, Casas & Ros (2000)."""
    from scipy.integrate import solve_ivp

    rng = np.random.default_rng(0)
    n = 5
    A0, A1, A2 = (rng.standard_normal((n, n)) for _ in range(3))
    A = lambda t: A0 + t * A1 + np.sin(3 * t) * A2  # noqa: E731
    Q = np.ascontiguousarray(np.eye(n)[:, :3])
    errors, estimates = [], []
    for h in (0.1, 0.05, 0.025):
        J = np.array([A(c * h) for c in magnus.GAUSS_NODES])
        Q_new = np.empty_like(Q)
        estimates.append(magnus.magnus_step(J, h, Q, Q_new, np.empty((8, n, n)), np.empty((6, n, n)), np.empty(n),
                                            1.0))
        ref = solve_ivp(lambda t, v: (A(t) @ v.reshape(n, 3)).ravel(), (0, h), Q.ravel(), method="DOP853",
                        rtol=1e-13, atol=1e-15).y[:, -1].reshape(n, 3)
        errors.append(np.abs(Q_new - ref).max())
    assert 2 ** 6.5 < errors[0] / errors[1] < 2 ** 7.5 and 2 ** 6.5 < errors[1] / errors[2] < 2 ** 7.5, errors
    assert 2 ** 4.7 < estimates[0] / estimates[1] < 2 ** 5.3 and 2 ** 4.7 < estimates[1] / estimates[2] < 2 ** 5.3


@pytest.mark.slow  # the step-controlled Magnus loop (~12 s of CPU cold); the step itself: the two tests above
def test_magnus_tangents_of_a_constant_linear_flow_are_exact():
    """For ``dy/dt = A y`` the tangent flow is ``exp(A t)``: the loop's Magnus steps are exact whatever steps the
    state takes, so one re-orthonormalization after T gives log |R_jj| of the QR of ``expm(A T) Q0`` (numpy's QR,
    SciPy's expm), to round-off; and a tangent step spans as many state steps as the loop holds (J is constant: the
    error estimate is 0)."""
    from scipy.linalg import expm as scipy_expm

    ly = importlib.import_module("knifeedge.lyapunov")
    rhs_into, jvp_into, gradients = _linear_flow(4)
    A = np.array([[-0.1, 2.0, 0.0, 0.0], [-2.0, -0.1, 0.0, 0.0], [0.3, 0.0, 0.05, 1.0], [0.0, 0.2, -1.0, 0.05]])
    Q0 = np.ascontiguousarray(np.linalg.qr(np.arange(1.0, 17.0).reshape(4, 4) + np.eye(4))[0][:, :3])
    T = 20.0
    y, Q, sums, hist_t, hist, steps, rejected, tangent_steps, _ = ly._magnus_kernel()(
        rhs_into, jvp_into, gradients, importlib.import_module("knifeedge.magnus").magnus_step,
        np.array([1.0, 0.0, 0.5, 0.0]), Q0.copy(), A.ravel().copy(), T, 1, 1e-8,
        1e-10, 1e-8, 1e-3, 10**6)
    expected = np.log(np.abs(np.diag(np.linalg.qr(scipy_expm(A * T) @ Q0)[1])))
    np.testing.assert_allclose(sums, expected, rtol=1e-12, atol=1e-12)
    assert hist_t[-1] == T and steps > 100 and tangent_steps <= steps // ly._HELD + 5  # 5: the first steps' growth


@pytest.mark.slow  # the step-controlled Magnus loop, as above
def test_magnus_tangent_steps_at_a_saddle_are_bounded_by_the_vectors_spread_not_by_tau():
    """At an equilibrium the state's steps grow without bound (its error is 0) and, J being constant, so would the
    exact Magnus steps: one step over the whole span would collapse the tangent vectors onto the unstable direction
    (e^40 between the first and third here, beyond double precision).  The tangent steps are bounded by the spread
    of the vectors' lengths they cause, whatever ``tau``, so the sums of log |R_jj| over T are the exact ones: for
    symmetric ``A = V diag(lambda) V^T``, the QR of ``exp(A T) Q0`` has ``|R_11 ... R_jj|`` = the volume of the
    first j columns, ``exp(T (lambda_1 + ... + lambda_j)) |det (V^T Q0)[:j, :j]|`` up to factors
    ``1 + O(exp(-T gap))`` (Cauchy-Binet; the gap 2 makes them 1 to e^-40)."""
    ly = importlib.import_module("knifeedge.lyapunov")
    lam = np.array([3.0, 1.0, -1.0, -3.0])
    V = np.linalg.qr(np.arange(16.0).reshape(4, 4) ** 0.5 + np.eye(4))[0]
    A = V @ np.diag(lam) @ V.T
    Q0 = np.ascontiguousarray(np.linalg.qr(np.arange(1.0, 17.0).reshape(4, 4) + np.eye(4))[0][:, :3])
    T = 20.0
    y, Q, sums, hist_t, hist, steps, rejected, tangent_steps, _ = ly._magnus_kernel()(
        *_linear_flow(4), importlib.import_module("knifeedge.magnus").magnus_step, np.zeros(4), Q0.copy(),
        A.ravel().copy(), T, 1, 1e-8, 1e-10, 1e-8, 1e-3, 10**6)
    minors = [1.0] + [abs(np.linalg.det((V.T @ Q0)[:j, :j])) for j in (1, 2, 3)]
    expected = lam[:3] * T + np.log(np.array(minors[1:]) / np.array(minors[:-1]))
    np.testing.assert_allclose(sums, expected, rtol=1e-10)
    assert hist_t[-1] == T and np.all(y == 0.0)
    assert tangent_steps >= T * (lam[0] - lam[2]) / ly._SPREAD  # each step spreads them by at most _SPREAD


@pytest.mark.slow  # the full celt's jvp_into and both step-controlled loops (~15 s of CPU cold)
def test_magnus_tangents_agree_with_runge_kutta_tangents_through_a_reversal():
    """Schoemer's celt spun the wrong way (-2 rad/s, tilted 0.05 rad) reverses within 20 s (scene
    ``celt_schoemer``): along this strongly varying Jacobian the Magnus tangent steps (their own steps, J from the
    state's dense output) and DOP853 stages on the variational equations are two discretizations of the same tangent
    flow, so over 60 s their five exponents agree to about the tolerance, on the same trajectory.  At their defaults
    (Magnus: ``tangent_rtol = MAGNUS_TANGENT_RTOL rtol``, its sixth-order steps being controlled by a fourth-order
    estimate) both are accurate far inside the exponents' own uncertainty, measured from Magnus tangents at
    ``tangent_rtol = 1e-4 rtol`` (measured at rtol 1e-8: Magnus 2.7e-7, DOP853 stages 2.4e-8, Dormand-Prince 5(4)
    stages, the earlier Runge-Kutta tangents, 3.4e-7); neither the Magnus steps nor the exponents depend on ``tau``."""
    m = ke.load("celt")
    p = m.preset("schoemer", sigma=0.0)
    y0 = m.initial_state(n0=(np.sin(0.05), 0.0, np.cos(0.05)), omega0=(0.0, 0.0, -2.0))
    magnus = ke.lyapunov(m, y0, p, 60.0, tau=1.0, rtol=1e-10)
    rk = ke.lyapunov(m, y0, p, 60.0, tau=1.0, rtol=1e-10, tangents="rk")
    assert magnus.method.endswith("Magnus tangents") and 0 < magnus.tangent_steps < magnus.steps
    omega_z = m.closed_state_names.index("omega_z")
    assert y0[omega_z] < 0 < magnus.y[omega_z]  # it reversed
    np.testing.assert_allclose(magnus.exponents, rk.exponents, rtol=0, atol=1e-8)
    np.testing.assert_allclose(magnus.y, rk.y, rtol=0, atol=1e-8)
    ref, rk, magnus = (ke.lyapunov(m, y0, p, 60.0, tau=1.0, rtol=1e-8, **kw)
                       for kw in ({"tangent_rtol": 1e-12}, {"tangents": "rk"}, {}))
    errors = [np.abs(r.exponents - ref.exponents).max() for r in (magnus, rk)]
    assert max(errors) <= 1e-3 * ref.uncertainty.min(), errors
    # the re-orthonormalization interval: neither the Magnus steps nor (beyond the tolerance) the exponents depend
    # on it (it sets the history's times and when the invariants' round-off is projected away)
    for tau in (0.25, 5.0):
        other = ke.lyapunov(m, y0, p, 60.0, tau=tau, rtol=1e-8)
        assert other.tangent_steps == magnus.tangent_steps and len(other.history_t) == round(60.0 / tau)
        np.testing.assert_allclose(other.exponents, magnus.exponents, rtol=0, atol=1e-7)
