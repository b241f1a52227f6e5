"""Scale-out of ``ke.sweep``: wall time on 1 and 2 local workers and a Dask LocalCluster, and the share of it
spent outside integration (scheduling, serialization, writing rows).

    python -m benchmarks.sweep_scaling [--runs 10000] [--repeats 3] [--out benchmarks/results/sweep_scaling.json]

The sweep: first-reversal runs of the two-mode ``full`` model (the ``tinversion`` scene's run: ``ell/L = 1/2``,
``D/ell = 1/2``, ``alpha = pi/4``, tilts 1e-3, DOP853 at rtol 1e-10), ``phi_dot`` from 0.05 to 0.4, each run's
span the scene's bound on its first reversal (``_t_end``); every row committed to an SQLite store.  On Dask
twice: with its default configuration, and with the lighter one of ``DASK_LIGHT_CONFIG`` (no profiler in the
workers, slower watchdogs), which a sweep's user may choose.

Two measures of the time spent outside integration, for each configuration with ``w`` workers:

* ``overhead_wall = 1 - busy / (w * wall)``: ``busy`` is the sum over runs of the wall time each spent in its
  worker integrating (the row's ``seconds``: ``RunSpec.simulate`` and the reversal columns); the rest of the
  workers' time went to starting them, handing out tasks, pickling, the parent's commits and the tail.  On a
  machine shared with other work both times stretch, and a worker waiting for a core counts as overhead.
* ``overhead_cpu_direct = 1 - cpu_in_runs / cpu_total``: ``cpu_in_runs`` is the CPU time of the sweep's runs
  themselves, measured in its workers as they run (the thread time of each ``run_one``), ``cpu_total`` the CPU
  time the sweep used -- its own process (scheduling, the store, unpickling rows) plus its workers (start-up
  included).  Both are measured in the same sweep, under the same load.
* ``overhead_cpu_sweep_own``: the part of it that is the sweep's own work -- the CPU time of the sweep's main
  thread (its code, and a Dask client's ``submit``) plus, on local workers, theirs outside the runs -- over the
  same ``cpu_total``; the rest is a Dask cluster's: the threads of its scheduler, client loop and nannies in the
  sweep's process, and its workers outside the runs.
* ``overhead_cpu = 1 - cpu_integration / cpu_total``: ``cpu_integration`` is the CPU time of the same runs
  integrated one after another in this process (``run_one``, measured first); ``cpu_total`` the CPU time the
  sweep used -- its own process (scheduling, the store, unpickling rows) plus its workers (start-up included).
  CPU time does not count waiting for a core; but a core shared with other work also runs slower, and
  ``cpu_integration`` is measured before the sweeps, so on a loaded machine this figure drifts by several per
  cent either way (``overhead_cpu_direct`` does not).

Each repeat measures ``cpu_integration`` again, then every configuration; the rows are the medians over the
repeats (``repeats`` holds every measurement), with the 1-minute load average of the machine before and after
(the sweep's own processes included), and the best wall time of each (other work on a shared machine only ever
adds time: a third busy process on 2 cores takes most of what a second worker would gain).
"""
from __future__ import annotations

import argparse
import importlib
import json
import multiprocessing
import os
import platform
import resource
import sqlite3
import tempfile
import threading
import time
from pathlib import Path

import numpy as np

import knifeedge as ke
from knifeedge.scenes.tinversion import RUN, _t_end
from knifeedge.sweep import run_one


_SWEEP = importlib.import_module("knifeedge.sweep")
#: a Dask cluster with less bookkeeping of its own: no statistical profiler in the workers (a stack sample of the
#: running task every 10 ms), its event-loop watchdog every 1 s (20 ms) and its CPU/memory monitor every 5 s (0.5 s)
DASK_LIGHT = "dask LocalCluster, 2 workers, light config"
DASK_LIGHT_CONFIG = {"distributed.worker.profile.enabled": False, "distributed.admin.tick.interval": "1s",
                     "distributed.admin.system-monitor.interval": "5s"}
