"""Rigid bodies built with the front end :mod:`derivation.rigid` that ``make derive`` writes into ``generated/``."""
from __future__ import annotations

from .celt import celt

MODELS = {"celt": celt()}
