"""Scene ``predictability``: how long the two-mode knife edge of Fig. 'Numerical2' can be followed in double precision.

The largest Lyapunov exponent ``lambda_max`` (:func:`knifeedge.lyapunov`, Benettin/QR on the emitted variational
equations) of the run of scene ``numerical2``, the horizon ``T = ln(tolerance / round-off) / lambda_max`` it
implies, and, against it, the measured spread of the reversal times of runs whose initial state differs by one
ulp in one component.  The exponent's prediction for reversal ``k`` is the stretching ``exp(Lambda(t_k))`` of a
generic perturbation up to ``t_k`` (``Lambda(t) = t * lambda(t)``, the running estimate), and, since round-off
enters at every step, the worst stretching over any window ending at ``t_k``; the measurement is the shift of the
reversal as a fraction of the interval ``t_R`` per relative perturbation (one ulp).
"""
from __future__ import annotations

import math

import numpy as np

from ..lyapunov import lyapunov
from .base import Scene, SceneResult
from .common import T_LABEL, layout, mark_reversals, require_success
from .numerical2 import RUN as NUMERICAL2_RUN

RUN = NUMERICAL2_RUN.with_(n_eval=None)
#: round-off: half an ulp of 1 (the relative error of one rounding)
ROUNDOFF = np.finfo(float).eps / 2


def _spread(scene: Scene, base, progress) -> tuple:
    """Largest shift of each reversal over the runs perturbed by one ulp, and the perturbed components."""
    shifts, perturbed = [], []
    for name, value in scene.run.y0.items():
        if value == 0.0:
            continue  # one ulp of zero is a denormal: no perturbation
        progress(f"integrating from {name} + 1 ulp")
        r = require_success(scene.run.with_(**{name: float(np.nextafter(value, np.inf))}).simulate(), scene)
        n = len(base.reversal_times)
        if len(r.reversal_times) < n:
            raise RuntimeError(f"scene {scene.name}: the run from {name} + 1 ulp reverses {len(r.reversal_times)} "
                               f"times, the unperturbed one {n}")
        shifts.append(np.abs(r.reversal_times[:n] - base.reversal_times))
        perturbed.append(name)
    return np.max(shifts, axis=0), perturbed


def _stretching(ly, t0: float, times) -> tuple:
    """``Lambda(t) = (t - t0) lambda(t)`` along the run and, at each of ``times``, ``exp(Lambda)`` from the start and
    over the worst window ending there."""
    stretch = (ly.history_t - t0) * ly.history[:, 0]
    start, worst = [], []
    for tk in times:
        j = max(1, int(np.searchsorted(ly.history_t, tk)))
        start.append(math.exp(stretch[j - 1]))
        worst.append(math.exp(stretch[j - 1] - min(0.0, float(stretch[:j].min()))))
    return stretch, start, worst


def _at(ly, t: float) -> float:
    """The running estimate of the largest exponent at time ``t``."""
    return float(ly.history[max(0, int(np.searchsorted(ly.history_t, t)) - 1), 0])


def compute(scene: Scene, progress) -> SceneResult:
    s, run = scene.settings, scene.run
    m = run.load()
    p, y0 = m.params(**dict(run.params)), m.state(**dict(run.y0))
    t0, t1 = run.t_span
    progress("largest Lyapunov exponent (Benettin/QR)")
    ly = lyapunov(m, y0, p, t0 + s["lyapunov_span"], k=1, h=s["h"], tau=s["tau"], t0=t0)
    lam_run, lam = _at(ly, t1), float(ly.exponents[0])
    scaling = [lam_run * (t1 - t0) / math.log(t1 - t0), lam * s["lyapunov_span"] / math.log(s["lyapunov_span"])]
    progress("integrating the unperturbed run")
    base = require_success(run.simulate(), scene)
    rev = base.reversal_times
    spread, perturbed = _spread(scene, base, progress)
    probe_name, probe = s["probe"]
    progress(f"integrating from {probe_name} (1 + {probe:g})")
    r = require_success(run.with_(**{probe_name: run.y0[probe_name] * (1 + probe)}).simulate(), scene)
    probe_shift = np.abs(r.reversal_times[:len(rev)] - rev)
    t_r = float(np.mean(np.diff(rev))) if len(rev) > 1 else float(rev[0])
    ulp = max(float(np.spacing(abs(v)) / abs(v)) for v in run.y0.values() if v != 0.0)
    measured = spread / t_r / ulp
    stretch, g_start, g_worst = _stretching(ly, t0, rev)
    tol = s["tolerance"]
    horizon = math.log(tol / ROUNDOFF) / lam if lam > 0 else math.inf
    res = SceneResult(scene)
    res.numbers.update({
        "lambda_max": lam, "lambda_max_uncertainty": float(ly.uncertainty[0]), "lambda_max_at_run_end": lam_run,
        "lambda_t_over_log_t": scaling, "horizon": horizon, "tolerance": tol, "roundoff": ROUNDOFF,
        "reversal_times": [float(t) for t in rev], "perturbed_components": ", ".join(perturbed),
        "reversal_spread": [float(x) for x in spread], "probe_shift": [float(x) for x in probe_shift],
        "amplification_measured": [float(x) for x in measured],
        "amplification_exponent": g_start, "amplification_exponent_worst_window": g_worst,
        "fixed_by_horizon": [int(k + 1) for k, t in enumerate(rev) if t < horizon],
        "fixed_measured": [int(k + 1) for k, x in enumerate(spread) if x <= tol * t_r],
    })
    _claims(res, scene, ly, probe_shift, spread)
    res.data.update(history_t=ly.history_t, history=ly.history[:, 0], stretch=stretch, rev=rev, t1=t1,
                    measured=measured, g_worst=np.array(g_worst), g_start=np.array(g_start))
    return res


