"""Integration methods as data: the tableau checks, the registry, Tsitouras 5(4).

Scenes as in test_integrators.py: the single-mode knife edge of the paper's Fig. 'numerical'
(g = ell = L = D = 1, theta(0) = 1e-3, phi_dot(0) = 0.1), whose spin reversal is at t = 106.361.
"""
import dataclasses
import math

import numpy as np
import pytest

import knifeedge as ke
from knifeedge.integrators import COMPILED_METHODS, ExplicitTableau, FixedMethod, load_kernel, methods, register
import stub_model as _stub

SINGLE = dict(g=1.0, ell=1.0, L=1.0, D=1.0)
SINGLE_Y0 = dict(theta=1e-3, theta_dot=0.0, phi_dot=0.1)


def _euler_heun(**over):
    """Heun's method with an Euler estimate, a valid 2(1) pair with the linear interpolant's power form."""
    kw = dict(name="heun", c=[0.0, 1.0], A=[[0.0, 0.0], [1.0, 0.0]], b=[0.5, 0.5], e=[-0.5, 0.5, 0.0],
              order=2, error_order=1, P=[[1.0, -0.5], [0.0, 0.5], [0.0, 0.0]], description="", reference="")
    kw.update(over)
    return ExplicitTableau(**kw)


def test_a_consistent_tableau_is_accepted_and_frozen():
    t = _euler_heun()
    assert t.stages == 2 and not t.A.flags.writeable
    with pytest.raises(AttributeError):
        t.order = 3


@pytest.mark.parametrize("over,match", [
    (dict(A=[[0.0, 0.0], [0.9, 0.0]]), "rows \\[1\\] of A do not sum to c"),
    (dict(b=[0.5, 0.6]), "weights b sum to"),
    (dict(e=[-0.5, 0.5, 0.1]), "error estimator e sums to"),
    (dict(A=[[0.0, 0.1], [0.9, 0.0]]), "strictly lower triangular"),
    (dict(c=[0.1, 1.0], A=[[0.1, 0.0], [1.0, 0.0]]), "c\\[0\\] must be 0"),
    (dict(P=[[1.0, -0.4], [0.0, 0.5], [0.0, 0.0]]), "dense output at x = 1"),
    (dict(order=1), "error_order < order"),
    (dict(P=None), "exactly one dense output"),
])
def test_an_inconsistent_tableau_is_refused_at_construction(over, match):
    with pytest.raises(ValueError, match=match):
        _euler_heun(**over)


def test_dop853_and_dp54_are_the_published_coefficients():
    """DOP853 and DP54 are SciPy's tables (``scipy.integrate.DOP853``, ``RK45``); entries of every array, bit for
    bit, against the literals of E. Hairer's Fortran dop853.f (``c2``, ``a21``, ``a1312``, ``b1``, ``bhh1``,
    ``er1``, ``c14``, ``a1413``, ``d41``) and Dormand & Prince (1980), Table 2 (``a54``, ``b5``, ``e7``)."""
    d, h = methods.DOP853, methods.DOP853.hairer
    assert d.c[1] == float("0.526001519587677318785587544488e-01")
    assert d.A[1, 0] == float("5.26001519587677318785587544488e-2")
    assert d.A[11, 10] == float("6.43392746015763530355970484046e-1")
    assert d.b[0] == float("5.42937341165687622380535766363e-2")
    assert h["e3"][0] == d.b[0] - float("0.244094488188976377952755905512")
    assert d.e[0] == float("0.1312004499419488073250102996e-01")
    assert h["c_ext"][0] == 0.1 and h["A_ext"][0, 12] == float("-8.298e-3")
    assert h["D"][0, 0] == float("-0.84289382761090128651353491142e+1")
    assert d.stages == 12 and h["A_ext"].shape == (3, 16) and h["D"].shape == (4, 16)
    assert methods.DP54_A[4, 3] == -212 / 729 and methods.DP54_B[4] == -2187 / 6784 and methods.DP54_E[6] == 1 / 40


def test_registered_methods_are_consistent_and_names_are_unique():
    """One registry for every kind of method: each registered method rebuilds (its checks pass), is a method of
    ``ke.simulate``, and a name is registered once; asking for a method of another kind is refused."""
    builtin = ["DOP853", "DP54", "Tsit5", "RK4", "implicit_midpoint", "gauss4", "gauss6"]
    assert list(COMPILED_METHODS)[:7] == builtin and set(builtin) <= set(ke.METHODS)  # (a test may add more)
    for name, t in COMPILED_METHODS.items():
        assert t.name == name
        assert type(t)(**{f.name: getattr(t, f.name) for f in dataclasses.fields(t)}).stages == t.stages
    with pytest.raises(ValueError, match="already registered"):
        register(_euler_heun(name="DP54"))
    with pytest.raises(ValueError, match="unknown erk method 'nope'"):
        methods.get("nope", "erk")
    with pytest.raises(ValueError, match="unknown erk method 'RK4'"):
        methods.get("RK4", "erk")
    assert methods.get("RK45") is COMPILED_METHODS["DP54"]


