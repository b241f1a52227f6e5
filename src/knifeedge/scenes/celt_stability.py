"""Scene ``celt_stability``: why a celt prefers one spin direction, from the linearization of its steady spins.

The growth rates (real parts of the physical eigenvalues, :func:`knifeedge.stability`) of the upright steady
spin against the spin ``Omega``, for the Kane & Levinson (1982) and Schoemer sets, undamped and damped, every
change of stability (:func:`knifeedge.stability_boundaries`, searched in ``boundary_interval``) marked, and the
slow-spin slopes of Moffatt & Tokieda (Nonlinearity 21 (2008) T1): pitch ``lambda Omega``, roll ``-mu Omega``
(``celt_amplitude.moffatt_tokieda``, derived from their formulas, not from the rigid body; evaluated as plain
Python: two numbers per parameter set do not pay for its compilation).  The model is the full rigid celt,
whose ``jvp_into`` the Lyapunov loop of scene ``celt_chaos`` compiles (``knifeedge figures`` compiles it once
for both); the small-tilt celt (``scene.with_(fidelity="reduced")``) gives the same boundaries to 1e-12.
"""
from __future__ import annotations

import numpy as np

from ..models import load
from ..stability import stability, stability_boundaries
from .base import RunSpec, Scene, SceneResult
from .common import layout


def _preset(name: str) -> dict:
    m = load("celt", "full")
    return dict(zip(m.param_names, m.preset(name).tolist()))


#: the two parameter sets: Kane & Levinson from the preset, Schoemer's from the scene's run (its base point)
SETS = (("kl", "Kane-Levinson"), ("schoemer", "Schoemer"))

RUN = RunSpec(
    model="celt", fidelity="full",
    params=_preset("schoemer"),
    y0={"n_x": 0.0, "n_y": 0.0, "n_z": 1.0, "omega_x": 0.0, "omega_y": 0.0, "omega_z": -2.0, "omega_n": -2.0},
    t_span=(0.0, 1.0), n_eval=None,
)


def _params(scene: Scene, key: str, damped: bool, m) -> np.ndarray:
    base = dict(scene.run.params) if key == "schoemer" else _preset("kane_levinson_1982")
    base["sigma"] = scene.settings["sigma"][key] if damped else 0.0
    # the small-tilt celt has no products of inertia I_xz, I_yz: zero ones are left out for it
    return m.params(**{k: v for k, v in base.items() if k in m.param_names or v != 0.0})


def _one_set(scene: Scene, m, amp, key: str, res: SceneResult) -> None:
    s = scene.settings
    spins = np.linspace(*s["spin_range"], s["n_spins"])
    # two numbers per set: the formula as plain Python (compiling it cost 1 s of CPU; same arithmetic)
    q = dict(zip(m.param_names, _params(scene, key, False, m)))
    lam, mu = (float(x) for x in amp.module.moffatt_tokieda.py_func(amp.params(**{k: q[k] for k in amp.param_names}))[:2])
    tables = {}
    for damped in (False, True):
        p = _params(scene, key, damped, m)
        label = f"{key}_{'damped' if damped else 'undamped'}"
        tables[damped] = stability(m, p, "steady_spin", spins)
        found = stability_boundaries(m, p, "steady_spin", s["boundary_interval"])
        res.numbers[f"boundaries_{label}"] = [float(b) for b in found]
        res.data[f"boundaries_{label}"] = found
        res.data[f"eig_{label}"] = tables[damped].eigenvalues
    slow = stability(m, _params(scene, key, False, m), "steady_spin", [s["slope_spin"]])
    slopes = {nm: float(ev.real) / s["slope_spin"] for nm, ev in zip(slow.names[0], slow.eigenvalues[0])}
    res.numbers.update({f"mt_lambda_{key}": lam, f"mt_mu_{key}": mu,
                        f"slope_pitch_{key}": slopes["pitch"], f"slope_roll_{key}": slopes["roll"],
                        f"damping_shift_{key}": float(np.abs(tables[True].max_growth_rate
                                                             - tables[False].max_growth_rate).max())})
    res.data[f"mt_{key}"] = (lam, mu)
    res.data["spins"] = spins
    err = max(abs(slopes["pitch"] / lam - 1), abs(slopes["roll"] / -mu - 1))
    res.claim(f"{key}: slow-spin growth rates are Moffatt-Tokieda's lambda Omega (pitch), -mu Omega (roll)",
              err < s["slope_rtol"], f"at Omega = {s['slope_spin']:g}: pitch {slopes['pitch']:.8g} vs lambda "
              f"{lam:.8g}, roll {slopes['roll']:.8g} vs -mu {-mu:.8g} (largest relative difference {err:.1e})")


