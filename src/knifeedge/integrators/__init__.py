"""Integrators compiled with numba that call a generated right-hand side directly.

:data:`COMPILED_METHODS` lists them; :func:`kernel` returns the compiled
``solve`` function of one method specialized to one model (compiled on first
use, then cached on disk across processes, see :mod:`.specialize`).
"""
from __future__ import annotations

from dataclasses import dataclass

from .specialize import cache_dir, load_kernel
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
    """The compiled ``solve`` function of ``method`` for ``model`` (a :class:`knifeedge.Model`)."""
    spec = COMPILED_METHODS[ALIASES.get(method, method)]
    rhs_name = "rhs_pose_q_into" if model.pose else "rhs_q_into"
    key = (model.module.__name__, rhs_name, spec.template, spec.variant)
    if key not in _KERNELS:
        _KERNELS[key] = load_kernel(spec.template, spec.variant, model.module, rhs_name, model.n_state).solve
    return _KERNELS[key]


__all__ = ["COMPILED_METHODS", "ALIASES", "CompiledMethod", "Status", "from_code", "kernel", "cache_dir"]
