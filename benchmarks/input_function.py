"""The cost per evaluation of a function input on the compiled methods (issue 22 item 1).

``python -m benchmarks.input_function`` derives tests/models/controlled_sleigh.py (a sleigh steered by a torque
``tau`` given at run time) into a temporary folder and runs it with the same constant torque given two ways:
the number 0.3 (the model's own compiled right-hand side, which reads the slots of ``p``) and a ``numba.njit``
function returning 0.3 (the right-hand side that writes the function's value into ``q`` at every evaluation,
``knifeedge.inputs.driven``).  Both runs take the same steps; it prints, per method, the CPU nanoseconds per
right-hand-side evaluation of each (median of the repeats, all interleaved in one process, the kernels
compiled before the timing) and their ratio.
"""
from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from numba import njit

import knifeedge as ke

MODEL = Path(__file__).resolve().parents[1] / "tests" / "models" / "controlled_sleigh.py"
REPEATS = 15
T1 = 400.0
RUNS = {"DOP853": dict(method="DOP853", rtol=1e-12, atol=1e-14, max_step=0.01), "RK4": dict(method="RK4", h=0.002),
        "gauss4": dict(method="gauss4", h=0.004)}


@njit
def constant_torque(t):
    return 0.3


def main(argv=None) -> int:
    from knifeedge.cli import main as cli_main

    with tempfile.TemporaryDirectory() as folder:
        assert cli_main(["derive", str(MODEL), "--out", folder]) == 0
        model = ke.load("controlled_sleigh", path=folder)
        p, y0 = model.params(a=0.5, k=0.8, c=0.1), [0.1, 0.0]
        cases = {"number": 0.3, "function": constant_torque}
        run = lambda kw, given: ke.simulate(model, y0, (0.0, T1), p, t_eval=np.array([T1]),  # noqa: E731
                                            inputs={"tau": given}, **kw)
        nfev = {}
        for name, kw in RUNS.items():  # compile the kernels; the same steps both ways
            one, two = run(kw, 0.3), run(kw, constant_torque)
            assert one.nfev == two.nfev and np.allclose(one.y, two.y, rtol=1e-13, atol=0), name
            nfev[name] = one.nfev
        times = {(r, c): [] for r in RUNS for c in cases}
        for _ in range(REPEATS):
            for r, kw in RUNS.items():
                for c, given in cases.items():
                    t = time.process_time()
                    run(kw, given)
                    times[r, c].append((time.process_time() - t) / nfev[r] * 1e9)
    print(f"ns of CPU per evaluation, median of {REPEATS} (constant torque 0.3 as a number / as a numba function)")
    for r in RUNS:
        a, b = (statistics.median(times[r, c]) for c in cases)
        print(f"  {r:7s} evaluations {nfev[r]:>8d}   number {a:7.1f}   function {b:7.1f}   ratio {b / a:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
