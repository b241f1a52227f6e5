"""Integrators compiled with numba that call a generated right-hand side directly.

:data:`COMPILED_METHODS` lists them; :func:`kernel` returns the compiled
``solve`` function of one method specialized to one model (compiled on first
use, then cached on disk across processes, see :mod:`.specialize`).
"""
from __future__ import annotations

import sys
import time
from dataclasses import dataclass

from .specialize import cache_dir, is_compiled, load_kernel
from .status import Status, from_code


@dataclass(frozen=True)
class CompiledMethod:
    """A compiled integration method.

    Attributes
    ----------
    name : str
    template : str  -- kernel template (``"erk"`` adaptive, ``"fixed"`` fixed step)
    variant : int   -- the template's variant number
    order : int     -- classical order of accuracy
    fixed_step : bool -- needs a step ``h`` instead of tolerances
    description : str
    """

    name: str
    template: str
    variant: int
    order: int
    fixed_step: bool
    description: str


COMPILED_METHODS = {
    m.name: m
    for m in (
        CompiledMethod("DOP853", "erk", 0, 8, False, "Dormand-Prince 8(5,3), Hairer's DOP853, dense output of order 7"),
        CompiledMethod("DP54", "erk", 1, 5, False, "Dormand-Prince 5(4), dense output of order 4 (SciPy's RK45)"),
        CompiledMethod("RK4", "fixed", 0, 4, True, "classical Runge-Kutta, fixed step"),
        CompiledMethod("implicit_midpoint", "fixed", 1, 2, True, "implicit midpoint rule (Gauss-Legendre, 1 stage)"),
        CompiledMethod("gauss4", "fixed", 2, 4, True, "Gauss-Legendre collocation, 2 stages, order 4"),
        CompiledMethod("gauss6", "fixed", 3, 6, True, "Gauss-Legendre collocation, 3 stages, order 6"),
    )
}
#: other accepted names of compiled methods
ALIASES = {"RK45": "DP54"}


_KERNELS: dict = {}


def kernel(model, method: str):
    """The compiled ``solve`` function of ``method`` for ``model`` (a :class:`knifeedge.Model`).

    The first use of a (model, method) pair on a machine compiles it, which
    takes seconds, and says so in one line on stderr; later uses, in any
    process, load the machine code from the cache (:func:`cache_dir`).
    """
    spec = COMPILED_METHODS[ALIASES.get(method, method)]
    rhs_name = "rhs_pose_q_into" if model.pose else "rhs_q_into"
    key = (model.module.__name__, rhs_name, spec.template, spec.variant)
    if key not in _KERNELS:
        module = load_kernel(spec.template, spec.variant, model.module, rhs_name, model.n_state)
        solve = module.solve
        if not is_compiled(module):
            solve = _announced(solve, f"{spec.name} for {model.name} ({model.fidelity}{', pose' if model.pose else ''})")
        _KERNELS[key] = solve
    return _KERNELS[key]


def _announced(solve, label: str):
    """``solve`` that says on stderr, at its first call, that it compiles now and once."""
    def first_call(*args):
        print(f"knifeedge: compiling the {label} integrator: once, then cached in {cache_dir()} ...",
              file=sys.stderr, end="", flush=True)
        t = time.perf_counter()
        out = solve(*args)
        print(f" {time.perf_counter() - t:.1f} s", file=sys.stderr, flush=True)
        for k, v in _KERNELS.items():
            if v is first_call:
                _KERNELS[k] = solve
        return out

    return first_call


__all__ = ["COMPILED_METHODS", "ALIASES", "CompiledMethod", "Status", "from_code", "kernel", "cache_dir"]
