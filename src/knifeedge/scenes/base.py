"""Scene descriptions: which model, at which fidelity, from which state, for how long.

A :class:`RunSpec` is one integration written as data (model name,
fidelity, pose or not, parameters and initial state by name, time span,
method, tolerances).  A :class:`Scene` is one figure of the paper: a main
``RunSpec``, the paper's caption, a one-line justification of the model it
uses, what it plots, the numbers it reports, and two functions: ``compute``
(runs the integrations, returns the numbers) and ``draw`` (plots them).
Switching a scene to another model, method or tolerance is a one-line change
of its ``RunSpec`` (or ``scene.with_(fidelity="full")`` at run time).
"""
from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

import numpy as np

#: run settings that :meth:`RunSpec.with_` and sweeps accept besides parameter and state names
RUN_SETTINGS = ("fidelity", "method", "rtol", "atol", "t_end", "pose", "n_eval", "max_steps")


def _frozen(mapping: Mapping | None) -> Mapping:
    return MappingProxyType({k: float(v) for k, v in dict(mapping or {}).items()})


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

    def __post_init__(self):
        object.__setattr__(self, "params", _frozen(self.params))
        object.__setattr__(self, "y0", _frozen(self.y0))
        object.__setattr__(self, "t_span", (float(self.t_span[0]), float(self.t_span[1])))

    # -- derived objects -----------------------------------------------------
    def load(self):
        """The :class:`knifeedge.Model` this run integrates."""
        from ..models import load

        return load(self.model, fidelity=self.fidelity, pose=self.pose)

    def simulate(self):
        """Integrate; returns a :class:`knifeedge.SimulationResult`."""
        from ..simulate import simulate

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
        ``t_end``, ``pose``, ``n_eval``, ``max_steps``).
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
                settings["t_span"] = (self.t_span[0], float(value))
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
        """Plain-data form (JSON-serialisable, picklable)."""
        return {
            "model": self.model, "fidelity": self.fidelity, "pose": self.pose,
            "params": dict(self.params), "y0": dict(self.y0), "t_span": list(self.t_span),
            "method": self.method, "rtol": self.rtol, "atol": self.atol, "n_eval": self.n_eval,
            "max_steps": self.max_steps,
        }

    @classmethod
    def from_dict(cls, d: Mapping) -> "RunSpec":
        d = dict(d)
        d["t_span"] = tuple(d["t_span"])
        return cls(**d)

    def describe(self) -> str:
        """One line: model, fidelity, parameters, initial state, span, method."""
        ps = ", ".join(f"{k}={_fmt(v)}" for k, v in self.params.items())
        ys = ", ".join(f"{k}={_fmt(v)}" for k, v in self.y0.items() if v != 0.0)
        pose = ", pose" if self.pose else ""
        return (f"{self.model} ({self.fidelity}{pose}); {ps}; y0: {ys or 'all zero'}; "
                f"t in [{_fmt(self.t_span[0])}, {_fmt(self.t_span[1])}]; {self.method} rtol={self.rtol:g} atol={self.atol:g}")


def _fmt(v: float) -> str:
    if v == math.pi / 4:
        return "pi/4"
    return f"{v:g}"


@dataclass
class SceneResult:
    """What a scene computed.

    Attributes
    ----------
    scene : Scene
    numbers : dict
        Name -> value (float, int or str) of every reported number.
    claims : list of (claim, verdict, evidence)
        The paper's statements this scene checks; ``verdict`` is
        ``"supports"``, ``"contradicts"`` or ``"n/a"``.
    data : dict
        Arrays the drawing needs (time series, fits, ...).
    """

    scene: "Scene"
    numbers: dict = field(default_factory=dict)
    claims: list = field(default_factory=list)
    data: dict = field(default_factory=dict, repr=False)

    def claim(self, text: str, supported: bool | None, evidence: str) -> None:
        verdict = "n/a" if supported is None else ("supports" if supported else "contradicts")
        self.claims.append((text, verdict, evidence))

    def figure(self):
        """A new matplotlib figure with this scene drawn on it."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=self.scene.figsize)
        self.scene.draw(self, fig)
        return fig

    def savefig(self, path: str | Path, dpi: int = 110) -> Path:
        """Write the figure as PNG; returns the path."""
        import matplotlib.pyplot as plt

        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        fig = self.figure()
        fig.savefig(path, dpi=dpi)
        plt.close(fig)
        return path

    def summary(self) -> str:
        """Plain-text summary: model, numbers, claims."""
        lines = [f"scene {self.scene.name}: {self.scene.title}", f"  model: {self.scene.run.describe()}",
                 f"  why: {self.scene.why}"]
        for k, v in self.numbers.items():
            lines.append(f"  {k} = {format_number(v)}")
        for text, verdict, evidence in self.claims:
            lines.append(f"  [{verdict}] {text} -- {evidence}")
        return "\n".join(lines)


def format_number(v) -> str:
    if isinstance(v, (bool, np.bool_)):
        return str(bool(v))
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        return f"{float(v):.6g}"
    if isinstance(v, (list, tuple, np.ndarray)):
        return "[" + ", ".join(format_number(x) for x in v) + "]"
    return str(v)


@dataclass(frozen=True)
class Scene:
    """One figure of the paper, as data plus two functions.

    Attributes
    ----------
    name : the paper's figure label (``"numerical"``, ``"tinversion"``, ...).
    title : a short title.
    caption : the paper's caption (or the issue's description for figures
        the paper does not have).
    why : one line: why this model, fidelity and state answer the question.
    run : the main integration (the base point of scans).
    plots : what the figure shows.
    reports : names of the numbers :attr:`SceneResult.numbers` holds.
    compute : ``compute(scene, progress) -> SceneResult``.
    draw : ``draw(result, fig)``.
    settings : scene-specific knobs (scan values, comparison tolerances).
    uses : every ``(model, fidelity, pose)`` the scene integrates (default:
        the main run's only).
    """

    name: str
    title: str
    caption: str
    why: str
    run: RunSpec
    plots: str
    reports: tuple[str, ...]
    compute: Callable = field(repr=False)
    draw: Callable = field(repr=False)
    settings: Mapping[str, Any] = field(default_factory=dict)
    figsize: tuple[float, float] = (7.5, 5.5)
    uses: tuple = ()

    def __post_init__(self):
        if not self.uses:
            object.__setattr__(self, "uses", ((self.run.model, self.run.fidelity, self.run.pose),))

    def with_(self, **changes: Any) -> "Scene":
        """A copy whose main run has some values changed (see :meth:`RunSpec.with_`)."""
        return dataclasses.replace(self, run=self.run.with_(**changes))

    def __call__(self, progress: Callable[[str], None] | None = None) -> SceneResult:
        """Run the scene: ``result = scene()``."""
        return self.compute(self, progress or (lambda msg: None))
