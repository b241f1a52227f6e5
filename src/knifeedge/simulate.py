"""``simulate``: integrate a model and locate its spin reversals.

The integration methods are looked up in :data:`METHODS`; every method
returns the same :class:`SimulationResult`.  Inputs are validated before any
work (``ValueError``/``TypeError`` naming the argument); a failed
integration is reported in ``success``/``status``/``message`` and its arrays
stop at the last good step.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp

from .models import Model


@dataclass
class SimulationResult:
    """Outcome of :func:`simulate`.

    Attributes
    ----------
    t : ndarray, shape (n_times,)
    y : ndarray, shape (n_state, n_times)
        States in the order of ``state_names``.
    state_names : tuple of str
    reversal_times : ndarray
        Spin reversals: zero crossings of ``phi_dot``, located on the
        solver's dense output.
    success : bool
    status : int
        0 reached the end of ``t_span``; negative values are failures.
    message : str
    nfev : int
        Right-hand-side evaluations.
    method : str
    model : Model
    p : ndarray
    """

    t: np.ndarray
    y: np.ndarray
    state_names: tuple
    reversal_times: np.ndarray
    success: bool
    status: int
    message: str
    nfev: int
    method: str
    model: Model = field(repr=False)
    p: np.ndarray = field(repr=False)

    def __getitem__(self, name: str) -> np.ndarray:
        """Time series of the named state, e.g. ``r["phi_dot"]``."""
        return self.y[self.model.index(name)]

    @property
    def energy(self) -> np.ndarray:
        """Energy per unit mass along the trajectory."""
        return self.model.energy(self.y, self.p)


SCIPY_METHODS = ("RK45", "DOP853", "LSODA", "Radau")
#: method name -> runner(model, y0, t_span, p, rtol, atol, t_eval, max_step)
METHODS: dict = {}


def _spin_index(model: Model) -> int:
    return model.index(model.spin_name)


def _run_scipy(scipy_method: str):
    def run(model: Model, y0, t_span, p, rtol, atol, t_eval, max_step):
        k = _spin_index(model)
        rhs = model.rhs

        def fun(t, y):
            return rhs(t, y, p)

        def reversal(t, y):
            return y[k]

        sol = solve_ivp(
            fun, t_span, y0, method=scipy_method, rtol=rtol, atol=atol, t_eval=t_eval,
            events=reversal, max_step=max_step,
        )
        return sol.t, sol.y, np.asarray(sol.t_events[0]), sol.status, sol.message, sol.nfev

    return run


for _m in SCIPY_METHODS:
    METHODS[f"scipy:{_m}"] = _run_scipy(_m)
    METHODS[_m] = METHODS[f"scipy:{_m}"]


def _check_t_span(t_span) -> tuple:
    try:
        t0, t1 = (float(v) for v in t_span)
    except (TypeError, ValueError):
        raise TypeError(f"`t_span` must be a pair (t0, t1) of numbers, got {t_span!r}") from None
    if not (math.isfinite(t0) and math.isfinite(t1)):
        raise ValueError(f"`t_span` must be finite, got {t_span!r}")
    if not t1 > t0:
        raise ValueError(f"`t_span` must satisfy t1 > t0 (forward, non-empty), got {t_span!r}")
    return t0, t1


def _check_tol(v, name: str) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)):
        raise TypeError(f"`{name}` must be a positive number, got {v!r}")
    v = float(v)
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"`{name}` must be positive and finite, got {v!r}")
    return v


def simulate(
    model: Model,
    y0,
    t_span,
    p,
    method: str = "DOP853",
    rtol: float = 1e-10,
    atol: float = 1e-12,
    t_eval=None,
    max_step: float = math.inf,
) -> SimulationResult:
    """Integrate ``model`` from ``y0`` over ``t_span`` with parameters ``p``.

    Parameters
    ----------
    model : Model from :func:`knifeedge.load`.
    y0 : array of shape (n_state,) or mapping of state names to values.
    t_span : (t0, t1) with t1 > t0, in units of the parameters' time.
    p : parameter array (from ``model.params``) or mapping of names to values.
    method : one of :data:`METHODS` (``"scipy:DOP853"`` etc.).
    rtol, atol : positive tolerances.
    t_eval : optional times at which to store the solution.
    max_step : largest step (default unbounded).

    Returns
    -------
    SimulationResult
    """
    if not isinstance(model, Model):
        raise TypeError(f"`model` must be a knifeedge Model (from knifeedge.load), got {type(model).__name__}")
    if not isinstance(method, str) or method not in METHODS:
        raise ValueError(f"unknown `method` {method!r}; accepted: {', '.join(sorted(METHODS))}")
    y0 = model.check_state(y0)
    p = model.check_params(p)
    t0, t1 = _check_t_span(t_span)
    rtol, atol = _check_tol(rtol, "rtol"), _check_tol(atol, "atol")
    if t_eval is not None:
        t_eval = np.asarray(t_eval, dtype=float)
        if t_eval.ndim != 1 or not np.all(np.isfinite(t_eval)) or np.any(np.diff(t_eval) <= 0) \
                or (t_eval.size and (t_eval[0] < t0 or t_eval[-1] > t1)):
            raise ValueError("`t_eval` must be a finite, strictly increasing 1-D array inside `t_span`")
    max_step = _check_tol(max_step, "max_step") if max_step != math.inf else math.inf

    t, y, rev, status, message, nfev = METHODS[method](model, y0, (t0, t1), p, rtol, atol, t_eval, max_step)
    t, y = np.asarray(t), np.asarray(y)
    finite = np.all(np.isfinite(y), axis=0)
    if not np.all(finite):
        bad = int(np.argmin(finite))
        t, y = t[:bad], y[:, :bad]
        rev = rev[rev <= (t[-1] if t.size else t0)]
        status, message = -3, f"The state became non-finite near t = {t[-1] if t.size else t0:.6g}; the step was rejected."
    return SimulationResult(
        t=t, y=y, state_names=model.state_names, reversal_times=np.asarray(rev, dtype=float),
        success=status >= 0, status=int(status), message=str(message), nfev=int(nfev), method=method,
        model=model, p=p,
    )
