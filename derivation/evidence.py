"""The outcome of one comparison of a published equation with the derivation (shared by the checks)."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Evidence:
    """Outcome of one comparison: ``passed`` and what was measured."""

    passed: bool
    dimension_error: str | None
    detail: str
