"""knifeedge against PyDy on PyDy's own kind of system: the Kane & Levinson (1982) rattleback.

``python -m benchmarks.rigid_pydy [--out DIR] [--repeats N]``

Side by side in one run:

- **knifeedge**: ``derivation.rigid.derive`` + the emitter (build and generate),
  the first compiled call (numba compile or cache load), and 5 s of motion with
  the compiled DOP853 at rtol 1e-12;
- **PyDy** (optional peer: ``pip install pydy cython``; skipped with a note when
  absent): the same body written with ``sympy.physics.mechanics.KanesMethod``
  (Euler angles ``Rz(q1) Rx(q2) Ry(q3)``, body angular velocity as generalized
  speeds, centre-of-mass velocity as dependent speeds with the two rolling
  constraints, height of the centre of mass holonomic), ``System.generate_ode_function``
  with the Cython generator, and 5 s with SciPy's DOP853 at rtol 1e-12.

Each run's error is the largest difference of ``n`` and ``omega . n`` at 5 s
against a converged reference (the independent Newton--Euler formulation of
``tests/rigid_reference.py`` at rtol 1e-13).  Writes ``rigid_pydy.json``.
"""
from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
import rigid_reference as ref  # noqa: E402

PYDY_NOTE = "pydy is not installed (pip install pydy cython); its side of the comparison is skipped"
T_END = 5.0
RTOL, ATOL = 1e-12, 1e-14
TILT = math.radians(0.5)
SPIN = 5.0


def _n0():
    return np.array([math.cos(TILT) * math.sin(TILT), math.sin(TILT), math.cos(TILT) ** 2])


def reference(p) -> tuple:
    s0 = np.concatenate([_n0(), [0.0, 0.0, SPIN]])
    sol = solve_ivp(lambda t, s: ref._rhs(s, *ref.unpack(p)), (0, T_END), s0, method="DOP853", rtol=1e-13,
                    atol=1e-15)
    n, w = sol.y[:3, -1], sol.y[3:6, -1]
    return n, float(n @ w)


def _error(n, spin, want) -> float:
    return max(float(np.abs(np.asarray(n) - want[0]).max()), abs(spin - want[1]))


def knifeedge_side(repeats: int, want) -> dict:
    """Build and generate (SymPy), first call (compile or cache load), median simulate time, error."""
    import knifeedge as ke
    from knifeedge.derive import codegen, rigid, rigid_emit
    from knifeedge.derive.celt import celt

    t0 = time.perf_counter()
    system = rigid.derive(celt())
    source = codegen.module_text(rigid_emit.module_parts(system))
    build = time.perf_counter() - t0
    m = ke.load("celt")
    p = m.preset("kane_levinson_1982")
    y0 = m.initial_state(n0=_n0(), omega0=(0.0, 0.0, SPIN))
    t0 = time.perf_counter()
    ke.simulate(m, y0, (0.0, 1e-3), p, rtol=RTOL, atol=ATOL)
    first = time.perf_counter() - t0
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        r = ke.simulate(m, y0, (0.0, T_END), p, rtol=RTOL, atol=ATOL, t_eval=[T_END])
        times.append(time.perf_counter() - t0)
    y = r.y[:, -1]
    n = y[:3] / np.linalg.norm(y[:3])
    return {"build_and_generate_s": build, "source_chars": len(source), "first_call_s": first,
            "simulate_s": statistics.median(times), "nfev": r.nfev, "error": _error(n, float(n @ y[3:6]), want),
            "us_per_eval": 1e6 * statistics.median(times) / r.nfev}


