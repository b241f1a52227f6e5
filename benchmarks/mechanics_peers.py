"""The peer models of ``sympy.physics.mechanics`` through knifeedge (issue 23): derive and run times, errors.

``python -m benchmarks.mechanics_peers`` (part of ``make bench``) takes the models of tests/models written as
their authors wrote them -- SymPy's test_kane5.py rolling disc, pydy#127's differential-drive robot, and the
Whipple bicycle of SymPy's test_kane3.py with the coordinates a Lagrangian needs -- and for each measures

* the CPU time of ``knifeedge derive FILE --out DIR`` in a child process (``from_mechanics``, the engine, the
  symmetry check at a general pose, the emitted module): the time to form the equations and generate code;
* the time of 10 s of motion at rtol 1e-10 (``ke.simulate``, its default compiled DOP853; compiled beforehand,
  median of 5 runs) and the largest error of its final state against a converged reference (the same run at
  rtol 1e-13; its own distance from a run at rtol 1e-12 is printed beside it).

PyDy (``System.generate_ode_function``) is the field's own path; it is optional and skipped with a note when
absent.  Its rows are the Whipple bicycle as SymPy's ``test_kane3.py`` writes it for Kane's method (the test's own
source, run up to its ``kanes_equations``: the rear contact fixed, the wheels' angles left out; the same four bodies
as tests/models/whipple_bicycle.py and the same names, so the benchmark's parameters of that file apply), for each
of PyDy's code generators: the time to form Kane's equations (``kanes_equations``, CRAMER's rule for the dependent
speeds, as the test), the time to generate and compile the right-hand side, and 10 s of motion from the same
state with SciPy's DOP853 at rtol 1e-10 (median of 5, each followed by knifeedge's run, whose median gives the
speedup; knifeedge's timed as a batch of 20 runs), its error against the same converged reference (knifeedge's
run at rtol 1e-13).
``python -m benchmarks.mechanics_peers --pydy-only`` runs the bicycle's rows alone.
"""
from __future__ import annotations

import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import knifeedge as ke

MODELS = Path(__file__).resolve().parents[1] / "tests" / "models"


def _initial(name: str, m):
    """A moving state of each model: the disc rolling and leaning, the robot driven, the bicycle at 5 m/s with a
    lean rate of 0.5 rad/s (self-stable: the lean decays)."""
    if name == "whipple_bicycle":
        from knifeedge.stability import steady_state

        y = steady_state(m, m.params(m.default_params), "straight_running", 5.0)
        y[m.state_names.index("q2_dot")] = 0.5
        return y
    values = dict(m.default_state)
    if name == "sympy_rolling_disc":
        values["q1_dot"] = 0.5
    return m.state(values)


def derive_cpu(file: Path, out: Path) -> float:
    """CPU seconds of ``knifeedge derive file --out out`` (a child process, so nothing is cached in this one)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([sys.executable, "-m", "knifeedge", "derive", str(file), "--out", str(out)], check=True,
                   stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def row(name: str, out: Path) -> dict:
    cpu = derive_cpu(MODELS / f"{name}.py", out)
    m = ke.load(name, path=out)
    p = m.params(m.default_params)
    y0 = _initial(name, m)
    span = (0.0, 10.0)
    ke.simulate(m, y0, span, p, rtol=1e-10, atol=1e-12)  # compiles
    times = []
    for _ in range(5):
        t0 = time.perf_counter()
        run = ke.simulate(m, y0, span, p, rtol=1e-10, atol=1e-12)
        times.append(time.perf_counter() - t0)
    ref = ke.simulate(m, y0, span, p, rtol=1e-13, atol=1e-15)
    ref12 = ke.simulate(m, y0, span, p, rtol=1e-12, atol=1e-14)
    scale = np.maximum(1.0, np.abs(ref.y[:, -1]))
    return {"model": name, "derive_cpu_s": cpu, "run_10s_ms": 1e3 * statistics.median(times),
            "error": float(np.max(np.abs(run.y[:, -1] - ref.y[:, -1]) / scale)),
            "reference_error": float(np.max(np.abs(ref12.y[:, -1] - ref.y[:, -1]) / scale)),
            "rhs_ops": m.module.OP_COUNTS["rhs"], "elimination": m.module.ELIMINATION, "nfev": int(run.nfev)}


#: knifeedge's 10 s runs timed together between two of PyDy's (one is ~2 ms: alone it is a scheduler's time slice)
KNIFEEDGE_BATCH = 20
#: PyDy's code generators, tried in this order (``theano`` is not maintained; ``cython`` needs a C compiler)
PYDY_GENERATORS = ("lambdify", "cython")


def _cpu_with_children() -> float:
    """CPU seconds of this process and its finished children (a compiler run by a code generator)."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def kane3_bicycle() -> dict:
    """SymPy's test_kane3.py bicycle: the test's own source run up to ``KM.kanes_equations(BL, FL)``; returns its
    namespace (``KM``, the symbols, ``conlist_speed``) and the CPU seconds of forming Kane's equations."""
    import inspect
    import textwrap

    from sympy.physics.mechanics.tests import test_kane3

    source = inspect.getsource(test_kane3.test_bicycle)
    end = source.index("\n", source.index("KM.kanes_equations(BL, FL)"))
    body = textwrap.dedent(source[source.index("\n", source.index("def test_bicycle")) + 1:end])
    namespace = dict(vars(test_kane3))
    t0 = time.process_time()
    exec(compile(body, test_kane3.__file__, "exec"), namespace)
    namespace["form_cpu_s"] = time.process_time() - t0
    return namespace


