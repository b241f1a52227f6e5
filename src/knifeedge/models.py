"""Model registry: :func:`load` returns a :class:`Model` backed by a generated module.

Everything a model knows (state and parameter names, units, admissible
parameters, defaults, which crossings are events, the compiled functions)
comes from the module that ``make derive`` wrote into ``knifeedge.generated``,
or that ``knifeedge derive`` wrote into a folder of the user's (``load(...,
path=DIR)``); nothing is derived at run time and no model is named here.
"""
from __future__ import annotations

import hashlib
import importlib
import importlib.util
import math
import sys
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from . import _validate, bodies, modulecheck
from .generated import MODULES

MODEL_NAMES = tuple(sorted({m for m, _ in MODULES}))
FIDELITIES = tuple(sorted({f for _, f in MODULES}))
#: what a generated module must define for the runtime (older modules lack some: regenerate them)
REQUIRED_METADATA = ("MODEL", "FIDELITY", "STATE_NAMES", "STATE_UNITS", "POSE_NAMES", "PARAM_NAMES", "PARAM_UNITS",
                     "PARAM_DOMAINS", "DEFAULT_PARAMS", "DEFAULT_STATE", "RATE_PAIRS", "TILT_NAMES",
                     "REVERSAL_EVENTS", "EVENT_NAMES", "VALIDITY", "MULTIPLIER_NAMES", "HAS_DISSIPATION", "EXPORTS")


class ValidityWarning(UserWarning):
    """A result left the domain where its model's fidelity holds (``Model.validity``)."""


