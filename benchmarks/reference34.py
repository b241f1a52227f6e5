"""A 34-digit reference for the rolling rattleback: Newton--Euler equations integrated in mpmath.

The double-precision checks of the celt compare two formulations (the
front end's closed form in ``generated/celt_full.py`` and the Newton--Euler
equations of ``tests/rigid_reference.py``).  Two double-precision runs that
agree could share an error of the integrator; this script confirms them with
a third run in 45-digit arithmetic (34 digits asked for, 11 guard digits: the step control must stay clear of round-off):

* the equations are those of ``tests/rigid_reference.py`` (Kane & Levinson
  1982; Garcia & Hubbard 1988), rewritten on ``mpmath.mpf`` scalars, with the
  dissipated work ``W' = sigma |omega|^2`` carried as a seventh state;
* the integrator is Gragg--Bulirsch--Stoer: the modified midpoint rule with
  ``2, 4, ..., 2k`` substeps and Aitken--Neville extrapolation in ``h^2``
  (order ``2k``; Hairer, Norsett & Wanner I, Sect. II.9), every coefficient
  exact, with the step controlled on the difference of the last two
  extrapolations (1e-35 per step); the first tenth of each run is repeated
  with a tolerance 1000 times tighter and the two must agree to the stated digits;
* each zero crossing of ``omega . n`` is found by the secant method on
  single GBS steps from the grid point before it, started from the crossing of
  a double-precision run (a celt reversal is a cluster of crossings that can
  lie 3e-4 s apart, closer than a grid step; the double run says where to look,
  the 34-digit run says where it is; the parity of crossings between grid
  points is checked against the signs at the grid points).

Both the initial state and the parameters are the same doubles the compiled
model gets (exact binary fractions), so the three runs solve the same problem.

Run ``python -m benchmarks.reference34`` (about an hour on one core); it writes
``tests/data/celt_reference34.json``, read by ``tests/test_rigid.py``.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import mpmath as mpm
import numpy as np

DPS = 45
#: share of each run repeated with half the grid step (the two must agree to the stated digits)
CHECK_SPAN = 0.1
#: absolute tolerance of each step on the difference of the last two extrapolations
TOL = mpm.mpf("1e-35")
OUT = Path(__file__).resolve().parents[1] / "tests" / "data" / "celt_reference34.json"
NAMES = ("a", "b", "c", "h", "m", "g", "I_xx", "I_yy", "I_zz", "I_xy", "I_xz", "I_yz", "sigma")

KANE_LEVINSON = dict(a=0.20, b=0.03, c=0.02, h=0.01, m=1.0, g=9.81, I_xx=2e-4, I_yy=1.6e-3, I_zz=1.7e-3,
                     I_xy=2e-5, I_xz=0.0, I_yz=0.0, sigma=0.0)
SCHOEMER = dict(a=(1 + math.sqrt(5)) / 2, b=1.0, c=1.0, h=0.1875, m=0.2, g=9.81, I_xx=0.05796875,
                I_yy=0.09032943, I_zz=0.12236068, I_xy=-0.025, I_xz=0.0, I_yz=0.0, sigma=0.0)
TILT = math.radians(0.5)
N_KL = (math.cos(TILT) * math.sin(TILT), math.sin(TILT), math.cos(TILT) * math.cos(TILT))

#: name -> (parameters, n0, omega0, t_end, first step)
CASES = {
    "kane_levinson_+5": (KANE_LEVINSON, N_KL, (0.0, 0.0, 5.0), 20.0, 0.002),
    "schoemer": (SCHOEMER, (0.0, 0.0, 1.0), (0.01, -0.02, -2.0), 60.0, 0.02),
    "kane_levinson_-5": (KANE_LEVINSON, N_KL, (0.0, 0.0, -5.0), 20.0, 0.002),
    "kane_levinson_+5_damped": ({**KANE_LEVINSON, "sigma": 1e-4}, N_KL, (0.0, 0.0, 5.0), 20.0, 0.002),
}


def initial_state(n0, omega0) -> np.ndarray:
    """(n, omega) in doubles: ``n0`` normalized as the models' ``initial_state`` does."""
    n = np.asarray(n0, dtype=float)
    return np.concatenate((n / np.linalg.norm(n), np.asarray(omega0, dtype=float)))


class Body:
    """The parameters as mpf (exactly the doubles given)."""

    def __init__(self, params: dict):
        f = {k: mpm.mpf(float(params[k])) for k in NAMES}
        self.e2 = (f["a"] ** 2, f["b"] ** 2, f["c"] ** 2)
        self.h, self.m, self.g, self.sigma = f["h"], f["m"], f["g"], f["sigma"]
        self.I = ((f["I_xx"], f["I_xy"], f["I_xz"]), (f["I_xy"], f["I_yy"], f["I_yz"]),
                  (f["I_xz"], f["I_yz"], f["I_zz"]))


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def matvec(A, v):
    return tuple(A[i][0] * v[0] + A[i][1] * v[1] + A[i][2] * v[2] for i in range(3))


