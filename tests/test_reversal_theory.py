"""Two-mode reversal theory (beyond the paper's Eq. ``tr``) against simulations.

``ke.reversal_time`` integrates the averaged two-mode flow by quadrature on
the level sets of its two integrals (energy and ln A2 - (c2/c1) ln A1, cf.
Moffatt & Tokieda, Proc. R. Soc. Edinb. 138A (2008) 361).  It is checked
against (i) a direct integration of the generated amplitude equations,
(ii) converged simulations of the ``full`` equations of the paper's two-mode
scene (Fig. Numerical2: ell/L = 1/2, D/ell = 1/2, alpha = pi/4, tilts 1e-3),
(iii) simulations with a noise background.  benchmarks/reversal_theory.py
prints the sweep over phi_dot0.
"""
import math

import numpy as np
import pytest

import knifeedge as ke
from knifeedge.background import noisy_intervals, simulate_noisy

SCENE = dict(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4)


def _amplitude_run(y0, t_end):
    m = ke.load("two_mode", "amplitude")
    return ke.simulate(m, y0, (0.0, t_end), m.params(**SCENE), rtol=1e-13, atol=1e-22).reversal_times


@pytest.mark.parametrize("y0", [[1e-3, 1e-3, 0.1], [1e-3, 1e-3, -0.1], [2e-2, 1e-4, 0.05], [1e-3, 3e-2, 0.0]])
def test_quadrature_equals_integrated_slow_flow(y0):
    m = ke.load("two_mode", "amplitude")
    pred = ke.reversal_time(m, m.params(**SCENE), y0)
    rev = _amplitude_run(y0, pred.first + 3.5 * pred.interval)
    assert rev[0] == pytest.approx(pred.first, rel=1e-8, abs=1e-6)
    np.testing.assert_allclose(np.diff(rev), pred.interval, rtol=1e-8)


def test_single_mode_closed_form():
    """Single mode: one reversal at t_R = atanh(A_phi0/A0)/(c A0), A0^2 = A_phi0^2 + (g ell/L^2) A_theta0^2
    (the corrected an1), none if spun the other way."""
    m = ke.load("single_mode", "amplitude")
    p = m.params(g=1.0, ell=1.0, L=1.0, D=1.0)
    pred = ke.reversal_time(m, p, [1e-3, 0.1])
    r = ke.simulate(m, [1e-3, 0.1], (0.0, 400.0), p, rtol=1e-13, atol=1e-300)
    assert r.reversal_times[0] == pytest.approx(pred.first, rel=1e-8)
    assert pred.interval == math.inf
    assert ke.reversal_time(m, p, [1e-3, -0.1]).first == math.inf


@pytest.fixture(scope="module")
def full_runs():
    """Full two-mode runs at two tolerances (the decayed mode reaches ~1e-15: atol must not cut it)."""
    m = ke.load("two_mode", "full")
    p = m.params(**SCENE)
    out = {}
    for phi0 in (0.1, -0.1, 0.05):
        y0 = [1e-3, 1e-3, 0.0, 0.0, phi0]
        pred = ke.reversal_time(m, p, y0)
        t_end = pred.first + 2.5 * pred.interval
        runs = [ke.simulate(m, y0, (0.0, t_end), p, method="DOP853", rtol=rtol, atol=1e-30).reversal_times
                for rtol in (1e-13, 3e-14)]
        out[phi0] = (pred, runs)
    return out


@pytest.mark.parametrize("phi0", [0.1, -0.1, 0.05])
def test_theory_against_converged_full_simulations(full_runs, phi0):
    """First reversal and intervals within 1% (measured: < 0.12%) once the simulation has converged."""
    pred, (coarse, fine) = full_runs[phi0]
    assert len(fine) == len(coarse) == 3
    assert np.max(np.abs(coarse - fine)) < 1e-4 * fine[-1]  # converged to 1e-4 of the time span
    assert fine[0] == pytest.approx(pred.first, rel=0.01)
    np.testing.assert_allclose(np.diff(fine), pred.interval, rtol=0.01)


