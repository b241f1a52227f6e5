"""Where each method fails: stability maps, long runs, tolerance limits, later reversals."""
from __future__ import annotations

import math
import time

import numpy as np

import knifeedge as ke

from .reference import reversal_error
from .scenes import PERIOD, TWO

FIXED = ("RK4", "implicit_midpoint", "gauss4", "gauss6")
#: step sizes of the stability map, in periods of the small oscillation
H_OVER_T = np.geomspace(0.004, 0.8, 24)


def classify(r, ref_times, tol=1e-3) -> str:
    if r.outcome is ke.integrators.Status.NON_FINITE:
        return "blow-up (reported)"
    if not r.success:
        return "solver failure (reported)"
    if len(r.reversal_times) != len(ref_times):
        return "wrong reversal count (silent)"
    if len(ref_times) and reversal_error(r.reversal_times, ref_times) > tol:
        return "reversal time off > 1e-3 (silent)"
    return "right"


def stability_map(scene, ref_times, progress=print) -> list:
    """Each fixed-step method over step sizes: right, silently wrong, or failed (and reported)."""
    rows = []
    m, p, y0 = scene.model, scene.p, scene.y
    for method in FIXED:
        for x in H_OVER_T:
            r = ke.simulate(m, y0, (0.0, scene.t_end), p, method=method, h=float(x * PERIOD), t_eval=[scene.t_end],
                            max_steps=10**8)
            rows.append({"scene": scene.key, "method": method, "h_over_T": float(x), "verdict": classify(r, ref_times),
                         "n_reversals": int(len(r.reversal_times)),
                         "reversal_error": reversal_error(r.reversal_times, ref_times) if r.success else None})
        right = [q["h_over_T"] for q in rows if q["method"] == method and q["verdict"] == "right"]
        progress(f"  stability {scene.key} {method}: largest right h/T = {max(right) if right else None}")
    return rows


def largest_right_step(rows) -> dict:
    """Per (scene, method): the largest h/T below which every step tried is right."""
    out = {}
    for key in sorted({(q["scene"], q["method"]) for q in rows}):
        qs = sorted((q for q in rows if (q["scene"], q["method"]) == key), key=lambda q: q["h_over_T"])
        best, first_wrong = None, None
        for q in qs:
            if q["verdict"] == "right" and first_wrong is None:
                best = q["h_over_T"]
            elif q["verdict"] != "right" and first_wrong is None:
                first_wrong = q
        out[f"{key[0]}:{key[1]}"] = {"largest_right_h_over_T": best,
                                     "beyond": first_wrong["verdict"] if first_wrong else None}
    return out


#: the settings compared on the later reversals (two-mode scene to t = 12000)
CONDITIONING = (
    [("DOP853", dict(rtol=r, atol=1e-12)) for r in (1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 3e-14)]
    + [("DOP853", dict(rtol=r, atol=1e-30, error_control="mode")) for r in (1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 3e-14)]
    + [("DOP853", dict(rtol=1e-6, atol=1e-12, max_step=s)) for s in (1.0, 0.7, 0.5, 0.3, 0.2)]
    + [("DP54", dict(rtol=r, atol=1e-30)) for r in (1e-10, 1e-11, 1e-12, 1e-13)]
    + [("gauss6", dict(h=h)) for h in (0.4, 0.3, 0.2, 0.15, 0.1, 0.07, 0.05)]
    + [("gauss4", dict(h=h)) for h in (0.2, 0.1, 0.05, 0.03, 0.02)]
    + [("RK4", dict(h=h)) for h in (0.1, 0.05, 0.03, 0.02, 0.01)]
    + [("implicit_midpoint", dict(h=h)) for h in (0.02, 0.01, 0.005)]
)


def _label(method, kw):
    if "h" in kw:
        return f"{method} h={kw['h']:g}"
    tail = ", mode" if kw.get("error_control") == "mode" else ""
    if "max_step" in kw:
        tail += f", max_step={kw['max_step']:g}"
    return f"{method} rtol={kw['rtol']:g}, atol={kw['atol']:g}{tail}"


