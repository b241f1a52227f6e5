"""Scene ``tinversion``: reversal time against phi_dot0 and against D/ell (paper Fig. 'tinversion').

Two sweeps of the reduced two-mode model (``ell/L = 1/2``, ``alpha = pi/4``,
tilts 1e-3): over ``phi_dot0`` at ``D/ell = 1/2`` and over ``D/ell`` at
``phi_dot0 = 0.1 sqrt(g/ell)``.  The time measured is the *first reversal
time* -- well conditioned, unlike the interval between later reversals (see
scene ``numerical2``).  Each scan gets a least-squares power-law fit
``t_R ~ x^b`` with the standard error of ``b``, next to the paper's
``b = -1`` (Eq. tr).  Eq. tr omits a logarithm, ``ln(theta_max/theta_0)``,
which grows with ``phi_dot0`` (``theta_max ~ phi_dot0 L/sqrt(g ell)``) and so
makes the fitted exponent in ``phi_dot0`` less steep than -1.  The
prediction of the amplitude equations (``knifeedge.reversal_time``, a
quadrature, no integration) is drawn too.

The largest ``phi_dot0`` of the scan takes the tilts beyond the small-tilt
domain of the reduced model and of the amplitude equations (``VALIDITY``,
0.6 rad): the scene keeps those points (the paper's range) and shows the
boundary on its figure, a shaded band, instead of warning at each run.
"""
from __future__ import annotations

import math
import warnings

import numpy as np

from ..models import ValidityWarning
from .base import Scene, SceneResult
from .common import fit_power_law, label_log_ticks, layout
from .numerical2 import RUN as TWO_MODE_RUN

RUN = TWO_MODE_RUN.with_(rtol=1e-10, atol=1e-14, n_eval=None, t_end=3600.0)


def _t_end(run, phi_dot: float, D: float) -> float:
    """A span that safely contains the first reversal: the base run's, scaled like Eq. tr, with margin."""
    base_phi, base_D = 0.1, 0.5
    log_ratio = math.log(phi_dot * run.params["L"] / 1e-3) / math.log(base_phi * run.params["L"] / 1e-3)
    return 2396.7 * (base_phi / phi_dot) * (base_D / D) * max(1.0, log_ratio) * 1.5


def _theory(run, points) -> tuple:
    """First reversal predicted by the amplitude equations (``knifeedge.reversal_time``) at each point, and
    whether the prediction stays in their domain."""
    from ..reversal import reversal_time

    out, inside = [], []
    for pt in points:
        spec = run.with_(**{k: v for k, v in pt.items() if k != "t_end"})
        with warnings.catch_warnings():  # said on the figure (see the module docstring)
            warnings.simplefilter("ignore", ValidityWarning)
            prediction = reversal_time(spec.load(), dict(spec.params), dict(spec.y0))
        out.append(prediction.first)
        inside.append(prediction.in_validity_domain)
    return out, inside


def _first_reversals(run, points) -> tuple:
    """First reversal time of each run (NaN if none), why it is missing, and whether the run stayed in the
    reduced model's domain."""
    t_r, why, inside = [], [], []
    for pt in points:
        with warnings.catch_warnings():  # said on the figure (see the module docstring)
            warnings.simplefilter("ignore", ValidityWarning)
            r = run.with_(**pt, n_eval=None).simulate()
        rev = r.reversal_times
        t_r.append(float(rev[0]) if r.success and len(rev) else math.nan)
        why.append("" if r.success and len(rev) else (r.message if not r.success else "no reversal in the span"))
        inside.append(r.in_validity_domain)
    return np.array(t_r), why, inside


def compute(scene: Scene, progress) -> SceneResult:
    run = scene.run
    res = SceneResult(scene)
    scans = {}
    for key, values, fixed in (("phi_dot", scene.settings["phi_dot0"], {"D": 0.5}),
                               ("D", scene.settings["D_over_ell"], {"phi_dot": 0.1})):
        points = []
        for v in values:
            pt = {**fixed, key: v}
            pt["t_end"] = _t_end(run, pt["phi_dot"], pt["D"])
            points.append(pt)
        progress(f"sweep over {key}: {len(points)} runs")
        t_r, why, inside = _first_reversals(run, points)
        if not np.all(np.isfinite(t_r)):
            bad = [w for w in why if w]
            raise RuntimeError(f"scene {scene.name}: {len(bad)} run(s) without a first reversal: {bad[0]}")
        b, se, a = fit_power_law(values, t_r)
        theory, inside_theory = _theory(run, points)
        outside = ~(np.array(inside) & np.array(inside_theory))
        scans[key] = {"x": np.array(values, float), "t_r": t_r, "b": b, "se": se, "a": a, "theory": np.array(theory),
                      "outside": outside, "bound": max(run.load().validity.values())}
        label = "phi_dot0" if key == "phi_dot" else "D_over_ell"
        res.numbers[f"outside_validity_domain_vs_{label}"] = [float(x) for x, o in zip(values, outside) if o]
        res.numbers[f"exponent_vs_{label}"] = b
        res.numbers[f"exponent_vs_{label}_stderr"] = se
        res.numbers[f"first_reversal_times_vs_{label}"] = [float(x) for x in t_r]
        if np.all(np.isfinite(theory)):
            bt, set_, _ = fit_power_law(values, theory)
            res.numbers[f"exponent_vs_{label}_amplitude_theory"] = bt
            res.numbers[f"max_relative_difference_vs_{label}_amplitude_theory"] = float(
                np.max(np.abs(np.array(theory) - t_r) / t_r))
        close = abs(b + 1) < scene.settings["exponent_tolerance"]
        name = "phi_dot0" if key == "phi_dot" else "(D/ell)"
        evidence = f"fitted exponent {b:.3f} +/- {se:.3f} (first reversal, {len(values)} runs, {min(values):g}..{max(values):g})"
        if np.all(np.isfinite(theory)):
            evidence += f"; the amplitude equations give {res.numbers[f'exponent_vs_{label}_amplitude_theory']:.3f}"
        if outside.any():
            evidence += (f"; {name} >= {min(np.array(values)[outside]):g} takes the tilts beyond the small-tilt domain "
                         f"({scans[key]['bound']:g} rad) of the reduced model or the amplitude equations (shaded)")
        if not close:
            evidence += (" -- Eq. tr drops the factor ln(theta_max/theta_0), and theta_max grows with phi_dot0, "
                         "so the exponent is less steep than -1")
        res.claim(f"t_R ~ 1/{name}: exponent -1 (Eq. tr)", close, evidence)
        if np.all(np.isfinite(theory)):
            d = res.numbers[f"max_relative_difference_vs_{label}_amplitude_theory"]
            res.claim(f"t_R vs {name} follows the amplitude theory", d < 0.02,
                      f"first reversal predicted by the amplitude equations within {d:.2%} of the reduced model's")
    res.data["scans"] = scans
    return res


