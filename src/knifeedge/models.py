"""Model registry: :func:`load` returns a :class:`Model` backed by a generated module.

Everything a model knows (state and parameter names, their order, the
compiled functions) comes from the module that ``make derive`` wrote into
``knifeedge.generated``; nothing is derived at run time.
"""
from __future__ import annotations

import importlib
import math
from collections.abc import Mapping

import numpy as np

from . import _validate
from .generated import MODULES

MODEL_NAMES = tuple(sorted({m for m, _ in MODULES}))
FIDELITIES = tuple(sorted({f for _, f in MODULES}))
#: parameters that may take any finite value (angles); the others must be positive
SIGNED_PARAMS = frozenset({"alpha"})


class Model:
    """A knife-edge model at one fidelity, with or without the pose.

    Attributes
    ----------
    name, fidelity : str
    pose : bool
        When true the state carries ``("phi", "x", "y")`` after the closed state.
    state_names : tuple of str
    param_names : tuple of str
    tilt_names : tuple of str
        The small coordinates (tilt angles).
    spin_name : str
        The state whose zero crossings are spin reversals (``"phi_dot"``).
    multiplier_names : tuple of str
        The constraints whose multipliers :meth:`multipliers` returns.
    rhs : compiled function ``rhs(t, y, p) -> ndarray``
        Also callable from other numba code.
    rhs_into : compiled function ``rhs_into(t, y, p, dy)`` writing into ``dy``.
    module : the generated module.
    """

    def __init__(self, name: str, fidelity: str, pose: bool):
        self.name = name
        self.fidelity = fidelity
        self.pose = bool(pose)
        self.module = importlib.import_module(f"{__package__}.generated.{MODULES[(name, fidelity)]}")
        mod = self.module
        if self.pose and not mod.POSE_NAMES:
            raise ValueError(f"`pose=True` needs a model with a pose; {name} at fidelity {fidelity!r} has none")
        self.closed_state_names: tuple = mod.STATE_NAMES
        self.pose_names: tuple = mod.POSE_NAMES
        self.state_names: tuple = mod.STATE_NAMES + (mod.POSE_NAMES if self.pose else ())
        self.param_names: tuple = mod.PARAM_NAMES
        self.tilt_names: tuple = mod.TILT_NAMES
        self.spin_name: str = mod.SPIN_NAME
        self.multiplier_names: tuple = mod.MULTIPLIER_NAMES
        self.rhs = mod.rhs_pose if self.pose else mod.rhs
        self.rhs_into = mod.rhs_pose_into if self.pose else mod.rhs_into

    def __repr__(self) -> str:
        return f"knifeedge.load({self.name!r}, fidelity={self.fidelity!r}, pose={self.pose})"

    @property
    def n_state(self) -> int:
        return len(self.state_names)

    def index(self, name: str) -> int:
        """Position of a state variable in the state vector."""
        try:
            return self.state_names.index(name)
        except ValueError:
            raise KeyError(f"unknown state {name!r}; this model's states are {self.state_names}") from None

    # -- parameters and states -------------------------------------------------
    def params(self, values: Mapping | None = None, /, **kwargs) -> np.ndarray:
        """Validated float64 parameter vector in the order of :attr:`param_names`.

        Accepts keywords (``m.params(g=1.0, ell=1.0, L=2.0, D=0.5)``) or one
        mapping.  Every parameter is required; lengths and ``g`` must be
        positive and finite, ``alpha`` any finite angle (radians).
        """
        if values is not None and kwargs:
            raise TypeError("pass the parameters either as one mapping or as keywords, not both")
        if values is not None and not isinstance(values, Mapping):
            raise TypeError(f"parameters `p` must be a mapping of names to values (or keywords); for an array use "
                            f"check_params; got {type(values).__name__}")
        values = dict(values if values is not None else kwargs)
        missing = [n for n in self.param_names if n not in values]
        extra = [n for n in values if n not in self.param_names]
        if missing or extra:
            msg = []
            if missing:
                msg.append(f"missing {missing}")
            if extra:
                msg.append(f"unknown {extra}")
            raise ValueError(f"parameters `p` of {self.name}: {', '.join(msg)}; expected exactly {self.param_names}")
        out = np.empty(len(self.param_names))
        for i, n in enumerate(self.param_names):
            out[i] = _finite_float(values[n], f"parameter `{n}`")
            if n not in SIGNED_PARAMS and not out[i] > 0:
                raise ValueError(f"parameter `{n}` must be positive, got {values[n]!r}")
        return out

    def check_params(self, p) -> np.ndarray:
        """Validate a parameter vector or mapping; returns a float64 array."""
        if isinstance(p, Mapping):
            return self.params(p)
        arr = _float_array(p, "parameters `p`")
        if arr.shape != (len(self.param_names),):
            raise ValueError(
                f"parameters `p` must have shape ({len(self.param_names)},) for {self.param_names}, got {arr.shape}"
            )
        values = arr.tolist()
        for n, v in zip(self.param_names, values):
            if not math.isfinite(v) or (n not in SIGNED_PARAMS and not v > 0):
                return self.params(dict(zip(self.param_names, values)))  # raises, naming the parameter
        return np.array(values)

    def state(self, values: Mapping | None = None, /, **kwargs) -> np.ndarray:
        """Validated float64 state vector in the order of :attr:`state_names`.

        Every state is required except the pose, which defaults to zero.
        """
        if values is not None and kwargs:
            raise TypeError("pass the state either as one mapping or as keywords, not both")
        if values is not None and not isinstance(values, Mapping):
            raise TypeError(f"initial state `y0` must be a mapping of names to values (or keywords); for an array "
                            f"use check_state; got {type(values).__name__}")
        values = dict(values if values is not None else kwargs)
        defaults = {n: 0.0 for n in self.pose_names} if self.pose else {}
        missing = [n for n in self.state_names if n not in values and n not in defaults]
        extra = [n for n in values if n not in self.state_names]
        if missing or extra:
            msg = []
            if missing:
                msg.append(f"missing {missing}")
            if extra:
                msg.append(f"unknown {extra}")
            raise ValueError(f"initial state `y0` of {self.name}: {', '.join(msg)}; expected {self.state_names}")
        return np.array(
            [_finite_float(values.get(n, defaults.get(n)), f"initial state `{n}`") for n in self.state_names]
        )

    def check_state(self, y) -> np.ndarray:
        """Validate a state vector or mapping; returns a float64 array."""
        if isinstance(y, Mapping):
            return self.state(y)
        arr = _float_array(y, "initial state `y0`")
        if arr.shape != (self.n_state,):
            raise ValueError(
                f"initial state `y0` must have shape ({self.n_state},) for {self.state_names}, got {arr.shape}"
            )
        if not all(map(math.isfinite, arr.tolist())):
            raise ValueError("All components of the initial state `y0` must be finite.")
        return arr

    # -- compiled quantities ---------------------------------------------------
    def energy(self, y, p) -> float | np.ndarray:
        """Energy per unit mass; ``y`` of shape (n_state,) or (n_state, n_times)."""
        y, p = self._states(y), self.check_params(p)
        if y.ndim == 1:
            return float(self.module.energy(y, p))
        return np.array([self.module.energy(np.ascontiguousarray(y[:, k]), p) for k in range(y.shape[1])])

    def multipliers(self, y, p) -> np.ndarray:
        """Lagrange multipliers (contact forces per unit mass), in :attr:`multiplier_names` order.

        ``y`` of shape (n_state,) gives shape (n_constraints,); (n_state, n_times)
        gives (n_constraints, n_times).
        """
        if not self.multiplier_names:
            raise ValueError(f"{self.name} at fidelity {self.fidelity!r} has no multipliers")
        y, p = self._states(y), self.check_params(p)
        if y.ndim == 1:
            return self.module.multipliers(y, p)
        return np.stack([self.module.multipliers(np.ascontiguousarray(y[:, k]), p) for k in range(y.shape[1])], 1)

    def pose_rates(self, y, p) -> np.ndarray:
        """``(phi_dot, x_dot, y_dot)`` at a pose-extended state (needs ``pose=True``)."""
        if not self.pose:
            raise ValueError("pose_rates needs the pose: load the model with `pose=True`")
        y = self._states(y, pose=True)
        if y.ndim != 1:
            raise ValueError(f"`y` must be one state of shape ({self.n_state},), got shape {y.shape}")
        return self.module.pose_rates(y, self.check_params(p))

    def _states(self, y, pose: bool = False) -> np.ndarray:
        """``y`` as finite float64 of shape (n, ) or (n, n_times): ``n`` the state's size, or the closed
        state's (without the pose) unless ``pose``; the compiled functions do not check their bounds."""
        if isinstance(y, np.ndarray) and y.dtype == np.float64 and y.ndim in (1, 2):
            arr = y
        else:
            arr = _validate.real_array(y, "`y`")
        sizes = (self.n_state,) if pose else tuple(sorted({self.n_state, len(self.closed_state_names)}))
        if arr.ndim not in (1, 2) or arr.shape[0] not in sizes:
            want = " or ".join(f"({n},) or ({n}, n_times)" for n in sizes)
            raise ValueError(f"`y` must have shape {want} for {self.state_names}, got shape {arr.shape}")
        if not np.isfinite(arr).all():
            raise ValueError("`y` must be finite")
        return np.ascontiguousarray(arr)