_RUN_ONE = _SWEEP.run_one
#: CPU seconds inside run_one of each local worker forked from this process, one slot each, written without a lock
#: (a lock shared by the workers stalls one whenever the other is preempted holding it); None in a Dask worker
_SHARED = None
_SLOTS_USED = None
_MINE = [None, None, 0.0]  # this process: its pid, its slot, its total
_IN_RUNS = 0.0  # in a Dask worker


def _timed_run_one(spec):
    """``run_one``, adding the CPU time of its thread to the total of this process."""
    global _IN_RUNS
    c = time.thread_time()
    out = _RUN_ONE(spec)
    dt = time.thread_time() - c
    if _SHARED is None:
        _IN_RUNS += dt
        return out
    if _MINE[0] != os.getpid():  # the first run of this worker: a slot of its own
        with _SLOTS_USED.get_lock():
            _MINE[:] = [os.getpid(), _SLOTS_USED.value, 0.0]
            _SLOTS_USED.value += 1
    _MINE[2] += dt
    _SHARED[_MINE[1]] = _MINE[2]
    return out


def _install_timer() -> None:
    """In a Dask worker: time its runs (by this module imported there, not a copy sent with the function)."""
    m = importlib.import_module("benchmarks.sweep_scaling")
    m._SHARED, m._IN_RUNS = None, 0.0
    importlib.import_module("knifeedge.sweep").run_one = m._timed_run_one


def _read_timer() -> float:
    return importlib.import_module("benchmarks.sweep_scaling")._IN_RUNS


def _warm_up() -> float:
    """In a fresh worker: import knifeedge and load the kernel (one run); its CPU seconds."""
    c = time.process_time()
    from knifeedge.scenes.tinversion import RUN
    from knifeedge.sweep import run_one

    run_one(RUN.with_(fidelity="full", phi_dot=0.2, t_end=10.0).to_dict())
    return time.process_time() - c


def _points(n: int) -> list:
    run = RUN.with_(fidelity="full")
    return [{"phi_dot": float(v), "t_end": _t_end(run, float(v), run.params["D"])} for v in np.linspace(0.05, 0.4, n)]


def _integration_cpu(points: list) -> float:
    """CPU seconds of the runs alone: run_one on each, in this process, one after another."""
    run = RUN.with_(fidelity="full")
    specs = [run.with_(**pt).to_dict() for pt in points]
    c0 = time.process_time()
    for spec in specs:
        run_one(spec)
    return time.process_time() - c0


def _descendants_cpu() -> float:
    """CPU seconds of this process's live descendants (Dask's worker processes)."""
    import psutil

    total = 0.0
    for p in psutil.Process().children(recursive=True):
        try:
            t = p.cpu_times()
            total += t.user + t.system
        except psutil.Error:
            pass
    return total


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)  # reaped children: the sweep's own workers
    return r.ru_utime + r.ru_stime


def _measure(name: str, n_workers: int, points: list, cpu_integration: float, executor=None, client=None) -> dict:
    global _SHARED, _SLOTS_USED
    run = RUN.with_(fidelity="full")
    _SHARED = None
    if client is not None:
        client.run(_install_timer)
    else:  # inherited by the workers forked for this sweep
        _SHARED = multiprocessing.Array("d", 256, lock=False)
        _SLOTS_USED = multiprocessing.Value("i", 0)
    _SWEEP.run_one = _timed_run_one
    try:
        row = _sweep(name, n_workers, points, cpu_integration, executor, run)
    finally:
        _SWEEP.run_one = _RUN_ONE
    in_runs = sum(client.run(_read_timer).values()) if client is not None else sum(_SHARED[:_SLOTS_USED.value])
    cpu_total = row["cpu_parent_s"] + row["cpu_workers_s"]
    row["cpu_in_runs_s"] = in_runs
    row["overhead_cpu_direct"] = 1.0 - in_runs / cpu_total
    # the sweep's own share: its main thread (the sweep's code, and a Dask client's submit) and its local workers
    # outside the runs; the rest is the threads of a Dask scheduler, client loop and nannies, and Dask's workers
    # outside the runs
    own = row["cpu_parent_main_thread_s"] + (0.0 if client is not None else row["cpu_workers_s"] - in_runs)
    row["overhead_cpu_sweep_own"] = own / cpu_total
    return row


