"""The straight-line solves of the numeric elimination (derivation/kkt_emit.py) against numpy's LAPACK solves.

The program binds symbols to expressions of earlier symbols; evaluating it line by line must give what
``numpy.linalg.solve`` gives for the same numbers, also where the leading entry of a column is zero at run time
(a row must be exchanged: without pivoting the solve divides by zero) and for matrices whose entries are
structurally zero (no select is written for them).
"""
import math

import numpy as np
import pytest
import sympy as sp

from knifeedge.derive import kkt_emit
from knifeedge.derive.jacobian import partial


def _run(prog, values: dict) -> dict:
    """Evaluate a program's lines in floating point (the entries given in ``values``)."""
    env = {k: sp.Float(v) for k, v in values.items()}
    for s, e in prog.lines:
        env[s] = sp.Float(e.xreplace(env))
    return env


def _value(x, env):
    return float(x) if x.is_Number else float(env[x])


@pytest.mark.parametrize("seed", range(4))
def test_lu_solve_matches_numpy_with_run_time_pivoting(seed):
    rng = np.random.default_rng(seed)
    m = 4
    A = sp.Matrix(m, m, lambda i, j: sp.Symbol(f"a{i}{j}", real=True))
    b = [sp.Symbol(f"b{i}", real=True) for i in range(m)]
    prog = kkt_emit.Program()
    (x,) = kkt_emit.lu_solve(prog, [list(A.row(i)) for i in range(m)], [b])
    for trial in range(3):
        An = rng.uniform(-1, 1, (m, m))
        if trial == 1:
            An[0, 0] = 0.0  # the first pivot is zero: a row exchange is needed
        if trial == 2:
            An[:, 0] = [0.0, 1e-9, 0.0, 0.7]  # partial pivoting picks 0.7, not the tiny entry
        bn = rng.uniform(-1, 1, m)
        env = _run(prog, {**{A[i, j]: An[i, j] for i in range(m) for j in range(m)},
                          **{b[i]: bn[i] for i in range(m)}})
        got = np.array([_value(xi, env) for xi in x])
        np.testing.assert_allclose(got, np.linalg.solve(An, bn), rtol=1e-12, atol=1e-12)


def test_lu_solve_skips_structural_zeros():
    """A triangular block (the rolling constraints at the representative pose) needs no select at all."""
    a, b, c, r0, r1 = sp.symbols("a b c r0 r1", real=True)
    prog = kkt_emit.Program()
    (x,) = kkt_emit.lu_solve(prog, [[sp.S.Zero, a], [b, c]], [[r0, r1]])
    assert not any(e.has(sp.Piecewise) for _, e in prog.lines)
    env = _run(prog, {a: 2.0, b: 4.0, c: 1.0, r0: 3.0, r1: 5.0})
    np.testing.assert_allclose([_value(xi, env) for xi in x], np.linalg.solve([[0, 2.0], [4.0, 1.0]], [3.0, 5.0]))


def test_ldl_solve_matches_numpy():
    rng = np.random.default_rng(5)
    k = 3
    S = {(i, j): sp.Symbol(f"m{i}{j}", real=True) for i in range(k) for j in range(i, k)}
    f = [sp.Symbol(f"f{i}", real=True) for i in range(k)]
    prog = kkt_emit.Program()
    a = kkt_emit.ldl_solve(prog, S, f)
    B = rng.uniform(-1, 1, (k, k))
    Mn = B @ B.T + k * np.eye(k)
    fn = rng.uniform(-1, 1, k)
    env = _run(prog, {**{s: Mn[i, j] for (i, j), s in S.items()}, **dict(zip(f, fn))})
    np.testing.assert_allclose([_value(x, env) for x in a], np.linalg.solve(Mn, fn), rtol=1e-13)


def test_partial_equals_sympy_diff():
    """The Jacobians' chain rule on a program's lines gives SymPy's derivative (the same expression)."""
    x, y, z = sp.symbols("x y z", real=True)
    cases = [x * y + sp.sin(x * z), sp.cos(x) ** 2 / y, sp.sqrt(x ** 2 + y) * z, (x + y) ** 3 - 2 * x,
             sp.Piecewise((x * y, sp.Abs(x) > sp.Abs(y)), (z, True)), sp.exp(x * y), sp.Integer(3), z]
    for e in cases:
        for v in (x, y):
            assert sp.simplify(partial(e, v) - sp.diff(e, v)) == 0, (e, v)
    assert partial(x * y + sp.sin(x * z), x) == sp.diff(x * y + sp.sin(x * z), x)
    assert math.isclose(float(partial(sp.sqrt(x ** 2 + y) * z, x).subs({x: 0.3, y: 2.0, z: 1.5})),
                        0.3 * 1.5 / math.sqrt(2.09))


def test_half_powers_use_the_bound_root():
    """``x**(-3/2)`` and ``x**(-5/2)`` of a symbol whose ``x**(-1/2)`` the program binds are written as that root
    cubed and to the fifth (products, not a call of ``pow``; the Whipple bicycle's right-hand side had three such
    calls), with the value of the power (1/sqrt(x)**k = x**(-k/2)); a power without a bound root is left as it is."""
    from knifeedge.derive.codegen import code

    x, y = sp.symbols("x y", real=True)
    base = x * y + 1
    prog = kkt_emit.Program()
    out = prog.cse([y / sp.sqrt(base), x / sp.sqrt(base), base ** sp.Rational(-3, 2) * y + base ** sp.Rational(-5, 2),
                    (x + 2) ** sp.Rational(-3, 2) + y])
    text = "\n".join(f"{s} = {code(e)}" for s, e in prog.lines)
    roots = [s for s, e in prog.lines if e.is_Pow and e.exp == sp.Rational(-1, 2)]
    assert len(roots) == 1 and "**((-3.0/2.0))" in text and text.count("**((-") == 1, text  # only (x + 2)**(-3/2)
    r = roots[0].name
    assert f"({r}*{r}*{r})" in text and f"{r}**5" in text, text
    values = {x: 0.3, y: -1.7}
    env = _run(prog, values)
    b = 0.3 * -1.7 + 1
    expected = [-1.7 / math.sqrt(b), 0.3 / math.sqrt(b), b**-1.5 * -1.7 + b**-2.5, 2.3**-1.5 - 1.7]
    assert [_value(o, env) for o in out] == pytest.approx(expected, rel=1e-14)
