"""Explicit Runge--Kutta methods as data: :class:`ExplicitTableau` and the registry :data:`TABLEAUS`.

A method is a frozen :class:`ExplicitTableau`, checked when it is built,
and registered by name with :func:`register`.  The adaptive kernel
(:mod:`.erk`, a numba closure per method) reads everything
it needs from the tableau: the stages, the weights, the error estimator, the
order of the controller and the dense output.  Adding a method is one file
defining its tableau plus one :func:`register` line in
:mod:`knifeedge.integrators`.

Conventions (the first-same-as-last form of Dormand--Prince pairs): stage
``j < s`` is ``K_j = f(t + c_j h, y + h sum_i A[j, i] K_i)``, the step is
``y_new = y + h sum_j b_j K_j`` and ``K_s = f(t + h, y_new)`` is both the
last term of the error estimate ``err = h sum_{j <= s} e_j K_j`` and the
first stage of the next step.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

#: tolerance of the consistency checks (the coefficients are given to about 16 digits)
CHECK_TOL = 1e-13


@dataclass(frozen=True, eq=False)
class ExplicitTableau:
    """An embedded explicit Runge--Kutta pair with dense output.

    Attributes
    ----------
    name : str
        Registry name (the ``method`` of :func:`knifeedge.simulate`).
    c : (s,) nodes, ``c[0] == 0``.
    A : (s, s) strictly lower-triangular stage coefficients.
    b : (s,) weights of the step.
    e : (s + 1,) error estimator: ``h sum_j e_j K_j`` over the stages and ``K_s = f(t + h, y_new)``.
    order : order of the step.
    error_order : order of the embedded estimate (the step-size controller uses ``-1/(error_order + 1)``).
    P : (s + 1, m) dense output ``y(t + x h) = y + h sum_j K_j sum_r P[j, r] x^(r + 1)``;
        ``None`` when the method has Hairer's DOP853 interpolant (``hairer``).
    hairer : dict or None
        DOP853 only: its second (3rd-order) estimator ``e3``, the extra
        stages of its dense output (``c_ext``, ``A_ext`` rows over all
        earlier stages) and the interpolant's matrix ``D``.
    description, reference : str
    """

    name: str
    c: np.ndarray
    A: np.ndarray
    b: np.ndarray
    e: np.ndarray
    order: int
    error_order: int
    P: np.ndarray | None
    description: str
    reference: str
    hairer: dict | None = field(default=None)

    def __post_init__(self):
        for attr in ("c", "A", "b", "e") + (("P",) if self.P is not None else ()):
            arr = np.array(getattr(self, attr), dtype=float)
            arr.flags.writeable = False
            object.__setattr__(self, attr, arr)
        problems = _problems(self)
        if problems:
            raise ValueError(f"tableau {self.name!r} is inconsistent: " + "; ".join(problems))

    @property
    def stages(self) -> int:
        """Stages per step (the first-same-as-last evaluation not counted)."""
        return self.c.size


def _problems(t: ExplicitTableau) -> list:
    out = []
    s = t.c.size
    if not isinstance(t.name, str) or not t.name.isidentifier():
        out.append(f"name must be an identifier, got {t.name!r}")
    if t.A.shape != (s, s) or t.b.shape != (s,) or t.e.shape != (s + 1,):
        return out + [f"shapes: c {t.c.shape}, A {t.A.shape} (want ({s}, {s})), b {t.b.shape} (want ({s},)), "
                      f"e {t.e.shape} (want ({s + 1},))"]
    if t.c[0] != 0.0:
        out.append(f"c[0] must be 0, got {t.c[0]!r}")
    if np.any(np.triu(t.A) != 0.0):
        out.append("A must be strictly lower triangular (an explicit method)")
    rows = t.A.sum(axis=1)
    bad = np.flatnonzero(np.abs(rows - t.c) > CHECK_TOL)
    if bad.size:
        out.append(f"rows {bad.tolist()} of A do not sum to c (sums {rows[bad].tolist()}, c {t.c[bad].tolist()})")
    if abs(t.b.sum() - 1.0) > CHECK_TOL:
        out.append(f"weights b sum to {t.b.sum()!r}, not 1")
    if abs(t.e.sum()) > CHECK_TOL:
        out.append(f"error estimator e sums to {t.e.sum()!r}, not 0 (it must vanish on constant derivatives)")
    if not (isinstance(t.order, int) and isinstance(t.error_order, int) and 0 < t.error_order < t.order):
        out.append(f"orders: need 0 < error_order < order, got {t.error_order!r}, {t.order!r}")
    if (t.P is None) == (t.hairer is None):
        out.append("give exactly one dense output: P (power series) or hairer (DOP853's)")
    elif t.P is not None:
        if t.P.ndim != 2 or t.P.shape[0] != s + 1:
            out.append(f"P must have {s + 1} rows, got shape {t.P.shape}")
        else:
            at_one = t.P.sum(axis=1)  # the interpolant at x = 1 must be the step
            want = np.append(t.b, 0.0)
            if np.any(np.abs(at_one - want) > CHECK_TOL):
                out.append("the dense output at x = 1 is not the step (rows of P must sum to b, then 0)")
    return out


#: registered methods by name
TABLEAUS: dict = {}


def register(tableau: ExplicitTableau) -> ExplicitTableau:
    """Register ``tableau`` under its name (a name is registered once)."""
    if not isinstance(tableau, ExplicitTableau):
        raise TypeError(f"`tableau` must be an ExplicitTableau, got {type(tableau).__name__}")
    if tableau.name in TABLEAUS and TABLEAUS[tableau.name] is not tableau:
        raise ValueError(f"a method named {tableau.name!r} is already registered")
    TABLEAUS[tableau.name] = tableau
    return tableau


def get(name: str) -> ExplicitTableau:
    """The registered tableau called ``name``."""
    try:
        return TABLEAUS[name]
    except KeyError:
        raise ValueError(f"unknown explicit method {name!r}; registered: {', '.join(sorted(TABLEAUS))}") from None


def erk_arrays(name: str) -> tuple:
    """The tables the adaptive integrator and a model's parts use for the registered method ``name``.

    Returns ``(A, C, E5, E3, DD, P, HAIRER, N_STAGES, N_EXT, DENSE_ROWS, ALT, ERROR_ORDER)``:
    ``A`` and ``C`` over every stage (the method's, then the weights as the row of the stage at ``t + h``,
    first same as last, then the extra stages of DOP853's interpolant); ``E5`` the error estimator
    (and ``E3`` DOP853's second one, else zeros); ``DD`` DOP853's interpolant rows or ``P`` the power
    series of the others (the unused one is a 1 x 1 zero); ``ALT`` the factors of the Horner scheme of
    the interpolant ``v = (v + F[r, i]) * (1 - x if ALT[r] else x)`` (Hairer's form alternates them, the
    power series has ``x`` throughout); ``DENSE_ROWS`` the rows of ``F``.
    """
    t = get(name)
    hairer = t.hairer is not None
    s = t.stages
    n_ext = s + 1 + (t.hairer["c_ext"].size if hairer else 0)
    A = np.zeros((n_ext, n_ext))
    A[:s, :s] = t.A
    A[s, :s] = t.b
    C = np.ones(n_ext)
    C[:s] = t.c
    E5 = t.e.copy()
    if hairer:
        A[s + 1:] = t.hairer["A_ext"]
        C[s + 1:] = t.hairer["c_ext"]
        E3 = t.hairer["e3"].copy()
        DD = t.hairer["D"].copy()
        P = np.zeros((1, 1))
        dense_rows = 3 + DD.shape[0]
    else:
        E3 = np.zeros(n_ext)
        DD = np.zeros((1, 1))
        P = t.P.copy()
        dense_rows = P.shape[1]
    ALT = np.array([hairer and r % 2 == 1 for r in range(dense_rows)])
    return A, C, E5, E3, DD, P, hairer, s, n_ext, dense_rows, ALT, t.error_order
