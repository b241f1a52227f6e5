"""What recording every step costs ``ke.simulate``, and the default call against ``solve_ivp`` with a Python rhs.

    python -m benchmarks.recording [--repeats 9] [--out benchmarks/results/recording.json]

The two-mode scene of the README ("Use": ``two_mode``, ``full``, g = ell = 1, L = 2, D = 0.5, alpha = pi/4,
tilts 1e-3, phi_dot 0.1), compiled DOP853 at the default rtol 1e-10, atol 1e-12, the spin reversals located
(always on).  For t = 0..3000 (the issue's scene) and two longer spans (more rows than the first buffer holds:
the buffer grows), per right-hand-side evaluation, each call divided by its own evaluation count:

* ``final_state``: ``t_eval=[t1]``, only the final state stored;
* ``every_step``: the default output, every accepted step (``t_eval=None``);
* ``every_step_all_events``: the same with the zero crossings of every state located too;
* ``kernel_every_step``: the compiled kernel alone storing every step into one buffer allocated beforehand
  (what the recording costs inside the step loop, without ``simulate``'s Python side);

and the minor page faults of one call (fresh memory the call touches).  Then ``simulate``'s fixed costs at
t = 0..3000 (input checks, a run of one step, the transposition of the rows) and the default call against
``solve_ivp(method="DOP853")`` with the model's right-hand side as plain Python (same tolerances, the same
reversal event, every step returned by both; the full span for both, no scaling).

CPU time (``time.process_time``), the calls interleaved so that a change of load hits all alike, medians of
the repeats; the load average is recorded before and after.
"""
from __future__ import annotations

import argparse
import importlib
import json
import os
import platform
import resource
import time
from pathlib import Path

import numpy as np

import knifeedge as ke
from knifeedge.integrators import kernel

from .overhead import _interleaved, default_call_race
from .scenes import TWO

SPANS = (3000.0, 30000.0, 300000.0)


def _faults(fn) -> float:
    """Minor page faults of one call of ``fn`` (median of 3)."""
    out = []
    for _ in range(3):
        a = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
        fn()
        out.append(resource.getrusage(resource.RUSAGE_SELF).ru_minflt - a)
    return float(sorted(out)[1])


def recording_row(scene, repeats: int) -> dict:
    """Cost per evaluation of the final state only, every step, every step with every state's events, the
    kernel alone storing every step; ratios to the final-state call."""
    sim = importlib.import_module("knifeedge.simulate")
    m, p, y0, t1 = scene.model, scene.p, scene.y, scene.t_end
    span = (0.0, t1)
    calls = {
        "final_state": lambda: ke.simulate(m, y0, span, p, t_eval=[t1]),
        "every_step": lambda: ke.simulate(m, y0, span, p),
        "every_step_all_events": lambda: ke.simulate(m, y0, span, p, events=m.state_names),
    }
    res = {k: fn() for k, fn in calls.items()}
    nfev = {k: r.nfev for k, r in res.items()}
    rows = res["every_step"].t.size
    run = sim.check_inputs(m, y0, span, p)
    solve = kernel(m, "DOP853")
    events = np.array([m.index(m.spin_name)], dtype=np.int64)
    pair = sim._mode_pairs(m)
    bufs = (np.empty(rows + 1), np.empty((rows + 1, m.n_state)), np.empty(10**5), np.empty(10**5, dtype=np.int64))

    def kernel_every_step():
        return solve(0.0, t1, run.y0, run.y0, run.p, (run.rtol, run.atol, 0.0, np.inf, pair, False),
                     (np.empty(0), True, events, run.max_steps, 2**62), bufs)

    out = kernel_every_step()
    assert out[2] == 0 and out[0] == rows - 1, "the kernel alone must take the run's steps in one call"
    nfev["kernel_every_step"] = int(out[3])
    calls["kernel_every_step"] = kernel_every_step
    sec = _interleaved(calls, repeats)
    row = {"t_end": t1, "rows": int(rows), "nfev": int(nfev["every_step"])}
    row.update({f"{k}_ns": 1e9 * v / nfev[k] for k, v in sec.items()})
    row.update({f"{k}_faults": _faults(fn) for k, fn in calls.items()})
    for k in ("every_step", "every_step_all_events", "kernel_every_step"):
        row[f"{k}_over_final_state"] = row[f"{k}_ns"] / row["final_state_ns"]
    return row


def fixed_costs(scene, repeats: int) -> dict:
    """Microseconds of ``simulate``'s Python side at the scene: input checks, a whole call over a span of one
    step, the transposition of the run's rows into the result's (n_state, rows) array."""
    sim = importlib.import_module("knifeedge.simulate")
    m, p, y0, t1 = scene.model, scene.p, scene.y, scene.t_end
    r = ke.simulate(m, y0, (0.0, t1), p)
    rows, n = np.ascontiguousarray(r.y.T), m.n_state
    sec = _interleaved({
        "check_inputs": lambda: sim.check_inputs(m, y0, (0.0, t1), p),
        "one_step_call": lambda: ke.simulate(m, y0, (0.0, 1e-3), p),
        "transposition": lambda: sim._assembled([(r.t, rows)], n),
    }, repeats)
    return {k + "_us": 1e6 * v for k, v in sec.items()}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.recording", description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=9)
    ap.add_argument("--out", type=Path, default=Path(__file__).resolve().parent / "results" / "recording.json")
    args = ap.parse_args(argv)
    results = {"machine": platform.platform(), "cpus": os.cpu_count(), "python": platform.python_version(),
               "repeats": args.repeats, "clock": "CPU time (process_time), interleaved, medians",
               "load_average_before": os.getloadavg()}
    ke.simulate(TWO.model, TWO.y, (0.0, 1.0), TWO.p)  # the kernel loaded (compiled on a first run)
    results["recording"] = []
    print("two-mode scene, DOP853 rtol 1e-10: ns per rhs evaluation (each call by its own evaluations)")
    print(f"{'t_end':>9} {'rows':>7} {'final':>7} {'every':>7} {'ratio':>6} {'+all ev':>8} {'kernel':>7} "
          f"{'faults f/e':>11}")
    for t1 in SPANS:
        q = recording_row(TWO.with_end(t1), args.repeats)
        results["recording"].append(q)
        print(f"{t1:9g} {q['rows']:7d} {q['final_state_ns']:7.1f} {q['every_step_ns']:7.1f} "
              f"{q['every_step_over_final_state']:6.3f} {q['every_step_all_events_ns']:8.1f} "
              f"{q['kernel_every_step_ns']:7.1f} {q['final_state_faults']:5.0f}/{q['every_step_faults']:<5.0f}")
    results["fixed_costs"] = fixed_costs(TWO, args.repeats)
    print("simulate's Python side at t_end 3000: " + ", ".join(f"{k} {v:.1f}" for k, v in results["fixed_costs"].items()))
    d = default_call_race(TWO, repeats=max(3, args.repeats // 3))
    results["default_call"] = d
    print(f"default call (every step, reversals), t = 0..3000: knifeedge DOP853 {1e3 * d['knifeedge_s']:.2f} ms, "
          f"solve_ivp DOP853 with a Python rhs {d['solve_ivp_python_rhs_s']:.3f} s: {d['ratio']:.0f}x "
          f"(rows {d['rows'][0]} and {d['rows'][1]}, rhs evaluations {d['knifeedge_nfev']} and "
          f"{d['solve_ivp_nfev']}, reversal times differ by {d['reversal_difference']:.1e})")
    results["load_average_after"] = os.getloadavg()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(results, indent=1) + "\n")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
