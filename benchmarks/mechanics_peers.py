"""The peer models of ``sympy.physics.mechanics`` through knifeedge (issue 23): derive and run times, errors.

``python -m benchmarks.mechanics_peers`` (part of ``make bench``) takes the models of tests/models written as
their authors wrote them -- SymPy's test_kane5.py rolling disc, pydy#127's differential-drive robot, and the
Whipple bicycle of SymPy's test_kane3.py with the coordinates a Lagrangian needs -- and for each measures

* the CPU time of ``knifeedge derive FILE --out DIR`` in a child process (``from_mechanics``, the engine, the
  symmetry check at a general pose, the emitted module): the time to form the equations and generate code;
* the CPU time of 10 s of motion at rtol 1e-10 (``ke.simulate``, its default compiled DOP853; compiled beforehand,
  median of :data:`ROUNDS` batches) and the largest error of its final state against a converged reference (the
  same run at rtol 1e-13; its own distance from a run at rtol 1e-12 is printed beside it); "fixed" is the CPU time
  of a run over 1 ms (a few steps): what ``simulate`` costs around its compiled kernel.

PyDy (``System.generate_ode_function``) is the field's own path; it is optional and skipped with a note when
absent.  Its rows are the Whipple bicycle as SymPy's ``test_kane3.py`` writes it for Kane's method (the test's own
source, run up to its ``kanes_equations``: the rear contact fixed, the wheels' angles left out; the same four bodies
as tests/models/whipple_bicycle.py and the same names, so the benchmark's parameters of that file apply): the time to
form Kane's equations (``kanes_equations``, CRAMER's rule for the dependent speeds, as the test), to generate and
compile the right-hand side, and 10 s of motion from the same state for each of :data:`PYDY_RUNS` (a generator, an
integrator -- ``odeint`` as PyDy's ``System.integrate`` calls it, or ``solve_ivp``'s DOP853 -- and a tolerance).

At equal error: each PyDy run's error against knifeedge's converged reference (rtol 1e-13) picks knifeedge's
DOP853 tolerance of nearest error among :data:`KNIFEEDGE_RTOLS` (the two errors are printed side by side); then
:data:`ROUNDS` interleaved rounds (one PyDy run, then a batch of knifeedge's matched run: the same load), medians of
CPU time (``time.process_time``; the speedup) and of wall time (in parentheses: on a shared machine it also counts
the waits for a core).
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
    go = lambda span=span: ke.simulate(m, y0, span, p, rtol=1e-10, atol=1e-12)  # noqa: E731
    run = go()  # compiles
    times = [clocked(go, KNIFEEDGE_BATCH)[1] for _ in range(ROUNDS)]
    fixed = [clocked(lambda: go((0.0, 1e-3)), 10 * KNIFEEDGE_BATCH)[1] for _ in range(ROUNDS)]
    ref = ke.simulate(m, y0, span, p, rtol=1e-13, atol=1e-15)
    ref12 = ke.simulate(m, y0, span, p, rtol=1e-12, atol=1e-14)
    scale = np.maximum(1.0, np.abs(ref.y[:, -1]))
    return {"model": name, "derive_cpu_s": cpu, "run_10s_ms": 1e3 * statistics.median(times),
            "fixed_ms": 1e3 * statistics.median(fixed),
            "error": float(np.max(np.abs(run.y[:, -1] - ref.y[:, -1]) / scale)),
            "reference_error": float(np.max(np.abs(ref12.y[:, -1] - ref.y[:, -1]) / scale)),
            "rhs_ops": m.module.OP_COUNTS["rhs"], "elimination": m.module.ELIMINATION, "nfev": int(run.nfev)}


#: knifeedge's 10 s runs timed together between two of PyDy's (one is ~1 ms: alone it is a scheduler's time slice)
KNIFEEDGE_BATCH = 20
#: knifeedge's relative tolerances (DOP853, atol = rtol / 100) among which each PyDy run's equal-error match is found
KNIFEEDGE_RTOLS = (1e-10, 3e-10, 1e-9, 2e-9, 3e-9, 5e-9, 1e-8)
#: PyDy's runs: (generator, integrator, rtol), atol = rtol / 100.  "odeint" is what PyDy's ``System.integrate``
#: calls by default (SciPy's ``odeint``, LSODA; Fortran steps, PyDy's fastest path); "DOP853" SciPy's ``solve_ivp``
#: with knifeedge's method.  ``theano`` is not maintained; ``cython`` needs a C compiler.
PYDY_RUNS = (("cython", "odeint", 1e-10), ("cython", "odeint", 1e-12), ("cython", "DOP853", 1e-10),
             ("lambdify", "odeint", 1e-10))
#: interleaved rounds (each: one PyDy run, then knifeedge's matched batch); the medians over them are reported
ROUNDS = 7


def _cpu_with_children() -> float:
    """CPU seconds of this process and its finished children (a compiler run by a code generator)."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def clocked(fn, repeat: int = 1) -> tuple:
    """``(wall, cpu)`` seconds of one ``fn()`` (the mean over ``repeat`` calls): ``time.perf_counter`` and
    ``time.process_time``.  On a shared machine the wall time also counts the time the process waits for a core
    (2 cores, load 7-11: 1.5-2.5x the CPU time, changing from one second to the next); the CPU time does not."""
    w, c = time.perf_counter(), time.process_time()
    for _ in range(repeat):
        fn()
    return (time.perf_counter() - w) / repeat, (time.process_time() - c) / repeat


