"""Scenes: one per figure of the paper, each a small declarative description.

>>> import knifeedge as ke
>>> ke.scene_names()
('numerical', 'amplitudes', 'ellipses', 'numerical2', 'tinversion', 'table_path', 'model_fidelity', 'rolling_disk', 'celt', 'celt_schoemer', 'knife_edge_rigid', 'knife_edge_vs_celt', 'celt_stability', 'predictability', 'celt_chaos', 'bicycle_stability')
>>> s = ke.scene("numerical")          # the paper's Fig. 'numerical'
>>> s.run.model, s.run.fidelity
('single_mode', 'reduced')
>>> result = s.with_(D=0.5)()          # doctest: +SKIP  (same scene, another D)
"""
from __future__ import annotations

import importlib

from .base import RUN_SETTINGS, RunSpec, Scene, SceneResult

#: scene names, the paper's figures in its order, then the others; each is a module of this package defining ``SCENE``
SCENE_NAMES = ("numerical", "amplitudes", "ellipses", "numerical2", "tinversion", "table_path", "model_fidelity",
               "rolling_disk", "celt", "celt_schoemer", "knife_edge_rigid", "knife_edge_vs_celt", "celt_stability",
               "predictability", "celt_chaos", "bicycle_stability")


def scene_names() -> tuple:
    """Names of the scenes, in the paper's order."""
    return SCENE_NAMES


def get_scene(name: str, **changes) -> Scene:
    """The scene called ``name``, with its main run changed by ``changes`` (see ``RunSpec.with_``)."""
    if not isinstance(name, str) or name not in SCENE_NAMES:
        raise ValueError(f"unknown scene `name` {name!r}; accepted: {', '.join(SCENE_NAMES)}")
    scene = importlib.import_module(f"{__name__}.{name}").SCENE
    return scene.with_(**changes) if changes else scene


scene = get_scene

__all__ = ["RunSpec", "Scene", "SceneResult", "RUN_SETTINGS", "SCENE_NAMES", "scene_names", "get_scene", "scene"]