def pydy_initial(ns, system, values: dict, v: float, lean_rate: float) -> np.ndarray:
    """The state of the PyDy system at upright straight running at ``v`` with the lean rate ``lean_rate``: the
    dependent speeds (yaw, pitch and front wheel rates) from the test's velocity constraints."""
    import sympy as sp

    values = {s: values[s.name] for s in system.constants_symbols}
    given = {ns["u2"]: lean_rate, ns["u3"]: v / values[ns["WRrad"]], ns["u5"]: 0.0}
    zero = {q: 0.0 for q in (ns["q1"], ns["q2"], ns["q4"], ns["q5"])}
    dep = [ns["u1"], ns["u4"], ns["u6"]]
    cons = sp.Matrix(ns["conlist_speed"]).xreplace(zero).xreplace(values)
    A = np.array(cons.jacobian(dep).xreplace(given).evalf(), dtype=float)
    b = np.array(cons.xreplace({u: 0 for u in dep}).xreplace(given).evalf(), dtype=float).ravel()
    known = {**zero, **given, **dict(zip(dep, np.linalg.solve(A, -b)))}
    return np.array([float(known.get(s, 0.0)) for s in system.states])


def pydy_rows(reference: dict, values: dict, knifeedge_run) -> list:
    """PyDy's rows (one per generator) for the bicycle; ``reference``: knifeedge's converged final state by name
    (q2, q5, q4 and their rates, and q3's); ``values``: the benchmark's parameters by name; ``knifeedge_run()``:
    knifeedge's 10 s at rtol 1e-10, timed between PyDy's runs (the speedup is the ratio of the medians)."""
    from pydy.system import System
    from scipy.integrate import solve_ivp

    ns = kane3_bicycle()
    km = ns["KM"]
    symbols = km.mass_matrix_full.free_symbols | km.forcing_full.free_symbols
    system = System(km, constants={s: values[s.name] for s in sorted(symbols, key=str) if s.name in values})
    x0 = pydy_initial(ns, system, values, 5.0, 0.5)
    p = np.array([system.constants[s] for s in system.constants_symbols], dtype=float)
    names = {ns["q2"]: "q2", ns["q5"]: "q5", ns["q4"]: "q4", ns["u2"]: "q2_dot", ns["u5"]: "q5_dot",
             ns["u3"]: "q3_dot"}
    index = {n: list(system.states).index(s) for s, n in names.items()}
    scale = max(1.0, max(abs(v) for v in reference.values()))
    rows = []
    for generator in PYDY_GENERATORS:
        t0 = _cpu_with_children()
        try:
            with tempfile.TemporaryDirectory() as tmp:
                kwargs = {"tmp_dir": tmp} if generator == "cython" else {}
                rhs = system.generate_ode_function(generator=generator, **kwargs)
        except Exception as exc:  # noqa: BLE001 - a generator that fails is a row that says so
            rows.append({"generator": generator, "failed": f"{type(exc).__name__}: {exc}"[:200]})
            continue
        generate = _cpu_with_children() - t0  # the C compiler runs in child processes
        f = lambda t, x: rhs(x, t, p)  # noqa: E731
        times, ours, run = [], [], None
        for _ in range(5):  # interleaved with knifeedge's run: the ratio sees the same load
            t0 = time.perf_counter()
            run = solve_ivp(f, (0.0, 10.0), x0, method="DOP853", rtol=1e-10, atol=1e-12)
            times.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            for _ in range(KNIFEEDGE_BATCH):
                knifeedge_run()
            ours.append((time.perf_counter() - t0) / KNIFEEDGE_BATCH)
        end = run.y[:, -1]
        rows.append({"generator": generator, "form_cpu_s": ns["form_cpu_s"], "generate_cpu_s": generate,
                     "run_10s_ms": 1e3 * statistics.median(times), "nfev": int(run.nfev),
                     "us_per_eval": 1e6 * statistics.median(times) / run.nfev,
                     "speedup": statistics.median(times) / statistics.median(ours),
                     "error": max(abs(end[index[n]] - reference[n]) for n in reference) / scale})
    return rows


