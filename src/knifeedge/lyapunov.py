"""Lyapunov exponents of the physical phase space by the Benettin/QR method on the emitted variational equations.

With a fixed step, the state and ``k`` tangent vectors are stepped together by the classical fourth-order
Runge-Kutta method in one compiled loop (the generated ``jvp_into``: the rates and the Jacobian-vector product
``J(y) Q`` of the ``k`` tangent vectors in one call; no Python call per step); every ``tau`` of time the tangent
vectors are re-orthonormalized (modified Gram-Schmidt, the QR of ChaosTools.jl's ``lyapunovspectrum``) and the
logarithms of the diagonal of R are summed.  The tangent vectors start orthogonal to the gradients of the
closed state's invariants (``STATE_INVARIANTS``), so they span the physical phase space, which the tangent flow
keeps (the round-off that leaks out of it is projected away before each re-orthonormalization).  With step
control (``rtol``) the state and the tangent vectors take DOP853 steps together (:func:`_benettin_adaptive`), or
the state Dormand-Prince 5(4) steps and the tangent vectors exponential (Magnus) steps of their own
(:func:`_benettin_magnus`; the default for more than one exponent).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit, types

from .integrators.common import step_factor
from .integrators.methods import DP54_A, DP54_B, DP54_E, DP54_P, erk_arrays
from . import magnus
from .magnus import GAUSS_NODES
from .models import Model
from .stability import jacobian

@njit(cache=True)
def _orthonormalize(Q, sums):
    """Modified Gram-Schmidt in place; adds log |R_jj| to ``sums``."""
    n, k = Q.shape
    for j in range(k):
        for i in range(j):
            r = 0.0
            for m in range(n):
                r += Q[m, i] * Q[m, j]
            for m in range(n):
                Q[m, j] -= r * Q[m, i]
        norm = 0.0
        for m in range(n):
            norm += Q[m, j] * Q[m, j]
        norm = math.sqrt(norm)
        sums[j] += math.log(norm)
        for m in range(n):
            Q[m, j] /= norm


@njit(cache=True)
def _project_out(G, Q):
    """Remove from the columns of ``Q`` their components along the rows of ``G`` (orthonormalized here)."""
    m, n = G.shape
    for i in range(m):
        for j in range(i):
            r = 0.0
            for c in range(n):
                r += G[i, c] * G[j, c]
            for c in range(n):
                G[i, c] -= r * G[j, c]
        norm = 0.0
        for c in range(n):
            norm += G[i, c] * G[i, c]
        norm = math.sqrt(norm)
        for c in range(n):
            G[i, c] /= norm
        for j in range(Q.shape[1]):
            r = 0.0
            for c in range(n):
                r += G[i, c] * Q[c, j]
            for c in range(n):
                Q[c, j] -= r * G[i, c]


#: the loops' vector helpers below are inlined into the loops by numba (``inline="always"``): compiled as functions
#: of their own, each cost a first run 0.1-0.2 s of CPU (numba's pipeline, LLVM's vectorized copy, the cache entry);
#: the same operations in the same order, the same bits.  ``_project_out`` and ``_orthonormalize`` stay functions:
#: inlined, the Magnus loop took 0.5-0.9 s longer to compile (docs/performance.md, "compiles other than the driver")
@njit(cache=True, inline="always")
def _shifted(out, x, c, dx):
    """``out = x + c dx`` (vectors)."""
    for i in range(x.size):
        out[i] = x[i] + c * dx[i]


@njit(cache=True, inline="always")
def _running(hist, b, sums, t):
    """Row ``b`` of the history: the running estimates ``sums / t`` (a loop: the array expression's assignment
    compiles numba's formatting of its shape error, half the loop's compile time)."""
    for j in range(sums.size):
        hist[b, j] = sums[j] / t


@njit(cache=True, inline="always")
def _rk4_update(x, h, d1, d2, d3, d4):
    """The classical Runge-Kutta step ``x += h/6 (d1 + 2 d2 + 2 d3 + d4)`` in place (vectors)."""
    for i in range(x.size):
        x[i] += h / 6.0 * (d1[i] + 2.0 * d2[i] + 2.0 * d3[i] + d4[i])


#: the first-class function types of a generated module's ``jvp_into(s, p, V, ds, out)`` (the rates ``ds`` and
#: ``out = J(s) V``) and ``invariant_gradients(s, p)``: the loop below is compiled for these types, not for one
#: module's functions, so one compiled loop (in numba's cache, once per machine) serves every model and calls them
#: through their addresses
_VECTOR = types.float64[::1]
_MATRIX = types.float64[:, ::1]
_JVP = types.FunctionType(types.none(_VECTOR, _VECTOR, _MATRIX, _VECTOR, _MATRIX))
#: ``jvp1_into(s, p, _v, ds, _dv)``: the product of one vector (the largest exponent's loop)
_JVP1 = types.FunctionType(types.none(_VECTOR, _VECTOR, _VECTOR, _VECTOR, _VECTOR))
_MATRIX_OF_STATE = types.FunctionType(_MATRIX(_VECTOR, _VECTOR))
_SIGNATURE = (_JVP, _MATRIX_OF_STATE, _MATRIX, types.int64, _VECTOR, types.float64, types.int64, types.int64, _VECTOR,
              _MATRIX, _VECTOR)


@njit(cache=True)
def _benettin(jvp_into, gradients, z, n, p, h, n_blocks, steps_per_block, sums, hist, hist_t):
    """RK4 on the state and ``k`` tangent vectors for ``n_blocks`` blocks of ``steps_per_block`` steps of ``h``,
    re-orthonormalized after each block, into ``sums`` (zeros: the sums of log |R_jj|), ``hist_t`` and ``hist``
    (the times and running estimates of the re-orthonormalizations, from time 0).  ``z`` (6, n (k + 1)): row 0
    the state (``n`` values) and the tangent vectors (the n x k matrix, row by row), rows 1-4 the four stages'
    derivatives of them, row 5 a stage's point: one loop over a row serves the state and the tangents, and the
    caller allocates the work space (numba compiles no allocation here)."""
    k = sums.size
    x, d1, d2, d3, d4, xt = z[0], z[1], z[2], z[3], z[4], z[5]
    y, Q, yt, Qt = x[:n], x[n:].reshape((n, k)), xt[:n], xt[n:].reshape((n, k))
    k1, k2, k3, k4 = d1[:n], d2[:n], d3[:n], d4[:n]
    K1, K2, K3, K4 = d1[n:].reshape((n, k)), d2[n:].reshape((n, k)), d3[n:].reshape((n, k)), d4[n:].reshape((n, k))
    for b in range(n_blocks):
        for _ in range(steps_per_block):
            jvp_into(y, p, Q, k1, K1)
            _shifted(xt, x, 0.5 * h, d1)
            jvp_into(yt, p, Qt, k2, K2)
            _shifted(xt, x, 0.5 * h, d2)
            jvp_into(yt, p, Qt, k3, K3)
            _shifted(xt, x, h, d3)
            jvp_into(yt, p, Qt, k4, K4)
            _rk4_update(x, h, d1, d2, d3, d4)
        # round-off leaks into the invariants' directions (rate 0), which would outgrow decaying directions
        _project_out(gradients(y, p), Q)
        _orthonormalize(Q, sums)
        hist_t[b] = (b + 1) * steps_per_block * h
        _running(hist, b, sums, hist_t[b])


def _kernel():
    """The compiled Benettin loop for the first-class function types (compiled, or loaded from numba's cache,
    once per process; its entry point takes a module's numba functions and passes their addresses)."""
    if _SIGNATURE not in _benettin.overloads:
        _benettin.compile(_SIGNATURE)
    return _benettin.overloads[_SIGNATURE].entry_point


#: Dormand-Prince 5(4) (SciPy's RK45; the project's ``DP54``), the state's steps of the Magnus loop: row s < 6 the
#: coefficients of stage s, row 6 the weights of the new point (whose rate is the seventh stage, FSAL); ``_E`` the
#: error estimator over the 7
_A = np.zeros((7, 6))
_A[:6, :5] = DP54_A
_A[6] = DP54_B
_E = DP54_E
_ADAPTIVE_SIGNATURE = (_JVP, _JVP1, _MATRIX_OF_STATE, _VECTOR, _MATRIX, _VECTOR, types.float64,
                       types.int64, types.float64, types.float64, types.float64, types.float64, types.int64)


@njit(cache=True)
def _stage_point(out, x, h, K, s):
    """``out = x + h sum_j A[s, j] K[j]`` over the stages ``j < s``."""
    for i in range(x.size):
        acc = 0.0
        for j in range(s):
            acc += _A[s, j] * K[j, i]
        out[i] = x[i] + h * acc


@njit(cache=True)
def _error_squares(x, x_new, K, h, rtol, atol):
    """Sum over the components of the squared embedded error estimates, each scaled by ``atol + rtol |x|`` (the
    terms of SciPy's RMS norm)."""
    acc = 0.0
    for i in range(x.size):
        e = 0.0
        for j in range(7):
            e += _E[j] * K[j, i]
        scale = atol + rtol * max(abs(x[i]), abs(x_new[i]))
        acc += (h * e / scale) ** 2
    return acc


#: Dormand-Prince 8(5,3) (SciPy's and Hairer's DOP853, ``integrators.methods``): row s < 12 of ``_A8`` the
#: coefficients of stage s, row 12 the weights of the new point; ``_E5``, ``_E3`` its two error estimators over the
#: 12 stages (the rate at the new point, the thirteenth stage, first same as last, enters neither)
_DOP853 = erk_arrays("DOP853")
_S8 = _DOP853.n_stages
_A8 = np.ascontiguousarray(_DOP853.A[:_S8 + 1, :_S8])
_E5, _E3 = np.ascontiguousarray(_DOP853.E5[:_S8]), np.ascontiguousarray(_DOP853.E3[:_S8])


@njit(cache=True, inline="always")
def _dop853_point(out, z, K, h, s):
    """``out = z + h sum_j A[s, j] K[j]`` over the stages ``j < s`` of DOP853 (row 12: the new point); stage by stage,
    so that the components' sums are independent (summed component by component, each waits on its previous term).
    Inlined, as :func:`_put` (numba's IR: as calls, the two cost the loop 11 % of its time, measured)."""
    _copy(out, z)
    for j in range(s):
        c = h * _A8[s, j]
        if c != 0.0:
            for i in range(z.size):
                out[i] += c * K[j, i]


#: the stages that DOP853's error estimators weigh (0, 5-11; the same for both), a constant tuple: the loop over them
#: is unrolled
_E_STAGES = tuple(int(j) for j in np.flatnonzero((_E5 != 0.0) | (_E3 != 0.0)))


@njit(cache=True)
def _dop853_error(z, z_new, K, h, n, rtol, atol, tangent_tol):
    """SciPy's DOP853 error norm of a step of ``z``: the state (its first ``n`` components, scaled by ``atol + rtol
    |z|``), then the tangent vectors (of unit length after each QR: scaled by ``tangent_tol (1 + |z|)``)."""
    s5, s3 = 0.0, 0.0
    for i in range(z.size):
        e5, e3 = 0.0, 0.0
        for j in _E_STAGES:
            e5 += _E5[j] * K[j, i]
            e3 += _E3[j] * K[j, i]
        size = max(abs(z[i]), abs(z_new[i]))
        inverse = 1.0 / (atol + rtol * size if i < n else tangent_tol * (1.0 + size))
        s5 += (e5 * inverse) ** 2
        s3 += (e3 * inverse) ** 2
    if s5 == 0.0 and s3 == 0.0:
        return 0.0
    return h * s5 / math.sqrt((s5 + 0.01 * s3) * z.size)


@njit(cache=True, inline="always")
def _put(row, ds, dq):
    """``row = (ds, dq)`` (vectors)."""
    for i in range(ds.size):
        row[i] = ds[i]
    for i in range(dq.size):
        row[ds.size + i] = dq[i]


@njit(cache=True, inline="always")
def _stage(jvp_into, jvp1_into, z, p, n, k, row, ds, dQ):
    """``row`` = the rates at the state ``z[:n]`` and the derivatives of the ``k`` tangent vectors ``z[n:]`` (row by
    row): one vector by ``jvp1_into``, several by ``jvp_into`` through the buffers ``ds``, ``dQ``."""
    if k == 1:
        jvp1_into(z[:n], p, z[n:], row[:n], row[n:])
    else:
        jvp_into(z[:n], p, z[n:].reshape((n, k)), ds, dQ)
        _put(row, ds, dQ.ravel())


@njit(cache=True)
def _no_product(s, p, V, ds, out):
    """In place of the ``jvp_into`` a loop of one tangent vector never calls (no model compiles it for nothing)."""


@njit(cache=True)
def _no_product1(s, p, v, ds, dv):
    """In place of the ``jvp1_into`` a loop of several tangent vectors never calls."""


@njit(cache=True)
def _benettin_adaptive(jvp_into, jvp1_into, gradients, y, Q, p, tau, n_blocks, rtol, atol, tangent_tol, h, max_steps):
    """As :func:`_benettin`, the state and the tangent vectors stepped together by DOP853 (SciPy's, ``simulate``'s
    default method) over ``n_blocks tau``, the errors of the state controlled to ``rtol``, ``atol``, the tangent
    vectors' to ``tangent_tol``.  The tangent vectors are re-orthonormalized at the end of the first step at or
    past each multiple of ``tau`` (the steps are not cut there: the sums of log |R_jj| do not depend on when);
    returns the times and running estimates of the re-orthonormalizations (at most ``n_blocks``, the last at the
    end), and the numbers of accepted and rejected steps (``max_steps`` reached: accepted = -1)."""
    n, k = Q.shape
    N = n * (k + 1)
    sums, hist, hist_t = np.zeros(k), np.empty((n_blocks, k)), np.empty(n_blocks)
    # one vector z: the state, then the tangent vectors row by row, so that one loop serves both in every stage
    z, zt, z_new, K = np.empty(N), np.empty(N), np.empty(N), np.empty((_S8, N))
    y_z, Q_z, ds, dQ = z[:n], z[n:].reshape((n, k)), np.empty(n), np.empty((n, k))
    _copy(y_z, y)
    _copy(z[n:], Q.ravel())
    t, t_final, t_qr, b, accepted, rejected = 0.0, n_blocks * tau, tau, 0, 0, 0
    _stage(jvp_into, jvp1_into, z, p, n, k, K[0], ds, dQ)
    while t_final - t > 1e-12 * tau:
        step = min(h, t_final - t)
        for s in range(1, _S8):
            _dop853_point(zt, z, K, step, s)
            _stage(jvp_into, jvp1_into, zt, p, n, k, K[s], ds, dQ)
        _dop853_point(z_new, z, K, step, _S8)
        # the tangent vectors are controlled too (at an equilibrium the state alone would let the step grow past
        # the stability of the tangent dynamics), relative to their unit length after each QR; the rate at the
        # new point (first same as last) enters neither estimate: it is computed once the step is accepted
        err = _dop853_error(z, z_new, K, step, n, rtol, atol, tangent_tol)
        if err <= 1.0:
            t = t_final if step == t_final - t else t + step
            _copy(z, z_new)
            accepted += 1
            if t >= t_qr - 1e-12 * tau:
                # round-off leaks into the invariants' directions (rate 0), which would outgrow decaying directions
                _project_out(gradients(y_z, p), Q_z)
                _orthonormalize(Q_z, sums)
                hist_t[b] = t
                _running(hist, b, sums, t)
                b += 1
                t_qr = min(t_final, (math.floor(t / tau + 1e-9) + 1) * tau)
            _stage(jvp_into, jvp1_into, z, p, n, k, K[0], ds, dQ)  # the first stage of the next step
        else:
            rejected += 1
        h = _controlled(h, step, err, -1.0 / 8.0)
        if accepted + rejected >= max_steps:
            accepted = -1
            break
    _copy(y, y_z)
    _copy(Q.ravel(), z[n:])
    return y, Q, sums, hist_t[:b], hist[:b], accepted, rejected


def _adaptive_kernel():
    """The compiled adaptive loop (compiled on first use, then loaded from numba's cache)."""
    if _ADAPTIVE_SIGNATURE not in _benettin_adaptive.overloads:
        _benettin_adaptive.compile(_ADAPTIVE_SIGNATURE)
    return _benettin_adaptive.overloads[_ADAPTIVE_SIGNATURE].entry_point


#: the state's dense output at the Gauss nodes is Shampine's quartic of Dormand-Prince 5(4) (``DP54_P``)
_P = DP54_P
_RHS = types.FunctionType(types.none(types.float64, _VECTOR, _VECTOR, _VECTOR))
_TENSOR = types.float64[:, :, ::1]
#: :func:`knifeedge.magnus.magnus_step`, called through its address (not inlined: the loop compiles in a third of
#: the time)
_MAGNUS_STEP = types.FunctionType(types.float64(_TENSOR, types.float64, _MATRIX, _MATRIX, _TENSOR, _TENSOR, _VECTOR,
                                                types.float64))
_MAGNUS_SIGNATURE = (_RHS, _JVP, _MATRIX_OF_STATE, _MAGNUS_STEP, _VECTOR, _MATRIX, _VECTOR, types.float64,
                     types.int64, types.float64, types.float64, types.float64, types.float64, types.int64)
#: state steps held for the tangent steps (a tangent step spans at most this many state steps)
_HELD = 32


@njit(cache=True)
def _copy(dst, src):
    """``dst = src`` (vectors; a loop compiles in a fraction of the time of a slice assignment)."""
    for i in range(src.size):
        dst[i] = src[i]


@njit(cache=True)
def _state_step(rhs_into, y, p, K, yt, y_new, step, rtol, atol):
    """One Dormand-Prince 5(4) step of the state from ``y`` (``K[0]`` its rate) into ``y_new`` (``K[1:]`` the
    stages, ``K[6]`` the rate at ``y_new``); returns the scaled RMS error estimate."""
    for s in range(1, 6):
        _stage_point(yt, y, step, K, s)
        rhs_into(0.0, yt, p, K[s])
    _stage_point(y_new, y, step, K, 6)
    rhs_into(0.0, y_new, p, K[6])
    return math.sqrt(_error_squares(y, y_new, K, step, rtol, atol) / y.size)


@njit(cache=True)
def _dense(out, time, held_t, held_h, held_y, held_K, n_held, y, t):
    """The state at ``time`` from the dense output of the held step that contains it (``y`` at ``t`` past them;
    ``held_K``: a step's stages in a row)."""
    for i in range(n_held):
        if held_t[i] <= time <= held_t[i] + held_h[i]:
            x, h = (time - held_t[i]) / held_h[i], held_h[i]
            for c in range(out.size):
                acc = 0.0
                for s in range(7):
                    acc += (((_P[s, 3] * x + _P[s, 2]) * x + _P[s, 1]) * x + _P[s, 0]) * x * held_K[i, s * out.size + c]
                out[c] = held_y[i, c] + h * acc
            return
    _copy(out, y)


@njit(cache=True)
def _hold(held_y, held_K, i, y, K):
    """Hold a step: its first point ``y`` in row ``i`` of ``held_y``, its stages ``K`` in row ``i`` of ``held_K``."""
    n = y.size
    for c in range(n):
        held_y[i, c] = y[c]
    for s in range(7):
        for c in range(n):
            held_K[i, s * n + c] = K[s, c]


@njit(cache=True)
def _drop_before(time, held_t, held_h, held_y, held_K, n_held):
    """Drop the held steps that end at or before ``time`` (``held_K`` with a step's stages in a row); returns how
    many are left."""
    first = 0
    while first < n_held and held_t[first] + held_h[first] <= time:
        first += 1
    for i in range(first, n_held):
        held_t[i - first], held_h[i - first] = held_t[i], held_h[i]
        for c in range(held_y.shape[1]):
            held_y[i - first, c] = held_y[i, c]
        for c in range(held_K.shape[1]):
            held_K[i - first, c] = held_K[i, c]
    return n_held - first


@njit(cache=True)
def _controlled(h, step, err, exponent):
    """The next step after ``step`` (tried as ``h`` or clipped below it) with the scaled error ``err`` (``exponent``:
    -1 / (1 + the order of the error estimate); the factor: the integrators' controller, :func:`step_factor`)."""
    factor = step_factor(err, exponent, False)
    return step * factor if (err > 1.0 or step == h) else max(h, step * factor)


#: the most e-folds by which one tangent step may spread the tangent vectors' lengths (log of the largest over the
#: smallest |R_jj| of the step's QR): their Gram-Schmidt loses about ``exp(spread)`` ulps of orthogonality
_SPREAD = 8.0


@njit(cache=True)
def _benettin_magnus(rhs_into, jvp_into, gradients, magnus_step, y, Q, p, tau, n_blocks, rtol, atol, tangent_tol, h,
                     max_steps):
    """As :func:`_benettin_adaptive`, the state stepped by Dormand-Prince 5(4) with its own error control, the tangent
    vectors by the sixth-order Magnus step (:func:`knifeedge.magnus.magnus_step`) with ``J`` at the Gauss nodes
    from the state's dense output, over tangent steps of their own (controlled to ``tangent_tol``, each within the
    state steps already taken, re-orthonormalized after each, and rejected if they spread the vectors' lengths by
    more than ``_SPREAD`` e-folds; not bounded by ``tau``).  The running estimates are recorded at the end of the
    first tangent step at or past each multiple of ``tau`` (a long step may pass several).  Returns as the other
    loops, and the tangent steps taken and rejected."""
    n, k = Q.shape
    sums, step_sums, hist, hist_t = np.zeros(k), np.zeros(k), np.empty((n_blocks, k)), np.empty(n_blocks)
    K, yt, y_new, ds, eye = np.empty((7, n)), np.empty(n), np.empty(n), np.empty(n), np.zeros((n, n))
    for i in range(n):
        eye[i, i] = 1.0
    J, M, W, d, Q_new = np.empty((3, n, n)), np.empty((8, n, n)), np.empty((6, n, n)), np.empty(n), np.empty((n, k))
    held_t, held_h, held_y, held_K = np.empty(_HELD), np.empty(_HELD), np.empty((_HELD, n)), np.empty((_HELD, 7 * n))
    t_final, t_qr, b, n_held = n_blocks * tau, tau, 0, 0
    accepted, rejected, tangent_steps, tangent_rejected = 0, 0, 0, 0
    t, T, H = 0.0, 0.0, min(h, tau)
    rhs_into(0.0, y, p, K[0])
    while t_final - T > 1e-12 * tau:
        # the state runs ahead of the tangent vectors until their next step lies within its steps
        while t < min(T + H, t_final) and t_final - t > 1e-12 * tau and n_held < _HELD:
            step = min(h, t_final - t)
            err = _state_step(rhs_into, y, p, K, yt, y_new, step, rtol, atol)
            if err <= 1.0:
                held_t[n_held], held_h[n_held] = t, step
                _hold(held_y, held_K, n_held, y, K)
                n_held += 1
                t = t_final if step == t_final - t else t + step
                _copy(y, y_new)
                _copy(K[0], K[6])
                accepted += 1
            else:
                rejected += 1
            h = _controlled(h, step, err, -0.2)
            if accepted + rejected >= max_steps:
                return y, Q, sums, hist_t[:b], hist[:b], -1, rejected, tangent_steps, tangent_rejected
        step = min(H, t - T)
        for g in range(3):
            _dense(yt, T + GAUSS_NODES[g] * step, held_t, held_h, held_y, held_K, n_held, y, t)
            jvp_into(yt, p, eye, ds, J[g])
        err = magnus_step(J, step, Q, Q_new, M, W, d, tangent_tol)
        T_new = t if step == t - T else T + step
        passed = T_new >= t_qr - 1e-12 * tau
        if err <= 1.0 and passed:
            # round-off leaks into the invariants' directions (rate 0), which would outgrow decaying directions
            _dense(yt, T_new, held_t, held_h, held_y, held_K, n_held, y, t)
            _project_out(gradients(yt, p), Q_new)
        for j in range(k):
            step_sums[j] = 0.0
        _orthonormalize(Q_new, step_sums)
        spread = max(step_sums) - min(step_sums)
        if err <= 1.0 and spread <= _SPREAD:
            T = T_new
            for i in range(n):
                for j in range(k):
                    Q[i, j] = Q_new[i, j]
            for j in range(k):
                sums[j] += step_sums[j]
            tangent_steps += 1
            n_held = _drop_before(T, held_t, held_h, held_y, held_K, n_held)
            if passed:
                hist_t[b] = T
                for j in range(k):
                    hist[b, j] = sums[j] / T
                b += 1
                t_qr = min(t_final, (math.floor(T / tau + 1e-9) + 1) * tau)
            H = _controlled(H, step, err, -0.2)
        else:
            tangent_rejected += 1
            if err <= 1e300 and spread < math.inf:
                H = min(_controlled(H, step, err, -0.2), step * 0.9 * _SPREAD / max(spread, 1e-300))
            else:  # the exponential overflowed
                H = 0.2 * step
    return y, Q, sums, hist_t[:b], hist[:b], accepted, rejected, tangent_steps, tangent_rejected


def _magnus_kernel():
    """The compiled loop with Magnus tangent steps (compiled on first use, then loaded from numba's cache)."""
    if _MAGNUS_SIGNATURE not in _benettin_magnus.overloads:
        _benettin_magnus.compile(_MAGNUS_SIGNATURE)
    return _benettin_magnus.overloads[_MAGNUS_SIGNATURE].entry_point


@dataclass(frozen=True)
class LyapunovResult:
    """Lyapunov exponents (1/time, largest first) and their running estimates.

    exponents : (k,) the estimates at ``t_end``.
    history_t : (n_blocks,) times of the re-orthonormalizations; ``history`` (n_blocks, k) the running estimates
        there (sorted like ``exponents``), to judge convergence.
    uncertainty : (k,) half the spread of each running estimate over the last quarter of the run.
    y : the final closed state; ``h``, ``tau``: the step (adaptive: the mean step) and the re-orthonormalization
        interval used; ``steps``, ``rejected``: the accepted and rejected steps; ``method``: which integrator.
    """

    exponents: np.ndarray
    history_t: np.ndarray
    history: np.ndarray
    uncertainty: np.ndarray
    y: np.ndarray
    h: float
    tau: float
    steps: int = 0
    rejected: int = 0
    method: str = "RK4"
    tangent_steps: int = 0
    tangent_rejected: int = 0


def _physical_basis(m: Model, y: np.ndarray, p: np.ndarray, k: int | None) -> np.ndarray:
    from .stability import _basis

    n = len(m.closed_state_names)
    G = m.module.invariant_gradients(y, p) if getattr(m.module, "STATE_INVARIANTS", ()) else np.zeros((0, n))
    _, Q = _basis(G, n)
    if k is None:
        return np.ascontiguousarray(Q)
    if not isinstance(k, int) or not 1 <= k <= Q.shape[1]:
        raise ValueError(f"`k` must be an integer from 1 to {Q.shape[1]} (the physical dimension), got {k!r}")
    return np.ascontiguousarray(Q[:, :k])


def lyapunov(m: Model, y0, p, t_end: float, k: int | None = None, h: float | None = None,
             tau: float | None = None, t0: float = 0.0, rtol: float | None = None, atol: float | None = None,
             max_steps: int = 10**8, tangent_rtol: float | None = None, tangents: str | None = None) -> LyapunovResult:
    """The ``k`` largest Lyapunov exponents (default: all, of the physical phase space) from ``y0`` over
    ``(t0, t_end)``.

    Without ``rtol``: classical Runge-Kutta with the fixed step ``h`` (default: 1/50 of the period of the fastest
    linear mode at ``y0``); ``tau``: the time between re-orthonormalizations (default ``10 h``), rounded to a whole
    number of steps.  With ``rtol`` (and ``atol``, default ``rtol * 1e-2``): the errors of the state and of the
    tangent vectors controlled as in ``simulate`` (the tangent vectors, of unit length after each
    re-orthonormalization, to ``tangent_rtol``, relative and absolute; default ``rtol``, and
    ``MAGNUS_TANGENT_RTOL * rtol`` for Magnus tangents), ``h`` the first step; the tangent vectors are
    re-orthonormalized at the end of the first step at or past each multiple of ``tau`` (default ``span / 1000``,
    rounded to divide the span), the last time at ``t_end``; ``max_steps`` bounds the steps.  ``tangents`` (with
    ``rtol``): ``"magnus"`` steps the tangent vectors by the sixth-order Magnus exponential
    (:mod:`knifeedge.magnus`; ``J`` at the Gauss nodes of the dense output of the state's Dormand-Prince 5(4)
    steps, as ``simulate(method="DP54")``) over steps of their own, each within the state's steps, so that where
    ``J`` hardly changes (a settled spin) neither they nor the state take more steps than the state alone (they are
    re-orthonormalized after every step, which is bounded by the spread of the vectors' lengths it causes, not by
    ``tau``; the history is recorded at the end of the first tangent step at or past each multiple of ``tau``);
    ``"rk"`` steps the state and them together by DOP853 (``simulate``'s default method; the steps then also
    resolve the tangent vectors' oscillation; a step costs less: one Jacobian-vector product per vector and stage,
    no full Jacobian, no matrix exponential).  Default: Magnus for more than one exponent, DOP853 for the largest
    alone (measured: docs/performance.md).  A looser ``tangent_rtol`` takes fewer tangent steps; the exponents
    then move by about that tolerance for Runge-Kutta tangents, by much less for Magnus tangents, whose
    sixth-order steps are controlled by the fourth-order estimate: hence their looser default, with which their
    exponents are about as accurate as Dormand-Prince 5(4) tangents at ``rtol`` (DOP853's are more accurate still;
    docs/performance.md, "Lyapunov exponents").
    """
    p = m.check_params(p)
    y = m._closed(y0).copy()
    if m.jacobian_needs_time:
        raise ValueError(f"{m.name} depends on the time explicitly: its Lyapunov exponents are not computed "
                         f"(the variational loop steps autonomous systems)")
    if not (isinstance(t_end, (int, float)) and math.isfinite(t_end) and t_end > t0):
        raise ValueError(f"`t_end` must be a finite time after `t0` = {t0}, got {t_end!r}")
    span = float(t_end) - float(t0)
    mod = m.module
    if not hasattr(mod, "jvp_into"):
        raise ValueError(f"the module of {m.name} ({m.fidelity}) was written without a Jacobian-vector product by an "
                         f"older knifeedge: regenerate it (make derive, or knifeedge derive)")
    p = np.ascontiguousarray(p, dtype=float)
    if h is None:
        rho = float(np.max(np.abs(np.linalg.eigvals(jacobian(m, y, p)))))
        h = min(2 * math.pi / rho / 50 if rho > 0 else span / 1e4, span / 100)
    if not (isinstance(h, (int, float)) and math.isfinite(h) and 0 < h <= span):
        raise ValueError(f"`h` must be a positive step no longer than the span, got {h!r}")
    Q = _physical_basis(m, y, p, k)
    functions = (mod.jvp_into, mod.invariant_gradients)
    if tangents not in (None, "magnus", "rk"):
        raise ValueError(f"`tangents` must be 'magnus', 'rk' or None (Magnus for more than one exponent), got "
                         f"{tangents!r}")
    if rtol is not None:
        magnus_tangents = tangents == "magnus" or (tangents is None and Q.shape[1] > 1)
        if magnus_tangents:
            functions = (mod.rhs_into, *functions)
        elif Q.shape[1] > 1:
            functions = (mod.jvp_into, _no_product1, mod.invariant_gradients)
        elif hasattr(mod, "jvp1_into"):
            functions = (_no_product, mod.jvp1_into, mod.invariant_gradients)
        else:
            raise ValueError(f"the module of {m.name} ({m.fidelity}) was written without the product of one vector "
                             f"(jvp1_into) by an older knifeedge: regenerate it (make derive, or knifeedge derive)")
        return _adaptive(functions, magnus_tangents, y, Q, p, span, float(t0), h, tau, rtol, atol, max_steps,
                         tangent_rtol)
    if atol is not None or tangent_rtol is not None:
        raise ValueError("`atol` and `tangent_rtol` need `rtol` (the adaptive method); with a fixed step `h` leave "
                         "them out")
    tau = 10 * h if tau is None else tau
    if not (isinstance(tau, (int, float)) and math.isfinite(tau) and h <= tau <= span):
        raise ValueError(f"`tau` must lie between the step `h` = {h} and the span, got {tau!r}")
    steps_per_block = max(1, round(tau / h))
    n_blocks = max(1, int(round(span / (steps_per_block * h))))
    h = span / (n_blocks * steps_per_block)
    if n_blocks * steps_per_block > max_steps:  # a span of 1e12 steps ran for days; of 1e300 overflowed in numba
        raise ValueError(f"the span {span:g} takes {n_blocks * steps_per_block:.3g} steps of `h` = {h:.3g}, more than "
                         f"`max_steps` = {max_steps}: shorten `t_end`, take a longer `h` or raise `max_steps`")
    (n, k), z = Q.shape, np.empty((6, Q.size + y.size))
    z[0, :n], z[0, n:] = y, Q.ravel()
    sums, hist, hist_t = np.zeros(k), np.empty((n_blocks, k)), np.empty(n_blocks)
    _kernel()(*functions, z, n, p, h, n_blocks, steps_per_block, sums, hist, hist_t)
    y = z[0, :n].copy()
    return _result(y, hist_t + float(t0), hist, h, steps_per_block * h, n_blocks * steps_per_block, "RK4")


#: the Magnus tangents' default ``tangent_rtol`` in units of ``rtol``: their sixth-order steps are controlled by the
#: fourth-order estimate, so that at ``10 rtol`` their exponents are about as accurate as Dormand-Prince 5(4)
#: tangents at ``rtol`` (the Runge-Kutta tangents before they moved to DOP853, more accurate still; measured
#: from references at ``tangent_rtol = 1e-4 rtol``: through the celt's reversal, 60 s, rtol
#: 1e-8: 2.7e-7 against 3.4e-7, rtol 1e-10: 1.1e-9 against 8.7e-10; over 10^4 s, rtol 1e-8: 1.6e-9 against 3.6e-8;
#: docs/performance.md), at ``100 rtol`` 13-20x less accurate
MAGNUS_TANGENT_RTOL = 10.0


def _adaptive(functions, magnus_tangents, y, Q, p, span, t0, h, tau, rtol, atol, max_steps,
              tangent_rtol) -> LyapunovResult:
    atol = rtol * 1e-2 if atol is None else atol
    if tangent_rtol is None:
        tangent_rtol = MAGNUS_TANGENT_RTOL * rtol if magnus_tangents else rtol
    for name, v in (("rtol", rtol), ("atol", atol), ("tangent_rtol", tangent_rtol)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise ValueError(f"`{name}` must be a positive tolerance, got {v!r}")
    tau = span / 1000 if tau is None else tau
    if not (isinstance(tau, (int, float)) and math.isfinite(tau) and 0 < tau <= span):
        raise ValueError(f"`tau` must be a positive time no longer than the span, got {tau!r}")
    if not (isinstance(max_steps, int) and max_steps > 0):
        raise ValueError(f"`max_steps` must be a positive integer, got {max_steps!r}")
    n_blocks = max(1, int(round(span / tau)))
    tau = span / n_blocks
    tolerances = float(rtol), float(atol), float(tangent_rtol)
    tangent_steps = tangent_rejected = 0
    if magnus_tangents:
        y, Q, sums, hist_t, hist, accepted, rejected, tangent_steps, tangent_rejected = _magnus_kernel()(
            *functions, magnus.magnus_step, y, Q, p, tau, n_blocks, *tolerances, min(h, tau), max_steps)
    else:
        y, Q, sums, hist_t, hist, accepted, rejected = _adaptive_kernel()(*functions, y, Q, p, tau, n_blocks,
                                                                          *tolerances, min(h, tau), max_steps)
    if accepted < 0:
        raise RuntimeError(f"the variational equations needed more than `max_steps` = {max_steps} steps; raise it "
                           f"or loosen `rtol`")
    method = (f"{'DP54' if magnus_tangents else 'DOP853'} rtol {rtol:g} atol {atol:g}"
              + (f" tangent_rtol {tangent_rtol:g}" if tangent_rtol != rtol else "")
              + (", Magnus tangents" if magnus_tangents else ""))
    # the Magnus loop's history is not evenly spaced (a long tangent step passes several multiples of tau)
    tail_after = t0 + 0.75 * span if magnus_tangents else None
    return _result(y, hist_t + t0, hist, span / accepted, tau, accepted, method, rejected, tangent_steps,
                   tangent_rejected, tail_after)


def _result(y, hist_t, hist, h, tau, steps, method, rejected=0, tangent_steps=0, tangent_rejected=0,
            tail_after=None) -> LyapunovResult:
    """The result, the exponents sorted; the uncertainty from the last quarter of the history's entries (from the
    entries after ``tail_after``, if given: the history's times are then not evenly spaced)."""
    order = np.argsort(-hist[-1], kind="stable")
    hist = hist[:, order]
    if tail_after is None:
        tail = hist[-max(1, len(hist_t) // 4):]
    else:
        tail = hist[(hist_t > tail_after) | (hist_t == hist_t[-1])]
    return LyapunovResult(hist[-1].copy(), hist_t, hist, 0.5 * (tail.max(axis=0) - tail.min(axis=0)), y, h, tau,
                          steps, rejected, method, tangent_steps, tangent_rejected)
