"""The kernel of one method for one model: made once per process (:func:`load_kernel`, :func:`kernel_module`),
compiled once per machine (:mod:`.cache`); :func:`kernel` its ``solve``, saying on stderr that it compiles at its
first call."""
from __future__ import annotations

import sys
import time
from types import ModuleType

from .cache import cache_dir
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


#: the ``solve`` of each kernel used so far (the first-call notice's wrapper until it has compiled)
_KERNELS: dict = {}


def kernel(model, method: str):
    """The compiled ``solve`` function of ``method`` for ``model`` (a :class:`knifeedge.Model`): its first use on a
    machine compiles it (seconds, said in one line on stderr); later uses, in any process, load it from the cache."""
    module = kernel_module(model, method)
    if module not in _KERNELS:
        pose = ", pose" if model.pose else ""
        _KERNELS[module] = module.solve if module.is_compiled() else _announced(
            module, f"{get(method).name} for {model.name} ({model.fidelity}{pose})")
    return _KERNELS[module]


def kernel_compiled(model, method: str) -> bool:
    """Whether the cache holds the compiled kernel of ``method`` for ``model`` (a later call loads it)."""
    return kernel_module(model, method).is_compiled()


def use_compiled(model, method: str) -> None:
    """Forget a first-call notice of the kernel of ``method`` for ``model`` (it was compiled elsewhere)."""
    module = kernel_module(model, method)
    _KERNELS[module] = module.solve


def _announced(module, label: str):
    """``module.solve`` that says on stderr, at its first call, that it compiles now and once (later calls of the
    same wrapper, e.g. the continued calls of the run that compiled it, go straight to ``solve``)."""
    solve, done = module.solve, []

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
        _KERNELS[module] = solve
        return out

    return first_call
