"""Rigid bodies built with the front end :mod:`derivation.rigid` that ``make derive`` writes into ``generated/``."""
from __future__ import annotations

from .celt import celt
from .rigid_knife_edge import knife_edge_body

MODELS = {"celt": celt(), "two_mode_rigid": knife_edge_body()}
