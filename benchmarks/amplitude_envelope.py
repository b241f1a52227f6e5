"""Envelope of theta(t) and spin rate of the reduced/full single-mode models against the closed form an1/an2.

Paper Fig. ``amplitudes``: A0 = 0.1 sqrt(g/ell), ell/L = 1, D/ell = 1.  For
each A0/omega the initial tilt is theta0 = A0/100 (theta_dot0 = 0) and the spin
phi_dot0 = sqrt(A0^2 - (g ell/L^2) theta0^2), so that A0 is the asymptotic
spin of the corrected an1.  Deviations are maxima over t in [0, 3 t_R]:
envelope sqrt(theta^2 + theta_dot^2/omega^2) against the corrected an2 (relative
to its maximum A0 L/sqrt(g ell)) and phi_dot against the corrected an1
(relative to A0).  ``python -m benchmarks.amplitude_envelope``.
"""
from __future__ import annotations

import math

import numpy as np

import knifeedge as ke

G = ELL = L = D = 1.0


def closed_form(t, t_r, a0):
    x = a0 * D * (t - t_r) / (2 * ELL)
    return a0 * L / math.sqrt(G * ELL) / np.cosh(x), -a0 * np.tanh(x)


def deviations(fidelity: str, a0: float) -> dict:
    m = ke.load("single_mode", fidelity)
    p = m.params(g=G, ell=ELL, L=L, D=D)
    theta0 = a0 / 100
    y0 = [theta0, 0.0, math.sqrt(a0**2 - G * ELL / L**2 * theta0**2)]
    pred = ke.reversal_time(m, p, y0)
    t_end = 3 * pred.first
    t = np.linspace(0.0, t_end, 20001)
    r = ke.simulate(m, y0, (0.0, t_end), p, rtol=1e-11, atol=1e-14, t_eval=t)
    omega = math.sqrt(G / ELL)
    env = np.hypot(r["theta"], r["theta_dot"] / omega)
    a_th, a_ph = closed_form(r.t, pred.first, a0)
    return {
        "a0": a0,
        "envelope": float(np.max(np.abs(env - a_th)) / (a0 * L / math.sqrt(G * ELL))),
        "spin": float(np.max(np.abs(r["phi_dot"] - a_ph)) / a0),
        "reversal_rel": float((r.reversal_times[0] - pred.first) / r.reversal_times[0]),
        "t_r_measured": float(r.reversal_times[0]),
        "t_r_predicted": pred.first,
    }


def main() -> None:
    for fid in ("reduced", "full"):
        rows = [deviations(fid, a0) for a0 in (0.025, 0.05, 0.1, 0.2)]
        for row in rows:
            print(f"{fid:8s} A0/omega={row['a0']:<6} envelope {row['envelope']:.3e}  spin {row['spin']:.3e}  "
                  f"t_R {row['t_r_measured']:.3f} vs {row['t_r_predicted']:.3f} ({row['reversal_rel']:+.2e})")
        a = np.log([r["a0"] for r in rows])
        for key in ("envelope", "spin"):
            slope = np.polyfit(a, np.log([r[key] for r in rows]), 1)[0]
            print(f"{fid:8s} {key}: deviation ~ (A0/omega)^{slope:.2f}")


if __name__ == "__main__":
    main()
