"""knifeedge: verified, compiled simulators of the chiral knife-edge rattleback.

Implements Jagla & Rojo, "The chiral knife edge: a simplified rattleback to
illustrate spin inversion" (arXiv:2309.06154).  The equations of motion are
derived by machine from the paper's Lagrangians (``derivation/``, SymPy) and
emitted as numba modules (``knifeedge.generated``); this package loads and
integrates them and never imports SymPy.

>>> import knifeedge as ke
>>> m = ke.load("single_mode", fidelity="full")
>>> m.state_names
('theta', 'theta_dot', 'phi_dot')
"""
from .models import FIDELITIES, MODEL_NAMES, Model, ValidityWarning, available, load
from .simulate import METHODS, SimulationResult, simulate
from .runspec import RunSpec
from .scenes import Scene, get_scene as scene, scene_names
from .sweep import SweepTable, sweep
from .reversal import ReversalPrediction, reversal_time
from .animation import animate
from .stability import Linearization, linearize, stability, stability_boundaries
from .sections import Section, poincare
from .lyapunov import LyapunovResult, lyapunov
from .integrators.compiler import compile_mode, set_compile_mode

__version__ = "0.1.0"
__all__ = ["load", "available", "ValidityWarning", "simulate", "Model", "SimulationResult", "METHODS", "MODEL_NAMES",
           "FIDELITIES", "sweep", "SweepTable", "scene", "scene_names", "Scene", "RunSpec", "reversal_time",
           "ReversalPrediction", "animate", "set_compile_mode", "compile_mode", "linearize", "Linearization", "stability",
           "stability_boundaries", "poincare", "Section", "lyapunov", "LyapunovResult"]