class Model:
    """A generated model at one fidelity, with or without the pose.

    Attributes
    ----------
    name, fidelity : str
    pose : bool
        When true the state carries :attr:`pose_names` after the closed state.
    state_names, state_units : tuple of str
        Names and units of the state (closed state, then the pose if ``pose``).
    closed_state_names : tuple of str
    pose_names, pose_units : tuple of str
    pose_doc : str
        What the pose coordinates mean.
    param_names, param_units : tuple of str
    param_domains : tuple of str
        ``"positive"`` (the parameter must be > 0) or ``"real"`` (any finite value).
    default_params, default_state : dict
        The model's default parameter set and initial closed state (may be empty).
    rate_pairs : tuple of (str, str)
        ``(coordinate, rate)`` pairs of the closed state.
    tilt_names : tuple of str
        The small coordinates (tilts) of the small-angle fidelities.
    reversal_events : tuple of str
        States (or :attr:`event_names`) whose zero crossings are ``reversal_times``.
    spin_name : str or None
        The first of :attr:`reversal_events` if it is a state, else ``None``.
    event_names : tuple of str
        Scalar event functions of the state the module defines (``event_values``).
    validity : dict
        Largest ``|value|`` of each named state where this fidelity holds (empty: everywhere);
        ``validity_doc`` says why.
    multiplier_names : tuple of str
        The constraints whose multipliers :meth:`multipliers` returns.
    has_dissipation : bool
        The model has non-conservative forces (:meth:`power_dissipated`).
    exports : tuple of str
        Model-specific helpers of the module (``model.module.<name>``).
    rhs : compiled function ``rhs(t, y, p) -> ndarray``
        Also callable from other numba code.
    rhs_into : compiled function ``rhs_into(t, y, p, dy)`` writing into ``dy``.
    module : the generated module.
    source_path : Path or None
        The module's file when loaded with ``load(..., path=...)``.
    """

    def __init__(self, module, pose: bool, source_path: Path | None = None):
        missing = [a for a in REQUIRED_METADATA if not hasattr(module, a)]
        if missing:
            raise ValueError(f"generated module {getattr(module, '__file__', module)} lacks {missing}: it was written "
                             f"by an older knifeedge; regenerate it (make derive, or knifeedge derive)")
        self.module = mod = module
        self.name: str = mod.MODEL
        self.fidelity: str = mod.FIDELITY
        self.pose = bool(pose)
        self.source_path = source_path
        if self.pose and not mod.POSE_NAMES:
            raise ValueError(f"`pose=True` needs a model with a pose; {self.name} at fidelity {self.fidelity!r} has none")
        self.fidelity_doc: str = getattr(mod, "FIDELITY_DOC", "")
        self.closed_state_names: tuple = mod.STATE_NAMES
        self.pose_names: tuple = mod.POSE_NAMES
        self.pose_units: tuple = getattr(mod, "POSE_UNITS", ())
        self.pose_doc: str = getattr(mod, "POSE_DOC", "")
        self.state_names: tuple = mod.STATE_NAMES + (mod.POSE_NAMES if self.pose else ())
        self.state_units: tuple = mod.STATE_UNITS + (self.pose_units if self.pose else ())
        self.param_names: tuple = mod.PARAM_NAMES
        self.param_units: tuple = mod.PARAM_UNITS
        self.param_domains: tuple = mod.PARAM_DOMAINS
        self.default_params: dict = dict(mod.DEFAULT_PARAMS)
        self.default_state: dict = dict(mod.DEFAULT_STATE)
        self.rate_pairs: tuple = mod.RATE_PAIRS
        self.tilt_names: tuple = mod.TILT_NAMES
        self.reversal_events: tuple = mod.REVERSAL_EVENTS
        self.event_names: tuple = mod.EVENT_NAMES
        self.spin_name: str | None = next((e for e in mod.REVERSAL_EVENTS if e in mod.STATE_NAMES), None)
        self.validity: dict = dict(mod.VALIDITY)
        self.validity_doc: str = getattr(mod, "VALIDITY_DOC", "")
        self.multiplier_names: tuple = mod.MULTIPLIER_NAMES
        self.has_dissipation: bool = bool(mod.HAS_DISSIPATION)
        #: the equations depend on the time explicitly: energy, multipliers, pose rates and powers need ``t``
        self.time_dependent: bool = bool(getattr(mod, "TIME_DEPENDENT", False))
        self.has_power_input: bool = bool(getattr(mod, "HAS_POWER_INPUT", False))
        #: holonomic constraints whose values :meth:`holonomic_residual` gives
        self.holonomic_names: tuple = tuple(getattr(mod, "HOLONOMIC_NAMES", ()))
        #: quantities given at run time (``simulate(..., inputs=...)``, :mod:`knifeedge.inputs`)
        self.input_names: tuple = tuple(getattr(mod, "INPUT_NAMES", ()))
        self.exports: tuple = mod.EXPORTS
        self._positive = tuple(d == "positive" for d in mod.PARAM_DOMAINS)
        self._nonnegative = tuple(d == "nonnegative" for d in mod.PARAM_DOMAINS)
        #: named parameter sets the module ships (``preset``)
        self.preset_names: tuple = tuple(sorted(getattr(mod, "PRESETS", {})))
        self.rhs = mod.rhs_pose if self.pose else mod.rhs
        self.rhs_into = mod.rhs_pose_into if self.pose else mod.rhs_into

    def __repr__(self) -> str:
        where = f", path={str(self.source_path.parent)!r}" if self.source_path is not None else ""
        return f"knifeedge.load({self.name!r}, fidelity={self.fidelity!r}, pose={self.pose}{where})"

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
        mapping.  Every parameter is required; each must be finite, and
        positive where :attr:`param_domains` says ``"positive"``.
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
            if self._positive[i] and not out[i] > 0:
                raise ValueError(f"parameter `{n}` must be positive, got {values[n]!r}")
            if self._nonnegative[i] and not out[i] >= 0:
                raise ValueError(f"parameter `{n}` must be nonnegative, got {values[n]!r}")
        return self._physical(out)

    def _physical(self, p: np.ndarray) -> np.ndarray:
        """``p``, if the module (a rigid body's: ``body_values``) says it describes a body that can exist."""
        values = getattr(self.module, "body_values", None)
        problems = bodies.problems(*values(p)) if values is not None else ()
        if problems:
            raise ValueError(f"parameters `p` of {self.name} describe no rigid body: {'; '.join(problems)}")
        return p

    def preset(self, name: str, /, **overrides) -> np.ndarray:
        """Validated parameter vector of a named parameter set the module ships; keywords override.

        ``m.preset("kane_levinson_1982", sigma=1e-4)``; the names are in :attr:`preset_names`.
        """
        presets = getattr(self.module, "PRESETS", {})
        if not isinstance(name, str) or name not in presets:
            accepted = ", ".join(self.preset_names) or "none"
            raise ValueError(f"unknown preset `name` {name!r} for {self.name}; accepted: {accepted}")
        unknown = [k for k in overrides if k not in self.param_names]
        if unknown:
            raise ValueError(f"unknown parameters {unknown} in the overrides of preset {name!r}; "
                             f"expected some of {self.param_names}")
        return self.params({**presets[name], **overrides})

    def initial_state(self, **physical) -> np.ndarray:
        """Initial state from a physical description, through the module's ``initial_state``.

        The keywords are the module's (for a rigid body: ``n0``, the upward vertical in body axes,
        normalized; ``omega0``, the angular velocity in body axes).  With ``pose=True`` the pose
        (zero unless ``pose=(...)`` is given) is appended.
        """
        build = getattr(self.module, "initial_state", None)
        if build is None:
            raise ValueError(f"{self.name} at fidelity {self.fidelity!r} has no physical initial-state builder; "
                             "use `state(...)`")
        if self.pose:
            physical.setdefault("pose", (0.0,) * len(self.pose_names))
        elif physical.get("pose") is not None:
            raise ValueError("`pose` needs a model loaded with `pose=True`")
        else:
            physical.pop("pose", None)
        return self.check_state(build(**physical))

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
        for positive, nonneg, v in zip(self._positive, self._nonnegative, values):
            if not math.isfinite(v) or (positive and not v > 0) or (nonneg and not v >= 0):
                return self.params(dict(zip(self.param_names, values)))  # raises, naming the parameter
        return self._physical(np.array(values))

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
    def _at(self, function, y, p, t, what: str, inputs=None):
        """``function(y, p)`` (``(y, p, t)`` for a :attr:`time_dependent` model) of one state or of each column.

        ``inputs`` (a model with :attr:`input_names`): a mapping as ``simulate`` takes, or a run's
        ``SimulationResult.inputs``; their values at each ``t`` are appended to ``p``."""
        if self.input_names:
            return self._at_inputs(function, y, p, t, what, inputs)
        if not self.time_dependent:
            if y.ndim == 1:
                return function(y, p)
            return [function(np.ascontiguousarray(y[:, k]), p) for k in range(y.shape[1])]
        if t is None:
            raise ValueError(f"{what} of {self.name} depends on the time: pass `t` (one time per state)")
        t = np.broadcast_to(np.asarray(t, dtype=float), y.shape[1:])
        if y.ndim == 1:
            return function(y, p, float(t))
        return [function(np.ascontiguousarray(y[:, k]), p, float(t[k])) for k in range(y.shape[1])]

    def _at_inputs(self, function, y, p, t, what: str, inputs):
        from . import inputs as _inputs

        if t is None:
            raise ValueError(f"{what} of {self.name} depends on the time: pass `t` (one time per state)")
        inp = inputs if isinstance(inputs, _inputs.Inputs) else _inputs.check(self, inputs)
        t = np.broadcast_to(np.asarray(t, dtype=float), y.shape[1:])
        inp.cover(float(np.min(t)), float(np.max(t)), what="`t`")
        if y.ndim == 1:
            return function(y, inp.parameters(p, float(t)), float(t))
        return [function(np.ascontiguousarray(y[:, k]), inp.parameters(p, float(t[k])), float(t[k]))
                for k in range(y.shape[1])]

    def energy(self, y, p, t=None, inputs=None) -> float | np.ndarray:
        """Energy per unit mass; ``y`` of shape (n_state,) or (n_state, n_times).

        ``t`` (a time, or one per state): needed when the model is :attr:`time_dependent`, whose energy is
        not conserved but changes at the rate ``power_input - power_dissipated``.
        """
        needs_pose = bool(getattr(self.module, "ENERGY_NEEDS_POSE", False))
        if needs_pose and not self.pose:
            raise ValueError(f"the energy of {self.name} holds a potential of the pose coordinates "
                             f"{self.pose_names}: load the model with `pose=True` and pass the pose-extended state")
        y, p = self._states(y, pose=needs_pose), self.check_params(p)
        e = self._at(self.module.energy, y, p, t, "the energy", inputs)
        return float(e) if y.ndim == 1 else np.array(e)

    def multipliers(self, y, p, t=None, inputs=None) -> np.ndarray:
        """Lagrange multipliers (contact forces per unit mass), in :attr:`multiplier_names` order.

        ``y`` of shape (n_state,) gives shape (n_constraints,); (n_state, n_times)
        gives (n_constraints, n_times).
        """
        if not self.multiplier_names:
            raise ValueError(f"{self.name} at fidelity {self.fidelity!r} has no multipliers")
        y, p = self._states(y), self.check_params(p)
        lam = self._at(self.module.multipliers, y, p, t, "the multipliers", inputs)
        return lam if y.ndim == 1 else np.stack(lam, 1)

    def pose_rates(self, y, p, t=None, inputs=None) -> np.ndarray:
        """Rates of the pose coordinates :attr:`pose_names` at a pose-extended state (needs ``pose=True``)."""
        if not self.pose:
            raise ValueError("pose_rates needs the pose: load the model with `pose=True`")
        y = self._states(y, pose=True)
        if y.ndim != 1:
            raise ValueError(f"`y` must be one state of shape ({self.n_state},), got shape {y.shape}")
        return self._at(self.module.pose_rates, y, self.check_params(p), t, "the pose rates", inputs)

    def _states(self, y, pose: bool = False) -> np.ndarray:
        """``y`` as finite float64 of shape (n, ) or (n, n_times): ``n`` the state's size, or the closed
        state's (without the pose) unless ``pose``; the compiled functions do not check their bounds."""
        if isinstance(y, np.ndarray) and y.dtype == np.float64 and y.ndim in (1, 2):
            arr = y
        elif isinstance(y, Mapping):
            raise TypeError(f"`y` must be an array of states in the order of {self.state_names}; for a mapping of "
                            f"names to values use model.state(...)")
        else:
            arr = _validate.real_array(y, "`y`")
        sizes = (self.n_state,) if pose else tuple(sorted({self.n_state, len(self.closed_state_names)}))
        if arr.ndim not in (1, 2) or arr.shape[0] not in sizes:
            want = " or ".join(f"({n},) or ({n}, n_times)" for n in sizes)
            raise ValueError(f"`y` must have shape {want} for {self.state_names}, got shape {arr.shape}")
        if not np.isfinite(arr).all():
            raise ValueError("`y` must be finite")
        return np.ascontiguousarray(arr)

    def jacobian(self, y, p, t=None, inputs=None) -> np.ndarray:
        """``d rhs / d y`` of the closed state at ``y`` (generated exactly, ``derivation/jacobian.py``).

        ``y``: the closed state, or the pose-extended state (its pose is ignored: the closed state's rates
        do not depend on it).  Returns shape (n_closed, n_closed), ``J[i, j] = d rate_i / d y_j``.
        ``t``: the time, needed when the rates depend on it explicitly (:attr:`jacobian_needs_time`).
        """
        return self._jacobian("jacobian", y, p, t, inputs)

    def jacobian_p(self, y, p, t=None, inputs=None) -> np.ndarray:
        """``d rhs / d p`` of the closed state at ``y``: shape (n_closed, n_params), ``J[i, j] = d rate_i / d p_j``."""
        return self._jacobian("jacobian_p", y, p, t, inputs)[:, :len(self.param_names)]

    @property
    def jacobian_needs_time(self) -> bool:
        """The rates depend on the time explicitly: the Jacobians take it as a third argument."""
        jacobian = getattr(self.module, "jacobian", None)
        return jacobian is not None and jacobian.py_func.__code__.co_argcount == 3

    def _jacobian(self, name: str, y, p, t, inputs=None):
        y = self._closed(y)  # refuses a module written without Jacobians
        p = self.check_params(p)
        function = getattr(self.module, name)
        if self.input_names:
            return self._at_inputs(function, y, p, t, "the Jacobian", inputs)
        if not self.jacobian_needs_time:
            return function(y, p)
        if t is None:
            raise ValueError(f"the Jacobian of {self.name} depends on the time: pass `t`")
        return function(y, p, float(t))

    def _closed(self, y) -> np.ndarray:
        if not hasattr(self.module, "invariant_gradients"):
            raise ValueError(f"the module of {self.name} ({self.fidelity}) was written without Jacobians and steady "
                             f"motions by an older knifeedge: regenerate it (make derive, or knifeedge derive)")
        y = self._states(y)
        if y.ndim != 1:
            raise ValueError(f"`y` must be one state of shape ({len(self.closed_state_names)},), got shape {y.shape}")
        return np.ascontiguousarray(y[:len(self.closed_state_names)])

    def frequencies(self, p) -> np.ndarray:
        """Angular frequencies of the small oscillations of :attr:`tilt_names` at zero spin (1/time).

        Only models whose tilts oscillate have them (``hasattr(model.module, "frequencies")``).
        """
        if not hasattr(self.module, "frequencies"):
            raise ValueError(f"{self.name} at fidelity {self.fidelity!r} has no oscillating modes (no `frequencies`)")
        return self.module.frequencies(self.check_params(p))

    def power_dissipated(self, y, p, t=None, inputs=None) -> float | np.ndarray:
        """Rate at which the non-conservative forces remove :meth:`energy`; 0 for a conservative model.

        ``energy(t) + integral_0^t power_dissipated dt = energy(0)`` along a run.
        ``y`` of shape (n_state,) or (n_state, n_times).
        """
        y, p = self._states(y), self.check_params(p)
        if not self.has_dissipation:
            return 0.0 if y.ndim == 1 else np.zeros(y.shape[1])
        power = self._at(self.module.power_dissipated, y, p, t, "the dissipated power", inputs)
        return float(power) if y.ndim == 1 else np.array(power)

    def power_input(self, y, p, t=None, inputs=None) -> float | np.ndarray:
        """Rate at which the explicit time, rheonomic constraints and inputs add :meth:`energy`; 0 if none.

        ``energy(t) = energy(0) + integral_0^t (power_input - power_dissipated) dt`` along a run.
        """
        y, p = self._states(y), self.check_params(p)
        if not self.has_power_input:
            return 0.0 if y.ndim == 1 else np.zeros(y.shape[1])
        power = self._at(self.module.power_input, y, p, t, "the input power", inputs)
        return float(power) if y.ndim == 1 else np.array(power)

    def holonomic_residual(self, y, p, t=None, inputs=None) -> np.ndarray:
        """Values of the holonomic constraints :attr:`holonomic_names` (zero on the constraint manifold).

        The run integrates their time derivative, so along a run they drift from zero by about the
        integrator's error; ``y`` of shape (n_state,) gives (n_holonomic,), (n_state, n_times) gives
        (n_holonomic, n_times).
        """
        if not self.holonomic_names:
            raise ValueError(f"{self.name} has no holonomic constraints")
        y, p = self._states(y), self.check_params(p)
        f = self._at(self.module.holonomic_residual, y, p, t, "the holonomic residual", inputs)
        return f if y.ndim == 1 else np.stack(f, 1)

    def dissipated_work(self, t, y, p) -> np.ndarray:
        """Energy removed by the non-conservative forces from ``t[0]`` to each ``t`` (trapezoidal rule on the samples).

        ``energy(y) + dissipated_work(t, y, p)`` is constant along a run, to the
        accuracy of the quadrature (sample the run densely, e.g. with ``t_eval``).
        """
        power = self.power_dissipated(y, p, t)
        t = np.asarray(t, dtype=float)
        out = np.zeros_like(t)
        if t.size > 1:
            out[1:] = np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(t))
        return out

    def event_values(self, y, p) -> np.ndarray:
        """Values of the model's scalar events :attr:`event_names` at the state ``y``."""
        if not self.event_names:
            raise ValueError(f"{self.name} defines no event functions")
        y = self._states(y)
        if y.ndim != 1:
            raise ValueError(f"`y` must be one state of shape ({len(self.closed_state_names)},), got shape {y.shape}")
        return self.module.event_values(y, self.check_params(p))

    def validity_excess(self, y) -> dict:
        """States that leave :attr:`validity`: ``{name: largest |value| reached}`` (empty when inside).

        ``y`` of shape (n_state,) or (n_state, n_times).
        """
        y = np.asarray(y, dtype=float)
        out = {}
        for name, bound in self.validity.items():
            if name not in self.state_names or y.size == 0:
                continue
            peak = float(np.max(np.abs(y[self.state_names.index(name)])))
            if peak > bound:
                out[name] = peak
        return out


