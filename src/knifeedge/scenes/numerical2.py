"""Scene ``numerical2``: periodic spin reversals of the two-mode knife edge (paper Fig. 'Numerical2').

Reversal time, two definitions (``docs/models.md``): the *first reversal
time* (from the initial state to the first zero of ``phi_dot``) and the
*interval* between consecutive reversals.  The first is well conditioned.
The later ones are not: each is seeded by the inactive tilt's amplitude
after it has decayed to ~1e-15 of the active one, so they move with the
integration error until the tolerance is tight (at rtol 1e-10 the second
reversal of this scene is ~4% early).  This scene integrates at two
tolerances and reports every reversal time with the difference between
them; a difference below ``settings["converged_below"]`` (relative) counts
as converged.
"""
from __future__ import annotations

import math

import numpy as np

from .base import RunSpec, Scene, SceneResult
from .common import RATE_LABEL, T_LABEL, layout, mark_reversals, require_success

RUN = RunSpec(
    model="two_mode", fidelity="reduced",
    params={"g": 1.0, "ell": 1.0, "L": 2.0, "D": 0.5, "alpha": math.pi / 4},
    y0={"theta1": 1e-3, "theta2": 1e-3, "theta1_dot": 0.0, "theta2_dot": 0.0, "phi_dot": 0.1},
    t_span=(0.0, 9000.0), method="DOP853", rtol=1e-12, atol=1e-16, n_eval=24001,
)


def compute(scene: Scene, progress) -> SceneResult:
    run = scene.run
    check = run.with_(rtol=scene.settings["check_rtol"], n_eval=None)
    progress(f"integrating the two-mode equations at rtol {run.rtol:g}")
    r = run.simulate()
    progress(f"integrating again at rtol {check.rtol:g} (convergence of the later reversals)")
    r2 = check.simulate()
    for x in (r, r2):
        require_success(x, scene)
    rev, rev2 = r.reversal_times, r2.reversal_times
    n = min(len(rev), len(rev2))
    diff = np.abs(rev[:n] - rev2[:n])
    intervals = np.diff(rev)
    tol = scene.settings["converged_below"]
    converged = bool(len(rev) == len(rev2) and np.all(diff <= tol * rev[:n]))
    from ..reversal import reversal_time

    theory = reversal_time(run.load(), dict(run.params), dict(run.y0))
    res = SceneResult(scene)
    res.numbers.update({
        "reversal_times": [float(t) for t in rev],
        f"reversal_times_at_rtol_{check.rtol:g}": [float(t) for t in rev2],
        "reversal_time_differences": [float(d) for d in diff],
        "first_reversal_time": float(rev[0]) if len(rev) else math.nan,
        "intervals_between_reversals": [float(d) for d in intervals],
        "mean_interval": float(np.mean(intervals)) if len(intervals) else math.nan,
        "converged": converged,
        "first_reversal_amplitude_theory": theory.first,
        "interval_amplitude_theory": theory.interval,
        "nfev": r.nfev,
    })
    sign = np.sign(r["phi_dot"])
    res.claim("phi_dot reverses periodically", len(rev) >= 3 and np.ptp(intervals) < 0.05 * np.mean(intervals),
              f"{len(rev)} reversals in t <= {run.t_span[1]:g}; intervals "
              + ", ".join(f"{d:.1f}" for d in intervals))
    active = _active_modes(r, rev)
    res.claim("the reversals are driven alternately by theta1 and theta2",
              len(active) >= 2 and all(a != b for a, b in zip(active, active[1:])),
              "largest tilt amplitude around each reversal: " + ", ".join(active))
    if len(intervals):
        dev = float(np.max(np.abs(intervals - theory.interval)) / theory.interval)
        res.claim("t_R (the interval) matches the amplitude equations", dev < 0.01,
                  f"simulated intervals within {dev:.2%} of {theory.interval:.1f} (knifeedge.reversal_time); "
                  f"first reversal {rev[0]:.2f} vs {theory.first:.2f}")
    res.claim("the reversal times are converged in the tolerance", converged,
              f"rtol {run.rtol:g} vs {check.rtol:g}: differences " + ", ".join(f"{d:.3g}" for d in diff)
              + f" (first reversal {diff[0]:.1e}; criterion {tol:g} relative)" if n else "no reversal")
    res.data.update(t=r.t, theta1=r["theta1"], theta2=r["theta2"], phi_dot=r["phi_dot"], rev=rev, sign=sign)
    return res


