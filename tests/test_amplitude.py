"""Amplitude equations by machine (paper section II.C: Chap1, Chap2, Chap3, an1, an2, Fig. Elipses).

The slow flows are derived by ``derivation/averaging.py`` from the
``reduced`` systems; here they are compared with the paper's equations as
transcribed in ``derivation/published.py`` (written from the paper, not from
the averaging), with the closed forms, and the generated modules with the
SymPy expressions they were printed from.
"""
import math
import random

import numpy as np
import pytest
import sympy as sp

import knifeedge as ke
from knifeedge.generated import MODULES
from knifeedge.derive import averaging
from knifeedge.derive import published as pub
from knifeedge.derive.models import D, L, alpha, ell, g

# the session's symbolic derivation of every model (`systems`) is built once, in one test worker
pytestmark = pytest.mark.xdist_group("symbolic")

A_theta, A_phi, A1, A2 = (sp.Symbol(n, nonnegative=True) for n in ("A_theta", "A_phi", "A1", "A2"))


def _flow(system):
    """{name: rate} of an amplitude system, with the published symbols for the state."""
    names = {str(s): s for s in system.state}
    rename = {names["A_theta"]: pub.A_theta, names["A_phi"]: pub.A_phi}
    return {str(s): r.subs(rename, simultaneous=True) for s, r in zip(system.state, system.rates)}, rename


def test_single_mode_slow_flow_against_Chap1_Chap2(systems):
    """Chap2 agrees with the derived slow flow; Chap1 as printed does not (extra factor ell),
    its correction (the averaged corrected FINAL1) does."""
    amp = systems[("single_mode", "amplitude")]
    flow, _ = _flow(amp)
    chap1, chap2 = pub.BY_LABEL["Chap1"], pub.BY_LABEL["Chap2"]
    assert sp.simplify(flow["A_theta"] - chap2.rhs) == 0
    assert sp.simplify(flow["A_phi"] - chap1.rhs) != 0
    assert chap1.status == "erratum"
    assert sp.simplify(flow["A_phi"] - chap1.corrected[1]) == 0
    # the printed Chap1 differs by exactly the factor ell
    assert sp.simplify(chap1.rhs / flow["A_phi"]) == ell


def test_phases_drop_out_and_frequencies_are_the_bare_ones(systems):
    """theta ~ A cos(omega t + beta): at this order the phases do not drift (paper: A_theta
    real, theta = A e^{i omega t}) and omega is sqrt(g/ell), and sqrt(g ell/(ell^2+L^2)) for theta2."""
    one, two = systems[("single_mode", "amplitude")], systems[("two_mode", "amplitude")]
    assert one.phase_rates == [0] and two.phase_rates == [0, 0]
    assert sp.simplify(one.frequencies[0] - sp.sqrt(g / ell)) == 0
    assert sp.simplify(two.frequencies[0] - sp.sqrt(g / ell)) == 0
    assert sp.simplify(two.frequencies[1] - sp.sqrt(g * ell / (ell**2 + L**2))) == 0


def test_closed_form_an_solves_the_derived_flow(systems):
    """an1/an2 as printed do not solve the derived slow flow; the corrected forms do (symbolic residual)."""
    amp = systems[("single_mode", "amplitude")]
    flow, _ = _flow(amp)
    t = pub.t

    def residual(a_phi, a_theta):
        r1 = sp.diff(a_phi, t) - flow["A_phi"].subs({pub.A_theta: a_theta, pub.A_phi: a_phi})
        r2 = sp.diff(a_theta, t) - flow["A_theta"].subs({pub.A_theta: a_theta, pub.A_phi: a_phi})
        return [sp.simplify(sp.expand(r.rewrite(sp.exp))) for r in (r1, r2)]

    an1, an2 = pub.BY_LABEL["an1"], pub.BY_LABEL["an2"]
    assert residual(an1.corrected[1], an2.corrected[1]) == [0, 0]
    assert residual(an1.rhs, an2.rhs) != [0, 0]


def test_ellipse_invariant(systems):
    """Fig. Elipses: the derived conserved quantity is a positive-definite quadratic form in
    (A_theta, A_phi), i.e. its level sets are ellipses, with axes ratio sqrt(g ell)/L; the
    corrected closed form stays on the ellipse A_phi^2 + (g ell/L^2) A_theta^2 = A0^2."""
    amp = systems[("single_mode", "amplitude")]
    A, S = amp.state
    inv = amp.invariants["energy"]
    assert sp.simplify(sum(sp.diff(inv, s) * r for s, r in zip(amp.state, amp.rates))) == 0
    H = sp.hessian(inv, (A, S))
    assert H[0, 1] == 0 and H[0, 0].is_positive and H[1, 1].is_positive
    assert sp.simplify(H[0, 0] / H[1, 1] - g * ell / L**2) == 0
    sol = {A: pub.BY_LABEL["an2"].corrected[1], S: pub.BY_LABEL["an1"].corrected[1]}
    level = sp.simplify((inv / H[1, 1] * 2).subs(sol).rewrite(sp.exp))
    assert sp.simplify(level - pub.A0**2) == 0