def matched(errors: dict, target: float) -> float:
    """The tolerance (a key of ``errors``, tolerance -> error) whose error is nearest ``target`` in ratio."""
    return min(errors, key=lambda rtol: abs(np.log(errors[rtol] / target)))


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


def _pydy_integrator(rhs, p: np.ndarray, x0: np.ndarray, integrator: str, rtol: float):
    """A 10 s run of PyDy's right-hand side: ``fn() -> (final state, evaluations)``."""
    from scipy.integrate import odeint, solve_ivp

    if integrator == "odeint":  # as System.integrate calls it: odeint(evaluate_ode_function, x0, times, args=...)
        def run():
            y, info = odeint(rhs, x0, [0.0, 10.0], args=(p,), rtol=rtol, atol=rtol / 100, full_output=True,
                             mxstep=10**6)
            return y[-1], int(info["nfe"][-1])
        return run

    def run():
        r = solve_ivp(lambda t, x: rhs(x, t, p), (0.0, 10.0), x0, method=integrator, rtol=rtol, atol=rtol / 100)
        return r.y[:, -1], int(r.nfev)
    return run


def pydy_system(values: dict) -> tuple:
    """SymPy's test_kane3.py bicycle as a PyDy ``System`` with the benchmark's parameters; its 10-state initial
    state (5 m/s, lean rate 0.5 rad/s), parameter array, the index of each of knifeedge's states in PyDy's, and the
    CPU seconds of forming Kane's equations."""
    from pydy.system import System

    ns = kane3_bicycle()
    km = ns["KM"]
    symbols = km.mass_matrix_full.free_symbols | km.forcing_full.free_symbols
    system = System(km, constants={s: values[s.name] for s in sorted(symbols, key=str) if s.name in values})
    x0 = pydy_initial(ns, system, values, 5.0, 0.5)
    p = np.array([system.constants[s] for s in system.constants_symbols], dtype=float)
    names = {ns["q2"]: "q2", ns["q5"]: "q5", ns["q4"]: "q4", ns["u2"]: "q2_dot", ns["u5"]: "q5_dot",
             ns["u3"]: "q3_dot"}
    index = {n: list(system.states).index(s) for s, n in names.items()}
    return system, x0, p, index, ns["form_cpu_s"]


def pydy_rows(ours) -> list:
    """PyDy's rows (one per entry of :data:`PYDY_RUNS`) against knifeedge at equal error; ``ours``: a
    :class:`KnifeedgeBicycle`.

    Each PyDy run's error against knifeedge's converged reference picks knifeedge's tolerance of nearest error
    (:func:`matched`); then :data:`ROUNDS` rounds, each one PyDy run followed by a batch of knifeedge's matched run
    (same load), and the speedups are the ratios of the medians, of CPU time and of wall time.
    """
    system, x0, p, index, form_cpu = pydy_system(ours.values)
    generated, rows = {}, []
    for generator, integrator, rtol in PYDY_RUNS:
        if generator not in generated:
            t0 = _cpu_with_children()
            try:
                with tempfile.TemporaryDirectory() as tmp:
                    kwargs = {"tmp_dir": tmp} if generator == "cython" else {}
                    generated[generator] = (system.generate_ode_function(generator=generator, **kwargs),
                                            _cpu_with_children() - t0)  # the C compiler runs in child processes
            except Exception as exc:  # noqa: BLE001 - a generator that fails is a row that says so
                generated[generator] = (None, f"{type(exc).__name__}: {exc}"[:200])
        rhs, generate = generated[generator]
        row = {"generator": generator, "integrator": integrator, "rtol": rtol}
        if rhs is None:
            rows.append({**row, "failed": generate})
            continue
        pydy = _pydy_integrator(rhs, p, x0, integrator, rtol)
        end, nfev = pydy()  # warm
        error = ours.error({n: end[i] for n, i in index.items()})
        our_rtol = matched(ours.errors, error)
        theirs, mine = [], []
        for _ in range(ROUNDS):
            theirs.append(clocked(pydy))
            mine.append(clocked(ours.run(our_rtol), KNIFEEDGE_BATCH))
        wall, cpu = (statistics.median(x[i] for x in theirs) for i in (0, 1))
        our_wall, our_cpu = (statistics.median(x[i] for x in mine) for i in (0, 1))
        rows.append({**row, "form_cpu_s": form_cpu, "generate_cpu_s": generate, "nfev": nfev, "error": error,
                     "cpu_ms": 1e3 * cpu, "wall_ms": 1e3 * wall, "us_per_eval": 1e6 * cpu / nfev,
                     "ours_rtol": our_rtol, "ours_error": ours.errors[our_rtol], "ours_nfev": ours.nfev[our_rtol],
                     "ours_cpu_ms": 1e3 * our_cpu, "ours_wall_ms": 1e3 * our_wall,
                     "speedup_cpu": cpu / our_cpu, "speedup_wall": wall / our_wall})
    return rows


