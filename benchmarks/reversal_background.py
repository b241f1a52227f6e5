"""Reversal intervals under a noise background: ``knifeedge.background`` against noisy simulations.

Two-mode ``full`` model, paper scene (ell/L = 1/2, D/ell = 1/2, alpha = pi/4, tilts 1e-3,
phi_dot0 = 0.1), white noise ``sigma`` on both tilt accelerations, RK4 h = 0.05, 32 seeds.
For each interval index the mean and its standard error are printed next to the
prediction ``noisy_intervals`` (seeds accumulate: T_{2j-1} = T_{2j} = T(epsilon sqrt(j)))
and the single-floor prediction ``reversal_time(background=epsilon)``.
``python -m benchmarks.reversal_background``.
"""
from __future__ import annotations

import math
import time

import numpy as np

import knifeedge as ke
from knifeedge.background import noise_floor, noisy_intervals, simulate_noisy

P = dict(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4)
Y0 = [1e-3, 1e-3, 0.0, 0.0, 0.1]


def main(n_seeds: int = 32, n_intervals: int = 6) -> None:
    m = ke.load("two_mode", "full")
    p = m.params(**P)
    clean = ke.reversal_time(m, p, Y0)
    print(f"noise-free: first {clean.first:.2f}, interval {clean.interval:.2f}")
    for sigma in (1e-7, 1e-9, 1e-11, 1e-13):
        t = time.perf_counter()
        eps = noise_floor(m, p, clean, sigma)
        pred = noisy_intervals(m, p, Y0, sigma, n_intervals)
        floor = ke.reversal_time(m, p, Y0, background=eps).interval
        t_end = clean.first + (n_intervals + 0.5) * clean.interval
        runs = [np.diff(simulate_noisy(m, Y0, t_end, p, sigma, seed=s, max_reversals=n_intervals + 1))
                for s in range(n_seeds)]
        runs = np.array([r[:n_intervals] for r in runs if len(r) >= n_intervals])
        mean, err = runs.mean(0), runs.std(0, ddof=1) / math.sqrt(len(runs))
        print(f"sigma {sigma:.0e}: epsilon (fast mode) {eps[0]:.2e}, single floor {floor:.1f}, "
              f"{len(runs)} runs, {time.perf_counter() - t:.1f} s")
        for k in range(n_intervals):
            print(f"   interval {k + 1}: simulated {mean[k]:8.1f} +- {err[k]:4.1f}   predicted {pred[k]:8.1f}"
                  f"   ({(mean[k] - pred[k]) / err[k]:+.1f} s.e.)")


if __name__ == "__main__":
    main()
