"""Adaptive embedded explicit Runge--Kutta integrator for any registered tableau (DOP853, DP54, Tsit5, ...).

SciPy's ``solve_ivp`` algorithm (``DOP853``, ``RK45``): initial step (Hairer, Norsett & Wanner I, Sect. II.4),
error norm ``scale_i = atol_i + rtol * max(|y_i|, |y_new_i|)`` (``mode_scaled``: the magnitude of a component is
the larger of itself and its partner ``pair[i]``) and controller (safety 0.9, factors in [0.2, 10], no increase
right after a rejection), so the two agree step for step up to round-off.  :func:`driver` serves every model;
a model's parts (:class:`AdaptiveKernel`) are called through their addresses (docs/integrators.md, "How the
compiled methods are built").
"""
from __future__ import annotations

import numpy as np
from numba import carray, njit, types

from . import common as _c
from . import fnptr as _fnptr
from . import irparts as _irparts
from .methods import erk_arrays
from .cache import cache_dir, compiled, compiled_cfunc, digest, is_cached
from .common import _EPS, EVENTS_PER_STEP, NEAR, step_factor
from .fnptr import call_f8, call_void

_DRIVERS: dict = {}


def driver(tableau: str):
    """The compiled integrator of the registered tableau ``tableau`` (one per method, every model):
    ``solve(fns, t0, t1, y0, f0, q, p, control, request, out)`` integrates from ``t0`` toward ``t1 > t0``, at most
    ``chunk`` accepted steps, as many as the buffers hold.

    Parameters
    ----------
    fns : (5,) int64: the addresses of the model's parts ``rhs``, ``attempt``, ``dense``, ``events`` (see
        :class:`AdaptiveKernel`) and the number of its event functions.
    y0 : (n,) initial state; f0 : (n,) its derivative when continuing (``h_init > 0``), else ignored.
    q : ``constants(p)`` of the right-hand side; p : the parameters (of the event functions).
    control : ``(rtol, atol, h_init, max_step, pair, mode_scaled)``, the step control: ``rtol`` float, ``atol``
        (n,) absolute tolerances; ``h_init`` the next step when continuing a run, or 0 to start one (the first
        step is then chosen); ``max_step`` the largest step; ``pair`` (n,) int, the partner component for
        ``mode_scaled`` error control (-1: none).
    request : ``(t_eval, every, events, max_steps, chunk)``, what to record and for how long (the same for
        every kernel): ``t_eval`` (m,) increasing output times in (t0, t1] still ahead (used when not
        ``every``); ``every``: store every accepted step instead (the start is not stored); ``events`` (e,)
        int, whose zero crossings are recorded: a state component ``c >= 0``, or ``-1 - j`` for the model's
        event function ``j`` (``event_values(s, p)[j]``), see :mod:`.common`; ``max_steps`` accepted steps
        allowed (the caller subtracts those already taken); ``chunk`` accepted steps after which the call
        returns with status 1 (paused).
    out : ``(ts, ys, ev_t, ev_k)``, the buffers filled (the same for every kernel): ``ts`` (r,), ``ys`` (r, n)
        output rows (with ``every``, the call pauses when they are full; otherwise they must hold
        ``t_eval``); ``ev_t`` (c,), ``ev_k`` (c,) int event times and numbers (the call pauses when a step
        could overflow them: a step finds at most ``EVENTS_PER_STEP`` crossings of each event).

    A paused run continues from the returned ``t, y, f, h_next`` (passed as ``t0, y0, f0, h_init``)
    with the steps, evaluations and results of one uninterrupted call.

    Returns
    -------
    n_out, n_ev, status, nfev, accepted, rejected, t, y, f, h_next
    """
    if tableau not in _DRIVERS:
        _DRIVERS[tableau] = compiled(_driver_closure(tableau), f"erk-{tableau}")
    return _DRIVERS[tableau]


def _values_(s, p, ev):
    """The model's event functions at ``s`` (``ev``: the address of its ``events`` part and their number)."""
    out = np.empty(ev[1])
    call_void(ev[0], (s, p, np.int64(p.size), out))
    return out


