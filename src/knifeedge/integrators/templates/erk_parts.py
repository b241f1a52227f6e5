"""A model's parts of the adaptive integrator (``erk.py``), compiled as C-callable functions.

:mod:`..specialize` writes this template for one model and one method: the
``# knifeedge:rhs`` and ``# knifeedge:event_values`` lines import the model's
functions, the ``# knifeedge:driver`` line the integrator, ``N`` and ``NV``
become its state size and its number of event functions, ``NQ`` the size of
its ``constants(p)``, and ``IR`` says how ``attempt`` and ``dense`` are
compiled.

The parts are the right-hand side (:func:`rhs`), the stages of a step with
the error norm (:func:`attempt`), the interpolant (:func:`dense`) and the
event functions (:func:`events`).  When ``IR`` is true (a specialized
kernel), ``attempt`` and ``dense`` are straight-line LLVM IR written from
the tableau with the state size and coefficients as constants
(:mod:`knifeedge.integrators.irparts`), linked with the IR of the model's
``rhs_q_into`` and ``constants`` that the generated module carries
(``LLVM_IR``, written at derive time; the right-hand side inlined into the
stages), numba compiling them only where the module has none; ``events`` is
a ``numba.cfunc`` (a no-op from the IR module for a model without event
functions).  Otherwise all four are numba's compilation (``attempt`` and
``dense`` of the loops over the tableau below: the reference the tests
compare the IR with).  All are compiled on first use (:func:`parts`) and cached; the
integrator, compiled once per method for every model, calls them through
their addresses (:mod:`knifeedge.integrators.fnptr`).  :func:`solve` is the
integrator with this model's parts: it takes the arguments of ``erk.solve``
without ``fns`` and ``q``.
"""
import ctypes
import sys

import numpy as np
from numba import carray, cfunc, types

from knifeedge.integrators import fnptr as _fnptr
from knifeedge.integrators import irparts as _irparts
from knifeedge.integrators import tableau as _tableau
from knifeedge.integrators.templates import erk as _driver  # knifeedge:driver
from knifeedge.integrators.templates._stub import constants as _constants, rhs_q_into as _rhs  # knifeedge:rhs
from knifeedge.integrators.templates._stub import event_values as _event_values  # knifeedge:event_values

TABLEAU = "DOP853"  # knifeedge:variant  (a registered ExplicitTableau, see knifeedge.integrators.tableau)
N = 3  # knifeedge:n  (the state size, a compile-time constant so that the loops over it unroll)
NV = 1  # knifeedge:nv  (the number of event functions)
NQ = 2  # knifeedge:nq  (the size of constants(p))
IR = False  # knifeedge:ir  (attempt and dense as LLVM IR written from the tableau; False: numba compiles the loops)

(A, C, E5, E3, DD, P, HAIRER, N_STAGES, N_EXT, DENSE_ROWS, ALT, ERROR_ORDER) = _tableau.erk_arrays(TABLEAU)

_F8 = types.float64
_I8 = types.int64
_D = types.CPointer(types.float64)
_L = types.CPointer(types.int64)
RHS_SIG = types.void(_F8, _D, _D, _I8, _D)
ATTEMPT_SIG = types.float64(_F8, _F8, _F8, _F8, _I8, _D, _I8, _D, _L)
DENSE_SIG = types.void(_F8, _F8, _D, _I8)
#: the integrator's workspace, in this order: K (N_EXT x N), y, y_new, work, scale (N each), F (DENSE_ROWS x N),
#: then q (NQ); the parts take their arrays at these fixed offsets of the one pointer
_O = N_EXT * N
_OQ = _O + (4 + DENSE_ROWS) * N
#: its size: a constant, so that every view of it is at an offset the compiler knows
_WS = _OQ + NQ
EVENTS_SIG = types.void(_D, _D, _I8, _D)


def rhs(t, yp, qp, nq, outp):
    """``out = f(t, y)`` (``q`` = ``constants(p)`` has ``nq`` elements)."""
    _rhs(t, carray(yp, (N,)), carray(qp, (nq,)), carray(outp, (N,)))