def compute(scene: Scene, progress) -> SceneResult:
    m = load("celt", scene.run.fidelity)
    amp = load("celt", "amplitude")
    res = SceneResult(scene)
    for key, name in SETS:
        progress(f"linearizing the steady spins of the {name} celt")
        _one_set(scene, m, amp, key, res)
    lo, hi = scene.settings["boundary_interval"]
    kl = res.numbers["boundaries_kl_undamped"]
    res.claim("the undamped Kane-Levinson celt's steady spin is unstable in both directions at every spin", not kl,
              f"changes of stability in ({lo:g}, {hi:g}) rad/s: {', '.join(f'{b:.12g}' for b in kl) or 'none'}")
    sch = res.numbers["boundaries_schoemer_undamped"]
    eig = res.data["eig_schoemer_undamped"].real.max(axis=1)
    spins = res.data["spins"]
    stable_above = len(sch) == 1 and bool(np.all(eig[spins > sch[0] * 1.01] <= 1e-9)) and bool(
        np.all(eig[spins < 0] > 0))
    res.claim("Schoemer's celt: every negative spin is unstable (it reverses), positive spins are stable above "
              "one critical spin", stable_above,
              f"boundaries in ({lo:g}, {hi:g}) rad/s: {', '.join(f'{b:.12g}' for b in sch) or 'none'}")
    return res


def draw(res: SceneResult, fig) -> None:
    d = res.data
    spins = d["spins"]
    axes = fig.subplots(2, 1, sharex=True)
    for ax, (key, name) in zip(axes, SETS):
        for damped, style in ((False, dict(color="C0", s=3)), (True, dict(color="C3", s=10, marker="x", lw=0.4))):
            ev = d[f"eig_{key}_{'damped' if damped else 'undamped'}"].real
            for j in range(ev.shape[1]):
                ax.scatter(spins, ev[:, j], label=("damped" if damped else "undamped") if j == 0 else None,
                           **style)
        lam, mu = d[f"mt_{key}"]
        small = np.linspace(-0.3, 0.3, 2) * max(abs(spins[0]), abs(spins[-1]))
        ax.plot(small, lam * small, "k--", lw=0.8, label=r"Moffatt-Tokieda $\lambda\Omega$, $-\mu\Omega$")
        ax.plot(small, -mu * small, "k--", lw=0.8)
        for damped, color, ls in ((False, "C0", "-"), (True, "C3", "--")):
            for b in d[f"boundaries_{key}_{'damped' if damped else 'undamped'}"]:
                if spins[0] <= b <= spins[-1]:
                    ax.axvline(b, color=color, lw=1.0, ls=ls)
                    ax.annotate(f"{b:.4f}", (b, 0), xytext=(3, 5 + 10 * damped), textcoords="offset points",
                                color=color, fontsize=8)
        ax.axhline(0, color="gray", lw=0.5)
        ax.set_ylabel("growth rates [1/s]")
        ax.set_title(f"{name} celt, upright steady spin", fontsize=10)
        ax.legend(fontsize=7, loc="best")
    axes[-1].set_xlabel(r"spin $\Omega$ [rad/s]")
    layout(fig, res.scene is SCENE, dict(left=0.1049, right=0.9800, bottom=0.0839, top=0.9516, hspace=0.1363))


SCENE = Scene(
    name="celt_stability",
    title="Linear stability of the celt's steady spins",
    caption=("Real parts of the physical eigenvalues of the upright steady spin against the spin, for the "
             "Kane-Levinson and Schoemer celts, undamped and damped, every stability boundary marked, and "
             "Moffatt & Tokieda's slow-spin slopes lambda Omega and -mu Omega."),
    why=("the full rigid celt: no integration, only its emitted Jacobian-vector product at the upright steady "
         "spins, the function the Lyapunov loop of scene celt_chaos compiles (knifeedge figures compiles it once "
         "for both; alone the small-tilt celt, whose linearization there is exact and equal to 1e-12 on the "
         "boundaries, compiles as long); the run is the Schoemer base point; Moffatt & Tokieda's slopes from "
         "their formula as plain Python (not compiled: two numbers per set)"),
    run=RUN,
    plots=("growth rates of the physical modes against the spin, undamped (dots) and damped (crosses), the "
           "stability boundaries (solid: undamped, dashed: damped) and the Moffatt-Tokieda slopes"),
    reports=("boundaries_kl_undamped", "boundaries_kl_damped", "boundaries_schoemer_undamped",
             "boundaries_schoemer_damped", "mt_lambda_kl", "mt_mu_kl", "slope_pitch_kl", "slope_roll_kl",
             "mt_lambda_schoemer", "mt_mu_schoemer", "slope_pitch_schoemer", "slope_roll_schoemer",
             "damping_shift_kl", "damping_shift_schoemer"),
    compute=compute,
    draw=draw,
    settings={"sigma": {"kl": 1e-4, "schoemer": 5e-3}, "spin_range": (-5.0, 5.0), "n_spins": 201, "boundary_interval": (-100.0, 100.0),
              "slope_spin": 1e-4, "slope_rtol": 1e-6},
    figsize=(7.5, 7.0),
    uses=(),  # it integrates nothing: no integrator is compiled for it
    lyapunov=(("celt", "full"),),  # its Jacobian-vector product: compiled with the Lyapunov loop, once
)