def solve3(A, b):
    """Gaussian elimination with partial pivoting on a 3 x 3 system."""
    M = [list(A[i]) + [b[i]] for i in range(3)]
    for k in range(3):
        piv = max(range(k, 3), key=lambda i: abs(M[i][k]))
        M[k], M[piv] = M[piv], M[k]
        for i in range(k + 1, 3):
            f = M[i][k] / M[k][k]
            for j in range(k, 4):
                M[i][j] -= f * M[k][j]
    x = [mpm.mpf(0)] * 3
    for i in (2, 1, 0):
        x[i] = (M[i][3] - sum(M[i][j] * x[j] for j in range(i + 1, 3))) / M[i][i]
    return x


def contact(body: Body, n):
    """Contact point ``r(n) = (0, 0, h) - E n / sqrt(n.E n)`` relative to the centre of mass."""
    en = tuple(e * x for e, x in zip(body.e2, n))
    d = mpm.sqrt(dot(n, en))
    return (-en[0] / d, -en[1] / d, body.h - en[2] / d), en, d


def rhs(body: Body, s):
    """d/dt of (n, omega, W): Newton--Euler in body axes, rolling contact, torque -sigma omega."""
    n, w = s[:3], s[3:6]
    r, en, d = contact(body, n)
    n_dot = cross(n, w)
    en_dot = dot(en, n_dot)
    r_dot = tuple(-e * x / d + y * en_dot / d ** 3 for e, x, y in zip(body.e2, n_dot, en))
    v = tuple(-x for x in cross(w, r))
    rr = dot(r, r)
    lhs = tuple(tuple(body.I[i][j] + body.m * ((rr if i == j else 0) - r[i] * r[j]) for j in range(3))
                for i in range(3))
    a = tuple(-x + y + body.g * z for x, y, z in zip(cross(w, r_dot), cross(w, v), n))
    t1 = cross(w, matvec(body.I, w))
    t2 = cross(r, a)
    b = tuple(-x + body.m * y - body.sigma * z for x, y, z in zip(t1, t2, w))
    w_dot = solve3(lhs, b)
    return list(n_dot) + list(w_dot) + [body.sigma * dot(w, w)]


def energy(body: Body, s):
    n, w = s[:3], s[3:6]
    r, _, _ = contact(body, n)
    v = cross(w, r)
    return (body.m * dot(v, v) + dot(w, matvec(body.I, w))) / 2 - body.m * body.g * dot(r, n)


def gbs_step(body: Body, y, H, k: int):
    """One Gragg--Bulirsch--Stoer step of size ``H``: midpoint rule with 2, 4, ..., 2k substeps, extrapolated."""
    f0 = rhs(body, y)
    table = []
    for j in range(1, k + 1):
        nsub = 2 * j
        h = H / nsub
        z0 = list(y)
        z1 = [a + h * b for a, b in zip(y, f0)]
        for _ in range(nsub - 1):
            f = rhs(body, z1)
            z0, z1 = z1, [a + 2 * h * b for a, b in zip(z0, f)]
        f = rhs(body, z1)
        row = [[(a + b + h * c) / 2 for a, b, c in zip(z0, z1, f)]]
        for m in range(1, j):
            ratio = (mpm.mpf(nsub) / (2 * (j - m))) ** 2 - 1
            row.append([a + (a - b) / ratio for a, b in zip(row[m - 1], table[-1][m - 1])])
        table.append(row)
    return table[-1][-1], max(abs(a - b) for a, b in zip(table[-1][-1], table[-1][-2]))


def spin(s):
    return dot(s[:3], s[3:6])


def integrate(body: Body, y0, t_end: float, H: float, k: int, tol: float = TOL, progress=None):
    """Accepted steps from 0 to ``t_end``: lists of times and states.

    The step starts at ``H`` and is controlled on the difference of the last
    two extrapolations (an estimate of the error of the next-to-last, so a
    conservative one of the result): ``tol`` absolute per step.
    """
    t_end = mpm.mpf(t_end)
    ts, ys = [mpm.mpf(0)], [list(y0)]
    Hm = mpm.mpf(H)
    worst = mpm.mpf(0)
    n_rej = 0
    while ts[-1] < t_end:
        step = min(Hm, t_end - ts[-1])
        y, err = gbs_step(body, ys[-1], step, k)
        if err > tol:
            Hm = step * max(mpm.mpf("0.2"), mpm.mpf("0.9") * (tol / err) ** (mpm.mpf(1) / (2 * k - 1)))
            n_rej += 1
            continue
        worst = max(worst, err)
        ts.append(ts[-1] + step)
        ys.append(y)
        Hm = step * min(mpm.mpf(2), mpm.mpf("0.9") * (tol / max(err, tol * mpm.mpf("1e-6"))) ** (mpm.mpf(1) / (2 * k - 1)))
        if progress and len(ts) % 500 == 0:
            progress(f"  t = {mpm.nstr(ts[-1], 6)} of {mpm.nstr(t_end, 6)}: {len(ts)} steps, {n_rej} rejected")
    return ts, ys, worst


