"""The fidelities: what each one is and how it is built, in one registry.

A fidelity is a level of description of one model.  ``full`` comes from the
engine; every other one is built from an earlier fidelity of the same model.
:func:`derivation.emit.build_all` derives, for every model, each fidelity
of :data:`FIDELITIES` (in its order) that applies to the model.  Adding a
fidelity is one entry here (and, if its modules differ in kind, an emitter).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from . import averaging, engine, truncation


@dataclass(frozen=True)
class Fidelity:
    """One fidelity.

    Attributes
    ----------
    name : the name used by ``knifeedge.load(..., fidelity=name)``.
    doc : what it is (written into each generated module as ``FIDELITY_DOC``).
    source : the fidelity it is built from (``None`` for ``full``).
    build : ``build(source_system) -> system`` (for ``full``, ``build(spec)``).
    applies : ``applies(spec) -> bool``, whether the model has this fidelity.
    """

    name: str
    doc: str
    source: str | None
    build: Callable
    applies: Callable


def _has_tilts(spec) -> bool:
    return bool(spec.small)


def _averageable(spec) -> bool:
    spins = [q for q in spec.independent if q in spec.cyclic]
    return bool(spec.small) and len(spins) == 1 and not spec.dissipative and not spec.state_order


FIDELITIES = {
    "full": Fidelity(
        "full", "exact consequences of the model's Lagrangian and constraints, nothing dropped",
        None, engine.derive, lambda spec: True),
    "reduced": Fidelity(
        "reduced",
        f"degree-{truncation.ORDER} Taylor polynomial of the full vector field in the tilts and tilt rates "
        "(tilt equations to O(theta), spin equation to O(theta^2))",
        "full", truncation.reduced, _has_tilts),
    "amplitude": Fidelity(
        "amplitude", "first-order averaged slow flow of the reduced equations",
        "reduced", averaging.average, _averageable),
}