def _initial_step_closure(ERROR_ORDER: int):
    def initial_step(rhs, t0, t1, y, y_new, f0, K, q, nq, rtol, atol, h_init, max_step):
        """The first step and the right-hand-side evaluations it took: ``h_init`` and ``K[0] = f0`` when a run
        continues (``h_init > 0``), else Hairer, Norsett & Wanner I, Sect. II.4 (as SciPy's
        select_initial_step)."""
        N = y.size
        if h_init > 0.0:
            for i in range(N):
                K[0, i] = f0[i]
            return h_init, 0
        call_void(rhs, (t0, y, q, nq, K[0]))
        d0 = 0.0
        d1 = 0.0
        for i in range(N):
            sc = atol[i] + abs(y[i]) * rtol
            d0 += (y[i] / sc) * (y[i] / sc)
            d1 += (K[0, i] / sc) * (K[0, i] / sc)
        d0 = np.sqrt(d0 / N)
        d1 = np.sqrt(d1 / N)
        h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
        h0 = min(h0, t1 - t0)
        h_abs = 0.0
        if h0 > 0.0:  # else the derivative overflows the scale: start at the smallest step
            for i in range(N):
                y_new[i] = y[i] + h0 * K[0, i]
            call_void(rhs, (t0 + h0, y_new, q, nq, K[1]))
            d2 = 0.0
            for i in range(N):
                sc = atol[i] + abs(y[i]) * rtol
                d2 += ((K[1, i] - K[0, i]) / sc) * ((K[1, i] - K[0, i]) / sc)
            d2 = np.sqrt(d2 / N) / h0
            if d1 <= 1e-15 and d2 <= 1e-15:
                h1 = max(1e-6, h0 * 1e-3)
            else:
                h1 = (0.01 / max(d1, d2)) ** (1.0 / (ERROR_ORDER + 1))
            h_abs = min(100 * h0, h1, t1 - t0, max_step)
        return h_abs, 2

    return njit(error_model="numpy")(initial_step)


def _workspace_closure(rows: dict):
    """``workspace(y0, q)``: the integrator's one array laid out as ``erk_arrays(...).rows`` says (the parts take
    their arrays at fixed offsets of one pointer, so the compiler can tell them apart), y and q filled in; returns
    it and its views ``K`` (the rows before ``y``), ``y, y_new, work, F``."""
    Y, Y_NEW, WORK, F, Q = rows["y"], rows["y_new"], rows["work"], rows["F"], rows["q"]

    def workspace(y0, q):
        N = y0.size
        ws = np.empty(Q * N + q.size)
        qw = ws[Q * N:]
        for i in range(q.size):
            qw[i] = q[i]
        y = ws[Y * N:(Y + 1) * N]
        for i in range(N):
            y[i] = y0[i]
        return (ws, ws[:Y * N].reshape((Y, N)), y, ws[Y_NEW * N:(Y_NEW + 1) * N], ws[WORK * N:(WORK + 1) * N],
                ws[F * N:Q * N].reshape((Q - F, N)))

    return njit(inline="always", error_model="numpy")(workspace)


