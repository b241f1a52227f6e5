"""Small helpers the scenes share: envelopes, energy drift, plotting style."""
from __future__ import annotations

import math

import numpy as np

#: the paper's caption convention: time in sqrt(ell/g), rates in sqrt(g/ell)
T_LABEL = r"$t\ [\sqrt{\ell/g}]$"
RATE_LABEL = r"$\dot\phi\ [\sqrt{g/\ell}]$"


def require_success(result, scene):
    """Return ``result``; raise ``RuntimeError`` naming the scene if its integration failed."""
    if not result.success:
        raise RuntimeError(f"scene {scene.name}: integration failed: {result.message}")
    return result


def run_to_first_reversal(spec, t_stop: float, scene):
    """``spec`` (a RunSpec) run up to ``t_stop`` if that is inside its span and the run reverses by then, else over
    its whole span.  An adaptive run takes the same steps whatever its end (but the last), so its first reversal
    is the whole span's to the bit."""
    if t_stop < spec.t_span[1]:
        r = require_success(spec.with_(t_end=t_stop).simulate(), scene)
        if len(r.reversal_times):
            return r
    return require_success(spec.simulate(), scene)


def first_reversal(result) -> float:
    """Time of the first reversal of a run (``result.reversal_times[0]``), ``nan`` if it has none."""
    return float(result.reversal_times[0]) if len(result.reversal_times) else math.nan


def claim_energy_conserved(res, label: str, drift: float, limit: float = 1e-9) -> None:
    """The integration check of a conservative run: claim ``drift`` (relative, of the energy or of the
    energy plus the dissipated work) below ``limit``."""
    res.claim(f"{label}energy conserved (integration check)", drift < limit, f"{drift:.1e} relative (limit {limit:g})")


def envelope(theta: np.ndarray, theta_dot: np.ndarray, omega: float) -> np.ndarray:
    """Oscillation amplitude ``sqrt(theta^2 + (theta_dot/omega)^2)``, shape of ``theta``.

    For a harmonic oscillation of angular frequency ``omega`` this is its
    amplitude at every instant (the paper's ``A_theta``).
    """
    return np.sqrt(np.asarray(theta) ** 2 + (np.asarray(theta_dot) / omega) ** 2)


def relative_energy_drift(result) -> float:
    """``max |E(t) - E(0)| / |E(0)|`` along a simulation.

    For a model whose energy needs neither the time, inputs nor the pose, the generated ``energy`` is called as
    plain Python (``py_func``: the same arithmetic, the same bits): for the few thousand samples of a scene that
    costs 15-35 ms, less than compiling it on a first run (0.2-0.3 s of CPU)."""
    m = result.model
    f = getattr(m.module.energy, "py_func", None)
    if f is None or m.time_dependent or m.input_names or getattr(m.module, "ENERGY_NEEDS_POSE", False):
        e = result.energy
    else:
        p, y = m.check_params(result.p), np.ascontiguousarray(result.y)
        e = np.array([f(np.ascontiguousarray(y[:, k]), p) for k in range(y.shape[1])])
    return float(np.max(np.abs(e - e[0])) / abs(e[0]))


def omega(params) -> float:
    """Pendulum frequency sqrt(g/ell) of the tilt mode(s)."""
    return math.sqrt(params["g"] / params["ell"])


def mark_reversals(ax, times, label: bool = True) -> None:
    """Dotted vertical lines at the spin reversals."""
    for i, t in enumerate(times):
        ax.axvline(t, color="k", ls=":", lw=0.9, label="spin reversal" if (label and i == 0) else None)


def fit_power_law(x, y) -> tuple:
    """Least-squares fit ``log y = a + b log x``; returns (b, standard error of b, a).

    The standard error is the usual ordinary-least-squares one,
    ``sqrt(s^2 / sum((log x - mean)^2))`` with ``s^2`` the residual variance
    on ``n - 2`` degrees of freedom.
    """
    lx, ly = np.log(np.asarray(x, float)), np.log(np.asarray(y, float))
    n = lx.size
    if n < 3:
        raise ValueError("a power-law fit with an uncertainty needs at least 3 points")
    b, a = np.polyfit(lx, ly, 1)
    resid = ly - (a + b * lx)
    s2 = float(resid @ resid) / (n - 2)
    se = math.sqrt(s2 / float(((lx - lx.mean()) ** 2).sum()))
    return float(b), se, float(a)


def label_log_ticks(ax, x) -> None:
    """Label a log-scaled x axis at the data values only (no crowded minor labels)."""
    from matplotlib.ticker import NullFormatter

    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xticks(list(x), [f"{v:g}" for v in x], fontsize=8)


#: the groups of matplotlib's settings that move texts and axes: fixed margins hold only at their defaults
_LAYOUT_RC = ("font.", "axes.", "xtick.", "ytick.", "figure.", "text.", "mathtext.", "legend.")


def _default_style() -> bool:
    """Whether every setting of :data:`_LAYOUT_RC` is matplotlib's default (no style or matplotlibrc changes it)."""
    from matplotlib import rcParams, rcParamsDefault

    return all(rcParams[k] == rcParamsDefault[k] for k in rcParams if k.startswith(_LAYOUT_RC))


def layout(fig, registered: bool, margins: dict, **tight) -> None:
    """Lay out ``fig``: at the scene's registered settings (``registered``: ``result.scene is SCENE``) and
    matplotlib's default style by ``fig.subplots_adjust(**margins)``, the margins ``fig.tight_layout(**tight)``
    gives it there (to 1e-4 of the figure; tests/test_figures_layout.py checks them); otherwise (other texts and
    tick labels, or a user's style with other fonts or sizes) by ``fig.tight_layout(**tight)``.  The tight layout
    lays out every text once more before the drawing does: 0.05-0.5 s of CPU a figure, 40 % of drawing it."""
    if registered and _default_style():
        fig.subplots_adjust(**margins)
    else:
        fig.tight_layout(**tight)
