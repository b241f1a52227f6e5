"""The emitted Jacobian-vector products ``jvp_into(s, p, V, ds, out)`` and ``jvp1_into(s, p, _v, ds, _dv)`` (one
vector; ``derivation/jacobian.py::jvp_source``).

Every generated module (iterated from the registry) writes the rates ``ds`` and ``J(s) V`` for the columns of
``V``, one forward pass through the right-hand side's common subexpressions per column.  The reference is the
emitted full Jacobian times ``V``: a separate derivation (gradients of every subexpression,
``derivation/jacobian.py::_gradients``), itself checked against eighth-order central differences of the
right-hand side (tests/test_jacobian.py).  The default tier runs the Python bodies (``py_func``: nothing to
compile).
"""
import numpy as np
import pytest

from test_jacobian import KEYS, _module, _point


def _jvp(mod, y, p, V, rates=None):
    out = np.full(V.shape, np.nan)  # every entry must be written
    ds = np.full(len(y), np.nan) if rates is None else rates
    mod.jvp_into.py_func(y, p, V, ds, out)
    return out


def _rhs(mod, y, p):
    ds = np.empty(len(y))
    mod.rhs_into.py_func(0.0, y, p, ds)
    return ds


@pytest.mark.parametrize("key", KEYS)
def test_jvp_is_the_jacobian_times_the_columns(key):
    mod = _module(key)
    rng = np.random.default_rng(7)
    for k in (1, 3):
        y, p = _point(mod, rng)
        V = rng.standard_normal((len(y), k))
        want = mod.jacobian.py_func(y, p) @ V
        rates = np.full(len(y), np.nan)
        got = _jvp(mod, y, p, V, rates)
        scale = max(1.0, float(np.abs(want).max()))
        assert got.shape == want.shape and np.abs(got - want).max() <= 1e-12 * scale, key
        np.testing.assert_allclose(rates, _rhs(mod, y, p), rtol=1e-14, atol=1e-14)  # the value with the derivative


@pytest.mark.parametrize("key", KEYS)
def test_the_product_of_one_vector_is_the_jacobian_times_it(key):
    """``jvp1_into(s, p, _v, ds, _dv)``, the same lines without the loop over columns (the largest Lyapunov exponent's
    loop calls it), against the emitted full Jacobian times ``v``."""
    mod = _module(key)
    rng = np.random.default_rng(11)
    y, p = _point(mod, rng)
    v = rng.standard_normal(len(y))
    want = mod.jacobian.py_func(y, p) @ v
    ds, dv = np.full(len(y), np.nan), np.full(len(y), np.nan)
    mod.jvp1_into.py_func(y, p, v, ds, dv)
    assert np.abs(dv - want).max() <= 1e-12 * max(1.0, float(np.abs(want).max())), key
    np.testing.assert_allclose(ds, _rhs(mod, y, p), rtol=1e-14, atol=1e-14)


def test_a_wrong_column_is_caught():
    """The check can fail: ``V``'s columns in a different order give a different product."""
    mod = _module("celt/full")
    y, p = _point(mod, np.random.default_rng(2))
    V = np.random.default_rng(3).standard_normal((len(y), 2))
    assert np.abs(_jvp(mod, y, p, V[:, ::-1]) - mod.jacobian.py_func(y, p) @ V).max() > 1e-6


def test_jvp_reports_its_operations():
    """The product costs its operations once (the right-hand side and the partial derivatives) and then a few
    per column: for the celt, a column costs less than a sixth of the full Jacobian."""
    mod = _module("celt/full")
    ops = mod.OP_COUNTS
    assert 0 < ops["jvp_column"] < ops["jacobian"] / 6 and 0 < ops["jvp_once"] < ops["jacobian"] / 3
