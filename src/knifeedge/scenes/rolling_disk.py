"""Scene ``rolling_disk``: a thin disk rolls upright only when it spins fast enough.

Not a figure of the paper: the model is the user-style example
``examples/rolling_disk.py`` (derived into the package by ``make derive``),
the proof that the engine works on a system it was not written for.  Upright
rolling at spin rate ``Omega = q3_dot`` is stable for
``Omega**2 > Omega_c**2 = g/(3r)`` (thin uniform disk; Routh, *Advanced
Dynamics*, section 244).  Linearized about upright rolling from a lean
``q2_0`` with no heading or lean rate, the lean oscillates about
``s = q2_0 Omega**2 / (Omega**2 - Omega_c**2)`` at angular frequency
``sqrt(12/5 (Omega**2 - Omega_c**2))``, between ``q2_0`` and ``2 s - q2_0``.
"""
from __future__ import annotations

import math

import numpy as np

from .base import RunSpec, Scene, SceneResult
from .common import layout, relative_energy_drift, require_success

RUN = RunSpec(
    model="rolling_disk", fidelity="full", pose=True,
    params={"g": 9.81, "r": 0.1},                     # a 10 cm disk on Earth (SI units)
    y0={"q2": 0.05, "q1_dot": 0.0, "q2_dot": 0.0, "q3_dot": 8.0},
    t_span=(0.0, 6.0), method="DOP853", rtol=1e-10, atol=1e-12, n_eval=6001,
)


def critical_spin(params) -> float:
    """Omega_c = sqrt(g/(3r)): the slowest spin at which a thin disk rolls stably upright."""
    return math.sqrt(params["g"] / (3.0 * params["r"]))


def linear_lean(params, y0) -> dict:
    """Linear theory of the lean about upright rolling (module docstring); valid for q1_dot = q2_dot = 0 at t = 0."""
    omega, omega_c, q20 = y0["q3_dot"], critical_spin(params), y0["q2"]
    k = 12.0 / 5.0 * (omega**2 - omega_c**2)
    if k <= 0:
        return {"stable": False, "growth_rate": math.sqrt(-k)}
    s = q20 * omega**2 / (omega**2 - omega_c**2)
    return {"stable": True, "bound": abs(2 * s - q20), "period": 2 * math.pi / math.sqrt(k)}


def _lean_period(t, lean) -> float:
    """Mean period of the lean's oscillation about its mean (from upward crossings); nan if fewer than two."""
    d = lean - 0.5 * (lean.max() + lean.min())
    up = np.nonzero((d[:-1] < 0) & (d[1:] >= 0))[0]
    if up.size < 2:
        return float("nan")
    tc = t[up] - d[up] * (t[up + 1] - t[up]) / (d[up + 1] - d[up])
    return float(np.mean(np.diff(tc)))


def compute(scene: Scene, progress) -> SceneResult:
    run = scene.run
    omega_c = critical_spin(run.params)
    slow = run.with_(q3_dot=scene.settings["slow_fraction"] * omega_c)
    res = SceneResult(scene)
    progress(f"rolling at q3_dot = {run.y0['q3_dot']:g} rad/s (Omega_c = {omega_c:.4g})")
    fast_r = require_success(run.simulate(), scene)
    progress(f"rolling at q3_dot = {slow.y0['q3_dot']:.4g} rad/s, below Omega_c")
    slow_r = require_success(slow.simulate(), scene)
    theory = linear_lean(run.params, run.y0)
    lean, lean_slow = np.abs(fast_r["q2"]), np.abs(slow_r["q2"])
    period = _lean_period(fast_r.t, fast_r["q2"])
    q20 = abs(run.y0["q2"])
    res.numbers.update({
        "omega_c": omega_c,
        "q3_dot": run.y0["q3_dot"],
        "predicted_stable": theory["stable"],
        "max_lean": float(lean.max()),
        "max_lean_linear_theory": theory.get("bound", float("nan")),
        "lean_period": period,
        "lean_period_linear_theory": theory.get("period", float("nan")),
        "q3_dot_slow": slow.y0["q3_dot"],
        "max_lean_slow": float(lean_slow.max()),
        "relative_energy_drift": max(relative_energy_drift(fast_r), relative_energy_drift(slow_r)),
        "distance_rolled": float(np.hypot(fast_r["x"][-1] - fast_r["x"][0], fast_r["y"][-1] - fast_r["y"][0])),
    })
    if theory["stable"]:
        res.claim("above Omega_c = sqrt(g/(3r)) the lean stays within the linear theory's bound |2s - q2_0|",
                  bool(lean.max() < 1.1 * theory["bound"]),
                  f"q3_dot = {run.y0['q3_dot']:.4g} > {omega_c:.4g}: max |q2| = {lean.max():.4g}, "
                  f"bound {theory['bound']:.4g}")
        res.claim("the lean oscillates with the linear theory's period 2 pi / sqrt(12/5 (Omega^2 - Omega_c^2))",
                  bool(abs(period - theory["period"]) < 0.05 * theory["period"]),
                  f"measured {period:.4g} s, linear theory {theory['period']:.4g} s")
    else:
        res.claim("above Omega_c = sqrt(g/(3r)) the lean stays within the linear theory's bound", None,
                  f"q3_dot = {run.y0['q3_dot']:.4g} is below Omega_c = {omega_c:.4g}: no bound; "
                  f"max |q2| = {lean.max():.4g}")
    res.claim("below Omega_c the disk leaves upright rolling: its lean grows tenfold or more",
              bool(lean_slow.max() > 10 * q20),
              f"q3_dot = {slow.y0['q3_dot']:.4g}: max |q2| = {lean_slow.max():.4g} from {q20:.4g}")
    res.claim("(integration check) energy is conserved", res.numbers["relative_energy_drift"] < 1e-8,
              f"relative drift {res.numbers['relative_energy_drift']:.1e}")
    res.data.update(t=fast_r.t, lean=fast_r["q2"], x=fast_r["x"], y=fast_r["y"],
                    t_slow=slow_r.t, lean_slow=slow_r["q2"], x_slow=slow_r["x"], y_slow=slow_r["y"],
                    omega=run.y0["q3_dot"], omega_slow=slow.y0["q3_dot"], omega_c=omega_c,
                    bound=theory.get("bound"))
    return res


