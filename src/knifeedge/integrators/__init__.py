"""Integrators compiled with numba that call a generated right-hand side directly.

:data:`COMPILED_METHODS` lists them (the methods as data, :mod:`.methods`); :func:`kernel` returns the compiled
``solve`` function of one method specialized to one model (compiled on first
use, then cached on disk across processes, see :mod:`.cache`).
"""
from __future__ import annotations

from .cache import cache_dir
from .kernels import kernel, kernel_compiled, kernel_module, load_kernel, use_compiled
from .status import Status, from_code
from .methods import ALIASES, COMPILED_METHODS, ExplicitTableau, FixedMethod, register
from .common import EVENTS_PER_STEP
from .compiler import compile_mode, set_compile_mode


__all__ = ["COMPILED_METHODS", "ALIASES", "EVENTS_PER_STEP", "ExplicitTableau", "FixedMethod", "Status", "cache_dir",
           "compile_mode", "from_code", "kernel", "kernel_compiled", "kernel_module", "load_kernel",
           "register", "set_compile_mode", "use_compiled"]