def test_equilibria_with_positive_spin_are_unstable(systems):
    """Paper after Chap3: '(A_theta = 0, A_phi != 0) ... a negative eigenvalue if A_phi > 0 (the stable
    case)'.  The linearization of the derived flow has eigenvalues 0 and D A_phi/(2 ell): the half
    A_phi > 0 is unstable (the spin that the tilt grows from), A_phi < 0 is stable."""
    amp = systems[("single_mode", "amplitude")]
    A, S = amp.state
    J = sp.Matrix(amp.rates).jacobian(amp.state).subs(A, 0)
    eig = J.eigenvals()
    assert set(eig) == {0, D * S / (2 * ell)}
    assert (D * S / (2 * ell)).subs(S, 1).is_positive


def test_two_mode_slow_flow_structure(systems):
    """eqs_2modes averaged: dA_i/dt = c_i A_phi A_i with c_1 c_2 < 0 (opposite chirality of the two
    modes, the origin of periodic reversals), dA_phi/dt = k_1 A1^2 + k_2 A2^2, and two integrals:
    the averaged energy and ln A2 - (c2/c1) ln A1 (Moffatt & Tokieda 2008)."""
    amp = systems[("two_mode", "amplitude")]
    c1, c2 = amp.growth
    assert sp.simplify(c1 + D * sp.sin(2 * alpha) / (4 * ell)) == 0
    assert sp.simplify(c2 - D * ell * sp.sin(2 * alpha) / (4 * (ell**2 + L**2))) == 0
    assert set(amp.invariants) == {"energy", "log_A1_A2"}
    for q in amp.invariants.values():
        assert sp.simplify(sum(sp.diff(q, s) * r for s, r in zip(amp.state, amp.rates))) == 0


def test_averaging_refuses_resonant_modes(systems):
    """Averaging over independent phases needs distinct frequencies: equal ones are refused."""
    from dataclasses import replace

    red = systems[("two_mode", "reduced")]
    th1, th2 = red.spec.small
    bad = red.explicit.copy()
    bad[1] = bad[1].subs(L, 0)  # theta2 then has the frequency of theta1
    with pytest.raises(ValueError, match="resonant"):
        averaging.average(replace(red, explicit=bad))


@pytest.mark.parametrize("key", sorted(MODULES))
@pytest.mark.slow
def test_generated_rhs_equals_its_sympy_source(systems, key):
    """The printed code evaluates to the expressions it was printed from (at random points,
    parameters away from 1 so that e.g. x/L**2 printed as x/L*L would be caught)."""
    sys_ = systems[key]
    m = ke.load(*key)
    rng = random.Random(1)
    exprs = sys_.state_rhs()
    f = sp.lambdify([list(sys_.state), list(sys_.spec.params)], exprs, "math")
    for _ in range(5):
        s = [rng.uniform(0.05, 0.9) for _ in sys_.state]
        p = [rng.uniform(1.3, 2.9) for _ in sys_.spec.params]
        np.testing.assert_allclose(m.rhs(0.0, np.array(s), np.array(p)), f(s, p), rtol=1e-12, atol=1e-15)


# not the symbolic group: that group goes first, to one worker, while the other compiles the DOP853 driver for
# its first checks; run later, this check loads the driver from the cache instead of compiling it again (~8 s)
@pytest.mark.xdist_group("amplitude_runtime")
def test_amplitude_model_runtime():
    """ke.load(..., 'amplitude'): state (A_theta, A_phi) / (A1, A2, A_phi), spin A_phi, no pose,
    no multipliers; its energy is conserved along a simulation."""
    m = ke.load("single_mode", fidelity="amplitude")
    assert m.state_names == ("A_theta", "A_phi") and m.spin_name == "A_phi"
    assert ke.load("two_mode", fidelity="amplitude").state_names == ("A1", "A2", "A_phi")
    with pytest.raises(ValueError, match="pose"):
        ke.load("single_mode", fidelity="amplitude", pose=True)
    p = m.params(g=1.0, ell=1.0, L=1.0, D=1.0)
    with pytest.raises(ValueError, match="multipliers"):
        m.multipliers(np.array([1e-3, 0.1]), p)
    r = ke.simulate(m, [1e-3, 0.1], (0.0, 300.0), p, rtol=1e-11, atol=1e-14)
    assert r.success and len(r.reversal_times) == 1
    e = r.energy
    assert np.max(np.abs(e - e[0])) < 1e-9 * e[0]
    # corrected an1: A_phi -> -A0 with A0^2 = A_phi0^2 + (g ell/L^2) A_theta0^2
    assert r["A_phi"][-1] == pytest.approx(-math.sqrt(0.1**2 + 1e-6), rel=1e-6)
