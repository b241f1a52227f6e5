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

import copy
import math
import threading
import types
import warnings
import dataclasses
from dataclasses import dataclass, field

import numpy as np
from numba import njit

from . import _validate
from . import inputs as _inputs
from .integrators import (ALIASES, COMPILED_METHODS, EVENTS_PER_STEP, Status, compile_mode,
                          from_code, kernel, kernel_compiled)
from .integrators.cache import call_repairing
from .integrators.compiler import compile_mode_set
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
        Reversals: zero crossings of the states or event functions the model
        declares as its reversal events (the spin rate of the knife edges),
        in increasing order, located on the solver's dense output.
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
    events : dict of str to ndarray
        Zero crossings of each event (a state or an event function of the
        model): the model's reversal events and those asked for with
        ``simulate(..., events=...)``, each located on the solver's dense
        output (increasing times; several inside one step are all found).
    in_validity_domain : bool
        False when the run left the domain where the model's fidelity holds
        (``model.validity``); a :class:`~knifeedge.models.ValidityWarning`
        is then issued and ``validity_message`` says which states left it.
    validity_message : str
    inputs : knifeedge.inputs.Inputs or None
        The run's validated inputs (a model with ``input_names``); ``energy`` and the model's functions
        take them (``model.energy(r.y, r.p, r.t, inputs=r.inputs)``).
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
    events: dict = field(default_factory=dict)
    in_validity_domain: bool = True
    validity_message: str = ""
    inputs: object = field(default=None, repr=False)

    def __getitem__(self, name: str) -> np.ndarray:
        """Time series of the named state, e.g. ``r["phi_dot"]``."""
        return self.y[self.model.index(name)]

    @property
    def energy(self) -> np.ndarray:
        """Energy per unit mass along the trajectory."""
        return self.model.energy(self.y, self.p, self.t, inputs=self.inputs)

    @property
    def holonomic_residual(self) -> np.ndarray:
        """Values of the model's holonomic constraints along the trajectory, shape (n_holonomic, n_times)."""
        return self.model.holonomic_residual(self.y, self.p, self.t, inputs=self.inputs)


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
    events: tuple = ()
    inputs: object = None  # knifeedge.inputs.Inputs of a model with inputs


SCIPY_METHODS = ("RK45", "DOP853", "LSODA", "Radau", "BDF")
#: SciPy's methods that use a Jacobian: they receive the generated one (``Model.jacobian``)
SCIPY_IMPLICIT = ("LSODA", "Radau", "BDF")
#: method name -> runner(run) -> (t, y, {event name: times}, Status, nfev, nsteps, nrejected)
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


#: accepted steps per call of a compiled kernel: between calls Python answers Ctrl-C; the steps are the same
CHUNK_STEPS = 50_000
#: rows of the output buffer of a run that stores every step, until its first pause tells how fast it goes
ROWS_FIRST = 4096
#: most rows allocated ahead of the steps that fill them (fixed steps: their count is known beforehand)
ROWS_AHEAD = 1 << 20
#: room of the first call's event buffers (at least four steps' worth); it doubles when a call fills it
EVENTS_FIRST = 64
#: a run's buffer of rows up to this size (bytes) is kept for the next run of the same thread: memory the
#: system need not hand out (and fault in, page by page) again
ROWS_KEPT_BYTES = 1 << 22
_KEPT = threading.local()


def _rows_buffer(n: int, cap: int) -> tuple:
    """Buffers ``(times (c,), rows (c, n))`` with ``c >= cap``: the thread's kept ones if they are large enough
    (taken: a run interrupted by an exception does not give them back), else new ones."""
    kept = getattr(_KEPT, "rows", None)
    if kept is not None and kept[1].shape[1] == n and kept[0].size >= cap:
        _KEPT.rows = None
        return kept
    return np.empty(cap), np.empty((cap, n))


def _keep_rows(ts: np.ndarray, ys: np.ndarray) -> bool:
    """Keep the buffers for the thread's next run if they are small enough and larger than those it keeps;
    whether they were kept."""
    if ts.nbytes + ys.nbytes > ROWS_KEPT_BYTES:
        return False
    kept = getattr(_KEPT, "rows", None)
    if kept is not None and kept[0].size > ts.size:
        return False
    _KEPT.rows = (ts, ys)
    return True


def _grown(buf: np.ndarray, used: int, size: int) -> np.ndarray:
    """A buffer of ``size`` rows holding the first ``used`` rows of ``buf``."""
    new = np.empty((size,) + buf.shape[1:], dtype=buf.dtype)
    new[:used] = buf[:used]
    return new


