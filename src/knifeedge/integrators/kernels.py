"""The kernel of one method for one model: made once per process, compiled once per machine.

:func:`kernel_module` finds the kernel of a model and a method's name (the one place that maps them);
:func:`load_kernel` returns an :class:`~.erk.AdaptiveKernel` (an adaptive method: the model's parts and the
integrator shared by every model) or a :class:`~.fixed.FixedKernel` (a fixed-step method); each has
``solve(...)`` and ``is_compiled()``.  Nothing is written but numba's compiled code (:mod:`.cache`).
"""
from __future__ import annotations

from types import ModuleType

from .erk import AdaptiveKernel
from .fixed import FixedKernel
from .methods import get

KINDS = {"erk": AdaptiveKernel, "fixed": FixedKernel}
_LOADED: dict = {}


def load_kernel(kind: str, variant: str, model_module: ModuleType, rhs_name: str, n_state: int):
    """The kernel of the registered method ``variant`` (``kind`` ``"erk"`` or ``"fixed"``) for the right-hand
    side ``rhs_name`` of the generated ``model_module`` on ``n_state`` states (compiled at its first call
    unless the cache holds it)."""
    if kind not in KINDS:
        raise ValueError(f"`kind` must be one of {tuple(KINDS)}, got {kind!r}")
    if isinstance(n_state, bool) or not isinstance(n_state, int) or n_state < 1:
        raise ValueError(f"`n_state` must be a positive integer, got {n_state!r}")
    key = (kind, variant, id(model_module), rhs_name, n_state)
    if key not in _LOADED:
        _LOADED[key] = (KINDS[kind](variant, model_module, rhs_name, n_state), model_module)
    return _LOADED[key][0]


def kernel_module(model, method: str):
    """The kernel of ``method`` (a registered name or alias) for ``model`` (a :class:`knifeedge.Model`: its
    module, with or without the pose), made by :func:`load_kernel`, compiled or not."""
    spec = get(method)
    rhs_name = "rhs_pose_q_into" if model.pose else "rhs_q_into"
    return load_kernel(spec.kind, spec.name, model.module, rhs_name, model.n_state)
