"""Bad input is refused before any work, with an error naming the argument in backticks.

Each case is what a demanding user tries: wrong types, NaN, inf, negative, huge,
empty, wrong shapes, unknown names.  The array and mapping forms of the state and
the parameters follow one rule: a real number is an int or a float (Python or
NumPy); ``bool``, complex and strings are refused in both forms.
"""
import math

import numpy as np
import pytest

import knifeedge as ke
from knifeedge.integrators import Status

P2 = dict(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4)
Y2 = dict(theta1=1e-3, theta2=1e-3, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1)


@pytest.fixture(scope="module")
def two():
    return ke.load("two_mode", "full")


def _call(m, **kw):
    args = dict(y0=Y2, t_span=(0.0, 10.0), p=P2)
    args.update(kw)
    return ke.simulate(m, args.pop("y0"), args.pop("t_span"), args.pop("p"), **args)


BAD_SIMULATE = [
    # (keyword arguments, exception, text the message must contain)
    # a fixed step below the resolution of t: its step count overflowed 64 bits and became one giant step
    (dict(method="RK4", h=1e-17, t_span=(0.0, 300.0)), ValueError, "`h`"),
    (dict(method="gauss4", h=1e-300), ValueError, "`h`"),
    (dict(method="RK4", h=1e-3, t_span=(1e15, 1e15 + 10)), ValueError, "`h`"),
    (dict(method="RK4", h=0.0), ValueError, "`h`"),
    (dict(method="RK4", h=-0.1), ValueError, "`h`"),
    (dict(method="RK4", h=math.nan), ValueError, "`h`"),
    (dict(method="RK4", h=math.inf), ValueError, "`h`"),
    (dict(method="RK4", h="0.1"), TypeError, "`h`"),
    (dict(method="RK4", h=True), TypeError, "`h`"),
    (dict(method="RK4", h=0.1j), TypeError, "`h`"),
    # tolerances of one or more: an error estimate means nothing there
    (dict(rtol=10), ValueError, "`rtol`"),
    (dict(rtol=1.0), ValueError, "`rtol`"),
    (dict(rtol=1e300), ValueError, "`rtol`"),
    (dict(rtol=math.inf), ValueError, "`rtol`"),
    (dict(rtol=math.nan), ValueError, "`rtol`"),
    (dict(rtol=1e-17), ValueError, "`rtol`"),
    (dict(rtol=-1e-6), ValueError, "`rtol`"),
    (dict(rtol="1e-6"), TypeError, "`rtol`"),
    (dict(rtol=1e-6 + 0j), TypeError, "`rtol`"),
    (dict(rtol=np.bool_(True)), TypeError, "`rtol`"),
    (dict(atol=1e300), ValueError, "`atol`"),
    (dict(atol=10.0), ValueError, "`atol`"),
    (dict(atol=1), ValueError, "`atol`"),
    (dict(atol=[1e-12] * 4 + [2.0]), ValueError, "`atol`"),
    (dict(atol=0.0), ValueError, "`atol`"),
    (dict(atol=[1e-12] * 4), ValueError, "`atol`"),
    (dict(atol=np.full(5, 1e-12 + 0j)), TypeError, "`atol`"),
    (dict(atol=np.ones(5, dtype=bool)), TypeError, "`atol`"),
    (dict(atol=["1e-12"] * 5), TypeError, "`atol`"),
    (dict(atol="1e-12"), TypeError, "`atol`"),
    (dict(atol=None), TypeError, "`atol`"),
    # the array form follows the mapping form's rule
    (dict(y0=np.array([1e-3 + 1j, 1e-3, 0, 0, 0.1])), TypeError, "`y0`"),
    (dict(y0=[True, 0, 0, 0, True]), TypeError, "`y0`"),
    (dict(y0=np.array([True, False, False, False, True])), TypeError, "`y0`"),
    (dict(y0=["1e-3", "1e-3", "0", "0", "0.1"]), TypeError, "`y0`"),
    (dict(y0="1e-3"), TypeError, "`y0`"),
    (dict(y0=[1e-3, 1e-3, 0, 0, None]), TypeError, "`y0`"),
    (dict(y0=[1e-3, 1e-3, 0, 0, 10**400]), ValueError, "`y0`"),
    (dict(y0=[1e-3, 1e-3, 0, 0, math.nan]), ValueError, "`y0`"),
    (dict(y0=[1e-3, 1e-3, 0, 0]), ValueError, "`y0`"),
    (dict(y0=[[1e-3, 1e-3, 0, 0, 0.1]]), ValueError, "`y0`"),
    (dict(y0=[]), ValueError, "`y0`"),
    (dict(y0={**Y2, "theta1": True}), TypeError, "`theta1`"),
    (dict(y0={**Y2, "theta1": 1e-3 + 0j}), TypeError, "`theta1`"),
    (dict(y0={**Y2, "theta1": "1e-3"}), TypeError, "`theta1`"),
    (dict(p=np.array([1, 1, 2, 0.5, 0.7 + 1j])), TypeError, "`p`"),
    (dict(p=["1", "1", "2", "0.5", "0.7"]), TypeError, "`p`"),
    (dict(p=[True, 1, 2, 0.5, 0.7]), TypeError, "`p`"),
    (dict(p={**P2, "D": True}), TypeError, "`D`"),
    (dict(p={**P2, "D": "0.5"}), TypeError, "`D`"),
    (dict(p={**P2, "D": -0.5}), ValueError, "`D`"),
    (dict(p=[1, 1, 2, -0.5, 0.7]), ValueError, "`D`"),
    (dict(p={**P2, "E": 1.0}), ValueError, "`p`"),
    # times and step budget
    (dict(t_span=(False, True)), TypeError, "`t_span`"),
    (dict(t_span=(0, 1j)), TypeError, "`t_span`"),
    (dict(t_span=("0", "10")), TypeError, "`t_span`"),
    (dict(t_span=(0.0, 1.0, 2.0)), TypeError, "`t_span`"),
    (dict(t_span=10.0), TypeError, "`t_span`"),
    (dict(t_span=(10.0, 0.0)), ValueError, "`t_span`"),
    (dict(t_span=(0.0, math.inf)), ValueError, "`t_span`"),
    (dict(t_eval=["1", "2"]), TypeError, "`t_eval`"),
    (dict(t_eval=[1.0, 2.0 + 1j]), TypeError, "`t_eval`"),
    (dict(t_eval=[[1.0, 2.0]]), ValueError, "`t_eval`"),
    (dict(t_eval=[2.0, 1.0]), ValueError, "`t_eval`"),
    (dict(t_eval=[1.0, 11.0]), ValueError, "`t_eval`"),
    (dict(t_eval=[1.0, math.nan]), ValueError, "`t_eval`"),
    (dict(t_eval="1"), TypeError, "`t_eval`"),
    (dict(max_steps=2**70), ValueError, "`max_steps`"),
    (dict(max_steps=0), ValueError, "`max_steps`"),
    (dict(max_steps=1e6), TypeError, "`max_steps`"),
    (dict(max_steps=True), TypeError, "`max_steps`"),
    (dict(max_step=0.0), ValueError, "`max_step`"),
    (dict(max_step=math.nan), ValueError, "`max_step`"),
    (dict(max_step="1"), TypeError, "`max_step`"),
    (dict(method="RK5"), ValueError, "`method`"),
    (dict(method=None), ValueError, "`method`"),
    (dict(method="RK4"), ValueError, "`h`"),
    (dict(method="scipy:RK45", h=0.1), ValueError, "`h`"),
    (dict(error_control="modes"), ValueError, "`error_control`"),
]