def _driver_closure(tableau: str):
    """The integrator of ``tableau`` as a Python closure over its sizes and helpers."""
    tab = erk_arrays(tableau)
    N_STAGES, N_EXT, ALT, ERROR_ORDER = tab.n_stages, tab.n_ext, tab.alt, tab.error_order
    DENSE_NFEV = N_EXT - N_STAGES - 1  # evaluations of the interpolant beyond the step's (DOP853: 3)
    values = njit(error_model="numpy")(_values_)
    function_ends, locate = _c.function_ends(values), _c.locator(values)
    initial_step, workspace = _initial_step_closure(ERROR_ORDER), _workspace_closure(tab.rows)
    ERROR_EXPONENT = -1.0 / (ERROR_ORDER + 1)
    EIGHTH = ERROR_ORDER == 7  # err ** (-1/8) as three square roots, cheaper than pow (DOP853)

    def solve(fns, t0, t1, y0, f0, q, p, control, request, out):
        """Integrate from ``t0`` toward ``t1 > t0`` (:func:`driver` says the arguments and returns)."""
        rtol, atol, h_init, max_step, pair, mode_scaled = control
        t_eval, every, events, max_steps, chunk = request
        ts, ys, ev_t, ev_k = out
        N = y0.size
        rhs, attempt, dense, ev = fns[0], fns[1], fns[2], fns[3:5]
        ms, n, nq = np.int64(1 if mode_scaled else 0), np.int64(N), np.int64(q.size)
        ws, K, y, y_new, work, F = workspace(y0, q)
        fa, fb = K[0], K[N_STAGES]  # the derivatives at the ends of a step (views of the first and last stages)
        ne, n_fun, ga, gb, sa, sb, crit, n_crit, flag, xs, gs = _c.alloc(events)
        # counters start as int64, not as the literal 0 (numba would type them twice)
        n_out, ie, n_ev, nfev = np.int64(0), np.int64(0), np.int64(0), np.int64(0)
        t = t0
        h_abs, calls = initial_step(rhs, t0, t1, y, y_new, f0, K, q, nq, rtol, atol, h_init, max_step)
        nfev += calls
        status, n_acc, n_rej = 0, 0, 0
        while t < t1:
            if n_acc >= max_steps:
                status = -2
                break
            if n_acc >= chunk or (every and n_out == ts.size) or n_ev + ne * EVENTS_PER_STEP > ev_t.size:
                status = 1
                break
            # the attempts of a step, the events' screen, their crossings and the output, written out (common.py
            # says what they do: as calls, inlined or not, they cost the kernels 1.5-4x per evaluation)
            # SciPy's smallest step is 10 ulps of t; nextafter is called only near it (10 ulps <= 10 eps |t|)
            near = 10.0 * _EPS * abs(t) + 1e-300
            if h_abs > max_step:
                h_abs = max_step
            elif h_abs < near and h_abs < 10.0 * abs(np.nextafter(t, np.inf) - t):
                h_abs = 10.0 * abs(np.nextafter(t, np.inf) - t)
            rejected = False
            while True:
                if h_abs < near and h_abs < 10.0 * abs(np.nextafter(t, np.inf) - t):
                    status = -1
                    break
                t_new = t + h_abs
                if t_new > t1:
                    t_new = t1
                h = t_new - t
                h_abs = abs(h)
                # the stages, y_new, K[N_STAGES] and the scaled error norm: the model's part
                err = call_f8(attempt, (t, h, t_new, rtol, ms, ws, n, nq, atol, pair))
                nfev += N_STAGES
                factor = step_factor(err, ERROR_EXPONENT, EIGHTH)
                if err < 1.0:
                    h_abs *= min(1.0, factor) if rejected else factor
                    break
                h_abs *= factor
                rejected = True
                n_rej += 1
            if status != 0:
                break
            n_acc += 1
            any_flag = False
            if ne > 0:
                for k in range(ne):
                    c = events[k]
                    if c >= 0:
                        ga[k], gb[k], sa[k], sb[k] = y[c], y_new[c], h * fa[c], h * fb[c]
                if n_fun > 0:
                    function_ends(events, y, y_new, fa, fb, h, p, ev, work, ga, gb, sa, sb)
                suspect = False  # whether the screen may flag any event (the bound of common.py)
                for k in range(ne):
                    g0, g1 = ga[k], gb[k]
                    if g0 == 0.0 or g1 == 0.0 or (g0 > 0.0) != (g1 > 0.0):
                        suspect = True
                    else:
                        d = g1 - g0
                        dev = 0.25 * max(abs(sa[k] - d), abs(sb[k] - d))
                        if min(abs(g0), abs(g1)) - dev <= NEAR * max(abs(g0), abs(g1)):
                            suspect = True
                if suspect:
                    any_flag = _c.screen(ga, gb, sa, sb, crit, n_crit, flag)
            if any_flag or (ie < t_eval.size and t_eval[ie] < t_new):
                call_void(dense, (t, h, ws, n, nq))  # the interpolant of the step: F (tab.dense_rows x N)
                nfev += DENSE_NFEV
            if any_flag:
                marks = (ga, gb, crit, n_crit, flag, xs, gs)
                n_ev = locate(events, (F, y, ALT, p, ev, work), t, h, marks, (ev_t, ev_k), n_ev)
            if every:  # the common case: a row per step
                ts[n_out] = t_new
                for i in range(N):
                    ys[n_out, i] = y_new[i]
                n_out += 1
            while not every and ie < t_eval.size and t_eval[ie] <= t_new:
                te = t_eval[ie]
                ts[n_out] = te
                x = (te - t) / h
                for i in range(N):
                    ys[n_out, i] = y_new[i] if te == t_new else _c.interpolate(F, y, ALT, x, i)
                n_out += 1
                ie += 1
            for i in range(N):
                y[i] = y_new[i]
                K[0, i] = K[N_STAGES, i]
            t = t_new
        return n_out, n_ev, status, nfev, n_acc, n_rej, t, y, K[0].copy(), h_abs

    return solve


