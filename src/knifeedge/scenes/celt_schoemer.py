"""Scene ``celt_schoemer``: Schoemer's golden-ratio rattleback, started upright with a slow spin.

The ``schoemer`` preset of the ``celt`` model (ellipsoid a = (1 + sqrt 5)/2,
b = c = 1, m = 0.2, h = 0.1875, I_xy = -0.025, no damping), started upright
with ``omega0 = (0.01, -0.02, -2.0)`` rad/s in body axes.
"""
from __future__ import annotations

import numpy as np

from .base import RunSpec, Scene, SceneResult
from .celt import BALANCE_COMPILES, energy_balance, episodes, initial_state, max_tilt_deg, preset
from .common import claim_energy_conserved, layout, require_success

RUN = RunSpec(
    model="celt", fidelity="full",
    params=preset("schoemer"),
    y0=initial_state((0.0, 0.0, 1.0), (0.01, -0.02, -2.0)),
    t_span=(0.0, 60.0), method="DOP853", rtol=1e-10, atol=1e-12, n_eval=12001,
)


def compute(scene: Scene, progress) -> SceneResult:
    progress("integrating Schoemer's rattleback")
    r = require_success(scene.run.simulate(), scene)
    res = SceneResult(scene)
    eps = episodes(r.reversal_times, scene.settings["episode_gap"])
    reversals = [e[0] for e in eps if e[2] % 2 == 1]
    w0, w1 = float(r["omega_n"][0]), float(r["omega_n"][-1])
    res.numbers.update({
        "crossings": [float(t) for t in r.reversal_times],
        "reversal_episodes": reversals,
        "spin_start": w0,
        "spin_end": w1,
        "max_tilt_deg": max_tilt_deg(r),
        "energy_balance": energy_balance(r),
        "nfev": r.nfev,
    })
    res.claim("the spin reverses once", len(reversals) == 1 and w0 * w1 < 0,
              f"{len(reversals)} reversal episode(s) at t = {', '.join(f'{t:.4f}' for t in reversals)} s; "
              f"omega.n {w0:+.4f} -> {w1:+.4f} rad/s")
    claim_energy_conserved(res, "", res.numbers["energy_balance"])
    res.data.update(t=r.t, spin=r["omega_n"], tilt=np.degrees(np.arccos(np.clip(r["n_z"], -1, 1))),
                    reversal_times=r.reversal_times)
    return res


def draw(res: SceneResult, fig) -> None:
    d = res.data
    a1, a2 = fig.subplots(2, 1, sharex=True)
    a1.plot(d["t"], d["tilt"], lw=0.5, color="C0")
    a1.set_ylabel("tilt of the body z axis [deg]")
    a2.plot(d["t"], d["spin"], color="C1")
    a2.plot(d["reversal_times"], np.zeros_like(d["reversal_times"]), "k|", ms=8)
    a2.axhline(0, color="gray", lw=0.5)
    a2.set_ylabel(r"$\omega\cdot n$ [rad/s]")
    a2.set_xlabel("t [s]")
    a1.set_title("Schoemer's rattleback, upright start, $\\omega_0 = (0.01, -0.02, -2)$ rad/s", fontsize=10)
    layout(fig, res.scene is SCENE, dict(left=0.0872, right=0.9800, bottom=0.1056, top=0.9377, hspace=0.0907))


SCENE = Scene(
    name="celt_schoemer",
    title="Schoemer's rattleback",
    caption=("Golden-ratio ellipsoid rattleback (a = (1 + sqrt 5)/2, b = c = 1, m = 0.2, h = 0.1875, "
             "I_xy = -0.025), started upright with omega0 = (0.01, -0.02, -2.0) rad/s, no damping."),
    why="full rigid-body celt model with the schoemer preset; no pose -- the figure shows the tilt and omega.n",
    run=RUN,
    plots="tilt of the body z axis and omega.n against time, zero crossings marked",
    reports=("crossings", "reversal_episodes", "spin_start", "spin_end", "max_tilt_deg", "energy_balance", "nfev"),
    compute=compute,
    draw=draw,
    settings={"episode_gap": 1.0},
    compiles=BALANCE_COMPILES,
)