def _sweep(name: str, n_workers: int, points: list, cpu_integration: float, executor, run) -> dict:
    forked = executor is None and threading.active_count() == 1  # else new interpreters (see knifeedge.workers)
    with tempfile.TemporaryDirectory() as d:
        store = Path(d) / "runs.sqlite"
        load0 = os.getloadavg()[0]
        c_self, c_children, c_desc = time.process_time(), _children_cpu(), _descendants_cpu()
        c_main = time.thread_time()
        t0 = time.time()
        w0 = time.perf_counter()
        table = ke.sweep(run, points, executor=executor if executor is not None else "processes",
                         max_workers=n_workers, out=store, progress=False)
        wall = time.perf_counter() - w0
        cpu_parent = time.process_time() - c_self
        cpu_main = time.thread_time() - c_main
        cpu_workers = (_children_cpu() - c_children) + (_descendants_cpu() - c_desc)
        with sqlite3.connect(store) as con:
            first = min(r[0] for r in con.execute("SELECT finished_at FROM runs")) - t0
    busy = float(np.nansum(table["seconds"]))
    assert table.n_missing == 0 and table.n_computed == len(points), table.summary()
    cpu_total = cpu_parent + cpu_workers
    return {
        "config": name, "workers": n_workers, "runs": len(points), "wall_s": wall, "busy_s": busy,
        "overhead_wall": 1.0 - busy / (n_workers * wall),
        "cpu_integration_s": cpu_integration, "cpu_parent_s": cpu_parent, "cpu_parent_main_thread_s": cpu_main,
        "cpu_workers_s": cpu_workers,
        "overhead_cpu": 1.0 - cpu_integration / cpu_total,
        "start_to_first_row_s": first, "runs_per_s": len(points) / wall, "mean_run_ms": 1e3 * busy / len(points),
        "ok": int(np.sum(table.ok)), "local_workers_forked": forked, "load_avg_1min_before": load0,
        "load_avg_1min_after": os.getloadavg()[0],
    }


_MEDIAN_KEYS = ("wall_s", "busy_s", "overhead_wall", "cpu_integration_s", "cpu_parent_s", "cpu_parent_main_thread_s",
                "cpu_workers_s", "overhead_cpu", "cpu_in_runs_s", "overhead_cpu_direct", "overhead_cpu_sweep_own",
                "start_to_first_row_s", "runs_per_s", "mean_run_ms")


