"""Fixed-step Runge--Kutta methods as data: :class:`FixedMethod` and the registry :data:`FIXED_METHODS`.

A method is its Butcher tableau ``(A, b, c)``, checked when it is built
(rows of ``A`` sum to ``c``, weights sum to one) and registered by name.
An explicit tableau (strictly lower-triangular ``A``, e.g. the classical
RK4) is stepped stage after stage; an implicit one (the Gauss--Legendre
collocation methods) by fixed-point iteration of its stage equations,
started from the previous step's collocation polynomial
(:attr:`FixedMethod.extrapolation`).  The fixed-step kernel
(:mod:`.fixed`, a numba closure per method and model) reads
everything from the registered method: adding one is a :class:`FixedMethod`
and a :func:`register_fixed` line.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import rk_tableaus as _tb
from .tableau import CHECK_TOL


@dataclass(frozen=True, eq=False)
class FixedMethod:
    """A Runge--Kutta method taken with a fixed step.

    Attributes
    ----------
    name : str -- registry name (the ``method`` of :func:`knifeedge.simulate`).
    A : (s, s) stage coefficients; b : (s,) weights; c : (s,) nodes.
    order : int; description : str.
    denominator : float -- the step's increment is summed as ``h / denominator * sum_j (denominator b_j) K_j``
        (RK4: 6, so that ``h/6 (K_0 + 2 K_1 + 2 K_2 + K_3)`` is computed as written); ``denominator b_j`` must
        be exact.
    """

    name: str
    A: np.ndarray
    b: np.ndarray
    c: np.ndarray
    order: int
    description: str
    denominator: float = 1.0

    def __post_init__(self):
        for attr in ("A", "b", "c"):
            arr = np.array(getattr(self, attr), dtype=float)
            arr.flags.writeable = False
            object.__setattr__(self, attr, arr)
        s = self.c.size
        problems = []
        if self.A.shape != (s, s) or self.b.shape != (s,):
            problems.append(f"shapes: A {self.A.shape}, b {self.b.shape}, c {self.c.shape}")
        elif np.any(np.abs(self.A.sum(axis=1) - self.c) > CHECK_TOL):
            problems.append("rows of A do not sum to c")
        if abs(self.b.sum() - 1.0) > CHECK_TOL:
            problems.append(f"weights b sum to {self.b.sum()!r}, not 1")
        elif np.any((self.b * self.denominator) / self.denominator != self.b):
            problems.append(f"the weights times the denominator {self.denominator!r} are not exact")
        if problems:
            raise ValueError(f"method {self.name!r} is inconsistent: " + "; ".join(problems))

    @property
    def stages(self) -> int:
        return self.c.size

    @property
    def implicit(self) -> bool:
        """Whether a stage depends on itself or a later one (then the stages are iterated)."""
        return bool(np.any(np.triu(self.A) != 0.0))

    @property
    def is_classical_rk4(self) -> bool:
        """Whether this is the classical RK4 tableau (the kernel then runs its increment as written out)."""
        return (self.stages == 4 and np.array_equal(self.A, _RK4_A) and np.array_equal(self.b, _tb.RK4_B)
                and np.array_equal(self.c, _tb.RK4_C))

    @property
    def extrapolation(self) -> np.ndarray:
        """``X[i, j]``: Lagrange basis polynomial ``j`` on the nodes ``c`` at ``1 + c[i]`` (the next step's
        starting stages from this step's collocation polynomial)."""
        s, c = self.stages, self.c
        if not self.implicit:  # nothing to iterate
            return np.zeros((s, s))
        X = np.ones((s, s))
        for i in range(s):
            for j in range(s):
                for k in range(s):
                    if k != j:
                        X[i, j] *= (1.0 + c[i] - c[k]) / (c[j] - c[k])
        return X


#: registered fixed-step methods by name
FIXED_METHODS: dict = {}


def register_fixed(method: FixedMethod) -> FixedMethod:
    """Register ``method`` under its name (a name is registered once)."""
    if not isinstance(method, FixedMethod):
        raise TypeError(f"`method` must be a FixedMethod, got {type(method).__name__}")
    if method.name in FIXED_METHODS and FIXED_METHODS[method.name] is not method:
        raise ValueError(f"a method named {method.name!r} is already registered")
    FIXED_METHODS[method.name] = method
    return method


_RK4_A = np.diag([0.5, 0.5, 1.0], k=-1)
RK4 = register_fixed(FixedMethod("RK4", _RK4_A, _tb.RK4_B, _tb.RK4_C, 4, "classical Runge-Kutta, fixed step", 6.0))
IMPLICIT_MIDPOINT = register_fixed(FixedMethod("implicit_midpoint", *_tb.GAUSS[1], 2,
                                               "implicit midpoint rule (Gauss-Legendre, 1 stage)"))
GAUSS4 = register_fixed(FixedMethod("gauss4", *_tb.GAUSS[2], 4, "Gauss-Legendre collocation, 2 stages, order 4"))
GAUSS6 = register_fixed(FixedMethod("gauss6", *_tb.GAUSS[3], 6, "Gauss-Legendre collocation, 3 stages, order 6"))
