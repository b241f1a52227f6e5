"""Integration methods as data: every compiled method is a tableau, checked when it is built, registered by name.

:class:`ExplicitTableau` (an embedded explicit pair with dense output, run by :mod:`.erk`) and
:class:`FixedMethod` (a Butcher tableau taken with a fixed step, :mod:`.fixed`) share one registry
(:data:`COMPILED_METHODS`, :func:`register`); adding one is docs/integrators.md, "A method is data".  DOP853's
and DP54's tables are SciPy's (``tests/test_tableaus.py`` checks them against the published literals).
"""
from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import ClassVar

import numpy as np
from numpy.polynomial import polynomial as _poly
from scipy.integrate import DOP853 as _DOP853, RK45 as _RK45

#: tolerance of the consistency checks (the coefficients are given to about 16 digits)
CHECK_TOL = 1e-13


def _freeze(method, names: tuple) -> None:
    """The attributes ``names`` of the frozen dataclass ``method`` as read-only float arrays."""
    for attr in names:
        arr = np.array(getattr(method, attr), dtype=float)
        arr.flags.writeable = False
        object.__setattr__(method, attr, arr)


def _butcher_problems(A, b, c) -> list:
    """What is wrong with the Butcher tableau ``(A, b, c)``: shapes, rows of ``A`` not summing to ``c``, weights
    not summing to one."""
    s = c.size
    if A.shape != (s, s) or b.shape != (s,):
        return [f"shapes: c {c.shape}, A {A.shape} (want ({s}, {s})), b {b.shape} (want ({s},))"]
    out = []
    rows = A.sum(axis=1)
    bad = np.flatnonzero(np.abs(rows - c) > CHECK_TOL)
    if bad.size:
        out.append(f"rows {bad.tolist()} of A do not sum to c (sums {rows[bad].tolist()}, c {c[bad].tolist()})")
    if abs(b.sum() - 1.0) > CHECK_TOL:
        out.append(f"weights b sum to {b.sum()!r}, not 1")
    return out


def _refuse(kind: str, name: str, problems: list) -> None:
    if problems:
        raise ValueError(f"{kind} {name!r} is inconsistent: " + "; ".join(problems))


@dataclass(frozen=True, eq=False)
class ExplicitTableau:
    """An embedded explicit Runge--Kutta pair with dense output, run by the adaptive integrator.

    Stage ``j < s`` is ``K_j = f(t + c_j h, y + h sum_i A[j, i] K_i)``, the step ``y_new = y + h sum_j b_j K_j``,
    and ``K_s = f(t + h, y_new)`` the last term of the error estimate and the next step's first stage.

    Attributes
    ----------
    name : str, the registry name (the ``method`` of :func:`knifeedge.simulate`).
    c : (s,) nodes, ``c[0] == 0``.
    A : (s, s) strictly lower-triangular stage coefficients.
    b : (s,) weights of the step.
    e : (s + 1,) error estimator: ``h sum_j e_j K_j`` over the stages and ``K_s = f(t + h, y_new)``.
    order : order of the step.
    error_order : order of the embedded estimate (the step-size controller uses ``-1/(error_order + 1)``).
    P : (s + 1, m) dense output ``y(t + x h) = y + h sum_j K_j sum_r P[j, r] x^(r + 1)``;
        ``None`` when the method has Hairer's DOP853 interpolant (``hairer``).
    hairer : dict or None, DOP853 only: its 3rd-order estimator ``e3``, the extra stages of its dense output
        (``c_ext``, ``A_ext`` rows over all earlier stages) and the interpolant's matrix ``D``.
    description, reference : str
    """

    #: the kernel that runs it (:func:`knifeedge.integrators.load_kernel`) and whether it takes a step ``h``
    kind: ClassVar[str] = "erk"
    fixed_step: ClassVar[bool] = False
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
        _freeze(self, ("c", "A", "b", "e") + (("P",) if self.P is not None else ()))
        _refuse("tableau", self.name, _tableau_problems(self))

    @property
    def stages(self) -> int:
        """Stages per step (the first-same-as-last evaluation not counted)."""
        return self.c.size