def _finite_float(v, what: str) -> float:
    return _validate.finite(v, what)


def _float_array(v, what: str) -> np.ndarray:
    """Array of real numbers by the same rule as the mapping form (no bool, complex or strings)."""
    return _validate.real_array(v, what)


_CACHE: dict = {}


def _module_from_path(folder: Path, name: str, fidelity: str):
    """Import ``folder/<name>_<fidelity>.py`` under a name unique to its content; returns (module, path).

    The name and fidelity are confined to ``folder``; the module's content hash and sizes are verified
    (:func:`knifeedge.modulecheck.check`) before it runs.
    """
    for what, v in (("name", name), ("fidelity", fidelity)):
        if any(c in v for c in "/\\\0:") or v.startswith(".") or v != v.strip():
            raise ValueError(f"model `{what}` {v!r} must be a plain name (no path separators, no leading dot): "
                             f"models are files of the folder `path`")
    path = (folder / f"{name}_{fidelity}.py").resolve()
    if not path.is_file():
        have = sorted(p.stem for p in folder.glob("*_*.py"))
        raise ValueError(f"no module for model `name` {name!r} at `fidelity` {fidelity!r} in `path` {str(folder)!r} "
                         f"(expected {path.name}); it holds {', '.join(have) or 'no generated modules'}. "
                         f"Write it with: knifeedge derive MODEL_FILE.py --out {folder}")
    data = path.read_bytes()
    digest = hashlib.sha256(data).hexdigest()[:16]
    # a flat name (kernels import the right-hand side by it) that changes with the content
    mod_name = f"knifeedge_model_{name}_{fidelity}_{digest}"
    module = sys.modules.get(mod_name)
    if module is None:  # checked before it runs (a module of the same content was checked when imported)
        modulecheck.check(data, str(path), f"knifeedge derive MODEL_FILE.py --out {folder}", (name, fidelity))
        spec = importlib.util.spec_from_file_location(mod_name, path)
        module = importlib.util.module_from_spec(spec)
        sys.modules[mod_name] = module
        try:
            spec.loader.exec_module(module)
        except BaseException:
            del sys.modules[mod_name]
            raise
    if getattr(module, "MODEL", None) != name or getattr(module, "FIDELITY", None) != fidelity:
        raise ValueError(f"{path} declares model {getattr(module, 'MODEL', None)!r} at fidelity "
                         f"{getattr(module, 'FIDELITY', None)!r}, not {name!r} at {fidelity!r}")
    return module, path, digest


