"""Fixed-step kernel for any registered :class:`~knifeedge.integrators.methods.FixedMethod`.

:class:`FixedKernel` is a numba closure over the method's tableau and the state size (its loops unroll) and the
model's compiled right-hand side (inlined by LLVM), cached by :mod:`.cache`.  An explicit method is stepped stage
after stage (the classical RK4's increment written out: the general loops cost it 10-17 % per evaluation), an
implicit one (Gauss--Legendre) by fixed-point iteration of its stage equations to round-off, started from the
previous step's collocation polynomial.  The grid ends on ``t1``; the state update is compensated (Kahan)
summation; the dense output (events, output times) is each step's cubic Hermite interpolant.
"""
import numpy as np
from numba import njit

from . import common as _c
from .cache import compiled, is_cached
from .common import _EPS, EVENTS_PER_STEP, NEAR
from .methods import get

MAX_STAGE_ITER = 100
#: the interpolant of a step: cubic Hermite as a power series
DENSE_ROWS = 3
ALT = np.zeros(DENSE_ROWS, dtype=np.bool_)
_OPTIONS = {"error_model": "numpy"}


def _increments(m, N: int, rhs):
    """``(rk4, explicit, gauss, solver_scale)``: the step functions of the method ``m`` on ``N`` states."""
    S, GA, GC, DENOMINATOR = m.stages, m.A.copy(), m.c.copy(), m.denominator
    GB = m.b * DENOMINATOR  # the increment is h / DENOMINATOR * sum_j GB[j] K_j

    def rk4(t, y, h, q, f0, K, work, dy):
        """The classical RK4's stages and increment ``h/6 (K_0 + 2 K_1 + 2 K_2 + K_3)``, as written."""
        for i in range(N):
            work[i] = y[i] + 0.5 * h * f0[i]
        rhs(t + 0.5 * h, work, q, K[1])
        for i in range(N):
            work[i] = y[i] + 0.5 * h * K[1, i]
        rhs(t + 0.5 * h, work, q, K[2])
        for i in range(N):
            work[i] = y[i] + h * K[2, i]
        rhs(t + h, work, q, K[3])
        for i in range(N):
            dy[i] = h / 6.0 * (f0[i] + 2.0 * K[1, i] + 2.0 * K[2, i] + K[3, i])
        return 3

    def explicit(t, y, h, q, f0, K, work, dy):
        """The stages of an explicit method from ``K[0] = f0``: ``y + (a_j0 h) K_0 + ...`` (zero coefficients
        skipped), and ``dy = h / DENOMINATOR * (GB_0 K_0 + ...)``; returns the right-hand-side calls."""
        for i in range(N):
            K[0, i] = f0[i]
        for s in range(1, S):
            for i in range(N):
                acc = y[i]
                for j in range(s):
                    if GA[s, j] != 0.0:
                        acc += GA[s, j] * h * K[j, i]
                work[i] = acc
            rhs(t + GC[s] * h, work, q, K[s])
        for i in range(N):
            acc = 0.0
            for j in range(S):
                acc += GB[j] * K[j, i]
            dy[i] = h / DENOMINATOR * acc
        return S - 1

    def solver_scale(y, atol, pair, out):
        """Scale of the stage solver's test: a component's magnitude, or its mode partner's if larger, or atol."""
        for i in range(N):
            a = abs(y[i])
            if pair[i] >= 0:
                a = max(a, abs(y[pair[i]]))
            out[i] = max(a, atol[i])

    def gauss(t, y, h, q, scale, Z, Znew, work, dy):
        """Solve the stage equations by fixed-point iteration; returns (rhs calls, converged).

        It stops when the largest change of a stage increment relative to ``scale`` is a few ulps, or stops
        decreasing while below 1e-14 of the largest state component; it fails when the change grows a
        thousandfold above its first value, becomes non-finite, or ``MAX_STAGE_ITER`` iterations pass.
        """
        nfev = 0
        dprev = np.inf
        dfirst = np.inf
        ynorm = 1e-300
        for i in range(N):
            ynorm = max(ynorm, abs(y[i]))
        for it in range(MAX_STAGE_ITER):
            for k in range(S):
                for i in range(N):
                    acc = 0.0
                    for j in range(S):
                        acc += GA[k, j] * Z[j, i]
                    work[i] = y[i] + h * acc
                rhs(t + GC[k] * h, work, q, Znew[k])
            nfev += S
            d = 0.0
            dglob = 0.0
            for k in range(S):
                for i in range(N):
                    change = abs(h * (Znew[k, i] - Z[k, i]))
                    r = change / scale[i]
                    if not (r <= d):
                        d = r
                    if not (change <= dglob):
                        dglob = change
                    Z[k, i] = Znew[k, i]
            if not np.isfinite(d):
                return nfev, False
            if it == 0:
                dfirst = d
            if d <= 4.0 * _EPS or dglob == 0.0 or (d >= dprev and dglob <= 1e-14 * ynorm):
                for i in range(N):
                    acc = 0.0
                    for k in range(S):
                        acc += GB[k] * Z[k, i]
                    dy[i] = h / DENOMINATOR * acc
                return nfev, True
            if d > 1e3 * dfirst:
                return nfev, False
            dprev = d
        return nfev, False

    return tuple(njit(**_OPTIONS)(f) for f in (rk4, explicit, gauss, solver_scale))