def pydy_system(p):
    """The rattleback in sympy.physics.mechanics (Kane's method) and a PyDy System."""
    import sympy as sp
    import sympy.physics.mechanics as me
    from pydy.system import System

    a, b, c, h, m, g, Ixx, Iyy, Izz, Ixy, Ixz, Iyz, _ = sp.symbols("a b c h m g I_xx I_yy I_zz I_xy I_xz I_yz sigma")
    q1, q2, q3, x, y = me.dynamicsymbols("q1 q2 q3 x y")
    u1, u2, u3, u4, u5 = me.dynamicsymbols("u1 u2 u3 u4 u5")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [q1, N.z])
    B = A.orientnew("B", "Axis", [q2, A.x])
    C = B.orientnew("C", "Axis", [q3, B.y])
    w_q = C.ang_vel_in(N)
    kd = [w_q.dot(C.x) - u1, w_q.dot(C.y) - u2, w_q.dot(C.z) - u3, x.diff() - u4, y.diff() - u5]
    C.set_ang_vel(N, u1 * C.x + u2 * C.y + u3 * C.z)
    n = [N.z.dot(C.x), N.z.dot(C.y), N.z.dot(C.z)]
    d = sp.sqrt(a**2 * n[0] ** 2 + b**2 * n[1] ** 2 + c**2 * n[2] ** 2)
    r = (-a**2 * n[0] / d) * C.x + (-b**2 * n[1] / d) * C.y + (h - c**2 * n[2] / d) * C.z  # contact from G
    zG = -r.dot(N.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", x * N.x + y * N.y + zG * N.z)
    G.set_vel(N, u4 * N.x + u5 * N.y + zG.diff(me.dynamicsymbols._t) * N.z)
    slip = G.vel(N) + C.ang_vel_in(N).cross(r)
    nh = [slip.dot(N.x), slip.dot(N.y)]
    body = me.RigidBody("body", G, C, m, (me.inertia(C, Ixx, Iyy, Izz, Ixy, Iyz, Ixz), G))
    kane = me.KanesMethod(N, q_ind=[q1, q2, q3, x, y], u_ind=[u1, u2, u3], u_dependent=[u4, u5], kd_eqs=kd,
                          velocity_constraints=nh)
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    names = dict(zip((a, b, c, h, m, g, Ixx, Iyy, Izz, Ixy, Ixz, Iyz), p[:12]))
    return System(kane, constants=names), (n, C, N, q1, q2, q3, u1, u2, u3, u4, u5, r)


def pydy_side(p, repeats: int, want) -> dict:
    import sympy as sp

    t0 = time.perf_counter()
    system, parts = pydy_system(p)
    build = time.perf_counter() - t0
    n_expr, C, N, q1, q2, q3, u1, u2, u3, u4, u5, r = parts
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        rhs = system.generate_ode_function(generator="cython", tmp_dir=tmp)
    generate = time.perf_counter() - t0
    states = system.states
    # initial state: R = Rz(q1) Rx(q2) Ry(q3) gives n = (-sin q3 cos q2, sin q2, cos q3 cos q2)
    w0 = [0.0, 0.0, SPIN]
    vals = {q1: 0.0, q2: TILT, q3: -TILT, u1: w0[0], u2: w0[1], u3: w0[2]}
    consts = dict(system.constants)
    # dependent speeds from the rolling constraint: v_G = -omega x r
    vG = -C.ang_vel_in(N).cross(r)
    vals[u4], vals[u5] = (float(sp.N(vG.dot(e).subs(vals).subs(consts))) for e in (N.x, N.y))
    x0 = np.array([float(vals.get(s, 0.0)) for s in states])
    pvec = np.array([float(system.constants[s]) for s in system.constants_symbols])
    f = lambda t, xx: rhs(xx, t, pvec)  # noqa: E731
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        sol = solve_ivp(f, (0.0, T_END), x0, method="DOP853", rtol=RTOL, atol=ATOL, t_eval=[T_END])
        times.append(time.perf_counter() - t0)
    end = dict(zip(states, sol.y[:, -1]))
    sub = {q1: end[q1], q2: end[q2], q3: end[q3]}
    n = np.array([float(sp.N(e.subs(sub))) for e in n_expr])
    w = np.array([end[u1], end[u2], end[u3]])
    return {"build_s": build, "generate_and_compile_s": generate, "simulate_s": statistics.median(times),
            "nfev": int(sol.nfev), "error": _error(n, float(n @ w), want),
            "us_per_eval": 1e6 * statistics.median(times) / sol.nfev}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.rigid_pydy", description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=Path(__file__).resolve().parent / "results")
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args(argv)
    p = np.array([0.20, 0.03, 0.02, 0.01, 1.0, 9.81, 2e-4, 1.6e-3, 1.7e-3, 2e-5, 0.0, 0.0, 0.0])
    want = reference(p)
    out = {"t_end": T_END, "rtol": RTOL, "atol": ATOL, "knifeedge": knifeedge_side(args.repeats, want)}
    print("knifeedge", out["knifeedge"], flush=True)
    try:
        import pydy  # noqa: F401
    except ImportError:
        out["pydy"] = PYDY_NOTE
    else:
        out["pydy"] = pydy_side(p, args.repeats, want)
        out["pydy_version"] = pydy.__version__
        out["simulate_speedup"] = out["pydy"]["simulate_s"] / out["knifeedge"]["simulate_s"]
    print("pydy", out["pydy"], flush=True)
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "rigid_pydy.json").write_text(json.dumps(out, indent=1, default=float))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
