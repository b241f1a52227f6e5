"""Poincaré sections: the states where a run crosses a state's zero or an event function's, in one direction.

Built on the event location of :func:`knifeedge.simulate` (crossings located on the solver's dense output); the
states at the crossings are the same run's dense output at those times (a second run with ``t_eval``).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .models import Model
from .simulate import SimulationResult, simulate


@dataclass(frozen=True)
class Section:
    """The crossings of ``section`` in ``direction``: times ``t`` (k,) and states ``y`` (n_state, k)."""

    t: np.ndarray
    y: np.ndarray
    state_names: tuple
    section: str
    direction: int
    run: SimulationResult

    def __getitem__(self, name: str) -> np.ndarray:
        """The named state at each crossing, e.g. ``sec["theta2"]``."""
        return self.y[self.state_names.index(name)]


def _rhs(m: Model):
    """``rhs(y, p)``: the rates of the model's state.  Where this process has compiled the model's ``jvp_into``
    already (the Lyapunov loop's, as in scene ``celt_chaos``), that function with no columns, not ``m.rhs``
    (compiling the celt's cost 1.1 s of CPU besides)."""
    jvp = getattr(m.module, "jvp_into", None)
    if m.pose or m.input_names or not getattr(jvp, "signatures", None):
        return lambda y, p: m.rhs(0.0, y, p)
    none = np.empty((len(m.state_names), 0))

    def rhs(y, p):
        ds = np.empty(y.size)
        jvp(y, p, none, ds, none)
        return ds
    return rhs


def _rates(m: Model, section: str, y: np.ndarray, p: np.ndarray) -> np.ndarray:
    """d(section)/dt at each column of ``y``: the state's rate, or the event function along the flow."""
    out = np.empty(y.shape[1])
    rhs = _rhs(m)
    for k in range(y.shape[1]):
        yk = np.ascontiguousarray(y[:, k])
        f = rhs(yk, p)
        if section in m.state_names:
            out[k] = f[m.index(section)]
            continue
        i = m.event_names.index(section)
        eps = 1e-7 * max(1.0, float(np.linalg.norm(yk))) / max(float(np.linalg.norm(f)), 1e-300)
        closed = len(m.closed_state_names)
        plus, minus = (m.event_values(yk[:closed] + s * eps * f[:closed], p)[i] for s in (1.0, -1.0))
        out[k] = (plus - minus) / (2 * eps)
    return out


def poincare(m: Model, y0, p, t_end: float, section: str, direction: int = 1, t0: float = 0.0,
             **options) -> Section:
    """States at the zero crossings of ``section`` (a state or one of ``m.event_names``) from ``t0`` to ``t_end``.

    ``direction``: ``+1`` upward crossings (the section's rate > 0), ``-1`` downward, ``0`` both.  ``options``
    go to :func:`knifeedge.simulate` (``method``, ``rtol``, ``atol``, ...).
    """
    if not isinstance(section, str) or (section not in m.state_names and section not in m.event_names):
        raise ValueError(f"`section` must name a state {m.state_names} or an event function {m.event_names}, "
                         f"got {section!r}")
    if direction not in (-1, 0, 1) or isinstance(direction, bool):
        raise ValueError(f"`direction` must be -1, 0 or 1, got {direction!r}")
    if "t_eval" in options or "events" in options:
        raise ValueError("`t_eval` and `events` are set by poincare; leave them out")
    p = m.check_params(p)
    first = simulate(m, y0, (t0, t_end), p, events=(section,), **options)
    times = first.events[section]
    if times.size == 0:
        return Section(times, np.empty((m.n_state, 0)), m.state_names, section, direction, first)
    run = simulate(m, y0, (t0, t_end), p, events=(section,), t_eval=times, **options)
    y = run.y
    if direction:
        keep = direction * _rates(m, section, y, p) > 0
        times, y = times[keep], y[:, keep]
    return Section(times, y, m.state_names, section, direction, run)