def test_tsit5_satisfies_the_order_conditions():
    """Tsitouras (2011): order 5 for the step (all 17 conditions up to order 5 hold for an explicit method whose
    rows sum to c and which satisfies the quadrature and the first-column conditions; we check the quadrature
    conditions b.c^k = 1/(k+1) and the tall trees b.A^k c), order 4 for the embedded solution b - e."""
    t = COMPILED_METHODS["Tsit5"]
    b, c, A = t.b, t.c, t.A
    for k in range(5):
        assert math.isclose(b @ c**k, 1 / (k + 1), abs_tol=1e-14), k
    assert math.isclose(b @ A @ c, 1 / 6, abs_tol=1e-14)
    assert math.isclose(b @ (c * (A @ c)), 1 / 8, abs_tol=1e-14)
    assert math.isclose(b @ A @ A @ c, 1 / 24, abs_tol=1e-14)
    assert math.isclose(b @ A @ A @ A @ c, 1 / 120, abs_tol=1e-14)
    b_hat = np.append(b, 0.0) - t.e
    c1 = np.append(c, 1.0)
    for k in range(4):
        assert math.isclose(b_hat @ c1**k, 1 / (k + 1), abs_tol=1e-14), k
    assert abs(b_hat @ c1**4 - 1 / 5) > 1e-6  # the estimate is of order 4, not 5


def _harmonic(method, rtol):
    """The stand-in oscillator q'' = -w^2 q (tests/stub_model.py, w = 2): q(t) = cos(2t), exact at t = 10."""
    m_solve = load_kernel("erk", method, _stub, "rhs_q_into", 3).solve
    y0, p = np.array([1.0, 0.0, 0.0]), np.array([2.0])
    ts, ys, ev_t, ev_k = np.empty(2), np.empty((2, 3)), np.empty(64), np.empty(64, dtype=np.int64)
    n_out, n_ev, status, nfev = m_solve(0.0, 10.0, y0, y0, p, (rtol, np.full(3, rtol * 1e-3), 0.0, np.inf,
                                                                np.full(3, -1), False),
                                        (np.array([5.0, 10.0]), False, np.array([0]), 10**6, 10**6),
                                        (ts, ys, ev_t, ev_k))[:4]
    assert status == 0 and n_out == 2
    return ys, ev_t[:n_ev], nfev


@pytest.mark.parametrize("method,order", [pytest.param("Tsit5", 5, marks=pytest.mark.slow),
                                          pytest.param("DP54", 5, marks=pytest.mark.slow), ("DOP853", 8)])
@pytest.mark.xdist_group("dp54_tsit5")  # one worker compiles the DP54 and Tsit5 integrators for all such tests
def test_adaptive_methods_converge_at_their_order(method, order):
    """Global error of q(10) = cos(20) against the number of evaluations: slope -order (within 30 %),
    measured between rtol 1e-7 and 1e-10; the zeros of q, cos(2t) = 0 at t = (2k+1) pi/4, are located too."""
    errs, work = [], []
    for rtol in (1e-7, 1e-10):
        ys, ev, nfev = _harmonic(method, rtol)
        errs.append(abs(ys[1, 0] - math.cos(20.0)))
        work.append(nfev)
        np.testing.assert_allclose(ev, (2 * np.arange(ev.size) + 1) * math.pi / 4, atol=100 * rtol)
        assert ev.size == 6
    slope = -math.log(errs[1] / errs[0]) / math.log(work[1] / work[0])
    assert 0.7 * order < slope < 1.3 * order + 1, (slope, errs, work)


