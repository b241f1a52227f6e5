"""The bicycle's stability chart (issue 23 item 4): the lean/steer coefficients taken by machine from the derived
nonlinear bicycle, against the benchmark (Meijaard, Papadopoulos, Ruina & Schwab 2007, *Proc. R. Soc. A* 463,
1955-1982, as SymPy's ``test_kane3.py`` holds its matrix), and the scene ``bicycle_stability``.

The expected numbers are the benchmark's: ``benchmark_matrix`` (test_kane3's ``Res``) and the weave and capsize
speeds of its section 4.  The fresh derivation of the coefficients is compared with the checked-in module in the
slow tier (tests/test_whipple_bicycle.py, which derives the bicycle once).
"""
import numpy as np
import pytest

import knifeedge as ke
from knifeedge.scenes import bicycle_stability as scene_module
from test_whipple_bicycle import CAPSIZE, WEAVE, benchmark_matrix


def test_coefficients_are_the_benchmarks():
    """A0 + v A1 + v^2 A2 equals test_kane3's matrix at 0..10 m/s, and each coefficient equals the benchmark's own
    (its value at 0, its odd and even parts in v)."""
    coeffs = scene_module.coefficients()
    for v in np.arange(0.0, 10.25, 0.25):
        np.testing.assert_allclose(scene_module.matrix(coeffs, v), benchmark_matrix(v), rtol=0, atol=1e-10,
                                   err_msg=f"v = {v}")
    a0, a1, a2 = coeffs
    np.testing.assert_allclose(a0, benchmark_matrix(0.0), rtol=0, atol=1e-10)
    np.testing.assert_allclose(a1, (benchmark_matrix(1.0) - benchmark_matrix(-1.0)) / 2, rtol=0, atol=1e-10)
    np.testing.assert_allclose(a2, (benchmark_matrix(1.0) + benchmark_matrix(-1.0)) / 2 - benchmark_matrix(0.0),
                               rtol=0, atol=1e-10)


def test_the_module_is_not_stale():
    """Its input hash is that of the model file and of its writer (a change of either needs make bicycle-linear);
    the polynomial fitted the Jacobian at the check speeds."""
    from knifeedge.derive import bicycle_linear
    from knifeedge.generated.linear import whipple_bicycle as module

    assert module.INPUT_HASH == bicycle_linear.input_hash(), "run make bicycle-linear and commit"
    assert module.FIT_RESIDUAL < bicycle_linear.FIT_TOLERANCE


def test_an_edited_module_is_refused(tmp_path, monkeypatch):
    import importlib.util

    origin = importlib.util.find_spec("knifeedge.generated.linear.whipple_bicycle").origin
    edited = tmp_path / "whipple_bicycle.py"
    edited.write_text(open(origin).read().replace("9.48977", "9.48978"))

    class Spec:
        pass

    spec = Spec()
    spec.origin = str(edited)
    monkeypatch.setattr(importlib.util, "find_spec", lambda name: spec)
    with pytest.raises(ValueError, match="make bicycle-linear"):
        scene_module.coefficients()


def test_the_scene_finds_the_weave_and_capsize_speeds():
    r = ke.scene("bicycle_stability")()
    np.testing.assert_allclose([r.numbers["weave_speed"], r.numbers["capsize_speed"]], [WEAVE, CAPSIZE], rtol=0,
                               atol=1e-9)
    assert [v for _, v, _ in r.claims] == ["supports"]
    assert set(r.scene.reports) <= set(r.numbers)
    eig = r.data["eigenvalues"]
    assert eig.shape == (r.scene.settings["n_speeds"], 4)
    stable = r.data["speeds"][eig.real.max(axis=1) < 0]
    assert WEAVE < stable.min() and stable.max() < CAPSIZE  # self-stable between the two speeds only


def test_a_scene_without_a_run_says_so():
    with pytest.raises(ValueError, match="integrates nothing"):
        ke.scene("bicycle_stability", v=1.0)
    with pytest.raises(ValueError, match="integrates nothing"):
        ke.sweep("bicycle_stability", {"v": [1.0, 2.0]})
