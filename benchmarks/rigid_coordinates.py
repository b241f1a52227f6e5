"""Orientation coordinates of a rolling rigid body: global error at equal tolerance.

``python -m benchmarks.rigid_coordinates [--out DIR]``

The same physics (the Kane & Levinson 1982 rattleback, ``tests/rigid_reference.py``)
integrated by SciPy's DOP853 at equal ``rtol`` in three state coordinates:

- ``vertical``: the upward vertical ``n`` in body axes (3 components) and the
  body angular velocity ``omega`` -- the coordinates of :mod:`derivation.rigid`;
- ``tilt_angles``: two angles ``al, be`` with ``n = (cos al sin be, sin al,
  cos al cos be)`` and ``omega`` (singular at ``al = +-90 deg``);
- ``euler``: angles ``(psi, a1, a2)`` of ``R = Rz(psi) Rx(a1) Ry(a2)``
  (``a1 = al``, ``a2 = -be``) and their rates as the velocity state, as a
  Lagrangian in Euler angles has it (singular at ``a1 = +-90 deg``);
- ``euler_zxz``: classical z-x-z Euler angles and their rates (singular at
  ``a1 = 0``, the upright body, where the rattleback starts).

The error is the largest difference of ``omega . n`` and ``n`` at the end of
the span against a converged reference (``vertical`` at rtol 1e-13), with the
number of right-hand-side evaluations.  Writes ``rigid_coordinates.json``.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
import rigid_reference as ref  # noqa: E402

P = np.array([0.20, 0.03, 0.02, 0.01, 1.0, 9.81, 2e-4, 1.6e-3, 1.7e-3, 2e-5, 0.0, 0.0, 0.0])
TILT = math.radians(0.5)
SPIN = 5.0


def _euler_maps(sequence: str = "zxy"):
    """``n(a)``, ``B(a)`` (``omega = B(a) a_dot``) and ``dB/dt a_dot`` for ``a = (psi, a1, a2)``.

    ``"zxy"``: ``R = Rz(psi) Rx(a1) Ry(a2)``; ``"zxz"``: ``R = Rz(psi) Rx(a1) Rz(a2)``
    (classical Euler angles, singular at ``a1 = 0``: the upright body).
    """
    psi, a1, a2 = sp.symbols("psi a1 a2")
    rates = sp.symbols("psi_d a1_d a2_d")
    ez, ex, ey = sp.Matrix([0, 0, 1]), sp.Matrix([1, 0, 0]), sp.Matrix([0, 1, 0])
    Rx = sp.rot_axis1(-a1)  # sympy's rot_axis is the passive rotation; negate for the active one
    R3, e3 = (sp.rot_axis2(-a2), ey) if sequence == "zxy" else (sp.rot_axis3(-a2), ez)
    B = sp.Matrix.hstack(R3.T * Rx.T * ez, R3.T * ex, e3)
    n = R3.T * Rx.T * ez
    a = sp.Matrix([psi, a1, a2])
    ad = sp.Matrix(rates)
    Bdot_ad = sum((B.diff(q) * qd for q, qd in zip(a, ad)), sp.zeros(3, 3)) * ad
    args = [list(a), list(ad)]
    return (sp.lambdify([list(a)], n, "numpy"), sp.lambdify([list(a)], B, "numpy"),
            sp.lambdify(args, Bdot_ad, "numpy"))


N_OF, B_OF, BDOT_OF = _euler_maps("zxy")
N_ZXZ, B_ZXZ, BDOT_ZXZ = _euler_maps("zxz")
ARGS = ref.unpack(P)


def vertical_rhs(t, s):
    return ref._rhs(s, *ARGS)


def tilt_rhs(t, s):
    al, be, w = s[0], s[1], s[2:5]
    n = np.array([math.cos(al) * math.sin(be), math.sin(al), math.cos(al) * math.cos(be)])
    d = ref._rhs(np.concatenate([n, w]), *ARGS)
    nd = d[:3]
    al_d = nd[1] / math.cos(al)
    be_d = (n[2] * nd[0] - n[0] * nd[2]) / (n[0] ** 2 + n[2] ** 2)
    return np.concatenate([[al_d, be_d], d[3:]])


def _angles_rhs(s, n_of, b_of, bdot_of):
    a, ad = s[:3], s[3:]
    n = np.asarray(n_of(a), float).ravel()
    B = np.asarray(b_of(a), float)
    w = B @ ad
    wd = ref._rhs(np.concatenate([n, w]), *ARGS)[3:]
    add = np.linalg.solve(B, wd - np.asarray(bdot_of(a, ad), float).ravel())
    return np.concatenate([ad, add])


def euler_rhs(t, s):
    return _angles_rhs(s, N_OF, B_OF, BDOT_OF)


def euler_zxz_rhs(t, s):
    return _angles_rhs(s, N_ZXZ, B_ZXZ, BDOT_ZXZ)


def initial():
    n0 = np.array([math.cos(TILT) * math.sin(TILT), math.sin(TILT), math.cos(TILT) ** 2])
    w0 = np.array([0.0, 0.0, SPIN])
    a0 = np.array([0.0, TILT, -TILT])
    ad0 = np.linalg.solve(np.asarray(B_OF(a0), float), w0)
    # zxz: n = (sin a1 sin a2, sin a1 cos a2, cos a1)
    z0 = np.array([0.0, math.acos(n0[2]), math.atan2(n0[0], n0[1])])
    zd0 = np.linalg.solve(np.asarray(B_ZXZ(z0), float), w0)
    return {"vertical": np.concatenate([n0, w0]), "tilt_angles": np.concatenate([[TILT, TILT], w0]),
            "euler": np.concatenate([a0, ad0]), "euler_zxz": np.concatenate([z0, zd0])}


def final_observables(name, y):
    if name == "vertical":
        n, w = y[:3] / np.linalg.norm(y[:3]), y[3:6]
    elif name == "tilt_angles":
        al, be = y[0], y[1]
        n, w = np.array([math.cos(al) * math.sin(be), math.sin(al), math.cos(al) * math.cos(be)]), y[2:5]
    else:
        n_of, b_of = (N_OF, B_OF) if name == "euler" else (N_ZXZ, B_ZXZ)
        n = np.asarray(n_of(y[:3]), float).ravel()
        w = np.asarray(b_of(y[:3]), float) @ y[3:]
    return n, float(n @ w)


def run(t_end: float = 5.0, rtols=(1e-6, 1e-8, 1e-10)) -> dict:
    y0 = initial()
    rhs = {"vertical": vertical_rhs, "tilt_angles": tilt_rhs, "euler": euler_rhs, "euler_zxz": euler_zxz_rhs}
    refsol = solve_ivp(vertical_rhs, (0, t_end), y0["vertical"], method="DOP853", rtol=1e-13, atol=1e-15)
    n_ref, spin_ref = final_observables("vertical", refsol.y[:, -1])
    out = {"t_end": t_end, "reference_nfev": int(refsol.nfev), "runs": []}
    for rtol in rtols:
        for name, f in rhs.items():
            sol = solve_ivp(f, (0, t_end), y0[name], method="DOP853", rtol=rtol, atol=rtol * 1e-2)
            n, spin = final_observables(name, sol.y[:, -1])
            err = max(abs(spin - spin_ref), float(np.abs(n - n_ref).max()))
            out["runs"].append({"coordinates": name, "rtol": rtol, "nfev": int(sol.nfev), "error": err})
            print(f"rtol {rtol:.0e}  {name:<12} nfev {sol.nfev:7d}  error {err:.2e}", flush=True)
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.rigid_coordinates", description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=Path(__file__).resolve().parent / "results")
    args = ap.parse_args(argv)
    res = run()
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "rigid_coordinates.json").write_text(json.dumps(res, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
