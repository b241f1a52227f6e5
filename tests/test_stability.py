"""Linear stability of the steady motions (``knifeedge.stability``) against classical and published results.

- Rolling disk (uniform thin disk): upright rolling is stable iff ``Omega^2 > g / (3 r)`` (Routh; Neimark &
  Fufaev, *Dynamics of Nonholonomic Systems*, ch. III; for moments ``A`` about a diameter and ``C`` about the axle
  the bound is ``A m g r / (C (C + m r^2))``, ``g/(3 r)`` for ``A = m r^2/4, C = m r^2/2``).
- Knife edges: at a slow spin ``Omega`` the tilt modes grow at ``c_i Omega``, the paper's amplitude equations:
  ``Chap2`` (``dA_theta/dt = D/(2 ell) A_theta A_phi``) for the single mode, and the averaged two-mode equations
  (the growth rates of ``two_mode_amplitude``, from ``Const52`` by averaging) for the two-mode edge.
- Celt: at a slow spin the pitch and roll modes grow at ``lambda Omega`` and ``-mu Omega``, Moffatt & Tokieda's
  ``lambda``, ``mu`` (Nonlinearity 21 (2008) T1; ``celt_amplitude.moffatt_tokieda``).
- The trivial directions: the celt's ``|n| = 1`` and ``omega_n = omega . n`` and the family's tangent, separated
  by construction, whatever their eigenvalues; together with the physical modes they are the spectrum of ``A``.
"""
import importlib
import math

import numpy as np
import docs_blocks
import pytest

import knifeedge as ke

st = importlib.import_module("knifeedge.stability")


def _slopes(m, p, omega):
    lin = ke.linearize(m, st.steady_state(m, p, "steady_spin", omega), p)
    return {md.name: md.growth_rate / omega for md in lin.modes}


def test_rolling_disk_upright_rolling_is_stable_iff_omega_squared_exceeds_g_over_3r():
    m = ke.load("rolling_disk")
    p = m.params(g=9.81, r=0.1)
    critical = math.sqrt(9.81 / (3 * 0.1))
    found = ke.stability_boundaries(m, p, "upright_rolling", (0.5, 30.0))
    assert found.shape == (1,)
    assert found[0] == pytest.approx(critical, rel=1e-10)
    table = ke.stability(m, p, "upright_rolling", [0.9 * critical, 1.1 * critical])
    assert table.max_growth_rate[0] > 0.1 and abs(table.max_growth_rate[1]) < 1e-12


def test_steady_states_are_read_without_compiling_them(monkeypatch):
    """The generated ``steady_state`` (a few assignments) is called as plain Python: compiled, it cost a first run
    0.13-0.26 s of CPU (``knifeedge figures`` cold). The same numbers as the compiled function's."""
    m = ke.load("rolling_disk")
    p = m.params(g=9.81, r=0.1)
    compiled = m.module.steady_state
    expected = compiled(0, 7.0, p)

    class NotCompiled:
        py_func = staticmethod(compiled.py_func)

        def __call__(self, *args):
            raise AssertionError("the compiled steady_state was called")

    monkeypatch.setattr(m.module, "steady_state", NotCompiled())
    assert np.array_equal(st.steady_state(m, p, "upright_rolling", 7.0), expected[0])
    lin = ke.linearize(m, expected[0], p)
    assert lin.family == "upright_rolling"
    ke.stability(m, p, "upright_rolling", [7.0])


def test_single_mode_slow_spin_growth_is_the_papers_chap2():
    m = ke.load("single_mode")
    p = m.params(g=1.0, ell=1.3, L=1.0, D=0.7)
    slopes = _slopes(m, p, 1e-3)
    assert set(slopes) == {"tilt"}
    assert slopes["tilt"] == pytest.approx(0.7 / (2 * 1.3), rel=1e-8)  # Chap2: D / (2 ell)


def test_two_mode_slow_spin_growth_is_the_averaged_two_mode_equations():
    m, amp = ke.load("two_mode"), ke.load("two_mode", "amplitude")
    p = m.params(m.default_params)
    lin = ke.linearize(m, st.steady_state(m, p, "steady_spin", 1e-3), p)
    got = sorted({round(md.growth_rate / 1e-3, 7) for md in lin.modes})
    np.testing.assert_allclose(got, sorted(amp.module.growth_rates(p)), rtol=1e-6)


