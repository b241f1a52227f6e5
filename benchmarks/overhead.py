"""Cost per right-hand-side evaluation against its floor, and the warm start of a second process."""
from __future__ import annotations

import json
import statistics
import subprocess
import sys
import time

import numpy as np
from numba import njit

import knifeedge as ke
from knifeedge.integrators import kernel
from knifeedge.integrators import load_kernel

from . import linear_rhs, peers
from .timing import median_time


def _floor_loop(rhs_into):
    @njit
    def floor(n, y, p, dy):
        # a compiled loop calling only the right-hand side; the tiny feedback keeps it from being hoisted
        for _ in range(n):
            rhs_into(0.0, y, p, dy)
            y[0] += 1e-300 * dy[0]
        return dy[0]

    return floor


def per_evaluation(scene, rtol=1e-10, repeats=7) -> dict:
    """Nanoseconds per rhs evaluation: the floors, the compiled DOP853 kernel, ``ke.simulate``, numbalsoda.

    Two floors: ``floor_ns`` is the right-hand side the kernels call
    (``rhs_q_into`` with its parameter-only subexpressions precomputed once,
    :func:`knifeedge.generated.*.constants`); ``floor_p_ns`` is ``rhs_into``,
    which recomputes them from the parameters at every call.  numbalsoda is
    given the same ``rhs_q_into``, so the two integrators differ only in
    their own cost.
    """
    m, p, y0 = scene.model, scene.p, scene.y
    n = m.n_state
    solve = kernel(m, "DOP853")
    atol = np.full(n, rtol * 1e-6)
    te = np.array([scene.t_end])
    pair = np.full(n, -1, dtype=np.int64)
    events = np.array([m.index(m.spin_name)])

    bufs = (np.empty(1), np.empty((1, n)), np.empty(64), np.empty(64, dtype=np.int64))

    def run_kernel():
        return solve(0.0, scene.t_end, y0, y0, p, (rtol, atol, 0.0, np.inf, pair, False),
                     (te, False, events, 10**8, 10**8), bufs)

    nfev = run_kernel()[3]
    t_kernel = median_time(run_kernel, repeats)
    t_api = median_time(lambda: ke.simulate(m, y0, (0.0, scene.t_end), p, rtol=rtol, atol=rtol * 1e-6, t_eval=te),
                        repeats)
    q = m.module.constants(p)
    y, dy = y0.copy(), np.empty(n)
    rhs_q = m.module.rhs_pose_q_into if m.pose else m.module.rhs_q_into
    floor_q, floor_p = _floor_loop(rhs_q), _floor_loop(m.rhs_into)
    t_floor = median_time(lambda: floor_q(nfev, y, q, dy), repeats)
    t_floor_p = median_time(lambda: floor_p(nfev, y, p, dy), repeats)
    out = {
        "scene": scene.key, "rtol": rtol, "nfev": int(nfev),
        "floor_ns": 1e9 * t_floor / nfev,
        "floor_p_ns": 1e9 * t_floor_p / nfev,
        "dop853_kernel_ns": 1e9 * t_kernel / nfev,
        "dop853_simulate_ns": 1e9 * t_api / nfev,
    }
    out["dop853_overhead_ns"] = out["dop853_kernel_ns"] - out["floor_ns"]
    nb = peers.numbalsoda_runner(scene)
    if nb is not None:
        nb_nfev = nb(rtol, rtol * 1e-6)[2]
        out["numbalsoda_nfev"] = int(nb_nfev)
        out["numbalsoda_ns"] = 1e9 * median_time(lambda: nb(rtol, rtol * 1e-6), repeats) / nb_nfev
        out["numbalsoda_overhead_ns"] = out["numbalsoda_ns"] - out["floor_ns"]
    return out


def _interleaved(fns: dict, repeats: int) -> dict:
    """Median CPU seconds of each callable, the calls interleaved so that a change of load hits all alike."""
    inner = {}
    for k, fn in fns.items():
        t = time.perf_counter()
        fn()
        inner[k] = max(1, int(0.05 / max(time.perf_counter() - t, 1e-9)))
    samples = {k: [] for k in fns}
    for _ in range(repeats):
        for k, fn in fns.items():
            t = time.process_time()
            for _ in range(inner[k]):
                fn()
            samples[k].append((time.process_time() - t) / inner[k])
    return {k: statistics.median(v) for k, v in samples.items()}


