"""Scene ``knife_edge_vs_celt``: first reversal time against the initial spin, knife edge and classical celt.

The paper's Eq. ``tr`` (and Garcia & Hubbard, Proc. R. Soc. Lond. A 418
(1988) 165, for the celt) give a reversal time inversely proportional to the
initial spin.  The scene measures the first reversal of the two-mode knife
edge (paper's model, ``full``) and of the Kane & Levinson celt (``full``,
undamped, spin in its reversing direction) for several initial spins, and fits
``t_R ~ spin^k`` to each.
"""
from __future__ import annotations

import math

import numpy as np

from .base import RunSpec, Scene, SceneResult
from .celt import N0, initial_state, preset
from .common import fit_power_law, label_log_ticks, require_success

KNIFE = RunSpec(
    model="two_mode", fidelity="full",
    params={"g": 1.0, "ell": 1.0, "L": 2.0, "D": 0.5, "alpha": math.pi / 4},
    y0={"theta1": 1e-2, "theta2": 1e-2, "theta1_dot": 0.0, "theta2_dot": 0.0, "phi_dot": 0.1},
    t_span=(0.0, 20000.0), rtol=1e-10, atol=1e-12, n_eval=None,
)
RUN = RunSpec(model="celt", fidelity="full", params=preset("kane_levinson_1982"),
              y0=initial_state(N0, (0.0, 0.0, 5.0)), t_span=(0.0, 30.0), rtol=1e-10, atol=1e-12, n_eval=None)


def compute(scene: Scene, progress) -> SceneResult:
    st = scene.settings
    res = SceneResult(scene)
    out = {}
    for label, spins, make in (
        ("knife_edge", st["knife_spins"], lambda w: KNIFE.with_(phi_dot=w)),
        ("celt", st["celt_spins"], lambda w: scene.run.with_(**initial_state(N0, (0.0, 0.0, w)))),
    ):
        times = []
        for w in spins:
            progress(f"{label}: initial spin {w:g}")
            r = require_success(make(w).simulate(), scene)
            times.append(float(r.reversal_times[0]) if len(r.reversal_times) else math.nan)
        ok = [(w, t) for w, t in zip(spins, times) if math.isfinite(t)]
        k, se, _ = fit_power_law([w for w, _ in ok], [t for _, t in ok]) if len(ok) >= 3 else (math.nan,) * 3
        res.numbers[f"spins_{label}"] = list(spins)
        res.numbers[f"first_reversal_{label}"] = times
        res.numbers[f"exponent_{label}"] = k
        res.numbers[f"exponent_stderr_{label}"] = se
        res.claim(f"{label}: t_R ~ 1/spin (paper Eq. tr; Garcia & Hubbard 1988)", abs(k + 1) < 0.1,
                  f"fitted exponent {k:.3f} +- {se:.3f}")
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
    fig.tight_layout()


SCENE = Scene(
    name="knife_edge_vs_celt",
    title="reversal time against the initial spin, knife edge and celt",
    caption=("First spin reversal against the initial spin for the two-mode knife edge (paper's model, full; "
             "tilts 0.01 rad) and the Kane & Levinson celt (full, undamped, tilts 0.5 deg), with the 1/spin law "
             "of the paper's Eq. tr and of Garcia & Hubbard."),
    why="full fidelity of both bodies, so that the comparison is not limited by a truncation",
    run=RUN,
    plots="first reversal time against the initial spin, both normalized by their smallest-spin value, log-log",
    reports=tuple(f"{q}_{b}" for b in ("knife_edge", "celt")
                  for q in ("spins", "first_reversal", "exponent", "exponent_stderr")),
    compute=compute,
    draw=draw,
    settings={"knife_spins": (0.025, 0.05, 0.1, 0.2), "celt_spins": (1.0, 1.5, 2.5, 5.0)},
    uses=(("celt", "full", False), ("two_mode", "full", False)),
)
