"""``RunSpec``: one integration written as data.

A core notion, below scenes, sweeps, figures and the command line (imports
flow ``runspec`` <- ``scenes`` <- ``sweep`` / ``figures`` / ``cli``): model
name, fidelity, pose or not, parameters and initial state by name, time
span, method, tolerances, and the folder of a user's model (``path``) so
that a worker process can load it.
"""
from __future__ import annotations

import dataclasses
import math
import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import Any

import numpy as np

from . import _validate

#: most output samples a run may ask for (8 MB per state)
MAX_N_EVAL = 1_000_000
#: run settings that :meth:`RunSpec.with_` and sweeps accept besides parameter and state names
RUN_SETTINGS = ("fidelity", "method", "rtol", "atol", "t_end", "pose", "n_eval", "max_steps", "path")


def _frozen(mapping: Mapping | None) -> Mapping:
    return MappingProxyType({k: _validate.finite(v, f"`{k}`") for k, v in dict(mapping or {}).items()})


def _count(v, name: str, low: int, high: int) -> int | None:
    """``None`` or a whole number in ``[low, high]`` (an integral float such as ``4001.0`` read back from a
    file is accepted; ``2.5`` is not)."""
    if v is None:
        return None
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating)) \
            or not (math.isfinite(v) and v == int(v)):
        raise TypeError(f"`{name}` must be a whole number or None, got {v!r}")
    if not low <= v <= high:
        raise ValueError(f"`{name}` must be from {low} to {high}, got {v!r}")
    return int(v)


@dataclass(frozen=True)
class RunSpec:
    """One integration as data.

    Attributes
    ----------
    model : ``"single_mode"`` or ``"two_mode"``.
    fidelity : ``"full"``, ``"reduced"`` (or ``"amplitude"`` where available).
    params : mapping of parameter names to values (units g = ell = 1 unless set).
    y0 : mapping of state names to initial values.
    t_span : (t0, t1) in units of sqrt(ell/g).
    pose : carry the position on the table ``(phi, x, y)``.
    method, rtol, atol : integrator and tolerances (see ``knifeedge.METHODS``).
    n_eval : number of equally spaced output samples; ``None`` keeps the
        solver's own steps.
    max_steps : step budget of the integrator (``None``: its default); a run
        that needs more fails with a message saying so.
    path : folder of a user's generated model (``knifeedge.load(model,
        path=...)``), stored as an absolute path so that a worker process in
        another directory loads the same model; ``None`` for the built-in
        models.
    """

    model: str
    fidelity: str
    params: Mapping[str, float]
    y0: Mapping[str, float]
    t_span: tuple[float, float]
    pose: bool = False
    method: str = "DOP853"
    rtol: float = 1e-10
    atol: float = 1e-12
    n_eval: int | None = 4001
    max_steps: int | None = None
    path: str | None = None

    def __post_init__(self):
        if self.path is not None:
            if not isinstance(self.path, (str, os.PathLike)):
                raise TypeError(f"`path` must be a folder (str or os.PathLike) or None, got {self.path!r}")
            object.__setattr__(self, "path", str(Path(self.path).expanduser().resolve()))
        object.__setattr__(self, "params", _frozen(self.params))
        object.__setattr__(self, "y0", _frozen(self.y0))
        if isinstance(self.t_span, (str, bytes)) or not hasattr(self.t_span, "__len__") or len(self.t_span) != 2:
            raise TypeError(f"`t_span` must be a pair (t0, t1) of numbers, got {self.t_span!r}")
        object.__setattr__(self, "t_span", tuple(_validate.finite(v, "`t_span`") for v in self.t_span))
        object.__setattr__(self, "n_eval", _count(self.n_eval, "n_eval", 2, MAX_N_EVAL))
        object.__setattr__(self, "max_steps", _count(self.max_steps, "max_steps", 1, 2**63 - 1))

    # -- derived objects -----------------------------------------------------
    def load(self):
        """The :class:`knifeedge.Model` this run integrates."""
        from .models import load

        if self.path is None:
            return load(self.model, fidelity=self.fidelity, pose=self.pose)
        return load(self.model, fidelity=self.fidelity, pose=self.pose, path=self.path)

    def simulate(self):
        """Integrate; returns a :class:`knifeedge.SimulationResult`."""
        from .simulate import simulate

        m = self.load()
        t_eval = None if self.n_eval is None else np.linspace(*self.t_span, int(self.n_eval))
        extra = {} if self.max_steps is None else {"max_steps": int(self.max_steps)}
        return simulate(m, dict(self.y0), self.t_span, dict(self.params), method=self.method,
                        rtol=self.rtol, atol=self.atol, t_eval=t_eval, **extra)

    # -- variations ----------------------------------------------------------
    def with_(self, **changes: Any) -> "RunSpec":
        """A copy with some parameters, initial values or settings changed.

        Keys may be parameter names (``D=0.5``), state names (``phi_dot=0.2``)
        or run settings (``fidelity``, ``method``, ``rtol``, ``atol``,
        ``t_end``, ``pose``, ``n_eval``, ``max_steps``, ``path``).
        """
        params, y0 = dict(self.params), dict(self.y0)
        settings: dict = {}
        unknown = []
        for key, value in changes.items():
            if key in params:
                params[key] = value
            elif key in y0:
                y0[key] = value
            elif key == "t_end":
                settings["t_span"] = (self.t_span[0], _validate.finite(value, "`t_end`"))
            elif key in RUN_SETTINGS:
                settings[key] = value
            else:
                unknown.append(key)
        if unknown:
            raise ValueError(
                f"unknown name(s) {unknown} for a {self.model} run; accepted: parameters {tuple(params)}, "
                f"initial state {tuple(y0)}, settings {RUN_SETTINGS}"
            )
        return dataclasses.replace(self, params=params, y0=y0, **settings)

    def to_dict(self) -> dict:
        """Plain-data form (JSON-serialisable, picklable); :meth:`from_dict` reads it back."""
        return {
            "model": self.model, "fidelity": self.fidelity, "pose": self.pose,
            "params": dict(self.params), "y0": dict(self.y0), "t_span": list(self.t_span),
            "method": self.method, "rtol": self.rtol, "atol": self.atol, "n_eval": self.n_eval,
            "max_steps": self.max_steps, "path": self.path,
        }

    @classmethod
    def from_dict(cls, d: Mapping) -> "RunSpec":
        return cls(**d)  # __post_init__ makes t_span a tuple

    def describe(self) -> str:
        """One line: model, fidelity, parameters, initial state, span, method."""
        ps = ", ".join(f"{k}={_fmt(v)}" for k, v in self.params.items())
        ys = ", ".join(f"{k}={_fmt(v)}" for k, v in self.y0.items() if v != 0.0)
        pose = ", pose" if self.pose else ""
        if self.path is not None:
            pose += f", from {self.path}"
        return (f"{self.model} ({self.fidelity}{pose}); {ps}; y0: {ys or 'all zero'}; "
                f"t in [{_fmt(self.t_span[0])}, {_fmt(self.t_span[1])}]; {self.method} rtol={self.rtol:g} atol={self.atol:g}")


def _fmt(v: float) -> str:
    if v == math.pi / 4:
        return "pi/4"
    return f"{v:g}"
