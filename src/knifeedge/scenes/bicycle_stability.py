"""Scene ``bicycle_stability``: the Whipple bicycle's eigenvalues against the forward speed (Meijaard et al. 2007).

The benchmark's Fig. 3 (Meijaard, Papadopoulos, Ruina & Schwab 2007, *Proc. R. Soc. A* 463, 1955-1982): real and
imaginary parts of the eigenvalues of upright straight running against the forward speed ``v``, the weave speed
(a complex pair crosses into the left half-plane) and the capsize speed (a real eigenvalue crosses into the right
one) found by machine (:func:`knifeedge.stability.growth_boundaries`) and marked; between them the bicycle is
self-stable.  The benchmark gives them as 4.29238253634111 and 6.02426201538837 m/s (its section 4).

The model is the lean/steer linearization ``A(v) = A0 + v A1 + v^2 A2``, whose coefficients ``make
bicycle-linear`` (``derivation/bicycle_linear.py``) took from the generated Jacobian of the nonlinear bicycle
derived by ``from_mechanics`` (``tests/models/whipple_bicycle.py``): a 4 x 4 eigenvalue problem per speed, no
integration and no compiled code, so the scene costs milliseconds.
"""
from __future__ import annotations

import importlib
import importlib.util
from pathlib import Path

import numpy as np

from ..modulecheck import sealed_ok
from ..stability import MARGINAL, growth_boundaries
from .base import Scene, SceneResult
from .common import layout

#: Meijaard et al. 2007, section 4: the weave and capsize speeds of the benchmark bicycle [m/s]
BENCHMARK_SPEEDS = {"weave": 4.29238253634111, "capsize": 6.02426201538837}
_MODULE = "knifeedge.generated.linear.whipple_bicycle"


def coefficients() -> tuple:
    """``(A0, A1, A2)`` of the generated module (4 x 4 arrays; state lean, steer, lean rate, steer rate)."""
    spec = importlib.util.find_spec(_MODULE)
    if spec is None or not sealed_ok(Path(spec.origin).read_bytes()):
        raise ValueError(f"{_MODULE} is missing or was edited after it was generated: run `make bicycle-linear`")
    module = importlib.import_module(_MODULE)
    return tuple(np.array(getattr(module, k), dtype=float) for k in ("A0", "A1", "A2"))


def matrix(coeffs, v: float) -> np.ndarray:
    """``A(v) = A0 + v A1 + v^2 A2``."""
    a0, a1, a2 = coeffs
    return a0 + v * a1 + v * v * a2


def growth(coeffs, v: float) -> tuple:
    """Largest real part at ``v`` and the threshold below which it counts as zero (as :func:`knifeedge.stability`)."""
    a = matrix(coeffs, v)
    return float(np.linalg.eigvals(a).real.max()), MARGINAL * float(np.linalg.norm(a))


def compute(scene: Scene, progress) -> SceneResult:
    s = scene.settings
    coeffs = coefficients()
    res = SceneResult(scene)
    progress("eigenvalues of the lean/steer equations against the speed")
    speeds = np.linspace(*s["speed_range"], s["n_speeds"])
    eig = np.array([np.sort_complex(np.linalg.eigvals(matrix(coeffs, v))) for v in speeds])
    found = growth_boundaries(lambda v: growth(coeffs, v), *s["speed_range"], n_grid=s["n_grid"])
    res.data.update(speeds=speeds, eigenvalues=eig, boundaries=found)
    res.numbers["boundaries"] = [float(b) for b in found]
    ok = len(found) == 2
    if ok:
        res.numbers["weave_speed"], res.numbers["capsize_speed"] = (float(b) for b in found)
        error = max(abs(res.numbers[f"{k}_speed"] - v) for k, v in BENCHMARK_SPEEDS.items())
        res.numbers["speed_error"] = error
        ok = error < s["speed_tol"]
    inside = speeds[(speeds > found[0]) & (speeds < found[-1])] if len(found) else speeds[:0]
    res.claim("the benchmark bicycle is self-stable between the weave speed 4.29238253634111 m/s and the capsize "
              "speed 6.02426201538837 m/s (Meijaard et al. 2007, section 4), and only there in "
              f"{s['speed_range'][0]:g}-{s['speed_range'][1]:g} m/s",
              ok and all(growth(coeffs, v)[0] < 0 for v in inside),
              f"changes of stability found at {', '.join(f'{b:.14g}' for b in found) or 'none'} m/s "
              f"(largest difference from the benchmark's {res.numbers.get('speed_error', float('nan')):.1e})")
    return res


def draw(res: SceneResult, fig) -> None:
    d = res.data
    speeds, eig = d["speeds"], d["eigenvalues"]
    ax = fig.subplots()
    found = d["boundaries"]
    if len(found) == 2:
        ax.axvspan(found[0], found[1], color="C2", alpha=0.12, label="self-stable")
    for j in range(eig.shape[1]):
        ax.scatter(speeds, eig[:, j].real, s=4, color="C0", label="real parts" if j == 0 else None)
        imag = np.abs(eig[:, j].imag)
        keep = imag > 0
        ax.scatter(speeds[keep], imag[keep], s=2, color="C1", label="imaginary parts" if j == 0 else None)
    for b, name in zip(found, ("weave", "capsize")):
        ax.axvline(b, color="k", lw=0.8, ls="--")
        ax.annotate(f"{name} {b:.6f} m/s", (b, 0), xytext=(4, -14 if name == "weave" else 8),
                    textcoords="offset points", fontsize=8)
    ax.axhline(0, color="gray", lw=0.5)
    ax.set_ylim(-10, 10)
    ax.set_xlabel("forward speed v [m/s]")
    ax.set_ylabel(r"eigenvalues $\lambda$ [1/s]")
    ax.set_title("Whipple bicycle (Meijaard et al. 2007), upright straight running", fontsize=10)
    ax.legend(fontsize=8, loc="lower left")
    layout(fig, res.scene is SCENE, dict(left=0.1179, right=0.9800, bottom=0.1161, top=0.9322))


SCENE = Scene(
    name="bicycle_stability",
    title="The Whipple bicycle's stability against its speed",
    caption=("Meijaard et al. 2007, Fig. 3: real and imaginary parts of the eigenvalues of the benchmark bicycle's "
             "upright straight running against the forward speed 0-10 m/s; the weave and capsize speeds, between "
             "which it is self-stable, found and marked."),
    why=("the lean/steer linearization A(v) = A0 + v A1 + v^2 A2 (generated/linear/whipple_bicycle.py), the "
         "cheapest model that answers: its coefficients are the exact Jacobian of the nonlinear bicycle derived by "
         "from_mechanics at three speeds (A is quadratic in v), so the scene solves 4 x 4 eigenvalue problems and "
         "integrates nothing"),
    run=None,
    plots=("real parts (blue) and imaginary parts (orange, |Im|) of the four eigenvalues against the speed, the "
           "weave and capsize speeds (dashed) and the self-stable range (shaded)"),
    reports=("boundaries", "weave_speed", "capsize_speed", "speed_error"),
    compute=compute,
    draw=draw,
    settings={"speed_range": (0.0, 10.0), "n_speeds": 401, "n_grid": 201, "speed_tol": 1e-9},
    figsize=(7.5, 5.0),
)
