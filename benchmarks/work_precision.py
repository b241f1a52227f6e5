"""Work-precision data: error against wall time and right-hand-side evaluations."""
from __future__ import annotations

import math

import numpy as np

import knifeedge as ke

from . import peers
from .reference import reversal_error, state_error
from .scenes import PERIOD
from .timing import median_time

RTOLS = [10.0**-k for k in range(4, 13)]
#: tolerances past 1e-12, down to the smallest accepted, for the tolerance limits
TIGHT_RTOLS = [1e-13, 3e-14, ke.simulate.__globals__["MIN_RTOL"] * 1.0001]
STEPS_PER_PERIOD = [8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512]


def atol_for(rtol: float) -> float:
    """The absolute tolerance paired with ``rtol``: 1e-6 of it (tilts start at 1e-3 and decay)."""
    return rtol * 1e-6


def _row(scene, ref, label, kind, setting, y_end, rev, nfev, seconds):
    e = scene.model.energy(y_end, scene.p) if np.all(np.isfinite(y_end)) else float("nan")
    return {
        "scene": scene.key, "method": label, "kind": kind, "setting": setting, "nfev": int(nfev),
        "seconds": seconds, "state_error": state_error(y_end, ref["y_end"]) if np.all(np.isfinite(y_end)) else math.inf,
        "reversal_error": reversal_error(rev, ref["reversal_times"]),
        "energy_error": abs(e - ref["energy0"]) / abs(ref["energy0"]),
    }


def compiled_rows(scene, ref, repeats, tight=True, progress=print):
    rows = []
    m, p, y0, span, te = scene.model, scene.p, scene.y, (0.0, scene.t_end), [scene.t_end]
    adaptive = [name for name, m in ke.integrators.COMPILED_METHODS.items() if not m.fixed_step]
    for method in adaptive:  # every registered explicit method: DOP853, DP54, Tsit5, ...
        for rtol in RTOLS + (TIGHT_RTOLS if tight else []):
            def call(rtol=rtol, method=method):
                return ke.simulate(m, y0, span, p, method=method, rtol=rtol, atol=atol_for(rtol), t_eval=te)
            r = call()
            if not r.success:
                progress(f"  {method} rtol {rtol:g}: {r.message}")
                continue
            sec = median_time(call, repeats)
            rows.append(_row(scene, ref, f"knifeedge {method}", "adaptive", rtol, r.y[:, -1], r.reversal_times,
                             r.nfev, sec))
    for method in ("RK4", "gauss4", "gauss6", "implicit_midpoint"):
        for n in STEPS_PER_PERIOD:
            h = PERIOD / n
            if method == "implicit_midpoint" and n < 16:
                continue

            def call(h=h, method=method):
                return ke.simulate(m, y0, span, p, method=method, h=h, t_eval=te)
            r = call()
            if not r.success:
                progress(f"  {method} h = T/{n}: {r.message}")
                continue
            sec = median_time(call, repeats)
            rows.append(_row(scene, ref, f"knifeedge {method}", "fixed", n, r.y[:, -1], r.reversal_times,
                             r.nfev, sec))
    progress(f"  {scene.key}: compiled methods done ({len(rows)} runs)")
    return rows


def peer_rows(scene, ref, repeats, progress=print, python_max_rtol=1e-12):
    rows = []
    runners = {
        "solve_ivp DOP853, Python rhs": peers.scipy_runner(scene, "DOP853", python_rhs=True),
        "solve_ivp DOP853, numba rhs": peers.scipy_runner(scene, "DOP853", python_rhs=False),
        "solve_ivp LSODA, numba rhs": peers.scipy_runner(scene, "LSODA", python_rhs=False),
    }
    nb = peers.numbalsoda_runner(scene)
    if nb is not None:
        runners["numbalsoda DOP853"] = nb
    for label, run in runners.items():
        slow = "Python" in label or "LSODA" in label
        for rtol in RTOLS:
            if "Python" in label and rtol < python_max_rtol:
                continue
            y, rev, nfev = run(rtol, atol_for(rtol))
            sec = median_time(lambda: run(rtol, atol_for(rtol)), repeats=3 if slow else repeats,
                              min_seconds=0.0 if slow else 0.02)
            rows.append(_row(scene, ref, label, "peer", rtol, y, rev, nfev, sec))
        progress(f"  {scene.key}: {label} done")
    return rows


def time_at_error(rows, method, error, key="state_error"):
    """Wall time of ``method`` at ``error`` by log-log interpolation over its runs (nan outside them)."""
    pts = sorted((r[key], r["seconds"]) for r in rows if r["method"] == method and 0 < r[key] < math.inf)
    if len(pts) < 2:
        return float("nan")
    e = np.log([q[0] for q in pts])
    s = np.log([q[1] for q in pts])
    x = math.log(error)
    if x < e.min() or x > e.max():
        return float("nan")
    # errors may be non-monotone at the tight end (round-off): use the cheapest run reaching the error
    best = float("nan")
    for i in range(len(pts) - 1):
        lo, hi = sorted((e[i], e[i + 1]))
        if lo <= x <= hi:
            w = 0.0 if hi == lo else (x - e[i]) / (e[i + 1] - e[i])
            cand = math.exp(s[i] + w * (s[i + 1] - s[i]))
            best = cand if not (best <= cand) else best
    return best


def equal_error_ratios(rows, ours="knifeedge DOP853", errors=(1e-6, 1e-8, 1e-10)):
    """{peer: {error: time_peer / time_ours}} at equal final-state error."""
    out = {}
    for method in sorted({r["method"] for r in rows}):
        if method == ours:
            continue
        out[method] = {}
        for err in errors:
            a, b = time_at_error(rows, method, err), time_at_error(rows, ours, err)
            out[method][f"{err:g}"] = a / b if a == a and b == b else None
    return out


def equal_tolerance_ratio(rows, peer, ours="knifeedge DOP853"):
    """Same algorithm, same tolerance => same steps and error: ratio of times at each rtol (median)."""
    a = {r["setting"]: r["seconds"] for r in rows if r["method"] == peer}
    b = {r["setting"]: r["seconds"] for r in rows if r["method"] == ours}
    common = sorted(set(a) & set(b))
    return {f"{k:g}": a[k] / b[k] for k in common}, (float(np.median([a[k] / b[k] for k in common])) if common else None)
