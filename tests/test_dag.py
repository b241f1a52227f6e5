"""derivation/dag.py: derivatives and values of large expressions walked as graphs, against SymPy's own
``diff`` and ``evalf`` (the reference), on expressions of the forms the front ends build: products of sums of
trigonometric functions, square roots, shared subtrees."""
import random

import mpmath
import pytest
import sympy as sp

from knifeedge.derive import dag

x, y, z = sp.symbols("x y z", real=True)
a = sp.Symbol("a", positive=True)


def _random_expression(rng: random.Random, depth: int) -> sp.Expr:
    if depth == 0:
        return rng.choice([x, y, z, a, sp.Rational(rng.randint(1, 9), rng.randint(1, 9))])
    e1, e2 = _random_expression(rng, depth - 1), _random_expression(rng, depth - 1)
    return rng.choice([e1 + e2, e1 * e2, sp.sin(e1) * e2, sp.cos(e1) + e2, e1**2 - e2, sp.sqrt(a + e1**2) * e2,
                       e1 / (a + e2**2), e1 ** 3 * sp.cos(e2)])


@pytest.mark.parametrize("seed", range(6))
def test_derivative_equals_sympys(seed):
    rng = random.Random(seed)
    e = _random_expression(rng, 3)
    e = e * e.subs(x, y) + e  # shared subtrees
    point = {x: sp.Rational(3, 7), y: sp.Rational(-2, 5), z: sp.Rational(5, 11), a: sp.Rational(13, 10)}
    for v in (x, y, z, a):
        ours, theirs = dag.derivative(e, v), sp.diff(e, v)
        assert abs(sp.N(ours.xreplace(point) - theirs.xreplace(point), 40)) < 1e-30


def test_values_equal_evalf():
    rng = random.Random(7)
    exprs = [_random_expression(rng, 4) for _ in range(6)] + [sp.pi * x, sp.Abs(y - x), sp.exp(z) + sp.log(a)]
    point = {x: sp.Rational(3, 7), y: sp.Rational(-2, 5), z: sp.Float("0.45", 30), a: sp.Rational(13, 10)}
    with mpmath.workdps(dag.DIGITS):
        values = dag.values(exprs, point)
    for e, v in zip(exprs, values):
        assert abs(v - mpmath.mpmathify(sp.N(e.xreplace(point), 40))) < 1e-27 * (1 + abs(v))


def test_a_symbol_without_a_value_is_an_error():
    with pytest.raises(TypeError):
        dag.values([x + y], {x: 1})