def _claims(res: SceneResult, scene: Scene, ly, probe_shift, spread) -> None:
    n, s = res.numbers, scene.settings
    a, b = n["lambda_t_over_log_t"]
    res.claim("the largest exponent is zero: its estimate falls like ln T / T, as on an integrable body",
              n["lambda_max"] < n["lambda_max_at_run_end"] / 3 and 0.5 < a / b < 2,
              f"lambda_max = {n['lambda_max_at_run_end']:.3g} at T = {scene.run.t_span[1]:g}, {n['lambda_max']:.3g} "
              f"at T = {s['lyapunov_span']:g}; lambda T / ln T = {a:.3g}, {b:.3g}")
    worst = max(x / g for x, g in zip(n["amplification_measured"], n["amplification_exponent_worst_window"]))
    res.claim("the largest Lyapunov exponent explains the spread of the reversal times (within a factor 10)",
              worst <= 10.0,
              f"one-ulp runs shift the reversals by {', '.join(f'{x:.2g}' for x in spread)} (amplification "
              f"{', '.join(f'{x:.2g}' for x in n['amplification_measured'])}); the exponent's stretching, worst "
              f"window: {', '.join(f'{g:.2g}' for g in n['amplification_exponent_worst_window'])}; horizon "
              f"T = ln({n['tolerance']:g}/{ROUNDOFF:.2g})/lambda_max = {n['horizon']:.3g}")
    name, probe = s["probe"]
    later = slice(1, None)
    floor = bool(np.all(probe_shift[later] < 10 * spread[later]))
    res.claim("the spread of the later reversals is the integration's error floor, not the flow's sensitivity",
              floor if len(spread) > 1 else None,
              f"a perturbation {probe:g} of {name} ({probe / np.finfo(float).eps:.2g} ulp) shifts the reversals by "
              f"{', '.join(f'{x:.2g}' for x in probe_shift)}, one ulp by {', '.join(f'{x:.2g}' for x in spread)}")


def draw(res: SceneResult, fig) -> None:
    d, n = res.data, res.numbers
    a1, a2 = fig.subplots(2, 1)
    t, lam = d["history_t"], d["history"]
    a1.semilogx(t, lam, color="C0", lw=0.8, label=r"running $\lambda_{max}(T)$")
    c = n["lambda_t_over_log_t"][-1]
    late = t >= d["t1"] / 3
    a1.semilogx(t[late], c * np.log(t[late]) / t[late], "k--", lw=0.7, label=f"{c:.2g} ln T / T")
    a1.axhline(0, color="gray", lw=0.5)
    a1.axvline(d["t1"], color="gray", lw=0.5, ls=":")
    a1.set_ylim(-4 * abs(n["lambda_max_at_run_end"]), 4 * abs(n["lambda_max_at_run_end"]))
    a1.set_ylabel(r"$\lambda_{max}$ [1/time]")
    a1.set_xlabel("T")
    a1.legend(fontsize=8, loc="upper right")
    a1.set_title(f"two-mode knife edge (scene numerical2): $\\lambda_{{max}}$ = {n['lambda_max']:.2g} at "
                 f"T = {t[-1]:.3g}", fontsize=10)
    w = t <= d["t1"]
    a2.semilogy(t[w], np.exp(d["stretch"][w]), color="C0", lw=0.8, label=r"stretching $\exp(t\,\lambda(t))$")
    a2.semilogy(d["rev"], d["g_worst"], "s", color="C0", mfc="none", label="exponent, worst window")
    a2.semilogy(d["rev"], np.maximum(d["measured"], 1e-300), "o", color="C3",
                label="measured: reversal shift / $t_R$ / ulp")
    mark_reversals(a2, d["rev"], label=False)
    a2.set_ylabel("amplification of one ulp")
    a2.set_xlabel(T_LABEL)
    a2.legend(fontsize=8, loc="center right")
    layout(fig, res.scene is SCENE, dict(left=0.1418, right=0.9800, bottom=0.1069, top=0.9429, hspace=0.2776))


SCENE = Scene(
    name="predictability",
    title="How far the two-mode reversals can be predicted",
    caption=("Largest Lyapunov exponent of the two-mode knife edge of Fig. Numerical2, the horizon "
             "T = ln(tolerance / round-off) / lambda_max it implies, and the measured spread of the reversal "
             "times of runs started one ulp apart."),
    why=("the reduced two-mode model and the run of scene numerical2 (the figure whose later reversals are "
         "ill-conditioned); the exponent from the emitted Jacobian, the spread from the same integrator as the "
         "figure"),
    run=RUN,
    plots="running estimate of lambda_max; stretching exp(t lambda(t)) against the measured amplification",
    reports=("lambda_max", "lambda_max_uncertainty", "lambda_max_at_run_end", "lambda_t_over_log_t", "horizon", "reversal_times", "reversal_spread",
             "amplification_measured", "amplification_exponent", "amplification_exponent_worst_window",
             "probe_shift", "fixed_by_horizon", "fixed_measured"),
    compute=compute,
    draw=draw,
    settings={"h": 0.1, "tau": 1.0, "lyapunov_span": 9e4, "tolerance": 1e-6, "probe": ("theta1", 1e-8)},
    figsize=(7.5, 6.0),
    lyapunov=(("two_mode", "reduced"),),
)