@pytest.mark.slow  # compiles the Tsit5 and DP54 integrators (~7 s each cold); the order conditions above stay
@pytest.mark.xdist_group("dp54_tsit5")  # one worker compiles the DP54 and Tsit5 integrators for all such tests
def test_tsit5_on_the_paper_scene_matches_dop853():
    """Fig. 'numerical': the spin reversal at t = 106.361 and the final state, Tsit5 against DOP853 (an
    independent method of order 8) at rtol 1e-11; Tsit5 needs fewer evaluations than DP54 at equal rtol."""
    m = ke.load("single_mode", "full")
    p = m.params(**SINGLE)
    kw = dict(rtol=1e-11, atol=1e-13)
    ts5 = ke.simulate(m, SINGLE_Y0, (0.0, 300.0), p, method="Tsit5", **kw)
    ref = ke.simulate(m, SINGLE_Y0, (0.0, 300.0), p, method="DOP853", **kw)
    dp5 = ke.simulate(m, SINGLE_Y0, (0.0, 300.0), p, method="DP54", **kw)
    assert ts5.success and round(ts5.reversal_times[0], 3) == 106.361
    assert math.isclose(ts5.reversal_times[0], ref.reversal_times[0], rel_tol=1e-8)
    np.testing.assert_allclose(ts5.y[:, -1], ref.y[:, -1], rtol=1e-6, atol=1e-9)
    assert ts5.nfev < dp5.nfev


# -- fixed-step methods as data ------------------------------------------------------------------------------------
def test_fixed_step_methods_are_registered_data_checked_when_built():
    """The fixed-step methods are registered tableaus: RK4 (its increment written out in the kernel, recognized
    by its tableau), the Gauss-Legendre methods of 1-3 stages (Hairer, Lubich & Wanner, Geometric Numerical
    Integration, Table II.1.1: implicit, rows of A summing to c); a tableau whose rows do not sum to c, or whose
    weights do not sum to one, is refused when built."""
    fixed = [name for name, m in COMPILED_METHODS.items() if m.fixed_step]
    assert fixed[:4] == ["RK4", "implicit_midpoint", "gauss4", "gauss6"]  # (a test may add more)
    assert all(isinstance(COMPILED_METHODS[name], FixedMethod) for name in fixed)
    assert COMPILED_METHODS["RK4"].is_classical_rk4 and not COMPILED_METHODS["RK4"].implicit
    for name, s in (("implicit_midpoint", 1), ("gauss4", 2), ("gauss6", 3)):
        m = COMPILED_METHODS[name]
        assert m.implicit and m.stages == s and m.order == 2 * s
        # the collocation polynomial through the nodes reproduces itself: extrapolating a constant is constant
        np.testing.assert_allclose(m.extrapolation.sum(axis=1), 1.0, rtol=1e-13)
    with pytest.raises(ValueError, match="of A do not sum to c"):
        FixedMethod("bad", [[0.0, 0.0], [0.4, 0.0]], [0.5, 0.5], [0.0, 0.5], 2, "rows off")
    with pytest.raises(ValueError, match="weights b sum to"):
        FixedMethod("bad", [[0.0, 0.0], [0.5, 0.0]], [0.5, 0.4], [0.0, 0.5], 2, "weights off")


@pytest.mark.slow  # compiles a kernel for a tableau no other check uses
def test_an_explicit_tableau_as_data_converges_at_its_order():
    """An explicit fixed-step method given only as its tableau (Kutta's 3/8 rule, order 4: E. Hairer, S. P.
    Norsett, G. Wanner, Solving ODEs I, Table II.1.2) runs through the kernel's general stage loops: on the stub
    oscillator q'' = -4 q its error at t = 10 against cos(20) falls 16-fold when the step halves (order 4)."""
    name = "kutta38_test"
    if name not in COMPILED_METHODS:
        register(FixedMethod(name, [[0, 0, 0, 0], [1 / 3, 0, 0, 0], [-1 / 3, 1, 0, 0], [1, -1, 1, 0]],
                                   [1 / 8, 3 / 8, 3 / 8, 1 / 8], [0, 1 / 3, 2 / 3, 1], 4, "Kutta's 3/8 rule", 8.0))
    assert not COMPILED_METHODS[name].is_classical_rk4
    solve = load_kernel("fixed", name, _stub, "rhs_q_into", 3).solve
    y0, p = np.array([1.0, 0.0, 0.0]), np.array([2.0])
    errs = []
    for n_steps in (200, 400):
        ts, ys, ev_t, ev_k = np.empty(2), np.empty((2, 3)), np.empty(64), np.empty(64, dtype=np.int64)
        out = solve(0.0, 10.0, y0, y0, p, (10.0 / n_steps, n_steps, 0, np.full(3, 1e-12), np.full(3, -1),
                                           np.zeros(3), np.empty((4, 3))),
                    (np.array([10.0]), False, np.empty(0, dtype=np.int64), 10**6, 10**6), (ts, ys, ev_t, ev_k))
        assert out[2] == 0 and out[0] == 1
        errs.append(abs(ys[0, 0] - math.cos(20.0)))
    assert 16 * 0.8 < errs[0] / errs[1] < 16 * 1.25, errs