_F8, _I8, _D = types.float64, types.int64, types.CPointer(types.float64)
RHS_SIG = types.void(_F8, _D, _D, _I8, _D)
EVENTS_SIG = types.void(_D, _D, _I8, _D)


class AdaptiveKernel:
    """A model's parts of the integrator of ``tableau`` and :meth:`solve`, the integrator run with them.

    The parts: ``attempt`` (the stages of a step with the error norm) and ``dense`` (the interpolant), the IR of
    ``generated/stages.py`` bound to the model's right-hand side (:mod:`.irparts`); the C-callable ``rhs``; the
    event functions (a ``numba.cfunc``; address 0, never called, for a model without them).  All are compiled,
    or loaded from the cache, on first use (:meth:`parts`).  ``path`` is the kernel's name in the cache folder.
    """

    def __init__(self, tableau: str, model_module, rhs_name: str, n_state: int):
        self.TABLEAU, self.RHS_NAME, self.N, self.model = tableau, rhs_name, n_state, model_module
        self.NV = len(getattr(model_module, "EVENT_NAMES", ()))
        self.NQ = _n_constants(model_module)
        self._rhs, self._constants = getattr(model_module, rhs_name), model_module.constants
        stem = digest(tableau, _irparts.stages_ir(tableau), self._rhs, n_state, self.NQ)
        self.path = cache_dir() / "kernels" / f"erk-{tableau}-{model_module.__name__.rsplit('.', 1)[-1]}-{stem}"
        self.driver = driver(tableau)
        self._events = compiled_cfunc(self._events_py(), EVENTS_SIG, f"{self.path.name}-events") if self.NV else None
        self._fns = self._library = self._constants_ir = None

    def _rhs_cfunc(self):
        rhs, N = self._rhs, self.N

        def rhs_part(t, yp, qp, nq, outp):
            """``out = f(t, y)`` (``q`` = ``constants(p)`` has ``nq`` elements)."""
            rhs(t, carray(yp, (N,)), carray(qp, (nq,)), carray(outp, (N,)))

        function = compiled_cfunc(rhs_part, RHS_SIG, f"{self.path.name}-rhs")
        function.compile()
        return function

    def _events_py(self):
        event_values, N, NV = self.model.event_values, self.N, self.NV

        def events_part(sp, pp, n_p, outp):
            """``out = event_values(s, p)`` (``p`` has ``n_p`` elements)."""
            out = carray(outp, (NV,))
            v = event_values(carray(sp, (N,)), carray(pp, (n_p,)))
            for k in range(NV):
                out[k] = v[k]

        return events_part

    def parts(self) -> np.ndarray:
        """``fns``, the integrator's first argument: the addresses of the compiled parts (compiled, or loaded from
        the cache, at the first call), then ``NV``."""
        if self._fns is None:
            self._library, addresses = _irparts.load_or_compile(self.path, self.TABLEAU, self.N, self.model,
                                                                self.RHS_NAME, self._rhs_cfunc)
            attempt, dense, rhs, constants = addresses  # the library is kept: the integrator calls them by address
            if constants:  # with the number of parameters it reads
                self._constants_ir = (np.int64(constants), self.model.LLVM_IR_READS)
            events = 0  # no event functions: never called
            if self._events is not None:
                self._events.compile()
                events = self._events.address
            self._fns = np.array([rhs, attempt, dense, events, self.NV], dtype=np.int64)
        return self._fns

    def constants(self, p) -> np.ndarray:
        """``q = constants(p)`` of the right-hand side: the model's, compiled as IR with the parts where it
        could be written so (``p`` must hold the parameters it reads), else numba's compilation of it."""
        self.parts()
        if self._constants_ir is None:
            return self._constants(p)
        address, reads = self._constants_ir
        if not (type(p) is np.ndarray and p.dtype == np.float64 and p.ndim == 1 and p.flags.c_contiguous):
            p = np.ascontiguousarray(p, dtype=np.float64)
        if p.ndim != 1 or p.size < reads:
            raise ValueError(f"the parameters have {p.size} elements; constants(p) reads {reads}")
        q, finite = _fnptr.constants_at(address, p, self.NQ)
        if not finite:  # numba's compilation raises where it divides by zero: say what it says
            return self._constants(p)
        return q

    def is_compiled(self) -> bool:
        """Whether the cache holds the compiled parts and the integrator (later calls load them)."""
        if not _irparts.cache_file(self.path).is_file() or not is_cached(self.driver):
            return False
        return self._events is None or is_cached(self._events)

    def arguments(self, t0, t1, y0, f0, p, control, request, out) -> tuple:
        """The integrator's arguments for the arguments of :meth:`solve`."""
        if y0.size != self.N:
            raise ValueError("the initial state does not have the size this kernel was specialized to")
        q = self.constants(p)
        if q.size != self.NQ:
            raise ValueError(f"constants(p) has {q.size} elements, not the {self.NQ} this kernel was specialized to")
        return self.parts(), t0, t1, y0, f0, q, p, _one_signature(control), request, out

    def argument_types(self, args: tuple) -> tuple:
        """numba's types of the integrator's arguments for the arguments ``args`` of :meth:`solve` (compiles
        nothing: what a separate process needs to compile the integrator)."""
        t0, t1, y0, f0, p, control, request, out = args
        sample = (np.zeros(5, dtype=np.int64), t0, t1, y0, f0, np.zeros(1), p, _one_signature(control), request, out)
        return tuple(self.driver.typeof_pyval(a) for a in sample)

    def compile_types(self, types_) -> None:
        """Compile (or load from the cache) the parts and the integrator for the argument types ``types_``."""
        self.parts()
        self.driver.compile(types_)

    def solve(self, t0, t1, y0, f0, p, control, request, out):
        """The integrator with this model's parts (see :func:`driver`'s parameters and returns, without ``fns``
        and ``q``)."""
        return self.driver(*self.arguments(t0, t1, y0, f0, p, control, request, out))


def _one_signature(control: tuple) -> tuple:
    """``control`` with ``pair`` read-only, as ``simulate`` passes it: a writable one is another numba type, and
    the integrator would compile a second time (3-4 s) for it."""
    pair = control[4]
    if pair.flags.writeable:
        pair = pair.view()
        pair.flags.writeable = False
        control = control[:4] + (pair,) + control[5:]
    return control


def _n_constants(model_module) -> int:
    """The size of ``model_module.constants(p)`` (run as plain Python on parameters all one)."""
    n_inputs = len(getattr(model_module, "INPUT_NAMES", ()))  # their slots follow the parameters (input_slots.py)
    n_params = len(getattr(model_module, "PARAM_NAMES", ())) + (1 + 2 * n_inputs if n_inputs else 0) or 1
    with np.errstate(all="ignore"):
        return int(np.size(model_module.constants.py_func(np.ones(n_params))))