def knifeedge_reference(out: Path) -> tuple:
    """knifeedge's bicycle run at rtol 1e-13 (the converged reference), final state by name; its parameters; and
    its 10 s run at rtol 1e-10 (compiled already)."""
    m = ke.load("whipple_bicycle", path=out)
    p = m.params(m.default_params)
    r = ke.simulate(m, _initial("whipple_bicycle", m), (0.0, 10.0), p, rtol=1e-13, atol=1e-15)
    names = ("q2", "q5", "q4", "q2_dot", "q5_dot", "q3_dot")
    y0 = _initial("whipple_bicycle", m)
    run = lambda: ke.simulate(m, y0, (0.0, 10.0), p, rtol=1e-10, atol=1e-12)  # noqa: E731
    return ({n: float(r.y[m.state_names.index(n), -1]) for n in names}, dict(zip(m.param_names, p.tolist())),
            run)


def _print_pydy(rows: list) -> None:
    for r in rows:
        if "failed" in r:
            print(f"pydy {r['generator']:<15} failed: {r['failed']}", flush=True)
            continue
        print(f"pydy {r['generator']:<15} {'kane':<11} {'':>8} {r['form_cpu_s']:>4.1f} + {r['generate_cpu_s']:.1f} s "
              f"{r['run_10s_ms']:>11.1f} ms {r['error']:>9.1e} {'':>10} ({r['nfev']} evaluations, "
              f"{r['us_per_eval']:.0f} us each; knifeedge {r['speedup']:.0f}x faster, interleaved)", flush=True)


def main(argv=None) -> int:
    import argparse

    ap = argparse.ArgumentParser(prog="python -m benchmarks.mechanics_peers", description=__doc__.split("\n")[0])
    ap.add_argument("--pydy-only", action="store_true", help="only the bicycle: knifeedge's row and PyDy's")
    args = ap.parse_args(argv)
    try:
        import pydy
        note = f"pydy {pydy.__version__}: its rows are the bicycle of sympy's test_kane3.py, one per generator"
    except ImportError:
        pydy = None
        note = "pydy is not installed (pip install pydy cython): its rows are skipped"
    print(note)
    print(f"{'model':<20} {'elimination':<11} {'rhs ops':>8} {'derive CPU':>11} {'10 s at 1e-10':>14} "
          f"{'error':>9} {'ref. error':>10}")
    names = ("whipple_bicycle",) if args.pydy_only else ("sympy_rolling_disc", "differential_drive", "whipple_bicycle")
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            r = row(name, Path(tmp))
            print(f"{r['model']:<20} {r['elimination']:<11} {r['rhs_ops']:>8} {r['derive_cpu_s']:>9.1f} s "
                  f"{r['run_10s_ms']:>11.1f} ms {r['error']:>9.1e} {r['reference_error']:>10.1e} ({r['nfev']} "
                  f"evaluations, {1e3 * r['run_10s_ms'] / r['nfev']:.2f} us each)", flush=True)
        if pydy is not None:
            _print_pydy(pydy_rows(*knifeedge_reference(Path(tmp))))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
