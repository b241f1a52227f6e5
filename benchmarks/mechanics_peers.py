"""The peer models of ``sympy.physics.mechanics`` through knifeedge (issue 23): derive and run times, errors.

``python -m benchmarks.mechanics_peers`` (part of ``make bench``) takes the models of tests/models written as
their authors wrote them -- SymPy's test_kane5.py rolling disc, pydy#127's differential-drive robot, and the
Whipple bicycle of SymPy's test_kane3.py with the coordinates a Lagrangian needs -- and for each measures

* the CPU time of ``knifeedge derive FILE --out DIR`` in a child process (``from_mechanics``, the engine, the
  symmetry check at a general pose, the emitted module): the time to form the equations and generate code;
* the time of 10 s of motion at rtol 1e-10 (``ke.simulate``, its default compiled DOP853; compiled beforehand,
  median of 5 runs) and the largest error of its final state against a converged reference (the same run at
  rtol 1e-13; its own distance from a run at rtol 1e-12 is printed beside it).

PyDy (``ODEFunctionGenerator``) is the field's own path; it is optional and skipped with a note when absent.
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
            "rhs_ops": m.module.OP_COUNTS["rhs"], "elimination": m.module.ELIMINATION}


def main() -> int:
    try:
        import pydy  # noqa: F401
        note = "pydy installed: its ODEFunctionGenerator rows are not written yet"
    except ImportError:
        note = "pydy is not installed (pip install pydy cython): its rows are skipped"
    print(note)
    print(f"{'model':<20} {'elimination':<11} {'rhs ops':>8} {'derive CPU':>11} {'10 s at 1e-10':>14} "
          f"{'error':>9} {'ref. error':>10}")
    with tempfile.TemporaryDirectory() as tmp:
        for name in ("sympy_rolling_disc", "differential_drive", "whipple_bicycle"):
            r = row(name, Path(tmp))
            print(f"{r['model']:<20} {r['elimination']:<11} {r['rhs_ops']:>8} {r['derive_cpu_s']:>9.1f} s "
                  f"{r['run_10s_ms']:>11.1f} ms {r['error']:>9.1e} {r['reference_error']:>10.1e}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