def later_reversals(ref, t_end=12000.0, progress=print) -> list:
    """Reversal-time errors against the reference for every setting of :data:`CONDITIONING`."""
    scene = TWO.with_end(t_end)
    m, p, y0 = scene.model, scene.p, scene.y
    rows = []
    for method, kw in CONDITIONING:
        t = time.perf_counter()
        r = ke.simulate(m, y0, (0.0, t_end), p, method=method, t_eval=[t_end], max_steps=10**8, **kw)
        sec = time.perf_counter() - t
        rt = r.reversal_times
        n = min(len(rt), len(ref))
        err = [abs(rt[i] - ref[i]) / ref[i] for i in range(n)]
        rows.append({
            "method": method, "label": _label(method, kw), "settings": {k: v for k, v in kw.items()},
            "nfev": int(r.nfev), "seconds": sec, "success": bool(r.success),
            "reversal_times": [float(x) for x in rt], "first_error": err[0] if err else None,
            "later_max_error": (max(err[1:]) if len(rt) == len(ref) and len(err) > 1 else math.inf),
        })
    progress(f"  later reversals: {len(rows)} settings done")
    return rows


def variant(q) -> str:
    """The method and how its steps are chosen: ``DOP853``, ``DOP853 mode``, ``DOP853 capped step``."""
    s = q["settings"]
    if s.get("error_control") == "mode":
        return f"{q['method']} (mode error control)"
    if "max_step" in s:
        return f"{q['method']} (capped step, rtol 1e-6)"
    return q["method"]


def cheapest_converged(rows, tol=1e-3) -> dict:
    """Per method variant: the cheapest setting keeping every later reversal within ``tol`` (relative)."""
    out = {}
    for method in sorted({variant(q) for q in rows}):
        ok = [q for q in rows if variant(q) == method and q["later_max_error"] <= tol]
        if ok:
            q = min(ok, key=lambda q: q["nfev"])
            out[method] = {"label": q["label"], "nfev": q["nfev"], "seconds": q["seconds"],
                           "later_max_error": q["later_max_error"]}
        else:
            out[method] = None
    return out


LONG = (
    ("DOP853", dict(rtol=1e-10, atol=1e-12)),
    ("DOP853", dict(rtol=3e-14, atol=1e-30)),
    ("DP54", dict(rtol=1e-10, atol=1e-12)),
    ("RK4", dict(h=0.05)),
    ("gauss4", dict(h=0.1)),
    ("gauss6", dict(h=0.2)),
    ("implicit_midpoint", dict(h=0.02)),
)


def long_runs(periods=1e5, ref_h=0.05, progress=print) -> dict:
    """Two-mode scene over ``periods`` oscillation periods: energy drift and reversals kept right.

    The reference is Gauss6 at ``ref_h`` checked against ``ref_h * 0.7``.  A reversal is kept
    right when it is within 1 % of the mean interval between reversals of the reference's.
    Energy is sampled on a grid common to every method's steps (multiples of 10).
    """
    t_end = PERIOD * periods
    t_end = 10.0 * math.floor(t_end / 10.0)
    scene = TWO.with_end(t_end)
    m, p, y0 = scene.model, scene.p, scene.y
    te = np.linspace(0.0, t_end, 201)
    e0 = m.energy(y0, p)

    def run(method, kw):
        t = time.perf_counter()
        r = ke.simulate(m, y0, (0.0, t_end), p, method=method, t_eval=te, max_steps=10**9, **kw)
        return r, time.perf_counter() - t

    ref, _ = run("gauss6", dict(h=ref_h))
    chk, _ = run("gauss6", dict(h=ref_h * 0.7))
    rt = ref.reversal_times
    window = 0.01 * float(np.mean(np.diff(rt))) if len(rt) > 1 else math.inf

    def kept(times):
        k = 0
        for a, b in zip(times, rt):
            if abs(a - b) > window:
                break
            k += 1
        return k

    out = {"t_end": t_end, "periods": periods, "reference": f"gauss6 h={ref_h:g}",
           "reference_reversals": int(len(rt)), "window": window,
           "reference_check_kept": kept(chk.reversal_times), "reference_check_count": int(len(chk.reversal_times)),
           "runs": []}
    progress(f"  long run reference: {len(rt)} reversals; h*0.7 keeps {out['reference_check_kept']}")
    for method, kw in LONG:
        r, sec = run(method, kw)
        finite = r.y[:, np.all(np.isfinite(r.y), axis=0)]
        drift = np.abs(m.energy(finite, p) - e0) / abs(e0) if finite.size else np.array([np.nan])
        out["runs"].append({
            "label": _label(method, kw), "method": method, "nfev": int(r.nfev), "seconds": sec,
            "success": bool(r.success), "message": r.message, "energy_drift_max": float(np.max(drift)),
            "energy_drift_end": float(drift[-1]), "reversals": int(len(r.reversal_times)),
            "reversals_kept_right": kept(r.reversal_times),
        })
        progress(f"  long run {_label(method, kw)}: {out['runs'][-1]['reversals_kept_right']}/{len(rt)} right, "
                 f"drift {out['runs'][-1]['energy_drift_max']:.1e}, {sec:.1f} s")
    return out