def _tableau_problems(t: ExplicitTableau) -> list:
    s = t.c.size
    out = [] if isinstance(t.name, str) and t.name.isidentifier() else [f"name must be an identifier, got {t.name!r}"]
    out += _butcher_problems(t.A, t.b, t.c)
    if t.e.shape != (s + 1,):
        out.append(f"shapes: e {t.e.shape} (want ({s + 1},))")
    if any(p.startswith("shapes") for p in out):
        return out
    if t.c[0] != 0.0:
        out.append(f"c[0] must be 0, got {t.c[0]!r}")
    if np.any(np.triu(t.A) != 0.0):
        out.append("A must be strictly lower triangular (an explicit method)")
    if abs(t.e.sum()) > CHECK_TOL:
        out.append(f"error estimator e sums to {t.e.sum()!r}, not 0 (it must vanish on constant derivatives)")
    if not (isinstance(t.order, int) and isinstance(t.error_order, int) and 0 < t.error_order < t.order):
        out.append(f"orders: need 0 < error_order < order, got {t.error_order!r}, {t.order!r}")
    if (t.P is None) == (t.hairer is None):
        out.append("give exactly one dense output: P (power series) or hairer (DOP853's)")
    elif t.P is not None:
        if t.P.ndim != 2 or t.P.shape[0] != s + 1:
            out.append(f"P must have {s + 1} rows, got shape {t.P.shape}")
        elif np.any(np.abs(t.P.sum(axis=1) - np.append(t.b, 0.0)) > CHECK_TOL):  # the interpolant at x = 1
            out.append("the dense output at x = 1 is not the step (rows of P must sum to b, then 0)")
    return out


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

    kind: ClassVar[str] = "fixed"
    fixed_step: ClassVar[bool] = True
    name: str
    A: np.ndarray
    b: np.ndarray
    c: np.ndarray
    order: int
    description: str
    denominator: float = 1.0

    def __post_init__(self):
        _freeze(self, ("A", "b", "c"))
        problems = _butcher_problems(self.A, self.b, self.c)
        if not problems and np.any((self.b * self.denominator) / self.denominator != self.b):
            problems.append(f"the weights times the denominator {self.denominator!r} are not exact")
        _refuse("method", self.name, problems)

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
        return (self.stages == 4 and np.array_equal(self.A, RK4.A) and np.array_equal(self.b, RK4.b)
                and np.array_equal(self.c, RK4.c))

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


#: the registered methods by name (adaptive and fixed-step), in the order registered
COMPILED_METHODS: dict = {}
#: other accepted names of compiled methods
ALIASES = {"RK45": "DP54"}


def register(method):
    """Register ``method`` (an :class:`ExplicitTableau` or a :class:`FixedMethod`) under its name (a name is
    registered once)."""
    if not isinstance(method, (ExplicitTableau, FixedMethod)):
        raise TypeError(f"`method` must be an ExplicitTableau or a FixedMethod, got {type(method).__name__}")
    if method.name in COMPILED_METHODS and COMPILED_METHODS[method.name] is not method:
        raise ValueError(f"a method named {method.name!r} is already registered")
    COMPILED_METHODS[method.name] = method
    return method


def get(name: str, kind: str | None = None):
    """The registered method called ``name`` (or its alias), of ``kind`` (``"erk"``, ``"fixed"``) if given."""
    method = COMPILED_METHODS.get(ALIASES.get(name, name))
    if method is None or kind not in (None, method.kind):
        known = sorted(n for n, m in COMPILED_METHODS.items() if kind in (None, m.kind))
        raise ValueError(f"unknown {kind or 'compiled'} method {name!r}; registered: {', '.join(known)}")
    return method


def erk_arrays(name: str) -> SimpleNamespace:
    """The tables of the registered adaptive method ``name`` as the integrator and a model's parts read them.

    ``A``, ``C`` over all ``n_ext`` stages (the method's ``n_stages``, the weights as the stage at ``t + h``, then
    DOP853's extra dense-output stages); ``E5`` the error estimator, ``E3`` DOP853's second one (else None);
    ``DD`` DOP853's interpolant or ``P`` the others' power series (the other one None); ``dense_rows``
    and ``alt``: the rows of the interpolant ``F`` and their Horner factors (:mod:`.common`); ``rows``: the
    integrator's one array (the workspace, its one layout), where each of its arrays starts, in rows of ``n``
    (the state's size): ``K`` (``n_ext`` rows) at 0, ``y``, ``y_new``, ``work``, ``scale`` (one row each),
    ``F`` (``dense_rows``), then ``q``.
    """
    t = get(name, "erk")
    hairer = t.hairer is not None
    s = t.stages
    n_ext = s + 1 + (t.hairer["c_ext"].size if hairer else 0)
    A = np.zeros((n_ext, n_ext))
    A[:s, :s] = t.A
    A[s, :s] = t.b
    C = np.ones(n_ext)
    C[:s] = t.c
    E3 = DD = P = None
    if hairer:
        A[s + 1:] = t.hairer["A_ext"]
        C[s + 1:] = t.hairer["c_ext"]
        E3, DD = t.hairer["e3"].copy(), t.hairer["D"].copy()
        dense_rows = 3 + DD.shape[0]
    else:
        P = t.P.copy()
        dense_rows = P.shape[1]
    alt = np.array([hairer and r % 2 == 1 for r in range(dense_rows)])
    rows = {"y": n_ext, "y_new": n_ext + 1, "work": n_ext + 2, "scale": n_ext + 3, "F": n_ext + 4,
            "q": n_ext + 4 + dense_rows}
    return SimpleNamespace(name=name, A=A, C=C, E5=t.e.copy(), E3=E3, DD=DD, P=P, hairer=hairer, n_stages=s,
                           n_ext=n_ext, dense_rows=dense_rows, alt=alt, error_order=t.error_order, rows=rows)


