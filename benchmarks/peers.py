"""The peers: what a user would otherwise run.

* ``solve_ivp`` with a plain Python right-hand side -- the generated
  equations' undecorated Python source (``rhs_into.py_func``), i.e. what a
  user writes first;
* ``solve_ivp`` with the generated numba right-hand side;
* numbalsoda's compiled DOP853 (Hairer's Fortran code) with the generated
  right-hand side wrapped as a C callback, when numbalsoda is installed.
  It gets the same right-hand side the compiled kernels call
  (``rhs_q_into`` with ``constants(p)``), so the race is between the
  integrators alone.

Each runner returns ``(y_end, reversal_times or None, nfev)``.
"""
from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

try:  # optional: needs a Fortran compiler to build
    import numbalsoda
    from numba import carray, cfunc
except ImportError:  # pragma: no cover - depends on the machine
    numbalsoda = None

NUMBALSODA_NOTE = ("numbalsoda is not installed (it needs a Fortran compiler to build: "
                   "apt-get install gfortran; pip install numbalsoda); its DOP853 is skipped")


def scipy_runner(scene, method: str, python_rhs: bool):
    model, p, y0 = scene.model, scene.p, scene.y
    n = model.n_state
    k = model.index(model.spin_name)
    if python_rhs:
        into = model.rhs_into.py_func

        def fun(t, y):
            dy = np.empty(n)
            into(t, y, p, dy)
            return dy
    else:
        rhs = model.rhs

        def fun(t, y):
            return rhs(t, y, p)

    def reversal(t, y):
        return y[k]

    def run(rtol, atol):
        sol = solve_ivp(fun, (0.0, scene.t_end), y0, method=method, rtol=rtol, atol=atol, events=reversal,
                        t_eval=[scene.t_end])
        return sol.y[:, -1], np.asarray(sol.t_events[0]), sol.nfev

    return run


def numbalsoda_runner(scene):
    """numbalsoda's DOP853, or None when it is not installed.  nfev is counted in the callback."""
    if numbalsoda is None:
        return None
    model, y0 = scene.model, scene.y
    p = model.module.constants(scene.p)  # the right-hand side the compiled kernels call, for a fair race
    n, n_p = model.n_state, p.size
    rhs_into = model.module.rhs_pose_q_into if model.pose else model.module.rhs_q_into

    @cfunc(numbalsoda.lsoda_sig)
    def f(t, u, du, data):
        u_ = carray(u, (n,))
        du_ = carray(du, (n,))
        d = carray(data, (n_p + 1,))
        d[n_p] += 1.0
        rhs_into(t, u_, d[:n_p], du_)

    address = f.address
    t_eval = np.array([0.0, scene.t_end])

    def run(rtol, atol):
        data = np.concatenate([p, [0.0]])
        usol, ok = numbalsoda.dop853(address, y0.copy(), t_eval, data=data, rtol=rtol, atol=atol, mxstep=10**9)
        if not ok:
            return np.full(n, np.nan), None, int(data[-1])
        return usol[-1], None, int(data[-1])

    return run
