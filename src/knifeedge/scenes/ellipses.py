"""Scene ``ellipses``: phase portrait of the single-mode amplitude equations (paper Fig. 'Elipses').

The orbits of Eqs. Chap3 are the ellipses ``A_phi^2 + (g ell/L^2) A_theta^2 = A0^2``,
traversed from ``A_phi = +A0`` to ``A_phi = -A0``; the equilibria
``(A_theta = 0, A_phi)`` are unstable for ``A_phi > 0`` (eigenvalue
``D A_phi / (2 ell) > 0``) and stable for ``A_phi < 0`` -- the reverse of
the paper's statement (``docs/errata.md``).  The scene draws the closed-form
orbits and checks them, and the stability, against simulations.
"""
from __future__ import annotations

import math

import numpy as np

from . import amplitude_theory as th
from .base import RunSpec, Scene, SceneResult
from .common import envelope, layout, omega, require_success

RUN = RunSpec(
    model="single_mode", fidelity="amplitude",
    params={"g": 1.0, "ell": 1.0, "L": 0.5, "D": 1.0},
    y0={"A_theta": 1e-4, "A_phi": 0.1},
    t_span=(0.0, 300.0), method="DOP853", rtol=1e-10, atol=1e-14, n_eval=2001,
)
#: the check against the real dynamics: the reduced model from a tilt of 1e-3
CHECK = RunSpec(
    model="single_mode", fidelity="reduced", params=RUN.params,
    y0={"theta": 1e-3, "theta_dot": 0.0, "phi_dot": 0.1},
    t_span=(0.0, 250.0), method="DOP853", rtol=1e-10, atol=1e-12, n_eval=6001,
)


def _rate(t, amp, mask) -> float:
    """Exponential growth rate of ``amp`` on ``mask`` (least-squares slope of log amp)."""
    return float(np.polyfit(t[mask], np.log(amp[mask]), 1)[0])


def _period_mean(t, amp, phi_dot, period):
    """Running means over one oscillation period (``t`` equally spaced); shortened arrays."""
    n = max(1, int(round(period / (t[1] - t[0]))))
    kernel = np.ones(n) / n
    return (np.convolve(t, kernel, "valid"), np.convolve(amp, kernel, "valid"),
            np.convolve(phi_dot, kernel, "valid"))


def compute(scene: Scene, progress) -> SceneResult:
    orbit_run = scene.run
    p = orbit_run.params
    run = CHECK.with_(**p)
    w = omega(p)
    res = SceneResult(scene)
    orbits = []
    for a0 in scene.settings["ellipse_A0"]:
        progress(f"integrating the amplitude equations from A_phi = {a0:g}")
        t_r = th.first_reversal_time(a0, orbit_run.y0["A_theta"], p["g"], p["ell"], p["L"], p["D"])
        o = require_success(orbit_run.with_(A_phi=a0, t_end=2.2 * t_r).simulate(), scene)
        orbits.append((o["A_theta"], o["A_phi"]))
    sims = []
    for a0 in scene.settings["simulated_A0"]:
        progress(f"integrating the single-mode equations from phi_dot = {a0:g}")
        t_r = th.first_reversal_time(a0, run.y0["theta"], p["g"], p["ell"], p["L"], p["D"])
        r = require_success(run.with_(phi_dot=a0, t_end=2.4 * t_r).simulate(), scene)
        t, amp, phi_dot = _period_mean(r.t, envelope(r["theta"], r["theta_dot"], w), r["phi_dot"], 2 * math.pi / w)
        inv = phi_dot**2 + p["g"] * p["ell"] / p["L"] ** 2 * amp**2
        if not r.reversal_times.size:
            raise RuntimeError(f"scene {scene.name}: the run from phi_dot = {a0:g} has no spin reversal before "
                               f"t = {2.4 * t_r:g}")
        rev = float(r.reversal_times[0])
        early = t < 0.5 * rev
        late = t > rev + 0.6 * (t[-1] - rev)
        sims.append({
            "A0": a0, "amp": amp, "phi_dot": phi_dot,
            "ellipse_deviation": float(np.max(np.abs(inv - inv[0])) / inv[0]),
            "growth_rate": _rate(t, amp, early), "phi_dot_early": float(np.mean(phi_dot[early])),
            "decay_rate": _rate(t, amp, late), "phi_dot_late": float(np.mean(phi_dot[late])),
        })
    s = sims[0]
    predicted_growth = p["D"] * s["phi_dot_early"] / (2 * p["ell"])
    predicted_decay = p["D"] * s["phi_dot_late"] / (2 * p["ell"])
    res.numbers.update({
        "eigenvalue_theory_at_A_phi": f"D A_phi / (2 ell) = {p['D'] / (2 * p['ell']):g} A_phi",
        "growth_rate_measured_near_A_phi_pos": s["growth_rate"],
        "growth_rate_theory_near_A_phi_pos": predicted_growth,
        "decay_rate_measured_near_A_phi_neg": s["decay_rate"],
        "decay_rate_theory_near_A_phi_neg": predicted_decay,
        "max_relative_deviation_from_ellipse": max(x["ellipse_deviation"] for x in sims),
    })
    res.claim("the solution curves are ellipses in the (A_theta, A_phi) plane (to the averaging error, "
              "O(phi_dot/omega))",
              all(x["ellipse_deviation"] < x["A0"] / w for x in sims),
              "simulated (amplitude, phi_dot) keeps A_phi^2 + (g ell/L^2) A_theta^2 within "
              + ", ".join(f"{x['ellipse_deviation']:.2%} (A0/omega = {x['A0'] / w:g})" for x in sims))
    res.claim("equilibria with A_phi > 0 are stable, with A_phi < 0 unstable (paper)", False,
              f"near A_phi = {s['phi_dot_early']:+.3f} the tilt amplitude grows at rate {s['growth_rate']:+.4f} "
              f"(theory {predicted_growth:+.4f}): unstable; near A_phi = {s['phi_dot_late']:+.3f} it decays at "
              f"{s['decay_rate']:+.4f} (theory {predicted_decay:+.4f}): stable -- the paper's statement is reversed")
    res.data.update(sims=sims, orbits=orbits, params=dict(p))
    return res


