"""Derived equations against the paper's, equation by equation (derivation/published.py).

"Derived equals published" means: every transcribed equation either agrees
with the derivation, or is a recorded erratum that fails as printed and
whose correction agrees.  The comparison for each label is re-derived here
by derivation.verify (dimensions, residual on the full equations, averaging,
residual of the closed form).
"""
import json
from pathlib import Path

import pytest
import sympy as sp

from knifeedge.derive import published as pub
from knifeedge.derive import verify
from knifeedge.derive.dimensions import check_equation
from knifeedge.derive.truncation import truncate

# the session's symbolic derivation of every model (`systems`) is built once, in one test worker
pytestmark = pytest.mark.xdist_group("symbolic")

ROOT = Path(__file__).resolve().parents[1]
REQUIRED = {"lambda2", "phiAf", "thetBf", "FINAL1", "FINAL2", "Chap1", "Chap2", "an1", "an2",
            "Const22", "Const23", "Const52", "eqs_2modes.2", "eqs_2modes.3", "t0", "tr",
            "vinculo1", "vinculo2"}


def test_every_required_label_is_transcribed_once():
    labels = [e.label for e in pub.PUBLISHED]
    assert len(labels) == len(set(labels))
    assert REQUIRED <= set(labels)


@pytest.mark.parametrize("entry", pub.PUBLISHED, ids=lambda e: e.label)
def test_verdict(entry, systems):
    printed = verify.evaluate(entry, systems)
    if entry.status == "agrees":
        assert entry.corrected is None
        assert printed.passed, f"{entry.label} recorded as agreeing, but: {printed.dimension_error or printed.detail}"
    else:
        assert entry.status == "erratum"
        assert not printed.passed, f"{entry.label} recorded as an erratum, but it agrees: {printed.detail}"
        fixed = verify.evaluate(entry, systems, corrected=True)
        assert fixed.passed, f"correction of {entry.label} does not agree: {fixed.dimension_error or fixed.detail}"


def test_dimension_checker_finds_the_known_inconsistencies():
    # FINAL1 and an2 as printed: length/time^2 vs 1/time^2, and an angle with dimension length^-1/2
    assert "length" in check_equation(pub.BY_LABEL["FINAL1"].lhs, pub.BY_LABEL["FINAL1"].rhs)
    assert check_equation(pub.BY_LABEL["an2"].lhs, pub.BY_LABEL["an2"].rhs) is not None
    assert check_equation(*pub.BY_LABEL["an2"].corrected) is None


def test_reduced_single_mode_is_FINAL3(systems):
    """Eqs. FINAL1 (corrected) and FINAL2 are exactly the reduced single-mode equations."""
    red = systems[("single_mode", "reduced")]
    theta_dd, phi_dd = red.explicit
    assert sp.simplify(theta_dd - pub.BY_LABEL["FINAL2"].rhs) == 0
    assert sp.simplify(phi_dd - pub.BY_LABEL["FINAL1"].corrected[1]) == 0
    # and the printed FINAL1 differs from it by the spurious factor ell
    assert sp.simplify(pub.BY_LABEL["FINAL1"].rhs / phi_dd) == pub.ell


def test_reduced_two_mode_is_eqs_2modes(systems):
    """Eqs. eqs_2modes (Const52 and the next two lines) solved for the accelerations and
    truncated at second order in the tilts equal the reduced two-mode equations."""
    red = systems[("two_mode", "reduced")]
    spec = red.spec
    eqs = [pub.BY_LABEL[k] for k in ("Const52", "eqs_2modes.2", "eqs_2modes.3")]
    sol = sp.solve([e.lhs - e.rhs for e in eqs], list(red.accelerations), dict=True)[0]
    for acc, derived in zip(red.accelerations, red.explicit):
        published = truncate(sol[acc], spec, list(red.state))
        assert verify.is_zero(published - derived), acc


def test_errata_are_documented():
    text = (ROOT / "docs" / "errata.md").read_text()
    for e in pub.PUBLISHED:
        if e.status == "erratum":
            assert f"`{e.label}`" in text, f"docs/errata.md does not discuss {e.label}"


def test_records_are_machine_readable():
    records = json.loads(json.dumps(pub.as_records()))
    assert {r["status"] for r in records} <= {"agrees", "erratum"}
    assert all((r["corrected"] is None) == (r["status"] == "agrees") for r in records)


def _rocking_frequencies(lagrangian, values):
    """Linear rocking frequencies of a two-mode Lagrangian at zero spin: Const22/Const23 give x_dot = 0
    there, so the tilts obey M theta'' = -K theta with M, K the Hessians of the kinetic and potential parts."""
    import numpy as np

    rates, tilts = [pub.theta1_dot, pub.theta2_dot], [pub.theta1, pub.theta2]
    at_rest = {s: 0 for s in (pub.x_dot, pub.y_dot, pub.phi_dot, *rates, *tilts)}
    Mm = np.array(sp.hessian(lagrangian, rates).subs(at_rest).subs(values), dtype=float)
    K = -np.array(sp.hessian(lagrangian, tilts).subs(at_rest).subs(values), dtype=float)
    return np.sort(np.sqrt(np.linalg.eigvals(np.linalg.solve(Mm, K)).real))


def test_section_III_lagrangian_erratum_changes_the_rocking_frequencies():
    """Twomodes.lagrangian (section III, Fig. sketch_2modes): the rigid body's linear rocking frequencies
    (numerical Jacobian of the generated two_mode_rigid module at upright rest) are those of the corrected
    Lagrangian, + (1/2) M g D theta_alpha^2, and not those of the printed one, at the parameters of
    Fig. Numerical2 (ell/L = 1/2, D/ell = 1/2, alpha = pi/4)."""
    import math

    import numpy as np

    import knifeedge as ke

    entry = pub.BY_LABEL["Twomodes.lagrangian"]
    values = {pub.M: 1, pub.g: 1, pub.ell: 1, pub.L: 2, pub.D: sp.Rational(1, 2), pub.alpha: sp.pi / 4}
    printed = _rocking_frequencies(entry.rhs, values)
    corrected = _rocking_frequencies(entry.corrected[1], values)
    np.testing.assert_allclose(printed, [1 / math.sqrt(5), 1.0], rtol=1e-14)  # sqrt(g ell/(L^2 + ell^2)), sqrt(g/ell)
    m = ke.load("two_mode_rigid")
    p = m.params(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4)
    s0 = m.initial_state(n0=(0.0, 0.0, 1.0), omega0=(0.0, 0.0, 0.0))
    h = 1e-6
    rhs = m.module.rhs.py_func  # the generated rhs as Python: 14 calls, no compile (~1.6 s of CPU)
    J = np.column_stack([(rhs(0.0, s0 + h * e, p) - rhs(0.0, s0 - h * e, p)) / (2 * h) for e in np.eye(7)])
    rigid = np.sort([w.imag for w in np.linalg.eigvals(J) if w.imag > 1e-6])
    np.testing.assert_allclose(rigid, corrected, rtol=1e-7)
    assert np.all(rigid / printed - 1 > 0.08)  # the missing term raises both frequencies by 9 % and 12 %