class KnifeedgeBicycle:
    """knifeedge's bicycle (derived into ``out``) from the benchmark's state: its converged reference (rtol 1e-13;
    final state by name), its error (as :func:`row`'s) and evaluations at each of :data:`KNIFEEDGE_RTOLS`, its
    parameters by name
    (``values``), and ``run(rtol)``: the 10 s run (compiled already)."""

    NAMES = ("q2", "q5", "q4", "q2_dot", "q5_dot", "q3_dot")

    def __init__(self, out: Path):
        m = self.model = ke.load("whipple_bicycle", path=out)
        self.p = m.params(m.default_params)
        self.y0 = _initial("whipple_bicycle", m)
        self.values = dict(zip(m.param_names, self.p.tolist()))
        end = self.run(1e-13, atol=1e-15)().y[:, -1]
        self.reference = {n: float(end[m.state_names.index(n)]) for n in self.NAMES}
        self.errors, self.nfev = {}, {}
        for rtol in KNIFEEDGE_RTOLS:
            r = self.run(rtol)()
            self.errors[rtol] = self.error({n: r.y[m.state_names.index(n), -1] for n in self.NAMES})
            self.nfev[rtol] = int(r.nfev)

    def error(self, end: dict) -> float:
        """The largest error of a final state (by name) against the reference, each relative to max(1, |value|)."""
        return float(max(abs(end[n] - v) / max(1.0, abs(v)) for n, v in self.reference.items()))

    def run(self, rtol: float, atol: float | None = None):
        m, y0, p = self.model, self.y0, self.p
        atol = rtol / 100 if atol is None else atol
        return lambda: ke.simulate(m, y0, (0.0, 10.0), p, rtol=rtol, atol=atol)


def _print_pydy(rows: list) -> None:
    print(f"{'PyDy generator, integrator':<32} {'rtol':>6} {'error':>8} {'evals':>6} {'CPU ms':>8} {'wall ms':>8}"
          f" | knifeedge {'rtol':>6} {'error':>8} {'evals':>6} {'CPU ms':>7} {'wall ms':>7} | faster CPU (wall)")
    for r in rows:
        name = f"pydy {r['generator']}, {r['integrator']}"
        if "failed" in r:
            print(f"{name:<32} failed: {r['failed']}", flush=True)
            continue
        print(f"{name:<32} {r['rtol']:>6.0e} {r['error']:>8.1e} {r['nfev']:>6} {r['cpu_ms']:>8.1f} "
              f"{r['wall_ms']:>8.1f} | knifeedge {r['ours_rtol']:>6.0e} {r['ours_error']:>8.1e} {r['ours_nfev']:>6} "
              f"{r['ours_cpu_ms']:>7.2f} {r['ours_wall_ms']:>7.2f} | {r['speedup_cpu']:>5.0f}x ({r['speedup_wall']:.0f}x)"
              f"  [form {r['form_cpu_s']:.1f} s + generate {r['generate_cpu_s']:.1f} s CPU; "
              f"{r['us_per_eval']:.1f} us CPU per evaluation]", flush=True)


def main(argv=None) -> int:
    import argparse

    ap = argparse.ArgumentParser(prog="python -m benchmarks.mechanics_peers", description=__doc__.split("\n")[0])
    ap.add_argument("--pydy-only", action="store_true", help="only the bicycle: knifeedge's row and PyDy's")
    args = ap.parse_args(argv)
    try:
        import pydy
        note = f"pydy {pydy.__version__}: its rows are the bicycle of sympy's test_kane3.py at equal error, one per generator and integrator"
    except ImportError:
        pydy = None
        note = "pydy is not installed (pip install pydy cython): its rows are skipped"
    print(note)
    print(f"{'model':<20} {'elimination':<11} {'rhs ops':>8} {'derive CPU':>11} {'10 s at 1e-10':>14} "
          f"{'error':>9} {'ref. error':>10}  (CPU times)")
    names = ("whipple_bicycle",) if args.pydy_only else ("sympy_rolling_disc", "differential_drive", "whipple_bicycle")
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            r = row(name, Path(tmp))
            print(f"{r['model']:<20} {r['elimination']:<11} {r['rhs_ops']:>8} {r['derive_cpu_s']:>9.1f} s "
                  f"{r['run_10s_ms']:>11.1f} ms {r['error']:>9.1e} {r['reference_error']:>10.1e} ({r['nfev']} "
                  f"evaluations, {1e3 * r['run_10s_ms'] / r['nfev']:.2f} us each; fixed {r['fixed_ms']:.3f} ms)",
                  flush=True)
        if pydy is not None:
            _print_pydy(pydy_rows(KnifeedgeBicycle(Path(tmp))))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
