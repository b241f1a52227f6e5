"""Recording every step: the rows stored are those of the steps taken, however the buffers grow.

``simulate`` without ``t_eval`` stores the start and every accepted step into
one buffer of rows, sized from the pace of the run so far (``ROWS_FIRST``
rows until the first pause) and grown when full; the event buffers double when
full; fixed-step methods know their number of rows beforehand (up to
``ROWS_AHEAD``).  None of this may change a step, a value or an event.
Scenes (units g = ell = 1): the two-mode scene of the paper's Fig.
'Numerical2' (README "Use") and the single-mode scene of Fig. 'numerical'.
"""
import importlib
import math

import numpy as np
import pytest

import knifeedge as ke

sim = importlib.import_module("knifeedge.simulate")

TWO = dict(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4)
TWO_Y0 = dict(theta1=1e-3, theta2=1e-3, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1)
SINGLE = dict(g=1.0, ell=1.0, L=1.0, D=1.0)
SINGLE_Y0 = dict(theta=1e-3, theta_dot=0.0, phi_dot=0.1)


def _scene(name):
    if name == "two":
        m = ke.load("two_mode", "full")
        return m, m.state(**TWO_Y0), m.params(**TWO), 3000.0
    m = ke.load("single_mode", "full")
    return m, m.state(**SINGLE_Y0), m.params(**SINGLE), 300.0


# DP54 shares DOP853's integrator (the slow checks run it); RK4 is the fixed-step one
CASES = [("two", "DOP853", {}), pytest.param("single", "DP54", {}, marks=pytest.mark.slow), ("single", "RK4", {"h": 0.05})]


@pytest.mark.parametrize("scene,method,kw", CASES)
def test_every_step_recorded_ends_on_the_final_state_call(scene, method, kw):
    """The default output (every accepted step, reversal events on) and the call asking only for the final
    state take the same steps: the last recorded row is that state, bit for bit, and the first is y0."""
    m, y0, p, t1 = _scene(scene)
    every = ke.simulate(m, y0, (0.0, t1), p, method=method, **kw)
    final = ke.simulate(m, y0, (0.0, t1), p, method=method, t_eval=[t1], **kw)
    ends = ke.simulate(m, y0, (0.0, t1), p, method=method, t_eval=[0.0, t1], **kw)
    assert every.success and final.success and ends.success
    assert every.t.size == every.nsteps + 1 and np.all(np.diff(every.t) > 0)
    assert every.t[0] == 0.0 and every.t[-1] == final.t[-1] == t1 and final.t.shape == (1,)
    np.testing.assert_array_equal(every.y[:, 0], y0)
    np.testing.assert_array_equal(every.y[:, -1], final.y[:, 0])
    np.testing.assert_array_equal(ends.y, every.y[:, [0, -1]])
    assert every.nfev == final.nfev and every.nsteps == final.nsteps
    np.testing.assert_array_equal(every.reversal_times, final.reversal_times)
    assert every.y.flags.c_contiguous and every.y.shape == (m.n_state, every.t.size)


def _spy_growth(monkeypatch):
    """Record each new buffer of rows (``"rows"``) and each growth of the event buffers (``"events"``)."""
    grown = []
    rows_ahead, events_grown = sim._rows_ahead, sim._grown

    def rows(*args):
        grown.append("rows")
        return rows_ahead(*args)

    def events(buf, used, size):
        grown.append("events")
        return events_grown(buf, used, size)

    monkeypatch.setattr(sim, "_rows_ahead", rows)
    monkeypatch.setattr(sim, "_grown", events)
    monkeypatch.setattr(sim, "_KEPT", sim.threading.local())  # no buffer kept from an earlier run
    return grown


@pytest.mark.parametrize("scene,method,kw", CASES)
def test_growing_buffers_give_the_rows_of_one_large_buffer(monkeypatch, scene, method, kw):
    """Rows and events grown from tiny buffers across many paused calls equal those of one call into
    buffers large enough for the whole run (events on every state: hundreds of crossings)."""
    m, y0, p, t1 = _scene(scene)
    args = (m, y0, (0.0, t1), p)
    kw = dict(kw, method=method, events=m.state_names)
    with monkeypatch.context() as mp:
        mp.setattr(sim, "ROWS_FIRST", 10**6)
        mp.setattr(sim, "ROWS_AHEAD", 10**6)
        mp.setattr(sim, "EVENTS_FIRST", 10**6)
        mp.setattr(sim, "CHUNK_STEPS", 10**9)
        grown = _spy_growth(mp)
        one = ke.simulate(*args, **kw)
        assert grown == []  # one buffer, one call
    grown = _spy_growth(monkeypatch)
    monkeypatch.setattr(sim, "ROWS_FIRST", 2)
    monkeypatch.setattr(sim, "ROWS_AHEAD", 3)
    monkeypatch.setattr(sim, "EVENTS_FIRST", 1)
    monkeypatch.setattr(sim, "CHUNK_STEPS", 333)
    parts = ke.simulate(*args, **kw)
    assert "rows" in grown and "events" in grown  # new buffers of rows, event buffers grown
    assert one.success and parts.success and one.nsteps > 1000
    assert sum(v.size for v in one.events.values()) > 150
    assert (one.nfev, one.nsteps, one.nrejected) == (parts.nfev, parts.nsteps, parts.nrejected)
    np.testing.assert_array_equal(one.t, parts.t)
    np.testing.assert_array_equal(one.y, parts.y)
    assert one.events.keys() == parts.events.keys()
    for name in one.events:
        np.testing.assert_array_equal(one.events[name], parts.events[name])


@pytest.mark.parametrize("t_eval", [None, "final", "grid"])
def test_a_result_keeps_its_rows_when_the_next_run_records(t_eval):
    """A thread keeps a run's buffer of rows for its next run; no result shares it: later runs (longer,
    shorter, other output) leave an earlier result as it was, and a run into a kept buffer holding stale rows
    stores what a run into new buffers stores."""
    m, y0, p, t1 = _scene("two")
    grid = {None: None, "final": [t1], "grid": np.linspace(0.0, t1, 7)}[t_eval]
    first = ke.simulate(m, y0, (0.0, t1), p, t_eval=grid)
    kept = first.t.copy(), first.y.copy(), {k: v.copy() for k, v in first.events.items()}
    ke.simulate(m, 2 * y0, (0.0, 3 * t1), p)
    ke.simulate(m, 3 * y0, (0.0, t1 / 3), p, events=m.state_names)
    ke.simulate(m, 4 * y0, (0.0, t1), p, t_eval=grid)
    again = ke.simulate(m, y0, (0.0, t1), p, t_eval=grid)
    for r in (first, again):
        np.testing.assert_array_equal(r.t, kept[0])
        np.testing.assert_array_equal(r.y, kept[1])
        for name, times in kept[2].items():
            np.testing.assert_array_equal(r.events[name], times)
