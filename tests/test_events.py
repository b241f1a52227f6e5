"""Zero crossings located by the kernels: state components and event functions, two inside one step.

The stand-in model (``tests/stub_model.py``) is the oscillator
``q' = v, v' = -w^2 q, w_' = -q`` with ``w = p[0]``; from ``q = 1, v = 0, w_ = W`` its solution is
``q = cos(w t)``, ``w_ = W - sin(w t) / w`` (closed forms), and its event function is
``q^2 - p[1]``.  Both are built to cross zero twice within a short time, as a celt's spin
``omega . n`` does within a reversal (issue 10: two crossings 3e-4 s apart): ``w_`` dips below zero
for a moment when ``W`` is just below ``1/w``, ``q^2 - c`` twice around each extremum of ``q`` when
``c`` is just below 1.
"""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import knifeedge as ke
from knifeedge.integrators import EVENTS_PER_STEP, load_kernel
import stub_model as _stub

W = 2.0


def _kernel(method):
    template = "fixed" if method == "RK4" else "erk"
    return template, load_kernel(template, method, _stub, "rhs_q_into", 3).solve


def _run(method, y0, p, t1, events, rtol=1e-10, h=None, atol=None):
    """Every step stored and the crossings of ``events`` (codes: component, or -1 - function)."""
    template, solve = _kernel(method)
    events = np.array(events, dtype=np.int64)
    ts, ys = np.empty(100_000), np.empty((100_000, 3))
    ev_t, ev_k = np.empty(4096), np.empty(4096, dtype=np.int64)
    pair, empty = np.full(3, -1), np.empty(0)
    if template == "erk":
        out = solve(0.0, t1, y0, y0, p, (rtol, np.full(3, atol or rtol * 1e-3), 0.0, np.inf, pair, False),
                    (empty, True, events, 10**7, 10**7), (ts, ys, ev_t, ev_k))
    else:
        n = math.ceil(t1 / h)
        out = solve(0.0, t1, y0, y0, p, (t1 / n, n, 0, np.full(3, 1e-6), pair, np.zeros(3), np.empty((4, 3))),
                    (empty, True, events, 10**7, 10**7), (ts, ys, ev_t, ev_k))
    n_out, n_ev, status = out[:3]
    assert status == 0
    return np.concatenate([[0.0], ts[:n_out]]), ev_t[:n_ev], ev_k[:n_ev]


def _dip_crossings(w_start, t1):
    """Closed form: w_(t) = W0 - sin(W t)/W = 0, i.e. sin(W t) = W W0: two roots per period."""
    s = math.asin(W * w_start)
    period = 2 * math.pi / W
    out = []
    for k in range(int(t1 / period) + 1):
        out += [(s + 2 * math.pi * k) / W, (math.pi - s + 2 * math.pi * k) / W]
    return np.array(sorted(x for x in out if 0 < x < t1))


def _square_crossings(c, t1):
    """Closed form: cos(W t)^2 = c, i.e. W t = k pi -+ arccos(sqrt(c))."""
    a = math.acos(math.sqrt(c))
    out = [k * math.pi + s * a for k in range(int(W * t1 / math.pi) + 2) for s in (-1, 1)]
    return np.array(sorted(x / W for x in out if 0 < x / W < t1))


def _pairs_inside_one_step(times, steps):
    """How many consecutive crossings share a step (same step index)."""
    idx = np.searchsorted(steps, times)
    return int(np.sum(idx[1:] == idx[:-1]))


@pytest.mark.parametrize("method,h", [("DOP853", None), pytest.param("DP54", None, marks=pytest.mark.slow),
                                      pytest.param("Tsit5", None, marks=pytest.mark.slow), pytest.param("RK4", 0.05, marks=pytest.mark.slow)])
def test_two_crossings_of_a_state_inside_one_step(method, h):
    """w_ = W0 - sin(2t)/2 with W0 = 0.4999 is below zero only for |t - pi/4 - k pi| < 0.01: both crossings
    of each dip fall inside one step (the step ends have the same sign), and are found to the tolerance
    (atol 1e-9 on w_, whose rate at the crossings is 0.02: times to about 5e-8)."""
    w0 = 0.49990
    t1 = 10.0
    steps, ev, k = _run(method, np.array([1.0, 0.0, w0]), np.array([W, 0.0]), t1, [2], h=h, atol=1e-9)
    exact = _dip_crossings(w0, t1)
    assert exact.size == 6 and np.min(np.diff(exact)[::2]) < 0.021
    assert _pairs_inside_one_step(exact, steps) >= 2  # the situation the screen is for
    tol = 1e-6 if h is None else 1e-4  # fixed steps: the cubic Hermite interpolant's error at h = 0.05
    np.testing.assert_allclose(ev, exact, atol=tol)
    assert np.all(k == 0)