def test_paper_scene_first_reversal(full_runs):
    """The established first reversal of the paper's two-mode scene, t = 2396.685."""
    _, (_, fine) = full_runs[0.1]
    assert fine[0] == pytest.approx(2396.685, abs=2e-3)


def test_background_interval_asymptotics():
    """With a floor epsilon on the fast mode the interval is
    T = (1/sqrt(E)) [ln(2 A1_max/epsilon)/|c1| + ln 2/c2]  (docs/amplitude.md), A1_max = sqrt(E/w1);
    the paper's t_R = (ell/D)/phi_dot0 keeps only the scale: T D phi_dot0/ell = (4/sin 2 alpha) [...]."""
    m = ke.load("two_mode", "full")
    p = m.params(**SCENE)
    y0 = [1e-3, 1e-3, 0.0, 0.0, 0.1]
    for eps in (1e-6, 1e-9, 1e-12):
        pred = ke.reversal_time(m, p, y0, background=eps)
        c1, c2 = pred.growth_rates
        E = pred.energy
        a_max = math.sqrt(E / pred.weights[0])
        asym = (math.log(2 * a_max / eps) / abs(c1) + math.log(2) / c2) / math.sqrt(E)
        assert pred.interval == pytest.approx(asym, rel=2e-3)
        # 4/sin(2 alpha) prefactor against the paper's (ell/D)/phi_dot0
        assert abs(c1) * math.sqrt(E) == pytest.approx(SCENE["D"] * 0.1 / (4 * SCENE["ell"]), rel=1e-3)
    deterministic = ke.reversal_time(m, p, y0)
    assert deterministic.interval > ke.reversal_time(m, p, y0, background=1e-12).interval


def test_noise_background_against_simulations():
    """White noise sigma on the tilt accelerations: the predicted mean intervals (seeds accumulate,
    T_{2j-1} = T_{2j} = T(epsilon sqrt(j))) against 16 noisy runs, within 3 standard errors."""
    m = ke.load("two_mode", "full")
    p = m.params(**SCENE)
    y0 = [1e-3, 1e-3, 0.0, 0.0, 0.1]
    sigma = 1e-9
    pred = noisy_intervals(m, p, y0, sigma, n_intervals=4)
    runs = [np.diff(simulate_noisy(m, y0, 10500.0, p, sigma, seed=s, max_reversals=5))[:4] for s in range(16)]
    M = np.array([r for r in runs if len(r) == 4])
    assert len(M) == 16
    mean, err = M.mean(axis=0), M.std(axis=0, ddof=1) / math.sqrt(len(M))
    assert np.all(np.abs(mean - pred) < 3 * err + 1.0), (mean, pred, err)
    # and the noise matters: the deterministic interval is far longer
    assert ke.reversal_time(m, p, y0).interval > pred[0] + 20 * err[0]


def test_bad_input():
    m = ke.load("two_mode", "full")
    p = m.params(**SCENE)
    y0 = [1e-3, 1e-3, 0.0, 0.0, 0.1]
    with pytest.raises(TypeError, match="`model`"):
        ke.reversal_time("two_mode", p, y0)
    with pytest.raises(ValueError, match="`background`"):
        ke.reversal_time(m, p, y0, background=-1.0)
    with pytest.raises(ValueError, match="`background`"):
        ke.reversal_time(m, p, y0, background=[1e-9, 1e-9, 1e-9])
    with pytest.raises(ValueError, match="`n_intervals`"):
        ke.reversal_time(m, p, y0, n_intervals=1)
    with pytest.raises(ValueError, match="amplitude equations"):
        s = ke.load("chaplygin_sleigh")
        ke.reversal_time(s, s.params(a=1.0, k=1.0), [1.0, 1.0])
    with pytest.raises(ValueError, match="nonzero"):
        ke.reversal_time(m, p, [0.0, 1e-3, 0.0, 0.0, 0.1])
    with pytest.raises(ValueError, match="`sigma`"):
        simulate_noisy(m, y0, 10.0, p, -1.0)