def attempt(t, h, t_new, rtol, mode_scaled, wsp, nq, ap, pairp):
    """One step from ``K[0] = f(t, y)``: the stages ``K[1 ..]``, ``y_new`` and ``K[N_STAGES] = f(t_new,
    y_new)``; returns the scaled norm of the error estimate (``scale`` is written too)."""
    ws = carray(wsp, (_WS,))
    K = carray(wsp, (N_EXT, N))  # at the start of the workspace (a reshape would call numba's helper each time)
    y = ws[_O:_O + N]
    y_new = ws[_O + N:_O + 2 * N]
    work = ws[_O + 2 * N:_O + 3 * N]
    scale = ws[_O + 3 * N:_O + 4 * N]
    q = ws[_OQ:]
    atol = carray(ap, (N,))
    pair = carray(pairp, (N,))
    # stages 1 .. N_STAGES from K[0] = f(t, y) (first same as last), then y_new and K[N_STAGES]
    for s in range(1, N_STAGES + 1):
        for i in range(N):
            acc = 0.0
            for j in range(s):
                acc += A[s, j] * K[j, i]
            if s < N_STAGES:
                work[i] = y[i] + h * acc
            else:
                y_new[i] = y[i] + h * acc
        if s < N_STAGES:
            _rhs(t + C[s] * h, work, q, K[s])
        else:
            _rhs(t_new, y_new, q, K[s])
    for i in range(N):
        m = max(abs(y[i]), abs(y_new[i]))
        if mode_scaled and pair[i] >= 0:
            m = max(m, abs(y[pair[i]]), abs(y_new[pair[i]]))
        scale[i] = atol[i] + rtol * m
    # the scaled norm of the embedded estimate (DOP853: its 5th- and 3rd-order ones combined as Hairer's)
    n5 = 0.0
    n3 = 0.0
    for i in range(N):
        e5 = 0.0
        e3 = 0.0
        for j in range(N_STAGES + 1):
            e5 += E5[j] * K[j, i]
            e3 += E3[j] * K[j, i]
        n5 += (e5 / scale[i]) * (e5 / scale[i])
        n3 += (e3 / scale[i]) * (e3 / scale[i])
    if not HAIRER:
        err = abs(h) * np.sqrt(n5 / N)
    elif n5 == 0.0 and n3 == 0.0:
        err = 0.0
    else:
        err = abs(h) * n5 / np.sqrt((n5 + 0.01 * n3) * N)
    return err


def dense(t, h, wsp, nq):
    """``F`` (``DENSE_ROWS`` x ``N``), the interpolant of the accepted step (DOP853: its extra stages first)."""
    ws = carray(wsp, (_WS,))
    K = carray(wsp, (N_EXT, N))  # at the start of the workspace (a reshape would call numba's helper each time)
    y = ws[_O:_O + N]
    y_new = ws[_O + N:_O + 2 * N]
    work = ws[_O + 2 * N:_O + 3 * N]
    F = ws[_O + 4 * N:_OQ].reshape((DENSE_ROWS, N))
    q = ws[_OQ:]
    if HAIRER:
        for s in range(N_STAGES + 1, N_EXT):
            for i in range(N):
                acc = 0.0
                for j in range(s):
                    acc += A[s, j] * K[j, i]
                work[i] = y[i] + h * acc
            _rhs(t + C[s] * h, work, q, K[s])
        for i in range(N):
            dy = y_new[i] - y[i]
            F[0, i] = dy
            F[1, i] = h * K[0, i] - dy
            F[2, i] = 2.0 * dy - h * (K[N_STAGES, i] + K[0, i])
            for r in range(DENSE_ROWS - 3):
                acc = 0.0
                for j in range(N_EXT):
                    acc += DD[r, j] * K[j, i]
                F[3 + r, i] = h * acc
    else:
        for i in range(N):
            for r in range(DENSE_ROWS):
                acc = 0.0
                for j in range(N_EXT):
                    acc += K[j, i] * P[j, r]
                F[r, i] = h * acc


def events(sp, pp, n_p, outp):
    """``out = event_values(s, p)`` (``p`` has ``n_p`` elements)."""
    out = carray(outp, (max(NV, 1),))
    v = _event_values(carray(sp, (N,)), carray(pp, (n_p,)))
    for k in range(NV):
        out[k] = v[k]


_PARTS: list = []
_OPTIONS = {"cache": True, "error_model": "numpy"}