class FixedKernel:
    """The kernel of the fixed-step ``method`` for the right-hand side ``rhs_name`` of the generated
    ``model_module`` on ``N`` states: :attr:`solve` (see :func:`_solve_closure` for its arguments; compiled at
    its first call, or loaded from the cache)."""

    def __init__(self, method: str, model_module, rhs_name: str, N: int):
        rhs, constants = getattr(model_module, rhs_name), model_module.constants
        names = tuple(getattr(model_module, "EVENT_NAMES", ()))
        function_ends, locate = None, _c.locator()
        if names:
            event_values = model_module.event_values

            def values_(s, p, ev):
                """The model's event functions at ``s``."""
                return event_values(s, p)

            values = njit(**_OPTIONS)(values_)
            function_ends, locate = _c.function_ends(values), _c.locator(values)
        py = _solve_closure(get(method, "fixed"), N, rhs, constants, bool(names), function_ends, locate)
        self.solve = compiled(py, f"fixed-{method}-{model_module.__name__.rsplit('.', 1)[-1]}-{rhs_name}")

    def is_compiled(self) -> bool:
        """Whether the cache holds the compiled :attr:`solve`."""
        return is_cached(self.solve)


def _begin_closure(N: int, S: int, rhs):
    """``begin(t, y0, q, f0, Z, first)``, inlined into the kernel: the right-hand-side calls it made and the
    kernel's arrays, ``y`` a copy of ``y0`` and ``f_old`` the derivative there (of a run: computed, and the
    stages ``Z`` set to it; of a continued run: ``f0``)."""

    def begin(t, y0, q, f0, Z, first):
        y, f_old = np.empty(N), np.empty(N)
        for i in range(N):
            y[i] = y0[i]
        calls = 0
        if first == 0:
            rhs(t, y, q, f_old)
            for k in range(S):
                for i in range(N):
                    Z[k, i] = f_old[i]
            calls = 1
        else:
            for i in range(N):
                f_old[i] = f0[i]
        return (calls, y, np.empty(N), np.empty(N), np.empty(N), np.empty(N), np.empty(N), f_old, np.empty(N),
                np.empty((S, N)), np.empty((S, N)), np.empty((DENSE_ROWS, N)))

    return njit(inline="always", **_OPTIONS)(begin)


