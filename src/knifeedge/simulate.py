"""``simulate``: integrate a model and locate its spin reversals.

The integration methods are looked up in :data:`METHODS`: the compiled
methods of :mod:`knifeedge.integrators` under their plain names (``"DOP853"``,
``"DP54"`` alias ``"RK45"``, ``"RK4"``, ``"implicit_midpoint"``,
``"gauss4"``, ``"gauss6"``) and SciPy's ``solve_ivp`` under ``"scipy:NAME"``.
Every method returns the same :class:`SimulationResult`.  Inputs are
validated before any work (``ValueError``/``TypeError`` naming the
argument); a failed integration is reported in ``success``/``status``/
``message``/``outcome`` and its arrays stop at the last good step.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from . import _validate
from .integrators import ALIASES, COMPILED_METHODS, Status, from_code, kernel
from .models import Model, ValidityWarning

#: the smallest relative tolerance accepted: below it the error estimate is round-off
MIN_RTOL = 100 * np.finfo(float).eps
#: tolerances must be below one: an error the size of the state controls nothing
MAX_TOL = 1.0
#: most output times `t_eval` may hold (8 MB per state)
MAX_T_EVAL = 10_000_000
MAX_STEPS_LIMIT = 2**63 - 1
ERROR_CONTROLS = ("component", "mode")


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
        Spin reversals: zero crossings of the model's spin rate
        (``model.spin_name``), located on the solver's dense output.
    success : bool
    status : int
        0 reached the end of ``t_span``; negative values are failures
        (see :class:`knifeedge.integrators.Status`).
    message : str
    nfev : int
        Right-hand-side evaluations.
    method : str
    model : Model
    p : ndarray
    outcome : Status
        How the integration ended (its value is ``message``).
    nsteps : int
        Accepted steps.
    nrejected : int
        Rejected steps (adaptive methods).
    in_validity_domain : bool
        False when the run left the domain where the model's fidelity holds
        (``model.validity``); a :class:`~knifeedge.models.ValidityWarning`
        is then issued and ``validity_message`` says which states left it.
    validity_message : str
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
    outcome: Status = Status.SUCCESS
    nsteps: int = 0
    nrejected: int = 0
    in_validity_domain: bool = True
    validity_message: str = ""

    def __getitem__(self, name: str) -> np.ndarray:
        """Time series of the named state, e.g. ``r["phi_dot"]``."""
        return self.y[self.model.index(name)]

    @property
    def energy(self) -> np.ndarray:
        """Energy per unit mass along the trajectory."""
        return self.model.energy(self.y, self.p)


@dataclass(frozen=True)
class _Run:
    """Validated inputs handed to a runner."""

    model: Model
    y0: np.ndarray
    t0: float
    t1: float
    p: np.ndarray
    rtol: float
    atol: np.ndarray  # shape (n_state,)
    t_eval: np.ndarray | None
    max_step: float
    h: float | None
    max_steps: int
    error_control: str


SCIPY_METHODS = ("RK45", "DOP853", "LSODA", "Radau")
#: method name -> runner(run) -> (t, y, reversal_times, Status, nfev, nsteps, nrejected)
METHODS: dict = {}


_PAIRS: dict = {}


def _mode_pairs(model: Model) -> np.ndarray:
    """``pair[i]``: the partner of a coordinate and its rate (``model.rate_pairs``), else -1 (read-only)."""
    if model not in _PAIRS:
        pair = np.full(model.n_state, -1, dtype=np.int64)
        for name, rate in model.rate_pairs:
            if name in model.state_names and rate in model.state_names:
                i, j = model.index(name), model.index(rate)
                pair[i], pair[j] = j, i
        pair.flags.writeable = False
        _PAIRS[model] = pair
    return _PAIRS[model]


def _event_index(model: Model) -> int:
    """Index of the state whose zero crossings are the reversals (``model.reversal_events``), -1 if none."""
    return model.index(model.spin_name) if model.spin_name is not None else -1


def _run_compiled(name: str):
    spec = COMPILED_METHODS[ALIASES.get(name, name)]

    def run(r: _Run):
        solve = kernel(r.model, name)
        spin = _event_index(r.model)
        every = r.t_eval is None
        t_eval = np.empty(0) if every else np.ascontiguousarray(r.t_eval)
        if spec.fixed_step:
            out = solve(r.t0, r.t1, r.y0, r.p, r.h, r.atol, t_eval, every, spin, r.max_steps, _mode_pairs(r.model))
        else:
            out = solve(r.t0, r.t1, r.y0, r.p, r.rtol, r.atol, 0.0, r.max_step, t_eval, every, spin,
                        r.max_steps, _mode_pairs(r.model), r.error_control == "mode")
        ts, ys, ev, code, nfev, nacc, nrej = out
        return ts, ys.T, ev, from_code(code), nfev, nacc, nrej

    return run


def _run_scipy(scipy_method: str):
    """SciPy's ``OdeSolver`` stepped here, as ``solve_ivp`` does, so that ``max_steps`` is honoured.

    The output at ``t_eval`` and the spin reversals are found on the step's
    dense output exactly as ``solve_ivp`` does (``brentq`` to 4 machine
    epsilons); a step with a non-finite state ends the run.
    """
    def run(r: _Run):
        from scipy import integrate  # imported on use: it adds ~0.3 s to the start-up
        from scipy.optimize import brentq

        solver_class = getattr(integrate, scipy_method)
        k = _event_index(r.model)  # -1: the model has no reversal events
        rhs, p = r.model.rhs, r.p

        def fun(t, y):
            return rhs(t, y, p)

        solver = solver_class(fun, r.t0, r.y0, r.t1, rtol=r.rtol, atol=r.atol, max_step=r.max_step)
        every = r.t_eval is None
        ts, ys = ([r.t0], [r.y0.copy()]) if every else ([], [])
        i_eval = 0
        reversals = []
        g = r.y0[k] if k >= 0 else 0.0
        outcome = Status.SUCCESS
        nsteps = 0
        eps4 = 4 * np.finfo(float).eps
        while solver.status == "running":
            if nsteps >= r.max_steps:
                outcome = Status.MAX_STEPS
                break
            solver.step()
            if solver.status == "failed":
                outcome = Status.STEP_SIZE_UNDERFLOW
                break
            t_old, t, y = solver.t_old, solver.t, solver.y
            if not np.isfinite(y).all():
                outcome = Status.NON_FINITE
                break
            nsteps += 1
            sol = None
            g_new = y[k] if k >= 0 else 0.0
            if k >= 0 and ((g <= 0 <= g_new) or (g >= 0 >= g_new)):
                sol = solver.dense_output()
                reversals.append(brentq(lambda s: sol(s)[k], t_old, t, xtol=eps4, rtol=eps4))
            g = g_new
            if every:
                ts.append(t)
                ys.append(y.copy())
            else:
                i_new = int(np.searchsorted(r.t_eval, t, side="right"))
                if i_new > i_eval:
                    sol = sol or solver.dense_output()
                    step_t = r.t_eval[i_eval:i_new]
                    ts.append(step_t)
                    ys.append(sol(step_t).T)
                    i_eval = i_new
        n = r.model.n_state
        if every:
            t_out, y_out = np.array(ts), np.array(ys).T
        elif ts:
            t_out, y_out = np.concatenate(ts), np.concatenate(ys).T
        else:
            t_out, y_out = np.empty(0), np.empty((n, 0))
        return t_out, y_out.reshape(n, -1), np.array(reversals), outcome, solver.nfev, nsteps, 0

    return run


for _m in COMPILED_METHODS:
    METHODS[_m] = _run_compiled(_m)
for _alias in ALIASES:
    METHODS[_alias] = _run_compiled(_alias)
for _m in SCIPY_METHODS:
    METHODS[f"scipy:{_m}"] = _run_scipy(_m)


def _check_t_span(t_span) -> tuple:
    if isinstance(t_span, (str, bytes)) or not hasattr(t_span, "__len__") or len(t_span) != 2:
        raise TypeError(f"`t_span` must be a pair (t0, t1) of numbers, got {t_span!r}")
    t0, t1 = (_validate.real(v, "each end of `t_span`") for v in t_span)
    if not (math.isfinite(t0) and math.isfinite(t1)):
        raise ValueError(f"`t_span` must be finite, got {t_span!r}")
    if not t1 > t0:
        raise ValueError(f"`t_span` must satisfy t1 > t0 (forward, non-empty), got {t_span!r}")
    return t0, t1


def _check_positive(v, name: str) -> float:
    v = _validate.real(v, f"`{name}`")
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"`{name}` must be positive and finite, got {v!r}")
    return v


def _check_rtol(rtol) -> float:
    rtol = _check_positive(rtol, "rtol")
    if rtol < MIN_RTOL:
        raise ValueError(f"`rtol` must be at least {MIN_RTOL:.3g} (100 machine epsilons): below it round-off "
                         f"dominates the error estimate; got {rtol!r}")
    if rtol >= MAX_TOL:
        raise ValueError(f"`rtol` must be less than {MAX_TOL:g}: a relative error of {rtol!r} or more leaves no "
                         f"significant digit and the step-size control nothing to control")
    return rtol


def _check_atol(atol, n: int) -> np.ndarray:
    if type(atol) is float and 0 < atol < MAX_TOL:  # the common case, without numpy's overhead
        return np.full(n, atol)
    if isinstance(atol, (list, tuple)) or isinstance(atol, np.ndarray) and atol.ndim > 0:
        arr = _validate.real_array(atol, "`atol`")
    else:
        arr = np.full(n, _validate.real(atol, "`atol`"))
    if arr.shape != (n,):
        raise ValueError(f"`atol` must be a number or have shape ({n},) (one per state), got shape {arr.shape}")
    if not all(math.isfinite(v) and v > 0 for v in arr.tolist()):
        raise ValueError(f"`atol` must be positive and finite, got {atol!r}")
    if not all(v < MAX_TOL for v in arr.tolist()):
        raise ValueError(f"`atol` must be less than {MAX_TOL:g} (the states are angles in rad and rates in "
                         f"sqrt(g/ell): an absolute error of one or more leaves no significant digit); got {atol!r}")
    return np.ascontiguousarray(arr)


def _check_t_eval(t_eval, t0: float, t1: float) -> np.ndarray:
    arr = _validate.real_array(t_eval, "`t_eval`")
    if arr.ndim != 1:
        raise ValueError(f"`t_eval` must be a 1-D array of times, got shape {arr.shape}")
    if arr.size > MAX_T_EVAL:
        raise ValueError(f"`t_eval` has {arr.size} times, more than the {MAX_T_EVAL} allowed")
    if not np.isfinite(arr).all() or (arr[1:] <= arr[:-1]).any() or (arr.size and (arr[0] < t0 or arr[-1] > t1)):
        raise ValueError("`t_eval` must be a finite, strictly increasing 1-D array inside `t_span`")
    return arr


def _check_max_step(v) -> float:
    v = _validate.real(v, "`max_step`")
    if v == math.inf:
        return v
    return _check_positive(v, "max_step")


def _check_max_steps(v) -> int:
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)):
        raise TypeError(f"`max_steps` must be a positive integer, got {v!r}")
    if v < 1:
        raise ValueError(f"`max_steps` must be a positive integer, got {v!r}")
    if v > MAX_STEPS_LIMIT:
        raise ValueError(f"`max_steps` must be at most 2**63 - 1 (a 64-bit step counter), got {v!r}")
    return int(v)


def _check_fixed_step(h, t0: float, t1: float) -> float:
    """A fixed step must advance t: at least 10 ulps of t (which also keeps the step count in 64 bits)."""
    h = _check_positive(h, "h")
    resolution = 10 * float(np.spacing(max(abs(t0), abs(t1))))
    if h <= resolution:
        raise ValueError(f"`h` = {h!r} is below the resolution of t over `t_span` ({resolution:.3g}, 10 ulps): "
                         f"the steps would not advance t")
    return h


def check_inputs(model: Model, y0, t_span, p, method: str = "DOP853", rtol: float = 1e-10, atol=1e-12, t_eval=None,
                 max_step: float = math.inf, *, h: float | None = None, max_steps: int = 1_000_000,
                 error_control: str = "component") -> _Run:
    """Validate the arguments of :func:`simulate` (same signature) without integrating.

    Raises the ``ValueError``/``TypeError`` that :func:`simulate` would, naming
    the argument; returns the validated inputs.  Sweeps call it for every
    run before any work.
    """
    if not isinstance(model, Model):
        raise TypeError(f"`model` must be a knifeedge Model (from knifeedge.load), got {type(model).__name__}")
    if not isinstance(method, str) or method not in METHODS:
        raise ValueError(f"unknown `method` {method!r}; accepted: {', '.join(sorted(METHODS))}")
    y0 = model.check_state(y0)
    p = model.check_params(p)
    t0, t1 = _check_t_span(t_span)
    rtol = _check_rtol(rtol)
    atol = _check_atol(atol, model.n_state)
    if t_eval is not None:
        t_eval = _check_t_eval(t_eval, t0, t1)
    max_step = math.inf if type(max_step) is float and max_step == math.inf else _check_max_step(max_step)
    max_steps = _check_max_steps(max_steps)
    spec = COMPILED_METHODS.get(ALIASES.get(method, method))
    fixed = spec is not None and spec.fixed_step
    if fixed and h is None:
        raise ValueError(f"method {method!r} has a fixed step: pass the step `h`")
    if not fixed and h is not None:
        raise ValueError(f"`h` is the step of a fixed-step method; {method!r} chooses its own steps (use `rtol`)")
    if h is not None:
        h = _check_fixed_step(h, t0, t1)
    if error_control not in ERROR_CONTROLS:
        raise ValueError(f"unknown `error_control` {error_control!r}; accepted: {', '.join(ERROR_CONTROLS)}")
    if error_control != "component" and (spec is None or fixed):
        raise ValueError(f"`error_control={error_control!r}` needs a compiled adaptive method, not {method!r}")

    return _Run(model, y0, t0, t1, p, rtol, atol, t_eval, max_step, h, max_steps, error_control)


def simulate(
    model: Model,
    y0,
    t_span,
    p,
    method: str = "DOP853",
    rtol: float = 1e-10,
    atol=1e-12,
    t_eval=None,
    max_step: float = math.inf,
    *,
    h: float | None = None,
    max_steps: int = 1_000_000,
    error_control: str = "component",
) -> SimulationResult:
    """Integrate ``model`` from ``y0`` over ``t_span`` with parameters ``p``.

    Parameters
    ----------
    model : Model from :func:`knifeedge.load`.
    y0 : array of shape (n_state,) or mapping of state names to values.
    t_span : (t0, t1) with t1 > t0, in units of the parameters' time.
    p : parameter array (from ``model.params``) or mapping of names to values.
    method : one of :data:`METHODS`.  Adaptive compiled: ``"DOP853"``
        (default), ``"DP54"`` (alias ``"RK45"``); fixed step (need ``h``):
        ``"RK4"``, ``"implicit_midpoint"``, ``"gauss4"``, ``"gauss6"``;
        SciPy: ``"scipy:RK45"``, ``"scipy:DOP853"``, ``"scipy:LSODA"``,
        ``"scipy:Radau"``.
    rtol : relative tolerance, at least ``MIN_RTOL`` (100 machine epsilons).
    atol : absolute tolerance, a number or one per state (shape (n_state,)).
        For the Gauss methods it is the floor of the scale of the stage
        solver's convergence test.
    t_eval : optional increasing times in ``t_span`` at which to store the
        solution (interpolated); by default every step is stored.
    max_step : largest step of an adaptive method (default unbounded).
    h : step of a fixed-step method (required for them, refused by the
        others); the run uses ``(t1 - t0) / ceil((t1 - t0) / h)``.
    max_steps : accepted steps allowed before the run stops with
        ``Status.MAX_STEPS`` (every method, SciPy's too).
    error_control : ``"component"`` -- each state on its own magnitude (as
        SciPy); ``"mode"`` -- a tilt and its rate share the larger of their
        magnitudes, so a small oscillation mode is controlled relative to
        its amplitude (use with a small ``atol``).  Compiled adaptive methods.

    Returns
    -------
    SimulationResult
    """
    run = check_inputs(model, y0, t_span, p, method, rtol, atol, t_eval, max_step, h=h, max_steps=max_steps,
                       error_control=error_control)
    model, t0, p = run.model, run.t0, run.p
    t, y, rev, outcome, nfev, nsteps, nrej = METHODS[method](run)
    t, y = np.asarray(t), np.asarray(y)
    if not np.isfinite(y).all():  # SciPy methods accept non-finite states; cut them off and say so
        bad = int(np.argmin(np.isfinite(y).all(axis=0)))
        t, y = t[:bad], y[:, :bad]
        rev = rev[rev <= (t[-1] if t.size else t0)]
        outcome = Status.NON_FINITE
    message = outcome.value
    if outcome is Status.NON_FINITE and t.size:
        message = f"{message} Last good state at t = {t[-1]:.6g}."
    excess = model.validity_excess(y) if model.validity else {}
    validity_message = ""
    if excess:
        validity_message = _validity_message(model, excess)
        warnings.warn(validity_message, ValidityWarning, stacklevel=2)
    return SimulationResult(
        t=t, y=y, state_names=model.state_names, reversal_times=np.asarray(rev, dtype=float),
        success=outcome.success, status=outcome.code, message=message, nfev=int(nfev), method=method,
        model=model, p=p, outcome=outcome, nsteps=int(nsteps), nrejected=int(nrej),
        in_validity_domain=not excess, validity_message=validity_message,
    )


def _validity_message(model: Model, excess: dict) -> str:
    """Which states left the domain of the fidelity, by how much, and what to use instead."""
    parts = ", ".join(f"|{n}| reached {v:.3g} > {model.validity[n]:g}" for n, v in excess.items())
    return (f"the run left the domain where {model.name} at fidelity {model.fidelity!r} holds ({parts}; "
            f"{model.validity_doc or 'see model.validity'}); its results there are not those of the full model: "
            f"use fidelity 'full'")
