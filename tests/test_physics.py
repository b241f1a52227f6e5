"""Physics invariants of the generated models along simulated trajectories.

Scenes of the paper (Jagla & Rojo, arXiv:2309.06154): the single-mode scene of
Fig. `numerical` (ell/L = 1, D/ell = 1, phi_dot = 0.1 sqrt(g/ell), small tilt)
and the two-mode scene of Fig. `Numerical2` (ell/L = 1/2, D/ell = 1/2,
alpha = pi/4). Units g = ell = 1.
"""
import math

import numpy as np
import pytest

import knifeedge as ke

SINGLE = dict(g=1.0, ell=1.0, L=1.0, D=1.0)
TWO = dict(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4)
SINGLE_Y0 = dict(theta=1e-3, theta_dot=0.0, phi_dot=0.1)
TWO_Y0 = dict(theta1=1e-3, theta2=1e-3, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1)
PERIODS_1000 = 1000 * 2 * math.pi  # 1000 periods of the fast tilt mode, omega = sqrt(g/ell) = 1


@pytest.mark.parametrize("name,params,y0", [("single_mode", SINGLE, SINGLE_Y0), ("two_mode", TWO, TWO_Y0)])
def test_full_model_conserves_energy(name, params, y0):
    """The constraints are ideal and time independent, so the energy (Jacobi integral) of the
    full equations is conserved; DOP853 at rtol 1e-10 over 1000 periods keeps it to 1e-8."""
    m = ke.load(name, fidelity="full")
    r = ke.simulate(m, y0, (0.0, PERIODS_1000), m.params(**params), method="DOP853", rtol=1e-10, atol=1e-12)
    assert r.success, r.message
    e = r.energy
    drift = np.max(np.abs(e - e[0])) / abs(e[0])
    assert drift < 1e-8, f"{name}: relative energy drift {drift:.2e}"


def test_reduced_energy_is_only_approximately_conserved():
    """The reduced (small-angle) model conserves the truncated energy only up to the dropped
    orders: its drift is larger than the full model's, but stays at the O(theta^2) level."""
    full, red = ke.load("single_mode", "full"), ke.load("single_mode", "reduced")
    p = full.params(**SINGLE)
    drifts = []
    for m in (full, red):
        r = ke.simulate(m, SINGLE_Y0, (0.0, 300.0), p, rtol=1e-11, atol=1e-13)
        e = r.energy
        drifts.append(np.max(np.abs(e - e[0])) / abs(e[0]))
    assert drifts[0] < 1e-9
    assert drifts[0] < drifts[1] < 0.1**2  # theta reaches 0.1 rad in this scene


def test_single_mode_scene_reverses_once():
    """Fig. `numerical`: exactly one reversal, after which the spin settles at minus its
    initial value. Energy conservation fixes the final spin: once the tilt has died out,
    (1/2) L^2 phi_dot^2 = E(0)."""
    m = ke.load("single_mode", fidelity="full")
    p = m.params(**SINGLE)
    r = ke.simulate(m, SINGLE_Y0, (0.0, 400.0), p, rtol=1e-10, atol=1e-12)
    assert r.success, r.message
    assert len(r.reversal_times) == 1
    expected = -math.sqrt(2 * m.energy(m.state(SINGLE_Y0), p)) / SINGLE["L"]
    assert r["phi_dot"][-1] == pytest.approx(expected, rel=1e-6)
    # after the reversal the tilt decays like the corrected an2, theta_max sech(0.05 (t - t_rev)):
    # about 1.2e-5 at t = 300
    assert np.abs(r["theta"][r.t > 300]).max() < 2e-5
    # the corrected t0 (docs/errata.md): (2 ell/(D phi_dot0)) arccosh(theta_max/theta0),
    # theta_max = phi_dot0 L/sqrt(g ell) by the corrected an2
    t0 = 2 / 0.1 * math.acosh(0.1 / 1e-3)
    assert r.reversal_times[0] == pytest.approx(t0, rel=0.01)


def test_two_mode_scene_reverses_repeatedly_in_both_directions():
    """Fig. `Numerical2`: the spin reverses periodically, driven alternately by theta1 and theta2.
    The first reversal at t = 2396.685 was measured independently (DOP853 on the full
    equations, rtol 1e-10..1e-12)."""
    m = ke.load("two_mode", fidelity="full")
    r = ke.simulate(m, TWO_Y0, (0.0, 12000.0), m.params(**TWO), rtol=1e-12, atol=1e-14)
    assert r.success, r.message
    rev = r.reversal_times
    assert rev[0] == pytest.approx(2396.685, abs=1e-3)
    assert len(rev) >= 3
    # between consecutive reversals the spin has the opposite sign each time
    mids = [(a + b) / 2 for a, b in zip(np.r_[0.0, rev], np.r_[rev, r.t[-1]])]
    signs = np.sign(np.interp(mids, r.t, r["phi_dot"]))
    assert np.all(signs[1:] == -signs[:-1]) and signs[0] > 0
    # and it comes back close to its initial magnitude in each direction
    for a, b in zip(rev[:-1], rev[1:]):
        seg = r["phi_dot"][(r.t > a) & (r.t < b)]
        assert np.max(np.abs(seg)) > 0.09


def test_contact_force_across_the_bar_is_minus_g_theta():
    """lambda2 (Eq. `lambda2`) on the full single-mode equations reduces to -M g theta exactly:
    check the generated multiplier against the printed formula with the simulated accelerations."""
    m = ke.load("single_mode", fidelity="full")
    p = m.params(g=1.3, ell=0.7, L=1.1, D=0.4)
    rng = np.random.default_rng(1)
    for _ in range(10):
        y = rng.uniform(-0.5, 0.5, 3)
        th, thd, phd = y
        thdd, phdd = m.rhs(0.0, y, p)[1:]
        g, ell, L, D = p
        lam2 = -D * (phd * thd + th * phdd) + ell * thdd
        assert m.multipliers(y, p)[1] == pytest.approx(lam2, rel=1e-12)
        assert lam2 == pytest.approx(-g * th, rel=1e-12)


def test_pose_rates_follow_the_constraints():
    """With the pose, x and y move only across the bar at the contact (vinculo1, vinculo2)."""
    m = ke.load("single_mode", fidelity="full", pose=True)
    p = m.params(**SINGLE)
    y = m.state(theta=0.05, theta_dot=0.02, phi_dot=0.1, phi=0.3)
    phi_dot, xd, yd = m.pose_rates(y, p)
    u = np.array([math.cos(0.3), math.sin(0.3)])
    v = np.array([-math.sin(0.3), math.cos(0.3)])
    assert np.dot(u, [xd, yd]) == pytest.approx(0.0, abs=1e-15)
    assert np.dot(v, [xd, yd]) + SINGLE["D"] * 0.05 * phi_dot == pytest.approx(0.0, abs=1e-15)
