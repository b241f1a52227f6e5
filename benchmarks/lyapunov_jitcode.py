"""jitcode's Lyapunov exponents (``jitcode_lyap``) on the celt's equations: the optional peer of
``benchmarks.lyapunov_speed``.

The equations are the derivation's own (``derivation.rigid.equations(celt())``): ``dn/dt = n x omega`` and
``M(n) domega/dt = f(n, omega)``, with the parameters' values substituted.  jitcode differentiates its right-hand
side symbolically; fed the expanded rates it did not finish its set-up in 9 minutes (NOTES.md), so here it gets
the entries of ``M`` and ``f`` as common subexpressions (``sympy.cse``, jitcode's ``helpers``) and the 3 x 3 solve
by Cramer's rule on helper symbols: nothing is expanded, and jitcode differentiates through the helpers by the
chain rule.  State ``(n, omega)`` (6 components: one more exponent than the physical phase space, the invariant
``|n| = 1``'s, which is 0).
"""
from __future__ import annotations

import time

import numpy as np

try:  # optional peer
    import jitcode
    import symengine as se
except ImportError:  # pragma: no cover - depends on the machine
    jitcode = None

NOTE = "jitcode is not installed (pip install jitcode; it needs a C compiler); its Lyapunov exponents are skipped"


def equations(p_values: dict) -> tuple:
    """``(f_sym, helpers)`` for jitcode: the celt's rates in jitcode's ``y(i)`` with the parameters' values."""
    import sympy as sp

    from knifeedge.derive.celt import celt
    from knifeedge.derive.rigid import N_VEC, OMEGA, equations as rigid_equations

    body = celt()
    parts = rigid_equations(body)
    values = {s: p_values[str(s)] for s in body.params}
    M = parts["mass_matrix"].xreplace(values)
    f = parts["forcing"].xreplace(values)
    wd = parts["omega_dot_symbols"]
    M = M.xreplace(dict.fromkeys(wd, 0))
    y = [se.Symbol(f"_y{i}") for i in range(6)]
    entries = list(M) + list(f)
    replacements, reduced = sp.cse(entries, symbols=sp.numbered_symbols("_c"))
    names = [se.Symbol(f"M{i}{j}") for i in range(3) for j in range(3)] + [se.Symbol(f"f{i}") for i in range(3)]
    to_y = {s: y[i] for i, s in enumerate(list(N_VEC) + list(OMEGA))}

    def conv(e):
        return se.sympify(e).subs(to_y)

    helpers = [(se.Symbol(str(a)), conv(b)) for a, b in replacements]
    helpers += [(nm, conv(e)) for nm, e in zip(names, reduced)]
    Ms = se.Matrix(3, 3, names[:9])
    fs = se.Matrix(3, 1, names[9:])
    det = se.Symbol("det_M")
    helpers.append((det, Ms.det()))
    rates_w = []
    for k in range(3):
        Mk = se.Matrix(3, 3, [fs[i] if j == k else Ms[i, j] for i in range(3) for j in range(3)])
        rates_w.append(Mk.det() / det)
    n, w = y[:3], y[3:]
    rates_n = [n[1] * w[2] - n[2] * w[1], n[2] * w[0] - n[0] * w[2], n[0] * w[1] - n[1] * w[0]]
    sym_y = jitcode.y
    back = {y[i]: sym_y(i) for i in range(6)}
    f_sym = [se.sympify(e).subs(back) for e in rates_n + rates_w]
    helpers = [(a, se.sympify(b).subs(back)) for a, b in helpers]
    return f_sym, helpers


def race(m, p, y0, span: float, rtol: float, tau: float, knifeedge_seconds: float, knifeedge_exponents) -> dict:
    """Set up and run ``jitcode_lyap`` (all 6 exponents, its DOP853 at ``rtol``, re-orthonormalized every
    ``tau``) from ``y0`` (the celt's closed state) over ``span``; times the set-up and the run apart."""
    if jitcode is None:
        print(NOTE)
        return {"note": NOTE}
    t = time.perf_counter()
    f_sym, helpers = equations(dict(zip(m.param_names, map(float, p))))
    t_equations = time.perf_counter() - t
    t = time.perf_counter()
    ode = jitcode.jitcode_lyap(f_sym, helpers=helpers, n_lyap=6, simplify=False, verbose=False)
    ode.set_integrator("dop853", rtol=rtol, atol=rtol * 1e-2)
    ode.set_initial_value(np.asarray(y0[:6], dtype=float), 0.0)
    t_setup = time.perf_counter() - t
    t = time.perf_counter()
    lyaps = []
    for time_k in np.arange(tau, span + 0.5 * tau, tau):
        lyaps.append(ode.integrate(time_k)[1])  # local exponents over one interval tau
    t_run = time.perf_counter() - t
    exponents = np.sort(np.mean(np.array(lyaps), axis=0))[::-1]  # equal intervals: the plain mean
    return {"jitcode": getattr(jitcode, "__version__", "installed"), "span": span, "rtol": rtol, "tau": tau,
            "seconds_equations": t_equations, "seconds_setup": t_setup, "seconds_run": t_run,
            "exponents": [float(x) for x in exponents], "knifeedge_full_seconds": knifeedge_seconds,
            "knifeedge_exponents": list(knifeedge_exponents), "ratio_run_jitcode_vs_knifeedge": t_run / knifeedge_seconds}
