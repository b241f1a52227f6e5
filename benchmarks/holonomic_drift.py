"""A holonomic constraint along a long run (issue 22 item 2): the Cartesian pendulum over 1000 periods.

``python -m benchmarks.holonomic_drift [rtol ...]`` derives the pendulum of tests/test_holonomic.py
(``L = (x_dot^2 + y_dot^2)/2 - g y``, rod ``x^2 + y^2 = l^2``, ``y`` dependent) into a temporary folder and runs
it, with each ``holonomic_rate`` of :data:`RATES`, from ``theta0 = 1`` for 1000 exact periods ``T = 4 sqrt(l/g) K(sin^2(theta0/2))`` (scipy.special.ellipk) with
DOP853.  It prints, per tolerance: the largest ``|x^2 + y^2 - l^2| / l^2`` along the run and at its end, the worst
relative error of a measured period (two crossings of ``x = 0``) against ``T``, and the energy's relative swing.
"""
from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import sympy as sp
from scipy.special import ellipk

import knifeedge as ke
from knifeedge.derive import ModelSpec, emit
from knifeedge.derive.cli import derive_specs

G, L, THETA0, PERIODS = 9.81, 0.7, 1.0, 1000


g, l = sp.symbols("g l", positive=True)
#: ``holonomic_rate`` of each variant: 0 (the differentiated constraint alone), the default 1, the pendulum's
#: small-oscillation frequency, and ten times it
RATES = {"rate0": 0, "rate1": 1, "rate_w": sp.sqrt(g / l), "rate_10w": 10 * sp.sqrt(g / l)}


def pendulum(name: str = "cartesian_pendulum", rate=1) -> ModelSpec:
    x, y, x_dot, y_dot = sp.symbols("x y x_dot y_dot", real=True)
    return ModelSpec(name=name, coordinates=(x, y), velocities=(x_dot, y_dot),
                     lagrangian=(x_dot**2 + y_dot**2) / 2 - g * y, constraints=(), holonomic=(x**2 + y**2 - l**2,),
                     holonomic_labels=("rod",), holonomic_rate=rate, dependent=(y,), params=(g, l), reversal_events=(x,))


def run(model, rtol: float) -> dict:
    period = 4 * np.sqrt(L / G) * ellipk(np.sin(THETA0 / 2) ** 2)
    y0 = {"x": L * np.sin(THETA0), "y": -L * np.cos(THETA0), "x_dot": 0.0}
    p = model.params(g=G, l=L)
    t0 = time.perf_counter()
    r = ke.simulate(model, y0, (0.0, PERIODS * period), p, rtol=rtol, atol=rtol * 1e-2, max_steps=10**8)
    wall = time.perf_counter() - t0
    res = np.abs(r.holonomic_residual[0]) / L**2
    e = r.energy
    return dict(rtol=rtol, steps=r.nsteps, wall=wall, residual_max=res.max(), residual_end=res[-1],
                period_err=np.max(np.abs(2 * np.diff(r.reversal_times) / period - 1)),
                energy_swing=np.ptp(e) / (G * L), crossings=r.reversal_times.size)


def main(argv=None) -> int:
    tols = [float(a) for a in (argv if argv is not None else sys.argv[1:])] or [1e-8, 1e-11]
    with tempfile.TemporaryDirectory() as out:
        emit.write_all(Path(out), derive_specs([pendulum(k, v) for k, v in RATES.items()]), registry=False)
        models = {k: ke.load(k, path=out) for k in RATES}
        for rtol, k in ((rtol, k) for rtol in tols for k in RATES):
            r = run(models[k], rtol)
            print(f"holonomic_rate {RATES[k]}, rtol {r['rtol']:.0e}: {r['steps']} steps, {r['wall']:.2f} s; |f|/l^2 max {r['residual_max']:.2e}, "
                  f"end {r['residual_end']:.2e}; period rel. err {r['period_err']:.2e} ({r['crossings']} crossings); "
                  f"energy swing / (g l) {r['energy_swing']:.2e}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
