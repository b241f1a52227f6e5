"""Run every benchmark: ``python -m benchmarks [--out DIR] [--quick]``.

Writes into ``--out`` (default ``benchmarks/results``):
``work_precision.png``, ``failures.png`` (charts), ``work_precision.csv``
(one row per run) and ``results.json`` (everything, including the ratios,
per-evaluation costs, warm start, references and failure maps), and prints a
summary.
"""
from __future__ import annotations

import argparse
import platform
import time
from pathlib import Path

from . import failures, overhead, peers, report, work_precision
from .reference import perturbation_spread, reference
from .scenes import SINGLE, TWO


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=Path(__file__).resolve().parent / "results")
    ap.add_argument("--quick", action="store_true", help="fewer repeats, a shorter long run")
    ap.add_argument("--repeats", type=int, default=None, help="timing repeats (default 7, quick 3)")
    ap.add_argument("--long-periods", type=float, default=None, help="periods of the long runs (default 1e5)")
    args = ap.parse_args(argv)
    repeats = args.repeats or (3 if args.quick else 7)
    periods = args.long_periods or (1e4 if args.quick else 1e5)
    args.out.mkdir(parents=True, exist_ok=True)
    t_start = time.perf_counter()
    log = lambda s: print(f"[{time.perf_counter() - t_start:7.1f} s] {s}", flush=True)  # noqa: E731
    results = {"machine": platform.platform(), "python": platform.python_version(), "repeats": repeats}
    if peers.numbalsoda is None:
        results["numbalsoda"] = peers.NUMBALSODA_NOTE
        log(peers.NUMBALSODA_NOTE)
    else:
        results["numbalsoda"] = f"numbalsoda {getattr(peers.numbalsoda, '__version__', 'installed')}"

    log("references")
    refs = {"single": reference(SINGLE, h=0.02), "two": reference(TWO, h=0.025)}
    for k, r in refs.items():
        log(f"  {k}: {r['method']}: Richardson state error {r['richardson_state_error']:.1e}, reversal "
            f"{r['richardson_reversal_error']:.1e}; SciPy DOP853 rtol 3e-14 differs by {r['scipy_dop853_state_difference']:.1e}"
            f" (state), {r['scipy_dop853_reversal_difference']:.1e} (reversal)")
    results["references"] = refs

    log("work-precision")
    rows = []
    for scene in (SINGLE, TWO):
        rows += work_precision.compiled_rows(scene, refs[scene.key], repeats, progress=log)
        # the pure-Python right-hand side of the two-mode model costs ~60 us a call: stop it at rtol 1e-10
        rows += work_precision.peer_rows(scene, refs[scene.key], repeats, progress=log,
                                         python_max_rtol=1e-10 if scene.key == "two" else 1e-12)
    report.write_csv(rows, args.out / "work_precision.csv")
    results["work_precision"] = rows
    ratios = {}
    for scene in (SINGLE, TWO):
        sub = [r for r in rows if r["scene"] == scene.key]
        ratios[scene.key] = {
            "equal_error": work_precision.equal_error_ratios(sub),
            "same_algorithm_same_rtol": {
                peer: dict(zip(("per_rtol", "median"), work_precision.equal_tolerance_ratio(sub, peer)))
                for peer in ("solve_ivp DOP853, Python rhs", "solve_ivp DOP853, numba rhs")},
        }
    results["ratios"] = ratios
    report.work_precision_chart(rows, (SINGLE, TWO), args.out / "work_precision.png")

    log("cost per right-hand-side evaluation")
    results["per_evaluation"] = [overhead.per_evaluation(SINGLE.with_end(3000.0), repeats=repeats),
                                 overhead.per_evaluation(TWO, repeats=repeats)]
    results["integrator_floor"] = overhead.integrator_floor(repeats=repeats)
    log("recording: final state only against every step with events")
    results["recording"] = [overhead.recording_cost(SINGLE.with_end(3000.0), repeats=repeats),
                            overhead.recording_cost(TWO, repeats=repeats)]
    log("the default call against solve_ivp with a Python right-hand side (two-mode scene)")
    results["default_call"] = overhead.default_call_race(TWO, repeats=max(3, repeats // 2))
    log("warm start of a second process")
    results["warm_start"] = overhead.warm_start(TWO)

    log("stability maps")
    stab = failures.stability_map(SINGLE, refs["single"]["reversal_times"], progress=log)
    stab += failures.stability_map(TWO, refs["two"]["reversal_times"], progress=log)
    results["stability_map"] = stab
    results["largest_right_step"] = failures.largest_right_step(stab)

    log("later reversals (two-mode scene, t = 0..12000)")
    ref12 = reference(TWO.with_end(12000.0), h=0.025)
    results["later_reversals_reference"] = ref12
    spread = perturbation_spread(TWO.with_end(12000.0), h=0.025)
    results["later_reversals_reference_spread"] = spread
    log("  reference reversals move by " + ", ".join(f"{x:.1e}" for x in spread["max_relative_shift"])
        + f" when the initial state moves by {spread['relative_perturbation']:g} (relative)")
    later = failures.later_reversals(ref12["reversal_times"], progress=log)
    results["later_reversals"] = later
    results["later_reversals_cheapest"] = failures.cheapest_converged(later)

    log(f"long runs ({periods:g} periods)")
    long = failures.long_runs(periods=periods, progress=log)
    results["long_runs"] = long
    report.failures_chart(stab, rows, later, ref12["reversal_times"], long, args.out / "failures.png",
                          later_floor=max(spread["max_relative_shift"][1:]))
    report.write_json(results, args.out / "results.json")
    _summary(results, log)
    log(f"wrote {args.out}/work_precision.png, failures.png, work_precision.csv, results.json")
    return 0


def _summary(res, log) -> None:
    print("\n=== summary ===")
    for scene, r in res["ratios"].items():
        same = r["same_algorithm_same_rtol"]
        for peer, v in same.items():
            if v["median"]:
                print(f"{scene}: {peer} / knifeedge DOP853 at the same rtol (same steps, same error): "
                      f"median {v['median']:.0f}x  (per rtol: "
                      + ", ".join(f"{k}: {x:.0f}" for k, x in v["per_rtol"].items()) + ")")
        for peer, v in r["equal_error"].items():
            vals = ", ".join(f"err {k}: {'-' if x is None else f'{x:.2f}x'}" for k, x in v.items())
            print(f"{scene}: time {peer} / knifeedge DOP853 at equal final-state error: {vals}")
    for q in res["per_evaluation"]:
        line = (f"{q['scene']}: per rhs evaluation: floor {q['floor_ns']:.1f} ns (rhs_into from the parameters "
                f"{q['floor_p_ns']:.1f} ns), DOP853 kernel "
                f"{q['dop853_kernel_ns']:.1f} ns (overhead {q['dop853_overhead_ns']:.1f} ns), via ke.simulate "
                f"{q['dop853_simulate_ns']:.1f} ns")
        if "numbalsoda_ns" in q:
            line += f", numbalsoda DOP853 {q['numbalsoda_ns']:.1f} ns (overhead {q['numbalsoda_overhead_ns']:.1f} ns)"
        print(line)
    print("integrator's own cost per evaluation (near-free rhs): " + ", ".join(
        f"{q['method']} n={q['n_state']}: {q['ns_per_evaluation']:.1f} ns" for q in res["integrator_floor"]))
    for q in res["recording"]:
        print(f"{q['scene']}: ke.simulate per evaluation: final state only {q['final_state_ns']:.1f} ns, every step "
              f"+ reversals {q['every_step_ns']:.1f} ns ({q['every_step_over_final_state']:.2f}x, {q['rows']} rows), "
              f"+ events on every state {q['every_step_all_events_ns']:.1f} ns")
    d = res["default_call"]
    print(f"{d['scene']}: default call: knifeedge DOP853 {1e3 * d['knifeedge_s']:.2f} ms, solve_ivp DOP853 with a "
          f"Python rhs {d['solve_ivp_python_rhs_s']:.2f} s: {d['ratio']:.0f}x (every step returned by both, "
          f"reversal times differ by {d['reversal_difference']:.1e})")
    w = res["warm_start"]
    print(f"warm second process: import {w['import_s']:.2f} s, then simulate {w['simulate_after_import_s']:.3f} s")
    for k, v in res["largest_right_step"].items():
        print(f"stability {k}: largest right h/T = {v['largest_right_h_over_T']}, beyond: {v['beyond']}")
    for k, v in res["later_reversals_cheapest"].items():
        print(f"later reversals within 1e-3: {k}: " + (f"{v['label']}, {v['nfev']} rhs evaluations, "
                                                      f"{v['seconds']:.2f} s" if v else "not reached"))
    for q in res["long_runs"]["runs"]:
        print(f"long run {q['label']}: {q['reversals_kept_right']}/{res['long_runs']['reference_reversals']} "
              f"reversals right, energy error at end {q['energy_drift_end']:.1e}, {q['nfev']} rhs evaluations")


if __name__ == "__main__":
    raise SystemExit(main())