def _median_row(rows: list) -> dict:
    out = dict(rows[0])
    for k in _MEDIAN_KEYS:
        out[k] = float(np.median([r[k] for r in rows]))
    best = min(rows, key=lambda r: r["wall_s"])  # other work on the machine only ever adds time
    out["best_wall_s"] = best["wall_s"]
    out["best_overhead_wall"] = best["overhead_wall"]
    out["best_overhead_cpu_direct"] = best["overhead_cpu_direct"]
    out["load_avg_1min"] = [min(r["load_avg_1min_before"] for r in rows), max(r["load_avg_1min_after"] for r in rows)]
    for k in ("load_avg_1min_before", "load_avg_1min_after"):
        out.pop(k)
    out["repeats"] = len(rows)
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.sweep_scaling", description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=10_000)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--out", type=Path, default=Path(__file__).resolve().parent / "results" / "sweep_scaling.json")
    ap.add_argument("--skip-dask", action="store_true")
    args = ap.parse_args(argv)
    points = _points(args.runs)
    # warm the compiled-kernel cache once (a first use compiles; that is not the sweep's cost)
    ke.sweep(RUN.with_(fidelity="full"), points[:1], executor="serial", progress=False)
    results = {"machine": platform.platform(), "cpus": os.cpu_count(), "python": platform.python_version(),
               "sweep": f"two_mode full, DOP853 rtol 1e-10, phi_dot 0.05..0.4, {args.runs} runs",
               "load_avg_1min_start": os.getloadavg()[0], "rows": [], "repeats": []}
    configs = [("local, 1 worker", 1), ("local, 2 workers", 2)]
    if not args.skip_dask:
        configs.append(("dask LocalCluster, 2 workers", 2))
        configs.append((DASK_LIGHT, 2))
    integration = []
    # the local sweeps first: once a Dask cluster has run in this process its threads stay, and local workers are
    # then new interpreters rather than forks of this process
    for phase in ("local", "dask"):
        for rep in range(args.repeats):
            todo = [(name, w) for name, w in configs if name.startswith("dask") == (phase == "dask")]
            if not todo:
                continue
            cpu_integration = _integration_cpu(points)
            integration.append(cpu_integration)
            print(f"{phase} repeat {rep + 1}/{args.repeats}: integration alone {cpu_integration:.2f} CPU s for "
                  f"{len(points)} runs (load {os.getloadavg()[0]:.2f})", flush=True)
            for name, w in todo:
                if phase == "dask":
                    import dask
                    from distributed import Client, LocalCluster

                    with dask.config.set(DASK_LIGHT_CONFIG if name == DASK_LIGHT else {}), \
                            LocalCluster(n_workers=w, threads_per_worker=1, processes=True, dashboard_address=None) \
                            as cluster, Client(cluster) as client:
                        # before the clock starts, as for local workers (forks of this warmed-up process): each
                        # worker imports knifeedge and loads the kernel (CPU time reported as worker_warmup_cpu_s)
                        warmup = client.run(_warm_up)
                        r = _measure(name, w, points, cpu_integration, client.get_executor(), client)
                        r["worker_warmup_cpu_s"] = sorted(warmup.values())
                else:
                    r = _measure(name, w, points, cpu_integration)
                results["repeats"].append(r)
                print(json.dumps(r), flush=True)
    results["cpu_integration_s"] = float(np.median(integration))
    results["cpu_integration_all_s"] = integration
    for name, _ in configs:
        results["rows"].append(_median_row([r for r in results["repeats"] if r["config"] == name]))
    one, two = results["rows"][0], results["rows"][1]
    results["speedup_2_vs_1"] = one["wall_s"] / two["wall_s"]
    results["speedup_2_vs_1_best"] = one["best_wall_s"] / two["best_wall_s"]
    ones = [r for r in results["repeats"] if r["config"] == one["config"]]
    twos = [r for r in results["repeats"] if r["config"] == two["config"]]
    results["speedup_2_vs_1_all"] = [a["wall_s"] / b["wall_s"] for a, b in zip(ones, twos)]
    results["load_avg_1min_end"] = os.getloadavg()[0]
    for r in results["rows"]:
        print(f"{r['config']:30s} wall {r['wall_s']:6.2f} s  overhead: wall {100 * r['overhead_wall']:5.1f} %, "
              f"CPU {100 * r['overhead_cpu_direct']:5.1f} % ({100 * r['overhead_cpu']:5.1f} % against the runs alone; "
              f"the sweep's own {100 * r['overhead_cpu_sweep_own']:.1f} %)"
              f"  (sweep process {r['cpu_parent_s']:.2f} CPU s, workers {r['cpu_workers_s']:.2f}, in runs "
              f"{r['cpu_in_runs_s']:.2f}; median of {r['repeats']})")
    print(f"speed-up of 2 local workers over 1: {results['speedup_2_vs_1']:.2f}x (medians), "
          f"{results['speedup_2_vs_1_best']:.2f}x (best walls) "
          f"(each repeat: {', '.join(f'{x:.2f}' for x in results['speedup_2_vs_1_all'])})")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(results, indent=1) + "\n")
    print(f"written to {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