@pytest.mark.parametrize("kw,exc,text", BAD_SIMULATE, ids=[repr(c[0])[:60] for c in BAD_SIMULATE])
def test_simulate_refuses_bad_input_naming_it(two, kw, exc, text):
    with pytest.raises(exc) as info:
        _call(two, **kw)
    assert text in str(info.value)


def test_array_and_mapping_forms_accept_the_same_numbers(two):
    """NumPy scalars, Python ints and 0-d arrays are numbers in both forms; the results agree."""
    names = two.state_names
    as_map = {n: np.float32(v) if i % 2 else np.array(v) for i, (n, v) in enumerate(Y2.items())}
    a = two.check_state(as_map)
    b = two.check_state([np.float32(Y2[n]) if i % 2 else np.array(Y2[n]) for i, n in enumerate(names)])
    np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(two.check_params([1, 1, 2, 0.5, np.float64(math.pi / 4)]),
                                  two.check_params({**P2, "g": 1, "ell": np.int64(1), "L": 2}))


def test_smallest_fixed_step_still_accepted_and_step_budget_reported(two):
    """A step just above the resolution of t is legal; a budget too small for it is a reported failure."""
    r = _call(two, method="RK4", h=1e-9, t_span=(0.0, 1.0), max_steps=1000)
    assert not r.success and r.outcome is Status.MAX_STEPS and r.nsteps == 1000
    assert r.t[-1] == pytest.approx(1e-6)
