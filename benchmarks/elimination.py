"""Numeric vs. symbolic elimination of the multipliers (issue 22 item 3): derive time and cost per evaluation.

``python -m benchmarks.elimination [--symbolic-pendulum]`` derives examples/rolling_disk.py and
examples/disk_pendulum.py with ``knifeedge derive`` into a temporary folder (the pendulum also forced to the closed
form with ``--symbolic-pendulum``: minutes), then times ``rhs_into`` in a compiled loop: the median of 9 repeats of
200,000 calls each, every ratio measured in this one run.  It also says whether ``derivation/ir_emit.py`` wrote the
right-hand side as IR or fell back to numba's compilation.
"""
from __future__ import annotations

import dataclasses
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from numba import njit

import knifeedge as ke

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
CALLS, REPEATS = 200_000, 9


@njit
def _loop(f, s, p, ds, n):
    acc = 0.0
    for i in range(n):
        s[0] += 1e-12 * i  # the state changes, so nothing is hoisted out of the loop
        f(0.0, s, p, ds)
        acc += ds[-1]
    return acc


def per_call_ns(model, s, p) -> float:
    f, ds = model.module.rhs_into, np.empty(len(s))
    _loop(f, s.copy(), p, ds, 10)
    times = []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        _loop(f, s.copy(), p, ds, CALLS)
        times.append((time.perf_counter() - t0) / CALLS * 1e9)
    return statistics.median(times)


def _ir(model) -> str:
    """Whether the module carries its right-hand side as LLVM IR (``derivation/ir_emit.py``) or numba compiles it."""
    return "IR" if "rhs_q_into" in getattr(model.module, "LLVM_IR", {}) else "numba (not straight-line)"


def main(argv=None) -> int:
    from knifeedge.derive import emit
    from knifeedge.cli import main as cli_main
    from knifeedge.derive.cli import derive_specs
    from knifeedge.derive.cli import load_specs

    argv = sys.argv[1:] if argv is None else argv
    out = Path(tempfile.mkdtemp(prefix="elimination"))
    for name in ("rolling_disk", "disk_pendulum"):
        t0 = time.perf_counter()
        assert cli_main(["derive", str(EXAMPLES / f"{name}.py"), "--out", str(out)]) == 0
        print(f"knifeedge derive examples/{name}.py: {time.perf_counter() - t0:.1f} s")
    models = {"disk (symbolic)": ke.load("rolling_disk", path=out), "disk with pendulum (numeric)":
              ke.load("disk_pendulum", path=out)}
    disk = load_specs(EXAMPLES / "rolling_disk.py")[0]
    emit.write_all(out, derive_specs([dataclasses.replace(disk, name="disk_numeric", elimination="numeric")]),
                   registry=False)
    models["disk (numeric)"] = ke.load("disk_numeric", path=out)
    if "--symbolic-pendulum" in argv:
        pend = load_specs(EXAMPLES / "disk_pendulum.py")[0]
        t0 = time.perf_counter()
        emit.write_all(out, derive_specs([dataclasses.replace(pend, name="pendulum_symbolic",
                                                              elimination="symbolic")]), registry=False)
        print(f"disk with pendulum, closed form: derived in {time.perf_counter() - t0:.0f} s")
        models["disk with pendulum (symbolic)"] = ke.load("pendulum_symbolic", path=out)
    ns = {}
    for label, m in models.items():
        s = np.array([m.default_state.get(k, 0.3) for k in m.state_names]) + 0.1
        ns[label] = per_call_ns(m, s, m.params(m.default_params))
        print(f"{label:32s} rhs_into {ns[label]:8.0f} ns/call, {m.module.OP_COUNTS['rhs']:5d} operations, "
              f"{m.module.ELIMINATION}; {_ir(m)}")
    print(f"ratio disk with pendulum (numeric) / disk (symbolic): "
          f"{ns['disk with pendulum (numeric)'] / ns['disk (symbolic)']:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
