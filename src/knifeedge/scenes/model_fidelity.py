"""Scene ``model_fidelity``: cost and error of the amplitude, reduced and full models side by side.

Part (a): the single-mode scene (``ell/L = 1``, ``D/ell = 1``, tilt 1e-3)
over ``phi_dot0/omega`` -- which at ``ell/L = 1`` is also the largest tilt
(radians) reached at the reversal.  Each model's first reversal time is
compared with the full model's at a tight tolerance; the cost is the wall
time of one integration (after compilation) and the number of right-hand
side evaluations.  Part (b): the two-mode scene of Fig. Numerical2, first
reversal and the interval to the second.

Part (a) runs the cheaper fidelities beyond their small-tilt domain on
purpose (that is where they stop being good enough): the scene holds back
their ValidityWarnings, reports the points outside, and shades the band
beyond the domain's bound (generated ``VALIDITY``) on its figure.
"""
from __future__ import annotations

import math
import time
import warnings

import numpy as np

from ..models import ValidityWarning
from .base import RunSpec, Scene, SceneResult
from .common import first_reversal, label_log_ticks, layout, require_success
from .numerical import RUN as SINGLE_RUN
from .numerical2 import RUN as TWO_RUN

RUN = SINGLE_RUN.with_(fidelity="full", rtol=1e-12, atol=1e-14, n_eval=None)


def _amplitude_run(run: RunSpec) -> RunSpec | None:
    """The amplitude-model version of a single- or two-mode run (None if not generated)."""
    from ..generated import MODULES

    if (run.model, "amplitude") not in MODULES:
        return None
    y = run.y0
    if run.model == "single_mode":
        y0 = {"A_theta": math.hypot(y["theta"], y["theta_dot"]), "A_phi": y["phi_dot"]}
    else:
        y0 = {"A1": math.hypot(y["theta1"], y["theta1_dot"]), "A2": y["theta2"], "A_phi": y["phi_dot"]}
    return RunSpec(model=run.model, fidelity="amplitude", params=dict(run.params), y0=y0, t_span=run.t_span,
                   method=run.method, rtol=1e-10, atol=1e-14, n_eval=None)