def _finite_float(v, what: str) -> float:
    return _validate.finite(v, what)


def _float_array(v, what: str) -> np.ndarray:
    """Array of real numbers by the same rule as the mapping form (no bool, complex or strings)."""
    return _validate.real_array(v, what)


_CACHE: dict = {}


def load(name: str, fidelity: str = "full", pose: bool = False) -> Model:
    """Load a generated model.

    Parameters
    ----------
    name : ``"single_mode"`` (paper section II), ``"two_mode"`` (section III) or
        ``"chaplygin_sleigh"`` (the sleigh of section II.C, fidelity ``"full"`` only).
    fidelity : ``"full"`` (exact consequences of the paper's Lagrangian and
        constraints), ``"reduced"`` (small-angle truncation, the order of
        the paper's ``FINAL1``/``FINAL2`` and ``eqs_2modes``) or
        ``"amplitude"`` (the averaged slow flow of ``reduced``, paper
        ``Chap3``: no pose, no multipliers; ``energy`` is its conserved
        averaged energy).
    pose : append ``("phi", "x", "y")`` to the state; only scenes that look at
        the path on the table need it.
    """
    if not isinstance(name, str) or name not in MODEL_NAMES:
        raise ValueError(f"unknown model `name` {name!r}; accepted: {', '.join(MODEL_NAMES)}")
    if not isinstance(fidelity, str) or (name, fidelity) not in MODULES:
        accepted = sorted(f for m, f in MODULES if m == name)
        raise ValueError(f"unknown `fidelity` {fidelity!r} for {name}; accepted: {', '.join(accepted)}")
    if not isinstance(pose, (bool, np.bool_)):
        raise TypeError(f"`pose` must be True or False, got {pose!r}")
    key = (name, fidelity, bool(pose))
    if key not in _CACHE:
        _CACHE[key] = Model(name, fidelity, bool(pose))
    return _CACHE[key]