@pytest.mark.parametrize("method", ["DOP853", pytest.param("DP54", marks=pytest.mark.slow)])  # DP54: slow tier
@pytest.mark.xdist_group("dp54_tsit5")  # one worker compiles the DP54 and Tsit5 integrators for all such tests
def test_two_crossings_of_an_event_function_inside_one_step(method):
    """The stub's event function q^2 - c with c = 0.99999 vanishes at W t = k pi -+ 0.0032: pairs 0.0032 apart
    around each extremum of q = cos(2t), inside one step; the kernel finds all of them."""
    c, t1 = 0.99999, 6.0
    steps, ev, k = _run(method, np.array([1.0, 0.0, 0.0]), np.array([W, c]), t1, [-1, 0])
    exact = _square_crossings(c, t1)
    assert exact.size == 7 and _pairs_inside_one_step(exact, steps) >= 2
    np.testing.assert_allclose(ev[k == 0], exact, atol=1e-8)
    # the component q = cos(2t) crosses at (2j + 1) pi / 4, one at a time
    np.testing.assert_allclose(ev[k == 1], (2 * np.arange(4) + 1) * math.pi / 4, atol=1e-8)


def test_crossings_agree_with_solve_ivp_dense_event_location():
    """The same event function located by SciPy's solve_ivp (DOP853, its dense output and brentq) with
    steps small enough (max_step 1e-3) that no two crossings share a step, against our kernel at its own
    steps: equal within solve_ivp's tolerance."""
    c, t1, rtol = 0.9999, 6.0, 1e-11

    def fun(t, s):
        return [s[1], -W * W * s[0], -s[0]]

    def g(t, s):
        return s[0] * s[0] - c

    ref = solve_ivp(fun, (0.0, t1), [1.0, 0.0, 0.0], method="DOP853", rtol=rtol, atol=1e-14, max_step=1e-3,
                    events=g).t_events[0]
    _, ev, k = _run("DOP853", np.array([1.0, 0.0, 0.0]), np.array([W, c]), t1, [-1], rtol=rtol)
    assert ref.size == ev.size == 7
    np.testing.assert_allclose(ev, ref, atol=1e-9)


def test_event_buffers_hold_every_crossing_a_step_can_find():
    """Each step can report up to EVENTS_PER_STEP crossings of one event; the kernel pauses before a step
    could overflow the buffers, so a tiny buffer still yields every crossing over several calls."""
    assert EVENTS_PER_STEP >= 3
    _, solve = _kernel("DOP853")
    y0, p = np.array([1.0, 0.0, 0.49990]), np.array([W, 0.0])
    found, t, y, f, h = [], 0.0, y0, y0, 0.0
    for _ in range(10_000):
        ev_t, ev_k = np.empty(EVENTS_PER_STEP), np.empty(EVENTS_PER_STEP, dtype=np.int64)
        out = solve(t, 10.0, y, f, p, (1e-10, np.full(3, 1e-13), h, np.inf, np.full(3, -1), False),
                    (np.empty(0), True, np.array([2], dtype=np.int64), 10**7, 10**7),
                    (np.empty(10**5), np.empty((10**5, 3)), ev_t, ev_k))
        found += list(ev_t[:out[1]])
        t, y, f, h = out[6:]
        if out[2] != 1:
            break
    np.testing.assert_allclose(found, _dip_crossings(0.49990, 10.0), atol=1e-7)


def test_screen_flags_a_dip_a_crossing_and_nothing_else():
    """The screen's verdicts (``integrators.common.screen``: compiled in the kernels, run by Python in the SciPy
    path) on closed-form ends: g = (x - 0.5)^2 - d over the step [0, 1] (values and rates at x = 0, 1) dips
    below zero for d > 0 (two crossings, flag 2 with the extremum at 0.5), stays above it for d < 0 far from
    zero (flag 0); a line through zero is flag 1."""
    from knifeedge.integrators.common import screen

    def verdict(fn, g0, g1, s0, s1):
        crit, n_crit, flag = np.zeros((1, 2)), np.zeros(1, dtype=np.int64), np.zeros(1, dtype=np.int64)
        fn(np.array([g0]), np.array([g1]), np.array([s0]), np.array([s1]), crit, n_crit, flag)
        return int(flag[0]), crit[0, :n_crit[0]].tolist()

    def ends(d):
        return 0.25 - d, 0.25 - d, -1.0, 1.0  # g(0), g(1), g'(0), g'(1) (the step is 1)

    for fn in (screen, screen.py_func):
        flag, crit = verdict(fn, *ends(0.01))
        assert flag == 2 and crit == pytest.approx([0.5])
        assert verdict(fn, *ends(-1.0)) == (0, [])
        assert verdict(fn, 1.0, -1.0, -2.0, -2.0)[0] == 1


