"""Charts (PNG) and tables (CSV, JSON) of a benchmark run."""
from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

STYLE = {
    "knifeedge DOP853": ("C0", "o", "-"), "knifeedge DP54": ("C1", "s", "-"), "knifeedge Tsit5": ("C6", "<", "-"),
    "knifeedge RK4": ("C2", "^", "-"),
    "knifeedge gauss4": ("C3", "v", "-"), "knifeedge gauss6": ("C4", "D", "-"),
    "knifeedge implicit_midpoint": ("C5", "x", "-"),
    "solve_ivp DOP853, Python rhs": ("k", "o", ":"), "solve_ivp DOP853, numba rhs": ("0.45", "o", "--"),
    "solve_ivp LSODA, numba rhs": ("C8", "P", "--"), "numbalsoda DOP853": ("C9", "*", "--"),
}


def write_csv(rows, path: Path) -> None:
    keys = list(rows[0])
    with path.open("w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)


def _clean(o):
    if isinstance(o, dict):
        return {k: _clean(v) for k, v in o.items()}
    if isinstance(o, (list, tuple)):
        return [_clean(v) for v in o]
    if isinstance(o, (np.floating, float)):
        return None if not math.isfinite(float(o)) else float(o)
    if isinstance(o, np.integer):
        return int(o)
    if isinstance(o, np.ndarray):
        return _clean(o.tolist())
    return o


def write_json(obj, path: Path) -> None:
    path.write_text(json.dumps(_clean(obj), indent=1))


def work_precision_chart(rows, scenes, path: Path) -> None:
    fig, axes = plt.subplots(3, len(scenes), figsize=(6.5 * len(scenes), 13), squeeze=False)
    for j, scene in enumerate(scenes):
        sub = [r for r in rows if r["scene"] == scene.key]
        for method in STYLE:
            pts = [r for r in sub if r["method"] == method and 0 < r["state_error"] < math.inf]
            if not pts:
                continue
            pts.sort(key=lambda r: r["nfev"])
            c, mk, ls = STYLE[method]
            kw = dict(color=c, marker=mk, ls=ls, ms=4, lw=1, label=method)
            axes[0, j].loglog([r["seconds"] for r in pts], [r["state_error"] for r in pts], **kw)
            axes[1, j].loglog([r["nfev"] for r in pts], [r["state_error"] for r in pts], **kw)
            rev = [r for r in pts if r["reversal_error"] is not None and 0 < r["reversal_error"] < math.inf]
            if rev:
                axes[2, j].loglog([r["seconds"] for r in rev], [r["reversal_error"] for r in rev], **kw)
        axes[0, j].set_title(scene.title)
        axes[0, j].set_xlabel("wall time per solve [s] (median of repeats)")
        axes[1, j].set_xlabel("right-hand-side evaluations")
        axes[2, j].set_xlabel("wall time per solve [s]")
        axes[0, j].set_ylabel("final-state error (max-norm, relative)")
        axes[1, j].set_ylabel("final-state error")
        axes[2, j].set_ylabel("first reversal time, relative error")
        for a in axes[:, j]:
            a.grid(True, which="major", lw=0.3)
    axes[0, 0].legend(fontsize=7, loc="lower left")
    fig.suptitle("Work-precision: adaptive methods over rtol 1e-4 ... 3e-14 (atol = 1e-6 rtol), "
                 "fixed-step methods over h = T/8 ... T/512", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


VERDICT_COLORS = {"right": "tab:green", "reversal time off > 1e-3 (silent)": "gold",
                  "wrong reversal count (silent)": "tab:red", "blow-up (reported)": "black",
                  "solver failure (reported)": "tab:gray"}


def failures_chart(stab, wp_rows, later, ref_times_later, long, path: Path, later_floor=None) -> None:
    """The four failure panels; ``later_floor`` (largest shift of reversals 2..4 under a round-off
    perturbation of the initial state) is drawn as the band below which errors are not resolved."""
    fig, ax = plt.subplots(2, 2, figsize=(14, 10))
    # (a) stability map
    a = ax[0, 0]
    labels = []
    for i, key in enumerate(sorted({(q["scene"], q["method"]) for q in stab})):
        labels.append(f"{key[0]}: {key[1]}")
        for q in stab:
            if (q["scene"], q["method"]) == key:
                a.scatter(q["h_over_T"], i, color=VERDICT_COLORS[q["verdict"]], s=28, marker="s")
    a.set_xscale("log")
    a.set_yticks(range(len(labels)), labels, fontsize=8)
    a.set_xlabel("step h / oscillation period T")
    for v, c in VERDICT_COLORS.items():
        a.scatter([], [], color=c, marker="s", label=v)
    a.legend(fontsize=7, loc="upper left")
    a.set_title("Stability map of the fixed-step methods (reversal count and times vs reference)", fontsize=9)
    # (b) tolerance limits
    b = ax[0, 1]
    for method in ("knifeedge DOP853", "knifeedge DP54", "solve_ivp DOP853, numba rhs", "numbalsoda DOP853"):
        for scene, ls in (("single", "-"), ("two", "--")):
            pts = sorted((r["setting"], r["state_error"]) for r in wp_rows
                         if r["method"] == method and r["scene"] == scene and r["kind"] != "fixed")
            if pts:
                c = STYLE[method][0]
                b.loglog([p[0] for p in pts], [p[1] for p in pts], ls=ls, marker="o", ms=3, color=c,
                         label=f"{method} ({scene})")
    xs = np.array([1e-14, 1e-4])
    b.loglog(xs, xs, color="0.7", lw=0.8, label="error = rtol")
    b.invert_xaxis()
    b.set_xlabel("rtol")
    b.set_ylabel("final-state error")
    b.set_title("Tolerance limits: where round-off wins", fontsize=9)
    b.legend(fontsize=6)
    # (c) later reversals
    c = ax[1, 0]
    from .failures import variant

    colors = {"DOP853": "C0", "DP54": "C1", "RK4": "C2", "gauss4": "C3", "gauss6": "C4", "implicit_midpoint": "C5"}
    for name in sorted({variant(q) for q in later}):
        pts = sorted((q["nfev"], q["later_max_error"]) for q in later if variant(q) == name)
        base = name.split(" ")[0]
        ls = "--" if "mode" in name else (":" if "capped" in name else "-")
        c.loglog([p[0] for p in pts], [min(p[1], 1.0) for p in pts], marker="o", ms=4, color=colors[base], ls=ls,
                 label=name)
    c.axhline(1e-3, color="k", lw=0.6, ls=":")
    if later_floor:
        c.axhspan(1e-8, later_floor, color="0.85", zorder=0)
        c.text(0.02, 0.02, f"below {later_floor:.0e}: set by round-off (double precision)", transform=c.transAxes,
               fontsize=7, color="0.3")
    c.set_xlabel("right-hand-side evaluations (two-mode scene, t = 0..12000)")
    c.set_ylabel("worst relative error of reversals 2..4 (1 = count wrong)")
    c.set_title("Conditioning of the later reversals: error against cost", fontsize=9)
    c.legend(fontsize=7)
    # (d) long runs
    d = ax[1, 1]
    if long:
        for q in long["runs"]:
            d.loglog(q["nfev"], max(q["energy_drift_end"], 1e-17), marker="o", ls="")
            d.annotate(f"{q['label']}\n{q['reversals_kept_right']}/{long['reference_reversals']} reversals right",
                       (q["nfev"], max(q["energy_drift_end"], 1e-17)), fontsize=6)
        d.set_xlabel("right-hand-side evaluations")
        d.set_ylabel("relative energy error at the end")
        d.set_title(f"Long runs: two-mode scene over {long['periods']:.0e} periods (t = {long['t_end']:.0f})",
                    fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
