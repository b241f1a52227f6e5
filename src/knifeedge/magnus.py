"""Exponential (Magnus) propagation of tangent vectors: ``dV/dt = J(t) V`` over a step by ``V <- exp(Omega) V``.

The variational equations of a trajectory are linear in the tangent vectors.  Over a step of length ``h`` the
sixth-order Magnus integrator of Blanes, Casas & Ros (BIT 40 (2000) 434-450; also Blanes, Casas, Oteo & Ros,
Phys. Rep. 470 (2009) 151-238, Sect. 5) takes ``J`` at the three Gauss-Legendre nodes ``1/2 -+ sqrt(15)/10, 1/2``
of the step and forms, with ``A_i = h J(t + c_i h)``,

    a1 = A2,  a2 = sqrt(15)/3 (A3 - A1),  a3 = 10/3 (A3 - 2 A2 + A1),
    C1 = [a1, a2],  C2 = -1/60 [a1, 2 a3 + C1],
    Omega6 = a1 + a3/12 + 1/240 [-20 a1 - a3 + C1, a2 + C2],

and the fourth-order ``Omega4 = a1 + a3/12 - C1/12`` from the same nodes: ``(Omega6 - Omega4) V`` estimates the
local error of the fourth-order step (``O(h^5)``, like the embedded estimate of Dormand-Prince 5(4)), and the
step propagates with ``Omega6`` (local extrapolation).  Where ``J`` is constant (a steady motion) every
commutator vanishes and ``exp(h J)`` is exact for any step: the step is not limited by the tangent dynamics'
oscillation or stability, as a Runge-Kutta step on the variational equations is.

``exp`` is scaling and squaring with the [13/13] Pade approximant (Higham, SIAM J. Matrix Anal. Appl. 26 (2005)
1179, Algorithm 2.3; SciPy's ``expm``), after a Parlett-Reinsch balancing by powers of 2 (the celt's Jacobian
mixes tilts and rates: its 1-norm is ten times its spectral radius, its balanced norm three times).  Small dense
matrices (n < ~20) in plain loops: no BLAS call, no allocation per step (the caller passes the work arrays).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

#: the [13/13] Pade coefficients b_0 .. b_13 (Higham 2005, Table 2.3's m = 13) and the largest 1-norm for which
#: the approximant's backward error is below the unit round-off (theta_13)
_PADE13 = np.array([64764752532480000.0, 32382376266240000.0, 7771770303897600.0, 1187353796428800.0,
                    129060195264000.0, 10559470521600.0, 670442572800.0, 33522128640.0, 1323241920.0, 40840800.0,
                    960960.0, 16380.0, 182.0, 1.0])
_THETA13 = 5.371920351148152
#: the Gauss-Legendre nodes of order 6 on [0, 1]
GAUSS_NODES = np.array([0.5 - math.sqrt(15.0) / 10.0, 0.5, 0.5 + math.sqrt(15.0) / 10.0])


@njit(cache=True)
def matmul(A, B, out):
    """``out = A B`` (``out`` distinct from ``A`` and ``B``)."""
    n, m = A.shape
    for i in range(n):
        for j in range(B.shape[1]):
            acc = 0.0
            for l in range(m):
                acc += A[i, l] * B[l, j]
            out[i, j] = acc


@njit(cache=True)
def _commutator(A, B, out, T):
    """``out = [A, B] = A B - B A`` (``T``: work)."""
    matmul(A, B, out)
    matmul(B, A, T)
    for i in range(A.shape[0]):
        for j in range(A.shape[0]):
            out[i, j] -= T[i, j]


@njit(cache=True)
def _solve_in_place(P, X):
    """``X <- P^-1 X`` by Gaussian elimination with partial pivoting (``P`` is overwritten)."""
    n = P.shape[0]
    for c in range(n):
        piv = c
        for r in range(c + 1, n):
            if abs(P[r, c]) > abs(P[piv, c]):
                piv = r
        if piv != c:
            for j in range(n):
                P[c, j], P[piv, j] = P[piv, j], P[c, j]
            for j in range(X.shape[1]):
                X[c, j], X[piv, j] = X[piv, j], X[c, j]
        inverse = 1.0 / P[c, c]
        for r in range(c + 1, n):
            f = P[r, c] * inverse
            if f != 0.0:
                for j in range(c, n):
                    P[r, j] -= f * P[c, j]
                for j in range(X.shape[1]):
                    X[r, j] -= f * X[c, j]
    for c in range(n - 1, -1, -1):
        inverse = 1.0 / P[c, c]
        for j in range(X.shape[1]):
            acc = X[c, j]
            for l in range(c + 1, n):
                acc -= P[c, l] * X[l, j]
            X[c, j] = acc * inverse


@njit(cache=True)
def balance(A, d):
    """Parlett-Reinsch balancing in place: ``A <- D^-1 A D`` with ``D = diag(d)``, powers of 2 (no round-off), so
    that ``exp(A_original) = D exp(A) D^-1``."""
    n = A.shape[0]
    for i in range(n):
        d[i] = 1.0
    converged = False
    while not converged:
        converged = True
        for i in range(n):
            c, r = 0.0, 0.0
            for j in range(n):
                if j != i:
                    c += abs(A[j, i])
                    r += abs(A[i, j])
            if c == 0.0 or r == 0.0:
                continue
            total, f = c + r, 1.0
            while c < r / 2.0:
                f, c, r = f * 2.0, c * 2.0, r / 2.0
            while c >= r * 2.0:
                f, c, r = f / 2.0, c / 2.0, r * 2.0
            if c + r < 0.95 * total:
                converged = False
                d[i] *= f
                for j in range(n):
                    A[j, i] *= f
                    A[i, j] /= f


@njit(cache=True)
def expm(A, out, W):
    """``out = exp(A)`` (n x n) by scaling and squaring with the [13/13] Pade approximant; ``W``: (6, n, n) work."""
    n = A.shape[0]
    norm = 0.0
    for j in range(n):
        col = 0.0
        for i in range(n):
            col += abs(A[i, j])
        norm = max(norm, col)
    s = 0 if norm <= _THETA13 else int(math.ceil(math.log2(norm / _THETA13)))
    A1, A2, A4, A6, T, U = W[0], W[1], W[2], W[3], W[4], W[5]
    scale = 0.5 ** s
    for i in range(n):
        for j in range(n):
            A1[i, j] = A[i, j] * scale
    matmul(A1, A1, A2)
    matmul(A2, A2, A4)
    matmul(A4, A2, A6)
    b = _PADE13
    for i in range(n):
        for j in range(n):
            T[i, j] = b[13] * A6[i, j] + b[11] * A4[i, j] + b[9] * A2[i, j]
    matmul(A6, T, out)
    for i in range(n):
        for j in range(n):
            out[i, j] += b[7] * A6[i, j] + b[5] * A4[i, j] + b[3] * A2[i, j] + (b[1] if i == j else 0.0)
            T[i, j] = b[12] * A6[i, j] + b[10] * A4[i, j] + b[8] * A2[i, j]
    matmul(A1, out, U)  # the odd part U = A (...)
    matmul(A6, T, out)
    for i in range(n):
        for j in range(n):
            v = out[i, j] + b[6] * A6[i, j] + b[4] * A4[i, j] + b[2] * A2[i, j] + (b[0] if i == j else 0.0)
            A2[i, j] = v - U[i, j]
            out[i, j] = v + U[i, j]
    _solve_in_place(A2, out)  # (V - U)^-1 (V + U)
    for _ in range(s):
        matmul(out, out, T)
        for i in range(n):
            for j in range(n):  # (a loop: a slice assignment costs seconds of compile)
                out[i, j] = T[i, j]


@njit(cache=True)
def magnus_step(J, h, Q, Q_new, M, W, d, tol):
    """``Q_new = exp(Omega6) Q`` from ``J`` (3, n, n) at the Gauss nodes of a step ``h``; returns the RMS over the
    entries of the error estimate ``(Omega6 - Omega4) Q_new``, each scaled by ``tol (1 + |Q_new|)``.  Work arrays:
    ``M`` (8, n, n), ``W`` (6, n, n), ``d`` (n,)."""
    n, k = Q.shape
    a1, a2, a3, c1, c2, T, D, E = M[0], M[1], M[2], M[3], M[4], M[5], M[6], M[7]
    r15 = math.sqrt(15.0) / 3.0
    for i in range(n):
        for j in range(n):
            a1[i, j] = h * J[1, i, j]
            a2[i, j] = h * r15 * (J[2, i, j] - J[0, i, j])
            a3[i, j] = h * 10.0 / 3.0 * (J[2, i, j] - 2.0 * J[1, i, j] + J[0, i, j])
    _commutator(a1, a2, c1, T)
    for i in range(n):
        for j in range(n):
            D[i, j] = 2.0 * a3[i, j] + c1[i, j]
    _commutator(a1, D, c2, T)
    for i in range(n):
        for j in range(n):
            D[i, j] = -20.0 * a1[i, j] - a3[i, j] + c1[i, j]
            E[i, j] = a2[i, j] - c2[i, j] / 60.0
    _commutator(D, E, a2, T)
    for i in range(n):
        for j in range(n):
            D[i, j] = a2[i, j] / 240.0 + c1[i, j] / 12.0  # Omega6 - Omega4
            E[i, j] = a1[i, j] + a3[i, j] / 12.0 + a2[i, j] / 240.0  # Omega6
    balance(E, d)
    expm(E, T, W)
    for i in range(n):
        for j in range(n):
            T[i, j] *= d[i] / d[j]
    matmul(T, Q, Q_new)
    acc = 0.0
    for j in range(k):
        for i in range(n):
            e = 0.0
            for l in range(n):
                e += D[i, l] * Q_new[l, j]
            acc += (e / (tol * (1.0 + abs(Q_new[i, j])))) ** 2
    return math.sqrt(acc / (n * k))