def _active_modes(r, rev) -> list:
    """Which tilt oscillates more strongly in the window around each reversal."""
    out = []
    for t in rev:
        w = (r.t > t - 100) & (r.t < t + 100)
        a1, a2 = np.max(np.abs(r["theta1"][w])), np.max(np.abs(r["theta2"][w]))
        out.append("theta1" if a1 > a2 else "theta2")
    return out


def draw(res: SceneResult, fig) -> None:
    d = res.data
    a1, a2 = fig.subplots(2, 1, sharex=True)
    a1.plot(d["t"], d["theta1"], lw=0.3, color="C0", label=r"$\theta_1$")
    a1.plot(d["t"], d["theta2"], lw=0.3, color="C2", alpha=0.8, label=r"$\theta_2$")
    a1.set_ylabel(r"$\theta_1,\ \theta_2$ [rad]")
    for line in a1.legend(loc="upper right", fontsize=8).get_lines():
        line.set_linewidth(2.0)
    a2.plot(d["t"], d["phi_dot"], color="C1")
    a2.axhline(0, color="gray", lw=0.5)
    mark_reversals(a2, d["rev"])
    mark_reversals(a1, d["rev"], label=False)
    rev = d["rev"]
    if len(rev) >= 2:
        y = 0.8 * np.max(d["phi_dot"])
        a2.annotate("", xy=(rev[1], y), xytext=(rev[0], y), arrowprops=dict(arrowstyle="<->", color="k"))
        a2.text(0.5 * (rev[0] + rev[1]), y * 1.05, f"$t_R$ = {rev[1] - rev[0]:.0f}", ha="center", va="bottom")
    a2.annotate(f"first reversal\nt = {rev[0]:.1f}" if len(rev) else "", xy=(rev[0] if len(rev) else 0, 0),
                xytext=(rev[0] * 0.25 if len(rev) else 0, -0.6 * np.max(d["phi_dot"])), fontsize=8,
                arrowprops=dict(arrowstyle="->", lw=0.7))
    a2.set_ylabel(RATE_LABEL)
    a2.set_xlabel(T_LABEL)
    a2.legend(loc="lower right", fontsize=8)
    a1.set_title(r"two modes (Eqs. eqs_2modes): $\ell/L=1/2$, $D/\ell=1/2$, $\alpha=\pi/4$, $\dot\phi_0=0.1\sqrt{g/\ell}$",
                 fontsize=10)
    layout(fig, res.scene is SCENE, dict(left=0.1174, right=0.98125, bottom=0.1167, top=0.9278, hspace=0.0932))


SCENE = Scene(
    name="numerical2",
    title="two-mode periodic spin reversals",
    caption=("Numerical solutions of Eqs. eqs_2modes with parameters l/L = 1/2, D/l = 1/2, alpha = pi/4. Note the "
             "periodic reversal of phi_dot, driven alternatively by the activation of the theta1 and theta2 modes. "
             "The reversal time t_R is indicated."),
    why=("reduced two-mode model: the paper's eqs_2modes are its small-angle truncation; 5 states, no pose. Its later "
         "reversals are ill-conditioned, so it runs at rtol 1e-12 and 1e-13 and reports the difference"),
    run=RUN,
    plots="theta1(t), theta2(t) and phi_dot(t), reversals marked, t_R (interval) and the first reversal indicated",
    reports=("reversal_times", "reversal_times_at_rtol_1e-13", "reversal_time_differences", "first_reversal_time",
             "intervals_between_reversals", "mean_interval", "converged", "first_reversal_amplitude_theory",
             "interval_amplitude_theory", "nfev"),
    compute=compute,
    draw=draw,
    settings={"check_rtol": 1e-13, "converged_below": 1e-3},
    figsize=(8.0, 5.5),
)
