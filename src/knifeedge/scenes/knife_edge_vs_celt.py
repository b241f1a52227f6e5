"""Scene ``knife_edge_vs_celt``: first reversal time against the initial spin, knife edge and classical celt.

The paper's Eq. ``tr``, ``t_R ~ (1/phi_dot0)(ell/D)``, and Garcia & Hubbard's
Eq. (46') for the celt (Proc. R. Soc. Lond. A 418 (1988) 165) give a reversal
time inversely proportional to the initial spin, up to a logarithm of the
ratio of the initial to the largest tilt.  The largest tilt grows in
proportion to the spin (``phi_dot0 L/sqrt(g ell)`` for the knife edge; the
first integral ``n^2 + P^2 + R^2`` of Moffatt & Tokieda for the celt), so with
initial tilts proportional to the spin that logarithm is the same for every
spin and the amplitude equations give ``t_R spin = const`` exactly.  The
scene measures the first reversal of the two-mode knife edge (paper's model,
``full``; initial tilts ``0.1 phi_dot0`` rad, i.e. a twentieth of the largest
tilt) and of the Kane & Levinson celt (``full``, undamped, spin in its
reversing direction, tilts ``5e-4 spin`` rad per rad/s: inside the small-tilt
regime, where the pitch tilt stays far below ``(c/a)^2 = 0.01`` rad) and fits
``t_R ~ spin^k``: the 1/spin law predicts ``k = -1``; the deviation allowed,
``settings["exponent_tolerance"] = 0.02``, covers the finite-amplitude
corrections (largest tilt up to 0.2 rad for the knife edge; spin up to 0.2
rad/s against rocking frequencies of 34 and 107 rad/s for the celt).
"""
from __future__ import annotations

import math

import numpy as np

from .base import RunSpec, Scene, SceneResult
from .celt import initial_state, preset
from .common import first_reversal, fit_power_law, label_log_ticks, layout, run_to_first_reversal

KNIFE = RunSpec(
    model="two_mode", fidelity="full",
    params={"g": 1.0, "ell": 1.0, "L": 2.0, "D": 0.5, "alpha": math.pi / 4},
    y0={"theta1": 1e-2, "theta2": 1e-2, "theta1_dot": 0.0, "theta2_dot": 0.0, "phi_dot": 0.1},
    t_span=(0.0, 4000.0), rtol=1e-10, atol=1e-12, n_eval=None,
)
RUN = RunSpec(model="celt", fidelity="full", params=preset("kane_levinson_1982"),
              y0=initial_state((5e-5, 5e-5, 1.0), (0.0, 0.0, 0.1)), t_span=(0.0, 300.0), rtol=1e-10, atol=1e-14,
              n_eval=None)


def knife_run(spin: float, st) -> RunSpec:
    """The knife edge at initial spin ``spin``, tilts proportional to it, for long enough to reverse."""
    tilt = st["knife_tilt_per_spin"] * spin
    return KNIFE.with_(phi_dot=spin, theta1=tilt, theta2=tilt, t_end=st["knife_t_spin"] / spin)


def celt_run(scene: Scene, spin: float) -> RunSpec:
    st = scene.settings
    tilt = st["celt_tilt_per_spin"] * spin
    return scene.run.with_(t_end=st["celt_t_spin"] / spin, **initial_state((tilt, tilt, 1.0), (0.0, 0.0, spin)))


def compute(scene: Scene, progress) -> SceneResult:
    st = scene.settings
    res = SceneResult(scene)
    out = {}
    tol = st["exponent_tolerance"]
    for label, spins, make in (
        ("knife_edge", st["knife_spins"], lambda w: knife_run(w, st)),
        ("celt", st["celt_spins"], lambda w: celt_run(scene, w)),
    ):
        times = []
        for w in spins:
            progress(f"{label}: initial spin {w:g}")
            spec = make(w)
            # the celt reverses at 0.28 of its span at every spin (t_R spin is constant): its run stops at half the
            # span (over the whole span if it has not reversed by then), the same first reversal to the bit
            stop = 0.5 * spec.t_span[1] if label == "celt" else spec.t_span[1]
            times.append(first_reversal(run_to_first_reversal(spec, stop, scene)))
        ok = [(w, t) for w, t in zip(spins, times) if math.isfinite(t)]
        k, se, _ = fit_power_law([w for w, _ in ok], [t for _, t in ok]) if len(ok) >= 3 else (math.nan,) * 3
        res.numbers[f"spins_{label}"] = list(spins)
        res.numbers[f"first_reversal_{label}"] = times
        res.numbers[f"exponent_{label}"] = k
        res.numbers[f"exponent_stderr_{label}"] = se
        res.claim(f"{label}: t_R ~ 1/spin (paper Eq. tr; Garcia & Hubbard 1988, Eq. 46')", abs(k + 1) < tol,
                  f"fitted exponent {k:.4f} +- {se:.4f} (1/spin: -1 within {tol:g})")
        out[label] = (list(spins), times)
    res.data.update(out)
    return res


def draw(res: SceneResult, fig) -> None:
    ax = fig.subplots()
    for i, label in enumerate(("knife_edge", "celt")):
        spins, times = res.data[label]
        s0 = np.asarray(spins, float)
        t = np.asarray(times, float)
        rel_s, rel_t = s0 / s0[0], t / t[0]
        ax.loglog(rel_s, rel_t, "o-", color=f"C{i}",
                  label=f"{label} (exponent {res.numbers[f'exponent_{label}']:.2f})")
    x = np.geomspace(1, max(max(np.asarray(res.data[k][0]) / res.data[k][0][0]) for k in ("knife_edge", "celt")), 20)
    ax.loglog(x, 1 / x, "k:", label="1/spin")
    ax.set_xlabel("initial spin / smallest initial spin")
    ax.set_ylabel("first reversal time / its value at the smallest spin")
    label_log_ticks(ax, [1, 2, 4])
    ax.legend(fontsize=8)
    ax.set_title("reversal time against the initial spin: knife edge (paper) and classical celt", fontsize=10)
    layout(fig, res.scene is SCENE, dict(left=0.1347, right=0.9800, bottom=0.1005, top=0.9384))


SCENE = Scene(
    name="knife_edge_vs_celt",
    title="reversal time against the initial spin, knife edge and celt",
    caption=("First spin reversal against the initial spin for the two-mode knife edge (paper's model, full; "
             "initial tilts 0.1 phi_dot0) and the Kane & Levinson celt (full, undamped, tilts 5e-4 rad per rad/s "
             "of spin), with the 1/spin law of the paper's Eq. tr and of Garcia & Hubbard: initial tilts in "
             "proportion to the spin keep the logarithmic factor of the law fixed."),
    why="full fidelity of both bodies, so that the comparison is not limited by a truncation",
    run=RUN,
    plots="first reversal time against the initial spin, both normalized by their smallest-spin value, log-log",
    reports=tuple(f"{q}_{b}" for b in ("knife_edge", "celt")
                  for q in ("spins", "first_reversal", "exponent", "exponent_stderr")),
    compute=compute,
    draw=draw,
    settings={"knife_spins": (0.025, 0.05, 0.1), "knife_tilt_per_spin": 0.1, "knife_t_spin": 400.0,
              "celt_spins": (0.05, 0.1, 0.2), "celt_tilt_per_spin": 5e-4, "celt_t_spin": 30.0,
              "exponent_tolerance": 0.02},
    uses=(("celt", "full", False), ("two_mode", "full", False)),
)
