"""The emitted Jacobians (``derivation/jacobian.py``) against finite differences of the emitted right-hand side.

Every generated module (iterated from the registry) is checked: ``jacobian(s, p)`` (d rhs / d state) and
``jacobian_p(s, p)`` (d rhs / d parameters) against an eighth-order central difference of ``rhs_into``, an
independent route (numbers, not the symbolic derivative).  The default tier runs the modules' Python bodies
(``py_func``: nothing to compile); the slow tier checks that the compiled functions give the same numbers.
"""
import importlib

import numpy as np
import pytest

import knifeedge as ke
from knifeedge.generated import MODULES

KEYS = [f"{m}/{f}" for m, f in sorted(MODULES)]
#: eighth-order central difference: f'(x) ~ sum_k c_k (f(x + k h) - f(x - k h)) / h
_STENCIL = ((1, 4 / 5), (2, -1 / 5), (3, 4 / 105), (4, -1 / 280))


def _module(key):
    return importlib.import_module(f"knifeedge.generated.{MODULES[tuple(key.split('/'))]}")


def _rhs(mod, y, p):
    out = np.empty(len(mod.STATE_NAMES))
    mod.rhs_into.py_func(0.0, y, p, out)
    return out


def _difference(f, x, h_rel=2e-3):
    """d f / d x by the eighth-order central stencil, one column per component of ``x`` (step relative to it)."""
    cols = []
    for j in range(len(x)):
        h = h_rel * (abs(x[j]) or 1.0)
        col = 0.0
        for k, c in _STENCIL:
            xp, xm = x.copy(), x.copy()
            xp[j] += k * h
            xm[j] -= k * h
            col = col + c * (f(xp) - f(xm))
        cols.append(col / h)
    return np.stack(cols, axis=1)


def _point(mod, rng):
    """A state near the module's default (or random), parameters its defaults (or random), all generic."""
    names, pnames = mod.STATE_NAMES, mod.PARAM_NAMES
    y = np.array([mod.DEFAULT_STATE.get(n, 0.0) for n in names]) + rng.uniform(0.05, 0.2, len(names))
    p = np.array([mod.DEFAULT_PARAMS.get(n, np.nan) for n in pnames])
    p = np.where(np.isfinite(p), p, rng.uniform(0.5, 2.0, len(pnames)))
    small = np.min(np.abs(p[p != 0])) * rng.uniform(0.05, 0.2, len(pnames))  # zero entries (I_xz, sigma) made generic
    return y, np.where(p == 0, small, p) * rng.uniform(0.9, 1.1, len(pnames))


def _assert_close(a, b, what):
    scale = max(1.0, float(np.max(np.abs(b))))
    err = float(np.max(np.abs(a - b))) if a.size else 0.0
    assert a.shape == b.shape, f"{what}: shape {a.shape}, expected {b.shape}"
    assert err <= 1e-7 * scale, f"{what}: differs from finite differences by {err:.3g} (scale {scale:.3g})"


@pytest.mark.parametrize("key", KEYS)
def test_jacobians_match_finite_differences(key):
    mod = _module(key)
    rng = np.random.default_rng(24)
    for _ in range(3):
        y, p = _point(mod, rng)
        _assert_close(mod.jacobian.py_func(y, p), _difference(lambda x: _rhs(mod, x, p), y), f"{key} jacobian")
        _assert_close(mod.jacobian_p.py_func(y, p), _difference(lambda x: _rhs(mod, y, x), p), f"{key} jacobian_p")


def test_a_wrong_jacobian_is_caught():
    """The check can fail: a Jacobian with one entry off by 1e-6 relative is reported."""
    mod = _module("two_mode/full")
    y, p = _point(mod, np.random.default_rng(1))
    jac = mod.jacobian.py_func(y, p)
    jac.flat[np.argmax(np.abs(jac))] *= 1 + 1e-5
    with pytest.raises(AssertionError, match="differs"):
        _assert_close(jac, _difference(lambda x: _rhs(mod, x, p), y), "perturbed")


def test_model_jacobian_calls_the_compiled_functions():
    m = ke.load("single_mode", pose=True)
    p = m.params(m.default_params)
    y = m.state({**m.default_state, "theta": 0.1})
    closed = y[:3]
    mod = m.module
    np.testing.assert_array_equal(m.jacobian(y, p), mod.jacobian.py_func(closed, p))
    np.testing.assert_array_equal(m.jacobian_p(y, p), mod.jacobian_p.py_func(closed, p))
    with pytest.raises(ValueError, match="`y`"):
        m.jacobian(np.zeros((3, 2)), p)


@pytest.mark.slow
@pytest.mark.parametrize("key", KEYS)
def test_compiled_jacobians_equal_their_python_bodies(key):
    mod = _module(key)
    y, p = _point(mod, np.random.default_rng(3))
    np.testing.assert_allclose(mod.jacobian(y, p), mod.jacobian.py_func(y, p), rtol=1e-13, atol=1e-13)
    np.testing.assert_allclose(mod.jacobian_p(y, p), mod.jacobian_p.py_func(y, p), rtol=1e-13, atol=1e-13)


@pytest.mark.parametrize("method", ["scipy:BDF", "scipy:Radau"])  # LSODA: only once stiff
def test_implicit_scipy_methods_use_the_generated_jacobian(method, monkeypatch):
    """SciPy's implicit methods call the generated Jacobian, and the run agrees with DOP853."""
    sim = importlib.import_module("knifeedge.simulate")
    calls = []
    original = sim._scipy_jacobian

    def counted(model, p):
        jac = original(model, p)
        return lambda t, y: calls.append(t) or jac(t, y)

    monkeypatch.setattr(sim, "_scipy_jacobian", counted)
    m = ke.load("single_mode")
    p = m.params(m.default_params)
    y0 = m.state({**m.default_state, "theta": 0.05})
    ref = ke.simulate(m, y0, (0.0, 20.0), p, rtol=1e-10)
    run = ke.simulate(m, y0, (0.0, 20.0), p, method=method, rtol=1e-8, atol=1e-10)
    assert calls, f"{method} never called the generated Jacobian"
    np.testing.assert_allclose(run.y[:, -1], ref.y[:, -1], rtol=0, atol=1e-5)


def test_a_module_written_before_the_jacobians_says_regenerate():
    import types

    m = ke.load("single_mode")
    dropped = ("jacobian", "jacobian_p", "invariant_gradients", "steady_state", "STEADY_FAMILIES", "STATE_INVARIANTS")
    old = ke.Model(types.SimpleNamespace(**{k: v for k, v in vars(m.module).items() if k not in dropped}), False)
    p = m.params(m.default_params)
    y = m.state(theta=0.01, theta_dot=0.0, phi_dot=0.1)
    for call in (lambda: old.jacobian(y, p), lambda: ke.linearize(old, y, p), lambda: ke.lyapunov(old, y, p, 1.0)):
        with pytest.raises(ValueError, match="regenerate"):
            call()