def _rows_ahead(stored: int, t0: float, t: float, t1: float, most: int) -> int:
    """Rows of the next buffer of a run that stored ``stored`` rows from ``t0`` to ``t``: what its pace so far
    needs to reach ``t1`` with a quarter to spare, at least half the rows stored (a run that speeds up still
    needs few buffers), at most ``most - stored`` and the larger of ``ROWS_AHEAD`` and ``stored`` (a run that
    slows down allocates no more than twice what it stores), and at least one."""
    pace = (stored - 1) / (t - t0) if t > t0 else 0.0
    guess = pace * (t1 - t) * 1.25 + 64
    size = max(stored // 2 + 1, int(min(guess, 2.0**62)) if math.isfinite(guess) else 0)
    return max(1, min(most - stored, max(ROWS_AHEAD, stored), size))


def _assembled(parts: list, n: int) -> tuple:
    """``(times (m,), states (n, m) C-contiguous)`` from buffers ``(times (k,), rows (k, n))`` in order: the
    rows transposed in blocks that stay in the cache, straight into the result."""
    if len(parts) == 1:
        t_out, rows = parts[0]
        if rows.shape[0] <= 8192:
            return t_out, rows.T.copy()  # a copy even when rows.T is contiguous (one row): buffers are reused
    else:
        t_out = np.concatenate([ts for ts, _ in parts])
    y_out = np.empty((n, t_out.size))
    a = 0
    for _, rows in parts:
        for b in range(0, rows.shape[0], 8192):
            block = rows[b:b + 8192]
            y_out[:, a:a + block.shape[0]] = block.T
            a += block.shape[0]
    return t_out, y_out


def _reversal_names(model: Model) -> tuple:
    """The states or event functions whose zero crossings are the model's ``reversal_times`` (may be empty)."""
    names = getattr(model, "reversal_events", None)
    if names is None:
        mod = model.module
        names = getattr(mod, "REVERSAL_EVENTS", None)
        if names is None:
            names = (mod.SPIN_NAME,) if getattr(mod, "SPIN_NAME", None) else ()
    return tuple(names)


def _event_names(model: Model, events: tuple) -> tuple:
    """The reversal states, then the requested ``events`` not among them."""
    names = _reversal_names(model)
    return names + tuple(e for e in events if e not in names)


def _event_code(model: Model, name: str) -> int:
    """The kernels' number of event ``name``: a state's index, or ``-1 - j`` for event function ``j``."""
    if name in model.state_names:
        return model.index(name)
    return -1 - tuple(getattr(model, "event_names", ())).index(name)


def _split_events(names: tuple, ev_t: np.ndarray, ev_k: np.ndarray) -> dict:
    """``{name: increasing times}`` from event times ``ev_t`` of the events numbered ``ev_k``."""
    order = np.argsort(ev_t, kind="stable")
    ev_t, ev_k = ev_t[order], ev_k[order]
    return {name: ev_t[ev_k == k] for k, name in enumerate(names)}


def _run_compiled(name: str):
    """The runner of compiled method ``name``: ``run(r)`` steps its kernel chunk by chunk (:class:`_CompiledRun`).

    A SciPy twin steps the run meanwhile when the kernel compiles in the background (:func:`_while_compiling`).
    """
    spec = COMPILED_METHODS[ALIASES.get(name, name)]

    def run(r: _Run):
        c = _CompiledRun(r, spec, name)
        twin = SCIPY_TWINS.get(spec.name)
        if (twin and not spec.fixed_step and r.error_control == "component" and compile_mode() == "background"
                and not kernel_compiled(r.model, name)):
            ph = _while_compiling(r, spec, twin, c.names, c.events, c.pair)
            if ph.done:
                return _phase_result(ph, c.every, c.n)
            c.continue_from(ph)
        c.step_to_end()
        return c.result()

    return run


def _phase_result(ph: "_Phase", every: bool, n: int) -> tuple:
    """The result of a run that a SciPy phase took from start to end, as a compiled run returns it."""
    pt, py = (np.array(ph.ts), np.array(ph.ys).reshape(-1, n)) if every else _joined(ph.ts, ph.ys, n)
    found = {e: np.array(v, dtype=float) for e, v in ph.found.items()}
    return pt, np.ascontiguousarray(py.T), found, ph.outcome, ph.nfev, ph.nsteps, 0


def _call_kernel(solve, *args) -> tuple:
    """``solve(*args)`` (a damaged file of numba's cache read on the way discarded and compiled again,
    :func:`~knifeedge.integrators.cache.call_repairing`); a Ctrl-C that arrived while numba called back into
    Python is raised as the ``KeyboardInterrupt`` it is."""
    try:
        return call_repairing(solve, *args)
    except SystemError as exc:  # Ctrl-C that arrived while numba called back into Python
        cause = exc.__cause__
        while cause is not None and not isinstance(cause, KeyboardInterrupt):
            cause = cause.__cause__
        if cause is not None:
            raise KeyboardInterrupt from None
        raise


class _CompiledRun:
    """One run of the compiled kernel of a method: its output and event buffers, counters and current step.

    Each call of the kernel fills the rows of a buffer after those stored (a C-contiguous tail: the kernel's
    argument types stay those it was compiled for); a full buffer is followed by one sized from the pace of the
    run so far (nothing copied), and all are transposed into the result at the end.
    """

    def __init__(self, r: _Run, spec, name: str):
        model = r.model
        self.r, self.spec, self.name = r, spec, name
        self.solve = kernel(model, name)
        self.names = _event_names(model, r.events)
        self.events = np.array([_event_code(model, e) for e in self.names], dtype=np.int64)
        self.every = r.t_eval is None
        self.pair = _mode_pairs(model)
        self.n = model.n_state
        self.nfev = self.nacc = self.nrej = 0
        self.t, self.y, self.f, self.carry = r.t0, r.y0, r.y0, 0.0
        self.code = None
        self._start_rows()
        self._start_events()

    def _start_rows(self) -> None:
        """The first output buffer, holding the initial state (once per output time at the start)."""
        r, n, every = self.r, self.n, self.every
        if every:
            self.t_eval = np.empty(0)
            self.most = min(r.max_steps, 2**62) + 1  # the start and at most one row per accepted step
            cap = min(ROWS_FIRST, self.most)
            self.used = 1
        else:
            self.t_eval = np.ascontiguousarray(r.t_eval)
            cap = self.t_eval.size + 1  # every output time, and a spare row: a tail is never empty
            self.used = int(np.searchsorted(self.t_eval, r.t0, side="right"))  # times at the start: the initial state
        if self.spec.fixed_step:
            self.n_steps = math.ceil((r.t1 - r.t0) / r.h)
            self.h = (r.t1 - r.t0) / self.n_steps
            self.comp, self.Z = np.zeros(n), np.empty((4, n))  # 4 >= stages of every fixed method
            if every:  # the rows are known: n_steps + 1 (up to ROWS_AHEAD of them now)
                cap = min(self.n_steps + 1, self.most, ROWS_AHEAD)
        self.ts, self.ys = _rows_buffer(n, cap)
        self.full, self.stored = [], 0  # the full buffers, their rows
        if every:
            self.ts[0], self.ys[0] = r.t0, r.y0
        else:
            self.ts[:self.used], self.ys[:self.used] = self.t_eval[:self.used], r.y0

    def _start_events(self) -> None:
        """The event buffers, with room for several steps' crossings."""
        self.per_step = EVENTS_PER_STEP * self.events.size  # most crossings one step records
        room = max(EVENTS_FIRST, 4 * self.per_step)
        self.ev_t, self.ev_k = np.empty(room), np.empty(room, dtype=np.int64)
        self.n_ev = 0

    def continue_from(self, ph: "_Phase") -> None:
        """Take over the rows, crossings, counters and solver state of the SciPy phase ``ph`` that stepped the
        run while the kernel compiled."""
        n = self.n
        self.solve = kernel(self.r.model, self.name)
        if self.every:  # the phase's rows (the start included) come first; the buffer takes the kernel's
            self.full.append((np.array(ph.ts), np.array(ph.ys)))
            self.stored, self.used = len(ph.ts), 0
        else:
            pt, py = _joined(ph.ts, ph.ys, n)
            self.ts[:pt.size], self.ys[:pt.size] = pt, py
            self.used = pt.size
        pe_t = np.array([x for e in self.names for x in ph.found[e]], dtype=float)
        pe_k = np.array([k for k, e in enumerate(self.names) for _ in ph.found[e]], dtype=np.int64)
        per_step = self.per_step
        if pe_t.size + per_step > self.ev_t.size:
            self.ev_t = np.empty(2 * (pe_t.size + per_step))
            self.ev_k = np.empty(2 * (pe_t.size + per_step), dtype=np.int64)
        self.n_ev = pe_t.size
        self.ev_t[:self.n_ev], self.ev_k[:self.n_ev] = pe_t, pe_k
        self.nfev, self.nacc = ph.nfev, ph.nsteps
        sv = ph.solver
        self.t, self.y = float(sv.t), np.array(sv.y, dtype=float)
        self.f, self.carry = np.array(sv.f, dtype=float), float(sv.h_abs)

    def _kernel_args(self, left: int, chunk: int) -> tuple:
        """The kernel's arguments ``t0, t1, y0, f0, p, control, request`` (before the output tails), for at most
        ``chunk`` of ``left`` steps."""
        r = self.r
        request = (self.t_eval if self.every else self.t_eval[self.used:], self.every, self.events, left, chunk)
        if self.spec.fixed_step:
            control = (self.h, self.n_steps, int(self.carry), r.atol, self.pair, self.comp, self.Z)
            return r.t0, r.t1, self.y, self.f, r.p, control, request
        control = (r.rtol, r.atol, self.carry, r.max_step, self.pair, r.error_control == "mode")
        return self.t, r.t1, self.y, self.f, r.p, control, request

    def step_to_end(self) -> None:
        """Call the kernel chunk by chunk until it stops for a reason other than a pause (``code`` 1)."""
        while True:
            left = min(self.r.max_steps - self.nacc, 2**62)
            chunk = min(CHUNK_STEPS, left)
            tails = (self.ts[self.used:], self.ys[self.used:], self.ev_t[self.n_ev:], self.ev_k[self.n_ev:])
            n_out, n_new, code, nf, na, nr, self.t, self.y, self.f, self.carry = _call_kernel(
                self.solve, *self._kernel_args(left, chunk), tails)
            self.used, self.n_ev = self.used + n_out, self.n_ev + n_new
            self.nfev, self.nacc, self.nrej = self.nfev + nf, self.nacc + na, self.nrej + nr
            self.code = code
            if code != 1:
                return
            self._make_room()

    def _make_room(self) -> None:
        """After a pause: a new row buffer if the rows are full, the event buffers doubled if nearly full."""
        if self.every and self.used == self.ts.size:  # paused with the rows full: the next buffer
            self.full.append((self.ts, self.ys))
            self.stored += self.used
            size = _rows_ahead(self.stored, self.r.t0, self.t, self.r.t1, self.most)
            self.ts, self.ys, self.used = np.empty(size), np.empty((size, self.n)), 0
        if self.n_ev + self.per_step > self.ev_t.size:  # paused with the event buffers nearly full: double them
            self.ev_t = _grown(self.ev_t, self.n_ev, 2 * self.ev_t.size)
            self.ev_k = _grown(self.ev_k, self.n_ev, 2 * self.ev_k.size)

    def result(self) -> tuple:
        """``(t, y (n, m), events, status, nfev, nacc, nrej)``, the rows assembled from the buffers."""
        ts, ys, used = self.ts, self.ys, self.used
        t_out, y_out = _assembled(self.full + [(ts[:used], ys[:used])], self.n)
        # the largest buffer small enough is kept for the next run; the times are copied if it is theirs, or
        # if much of it is spare (a result keeps only what it shows)
        biggest = max(self.full + [(ts, ys)], key=lambda b: b[0].size)
        kept = _keep_rows(*biggest)
        if t_out.base is ts and ((kept and biggest[0] is ts) or 8 * (ts.size - used) > ts.size):
            t_out = t_out.copy()
        events_out = _split_events(self.names, self.ev_t[:self.n_ev], self.ev_k[:self.n_ev])
        return t_out, y_out, events_out, from_code(self.code), self.nfev, self.nacc, self.nrej


#: the SciPy solver with the tableau, initial step, error norm and step-size control of a compiled method
SCIPY_TWINS = {"DOP853": "DOP853", "DP54": "RK45"}


def _joined(ts: list, ys: list, n: int) -> tuple:
    """Output rows of a SciPy phase at ``t_eval`` as arrays of shapes (k,) and (k, n)."""
    if not ts:
        return np.empty(0), np.empty((0, n))
    return np.concatenate(ts), np.concatenate(ys)


def _python_functions(model: Model, p: np.ndarray) -> tuple:
    """``fun(t, y)`` and ``event_values(y)`` of ``model`` at ``p`` as plain Python (nothing to compile)."""
    mod = model.module
    rhs = (mod.rhs_pose_q_into if model.pose else mod.rhs_q_into).py_func
    q = mod.constants.py_func(p).tolist()
    n = model.n_state

    def fun(t, y):
        out = [0.0] * n
        rhs(t, y.tolist(), q, out)
        return np.array(out)

    ev = getattr(mod, "event_values", None)
    ev = ev.py_func if ev is not None else None
    return fun, (lambda y: ev(y, p)) if ev is not None else None


def _while_compiling(r: _Run, spec, twin: str, names: tuple, events: np.ndarray, pair: np.ndarray) -> "_Phase":
    """Step ``r`` with SciPy's ``twin`` of ``spec`` while another process compiles its kernel.

    The phase ends when the run does, or after the step during which the
    compiled kernel became ready (or its compiling process failed: the
    kernel then compiles here, at its first call).
    """
    import sys
    import time

    from .integrators import compiler, kernel_module, use_compiled
    from .integrators.cache import cache_dir

    model = r.model
    module = kernel_module(model, spec.name)
    n = model.n_state
    out = (np.empty(1), np.empty((1, n)), np.empty(1), np.empty(1, dtype=np.int64))
    probe = (r.t0, r.t1, r.y0, r.y0, r.p, (r.rtol, r.atol, 0.0, r.max_step, pair, False),
             (np.empty(0), True, events, 1, 1), out)
    pending = compiler.start(model, spec.name, module, module.argument_types(probe))
    label = f"{spec.name} for {model.name} ({model.fidelity}{', pose' if model.pose else ''})"
    print(f"knifeedge: compiling {label} in a background process (once: it is then cached in {cache_dir()}); "
          f"meanwhile SciPy's {twin} (same steps) with a Python right-hand side runs", file=sys.stderr, flush=True)
    fun, event_values = _python_functions(model, r.p)
    t_start = time.perf_counter()
    ph = _scipy_phase(r, twin, fun, event_values, stop=lambda: pending.ready() or pending.failed())
    if ph.done:
        print(f"knifeedge: run done in {time.perf_counter() - t_start:.1f} s before the compiled {label} was "
              f"ready; the compiling goes on in the background", file=sys.stderr, flush=True)
    elif pending.ready():
        use_compiled(model, spec.name)
        print(f"knifeedge: compiled {label} ready after {time.perf_counter() - t_start:.1f} s; "
              f"the run continues in it at t = {ph.solver.t:.6g}", file=sys.stderr, flush=True)
    else:
        print(f"knifeedge: the background compiling of {label} failed; compiling it here. Its output:\n"
              f"{pending.log()}", file=sys.stderr, flush=True)
    return ph


class _Phase:
    """What :func:`_scipy_phase` did: its output rows, crossings and counters, and the solver it stopped."""

    def __init__(self, ts, ys, found, outcome, nfev, nsteps, solver, done):
        self.ts, self.ys, self.found, self.outcome = ts, ys, found, outcome
        self.nfev, self.nsteps, self.solver, self.done = nfev, nsteps, solver, done


def _scipy_phase(r: _Run, scipy_method: str, fun, event_values, stop=None, jac=None) -> _Phase:
    """Step SciPy's solver ``scipy_method`` from the start of ``r`` to its end, or until ``stop()`` is true.

    ``fun(t, y)``: the right-hand side; ``event_values(y)``: the model's
    event functions; ``jac(t, y)``: its Jacobian (implicit methods), or ``None``.  ``stop`` is asked about every 0.05 s of stepping; when
    it says yes the phase ends after a whole step, with ``done`` false.
    """
    import time

    from scipy import integrate  # imported on use: it adds ~0.3 s to the start-up

    solver_class = getattr(integrate, scipy_method)
    model = r.model
    names = _event_names(model, r.events)
    codes = [_event_code(model, e) for e in names]
    options = {"jac": jac} if jac is not None else {}
    solver = solver_class(fun, r.t0, r.y0, r.t1, rtol=r.rtol, atol=r.atol, max_step=r.max_step, **options)
    every = r.t_eval is None
    ts, ys = ([r.t0], [r.y0.copy()]) if every else ([], [])
    i_eval = 0
    outcome = Status.SUCCESS
    nsteps = 0
    crossings = _StepCrossings(names, codes, fun, event_values, solver, r.y0)
    next_ask = time.perf_counter() + 0.05
    done = True
    while solver.status == "running":
        if nsteps >= r.max_steps:
            outcome = Status.MAX_STEPS
            break
        if stop is not None and time.perf_counter() > next_ask:
            if stop():
                done = False
                break
            next_ask = time.perf_counter() + 0.05
        solver.step()
        if solver.status == "failed":
            outcome = Status.STEP_SIZE_UNDERFLOW
            break
        if not np.isfinite(solver.y).all():
            outcome = Status.NON_FINITE
            break
        nsteps += 1
        sol = crossings.after_step(solver)
        if every:
            ts.append(solver.t)
            ys.append(solver.y.copy())
        else:
            i_eval = _rows_at_t_eval(r.t_eval, solver, sol, i_eval, ts, ys)
    return _Phase(ts, ys, crossings.found, outcome, solver.nfev, nsteps, solver, done)


def _rows_at_t_eval(t_eval: np.ndarray, solver, sol, i_eval: int, ts: list, ys: list) -> int:
    """Append the output times of ``t_eval`` that the solver's last step passed, and the states there from its
    dense output (``sol`` if already made), to ``ts`` and ``ys``; the index of the next output time."""
    i_new = int(np.searchsorted(t_eval, solver.t, side="right"))
    if i_new > i_eval:
        sol = sol or solver.dense_output()
        step_t = t_eval[i_eval:i_new]
        ts.append(step_t)
        ys.append(sol(step_t).T)
        i_eval = i_new
    return i_eval


class _StepCrossings:
    """The zero crossings of the events of a SciPy phase, found step by step by the compiled kernels' rule.

    Each step is screened with the events' values and rates at its ends
    (``common.screen``, run by Python: nothing to compile); a suspected
    step is located on the dense output by the kernels' locator
    (``common.locator``, its ``py_func`` run by Python).  ``found``:
    ``{name: [times]}``.
    """

    def __init__(self, names: tuple, codes: list, fun, event_values, solver, y0: np.ndarray):
        from .integrators import common

        self.names, self.codes, self.fun, self.event_values = names, codes, fun, event_values
        self.screen = common.screen.py_func
        self.locate = common.locator(event_at=lambda step, x, c: self._at(step(x), c)).py_func
        self.events = np.array(codes, dtype=np.int64)
        self.xs, self.gs = np.empty(common.SAMPLES + 3), np.empty(common.SAMPLES + 3)
        self.ev_t = np.empty(len(codes) * common.EVENTS_PER_STEP)
        self.ev_k = np.empty(len(codes) * common.EVENTS_PER_STEP, dtype=np.int64)
        self.found = {e: [] for e in names}
        self.f_old = self._rate(solver) if codes else None
        # the screen's flags and Hermite extrema, as the kernels keep them
        self.crit = np.zeros((len(codes), 2))
        self.n_crit, self.flag = np.zeros(len(codes), dtype=np.int64), np.zeros(len(codes), dtype=np.int64)
        self.y_prev = y0.copy()

    def _rate(self, solver) -> np.ndarray:
        """The derivative at the solver's current point (RK methods keep it)."""
        f = getattr(solver, "f", None)
        return np.array(f if f is not None else self.fun(solver.t, solver.y), dtype=float)

    def _values(self, y, f, h) -> tuple:
        """Each event's value and rate times ``h`` at a state ``y`` with derivative ``f``."""
        codes, event_values = self.codes, self.event_values
        g, s = np.empty(len(codes)), np.empty(len(codes))
        fun_v = fun_w = None
        if any(c < 0 for c in codes):
            fun_v = event_values(y)
            fun_w = event_values(y + 1e-7 * h * f)
        for k, c in enumerate(codes):
            if c >= 0:
                g[k], s[k] = y[c], h * f[c]
            else:
                g[k], s[k] = fun_v[-1 - c], (fun_w[-1 - c] - fun_v[-1 - c]) / 1e-7
        return g, s

    def _at(self, y, c: int) -> float:
        """The value of the event numbered ``c`` at the state ``y``."""
        return y[c] if c >= 0 else self.event_values(y)[-1 - c]

    def after_step(self, solver):
        """Record the crossings inside the step the solver just took; its dense output if one was made, else
        ``None``."""
        sol = None
        if self.codes:
            t_old, t, y = solver.t_old, solver.t, solver.y
            h = t - t_old
            f_new = self._rate(solver)
            ga, sa = self._values(self.y_prev, self.f_old, h)
            gb, sb = self._values(y, f_new, h)
            if self.screen(ga, gb, sa, sb, self.crit, self.n_crit, self.flag):
                sol = solver.dense_output()
                marks = (ga, gb, self.crit, self.n_crit, self.flag, self.xs, self.gs)
                n = self.locate(self.events, lambda x: sol(t_old + x * h), t_old, h, marks, (self.ev_t, self.ev_k), 0)
                for i in range(n):
                    self.found[self.names[self.ev_k[i]]].append(float(self.ev_t[i]))
            self.f_old = f_new
        self.y_prev = solver.y.copy()
        return sol


def _scipy_jacobian(model: Model, p: np.ndarray, inputs=None):
    """``jac(t, y)`` for SciPy: the generated ``jacobian`` of the closed state; ``None`` with the pose (SciPy then
    differentiates numerically).  ``inputs``: a run's function inputs, their slots at every time."""
    if model.pose:
        return None
    jacobian = model.module.jacobian
    if inputs is not None:
        return lambda t, y: jacobian(y, inputs.parameters(p, t), t)
    if model.jacobian_needs_time:
        return lambda t, y: jacobian(y, p, t)
    return lambda t, y: jacobian(y, p)


def _run_scipy(scipy_method: str):
    """SciPy's ``OdeSolver`` stepped here, as ``solve_ivp`` does, so that ``max_steps`` is honoured.

    The output at ``t_eval`` is found on the step's dense output exactly as
    ``solve_ivp`` does; the zero crossings of the events (states or event
    functions) as in the compiled kernels: each step is screened with the
    event's values and rates at its ends, a suspected step is sampled on the
    dense output (two or more crossings inside one step included) by the
    kernels' locator (``common.locator``).  A step with a non-finite state
    ends the run.
    """
    def run(r: _Run):
        model, p = r.model, r.p
        rhs = model.rhs
        module_events = getattr(model.module, "event_values", None)
        jac = _scipy_jacobian(model, p) if scipy_method in SCIPY_IMPLICIT else None
        fun = lambda t, y: rhs(t, y, p)  # noqa: E731
        if r.inputs is not None:  # a function input (knifeedge/inputs.py): the slots at every time
            fun = lambda t, y: rhs(t, y, r.inputs.parameters(p, t))  # noqa: E731
            jac = _scipy_jacobian(model, p, r.inputs) if jac is not None else None
        ph = _scipy_phase(r, scipy_method, fun, lambda y: module_events(y, p), jac=jac)
        ts, ys, n = ph.ts, ph.ys, model.n_state
        if r.t_eval is None:
            t_out, y_out = np.array(ts), np.array(ys).T
        elif ts:
            t_out, y_out = np.concatenate(ts), np.concatenate(ys).T
        else:
            t_out, y_out = np.empty(0), np.empty((n, 0))
        events = {e: np.array(v, dtype=float) for e, v in ph.found.items()}
        return t_out, y_out.reshape(n, -1), events, ph.outcome, ph.nfev, ph.nsteps, 0

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


def _check_events(events, model: Model) -> tuple:
    if isinstance(events, str):
        events = (events,)
    try:
        events = tuple(events)
    except TypeError:
        raise TypeError(f"`events` must be a name or a sequence of names (states or event functions), "
                        f"got {events!r}") from None
    functions = tuple(getattr(model, "event_names", ()))
    for e in events:
        if not isinstance(e, str) or (e not in model.state_names and e not in functions):
            raise ValueError(f"`events` names unknown state or event function {e!r}; this model's states are "
                             f"{model.state_names}" + (f" and its event functions {functions}" if functions else ""))
    return tuple(dict.fromkeys(events))


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
                 error_control: str = "component", events=(), inputs=None) -> _Run:
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
    events = _check_events(events, model)
    inp = _inputs.check(model, inputs)
    if inp is not None:
        inp.cover(t0, t1)
        if spec is not None:
            _inputs.check_compiled(model, inp, method)
    return _Run(model, y0, t0, t1, p, rtol, atol, t_eval, max_step, h, max_steps, error_control, events, inp)


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
    events=(),
    inputs=None,
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
        ``"scipy:Radau"``, ``"scipy:BDF"`` (the implicit three receive the
        generated Jacobian, ``Model.jacobian``, unless ``pose``).
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
    events : names of states or of the model's event functions
        (``model.event_names``, scalar functions of the state) whose zero
        crossings to report in ``result.events`` (a name or a sequence of
        names), besides the model's reversal events, which are always
        reported.  Crossings are located on each step's dense output, two or
        more inside one step included: a step whose ends have the same sign
        is sampled when the cubic through the event's values and rates at
        its ends dips toward zero inside it (see
        ``knifeedge/integrators/blocks.py``).
    inputs : ``{name: value}`` for each of ``model.input_names`` (a model that declares ``inputs``): a
        number, samples ``(t_array, u_array)`` covering ``t_span`` (interpolated piecewise linearly: the run
        restarts at each sample time, exact for that input), or a function of ``t`` called at the true time
        (a ``numba.njit`` function on the compiled methods; any callable on the SciPy ones; ``(u, du_dt)``
        where the model reads the input's rate).  See :mod:`knifeedge.inputs`.

    Returns
    -------
    SimulationResult
    """
    run = check_inputs(model, y0, t_span, p, method, rtol, atol, t_eval, max_step, h=h, max_steps=max_steps,
                       error_control=error_control, events=events, inputs=inputs)
    model, t0, p = run.model, run.t0, run.p
    compiled = ALIASES.get(method, method) in COMPILED_METHODS
    if run.inputs is not None and run.inputs.has_function and compiled:  # its rhs calls them (inputs.driven)
        with compile_mode_set("wait"):  # no SciPy twin nor compiling process: they would not call them
            t, y, found, outcome, nfev, nsteps, nrej = _run_segments(
                METHODS[method], dataclasses.replace(run, model=driven_model(model, run.inputs)))
    elif run.inputs is not None and not run.inputs.has_function:  # numbers and samples: interval by interval
        t, y, found, outcome, nfev, nsteps, nrej = _run_segments(METHODS[method], run)
    else:
        t, y, found, outcome, nfev, nsteps, nrej = METHODS[method](run)
    t, y = np.asarray(t), np.asarray(y)
    if not np.isfinite(y).all():  # SciPy methods accept non-finite states; cut them off and say so
        bad = int(np.argmin(np.isfinite(y).all(axis=0)))
        t, y = t[:bad], y[:, :bad]
        last = t[-1] if t.size else t0
        found = {k: v[v <= last] for k, v in found.items()}
        outcome = Status.NON_FINITE
    message = outcome.value
    if outcome is Status.NON_FINITE and t.size:
        message = f"{message} Last good state at t = {t[-1]:.6g}."
    reversal = [found[k] for k in _reversal_names(model)]
    rev = np.sort(np.concatenate(reversal)) if len(reversal) > 1 else (reversal[0] if reversal else np.empty(0))
    excess = model.validity_excess(y) if model.validity else {}
    validity_message = ""
    if excess:
        validity_message = _validity_message(model, excess)
        warnings.warn(validity_message, ValidityWarning, stacklevel=2)
    return SimulationResult(
        t=t, y=y, state_names=model.state_names, reversal_times=rev,
        success=outcome.success, status=outcome.code, message=message, nfev=int(nfev), method=method,
        model=model, p=p, outcome=outcome, nsteps=int(nsteps), nrejected=int(nrej), events=found,
        in_validity_domain=not excess, validity_message=validity_message, inputs=run.inputs,
    )


def _validity_message(model: Model, excess: dict) -> str:
    """Which states left the domain of the fidelity, by how much, and what to use instead."""
    parts = ", ".join(f"|{n}| reached {v:.3g} > {model.validity[n]:g}" for n, v in excess.items())
    return (f"the run left the domain where {model.name} at fidelity {model.fidelity!r} holds ({parts}; "
            f"{model.validity_doc or 'see model.validity'}); its results there are not those of the full model: "
            f"use fidelity 'full'")


def _run_segments(runner, r):
    """Run ``r`` (a validated run whose ``inputs`` are numbers or samples) interval by interval.

    Each interval between consecutive :meth:`Inputs.breakpoints` is one run of ``runner`` (a method of
    ``simulate.METHODS``) with the slots of that interval appended to ``p``; its last state starts the next.
    Returns what a runner returns, ``(t, y, events, outcome, nfev, nsteps, nrejected)``, joined: every
    requested output time once (with ``t_eval``), or every step (without; the intervals' ends once).
    """
    inp = r.inputs
    cuts = inp.breakpoints(r.t0, r.t1)
    slots = np.concatenate([np.broadcast_to(r.p, (cuts.size - 1, r.p.size)), inp.slots(cuts[:-1])], axis=1)
    every = r.t_eval is None
    if not every:  # the requested times in (ta, tb] ([t0, tb] first)
        bounds = np.searchsorted(r.t_eval, cuts, side="right")
        bounds[0] = np.searchsorted(r.t_eval, r.t0, side="left")
    ts, ys, found = [], [], {}
    nfev = nsteps = nrej = 0
    y, outcome = r.y0, Status.SUCCESS
    for k in range(cuts.size - 1):
        ta, tb = float(cuts[k]), float(cuts[k + 1])
        if nsteps >= r.max_steps:
            outcome = Status.MAX_STEPS
            break
        t_eval, extra = None, False
        if not every:  # and tb, whose state starts the next interval
            t_eval = r.t_eval[bounds[k]:bounds[k + 1]]
            extra = not (t_eval.size and t_eval[-1] == tb)
            t_eval = np.concatenate([t_eval, [tb]]) if extra else t_eval
        seg = dataclasses.replace(r, y0=y, t0=ta, t1=tb, p=slots[k], t_eval=t_eval, max_steps=r.max_steps - nsteps,
                                  inputs=None)
        if k == 0:
            t, yy, fnd, outcome, nf, ns, nr = runner(seg)
        else:  # the kernel is compiled (or compiles) at the first interval; no second background phase
            with compile_mode_set("wait"):
                t, yy, fnd, outcome, nf, ns, nr = runner(seg)
        t, yy = np.asarray(t), np.asarray(yy)
        nfev, nsteps, nrej = nfev + nf, nsteps + ns, nrej + nr
        for name, v in fnd.items():
            found.setdefault(name, []).append(np.asarray(v))
        done = outcome.success and t.size and t[-1] == tb
        if done:
            y = yy[:, -1].copy()
        if done and extra:
            t, yy = t[:-1], yy[:, :-1]
        if every and k > 0 and t.size:
            t, yy = t[1:], yy[:, 1:]  # the interval's start is the previous one's end
        ts.append(t)
        ys.append(yy)
        if not done:
            break
    events = {name: np.concatenate(v) for name, v in found.items()}
    return np.concatenate(ts), np.concatenate(ys, axis=1), events, outcome, nfev, nsteps, nrej


#: the modules of :func:`driven_model`, by name (the model's module's and a hash of the functions) and module
_DRIVEN: dict = {}


def driven_model(model: Model, inp) -> Model:
    """``model`` whose compiled right-hand sides (``rhs_q_into``, ``rhs_pose_q_into``) first write each function
    input of ``inp`` (:class:`knifeedge.inputs.Inputs`) into its slots of ``q`` at the time ``t`` they are
    called at, then call the model's: what every compiled method runs for a function input.

    The slots of input ``u`` (value and rate ``q[NP + 1 + 2 i]``, ``q[NP + 2 + 2 i]``, read as ``value + rate
    (t - q[NP])``) get ``u(t) - r (t - q[NP])`` and ``r = du_dt(t)`` (``u(t)`` alone where the model does not
    read the rate), so that the model reads ``u(t)`` and ``du_dt(t)`` while the other inputs' slots (numbers,
    samples of the interval starting at ``q[NP]``) stay as they are.  The adaptive kernels take it through their
    path of a right-hand side without IR (:class:`~knifeedge.integrators.erk.AdaptiveKernel`), the fixed-step
    ones as their right-hand side; the kernel's cache name names the functions by their files' SHA-256
    (:mod:`knifeedge.integrators.cache`).  :func:`knifeedge.inputs.check_compiled` must have passed.
    """
    from .integrators.cache import digest

    module = model.module
    n_p = len(module.PARAM_NAMES)
    functions = inp.functions(n_p)
    name = f"{module.__name__}__inputs_{digest(functions)[:16]}"
    if (name, id(module)) not in _DRIVEN:
        ns = types.ModuleType(name)
        ns.__dict__.update({k: v for k, v in vars(module).items() if k != "__name__"})
        ns.LLVM_IR = {k: v for k, v in getattr(module, "LLVM_IR", {}).items() if not k.startswith("rhs")}
        for rhs_name in ("rhs_q_into", "rhs_pose_q_into"):
            if hasattr(module, rhs_name):
                rhs = getattr(module, rhs_name)
                for slot, f, df in functions:
                    rhs = _writing(rhs, slot, n_p, f, df)
                setattr(ns, rhs_name, rhs)
        _DRIVEN[(name, id(module))] = (ns, module)
    out = copy.copy(model)
    out.module = _DRIVEN[(name, id(module))][0]
    return out


def _writing(rhs, SLOT: int, T0: int, f, df):
    """``rhs(t, s, q, ds)`` after writing the input ``f`` (and its rate ``df``, or none) into ``q[SLOT]``,
    ``q[SLOT + 1]`` (see :func:`driven_model`)."""
    if df is None:
        def rhs_with_input(t, s, q, ds):
            q[SLOT] = f(t)
            rhs(t, s, q, ds)
    else:
        def rhs_with_input(t, s, q, ds):
            r = df(t)
            q[SLOT] = f(t) - r * (t - q[T0])
            q[SLOT + 1] = r
            rhs(t, s, q, ds)
    return njit(error_model="numpy")(rhs_with_input)
