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


@pytest.mark.slow  # the full celt's Jacobian compiles in 10-20 s cold
def test_celt_stability_small_tilt_equals_the_full_rigid_body():
    """The linearization at an upright spin is exact at first order in the tilts: the small-tilt derivation
    (derivation/rigid_small.py) and the full rigid body (derivation/rigid.py) give the same eigenvalues and the
    same boundaries, damped and undamped."""
    r = result("celt_stability")
    full = ke.load("celt", "full")
    s = r.scene.settings
    for key, preset in (("kl", "kane_levinson_1982"), ("schoemer", "schoemer")):
        for damped in (False, True):
            label = f"{key}_{'damped' if damped else 'undamped'}"
            p = full.preset(preset, sigma=s["sigma"][key] if damped else 0.0)
            spins = r.data["spins"][::20]
            table = ke.stability(full, p, "steady_spin", spins)
            np.testing.assert_allclose(np.sort_complex(table.eigenvalues),
                                       np.sort_complex(r.data[f"eig_{label}"][::20]), rtol=1e-9, atol=1e-12)
            found = ke.stability_boundaries(full, p, "steady_spin", s["boundary_interval"])
            np.testing.assert_allclose(found, r.numbers[f"boundaries_{label}"], rtol=1e-9)
