"""Runtime API: names, shapes, and clear errors on bad input (before any work)."""
import math

import numpy as np
import pytest

import knifeedge as ke

TWO = dict(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4)


def test_names_and_orders():
    m = ke.load("two_mode", fidelity="full", pose=False)
    assert m.state_names == ("theta1", "theta2", "theta1_dot", "theta2_dot", "phi_dot")
    assert m.param_names == ("g", "ell", "L", "D", "alpha")
    s = ke.load("single_mode")
    assert s.state_names == ("theta", "theta_dot", "phi_dot")
    assert s.param_names == ("g", "ell", "L", "D")
    mp = ke.load("two_mode", fidelity="reduced", pose=True)
    assert mp.state_names[-3:] == ("phi", "x", "y")


def test_params_are_a_validated_float_array():
    m = ke.load("two_mode")
    p = m.params(**TWO)
    assert p.dtype == np.float64 and p.shape == (5,)
    assert p[-1] == math.pi / 4
    assert m.params(**{**TWO, "alpha": -3.0})[-1] == -3.0  # alpha: any finite angle


def test_simulate_result_fields():
    m = ke.load("single_mode")
    p = m.params(g=1.0, ell=1.0, L=1.0, D=1.0)
    r = ke.simulate(m, np.array([1e-3, 0.0, 0.1]), (0.0, 10.0), p, rtol=1e-8, atol=1e-10)
    assert r.success and r.status == 0 and isinstance(r.message, str)
    assert r.y.shape == (3, r.t.size) and r.nfev > 0
    np.testing.assert_array_equal(r["phi_dot"], r.y[2])
    assert r.reversal_times.size == 0
    with pytest.raises(KeyError, match="unknown state"):
        r["psi"]


@pytest.mark.parametrize("kwargs,match", [
    (dict(name="three_mode"), "unknown model `name`"),
    (dict(name="two_mode", fidelity="exact"), "unknown `fidelity`"),
    (dict(name="two_mode", pose="yes"), "`pose`"),
])
def test_load_rejects(kwargs, match):
    with pytest.raises((ValueError, TypeError), match=match):
        ke.load(**kwargs)


@pytest.mark.parametrize("params,match", [
    ({k: v for k, v in TWO.items() if k != "D"}, r"missing \['D'\]"),
    ({**TWO, "M": 1.0}, r"unknown \['M'\]"),
    ({**TWO, "L": 0.0}, "`L` must be positive"),
    ({**TWO, "g": -1.0}, "`g` must be positive"),
    ({**TWO, "ell": float("nan")}, "`ell` must be finite"),
    ({**TWO, "alpha": float("inf")}, "`alpha` must be finite"),
    ({**TWO, "D": "half"}, "`D` must be a real number"),
])
def test_params_reject(params, match):
    with pytest.raises((ValueError, TypeError), match=match):
        ke.load("two_mode").params(**params)


def _sim(**over):
    m = ke.load("two_mode")
    args = dict(model=m, y0=np.array([1e-3, 1e-3, 0.0, 0.0, 0.1]), t_span=(0.0, 1.0), p=m.params(**TWO))
    args.update(over)
    return ke.simulate(**args)


@pytest.mark.parametrize("over,match", [
    (dict(method="Euler"), "unknown `method`"),
    (dict(y0=np.array([1e-3, np.nan, 0.0, 0.0, 0.1])), "must be finite"),
    (dict(y0=np.zeros(4)), r"must have shape \(5,\)"),
    (dict(y0={"theta1": 0.0}), "missing"),
    (dict(y0={"theta1": 0.0, "theta2": 0, "theta1_dot": 0, "theta2_dot": 0, "phi_dot": 0.1, "psi": 1}), "unknown"),
    (dict(t_span=(1.0, 0.0)), "`t_span`"),
    (dict(t_span=(1.0, 1.0)), "`t_span`"),
    (dict(t_span=(0.0, float("inf"))), "`t_span`"),
    (dict(rtol=0.0), "`rtol`"),
    (dict(atol=-1e-9), "`atol`"),
    (dict(p=np.ones(4)), r"shape \(5,\)"),
    (dict(p=np.array([1.0, 1.0, -2.0, 0.5, 0.0])), "`L` must be positive"),
    (dict(model="two_mode"), "`model`"),
])
def test_simulate_rejects(over, match):
    with pytest.raises((ValueError, TypeError), match=match):
        _sim(**over)


def test_failed_integration_is_reported_not_returned_silently():
    """A state that overflows is a failure in the result, and no non-finite values are returned."""
    m = ke.load("single_mode")
    p = m.params(g=1.0, ell=1.0, L=1.0, D=1.0)
    r = ke.simulate(m, dict(theta=1e100, theta_dot=1e100, phi_dot=1e100), (0.0, 10.0), p)
    assert not r.success and r.status < 0
    assert r.message
    assert np.all(np.isfinite(r.y))
