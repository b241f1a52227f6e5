"""Scene descriptions: which model, at which fidelity, from which state, for how long.

A :class:`~knifeedge.runspec.RunSpec` (defined in the core module
``knifeedge.runspec``) is one integration written as data.  A :class:`Scene` is one figure of the paper: a main
``RunSpec``, the paper's caption, a one-line justification of the model it
uses, what it plots, the numbers it reports, and two functions: ``compute``
(runs the integrations, returns the numbers) and ``draw`` (plots them).
Switching a scene to another model, method or tolerance is a one-line change
of its ``RunSpec`` (or ``scene.with_(fidelity="full")`` at run time).
"""
from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..runspec import RUN_SETTINGS, RunSpec  # noqa: F401  (re-exported: a scene's main run is a RunSpec)


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

    def figure(self, dpi: float | None = None):
        """A new matplotlib figure with this scene drawn on it (at ``dpi``, default matplotlib's)."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=self.scene.figsize, dpi=dpi)
        self.scene.draw(self, fig)
        return fig

    def savefig(self, path: str | Path, dpi: int = 110) -> Path:
        """Write the figure as PNG; returns the path."""
        import matplotlib.pyplot as plt

        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        fig = self.figure(dpi)  # drawn at the dpi it is saved at: the texts are laid out once, not twice
        fig.savefig(path, dpi=dpi)
        plt.close(fig)
        return path

    def summary(self) -> str:
        """Plain-text summary: model, numbers, claims."""
        lines = [f"scene {self.scene.name}: {self.scene.title}", f"  model: {self.scene.describe_model()}",
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
    run : the main integration (the base point of scans); ``None`` for a scene that integrates nothing
        (its model is named in ``why``; it cannot be swept or animated).
    plots : what the figure shows.
    reports : names of the numbers :attr:`SceneResult.numbers` holds.
    compute : ``compute(scene, progress) -> SceneResult``.
    draw : ``draw(result, fig)``.
    settings : scene-specific knobs (scan values, comparison tolerances).
    uses : every ``(model, fidelity, pose)`` the scene integrates (default,
        ``None``: the main run's only; ``()``: none, the scene integrates
        nothing).
    lyapunov : every ``(model, fidelity)`` whose Lyapunov exponents or
        linearization (its ``jvp_into``) the scene computes (``knifeedge
        figures`` compiles the variational loop and the model's ``jvp_into``
        once, before the scenes that need them).
    compiles : every ``(model, fidelity, function)`` of a generated module
        that the scene calls compiled, other than its integrators and
        Lyapunov loops (``knifeedge figures`` runs two scenes that share
        one one after the other: the second loads what the first compiled).
    """

    name: str
    title: str
    caption: str
    why: str
    run: RunSpec | None
    plots: str
    reports: tuple[str, ...]
    compute: Callable = field(repr=False)
    draw: Callable = field(repr=False)
    settings: Mapping[str, Any] = field(default_factory=dict)
    figsize: tuple[float, float] = (7.5, 5.5)
    uses: tuple | None = None
    lyapunov: tuple = ()
    compiles: tuple = ()

    def __post_init__(self):
        if self.uses is None:
            uses = () if self.run is None else ((self.run.model, self.run.fidelity, self.run.pose),)
            object.__setattr__(self, "uses", uses)

    def with_(self, **changes: Any) -> "Scene":
        """A copy whose main run has some values changed (see :meth:`RunSpec.with_`)."""
        return dataclasses.replace(self, run=self.main_run().with_(**changes))

    def main_run(self) -> RunSpec:
        """The main run; ``ValueError`` for a scene that integrates nothing."""
        if self.run is None:
            raise ValueError(f"scene {self.name!r} integrates nothing (its model: {self.why}); it has no run to "
                             f"change, sweep or animate")
        return self.run

    def describe_model(self) -> str:
        """One line: the main run, or for a scene without one, that it integrates nothing."""
        return self.run.describe() if self.run is not None else "no integration (see why)"

    def __call__(self, progress: Callable[[str], None] | None = None) -> SceneResult:
        """Run the scene: ``result = scene()``."""
        if progress is not None and not callable(progress):
            raise TypeError(f"`progress` must be None or a callable(message), got {progress!r}")
        return self.compute(self, progress or (lambda msg: None))