def erk_fingerprint(name: str) -> str:
    """A SHA-256 of :func:`erk_arrays` of ``name``: the tables the stages' IR (generated/stages.py) was written
    from must be the registered ones."""
    tab = erk_arrays(name)
    data = [repr((k, v.shape, v.tobytes()) if isinstance(v, np.ndarray) else (k, v)) for k, v in vars(tab).items()]
    return hashlib.sha256("".join(data).encode()).hexdigest()


# -- the methods -----------------------------------------------------------------------------------------------
#: Dormand-Prince 5(4), the tables of SciPy's ``RK45`` (lyapunov.py reads them): ``DP54_A`` (6 x 5), ``DP54_E``
#: over the 6 stages and f at the new point, ``DP54_P`` the dense output ``y + h sum_j (K^T P)[:, j] x^(j + 1)``
DP54_C, DP54_A, DP54_B, DP54_E, DP54_P = _RK45.C, _RK45.A, _RK45.B, _RK45.E, _RK45.P

_S3 = math.sqrt(3.0)
_S15 = math.sqrt(15.0)
#: stages -> (A, b, c) of the Gauss--Legendre method of order 2 s: symmetric, keeps quadratic invariants (Hairer,
#: Lubich & Wanner, Geometric Numerical Integration, Table II.1.1 and Sect. II.1.3)
GAUSS = {
    1: (np.array([[0.5]]), np.array([1.0]), np.array([0.5])),
    2: (
        np.array([[0.25, 0.25 - _S3 / 6], [0.25 + _S3 / 6, 0.25]]),
        np.array([0.5, 0.5]),
        np.array([0.5 - _S3 / 6, 0.5 + _S3 / 6]),
    ),
    3: (
        np.array([
            [5 / 36, 2 / 9 - _S15 / 15, 5 / 36 - _S15 / 30],
            [5 / 36 + _S15 / 24, 2 / 9, 5 / 36 - _S15 / 24],
            [5 / 36 + _S15 / 30, 2 / 9 + _S15 / 15, 5 / 36],
        ]),
        np.array([5 / 18, 4 / 9, 5 / 18]),
        np.array([0.5 - _S15 / 10, 0.5, 0.5 + _S15 / 10]),
    ),
}


