"""Scene ``celt``: the classical rattleback of Kane & Levinson (1982), both spin directions, with and without damping.

T. R. Kane and D. A. Levinson, "Realistic mathematical modeling of the
rattleback", Int. J. Non-Linear Mech. 17 (1982) 175-186: the ellipsoidal celt
of the ``kane_levinson_1982`` preset, started at tilts ``al = be = 0.5 deg``
with ``omega0 = (0, 0, Omega)``.  A reversal of a celt is a cluster of
crossings of ``omega . n`` (the rocking rides on the spin); the scene reports
the crossings and the episodes (crossings closer than ``episode_gap``).
"""
from __future__ import annotations

import math

import numpy as np

from .base import RunSpec, Scene, SceneResult
from .common import claim_energy_conserved, layout, require_success

#: the generated functions :func:`energy_balance` calls compiled (its runs' thousands of samples)
BALANCE_COMPILES = (("celt", "full", "energy"), ("celt", "full", "power_dissipated"))
#: Kane & Levinson's initial tilts (about the body x and y axes)
TILT = math.radians(0.5)
N0 = (math.cos(TILT) * math.sin(TILT), math.sin(TILT), math.cos(TILT) * math.cos(TILT))


def initial_state(n0, omega0) -> dict:
    """Closed state of the celt as a mapping, from the upward vertical ``n0`` and the body angular velocity."""
    from ..models import load

    m = load("celt")
    return dict(zip(m.closed_state_names, m.initial_state(n0=n0, omega0=omega0).tolist()))


def preset(name: str, **overrides) -> dict:
    from ..models import load

    m = load("celt")
    return dict(zip(m.param_names, m.preset(name, **overrides).tolist()))


def episodes(times, gap: float) -> list:
    """Group zero crossings closer than ``gap`` into episodes ``(start, end, n_crossings)``.

    An episode with an odd number of crossings reverses the spin; an even one
    is a rocking excursion that leaves it as it was.
    """
    out: list = []
    for t in np.asarray(times, dtype=float):
        if out and t - out[-1][1] < gap:
            out[-1] = (out[-1][0], float(t), out[-1][2] + 1)
        else:
            out.append((float(t), float(t), 1))
    return out


def max_tilt_deg(r) -> float:
    """Largest angle between the body z axis and the vertical along a run [deg]."""
    nz = r["n_z"] / np.sqrt(r["n_x"] ** 2 + r["n_y"] ** 2 + r["n_z"] ** 2)
    return float(np.degrees(np.arccos(np.clip(nz.min(), -1.0, 1.0))))


def energy_balance(r) -> float:
    """``max |E(t) + W(t) - E(0)| / |E(0)|``, ``W`` the work dissipated (Simpson on the output grid)."""
    from scipy.integrate import cumulative_simpson

    E = r.energy
    W = cumulative_simpson(r.model.power_dissipated(r.y, r.p), x=r.t, initial=0.0)
    return float(np.max(np.abs(E + W - E[0])) / abs(E[0]))


RUN = RunSpec(
    model="celt", fidelity="full",
    params=preset("kane_levinson_1982"),
    y0=initial_state(N0, (0.0, 0.0, 5.0)),
    t_span=(0.0, 20.0), method="DOP853", rtol=1e-10, atol=1e-12, n_eval=20001,
)


