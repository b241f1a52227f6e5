"""The cost of run-time inputs given as samples (issue 22 item 1): one run per interval between samples.

``python -m benchmarks.inputs`` derives tests/models/controlled_sleigh.py (a sleigh steered by a torque ``tau``
given at run time) into a temporary folder and times ``knifeedge.simulate`` over ``t in [0, 100]`` with ``tau``
given as a constant, and as 10, 100 and 1000 samples of ``0.3 sin(t/5)`` (piecewise linear: the run restarts at
each sample time), on DOP853 at rtol 1e-10 with 201 output times and with every step stored, and on RK4 with
``h = 0.01``.  Median of 7 repeats, all interleaved in one run; the kernels are compiled before the timing.
"""
from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import knifeedge as ke

MODEL = Path(__file__).resolve().parents[1] / "tests" / "models" / "controlled_sleigh.py"
REPEATS = 7
T1 = 100.0


def _cases() -> dict:
    out = {"constant": 0.3}
    for n in (10, 100, 1000):
        ts = np.linspace(0.0, T1, n)
        out[f"{n} samples"] = (ts, 0.3 * np.sin(ts / 5))
    return out


def main(argv=None) -> int:
    from knifeedge.cli import main as cli_main

    with tempfile.TemporaryDirectory() as folder:
        assert cli_main(["derive", str(MODEL), "--out", folder]) == 0
        model = ke.load("controlled_sleigh", path=folder)
        p, y0 = model.params(a=0.5, k=0.8, c=0.1), [0.1, 0.0]
        runs = {"DOP853, 201 outputs": dict(method="DOP853", rtol=1e-10, t_eval=np.linspace(0, T1, 201)),
                "DOP853, every step": dict(method="DOP853", rtol=1e-10),
                "RK4 h=0.01, 201 outputs": dict(method="RK4", h=0.01, t_eval=np.linspace(0, T1, 201))}
        cases = _cases()
        times = {(r, c): [] for r in runs for c in cases}
        steps = {}
        for kw in runs.values():  # compile the kernels
            ke.simulate(model, y0, (0, T1), p, inputs={"tau": 0.3}, **kw)
        for _ in range(REPEATS):
            for r, kw in runs.items():
                for c, value in cases.items():
                    t0 = time.perf_counter()
                    res = ke.simulate(model, y0, (0, T1), p, inputs={"tau": value}, **kw)
                    times[(r, c)].append(time.perf_counter() - t0)
                    steps[(r, c)] = res.nsteps
        print("| run | input | time | per interval | steps |")
        print("|---|---|---|---|---|")
        for r in runs:
            base = statistics.median(times[(r, "constant")])
            for c in cases:
                med = statistics.median(times[(r, c)])
                n_int = 1 if c == "constant" else int(c.split()[0]) - 1
                extra = "" if c == "constant" else f"{(med - base) / n_int * 1e6:.0f} us"
                print(f"| {r} | {c} | {med * 1e3:.2f} ms ({med / base:.1f}x) | {extra} | {steps[(r, c)]} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
