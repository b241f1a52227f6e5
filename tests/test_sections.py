"""Poincaré sections (``knifeedge.poincare``) on the event location of ``simulate``."""
import numpy as np
import pytest

import knifeedge as ke


def test_upward_crossings_of_the_tilt_come_once_per_period():
    """Single-mode knife edge at a slow spin: the tilt oscillates at the paper's omega = sqrt(g ell)/... (the
    module's ``frequencies``), so the upward zeros of theta are one period apart, with theta = 0, theta_dot > 0."""
    m = ke.load("single_mode")
    p = m.params(m.default_params)
    sec = ke.poincare(m, m.state(theta=1e-3, theta_dot=0.0, phi_dot=1e-4), p, 60.0, "theta", direction=1)
    period = 2 * np.pi / m.frequencies(p)[0]
    assert sec.t.size == 9
    np.testing.assert_allclose(np.diff(sec.t), period, rtol=1e-5)
    assert np.all(np.abs(sec["theta"]) < 1e-14) and np.all(sec["theta_dot"] > 0)
    both = ke.poincare(m, m.state(theta=1e-3, theta_dot=0.0, phi_dot=1e-4), p, 60.0, "theta", direction=0)
    down = ke.poincare(m, m.state(theta=1e-3, theta_dot=0.0, phi_dot=1e-4), p, 60.0, "theta", direction=-1)
    assert both.t.size == sec.t.size + down.t.size and np.all(down["theta_dot"] < 0)


def test_bad_section_and_direction_are_named():
    m = ke.load("single_mode")
    p = m.params(m.default_params)
    y0 = m.state(theta=1e-3, theta_dot=0.0, phi_dot=0.1)
    with pytest.raises(ValueError, match="`section`"):
        ke.poincare(m, y0, p, 1.0, "psi")
    with pytest.raises(ValueError, match="`direction`"):
        ke.poincare(m, y0, p, 1.0, "theta", direction=2)


def test_the_directions_come_from_a_compiled_jvp_into_when_there_is_one(monkeypatch):
    """``knifeedge figures`` cold (issue 25 item 4): after a Lyapunov loop (scene celt_chaos) the crossings'
    directions are the rates its ``jvp_into`` gives (no columns), not a compile of ``rhs`` besides; the same
    section either way.  The compiled function is stood in for by the Python one, counted."""
    m = ke.load("single_mode")
    p = m.params(m.default_params)
    y0 = m.state(theta=1e-3, theta_dot=0.0, phi_dot=1e-4)
    plain = ke.poincare(m, y0, p, 60.0, "theta", direction=1)
    calls = []

    class Compiled:
        signatures = ["(the Lyapunov loop's)"]

        def __call__(self, s, q, V, ds, out):
            calls.append(V.shape)
            ds[:] = m.module.rhs.py_func(0.0, s, q)

    monkeypatch.setattr(m.module, "jvp_into", Compiled())
    via = ke.poincare(m, y0, p, 60.0, "theta", direction=1)
    assert calls and set(calls) == {(len(m.state_names), 0)}
    np.testing.assert_array_equal(via.t, plain.t)
