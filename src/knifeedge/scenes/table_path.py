"""Scene ``table_path``: where the knife edge goes on the table while its spin reverses.

The only scene that needs the pose ``(phi, x, y)``: the closed state says
nothing about position, which follows by quadrature of the constraint
velocities.  ``(x, y)`` is the middle point O of the knife edge and ``phi``
its heading.
"""
from __future__ import annotations

import math

import numpy as np

from .base import Scene, SceneResult
from .common import T_LABEL, layout, mark_reversals, require_success
from .numerical2 import RUN as TWO_MODE_RUN

RUN = TWO_MODE_RUN.with_(pose=True, rtol=1e-12, t_end=5600.0, n_eval=56001)


def compute(scene: Scene, progress) -> SceneResult:
    progress("integrating the two-mode equations with the pose")
    r = require_success(scene.run.simulate(), scene)
    x, y, phi = r["x"], r["y"], r["phi"]
    rev = r.reversal_times
    dist = np.hypot(x - x[0], y - y[0])
    turns = [float(np.interp(t, r.t, phi) / (2 * math.pi)) for t in rev]
    res = SceneResult(scene)
    res.numbers.update({
        "reversal_times": [float(t) for t in rev],
        "heading_at_reversals_turns": turns,
        "max_distance_of_O_from_start": float(dist.max()),
        "distance_of_O_from_start_at_end": float(dist[-1]),
        "tilt_amplitude_max": float(max(np.abs(r["theta1"]).max(), np.abs(r["theta2"]).max())),
    })
    res.claim("the knife edge spins one way, stops, and spins back (reversals of phi_dot)", len(rev) >= 1,
              f"heading at the reversals: {', '.join(f'{u:.2f}' for u in turns)} turns")
    res.claim("it rocks in place rather than travelling", dist.max() < 0.1 * scene.run.params["ell"],
              f"point O stays within {dist.max():.4f} ell of its start (ends {dist[-1]:.4f} ell away)")
    w = (r.t > rev[0] - scene.settings["window"]) & (r.t < rev[0] + scene.settings["window"]) if len(rev) else r.t < 300
    res.data.update(t=r.t, x=x, y=y, phi=phi, rev=rev, window=w)
    return res


def draw(res: SceneResult, fig) -> None:
    d = res.data
    a0, a1, a2 = fig.subplots(1, 3, gridspec_kw={"width_ratios": [1, 1, 1.2]})
    a0.plot(d["x"], d["y"], color="0.6", lw=0.2)
    w = d["window"]
    a0.plot(d["x"][w], d["y"][w], color="C3", lw=0.3)
    a0.set_aspect("equal")
    a0.set_title("(a) path of O, whole run\n(red: around the first reversal)", fontsize=9)
    a0.set_xlabel(r"$x\ [\ell]$")
    a0.set_ylabel(r"$y\ [\ell]$")
    sc = a1.scatter(d["x"][w], d["y"][w], c=d["t"][w], s=0.5, cmap="coolwarm")
    a1.set_aspect("equal")
    a1.set_title("(b) path of O around the first\nreversal, coloured by time", fontsize=9)
    a1.set_xlabel(r"$x\ [\ell]$")
    fig.colorbar(sc, ax=a1, shrink=0.6, label=T_LABEL)
    for ax in (a0, a1):
        ax.tick_params(labelsize=7)
        ax.ticklabel_format(style="sci", scilimits=(-2, 2))
    a2.plot(d["t"], d["phi"] / (2 * math.pi), color="C1")
    mark_reversals(a2, d["rev"])
    a2.set_xlabel(T_LABEL)
    a2.set_ylabel(r"heading $\phi / 2\pi$ [turns]")
    a2.set_title("(c) heading of the knife edge", fontsize=9)
    a2.legend(fontsize=8)
    fig.suptitle(r"two-mode knife edge on the table: $\ell/L=1/2$, $D/\ell=1/2$, $\alpha=\pi/4$, "
                 r"$\dot\phi_0=0.1\sqrt{g/\ell}$", fontsize=10)
    layout(fig, res.scene is SCENE, dict(left=0.0495, right=0.9875, bottom=0.1395, top=0.7515, wspace=0.3625),
           rect=(0, 0, 1, 0.92))


SCENE = Scene(
    name="table_path",
    title="the knife edge on the table during reversals",
    caption=("Trajectory of the knife edge on the table during spin reversals (not a figure of the paper): the middle "
             "point O of the edge and its heading phi, for the two-mode scene of Fig. Numerical2."),
    why=("reduced two-mode model with the pose (8 states): the only scene that asks where the body is, so the only one "
         "that integrates (phi, x, y). It reports no reversal time beyond the first: the later ones are ill-conditioned "
         "(see numerical2), and adding the pose to the error control moves them"),
    run=RUN,
    plots="path of O on the table (whole run, and around the first reversal coloured by time), heading phi(t)",
    reports=("reversal_times", "heading_at_reversals_turns", "max_distance_of_O_from_start",
             "distance_of_O_from_start_at_end", "tilt_amplitude_max"),
    compute=compute,
    draw=draw,
    settings={"window": 150.0},
    figsize=(12.0, 4.6),
)
