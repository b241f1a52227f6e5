"""A rattleback carrying a mass on a spring (issue 22 item 3), written as a user would: examples/rattleback_spring.py
(an ``Ellipsoid`` base and a ``Slider``, ``knifeedge.derive.multibody``), derived through the numeric elimination.

Checked against the closed form of its small oscillations at rest (Bondi, "The rigid body dynamics of unidirectional
spin", Proc. R. Soc. Lond. A 405 (1986) 265-279, section 3: the tilts of a body resting on a convex bottom, with the
masses on the body's vertical axis): with ``I_xz = I_yz = 0`` and point masses ``m_i`` at heights ``H_i`` above the
contact, the tilts ``(a1, a2)`` obey ``J x'' + K x = 0`` with

    J = [[I_xx + S, I_xy], [I_xy, I_yy + S]],   S = sum m_i H_i^2,
    K = g diag(sum m_i (R_y - H_i), sum m_i (R_x - H_i)),   R_x = a^2/c, R_y = b^2/c (the radii of curvature),

and the spring's mass ``mu`` oscillates along the axis at ``w^2 = k/mu`` about its sag ``s = d - mu g/k`` (the
contact holds the base vertically: at first order the slider decouples from the tilts).  The shell's centre of mass
is at ``H_0 = c - h``, the mass at ``H_1 = c - h + s``.  The eigenvalues of ``model.jacobian`` at rest are
``+-i w`` for the three modes and 0 (the spin ``psi_dot``, a family of steady states).  Energy (no dissipation) is
conserved along a run.  Slow tier: the derivation (~25 s CPU), its Jacobian's first compile (~50 s) and the DOP853
kernel's (~15 s), except the check that the docs show the example file.
"""
import importlib.util
from pathlib import Path

import numpy as np
import pytest

import knifeedge as ke

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "rattleback_spring.py"
#: Kane & Levinson's rattleback (derivation/celt.py's preset) with a tenth of its mass on a spring
VALUES = dict(a=0.20, b=0.03, c=0.02, h=0.01, m=1.0, g=9.81, I_xx=2e-4, I_yy=1.6e-3, I_zz=1.7e-3, I_xy=2e-5,
              mu=0.1, k=400.0, d=0.005)


@pytest.fixture(scope="module")
def model(tmp_path_factory):
    from knifeedge.derive import emit
    from knifeedge.derive.cli import derive_specs

    spec = importlib.util.spec_from_file_location("_example_rattleback_spring", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    out = tmp_path_factory.mktemp("rattleback_spring")
    emit.write_all(out, derive_specs([module.MODEL]), registry=False)
    return ke.load("rattleback_spring", path=out)


def _sag(v):
    return v["d"] - v["mu"] * v["g"] / v["k"]


def closed_form_frequencies(v) -> np.ndarray:
    """The three angular frequencies of the module docstring, ascending."""
    H0 = v["c"] - v["h"]
    H1 = H0 + _sag(v)
    S = v["m"] * H0**2 + v["mu"] * H1**2
    J = np.array([[v["I_xx"] + S, v["I_xy"]], [v["I_xy"], v["I_yy"] + S]])
    Rx, Ry = v["a"] ** 2 / v["c"], v["b"] ** 2 / v["c"]
    K = v["g"] * np.diag([v["m"] * (Ry - H0) + v["mu"] * (Ry - H1), v["m"] * (Rx - H0) + v["mu"] * (Rx - H1)])
    tilts = np.sqrt(np.linalg.eigvals(np.linalg.solve(J, K)).real)
    return np.sort(np.append(tilts, np.sqrt(v["k"] / v["mu"])))


@pytest.mark.slow
def test_the_model_is_the_bodies_state(model):
    assert model.state_names == ("a1", "a2", "s", "a1_dot", "a2_dot", "s_dot", "psi_dot")
    assert model.module.ELIMINATION == "numeric"


@pytest.mark.slow
@pytest.mark.parametrize("changes", [{}, {"mu": 0.3, "k": 150.0, "I_xy": -4e-5}])
def test_small_oscillations_at_rest_have_the_closed_form_frequencies(model, changes):
    v = {**VALUES, **changes}
    p = model.params(**v)
    rest = np.array([0.0, 0.0, _sag(v), 0.0, 0.0, 0.0, 0.0])
    np.testing.assert_allclose(model.module.rhs(0.0, rest, p), 0.0, atol=1e-14)  # an equilibrium
    ev = np.linalg.eigvals(model.jacobian(rest, p))
    assert np.max(np.abs(ev.real)) < 1e-10 * np.max(np.abs(ev))  # a centre: no growth, no decay
    omegas = np.sort(np.abs(ev.imag))
    assert omegas[0] < 1e-10 * omegas[-1]  # the spin: a family of steady states
    # each frequency twice (+-i w), ascending
    np.testing.assert_allclose(omegas[1::2], closed_form_frequencies(v), rtol=1e-12)  # measured 4e-15
    np.testing.assert_allclose(omegas[2::2], closed_form_frequencies(v), rtol=1e-12)


@pytest.mark.slow
def test_energy_is_conserved_along_a_run(model):
    """Tilted, spinning against its preferred sense, the spring excited: energy holds to 1e-9 relative at rtol 1e-11."""
    p = model.params(**VALUES)
    y0 = np.array([0.01, 0.01, _sag(VALUES) + 1e-3, 0.0, 0.0, 0.0, -3.0])
    r = ke.simulate(model, y0, (0.0, 5.0), p, rtol=1e-11, atol=1e-13)
    assert r.success
    assert np.ptp(r.energy) < 1e-9 * abs(r.energy[0])
    assert np.ptp(r.y[:, 2]) > 1e-3  # the spring moved


def test_the_docs_show_the_example_file_as_it_is():
    import re

    from test_your_own_model import DOC

    shown = re.findall(r"```python spring-file=rattleback_spring.py\n(.*?)```", DOC.read_text(), flags=re.S)
    assert shown == [EXAMPLE.read_text()]


@pytest.mark.slow
def test_doc_section_on_the_spring_rattleback_runs(tmp_path, monkeypatch):
    """docs/your-own-model.md section 11's second example, as written: derive, run, energy, the spin slowing."""
    from test_multibody import _run_doc_section

    _run_doc_section(tmp_path, monkeypatch, "spring", ["rattleback_spring.py"])