@pytest.fixture(scope="module")
def celt_kane_levinson():
    m = ke.load("celt", "full")
    tilt = math.radians(0.5)  # Kane & Levinson's start: al = be = 0.5 deg, omega0 = (0, 0, 5)
    n0 = (math.cos(tilt) * math.sin(tilt), math.sin(tilt), math.cos(tilt) * math.cos(tilt))
    return m, m.preset("kane_levinson_1982"), m.initial_state(n0=n0, omega0=(0.0, 0.0, 5.0))


@pytest.mark.parametrize("method,t_end", [("DOP853", 20.0), ("scipy:DOP853", 3.0)])
def test_celt_reversal_crossings_3e_4_apart_are_all_found(celt_kane_levinson, method, t_end):
    """Issue 10: a celt reversal is a cluster of crossings of omega . n, two of them 3.1e-4 s apart
    (Kane-Levinson celt, Omega = +5 rad/s: at t = 2.6846 and 2.6850 s).  At rtol = atol = 1e-8 the steps
    there are longer than the pair's gap and one step holds both (same sign at its ends); every crossing
    is still reported, at the times of a run whose steps are limited to 2e-5 s (each step then holds at
    most one crossing), within the tolerance's effect on them."""
    m, p, y0 = celt_kane_levinson
    r = ke.simulate(m, y0, (0.0, t_end), p, method=method, rtol=1e-8, atol=1e-8)
    fine = ke.simulate(m, y0, (0.0, t_end), p, rtol=1e-10, atol=1e-12, max_step=2e-5)
    assert fine.reversal_times.size == (10 if t_end == 20.0 else 7)
    assert 3.0e-4 < np.min(np.diff(fine.reversal_times)) < 3.2e-4
    steps = np.searchsorted(r.t, r.reversal_times)
    if method == "DOP853":
        assert np.any(steps[1:] == steps[:-1])  # a pair inside one step: the case the screen exists for
    assert r.reversal_times.size == fine.reversal_times.size
    np.testing.assert_allclose(r.reversal_times, fine.reversal_times, atol=1e-5)


@pytest.fixture(scope="module")
def sleigh(tmp_path_factory):
    """The damped Chaplygin sleigh of tests/models/damped_sleigh.py, whose event function is
    heading_speed = phi_dot - v (EVENT_NAMES / event_values of its generated module)."""
    from pathlib import Path

    from knifeedge import cli

    out = tmp_path_factory.mktemp("event_models")
    assert cli.main(["derive", str(Path(__file__).resolve().parent / "models" / "damped_sleigh.py"),
                     "--out", str(out)]) == 0
    return ke.load("damped_sleigh", path=out)


@pytest.mark.parametrize("method,kw", [("DOP853", {}), pytest.param("DP54", {}, marks=pytest.mark.slow),
                                       pytest.param("RK4", {"h": 0.01}, marks=pytest.mark.slow), ("scipy:DOP853", {})])
def test_event_functions_of_a_model_are_located_by_every_method(sleigh, method, kw):
    """simulate(..., events=("heading_speed",)) locates the zero of the model's event function phi_dot - v
    (the turning rate falls to the speed as the damping slows the turn): where it is reported, the state
    interpolated there makes the function vanish, and the compiled and SciPy paths agree."""
    p = sleigh.params(sleigh.default_params)
    r = ke.simulate(sleigh, sleigh.default_state, (0.0, 30.0), p, method=method, events=("heading_speed",), **kw)
    ref = ke.simulate(sleigh, sleigh.default_state, (0.0, 30.0), p, method="scipy:DOP853",
                      events="heading_speed")
    t = r.events["heading_speed"]
    assert t.size == 1 and set(r.events) == {"phi_dot", "heading_speed"}
    at = ke.simulate(sleigh, sleigh.default_state, (0.0, 30.0), p, method=method, t_eval=t, **kw)
    assert abs(sleigh.event_values(at.y[:, 0], p)[0]) < 1e-12
    np.testing.assert_allclose(t, ref.events["heading_speed"], rtol=1e-7 if method == "RK4" else 1e-9)
    with pytest.raises(ValueError, match="event functions"):
        ke.simulate(sleigh, sleigh.default_state, (0.0, 1.0), p, events=("heading",))