def compute(scene: Scene, progress) -> SceneResult:
    res = SceneResult(scene)
    st = scene.settings
    base = scene.run
    runs = {}
    for sigma in st["sigmas"]:
        for spin in st["spins"]:
            progress(f"integrating the celt, Omega = {spin:+g} rad/s, sigma = {sigma:g} N m s")
            spec = base.with_(sigma=sigma, **initial_state(N0, (0.0, 0.0, spin)))
            r = require_success(spec.simulate(), scene)
            runs[(sigma, spin)] = r
            key = f"Omega{spin:+g}_sigma{sigma:g}"
            eps = episodes(r.reversal_times, st["episode_gap"])
            reversals = [e for e in eps if e[2] % 2 == 1]
            res.numbers.update({
                f"crossings_{key}": [float(t) for t in r.reversal_times],
                f"reversal_episodes_{key}": [e[0] for e in reversals],
                f"spin_end_{key}": float(r["omega_n"][-1]),
                f"max_tilt_deg_{key}": max_tilt_deg(r),
                f"energy_balance_{key}": energy_balance(r),
            })
    undamped = [s for s in st["spins"] if (0.0, s) in runs]
    for spin in undamped:
        key = f"Omega{spin:+g}_sigma0"
        claim_energy_conserved(res, f"undamped, Omega = {spin:+g}: ", res.numbers[f"energy_balance_{key}"])
    damped = max(st["sigmas"])
    if damped > 0:
        rev = {s: len(res.numbers[f"reversal_episodes_Omega{s:+g}_sigma{damped:g}"]) for s in st["spins"]}
        one_way = sorted(rev.values()) == [0, 1]
        res.claim(f"with damping sigma = {damped:g}, only one spin direction reverses (the classical one-way bias)",
                  one_way, ", ".join(f"Omega = {s:+g}: {n} reversal(s)" for s, n in rev.items()))
    res.data.update(runs={k: (r.t, r["omega_n"], r.reversal_times) for k, r in runs.items()})
    return res


def draw(res: SceneResult, fig) -> None:
    runs = res.data["runs"]
    sigmas = sorted({s for s, _ in runs})
    axes = fig.subplots(len(sigmas), 1, sharex=True, squeeze=False)[:, 0]
    for ax, sigma in zip(axes, sigmas):
        for i, ((s, spin), (t, wn, rev)) in enumerate(sorted(runs.items())):
            if s != sigma:
                continue
            ax.plot(t, wn, lw=0.6, color=f"C{i % 2}", label=rf"$\Omega_0={spin:+g}$ rad/s")
            ax.plot(rev, np.zeros_like(rev), "k|", ms=8)
        ax.axhline(0, color="gray", lw=0.5)
        ax.set_ylabel(r"$\omega\cdot n$ [rad/s]")
        ax.set_title(rf"$\sigma = {sigma:g}$ N m s", fontsize=9)
        ax.legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel("t [s]")
    fig.suptitle("Kane & Levinson (1982) rattleback: vertical spin; ticks at the zero crossings", fontsize=10)
    layout(fig, res.scene is SCENE, dict(left=0.0872, right=0.9800, bottom=0.0968, top=0.8963, hspace=0.1730))


SCENE = Scene(
    name="celt",
    title="classical rattleback (Kane & Levinson 1982)",
    caption=("The celt of Kane & Levinson (1982), ellipsoid a, b, c = 0.20, 0.03, 0.02 m, centre of mass h = 0.01 m "
             "below the ellipsoid's centre, I_xy = 2e-5 kg m^2, started at tilts of 0.5 deg with spin +5 and -5 rad/s, "
             "without and with a damping torque -sigma*omega (sigma = 1e-4 N m s)."),
    why=("full rigid-body model (derivation/rigid.py): exact rolling of the ellipsoid, no small-angle truncation; "
         "state n, omega in body axes, no pose -- the figure shows the vertical spin omega.n"),
    run=RUN,
    plots="omega.n against time for both spin directions, one panel per damping",
    reports=tuple(f"{q}_Omega{s:+g}_sigma{g:g}" for g in (0.0, 1e-4) for s in (5.0, -5.0)
                  for q in ("crossings", "reversal_episodes", "spin_end", "max_tilt_deg", "energy_balance")),
    compute=compute,
    draw=draw,
    settings={"spins": (5.0, -5.0), "sigmas": (0.0, 1e-4), "episode_gap": 1.0},
    figsize=(7.5, 6.0),
    compiles=BALANCE_COMPILES,
)