def crossing(body: Body, ts, ys, guess: float, k: int):
    """Zero of omega.n near ``guess`` by the secant method on single GBS steps from the grid point before it."""
    i = max(j for j in range(len(ts) - 1) if ts[j] <= guess)
    t_i = ts[i]

    def g(t):
        dt = t - t_i
        return spin(ys[i]) if dt == 0 else spin(gbs_step(body, ys[i], dt, k)[0])

    a, b = mpm.mpf(guess) - mpm.mpf("1e-7"), mpm.mpf(guess) + mpm.mpf("1e-7")
    ga, gb = g(a), g(b)
    for _ in range(60):
        c = b - gb * (b - a) / (gb - ga)
        if abs(c - b) < mpm.mpf(10) ** (-(DPS - 3)):
            return c
        a, ga, b, gb = b, gb, c, g(c)
    raise RuntimeError(f"the secant method did not converge near t = {guess}")


def double_run(params: dict, y0: np.ndarray, t_end: float):
    """Crossings of omega.n from SciPy's DOP853 on the double-precision Newton--Euler equations."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
    import rigid_reference as ref

    p = np.array([params[k] for k in NAMES])
    sol = ref.integrate(y0, (0.0, t_end), p, rtol=1e-13, atol=1e-15)
    return sol.t_events[0]


def case(name: str, k: int, log, t_end: float | None = None) -> dict:
    params, n0, omega0, t_full, H = CASES[name]
    t_end = t_full if t_end is None else t_end
    y0 = initial_state(n0, omega0)
    body = Body(params)
    start = [mpm.mpf(float(v)) for v in y0] + [mpm.mpf(0)]
    t0 = time.perf_counter()
    ts, ys, worst = integrate(body, start, t_end, H, k, progress=log)
    check = CHECK_SPAN * t_end
    _, ys2, _ = integrate(body, start, check, H, k, tol=TOL * mpm.mpf("1e-3"))
    j = max(i for i in range(len(ts)) if ts[i] <= check)
    y_check = gbs_step(body, ys[j], mpm.mpf(check) - ts[j], k)[0] if ts[j] < check else ys[j]
    grid_diff = max(abs(a - b) for a, b in zip(y_check, ys2[-1]))
    log(f"{name}: {len(ts) - 1} steps; states at t = {check:g} with tolerances {mpm.nstr(TOL, 2)} and "
        f"{mpm.nstr(TOL * mpm.mpf('1e-3'), 2)} differ by {mpm.nstr(grid_diff, 3)}")
    guesses = double_run(params, y0, t_end)
    times = [crossing(body, ts, ys, float(tg), k) for tg in guesses]
    # parity of the crossings between grid points against the signs at the grid points
    signs = [spin(y) > 0 for y in ys]
    for i in range(len(ys) - 1):
        inside = sum(1 for t in times if ts[i] < t <= ts[i + 1])
        if (signs[i] != signs[i + 1]) != (inside % 2 == 1):
            raise RuntimeError(f"{name}: crossings of the double run disagree with the signs on step {i}")
    end = ys[-1]
    e0, e1 = energy(body, start), energy(body, end)
    return {
        "params": params, "n0": list(map(float, y0[:3])), "omega0": list(map(float, y0[3:])), "t_end": t_end,
        "first_step": H, "steps": len(ts) - 1, "step_tolerance": mpm.nstr(TOL, 2), "gbs_columns": k,
        "extrapolation_difference": mpm.nstr(worst, 3),
        "tighter_tolerance_check_time": check,
        "tighter_tolerance_difference": mpm.nstr(grid_diff, 3),
        "crossings": [mpm.nstr(t, 34) for t in times],
        "double_run_crossings": [float(t) for t in guesses],
        "spin_end": mpm.nstr(spin(end), 34),
        "state_end": [mpm.nstr(v, 34) for v in end[:6]],
        "energy_start": mpm.nstr(e0, 34),
        "energy_end": mpm.nstr(e1, 34),
        "dissipated_work_end": mpm.nstr(end[6], 34),
        "energy_balance_residual": mpm.nstr((e1 + end[6] - e0) / e0, 3),
        "seconds": round(time.perf_counter() - t0, 1),
    }


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", nargs="*", default=list(CASES), choices=list(CASES))
    ap.add_argument("--columns", type=int, default=16, help="GBS columns k (order 2k; default: %(default)s)")
    ap.add_argument("--t-end", type=float, default=None, help="end of every run (default: each case's own)")
    ap.add_argument("--out", type=Path, default=OUT)
    args = ap.parse_args(argv)
    mpm.mp.dps = DPS
    log = lambda s: print(s, file=sys.stderr, flush=True)  # noqa: E731
    data = json.loads(args.out.read_text()) if args.out.exists() else {}
    data["about"] = ("Newton-Euler rattleback integrated at 45 digits by Gragg-Bulirsch-Stoer "
                     "(benchmarks/reference34.py); numbers as decimal strings, 34 significant digits")
    for name in args.cases:
        data[name] = case(name, args.columns, log, args.t_end)
        log(f"{name}: {len(data[name]['crossings'])} crossings, {data[name]['seconds']} s")
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text(json.dumps(data, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
