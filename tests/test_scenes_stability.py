"""Scenes built on the linear stability and the Lyapunov exponents (issue 24): their numbers against independent
references."""
from __future__ import annotations

import numpy as np
import pytest

import knifeedge as ke

_RESULTS: dict = {}


def result(name):
    if name not in _RESULTS:
        _RESULTS[name] = ke.scene(name)()
    return _RESULTS[name]


def test_celt_stability_slopes_are_moffatt_tokiedas():
    """Moffatt & Tokieda (Nonlinearity 21 (2008) T1): at a slow spin the pitch mode grows at lambda Omega and the
    roll mode at -mu Omega; lambda, mu from their closed forms (celt_amplitude.moffatt_tokieda)."""
    r = result("celt_stability")
    assert set(r.scene.reports) <= set(r.numbers)
    amp = ke.load("celt", "amplitude")
    for key, preset in (("kl", "kane_levinson_1982"), ("schoemer", "schoemer")):
        lam, mu = amp.module.moffatt_tokieda(amp.preset(preset, sigma=0.0))[:2]
        assert r.numbers[f"slope_pitch_{key}"] == pytest.approx(lam, rel=1e-7)
        assert r.numbers[f"slope_roll_{key}"] == pytest.approx(-mu, rel=1e-7)


def test_celt_stability_boundaries():
    """Kane-Levinson undamped: unstable at every spin (the slopes lambda, -mu have opposite signs at small spin
    and neither pair crosses); Schoemer undamped: one boundary, at 1.80084 rad/s (the full rigid body's, slow
    test test_stability.py::test_celt_boundaries_agree_between_the_full_and_the_small_tilt_derivations)."""
    r = result("celt_stability")
    assert r.numbers["boundaries_kl_undamped"] == []
    assert r.numbers["boundaries_schoemer_undamped"] == pytest.approx([1.8008390118758], rel=1e-10)
    assert all(v == "supports" for _, v, _ in r.claims), r.claims


def _by_frequency(eigenvalues):
    """Each row sorted by the imaginary part (distinct here; the real parts are ~1e-18 noise at zero spin)."""
    return np.take_along_axis(eigenvalues, np.argsort(eigenvalues.imag, axis=1), axis=1)


@pytest.mark.slow  # the small-tilt celt's Jacobian-vector product compiles for this test alone
def test_celt_stability_small_tilt_equals_the_full_rigid_body():
    """The linearization at an upright spin is exact at first order in the tilts: the small-tilt derivation
    (derivation/rigid_small.py) and the full rigid body (derivation/rigid.py, the scene's model) give the same
    eigenvalues and the same boundaries, damped and undamped."""
    r = result("celt_stability")
    assert r.scene.run.fidelity == "full"
    small = ke.load("celt", "reduced")
    s = r.scene.settings
    for key, preset in (("kl", "kane_levinson_1982"), ("schoemer", "schoemer")):
        for damped in (False, True):
            label = f"{key}_{'damped' if damped else 'undamped'}"
            p = small.preset(preset, sigma=s["sigma"][key] if damped else 0.0)
            spins = r.data["spins"][::20]
            table = ke.stability(small, p, "steady_spin", spins)
            np.testing.assert_allclose(_by_frequency(table.eigenvalues), _by_frequency(r.data[f"eig_{label}"][::20]),
                                       rtol=1e-9, atol=1e-12)
            found = ke.stability_boundaries(small, p, "steady_spin", s["boundary_interval"])
            np.testing.assert_allclose(found, r.numbers[f"boundaries_{label}"], rtol=1e-9)


@pytest.mark.slow  # the two-mode Lyapunov kernel compiles in ~13 s cold, and five runs of 9000 time units
def test_predictability_scene():
    """The two-mode edge of Fig. Numerical2: its largest exponent falls like ln T / T (zero, as for an integrable
    flow: tests/test_lyapunov.py checks the same law on the rolling disk), so its horizon exceeds the run; the
    first reversal moves with the initial state (a 1e-8 perturbation of theta1 moves it 1e-10, above the 5e-12
    floor of one-ulp runs), the later ones by the same amount whatever the perturbation (the integration's
    floor)."""
    r = result("predictability")
    n = r.numbers
    assert set(r.scene.reports) <= set(n)
    assert 0 < n["lambda_max"] < 1e-4 and n["lambda_max"] < n["lambda_max_at_run_end"] / 3
    assert n["horizon"] > r.scene.run.t_span[1]
    assert n["fixed_by_horizon"] == [1, 2, 3] and n["fixed_measured"][:1] == [1]
    assert n["probe_shift"][0] > 10 * n["reversal_spread"][0]
    assert all(p < 10 * s for p, s in zip(n["probe_shift"][1:], n["reversal_spread"][1:]))
    verdicts = [v for _, v, _ in r.claims]
    assert verdicts == ["supports", "contradicts", "supports"]


@pytest.mark.slow  # the full celt's Jacobian (10-20 s cold) and 1000 s of its variational equations (~5 s)
def test_celt_chaos_scene():
    """Scene ``celt_chaos``: the energy against the Newton-Euler reference's (tests/rigid_reference.py), the upright
    spin of the same energy and its growth rate against the held-out linearization by hand
    (tests/test_celt_held_out.py), and the spectrum's structure: one positive exponent, two zero (flow direction,
    energy), a negative sum (Borisov & Mamaev, Physics-Uspekhi 46 (2003) 393: the non-holonomic celt's phase
    volume is not conserved)."""
    import rigid_reference as ref
    from test_celt_held_out import hand_block

    r = result("celt_chaos")
    assert set(r.scene.reports) <= set(r.numbers)
    run = r.scene.run
    p = np.array([run.params[k] for k in ref.NAMES])
    y0 = np.array([run.y0[k] for k in ("n_x", "n_y", "n_z", "omega_x", "omega_y", "omega_z")])
    assert r.numbers["energy"] == pytest.approx(ref.energy(y0, p), rel=1e-12)
    spin = r.numbers["steady_spin_same_energy"]
    upright = np.array([0.0, 0.0, 1.0, 0.0, 0.0, spin])
    assert ref.energy(upright, p) == pytest.approx(r.numbers["energy"], rel=1e-12)
    expected = float(np.linalg.eigvals(hand_block(p, spin)).real.max())
    assert r.numbers["steady_spin_growth_rate"] == pytest.approx(expected, rel=1e-8)
    lam = np.array(r.numbers["exponents"])
    assert lam[0] > 0.5 and np.sort(np.abs(lam))[1] < 0.015 and lam.sum() < -0.02
    assert all(v == "supports" for _, v, _ in r.claims), r.claims
