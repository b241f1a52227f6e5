"""Issue 26, root 7: the package's own work stays inside its validity domains.

A built-in scene whose runs leave the domain of their fidelity (generated
``VALIDITY``: where the small-tilt fidelities' first reversal is within 0.1 %
of the full model's) shows the boundary on its figure instead of warning at
every run; the default tier turns any other ``ValidityWarning`` into an error
(``tests/conftest.py``).
"""
import dataclasses
import warnings

import numpy as np
import pytest

import knifeedge as ke


def test_the_packages_own_work_stays_inside_its_validity_domains():
    """Scene tinversion (paper Fig. 'tinversion') scans phi_dot0 up to 0.4, where the largest tilt,
    phi_dot0 L/sqrt(g ell) = 0.8 rad (L = 2), exceeds the 0.6 rad domain of the reduced two-mode model and of
    the amplitude equations: the scene computes without a ValidityWarning, names the points outside, and
    shades them on its figure; points inside give the same first reversal as a run alone."""
    base = ke.scene("tinversion")
    scene = dataclasses.replace(base, settings={**base.settings, "phi_dot0": (0.1, 0.2, 0.4),
                                                "D_over_ell": (0.5, 0.7, 1.0)})
    with warnings.catch_warnings():
        warnings.simplefilter("error", ke.ValidityWarning)
        res = scene()
    assert res.numbers["outside_validity_domain_vs_phi_dot0"] == [0.4]
    assert res.numbers["outside_validity_domain_vs_D_over_ell"] == []
    assert any("beyond the small-tilt domain" in evidence for _, _, evidence in res.claims)
    # the point outside really is outside: a run alone says so
    run = base.run.with_(phi_dot=0.4, t_end=2000.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        alone = run.simulate()
    assert not alone.in_validity_domain and any(issubclass(w.category, ke.ValidityWarning) for w in caught)
    assert np.max(np.abs(alone["theta2"])) > 0.6
    fig = res.figure()
    labels = [p.get_label() for p in fig.axes[0].patches]
    assert any("outside the small-tilt domain" in label for label in labels)
    assert not fig.axes[1].patches
    first = base.run.with_(phi_dot=0.1, n_eval=None).simulate().reversal_times[0]
    assert res.numbers["first_reversal_times_vs_phi_dot0"][0] == first


@pytest.mark.slow
def test_the_packages_own_work_stays_inside_its_validity_domains_model_fidelity():
    """Scene model_fidelity runs the reduced and amplitude fidelities beyond their domain on purpose (to find
    where they stop being good enough): no ValidityWarning, the points outside reported, the band shaded from the
    domain's bound (0.21 rad, generated VALIDITY of single_mode reduced)."""
    base = ke.scene("model_fidelity")
    scene = dataclasses.replace(base, settings={**base.settings, "phi_dot0_over_omega": (0.1, 0.4)})
    with warnings.catch_warnings():
        warnings.simplefilter("error", ke.ValidityWarning)
        res = scene()
    assert res.numbers["single_mode_reduced_outside_validity_domain"] == [0.4]
    assert res.numbers["single_mode_amplitude_outside_validity_domain"] == [0.4]
    assert res.data["bound"] == ke.load("single_mode", "reduced").validity["theta"] == 0.21
    fig = res.figure()
    assert any("outside the small-tilt domain" in p.get_label() for p in fig.axes[0].patches)