def draw(res: SceneResult, fig) -> None:
    d = res.data
    a1, a2 = fig.subplots(1, 2, gridspec_kw={"width_ratios": (1.3, 1.0)})
    fast = rf"$\dot q_3 = {d['omega']:.3g}$ ({d['omega'] / d['omega_c']:.2f} $\Omega_c$)"
    slow = rf"$\dot q_3 = {d['omega_slow']:.3g}$ ({d['omega_slow'] / d['omega_c']:.2f} $\Omega_c$)"
    a1.plot(d["t"], d["lean"], color="C0", label=fast)
    a1.plot(d["t_slow"], d["lean_slow"], color="C3", label=slow)
    if d["bound"] is not None:
        a1.axhline(d["bound"], color="C0", ls=":", lw=0.8, label="linear theory's bound")
    a1.set_xlabel("t [s]")
    a1.set_ylabel(r"lean $q_2$ [rad]")
    a1.legend(loc="upper left", fontsize=8)
    a2.plot(d["x"], d["y"], color="C0")
    a2.plot(d["x_slow"], d["y_slow"], color="C3")
    a2.plot([0.0], [0.0], "ko", ms=3)
    a2.set_aspect("equal", adjustable="datalim")
    a2.set_xlabel("x [m]")
    a2.set_ylabel("y [m]")
    a2.set_title("contact point on the table", fontsize=9)
    fig.suptitle(r"rolling disk: upright rolling is stable for $\dot q_3^2 > \Omega_c^2 = g/(3r)$", fontsize=10)
    layout(fig, res.scene is SCENE, dict(left=0.0751, right=0.9833, bottom=0.1290, top=0.8461, wspace=0.2131))


SCENE = Scene(
    name="rolling_disk",
    title="rolling disk: stability of upright rolling",
    caption=("Not a figure of the paper. A uniform thin disk (radius r = 0.1 m, g = 9.81 m/s^2) rolling without "
             "slipping, leaned by 0.05 rad: spun at q3_dot above Omega_c = sqrt(g/(3r)) it keeps rolling, its lean "
             "oscillating within the linear theory's bound, along a wavy circle; below Omega_c it leans far over "
             "and curls around in loops."),
    why=("rolling_disk, full: derived by the same engine from the user-style example examples/rolling_disk.py "
         "(its Lagrangian and rolling constraints only); the pose gives the contact point's path"),
    run=RUN,
    plots="the lean q2(t) above and below the threshold, and the contact point's path on the table",
    reports=("omega_c", "q3_dot", "predicted_stable", "max_lean", "max_lean_linear_theory", "lean_period",
             "lean_period_linear_theory", "q3_dot_slow", "max_lean_slow", "relative_energy_drift",
             "distance_rolled"),
    compute=compute,
    draw=draw,
    settings={"slow_fraction": 0.7},
    figsize=(9.0, 4.5),
)
