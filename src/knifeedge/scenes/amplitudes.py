"""Scene ``amplitudes``: closed-form amplitudes (Eqs. an) against the simulation (paper Fig. 'amplitudes')."""
from __future__ import annotations

import numpy as np

from . import amplitude_theory as th
from .base import Scene, SceneResult
from .common import RATE_LABEL, T_LABEL, envelope, first_reversal, layout, omega, require_success
from .numerical import RUN


def compute(scene: Scene, progress) -> SceneResult:
    run = scene.run
    p, y0 = run.params, run.y0
    progress("integrating the single-mode equations")
    r = require_success(run.simulate(), scene)
    w = omega(p)
    a_theta0 = float(envelope(y0["theta"], y0["theta_dot"], w))
    a0 = th.asymptotic_spin(y0["phi_dot"], a_theta0, p["g"], p["ell"], p["L"])
    t_r = th.first_reversal_time(y0["phi_dot"], a_theta0, p["g"], p["ell"], p["L"], p["D"])
    a_theta, a_phi = th.amplitudes(r.t, t_r, a0, p["g"], p["ell"], p["L"], p["D"])
    sim_amp = envelope(r["theta"], r["theta_dot"], w)
    t_sim = first_reversal(r)
    err_theta = float(np.max(np.abs(sim_amp - a_theta)) / a0)
    err_phi = float(np.max(np.abs(r["phi_dot"] - a_phi)) / a0)
    res = SceneResult(scene)
    res.numbers.update({
        "A0": a0,
        "t_R_theory": t_r,
        "t_R_simulated": t_sim,
        "t_R_relative_difference": abs(t_r - t_sim) / t_sim,
        "max_error_A_theta_over_A0": err_theta,
        "max_error_A_phi_over_A0": err_phi,
        "A_theta_peak_theory": a0 * p["L"] / np.sqrt(p["g"] * p["ell"]),
        "A_theta_peak_simulated": float(sim_amp.max()),
    })
    res.claim("the closed-form amplitudes (an) agree with the full solution",
              err_theta < 0.05 and err_phi < 0.05,
              f"max |envelope - A_theta| = {err_theta:.2%} of A0, max |phi_dot - A_phi| = {err_phi:.2%} of A0; "
              f"reversal at t = {t_r:.2f} (theory, from the initial state alone) vs {t_sim:.2f} (simulated)")
    res.claim("an1 as printed, A_phi = +A0 tanh(A0 D t/(2 ell)), describes a spin that starts positive", False,
              "with phi_dot(0) > 0 the spin decreases through zero; the solution is A_phi = -A0 tanh(...) "
              "(sign erratum, docs/errata.md)")
    res.data.update(t=r.t, theta=r["theta"], phi_dot=r["phi_dot"], a_theta=a_theta, a_phi=a_phi, t_r=t_r)
    return res


def draw(res: SceneResult, fig) -> None:
    d = res.data
    ax = fig.subplots()
    ax.plot(d["t"], d["theta"], ":", color="C0", lw=0.7, label=r"$\theta(t)$, simulated (Fig. numerical)")
    ax.plot(d["t"], d["phi_dot"], ":", color="k", lw=1.4, zorder=4, label=r"$\dot\phi(t)$, simulated")
    ax.plot(d["t"], d["a_theta"], color="C0", lw=1.8, label=r"$A_\theta(t)$, Eq. an2 (corrected)")
    ax.plot(d["t"], d["a_phi"], color="C1", lw=1.8, label=r"$A_\phi(t)$, Eq. an1 (sign corrected)")
    ax.axhline(0, color="gray", lw=0.5)
    ax.axvline(d["t_r"], color="k", ls="--", lw=0.8, label=f"$t_R$ (theory) = {d['t_r']:.1f}")
    ax.set_xlabel(T_LABEL)
    ax.set_ylabel(r"$\theta,\ A_\theta$ [rad];  " + RATE_LABEL)
    ax.set_title(r"amplitude equations vs simulation: $A_0=0.1\sqrt{g/\ell}$, $\ell/L=1$, $D/\ell=1$", fontsize=10)
    ax.legend(fontsize=8, loc="lower left")
    layout(fig, res.scene is SCENE, dict(left=0.1373, right=0.9800, bottom=0.1167, top=0.9278))


SCENE = Scene(
    name="amplitudes",
    title="closed-form amplitudes vs simulation",
    caption=("Analytical solutions (Eqs. an) of the amplitude Equations (Chap3), for A0 = 0.1 sqrt(g/l), l/L = 1, "
             "D/l = 1. In dotted lines we also plot the full solution for theta (Fig. numerical) for comparison."),
    why=("closed-form Eqs. an (no integration) for the theory; the reduced single-mode run of scene 'numerical' "
         "for the dotted solution -- 3 states, no pose"),
    run=RUN,
    plots="A_theta(t), A_phi(t) from Eqs. an (corrected) with theta(t), phi_dot(t) simulated, dotted",
    reports=("A0", "t_R_theory", "t_R_simulated", "t_R_relative_difference", "max_error_A_theta_over_A0",
             "max_error_A_phi_over_A0", "A_theta_peak_theory", "A_theta_peak_simulated"),
    compute=compute,
    draw=draw,
)