def draw(res: SceneResult, fig) -> None:
    ax = fig.subplots()
    levels = res.scene.settings["ellipse_A0"]
    for i, (a_theta, a_phi) in enumerate(res.data["orbits"]):
        for side in (1, -1):
            x, y = side * a_theta, a_phi
            ax.plot(x, y, color="k", lw=1.2,
                    label="orbits of the amplitude equations (Chap3)" if (i == 0 and side == 1) else None)
            # arrows along the flow (from A_phi = +A0 down to A_phi = -A0)
            for frac in ((0.3, 0.7) if len(x) > 6 else ()):
                j = int(np.argmin(np.abs(y - (1 - 2 * frac) * levels[i])))
                j = min(j, len(x) - 6)
                ax.annotate("", xy=(x[j + 5], y[j + 5]), xytext=(x[j], y[j]),
                            arrowprops=dict(arrowstyle="-|>", color="k", lw=1.0))
    for i, sim in enumerate(res.data["sims"]):
        ax.plot(sim["amp"], sim["phi_dot"], color=f"C{i + 1}", lw=2.5, alpha=0.6,
                label=rf"simulated envelope (period mean), reduced model, $\dot\phi_0={sim['A0']:g}$")
    eq = np.array(levels)
    ax.plot(np.zeros_like(eq), eq, "o", mfc="white", mec="C3", ms=8, label=r"unstable equilibria ($A_\phi>0$)")
    ax.plot(np.zeros_like(eq), -eq, "o", color="C0", ms=8, label=r"stable equilibria ($A_\phi<0$)")
    ax.axhline(0, color="gray", lw=0.5)
    ax.axvline(0, color="gray", lw=0.5)
    ax.set_xlabel(r"$A_\theta$ [rad]")
    ax.set_ylabel(r"$\dot\phi \equiv A_\phi\ [\sqrt{g/\ell}]$")
    ax.set_title(r"phase portrait of the amplitude equations, $\ell/L=2$, $D/\ell=1$", fontsize=10)
    ax.set_aspect("equal")
    fig.legend(fontsize=8, loc="lower center", ncol=2)
    layout(fig, res.scene is SCENE, dict(left=0.0214, right=0.9786, bottom=0.1979, top=0.9543), rect=(0, 0.12, 1, 1))


SCENE = Scene(
    name="ellipses",
    title="phase portrait of the amplitude equations",
    caption="Phase portrait of the motion amplitudes of the single mode rattleback.",
    why=("the single-mode amplitude model (2 amplitudes, no fast oscillation) draws the portrait; two reduced "
         "single-mode runs (3 states) only check the ellipses and the stability against the real dynamics"),
    run=RUN,
    plots="ellipses A_phi^2 + (g ell/L^2) A_theta^2 = A0^2 with the flow direction, equilibria open (unstable) / filled "
          "(stable), simulated envelopes on top",
    reports=("eigenvalue_theory_at_A_phi", "growth_rate_measured_near_A_phi_pos", "growth_rate_theory_near_A_phi_pos",
             "decay_rate_measured_near_A_phi_neg", "decay_rate_theory_near_A_phi_neg",
             "max_relative_deviation_from_ellipse"),
    compute=compute,
    draw=draw,
    uses=(("single_mode", "amplitude", False), ("single_mode", "reduced", False)),
    settings={"ellipse_A0": (0.05, 0.1, 0.15, 0.2), "simulated_A0": (0.1, 0.2)},
    figsize=(7.0, 7.5),
)