def _tsit5() -> ExplicitTableau:
    """Tsit5: the stages, weights and embedded 4th-order weights ``B_HAT`` (the 7th over K_s = f(t + h, y_new))
    of Tsitouras (2011); ``P[j, r]`` the coefficient of ``x^(r+1)`` in the continuous weight ``b_j(x)`` (Sect. 3).
    """
    C = [0.0, 0.161, 0.327, 0.9, 0.9800255409045096857298102862870245954942, 1.0]
    A = np.zeros((6, 6))
    A[1, 0] = 0.161
    A[2, :2] = [-0.008480655492356988544426874250230774675121, 0.3354806554923569885444268742502307746751]
    A[3, :3] = [2.897153057105493432130432594192938764925, -6.359448489975074843148159912383825625953,
                4.362295432869581411017727318190886861028]
    A[4, :4] = [5.325864828439256604428877920840511317836, -11.74888356406282787774717033978577296189,
                7.495539342889836208304604784564358155659, -0.09249506636175524925650207933207191611350]
    A[5, :5] = [5.861455442946420028659251486982647890394, -12.92096931784710929170611868178335939542,
                8.159367898576158643180400794539253485182, -0.07158497328140099722453054252582973869127,
                -0.02826905039406838290900305721271224146718]
    B = np.array([0.09646076681806522951816731316512876333712, 0.01, 0.4798896504144995747752495322905965199130,
                  1.379008574103741893192274821856872770756, -3.290069515436080679901047585711363850116,
                  2.324710524099773982415355918398765796109])
    B_HAT = np.array([0.09468075576583945807478876255758922856118, 0.009183565540343253096776363936645313759814,
                      0.4877705284247615707855642599631228241517, 1.234297566930478985655109673884237654036,
                      -2.707712349983525454881109975059321670690, 1.866628418170587035753719399566211498666,
                      1 / 66])
    x = [0.0, 1.0]  # the polynomial x
    factored = [  # b_j(x) = scale * product of factors (polynomials in x, lowest degree first)
        (-1.0530884977290216, [x, [-1.3299890189751412, 1.0], [0.7139816917074209, -1.4364028541716351, 1.0]]),
        (0.1017, [x, x, [1.2949852507374631, -2.1966568338249754, 1.0]]),
        (2.490627285651252793, [x, x, [1.57803468208092486, -2.38535645472061657, 1.0]]),
        (-16.54810288924490272, [x, x, [-1.21712927295533244, 1.0], [-0.61620406037800089, 1.0]]),
        (47.37952196281928122, [x, x, [-1.203071208372362603, 1.0], [-0.658047292653547382, 1.0]]),
        (-34.87065786149660974, [x, x, [-1.2, 1.0], [-0.666666666666666667, 1.0]]),
        (2.5, [x, x, [-1.0, 1.0], [-0.6, 1.0]]),
    ]
    P = np.zeros((7, 4))
    for j, (scale, factors) in enumerate(factored):
        p = np.array([scale])
        for f in factors:
            p = _poly.polymul(p, f)
        P[j, : p.size - 1] = p[1:]  # no constant term
    # the published factors are rounded to ~16 digits: make b_j(1) equal the weights exactly
    P[:6, -1] += B - P[:6].sum(axis=1)
    P[6, -1] -= P[6].sum()
    return ExplicitTableau(
        name="Tsit5", c=C, A=A, b=B, e=np.append(B, 0.0) - B_HAT, order=5, error_order=4, P=P,
        description="Tsitouras 5(4), 7 stages (first same as last), dense output of order 4",
        reference="Ch. Tsitouras, Comput. Math. Appl. 62 (2011) 770-775",
    )


DOP853 = register(ExplicitTableau(  # SciPy's DOP853: its 12 stages, then 3 extra stages of the dense output
    name="DOP853", c=_DOP853.C, A=_DOP853.A, b=_DOP853.B, e=_DOP853.E5, order=8, error_order=7, P=None,
    hairer={"e3": _DOP853.E3, "c_ext": _DOP853.C_EXTRA, "A_ext": _DOP853.A_EXTRA, "D": _DOP853.D},
    description="Dormand-Prince 8(5,3), Hairer's DOP853, dense output of order 7",
    reference="E. Hairer, S. P. Norsett, G. Wanner, Solving ODEs I, Sect. II.10; Hairer's Fortran DOP853",
))
DP54 = register(ExplicitTableau(
    name="DP54", c=DP54_C, A=np.pad(DP54_A, ((0, 0), (0, 1))), b=DP54_B, e=DP54_E, order=5, error_order=4,
    P=DP54_P, description="Dormand-Prince 5(4), dense output of order 4 (SciPy's RK45)",
    reference="J. R. Dormand, P. J. Prince, J. Comput. Appl. Math. 6 (1980) 19-26; Shampine, Math. Comp. 46 (1986)",
))
TSIT5 = register(_tsit5())
RK4 = register(FixedMethod("RK4", np.diag([0.5, 0.5, 1.0], k=-1), [1 / 6, 1 / 3, 1 / 3, 1 / 6], [0.0, 0.5, 0.5, 1.0], 4,
                           "classical Runge-Kutta, fixed step", 6.0))
IMPLICIT_MIDPOINT = register(FixedMethod("implicit_midpoint", *GAUSS[1], 2,
                                         "implicit midpoint rule (Gauss-Legendre, 1 stage)"))
GAUSS4 = register(FixedMethod("gauss4", *GAUSS[2], 4, "Gauss-Legendre collocation, 2 stages, order 4"))
GAUSS6 = register(FixedMethod("gauss6", *GAUSS[3], 6, "Gauss-Legendre collocation, 3 stages, order 6"))
