"""Scene ``numerical``: one spin reversal of the single-mode knife edge (paper Fig. 'numerical')."""
from __future__ import annotations

import numpy as np

from .base import RunSpec, Scene, SceneResult
from .common import RATE_LABEL, T_LABEL, envelope, layout, mark_reversals, omega, relative_energy_drift, require_success

RUN = RunSpec(
    model="single_mode", fidelity="reduced",
    params={"g": 1.0, "ell": 1.0, "L": 1.0, "D": 1.0},
    y0={"theta": 1e-3, "theta_dot": 0.0, "phi_dot": 0.1},
    t_span=(0.0, 250.0), method="DOP853", rtol=1e-10, atol=1e-12, n_eval=8001,
)


def compute(scene: Scene, progress) -> SceneResult:
    progress("integrating the single-mode equations")
    r = scene.run.simulate()
    res = SceneResult(scene)
    require_success(r, scene)
    w = omega(scene.run.params)
    amp = envelope(r["theta"], r["theta_dot"], w)
    rev = r.reversal_times
    check = scene.run.with_(rtol=scene.run.rtol * 1e-2, atol=scene.run.atol * 1e-2, n_eval=None).simulate()
    shift = float(abs(check.reversal_times[0] - rev[0])) if len(rev) and len(check.reversal_times) else float("nan")
    phi0, phi1 = float(r["phi_dot"][0]), float(r["phi_dot"][-1])
    res.numbers.update({
        "reversal_times": [float(t) for t in rev],
        "n_reversals": len(rev),
        "phi_dot_start": phi0,
        "phi_dot_end": phi1,
        "theta_amplitude_start": float(amp[0]),
        "theta_amplitude_max": float(amp.max()),
        "t_theta_amplitude_max": float(r.t[np.argmax(amp)]),
        "theta_amplitude_end": float(amp[-1]),
        "reversal_time_change_at_100x_tighter_rtol": shift,
        "relative_energy_change_from_truncation": relative_energy_drift(r),
        "nfev": r.nfev,
    })
    res.claim("phi_dot changes sign once (one inversion)", len(rev) == 1,
              f"{len(rev)} reversal(s), at t = {', '.join(f'{t:.3f}' for t in rev)}")
    res.claim("the spin ends reversed with the same magnitude", abs(phi1 + phi0) < 1e-3 * abs(phi0),
              f"phi_dot {phi0:+.6f} -> {phi1:+.6f}")
    res.claim("theta's amplitude grows, peaks at the reversal, then decays",
              amp[-1] < 2 * amp[0] and amp.max() > 10 * amp[0] and abs(r.t[np.argmax(amp)] - rev[0]) < 5.0 if len(rev) else False,
              f"amplitude {amp[0]:.2e} -> max {amp.max():.4f} at t = {r.t[np.argmax(amp)]:.1f} -> {amp[-1]:.2e}")
    res.claim("(integration check) the reversal time is converged in the tolerance",
              bool(len(rev)) and shift < 1e-6 * rev[0],
              f"moves by {shift:.1e} at rtol {scene.run.rtol * 1e-2:g}; the energy changes by "
              f"{res.numbers['relative_energy_change_from_truncation']:.1e} (relative) because the reduced equations conserve it only to their "
              "truncation order, not by integration error")
    res.data.update(t=r.t, theta=r["theta"], phi_dot=r["phi_dot"], amplitude=amp, reversal_times=rev)
    return res


def draw(res: SceneResult, fig) -> None:
    d = res.data
    a1, a2 = fig.subplots(2, 1, sharex=True)
    a1.plot(d["t"], d["theta"], lw=0.4, color="C0", label=r"$\theta(t)$")
    a1.plot(d["t"], d["amplitude"], lw=1.0, color="C3", ls="--", label=r"amplitude $\sqrt{\theta^2+\dot\theta^2/\omega^2}$")
    a1.set_ylabel(r"$\theta$ [rad]")
    a1.legend(loc="upper right", fontsize=8)
    a2.plot(d["t"], d["phi_dot"], color="C1")
    a2.axhline(0, color="gray", lw=0.5)
    mark_reversals(a2, d["reversal_times"])
    mark_reversals(a1, d["reversal_times"], label=False)
    a2.set_ylabel(RATE_LABEL)
    a2.set_xlabel(T_LABEL)
    a2.legend(loc="upper right", fontsize=8)
    a1.set_title("single mode: spin inversion (Eqs. FINAL3), " + r"$\ell/L=1,\ D/\ell=1,\ \dot\phi_0=0.1\sqrt{g/\ell}$",
                 fontsize=10)
    layout(fig, res.scene is SCENE, dict(left=0.1252, right=0.9800, bottom=0.1167, top=0.9278, hspace=0.0932))


SCENE = Scene(
    name="numerical",
    title="single-mode spin inversion",
    caption=("Numerical solution of the single mode rattleback of Equations (FINAL3) illustrating the spin inversion "
             "accompanied by an increase and decrease of the amplitude of oscillating mode. Initial condition has "
             "phi_dot = 0.1 sqrt(g/l), and theta very small. Other parameters used were l/L = 1, D/l = 1."),
    why=("reduced single-mode model: the paper's Eqs. FINAL3 are its small-angle truncation (with the erratum on "
         "FINAL1); 3 states, no pose -- the figure shows only theta(t) and phi_dot(t)"),
    run=RUN,
    plots="theta(t) with its amplitude, and phi_dot(t) with the reversal marked",
    reports=("reversal_times", "n_reversals", "phi_dot_start", "phi_dot_end", "theta_amplitude_start",
             "theta_amplitude_max", "t_theta_amplitude_max", "theta_amplitude_end", "reversal_time_change_at_100x_tighter_rtol", "relative_energy_change_from_truncation", "nfev"),
    compute=compute,
    draw=draw,
)