def available(path: str | Path | None = None) -> list:
    """``(model, fidelity)`` pairs available built in, or in the folder ``path``."""
    if path is None:
        return sorted(MODULES)
    folder = Path(path)
    out = []
    for p in sorted(folder.glob("*.py")):
        for fid in ("full", "reduced", "amplitude"):
            if p.stem.endswith("_" + fid):
                out.append((p.stem[: -len(fid) - 1], fid))
    return out


def load(name: str, fidelity: str = "full", pose: bool = False, path: str | Path | None = None) -> Model:
    """Load a generated model.

    Parameters
    ----------
    name : a built-in model (:data:`MODEL_NAMES`: ``"single_mode"``, paper
        section II; ``"two_mode"``, section III; ``"chaplygin_sleigh"``,
        section II.C) or, with ``path``, a model written there by
        ``knifeedge derive``.
    fidelity : ``"full"`` (exact consequences of the model's Lagrangian and
        constraints), ``"reduced"`` (small-angle truncation) or
        ``"amplitude"`` (the averaged slow flow of ``reduced``: no pose, no
        multipliers; ``energy`` is its conserved averaged energy).  Each
        model's module says what its fidelity is (``model.fidelity_doc``)
        and where it holds (``model.validity``).
    pose : append the pose coordinates (``model.pose_names``) to the state.
    path : folder of modules written by ``knifeedge derive FILE --out path``
        (default: the built-in models).  Such a model works like a built-in
        one: every method, the compiled-kernel cache (keyed by the module's
        content), sweeps and the CLI (``--path``).
    """
    if not isinstance(name, str) or not name:
        raise TypeError(f"model `name` must be a non-empty string, got {name!r}")
    if not isinstance(fidelity, str):
        raise TypeError(f"`fidelity` must be a string, got {fidelity!r}")
    if not isinstance(pose, (bool, np.bool_)):
        raise TypeError(f"`pose` must be True or False, got {pose!r}")
    if path is not None:
        if not isinstance(path, (str, Path)):
            raise TypeError(f"`path` must be a folder (str or Path), got {type(path).__name__}")
        folder = Path(path)
        if not folder.is_dir():
            raise ValueError(f"`path` {str(path)!r} is not a folder")
        module, file, digest = _module_from_path(folder, name, fidelity)
        key = (str(file), digest, bool(pose))
        if key not in _CACHE:
            _CACHE[key] = Model(module, bool(pose), source_path=file)
        return _CACHE[key]
    if name not in MODEL_NAMES:
        raise ValueError(f"unknown model `name` {name!r}; accepted: {', '.join(MODEL_NAMES)} "
                         f"(or a model of your own with `path=`)")
    if (name, fidelity) not in MODULES:
        accepted = sorted(f for m, f in MODULES if m == name)
        raise ValueError(f"unknown `fidelity` {fidelity!r} for {name}; accepted: {', '.join(accepted)}")
    key = (name, fidelity, bool(pose))
    if key not in _CACHE:
        module_name = f"{__package__}.generated.{MODULES[(name, fidelity)]}"
        origin = Path(importlib.util.find_spec(module_name).origin)
        modulecheck.check(origin.read_bytes(), str(origin), "make derive in the source tree, or reinstall knifeedge",
                          (name, fidelity))
        module = importlib.import_module(module_name)
        _CACHE[key] = Model(module, bool(pose))
    return _CACHE[key]