def draw(res: SceneResult, fig) -> None:
    axes = fig.subplots(1, 2)
    labels = {"phi_dot": (r"$\dot\phi_0\ [\sqrt{g/\ell}]$", "(a)  $D/\\ell=1/2$"),
              "D": (r"$D/\ell$", r"(b)  $\dot\phi_0=0.1\sqrt{g/\ell}$")}
    for ax, (key, s) in zip(axes, res.data["scans"].items()):
        x = s["x"]
        ax.loglog(x, s["t_r"], "o", color="C0", label="first reversal, reduced model")
        xx = np.geomspace(x.min(), x.max(), 50)
        ax.loglog(xx, np.exp(s["a"]) * xx ** s["b"], "-", color="C0", lw=1,
                  label=f"fit: exponent {s['b']:.3f} $\\pm$ {s['se']:.3f}")
        c = np.exp(np.mean(np.log(s["t_r"]) + np.log(x)))
        ax.loglog(xx, c / xx, "--", color="k", lw=1, label="exponent $-1$ (Eq. tr)")
        if np.all(np.isfinite(s["theory"])):
            ax.loglog(x, s["theory"], "x", color="C3", ms=8, label="amplitude equations (reversal_time)")
        if s["outside"].any():
            _shade_outside(ax, x, s["outside"], s["bound"])
        label_log_ticks(ax, x)
        ax.set_xlabel(labels[key][0])
        ax.set_title(labels[key][1], fontsize=10)
        ax.legend(fontsize=7)
    axes[0].set_ylabel(r"$t_R\ [\sqrt{\ell/g}]$")
    fig.suptitle(r"reversal time vs $\dot\phi_0$ and $D/\ell$; $\ell/L=1/2$, $\alpha=\pi/4$, tilts $10^{-3}$", fontsize=10)
    layout(fig, res.scene is SCENE, dict(left=0.0990, right=0.9850, bottom=0.1364, top=0.8360, wspace=0.1807))


def _shade_outside(ax, x, outside, bound: float) -> None:
    """A band over the points of the scan beyond the small-tilt domain (from halfway, on the log axis, between
    the last point inside and the first outside to past the end of the scan)."""
    first_out = x[outside].min()
    inside = x[~outside & (x < first_out)]
    start = math.sqrt(inside.max() * first_out) if inside.size else x.min() / 1.15
    ax.axvspan(start, x[outside].max() * 1.15, color="0.88", zorder=0,
               label=f"tilts beyond {bound:g} rad: outside the small-tilt domain")


SCENE = Scene(
    name="tinversion",
    title="reversal time against phi_dot0 and D/ell",
    caption=("Numerical results for the inversion time t_R (see Fig. Numerical2) as a function of phi_dot0 for D/l = 1/2 "
             "(a), and as a function of D/l for phi_dot0 = 0.1 sqrt(g/l) (b). In both cases l/L = 1/2. The straight "
             "lines depict a power law with exponent -1, that is in both cases the expected result for Eq. tr."),
    why=("reduced two-mode model (5 states, no pose), first reversal only: it is well conditioned at rtol 1e-10 and "
         "needs no span beyond it; the amplitude equations give the theory's prediction by quadrature"),
    run=RUN,
    plots="log-log first reversal time vs phi_dot0 and vs D/ell, fitted power law, the exponent -1, amplitude model",
    reports=("exponent_vs_phi_dot0", "exponent_vs_phi_dot0_stderr", "exponent_vs_D_over_ell",
             "exponent_vs_D_over_ell_stderr", "first_reversal_times_vs_phi_dot0", "first_reversal_times_vs_D_over_ell"),
    compute=compute,
    draw=draw,
    settings={"phi_dot0": (0.05, 0.075, 0.1, 0.15, 0.2, 0.3, 0.4), "D_over_ell": (0.25, 0.35, 0.5, 0.7, 1.0, 1.4, 2.0),
              "exponent_tolerance": 0.05},
    figsize=(10.0, 4.5),
)
