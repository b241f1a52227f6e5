"""Reference solutions of known accuracy.

No closed form exists for these scenes, so the reference is the 3-stage
Gauss--Legendre method (order 6, compensated summation) at two small steps
h and h/2: their difference divided by 2^6 - 1 estimates the error of the
finer one (Richardson), and DOP853 at its tightest tolerance (rtol 3e-14,
no absolute floor) through SciPy's own implementation is a check by an
independent code and method.  All three numbers are reported.
"""
from __future__ import annotations

import numpy as np

import knifeedge as ke


def _run(scene, method, **kw):
    r = ke.simulate(scene.model, scene.y, (0.0, scene.t_end), scene.p, method=method, t_eval=[scene.t_end], **kw)
    if not r.success:
        raise RuntimeError(f"reference run {method} {kw} failed: {r.message}")
    return r.y[:, -1], r.reversal_times


def state_error(y, ref):
    return float(np.max(np.abs(y - ref)) / np.max(np.abs(ref)))


def reversal_error(times, ref_times):
    """Largest relative error of the reversal times; inf when the count differs."""
    if times is None:
        return float("nan")
    if len(times) != len(ref_times):
        return float("inf")
    if len(ref_times) == 0:
        return 0.0
    return float(np.max(np.abs(np.asarray(times) - ref_times) / ref_times))


def reference(scene, h: float, scipy_check: bool = True) -> dict:
    """Reference final state and reversal times of ``scene`` with their convergence evidence."""
    y1, r1 = _run(scene, "gauss6", h=h)
    y2, r2 = _run(scene, "gauss6", h=h / 2)
    out = {
        "method": f"gauss6 at h = {h / 2:g} (Richardson against h = {h:g})",
        "y_end": y2, "reversal_times": r2,
        "energy0": float(scene.model.energy(scene.y, scene.p)),
        "richardson_state_error": state_error(y1, y2) / 63.0,
        "richardson_reversal_error": reversal_error(r1, r2) / 63.0,
    }
    if scipy_check:
        y3, r3 = _run(scene, "scipy:DOP853", rtol=3e-14, atol=1e-30)
        out["scipy_dop853_state_difference"] = state_error(y3, y2)
        out["scipy_dop853_reversal_difference"] = reversal_error(r3, r2)
    return out


def perturbation_spread(scene, h: float, relative: float = 1e-12) -> dict:
    """How far the reference's reversal times move when the initial state moves by round-off.

    Each component of the initial state is multiplied by ``1 + relative`` in
    turn (the spin rate and tilts; a zero component is shifted by
    ``relative``) and the scene rerun with the reference's method.  The
    largest relative shift of each reversal is the accuracy to which the
    problem itself fixes it in double precision: a reference cannot be
    trusted beyond it, whatever its Richardson estimate says.
    """
    base = _run(scene, "gauss6", h=h)[1]
    shifts = np.zeros(len(base))
    for i in range(scene.y.size):
        y = scene.y.copy()
        y[i] = y[i] * (1.0 + relative) if y[i] != 0.0 else relative
        r = ke.simulate(scene.model, y, (0.0, scene.t_end), scene.p, method="gauss6", h=h, t_eval=[scene.t_end])
        if len(r.reversal_times) != len(base):
            shifts[:] = np.inf
            break
        shifts = np.maximum(shifts, np.abs(r.reversal_times - base) / base)
    return {"relative_perturbation": relative, "max_relative_shift": shifts.tolist()}
