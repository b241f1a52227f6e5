"""A background tilt level: weak random forcing of the tilts, and the floor it sets.

Between reversals the inactive tilt mode decays by many orders of magnitude;
a real rattleback has imperfections and noise that keep it from going below
some background (the paper's "background value of the inactive mode", after
Eq. ``t0``).  :func:`simulate_noisy` imposes one: white noise of intensity
``sigma`` on each tilt acceleration,

    d(theta_i_dot) = (...) dt + sigma dW_i,

integrated with classical RK4 and the noise added after each step (additive
noise: strong order 1/2, exact in distribution for the linear part).

:func:`noise_floor` predicts the amplitude level this sets.  For an oscillator
of frequency ``omega`` the forcing feeds ``<A^2>`` at the rate
``sigma^2/omega^2``; a mode whose amplitude grows as ``exp(Gamma(t))`` after a
reversal at ``t_r`` keeps the noise injected at time ``s`` with the weight
``exp(-2 (Gamma(s) - Gamma(t_r)))``.  Near the reversal ``Gamma`` is quadratic,
``Gamma(s) - Gamma(t_r) = |c_1 c_2| E (s - t_r)^2 / 2`` (slow flow of
:mod:`knifeedge.reversal`), so the mode starts growing from a complex Gaussian
seed with

    <A_seed^2> = (sigma^2/omega_i^2) sqrt(pi / (|c_1 c_2| E)),

and ``E[ln A_seed] = ln sqrt(<A_seed^2>) - gamma_Euler/2``.  The floor that
reproduces the mean interval is therefore
``epsilon_i = sqrt(<A_seed^2>) exp(-gamma_Euler/2)``; the interval scatters
with standard deviation ``pi/sqrt(24)/(|c_i| sqrt(E))``.

Without dissipation the seeds accumulate.  The slow flow is reversible: in
the phase after its growth the mode decays back to exactly the amplitude it
grew from, and the next reversal adds a fresh, independent seed.  The seed
variance after the ``j``-th growth is ``j <A_seed^2>``, and the intervals come
in equal pairs (a growth phase and its time reverse):
``T_{2j-1} = T_{2j} = T(epsilon sqrt(j))`` (:func:`noisy_intervals`).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from . import _validate
from .models import Model
from .reversal import ReversalPrediction, _amplitude_module

EULER_GAMMA = 0.5772156649015329
#: most RK4 steps one :func:`simulate_noisy` call takes (about 1-2 microseconds each, in one compiled loop)
MAX_NOISY_STEPS = 10**7


def noise_floor(model: Model, p, prediction: ReversalPrediction, sigma: float) -> np.ndarray:
    """Background level per tilt set by white noise of intensity ``sigma`` on the tilt accelerations.

    Parameters
    ----------
    model, p : the knife edge and its parameters.
    prediction : :func:`knifeedge.reversal_time` of the noise-free motion (for
        ``E`` and the growth rates).
    sigma : noise intensity (rad/time^(3/2)), ``>= 0``.

    Returns
    -------
    ndarray, shape (n_tilts,)
        ``epsilon_i`` (rad), to pass as ``background`` to ``reversal_time``.
    """
    if not (math.isfinite(_validate.real(sigma, "`sigma`")) and sigma >= 0):
        raise ValueError(f"`sigma` must be a finite number >= 0, got {sigma!r}")
    p = model.check_params(p)
    omega = np.asarray(_amplitude_module(model).frequencies(p))
    c = prediction.growth_rates
    rate = abs(float(np.prod(c))) * prediction.energy
    mean_sq = sigma**2 / omega**2 * math.sqrt(math.pi / rate)
    return np.sqrt(mean_sq) * math.exp(-EULER_GAMMA / 2)


@njit(cache=True)
def _loop(rhs, y0, p, t1, h, noise_index, sigma, spin_index, seed, max_reversals):
    np.random.seed(seed)
    y = y0.copy()
    n = y.size
    rev = np.empty(max_reversals)
    n_rev = 0
    t = 0.0
    sq = math.sqrt(h)
    tmp = np.empty(n)
    while t < t1 and n_rev < max_reversals:
        k1 = rhs(t, y, p)
        for j in range(n):
            tmp[j] = y[j] + 0.5 * h * k1[j]
        k2 = rhs(t + 0.5 * h, tmp, p)
        for j in range(n):
            tmp[j] = y[j] + 0.5 * h * k2[j]
        k3 = rhs(t + 0.5 * h, tmp, p)
        for j in range(n):
            tmp[j] = y[j] + h * k3[j]
        k4 = rhs(t + h, tmp, p)
        old = y[spin_index]
        for j in range(n):
            y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j])
        for j in noise_index:
            y[j] += sigma * sq * np.random.standard_normal()
        new = y[spin_index]
        if (old > 0.0 and new <= 0.0) or (old < 0.0 and new >= 0.0):
            rev[n_rev] = t + h * old / (old - new)
            n_rev += 1
        t += h
        if not np.isfinite(new):
            break
    return rev[:n_rev], t


def simulate_noisy(model: Model, y0, t_end: float, p, sigma: float, h: float = 0.05, seed: int = 0,
                   max_reversals: int = 64) -> np.ndarray:
    """Spin-reversal times of ``model`` with white noise ``sigma`` on the tilt accelerations.

    Parameters
    ----------
    model : a knife edge at fidelity ``full`` or ``reduced`` (no pose).
    y0 : initial state, shape (n_state,) or mapping.
    t_end : end time (> 0).
    p : parameters.
    sigma : noise intensity (rad/time^(3/2)), ``>= 0``.
    h : RK4 step (time); ``h * omega`` must be small (the default suits ``g = ell = 1``).
    seed : seed of the noise.
    max_reversals : stop after this many reversals.

    Returns
    -------
    ndarray, shape (n_reversals,)
        Times at which the spin rate changed sign.
    """
    if not isinstance(model, Model) or model.fidelity not in ("full", "reduced") or model.pose:
        raise ValueError("`model` must be a knife edge at fidelity 'full' or 'reduced', without the pose")
    y0 = model.check_state(y0)
    p = model.check_params(p)
    for name, v in (("t_end", t_end), ("h", h)):
        if not (math.isfinite(_validate.real(v, f"`{name}`")) and v > 0):
            raise ValueError(f"`{name}` must be a positive number, got {v!r}")
    t_end, h = float(t_end), float(h)
    if h <= 10 * math.ulp(t_end):
        raise ValueError(f"`h` = {h!r} is below the resolution of t up to `t_end` = {t_end:g}: t would not advance")
    if t_end / h > MAX_NOISY_STEPS:
        raise ValueError(f"`t_end`/`h` = {t_end / h:.3g} steps, more than the {MAX_NOISY_STEPS:.0e} allowed "
                         f"in one call (a compiled loop that Ctrl-C cannot stop): shorten `t_end` or enlarge `h`")
    if not (math.isfinite(_validate.real(sigma, "`sigma`")) and sigma >= 0):
        raise ValueError(f"`sigma` must be a finite number >= 0, got {sigma!r}")
    for name, v, high in (("seed", seed, 2**32 - 1), ("max_reversals", max_reversals, 10**6)):
        if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)):
            raise TypeError(f"`{name}` must be an integer, got {v!r}")
        if not (0 if name == "seed" else 1) <= v <= high:
            raise ValueError(f"`{name}` must be an integer from {0 if name == 'seed' else 1} to {high}, got {v!r}")
    rate_of = dict(model.rate_pairs)
    noise_index = np.array([model.index(rate_of[q]) for q in model.tilt_names], dtype=np.int64)
    rev, t = _loop(model.rhs, y0, p, float(t_end), float(h), noise_index, float(sigma),
                   model.index(model.spin_name), int(seed), int(max_reversals))
    return np.asarray(rev)


def noisy_intervals(model: Model, p, y0, sigma: float, n_intervals: int = 6) -> np.ndarray:
    """Predicted mean intervals between reversals under white noise ``sigma`` on the tilt accelerations.

    Returns
    -------
    ndarray, shape (n_intervals,)
        ``T_k`` for ``k = 1..n_intervals`` after the first reversal:
        ``T_{2j-1} = T_{2j} = T(epsilon sqrt(j))``, ``epsilon`` from
        :func:`noise_floor` (see the module docstring).
    """
    from .reversal import MAX_INTERVALS, reversal_time

    if isinstance(n_intervals, (bool, np.bool_)) or not isinstance(n_intervals, (int, np.integer)):
        raise TypeError(f"`n_intervals` must be a positive integer, got {n_intervals!r}")
    if not 1 <= n_intervals <= MAX_INTERVALS:
        raise ValueError(f"`n_intervals` must be an integer from 1 to {MAX_INTERVALS}, got {n_intervals!r}")
    clean = reversal_time(model, p, y0)
    eps = noise_floor(model, p, clean, sigma)
    out = np.empty(n_intervals)
    for k in range(n_intervals):
        j = k // 2 + 1
        out[k] = reversal_time(model, p, y0, background=eps * math.sqrt(j)).intervals[0]
    return out