def _timed(run: RunSpec, repeats: int = 3):
    """(result, median wall seconds of ``repeats`` integrations after one warm-up); a run outside its fidelity's
    domain says so in ``result.in_validity_domain`` (shown on the figure), not by a warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        r = run.simulate()
        times = []
        for _ in range(repeats):
            t0 = time.perf_counter()
            run.simulate()
            times.append(time.perf_counter() - t0)
    return r, float(np.median(times))


def compute(scene: Scene, progress) -> SceneResult:
    res = SceneResult(scene)
    ref_run = scene.run
    good = scene.settings["good_enough"]
    rows = []
    for ratio in scene.settings["phi_dot0_over_omega"]:
        w = math.sqrt(ref_run.params["g"] / ref_run.params["ell"])
        t_end = 2.5 * 2 * ref_run.params["ell"] / (ratio * w * ref_run.params["D"]) * math.log(
            2 * ratio * w * ref_run.params["L"] / (math.sqrt(ref_run.params["g"] * ref_run.params["ell"]) * 1e-3))
        base = ref_run.with_(phi_dot=ratio * w, t_end=t_end)
        progress(f"single mode, phi_dot0/omega = {ratio:g}: full, reduced, amplitude")
        ref = require_success(base.simulate(), scene)  # the reference: full model, rtol 1e-12
        if not ref.reversal_times.size:
            raise RuntimeError(f"scene {scene.name}: the reference run (phi_dot0/omega = {ratio:g}) has no spin "
                               f"reversal before t = {t_end:g}")
        t_ref = float(ref.reversal_times[0])
        row = {"ratio": ratio}
        for fid, run in (("full", base.with_(rtol=1e-10, atol=1e-12)),
                         ("reduced", base.with_(fidelity="reduced", rtol=1e-10, atol=1e-12)),
                         ("amplitude", _amplitude_run(base))):
            if run is None:
                continue
            r, t = _timed(run)
            tr = first_reversal(r)
            row[fid] = (tr, abs(tr - t_ref) / t_ref, t, r.nfev)
            if not r.in_validity_domain:
                row.setdefault("outside", []).append(fid)
        rows.append(row)
    fids = [f for f in ("full", "reduced", "amplitude") if f in rows[0]]
    for fid in fids[1:]:
        ok = [row["ratio"] for row in rows if row[fid][1] <= good]
        bad = [row["ratio"] for row in rows if not row[fid][1] <= good]
        res.numbers[f"single_mode_{fid}_errors"] = [row[fid][1] for row in rows]
        res.numbers[f"single_mode_{fid}_good_enough_up_to"] = max(ok) if ok else math.nan
        res.numbers[f"single_mode_{fid}_outside_validity_domain"] = [row["ratio"] for row in rows
                                                                     if fid in row.get("outside", ())]
        res.claim(f"{fid} model: first reversal within {good:.0%} of the full model",
                  None, f"up to phi_dot0/omega = {max(ok) if ok else 'none'}"
                  + (f"; not from {min(bad):g} on" if bad else " (all values tried)"))
    for fid in fids:
        res.numbers[f"single_mode_{fid}_median_seconds_rtol_1e-10"] = float(np.median([row[fid][2] for row in rows]))
        res.numbers[f"single_mode_{fid}_median_nfev_rtol_1e-10"] = float(np.median([row[fid][3] for row in rows]))
    res.numbers["phi_dot0_over_omega"] = list(scene.settings["phi_dot0_over_omega"])

    # (b) the two-mode scene
    two = []
    two_runs = [("full", TWO_RUN.with_(fidelity="full", n_eval=None, t_end=5600.0)),
                ("reduced", TWO_RUN.with_(n_eval=None, t_end=5600.0)),
                ("amplitude", _amplitude_run(TWO_RUN.with_(t_end=5600.0)))]
    for fid, run in two_runs:
        if run is None:
            continue
        progress(f"two mode, {fid}")
        r, t = _timed(run, repeats=1)
        rev = r.reversal_times
        two.append((fid, [float(x) for x in rev], t, r.nfev))
        res.numbers[f"two_mode_{fid}_reversal_times"] = [float(x) for x in rev]
        res.numbers[f"two_mode_{fid}_seconds"] = t
        res.numbers[f"two_mode_{fid}_nfev"] = r.nfev
    ref_first = two[0][1][0]
    for fid, rev, t, nfev in two[1:]:
        res.claim(f"two mode, {fid} model: first reversal agrees with the full model", abs(rev[0] - ref_first) < 0.01 * ref_first,
                  f"{rev[0]:.2f} vs {ref_first:.2f} (full), {two[0][3] / nfev:.1f}x fewer rhs evaluations, "
                  f"{two[0][2] / t:.1f}x less wall time")
    bound = min(ref_run.with_(fidelity="reduced").load().validity.values())  # the largest tilt the domain allows
    res.data.update(rows=rows, fids=fids, two=two, good=good, bound=bound)
    return res


def draw(res: SceneResult, fig) -> None:
    rows, fids = res.data["rows"], res.data["fids"]
    a0, a1, a2 = fig.subplots(1, 3, gridspec_kw={"width_ratios": [1.2, 1.2, 1]})
    x = [row["ratio"] for row in rows]
    colors = {"full": "k", "reduced": "C0", "amplitude": "C3"}
    for fid in fids:
        err = [max(row[fid][1], 1e-12) for row in rows]
        a0.loglog(x, err, "o-", color=colors[fid], label=fid)
    a0.axhline(res.data["good"], color="gray", ls="--", lw=0.8, label=f"{res.data['good']:.0%}")
    if max(x) > res.data["bound"]:  # where the reduced and amplitude fidelities leave their domain (VALIDITY)
        a0.axvspan(res.data["bound"], max(x) * 1.15, color="0.88", zorder=0,
                   label=f"tilts beyond {res.data['bound']:g} rad: outside the small-tilt domain")
    label_log_ticks(a0, x)
    a0.set_xlabel(r"$\dot\phi_0/\omega$  (= max tilt [rad] at $\ell/L=1$)")
    a0.set_ylabel("relative error of the first reversal time\n(all at rtol 1e-10; reference: full, rtol 1e-12)")
    a0.set_title("(a) single mode: error", fontsize=9)
    a0.legend(fontsize=8)
    for fid in fids:
        a1.loglog(x, [row[fid][3] for row in rows], "o-", color=colors[fid], label=fid)
    label_log_ticks(a1, x)
    a1.set_xlabel(r"$\dot\phi_0/\omega$")
    a1.set_ylabel("right-hand-side evaluations per integration")
    a1.set_title("(a) single mode: cost at rtol 1e-10 (wall times in the numbers)", fontsize=9)
    a1.legend(fontsize=8)
    two = res.data["two"]
    names = [f for f, *_ in two]
    a2.bar(range(len(two)), [nfev for *_, nfev in two], color=[colors[f] for f in names])
    a2.set_xticks(range(len(two)), names)
    a2.set_yscale("log")
    a2.set_ylabel("right-hand-side evaluations")
    for i, (f, rev, t, nfev) in enumerate(two):
        txt = "\n".join(f"$t_{k + 1}$={v:.1f}" for k, v in enumerate(rev[:2])) + f"\n{t * 1e3:.3g} ms"
        a2.text(i, nfev * 1.15, txt, ha="center", va="bottom", fontsize=7)
    a2.set_ylim(top=max(nfev for *_, nfev in two) * 30)
    a2.set_title("(b) two mode (Fig. Numerical2): cost;\nfirst reversal $t_1$ (well conditioned),\nsecond $t_2$ (ill-conditioned except amplitude)", fontsize=9)
    fig.suptitle("model fidelity: which model each scene may use", fontsize=10)
    layout(fig, res.scene is SCENE, dict(left=0.0790, right=0.9885, bottom=0.1315, top=0.7946, wspace=0.1973))


SCENE = Scene(
    name="model_fidelity",
    title="cost and error of amplitude, reduced and full models",
    caption=("For the scenes above, cost and error of the amplitude, reduced and full models side by side: which model "
             "each scene may use, and where the cheaper one stops being good enough as phi_dot0/omega or the tilt "
             "amplitude grow (not a figure of the paper)."),
    why=("all three fidelities by construction; the full model at rtol 1e-12 is the reference, no pose anywhere "
         "(position does not enter the reversal times)"),
    run=RUN,
    plots="relative error of the first reversal vs phi_dot0/omega, wall time per integration, two-mode comparison",
    reports=("single_mode_reduced_errors", "single_mode_amplitude_errors", "single_mode_reduced_good_enough_up_to",
             "single_mode_amplitude_good_enough_up_to", "two_mode_full_reversal_times", "two_mode_reduced_reversal_times",
             "two_mode_amplitude_reversal_times"),
    compute=compute,
    draw=draw,
    settings={"phi_dot0_over_omega": (0.025, 0.05, 0.1, 0.2, 0.4, 0.8), "good_enough": 0.01},
    uses=(("single_mode", "full", False), ("single_mode", "reduced", False), ("single_mode", "amplitude", False),
          ("two_mode", "full", False), ("two_mode", "reduced", False), ("two_mode", "amplitude", False)),
    figsize=(13.0, 4.6),
)