def recording_cost(scene, repeats=7) -> dict:
    """Cost per evaluation of ``ke.simulate`` (DOP853, its default rtol 1e-10 / atol 1e-12): only the final
    state asked for, against every step recorded (the default) with the reversal events, and the named
    events of every state on top.  CPU time, interleaved, medians of ``repeats``."""
    m, p, y0, span = scene.model, scene.p, scene.y, (0.0, scene.t_end)
    calls = {
        "final_state": lambda: ke.simulate(m, y0, span, p, t_eval=[scene.t_end]),
        "every_step": lambda: ke.simulate(m, y0, span, p),
        "every_step_all_events": lambda: ke.simulate(m, y0, span, p, events=m.state_names),
    }
    nfev = calls["every_step"]().nfev
    sec = _interleaved(calls, repeats)
    out = {"scene": scene.key, "nfev": int(nfev), "rows": int(calls["every_step"]().t.size)}
    out.update({f"{k}_ns": 1e9 * v / nfev for k, v in sec.items()})
    out["every_step_over_final_state"] = sec["every_step"] / sec["final_state"]
    return out


def default_call_race(scene, repeats=3) -> dict:
    """``ke.simulate(model, y0, t_span, p)`` (compiled DOP853, rtol 1e-10, atol 1e-12, every step returned,
    the spin reversals located) against ``solve_ivp(DOP853)`` with a plain Python right-hand side and the same
    tolerances, event and output: what a user would run first.  CPU time, interleaved, medians."""
    from scipy.integrate import solve_ivp

    m, p, y0, span = scene.model, scene.p, scene.y, (0.0, scene.t_end)
    n, k = m.n_state, m.index(m.spin_name)
    into = m.rhs_into.py_func

    def fun(t, y):
        dy = np.empty(n)
        into(t, y, p, dy)
        return dy

    def reversal(t, y):
        return y[k]

    calls = {"knifeedge": lambda: ke.simulate(m, y0, span, p),
             "solve_ivp": lambda: solve_ivp(fun, span, y0, method="DOP853", rtol=1e-10, atol=1e-12, events=reversal)}
    ours, theirs = calls["knifeedge"](), calls["solve_ivp"]()
    sec = _interleaved(calls, repeats)
    return {"scene": scene.key, "knifeedge_s": sec["knifeedge"], "solve_ivp_python_rhs_s": sec["solve_ivp"],
            "ratio": sec["solve_ivp"] / sec["knifeedge"], "knifeedge_nfev": int(ours.nfev),
            "solve_ivp_nfev": int(theirs.nfev), "rows": [int(ours.t.size), int(theirs.t.size)],
            "reversal_difference": float(abs(ours.reversal_times[0] - theirs.t_events[0][0]))}


def integrator_floor(repeats=7) -> list:
    """Cost per evaluation of the compiled DOP853 and DP54 with a near-free rhs (:mod:`.linear_rhs`).

    This is the integrator's own arithmetic and bookkeeping for a state of
    3 and of 5 components (rtol 1e-10, t = 0..300): what it adds to each
    evaluation whatever the right-hand side costs.
    """
    out = []
    for n in (3, 5):
        for method in ("DOP853", "DP54", "Tsit5"):
            solve = load_kernel("erk", method, linear_rhs, f"linear{n}_into", n).solve
            y0, p = np.full(n, 0.5), np.array([0.1])
            atol, te, pair = np.full(n, 1e-16), np.array([300.0]), np.full(n, -1, dtype=np.int64)

            bufs = (np.empty(1), np.empty((1, n)), np.empty(64), np.empty(64, dtype=np.int64))

            def run(solve=solve, y0=y0, p=p, atol=atol, te=te, pair=pair, none=np.empty(0, dtype=np.int64), bufs=bufs):
                return solve(0.0, 300.0, y0, y0, p, (1e-10, atol, 0.0, np.inf, pair, False),
                             (te, False, none, 10**8, 10**8), bufs)

            nfev = run()[3]
            out.append({"n_state": n, "method": method, "nfev": int(nfev),
                        "ns_per_evaluation": 1e9 * median_time(run, repeats) / nfev})
    return out


_WARM = r"""
import json, time
t0 = time.perf_counter()
import knifeedge as ke
t1 = time.perf_counter()
m = ke.load("{model}")
r = ke.simulate(m, {y0!r}, (0.0, {t_end!r}), {params!r}, method="{method}", {extra})
t2 = time.perf_counter()
print(json.dumps({{"import_s": t1 - t0, "simulate_s": t2 - t1, "success": bool(r.success)}}))
"""


def warm_start(scene, method="DOP853", extra="rtol=1e-10", runs=5) -> dict:
    """A fresh Python process imports knifeedge and runs one simulation (cache already warm)."""
    code = _WARM.format(model=scene.model_name, y0=scene.y0, t_end=scene.t_end, params=scene.params,
                        method=method, extra=extra)
    samples = []
    for i in range(runs + 1):
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
        if i:  # the first run may compile and fill the cache
            samples.append(json.loads(out.stdout.strip().splitlines()[-1]))
    return {
        "scene": scene.key, "method": method, "runs": runs,
        "import_s": statistics.median(s["import_s"] for s in samples),
        "simulate_after_import_s": statistics.median(s["simulate_s"] for s in samples),
        "success": all(s["success"] for s in samples),
    }
