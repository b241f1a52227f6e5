"""A model's parts of the adaptive integrator (``erk.py``), compiled as C-callable functions.

:mod:`..specialize` writes this template for one model and one method: the
``# knifeedge:rhs`` and ``# knifeedge:event_values`` lines import the model's
functions, the ``# knifeedge:driver`` line the integrator, ``N`` and ``NV``
become its state size and its number of event functions, ``NQ`` the size of
its ``constants(p)``.

The parts are the right-hand side, the stages of a step with the error norm
(``attempt``), the interpolant (``dense``) and the event functions
(:func:`events`).  ``attempt`` and ``dense`` are straight-line LLVM IR
written from the tableau with the state size and coefficients as constants
(:mod:`knifeedge.integrators.irparts`), linked with the IR of the model's
``rhs_q_into`` and ``constants`` that the generated module carries
(``LLVM_IR``, written at derive time; the right-hand side inlined into the
stages), numba compiling the right-hand side (:func:`rhs`) only where the
module has no IR of it; ``events`` is a ``numba.cfunc`` (a no-op from the IR
module for a model without event functions).  All are compiled on first use
(:func:`parts`) and cached; the integrator, compiled once per method for
every model, calls them through their addresses
(:mod:`knifeedge.integrators.fnptr`).  :func:`solve` is the integrator with
this model's parts: it takes the arguments of ``erk.solve`` without ``fns``
and ``q``.
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

(_, _, _, _, _, _, _, N_STAGES, N_EXT, DENSE_ROWS, _, _) = _tableau.erk_arrays(TABLEAU)
#: the right-hand side's name in the generated module (its IR is ``LLVM_IR[RHS_NAME]``)
RHS_NAME = _rhs.py_func.__name__

_F8 = types.float64
_I8 = types.int64
_D = types.CPointer(types.float64)
RHS_SIG = types.void(_F8, _D, _D, _I8, _D)
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
        model = sys.modules[_rhs.py_func.__module__]  # the generated module (its LLVM_IR)
        lib, addresses = _irparts.load_or_compile(__file__, TABLEAU, N, NQ, model, RHS_NAME,
                                                  lambda: cfunc(RHS_SIG, **_OPTIONS)(rhs))
        attempt_address, dense_address, rhs_address = addresses[:3]
        if addresses[3]:
            constants = (np.int64(addresses[3]), ctypes.CFUNCTYPE(ctypes.c_int64)(addresses[4])())
        events_address = None if NV else addresses[5]  # no event functions: a no-op, never called
        kept = (lib,)
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

    if not _irparts.cache_file(__file__).is_file():
        return False
    return all(cached(f) for f in ((events, _driver.solve) if NV else (_driver.solve,)))


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
