"""Reversal times of the two-mode ``full`` model against ``ke.reversal_time`` (averaged theory).

Paper's two-mode scene: ell/L = 1/2, D/ell = 1/2, alpha = pi/4, tilts 1e-3 (rates 0),
spin rates phi_dot0 from -0.5 to 0.5 (omega_1 = 1).  Every simulation is run at two
tolerances (DOP853, rtol 1e-13 and 3e-14, atol 1e-30: the decayed mode reaches
~1e-15) and the convergence (largest change of a reversal time) is printed with the
comparison.  ``python -m benchmarks.reversal_theory``.
"""
from __future__ import annotations

import math
import time

import numpy as np

import knifeedge as ke

P = dict(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4)


def compare(phi_dot0: float, n_rev: int = 4) -> dict:
    m = ke.load("two_mode", "full")
    p = m.params(**P)
    y0 = [1e-3, 1e-3, 0.0, 0.0, phi_dot0]
    pred = ke.reversal_time(m, p, y0)
    t_end = pred.first + (n_rev - 0.5) * pred.interval
    runs = [ke.simulate(m, y0, (0.0, t_end), p, method="DOP853", rtol=rtol, atol=1e-30).reversal_times
            for rtol in (1e-13, 3e-14)]
    n = min(len(r) for r in runs)
    conv = float(np.max(np.abs(runs[0][:n] - runs[1][:n]))) if n else math.nan
    rev = runs[1]
    iv = np.diff(rev)
    return {"phi_dot0": phi_dot0, "first_pred": pred.first, "first_sim": rev[0],
            "interval_pred": pred.interval, "intervals_sim": iv, "convergence": conv,
            "first_err": (pred.first - rev[0]) / rev[0],
            "interval_err": float(np.max(np.abs(pred.interval - iv) / iv)) if iv.size else math.nan}


def main() -> None:
    print(f"{'phi0':>6} {'first sim':>10} {'pred':>10} {'err':>9} | {'intervals sim':>28} {'pred':>9} {'max err':>9} | conv")
    for phi0 in (0.02, 0.05, 0.1, -0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5):
        t = time.perf_counter()
        r = compare(phi0)
        print(f"{phi0:6.2f} {r['first_sim']:10.3f} {r['first_pred']:10.3f} {r['first_err']:+9.2e} | "
              f"{np.array2string(r['intervals_sim'], precision=1):>28} {r['interval_pred']:9.2f} "
              f"{r['interval_err']:9.2e} | {r['convergence']:.1e}  ({time.perf_counter() - t:.1f} s)", flush=True)


if __name__ == "__main__":
    main()
