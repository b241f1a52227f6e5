"""Generated numba code against the symbolic expressions it was printed from.

Every generated module (every model, every fidelity) is evaluated at random
states and parameters and compared with ``sympy.lambdify`` of the derived
expressions: this catches printer errors (operator precedence, rational
constants, powers) that a symbolic comparison cannot see.  The integrators' form of
the right-hand side, ``rhs_q_into`` with the parameter-only subexpressions
precomputed by ``constants(p)``, is checked against the same expressions.
"""
import importlib

import numpy as np
import pytest
import sympy as sp

from knifeedge.derive.engine import ReducedSystem

from knifeedge.generated import MODULES

# the session's symbolic derivation of every model (`systems`) is built once, in one test worker
# every generated module against the derivation it was printed from: symbolic work, in the slow checks
pytestmark = [pytest.mark.xdist_group("symbolic"), pytest.mark.slow]

#: every generated module, from the registry (a new model is checked without editing this file)
KEYS = [f"{m}/{f}" for m, f in sorted(MODULES)]


def _module(key):
    from knifeedge.generated import MODULES

    return importlib.import_module(f"knifeedge.generated.{MODULES[tuple(key.split('/'))]}")


def _points(rng, n_state, params, n=25):
    for _ in range(n):
        y = rng.uniform(-0.8, 0.8, n_state)
        p = rng.uniform(0.4, 2.5, len(params))
        for i, s in enumerate(params):
            if s.name == "alpha":
                p[i] = rng.uniform(-3, 3)
        yield y, p


def _close(a, b):
    a, b = np.atleast_1d(np.asarray(a, float)), np.atleast_1d(np.asarray(b, float)).ravel()
    return np.max(np.abs(a - b)) <= 1e-12 * max(1.0, np.max(np.abs(b)))


@pytest.mark.parametrize("key", KEYS)
def test_generated_equals_lambdified(key, systems):
    model, fidelity = key.split("/")
    if (model, fidelity) not in systems:
        pytest.skip(f"{key} is not derived")
    system = systems[(model, fidelity)]
    mod = _module(key)
    params = list(system.spec.params)
    state = list(system.state)
    assert tuple(map(str, state)) == mod.STATE_NAMES
    assert tuple(map(str, params)) == mod.PARAM_NAMES
    rhs = sp.lambdify([state, params], system.state_rhs(), "math")
    energy = sp.lambdify([state, params], system.energy, "math")
    checks = [(mod.rhs, lambda y, p: rhs(y, p)), (mod.energy, lambda y, p: energy(y, p))]
    if isinstance(system, ReducedSystem) and len(system.multipliers):  # small-tilt rigid fidelities keep none
        lam = sp.lambdify([state, params], list(system.multipliers), "math")
        checks.append((mod.multipliers, lambda y, p: lam(y, p)))
    def rhs_q(t, y, p):  # the integrators' form: parameter-only subexpressions precomputed once
        ds = np.empty(len(state))
        mod.rhs_q_into(t, y, mod.constants(p), ds)
        return ds

    checks.append((rhs_q, lambda y, p: rhs(y, p)))
    rng = np.random.default_rng(7)
    for y, p in _points(rng, len(state), params):
        assert np.array_equal(mod.constants(p)[:len(params)], p), f"{key}: constants(p) must start with p"
        for compiled, reference in checks:
            assert _close(compiled(0.0, y, p) if compiled in (mod.rhs, rhs_q) else compiled(y, p), reference(y, p)), \
                f"{key}: {compiled.__name__} differs from the derived expression at y={y}, p={p}"
    if isinstance(system, ReducedSystem) and system.spec.pose:
        pose = list(system.spec.pose)
        rates = [system.pose_rates[q] for q in pose]
        ref = sp.lambdify([state + pose, params], system.state_rhs() + rates, "math")
        for y, p in _points(rng, len(state) + len(pose), params, n=10):
            assert _close(mod.rhs_pose(0.0, y, p), ref(y, p)), f"{key}: rhs_pose differs"
            ds = np.empty(len(y))
            mod.rhs_pose_q_into(0.0, y, mod.constants(p), ds)
            assert _close(ds, ref(y, p)), f"{key}: rhs_pose_q_into differs"
