"""Integrators compiled with numba that call a generated right-hand side directly.

:data:`COMPILED_METHODS` lists them (the methods as data, :mod:`.methods`); :func:`kernel` returns the compiled
``solve`` function of one method specialized to one model (compiled on first
use, then cached on disk across processes, see :mod:`.cache`).
"""
from __future__ import annotations

import sys
import time

from .cache import cache_dir
from .kernels import kernel_module, load_kernel
from .status import Status, from_code
from .methods import ALIASES, COMPILED_METHODS, ExplicitTableau, FixedMethod, get, register
from .common import EVENTS_PER_STEP
from .compiler import compile_mode, set_compile_mode


#: the ``solve`` of each kernel used so far (the first-call notice's wrapper until it has compiled)
_KERNELS: dict = {}


def kernel(model, method: str):
    """The compiled ``solve`` function of ``method`` for ``model`` (a :class:`knifeedge.Model`).

    The first use of a (model, method) pair on a machine compiles it, which
    takes seconds, and says so in one line on stderr; later uses, in any
    process, load the machine code from the cache (:func:`cache_dir`).
    """
    module = kernel_module(model, method)
    if module not in _KERNELS:
        solve = module.solve
        if not module.is_compiled():
            pose = ", pose" if model.pose else ""
            solve = _announced(solve, f"{get(method).name} for {model.name} ({model.fidelity}{pose})")
        _KERNELS[module] = solve
    return _KERNELS[module]


def kernel_compiled(model, method: str) -> bool:
    """Whether the cache holds the compiled kernel of ``method`` for ``model`` (a later call loads it)."""
    return kernel_module(model, method).is_compiled()


def use_compiled(model, method: str) -> None:
    """Forget a first-call notice of the kernel of ``method`` for ``model`` (it was compiled elsewhere)."""
    module = kernel_module(model, method)
    _KERNELS[module] = module.solve


def _announced(solve, label: str):
    """``solve`` that says on stderr, at its first call, that it compiles now and once (later calls of the
    same wrapper, e.g. the continued calls of the run that compiled it, go straight to ``solve``)."""
    done = []

    def first_call(*args):
        if done:
            return solve(*args)
        print(f"knifeedge: compiling {label}; once, it is then cached in {cache_dir()} ...",
              file=sys.stderr, end="", flush=True)
        t = time.perf_counter()
        try:
            out = solve(*args)
        finally:
            print(f" {time.perf_counter() - t:.1f} s", file=sys.stderr, flush=True)
        done.append(True)
        for k, v in _KERNELS.items():
            if v is first_call:
                _KERNELS[k] = solve
        return out

    return first_call


__all__ = ["COMPILED_METHODS", "ALIASES", "EVENTS_PER_STEP", "ExplicitTableau", "FixedMethod", "Status", "cache_dir",
           "compile_mode", "from_code", "kernel", "kernel_compiled", "kernel_module", "load_kernel",
           "register", "set_compile_mode", "use_compiled"]