def parts() -> np.ndarray:
    """The addresses of the compiled parts (compiled, or loaded from the cache, at the first call), then
    ``NV``: the ``fns`` argument of the integrator."""
    if not _PARTS:
        constants = None
        if IR:  # the right-hand side and constants too, as IR (numba's compilation where they cannot be)
            model = sys.modules[_rhs.py_func.__module__]  # the generated module (its LLVM_IR)
            lib, addresses = _irparts.load_or_compile(__file__, TABLEAU, N, NQ, model, _rhs.py_func.__name__,
                                                      lambda: cfunc(RHS_SIG, **_OPTIONS)(rhs))
            attempt_address, dense_address, rhs_address = addresses[:3]
            if addresses[3]:
                constants = (np.int64(addresses[3]), ctypes.CFUNCTYPE(ctypes.c_int64)(addresses[4])())
            events_address = None if NV else addresses[5]  # no event functions: a no-op, never called
            kept = (lib,)
        else:
            # "contract": fused multiply-adds in the stage sums
            fast = dict(_OPTIONS, fastmath={"contract"})
            rhs_c = cfunc(RHS_SIG, **_OPTIONS)(rhs)
            attempt_c, dense_c = cfunc(ATTEMPT_SIG, **fast)(attempt), cfunc(DENSE_SIG, **fast)(dense)
            kept = (rhs_c, attempt_c, dense_c)
            rhs_address, attempt_address, dense_address = rhs_c.address, attempt_c.address, dense_c.address
            events_address = None
        if events_address is None:
            events_c = cfunc(EVENTS_SIG, **_OPTIONS)(events)
            kept += (events_c,)
            events_address = events_c.address
        _PARTS.append(kept)  # kept alive: the integrator calls them by address
        _PARTS.append(np.array([rhs_address, attempt_address, dense_address, events_address, NV], dtype=np.int64))
        _PARTS.append(constants)
    return _PARTS[1]


def constants(p) -> np.ndarray:
    """``q = constants(p)`` of the right-hand side: the model's, compiled as IR with the parts where it could be
    written so (``p`` must hold the parameters it reads), else numba's compilation of it."""
    parts()
    if _PARTS[2] is None:
        return _constants(p)
    address, reads = _PARTS[2]
    if not (type(p) is np.ndarray and p.dtype == np.float64 and p.ndim == 1 and p.flags.c_contiguous):
        p = np.ascontiguousarray(p, dtype=np.float64)
    if p.ndim != 1 or p.size < reads:
        raise ValueError(f"the parameters have {p.size} elements; constants(p) reads {reads}")
    q, finite = _fnptr.constants_at(address, p, NQ)
    if not finite:  # numba's compilation raises where it divides by zero: say what it says
        return _constants(p)
    return q


def is_compiled() -> bool:
    """Whether the cache holds the compiled parts and the integrator (later calls load them)."""
    from knifeedge.integrators.specialize import cached

    if IR:
        if not _irparts.cache_file(__file__).is_file():
            return False
        return all(cached(f) for f in ((events, _driver.solve) if NV else (_driver.solve,)))
    return all(cached(f) for f in (rhs, attempt, dense, events, _driver.solve))


def arguments(t0, t1, y0, f0, p, *rest) -> tuple:
    """The integrator's arguments for the arguments of :func:`solve`."""
    if y0.size != N:
        raise ValueError("the initial state does not have the size this kernel was specialized to")
    q = constants(p)
    if q.size != NQ:
        raise ValueError(f"constants(p) has {q.size} elements, not the {NQ} this kernel was specialized to")
    return (parts(), t0, t1, y0, f0, q, p) + _one_signature(rest)


def _one_signature(rest: tuple) -> tuple:
    """``rest`` (``rtol`` .. ``ev_k``) with ``pair`` read-only, as ``simulate`` passes it: a writable one is
    another numba type, and the integrator would compile a second time (3-4 s) for it."""
    pair = rest[8]
    if pair.flags.writeable:
        pair = pair.view()
        pair.flags.writeable = False
        rest = rest[:8] + (pair,) + rest[9:]
    return rest


def argument_types(args: tuple) -> tuple:
    """numba's types of the integrator's arguments for the arguments ``args`` of :func:`solve` (compiles
    nothing: what a separate process needs to compile the integrator)."""
    t0, t1, y0, f0, p, *rest = args
    sample = (np.zeros(5, dtype=np.int64), t0, t1, y0, f0, np.zeros(1), p, *_one_signature(tuple(rest)))
    return tuple(_driver.solve.typeof_pyval(a) for a in sample)


def compile_types(types_) -> None:
    """Compile (or load from the cache) the parts and the integrator for the argument types ``types_``."""
    parts()
    _driver.solve.compile(types_)


def solve(t0, t1, y0, f0, p, rtol, atol, h_init, max_step, t_eval, every, events, max_steps, pair, mode_scaled,
          chunk, ts, ys, ev_t, ev_k):
    """``erk.solve`` with this model's parts (see its parameters and returns)."""
    return _driver.solve(*arguments(t0, t1, y0, f0, p, rtol, atol, h_init, max_step, t_eval, every, events,
                                    max_steps, pair, mode_scaled, chunk, ts, ys, ev_t, ev_k))