@pytest.mark.slow  # the celt's Jacobian compiles in 10-20 s cold
@pytest.mark.parametrize("preset", ["kane_levinson_1982", "schoemer"])
def test_celt_slow_spin_slopes_are_moffatt_tokieda(preset):
    m, amp = ke.load("celt"), ke.load("celt", "amplitude")
    p = m.preset(preset, sigma=0.0)
    lam, mu = amp.module.moffatt_tokieda(p)[:2]
    slopes = _slopes(m, p, 1e-4)  # the next order is O(Omega^2): 4e-8 relative at 1e-3 for schoemer
    assert slopes["pitch"] == pytest.approx(lam, rel=1e-8)
    assert slopes["roll"] == pytest.approx(-mu, rel=1e-8)


@pytest.mark.slow
def test_celt_trivial_directions_are_separated_by_construction():
    m = ke.load("celt")
    p = m.preset("kane_levinson_1982")  # damped: the spin decays along the family
    lin = ke.linearize(m, st.steady_state(m, p, "steady_spin", 0.5), p)
    whats = [t.name for t in lin.trivial]
    assert any("|n|^2 = 1" in w for w in whats) and any("omega_n = omega . n" in w for w in whats)
    assert any(w.startswith("family steady_spin") for w in whats)
    assert lin.family == "steady_spin" and lin.value == 0.5
    # named by the largest tilt component (a slow spin: a fast one mixes n_x and n_y within each mode)
    assert [md.name for md in lin.modes].count("pitch") == 2 and [md.name for md in lin.modes].count("roll") == 2
    every = np.concatenate([lin.physical_eigenvalues, [t.eigenvalue for t in lin.trivial]])
    np.testing.assert_allclose(np.sort_complex(every), np.sort_complex(lin.eigenvalues), atol=1e-9)
    # the family's tangent decays as the damping torque slows the spin: -sigma / I_zz
    spin = next(t for t in lin.trivial if t.name.startswith("family"))
    sigma, i_zz = p[m.param_names.index("sigma")], p[m.param_names.index("I_zz")]
    assert spin.eigenvalue.real == pytest.approx(-sigma / i_zz, rel=1e-9)


def test_linearize_works_off_the_steady_motions():
    m = ke.load("two_mode")
    p = m.params(m.default_params)
    y = m.state(theta1=0.01, theta2=-0.02, theta1_dot=0.0, theta2_dot=0.03, phi_dot=0.2)
    lin = ke.linearize(m, y, p)
    assert lin.family is None and lin.trivial == () and len(lin.modes) == 5
    # A is jvp_into of the identity (forward mode through the rates): the generated Jacobian to round-off
    J = m.jacobian(y, p)
    np.testing.assert_allclose(lin.A, J, rtol=1e-13, atol=1e-13 * np.abs(J).max())


def test_bad_family_and_interval_are_named():
    m = ke.load("single_mode")
    p = m.params(m.default_params)
    with pytest.raises(ValueError, match="`family`"):
        ke.stability(m, p, "straight", [1.0])
    with pytest.raises(ValueError, match="`interval`"):
        ke.stability_boundaries(m, p, "steady_spin", (1.0, 0.0))


@pytest.mark.slow  # the celt's Jacobian
def test_docs_snippets_run(tmp_path, monkeypatch):
    """Every Python block of docs/stability.md runs as pasted."""
    import re
    from pathlib import Path

    text = (Path(__file__).resolve().parent.parent / "docs" / "stability.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 2
    monkeypatch.chdir(tmp_path)
    for code in blocks:
        docs_blocks.run(code, "docs/stability.md", notes=True)


@pytest.mark.slow
@pytest.mark.parametrize("sigma", [0.0, None])
def test_celt_boundaries_agree_between_the_full_and_the_small_tilt_derivations(sigma):
    """The steady spin's linearization is exact at first order in the tilts, so the full rigid body
    (derivation/rigid.py) and its small-tilt truncation (derivation/rigid_small.py, a separate derivation)
    must put the Schömer celt's stability boundary at the same spin (undamped and damped)."""
    found = []
    for fidelity in ("full", "reduced"):
        m = ke.load("celt", fidelity)
        p = m.preset("schoemer") if sigma is None else m.preset("schoemer", sigma=sigma)
        found.append(ke.stability_boundaries(m, p, "steady_spin", (-100.0, 100.0)))
    assert found[0].shape == found[1].shape == (1,)
    np.testing.assert_allclose(found[0], found[1], rtol=1e-10)
    assert 1.7 < found[0][0] < 1.9  # stable above it: the reversal direction is the negative spin
