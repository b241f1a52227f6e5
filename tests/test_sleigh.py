"""The Chaplygin sleigh through the generic engine, and its exact map onto Chap3 (paper section II.C).

Reference equations: Bloch, *Nonholonomic Mechanics and Control* (2003),
section 1.7 (also Neimark & Fufaev 1972): with ``v`` the speed of the contact
point along the axis, ``omega = phi_dot`` and per unit mass,
``dv/dt = a omega^2``, ``(k^2 + a^2) d(omega)/dt = -a v omega``.
"""
import math
import random
from dataclasses import replace

import numpy as np
import pytest
import sympy as sp

import knifeedge as ke
from knifeedge.derive import engine
from knifeedge.derive.sleigh import a, amplitude_analogy, k

# the session's symbolic derivation of every model (`systems`) is built once, in one test worker
pytestmark = pytest.mark.xdist_group("symbolic")


@pytest.fixture(scope="module")
def sleigh(systems):
    return systems[("chaplygin_sleigh", "full")]


def test_sleigh_equations_are_the_textbook_ones(sleigh):
    v, w = sleigh.state
    assert [str(s) for s in sleigh.state] == ["v", "phi_dot"]
    assert sp.simplify(sleigh.explicit[0] - a * w**2) == 0
    assert sp.simplify(sleigh.explicit[1] + a * v * w / (k**2 + a**2)) == 0


def test_generated_sleigh_module():
    m = ke.load("chaplygin_sleigh")
    assert m.state_names == ("v", "phi_dot") and m.param_names == ("a", "k") and m.tilt_names == ()
    rng = random.Random(3)
    for _ in range(5):
        v, w, a_, k_ = (rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(0.2, 2), rng.uniform(0.2, 2))
        np.testing.assert_allclose(m.rhs(0.0, np.array([v, w]), np.array([a_, k_])),
                                   [a_ * w**2, -a_ * v * w / (k_**2 + a_**2)], rtol=1e-13)


def test_quasi_velocity_reduction_holds_at_a_general_pose(sleigh):
    """The equations derived at phi = 0 on (v, phi_dot) equal the unreduced DAE at a random pose;
    a wrong sign is caught."""
    assert engine.check_symmetry(sleigh) < 1e-25
    bad = sleigh.explicit.copy()
    bad[1] = -bad[1]
    with pytest.raises(ValueError, match="general pose"):
        engine.check_symmetry(replace(sleigh, explicit=bad))


def test_sleigh_motion_respects_the_knife_edge_and_straightens_out():
    """Along a simulation with the pose: no velocity across the axis, energy conserved, and the
    sleigh ends moving straight ahead with v -> sqrt(v0^2 + (a^2 + k^2) omega0^2) (its energy)."""
    m = ke.load("chaplygin_sleigh", pose=True)
    p = m.params(a=0.5, k=0.8)
    r = ke.simulate(m, {"v": -0.3, "phi_dot": 1.0}, (0.0, 80.0), p, rtol=1e-11, atol=1e-13)
    assert r.success
    rates = np.array([m.pose_rates(r.y[:, i], p) for i in range(r.y.shape[1])]).T
    phi = r["phi"]
    across = -rates[1] * np.sin(phi) + rates[2] * np.cos(phi)
    assert np.max(np.abs(across)) < 1e-12
    e = r.energy
    assert np.max(np.abs(e - e[0])) < 1e-9 * e[0]
    assert r["v"][-1] == pytest.approx(math.sqrt(0.3**2 + (0.25 + 0.64) * 1.0), rel=1e-6)
    assert abs(r["phi_dot"][-1]) < 1e-6


def test_analogy_is_exact_symbolically(systems, sleigh):
    """v = -kappa A_phi, phi_dot = mu A_theta maps the sleigh onto the derived single-mode slow flow
    identically, with kappa = D (a^2 + k^2)/(2 a ell) and mu^2 = kappa g D/(2 a L^2)."""
    from knifeedge.derive.models import D, L, ell, g

    amp = systems[("single_mode", "amplitude")]
    m = amplitude_analogy(sleigh, amp)
    assert sp.simplify(m["kappa"] - D * (a**2 + k**2) / (2 * a * ell)) == 0
    assert sp.simplify(m["mu"] ** 2 - m["kappa"] * g * D / (2 * a * L**2)) == 0
    sub = m["substitution"]
    A, S = amp.state
    v, w = sleigh.state
    dv, dw = (e.subs(sub, simultaneous=True) for e in sleigh.explicit)
    # d(v)/dt = -kappa dA_phi/dt and d(phi_dot)/dt = mu dA_theta/dt on the slow flow
    assert sp.simplify(dv - sp.diff(sub[v], S) * amp.rates[1]) == 0
    assert sp.simplify(dw - sp.diff(sub[w], A) * amp.rates[0]) == 0


def test_analogy_overlay_numerically(systems, sleigh):
    """Simulate the sleigh and the single-mode amplitude model separately; the mapped sleigh
    trajectory lies on the amplitude trajectory (Fig. Elipses <-> the sleigh's energy ellipses)."""
    from knifeedge.derive.models import D, L, ell, g

    amp = systems[("single_mode", "amplitude")]
    m = amplitude_analogy(sleigh, amp)
    vals = {g: 1.0, ell: 1.0, L: 1.0, D: 1.0, a: 0.5, k: 0.8}
    kappa, mu = float(m["kappa"].subs(vals)), float(m["mu"].subs(vals))
    ma, ms = ke.load("single_mode", "amplitude"), ke.load("chaplygin_sleigh")
    pa, ps = ma.params(g=1.0, ell=1.0, L=1.0, D=1.0), ms.params(a=0.5, k=0.8)
    y_amp = np.array([1e-3, 0.1])
    t = np.linspace(0.0, 300.0, 601)
    ra = ke.simulate(ma, y_amp, (0.0, 300.0), pa, rtol=1e-12, atol=1e-15, t_eval=t)
    rs = ke.simulate(ms, [-kappa * y_amp[1], mu * y_amp[0]], (0.0, 300.0), ps, rtol=1e-12, atol=1e-15, t_eval=t)
    np.testing.assert_allclose(-rs["v"] / kappa, ra["A_phi"], atol=1e-9)
    np.testing.assert_allclose(rs["phi_dot"] / mu, ra["A_theta"], atol=1e-9)
    assert ra.reversal_times[0] > 50  # the overlay covers the reversal (v changes sign)