def _solve_closure(m, N: int, rhs, constants, HAS_FUN, function_ends, locate):
    """The kernel as a Python closure over the method ``m``, the state size, the model's functions."""
    rk4_increment, explicit_increment, gauss_increment, solver_scale = _increments(m, N, rhs)
    IMPLICIT, CLASSICAL_RK4, S, EXTRAP = m.implicit, m.is_classical_rk4, m.stages, m.extrapolation
    begin = _begin_closure(N, S, rhs)
    NO_EV = np.zeros(2, dtype=np.int64)  # the event functions are the model's own (the adaptive kernel's ``ev``)

    def solve(t0, t1, y0, f0, p, control, request, out):
        """Integrate from ``t0`` over steps ``first + 1 .. n_steps`` of size ``h_fixed``, at most ``chunk`` of them.

        ``control`` is ``(h_fixed, n_steps, first, atol, pair, comp, Z)``: step ``k`` ends at ``t0 + k h_fixed``
        (the last at ``t1``); ``atol`` and the mode partners ``pair`` set the scale of the implicit solver's test;
        ``y0`` is the state after step ``first``, ``f0`` its derivative (ignored when ``first == 0``); ``comp``
        (the Kahan compensation) and ``Z`` (the last step's stages) are updated in place, so that a run in chunks
        takes the steps of one call.  ``request``, ``out`` and the returns are the adaptive kernel's
        (:func:`.erk.driver`; no rejected steps; ``h_next`` is the index of the last step taken).
        """
        h_fixed, n_steps, first, atol, pair, comp, Z = control
        t_eval, every, events, max_steps, chunk = request
        ts, ys, ev_t, ev_k = out
        if y0.size != N:
            raise ValueError("the initial state does not have the size this kernel was specialized to")
        q = constants(p)
        t = t0 if first == 0 else t0 + first * h_fixed
        calls, y, y_new, dy, comp_trial, scale, work, f_old, f_new, K, Znew, F = begin(t, y0, q, f0, Z, first)
        ne, n_fun, ga, gb, sa, sb, crit, n_crit, flag, xs, gs = _c.alloc(events)
        # counters start as int64, not as the literal 0 (numba would compile the callees for both types)
        n_out, ie, n_ev, nfev = np.int64(0), np.int64(0), np.int64(0), np.int64(calls)
        status, n_acc, step = 0, 0, first
        while step < n_steps:
            if n_acc >= max_steps:
                status = -2
                break
            if n_acc >= chunk or (every and n_out == ts.size) or n_ev + ne * EVENTS_PER_STEP > ev_t.size:
                status = 1
                break
            step += 1
            t_new = t1 if step == n_steps else t0 + step * h_fixed
            if IMPLICIT:  # constants numba prunes on: only the method's branch is compiled in
                solver_scale(y, atol, pair, scale)
                calls, ok = gauss_increment(t, y, h_fixed, q, scale, Z, Znew, work, dy)
                nfev += calls
                if not ok:
                    status = -4
                    break
            elif CLASSICAL_RK4:
                nfev += rk4_increment(t, y, h_fixed, q, f_old, K, work, dy)
            else:
                nfev += explicit_increment(t, y, h_fixed, q, f_old, K, work, dy)
            for i in range(N):
                comp_trial[i] = comp[i]
            _c.compensated_add(y, dy, comp_trial, y_new)
            if not _c.all_finite(y_new):
                status = -3
                break
            rhs(t_new, y_new, q, f_new)
            nfev += 1
            if not _c.all_finite(f_new):
                status = -3
                break
            for i in range(N):
                comp[i] = comp_trial[i]
            n_acc += 1
            h = t_new - t  # the step as taken
            # the events' screen, their crossings and the output, written out (common.py says what they do: as
            # calls, inlined or not, they cost the kernels 1.5-4x per evaluation)
            any_flag = False
            if ne > 0:
                for k in range(ne):
                    c = events[k]
                    if c >= 0:
                        ga[k], gb[k], sa[k], sb[k] = y[c], y_new[c], h * f_old[c], h * f_new[c]
                if HAS_FUN:
                    if n_fun > 0:
                        function_ends(events, y, y_new, f_old, f_new, h, p, NO_EV, work, ga, gb, sa, sb)
                suspect = False  # whether the screen may flag any event (the bound of common.py)
                for k in range(ne):
                    g0, g1 = ga[k], gb[k]
                    if g0 == 0.0 or g1 == 0.0 or (g0 > 0.0) != (g1 > 0.0):
                        suspect = True
                    else:
                        d = g1 - g0
                        dev = 0.25 * max(abs(sa[k] - d), abs(sb[k] - d))
                        if min(abs(g0), abs(g1)) - dev <= NEAR * max(abs(g0), abs(g1)):
                            suspect = True
                if suspect:
                    any_flag = _c.screen(ga, gb, sa, sb, crit, n_crit, flag)
            if any_flag or (ie < t_eval.size and t_eval[ie] < t_new):
                _c.hermite_coefficients(y, y_new, f_old, f_new, h, F)
            if any_flag:
                marks = (ga, gb, crit, n_crit, flag, xs, gs)
                n_ev = locate(events, (F, y, ALT, p, NO_EV, work), t, h, marks, (ev_t, ev_k), n_ev)
            if every:  # the common case: a row per step
                ts[n_out] = t_new
                for i in range(N):
                    ys[n_out, i] = y_new[i]
                n_out += 1
            while not every and ie < t_eval.size and t_eval[ie] <= t_new:
                te = t_eval[ie]
                ts[n_out] = te
                x = (te - t) / h
                for i in range(N):
                    ys[n_out, i] = y_new[i] if te == t_new else _c.interpolate(F, y, ALT, x, i)
                n_out += 1
                ie += 1
            if IMPLICIT:  # start the next stage iteration from this step's collocation polynomial
                for k in range(S):
                    for i in range(N):
                        acc = 0.0
                        for j in range(S):
                            acc += EXTRAP[k, j] * Z[j, i]
                        Znew[k, i] = acc
                for k in range(S):
                    for i in range(N):
                        Z[k, i] = Znew[k, i]
            for i in range(N):
                y[i] = y_new[i]
                f_old[i] = f_new[i]
            t = t_new
        return n_out, n_ev, status, nfev, n_acc, 0, t, y, f_old, float(step)

    return solve
