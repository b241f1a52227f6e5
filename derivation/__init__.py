"""knifeedge.derive: the symbolic engine (needs SymPy: ``pip install 'knifeedge[derive]'``).

A model is data, a :class:`ModelSpec` (its numbered contract is in the class
docstring); :func:`derive` turns it into a reduced first-order system,
:func:`build` into every fidelity of :data:`FIDELITIES`, and
:func:`derive_files` (the ``knifeedge derive`` command) writes the compiled
modules that ``knifeedge.load(name, path=...)`` loads.  :data:`t` is the time:
it may appear in a model's Lagrangian, forces, dissipation and constraints.
"""
from .engine import ModelSpec, ModelSpecError, ReducedSystem, check_symmetry, derive
from .names import t
from .fidelities import FIDELITIES, Fidelity
from .emit import build, write_all
from .cli import DeriveError, derive_files, load_specs
from .mechanics import MechanicsConversionError, from_mechanics

__all__ = ["t", "ModelSpec", "ModelSpecError", "ReducedSystem", "derive", "check_symmetry", "FIDELITIES", "Fidelity",
           "build", "write_all", "DeriveError", "derive_files", "load_specs", "from_mechanics",
           "MechanicsConversionError"]
