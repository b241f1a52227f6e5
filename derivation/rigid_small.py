"""Small-tilt fidelities of a rigid body rolling on the table: ``reduced`` and ``amplitude``.

Both start from the exact equations of :func:`derivation.rigid.equations`,
``M(n) domega/dt = f(n, omega)``, of a body whose upright state spinning
about the vertical body axis is an equilibrium (the lowest point of the shape
is on the body ``z`` axis when upright and ``I_xz = I_yz = 0``; :func:`check`).

``reduced`` (small tilts, spin kept)
    Scale the horizontal components of the vertical, ``n_x, n_y``, and the
    rocking rates ``omega_x, omega_y`` by ``eps``, keep the spin ``omega_z``
    of order one (``n_z = sqrt(1 - n_x^2 - n_y^2)``).  Expanding ``M`` and
    ``f`` to second order and solving order by order,
    ``x0 = M0^-1 f0``, ``x1 = M0^-1 (f1 - M1 x0)``,
    ``x2 = M0^-1 (f2 - M1 x1 - M2 x0)``, the reduced equations keep the
    rocking accelerations to first order and the spin acceleration to second
    order -- the ordering of the paper's reduced knife edges (Eqs.
    ``FINAL3``, ``eqs_2modes``)::

        dn_x/dt = n_y omega_z - omega_y,      dn_y/dt = omega_x - n_x omega_z,
        domega_x/dt = x0_x + x1_x,  domega_y/dt = x0_y + x1_y,  domega_z/dt = x0_z + x2_z.

    (The other orders vanish: the body is symmetric under a half turn about
    its vertical axis.)  The vertical spin is ``omega_z`` (``omega . n`` to
    second order); its zero crossings are the reversals.

``amplitude`` (averaged over the two rocking modes)
    With the tilt ``q = (n_x, n_y)`` and ``q_dot = (n_y omega_z - omega_y,
    omega_x - n_x omega_z)`` the reduced rocking equations are
    ``q_ddot = -W(omega_z) q - V(omega_z) q_dot``.  Without spin and damping
    ``q_ddot = -W0 q``: two rocking modes, *pitch* (mostly ``n_x``: the long
    ``x`` axis tips) and *roll* (mostly ``n_y``), which the inertia
    misalignment ``I_xy`` couples -- their shapes ``u_k`` (unit vectors,
    right eigenvectors of ``W0``; ``v_k`` the left ones with ``v_k . u_k = 1``)
    are not the body axes.  In the normal modes ``q = sum_k A_k u_k
    cos(Omega_k t + phase_k)``, first-order averaging over the two
    non-resonant phases gives::

        dA_k/dt = -(1/2) v_k . V(omega_z) u_k  A_k = (lambda_k omega_z - d_k sigma) A_k,
        domega_z/dt = x0_z(omega_z) + sum_k <x2_z>_k A_k^2,

    where ``<x2_z>_k`` is the average of the quadratic form ``x2_z(q, q_dot)``
    over one period of mode ``k`` (``<q q^T> = u u^T/2``, ``<q_dot q_dot^T> =
    Omega^2 u u^T/2``, ``<q q_dot^T> = 0``).  ``A_k`` is the tilt amplitude of
    mode ``k`` [rad].  The growth rates are exactly linear in the spin;
    the spin equation's coefficients are even in it.  :func:`moffatt_tokieda`
    gives the limit in which these are the equations of Moffatt & Tokieda.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from . import rigid
from .engine import ReducedSystem

n_x, n_y, n_z = rigid.N_VEC
omega_x, omega_y, omega_z = rigid.OMEGA
eps = sp.Symbol("eps", positive=True)
#: tilt rates (the time derivatives of n_x, n_y) used by the averaging
q1_dot, q2_dot = sp.symbols("q1_dot q2_dot", real=True)
#: amplitude-model state: tilt amplitudes of the pitch and roll modes, and the spin
A_pitch, A_roll = sp.symbols("A_pitch A_roll", nonnegative=True)

REDUCED_STATE = (n_x, n_y, omega_x, omega_y, omega_z)
AMPLITUDE_STATE = (A_pitch, A_roll, omega_z)
UNITS = {"A_pitch": "rad", "A_roll": "rad"}


STATE_VARS = (n_x, n_y, omega_x, omega_y, omega_z, q1_dot, q2_dot, A_pitch, A_roll)


def terms(e: sp.Expr, variables) -> dict:
    """``{monomial in variables: coefficient}`` of the polynomial ``e`` (coefficients free of ``variables``)."""
    out: dict = {}
    for t in sp.Add.make_args(sp.expand(e)):
        c, m = t.as_independent(*variables, as_Add=False)
        out[m] = out.get(m, sp.S.Zero) + c
    return {m: c for m, c in out.items() if c != 0}


def collect(e: sp.Expr, variables=STATE_VARS) -> sp.Expr:
    """``e`` as a polynomial in ``variables``, one term per monomial."""
    return sp.Add(*(c * m for m, c in terms(e, variables).items()))


def _scaling() -> dict:
    """Tilts and rocking rates of order ``eps``; ``n_z = sqrt(1 - eps^2 (n_x^2 + n_y^2))`` to second order."""
    return {n_x: eps * n_x, n_y: eps * n_y, n_z: 1 - eps**2 * (n_x**2 + n_y**2) / 2,
            omega_x: eps * omega_x, omega_y: eps * omega_y}


def _taylor(e: sp.Expr, order: int, zero: dict) -> list:
    """Coefficients of ``eps^0 .. eps^order`` of the polynomial (in the state) ``e`` under :func:`_scaling`."""
    d = sp.expand(sp.sympify(e).xreplace(zero).xreplace(_scaling()))
    return [d.coeff(eps, k) if k else d.subs(eps, 0) for k in range(order + 1)]


@dataclass(frozen=True)
class _TaylorShape:
    """A shape's lowest point replaced by its Taylor polynomial about the upright vertical ``(0, 0, 1)``.

    Terms kept: orders 0, 1, 2 in ``n_x, n_y`` and order 1 in ``n_z - 1`` (which is second order in the
    tilts); its Jacobian is then right to first order, which is all the second-order equations use
    (``dn/dt`` is first order).
    """

    shape: object

    def lowest_point(self, n: sp.Matrix) -> sp.Matrix:
        r = self.shape.lowest_point(rigid.N_VEC)
        up = {n_x: 0, n_y: 0, n_z: 1}
        dz = n[2] - 1
        out = r.xreplace(up) + r.diff(n_z).xreplace(up) * dz
        for v, nv in ((n_x, n[0]), (n_y, n[1])):
            out += r.diff(v).xreplace(up) * nv
        for (v, nv), (w, nw) in ((((n_x, n[0]), (n_x, n[0]))), (((n_x, n[0]), (n_y, n[1]))),
                                 (((n_y, n[1]), (n_y, n[1])))):
            k = 1 if v == w else 2
            out += k * r.diff(v, w).xreplace(up) * nv * nw / 2
        return out.applyfunc(sp.simplify)


def zero_products(body: rigid.RigidBody) -> dict:
    """Products of inertia that must vanish for the upright spin to be an equilibrium (``I_xz``, ``I_yz``)."""
    inertia = sp.Matrix(body.inertia)
    return {e: 0 for e in (inertia[0, 2], inertia[1, 2]) if isinstance(e, sp.Symbol)}


def check(body: rigid.RigidBody) -> None:
    """Refuse a body whose upright spinning state is not an equilibrium (the small-tilt fidelities expand about it)."""
    zero = zero_products(body)
    inertia = sp.Matrix(body.inertia).xreplace(zero)
    r0 = body.shape.lowest_point(sp.Matrix([0, 0, 1])).xreplace(zero)
    problems = []
    if inertia[0, 2] != 0 or inertia[1, 2] != 0:
        problems.append("the products of inertia I_xz, I_yz must be zero (or plain symbols, set to zero)")
    if sp.simplify(r0[0]) != 0 or sp.simplify(r0[1]) != 0:
        problems.append("the lowest point of the upright body must lie on the body z axis")
    if problems:
        raise ValueError(f"{body.name}: no small-tilt fidelities: " + "; ".join(problems))


@dataclass
class SmallTiltSystem(rigid.RollingSystem):
    """A small-tilt fidelity of a rigid body (``reduced`` or ``amplitude``): the state and its rates.

    ``rates`` are the right-hand sides in the order of ``state``; ``energy`` the
    mechanical energy to the order of the fidelity; ``power`` the power dissipated.
    ``dropped`` names the parameters set to zero (``I_xz``, ``I_yz``).
    """

    fidelity: str = "reduced"
    rates: list = field(default_factory=list)
    dropped: dict = field(default_factory=dict)
    coefficients: dict = field(default_factory=dict)
    #: read by emit.write_all for the other fidelities' ``frequencies(p)`` (rigid modules export ``modes(p)``)
    frequencies: tuple = ()

    def state_rhs(self) -> list:
        return list(self.rates)


_EXPANSIONS: dict = {}


def _expansion(body: rigid.RigidBody) -> dict:
    """Orders 0..2 of ``M``, ``f``, the energy, and the order-by-order solution ``x0, x1, x2`` (cached per body)."""
    key = (body.name, sp.srepr(sp.Matrix(body.inertia)), sp.srepr(body.sigma), repr(body.shape))
    if key not in _EXPANSIONS:
        _EXPANSIONS[key] = _expand(body)
    return _EXPANSIONS[key]


#: placeholders for the inertia about the contact point upright (``M0``) while solving order by order
_J = sp.symbols("_J_xx _J_yy _J_xy _J_zz _J_det", real=True)


def _expand(body: rigid.RigidBody) -> dict:
    import dataclasses

    check(body)
    zero = zero_products(body)
    parts = rigid.equations(dataclasses.replace(body, shape=_TaylorShape(body.shape)))
    M, f = parts["mass_matrix"], parts["forcing"]
    Ms = [sp.zeros(3, 3) for _ in range(3)]
    fs = [sp.zeros(3, 1) for _ in range(3)]
    for i in range(3):
        for j in range(3):
            for k, c in enumerate(_taylor(M[i, j], 2, zero)):
                Ms[k][i, j] = c
        for k, c in enumerate(_taylor(f[i], 2, zero)):
            fs[k][i] = c
    M0 = Ms[0]
    if M0[0, 2] != 0 or M0[1, 2] != 0:
        raise ValueError(f"{body.name}: the upright inertia about the contact couples spin and rocking")
    jxx, jyy, jxy, jzz, det = _J
    fill = {jxx: M0[0, 0], jyy: M0[1, 1], jxy: M0[0, 1], jzz: M0[2, 2], det: sp.factor(M0[0, 0] * M0[1, 1] - M0[0, 1]**2)}
    M0inv = sp.Matrix([[jyy / det, -jxy / det, 0], [-jxy / det, jxx / det, 0], [0, 0, 1 / jzz]])
    x0 = (M0inv * fs[0]).applyfunc(lambda e: collect(e, STATE_VARS))
    x1 = (M0inv * (fs[1] - Ms[1] * x0)).applyfunc(lambda e: collect(e, STATE_VARS))
    x2 = (M0inv * (fs[2] - Ms[1] * x1 - Ms[2] * x0)).applyfunc(lambda e: collect(e, STATE_VARS))
    energy = parts["kinetic"] + body.mass * body.gravity * parts["height"]
    e_orders = _taylor(energy, 2, zero)
    return {"M": Ms, "f": fs, "x": (x0, x1, x2), "energy": e_orders[0] + e_orders[2], "odd": (x1[2], x2[0], x2[1]),
            "zero": zero, "height": _taylor(parts["height"], 2, zero), "fill": fill}


def fill(e, body: rigid.RigidBody):
    """Replace the placeholders of ``M0`` by their expressions in the parameters."""
    return sp.sympify(e).xreplace(_expansion(body)["fill"])


def reduced(full: rigid.RollingSystem) -> SmallTiltSystem:
    """The ``reduced`` fidelity of a derived rigid body (see the module docstring)."""
    body = full.body
    ex = _expansion(body)
    x0, x1, x2 = ex["x"]
    rates = [n_y * omega_z - omega_y, omega_x - n_x * omega_z, x0[0] + x1[0], x0[1] + x1[1], x0[2] + x2[2]]
    rates = [fill(r, body) for r in rates]
    import dataclasses

    spec = dataclasses.replace(full.spec, params=tuple(q for q in full.spec.params if q not in ex["zero"]), pose=())
    return SmallTiltSystem(
        spec=spec, state=REDUCED_STATE, accelerations=full.accelerations, mass_matrix=ex["M"][0],
        forcing=sp.Matrix(rates[2:]), explicit=sp.Matrix(rates[2:]), multipliers=sp.Matrix([]),
        multipliers_implicit=sp.Matrix([]), energy=sp.expand(ex["energy"]), pose_rates={}, body=body,
        contact=full.contact, height=full.height, power=full.power.xreplace(ex["zero"]), omega_dot=None,
        fidelity="reduced", rates=rates, dropped=ex["zero"],
    )


def tilt_form(system: SmallTiltSystem) -> dict:
    """The reduced rocking equations as ``q_ddot = -W q - V q_dot`` and the spin's quadratic form.

    ``q = (n_x, n_y)``, ``q_dot`` its rate.  Returns ``W`` and ``V`` as ``{monomial in (omega_z, sigma):
    2x2 coefficient matrix}``, ``spin`` (``x0_z``) and ``S``: ``x2_z`` as ``{monomial in (omega_z, sigma):
    {(i, j): coefficient of z_i z_j}}`` with ``z = (n_x, n_y, q1_dot, q2_dot)``, ``i <= j``.
    """
    ex = _expansion(system.body)
    x0, x1, x2 = ex["x"]
    sigma = system.body.sigma if isinstance(system.body.sigma, sp.Symbol) else None
    slow = (omega_z, sigma) if sigma is not None else (omega_z,)
    z = (n_x, n_y, q1_dot, q2_dot)
    back = {omega_x: q2_dot + n_x * omega_z, omega_y: n_y * omega_z - q1_dot}
    wdx, wdy = ((x0[i] + x1[i]).xreplace(back) for i in (0, 1))
    qdd = [q2_dot * omega_z - wdy, wdx - q1_dot * omega_z]
    W: dict = {}
    V: dict = {}
    for row, e in enumerate(qdd):
        for mono, c in terms(e, z + slow).items():
            zpart, spart = mono.as_independent(*slow, as_Add=False)
            col = z.index(zpart)
            target = W if col < 2 else V
            target.setdefault(spart, sp.zeros(2, 2))[row, col % 2] -= c
    zero_part, S = _quadratic(x2[2], slow)
    if zero_part != 0:
        raise ValueError(f"spin acceleration has a part free of the rocking: {zero_part}")
    return {"W": W, "V": V, "spin": x0[2], "S": S, "slow": slow}


@dataclass(frozen=True)
class Modes:
    """Rocking modes of the non-spinning, undamped body: ``W0 u_k = Omega_k^2 u_k``, ``v_k . u_j = delta_kj``."""

    W0: sp.Matrix
    omega2: tuple   # (pitch, roll)
    u: tuple        # unit right eigenvectors
    v: tuple        # left eigenvectors, v_k . u_k = 1


def modes(W0: sp.Matrix) -> Modes:
    """Closed-form modes of ``W0``; pitch is the ``+`` root, assumed mostly ``n_x`` (``W0[0,0] > W0[1,1]``)."""
    w11, w12, w21, w22 = W0[0, 0], W0[0, 1], W0[1, 0], W0[1, 1]
    root = sp.sqrt((w11 - w22) ** 2 + 4 * w12 * w21)
    lp, lm = (w11 + w22 + root) / 2, (w11 + w22 - root) / 2
    u_p, u_m = sp.Matrix([lp - w22, w21]), sp.Matrix([w12, lm - w11])
    v_p, v_m = sp.Matrix([lp - w22, w12]), sp.Matrix([w21, lm - w11])
    u_p, u_m = u_p / sp.sqrt(u_p.dot(u_p)), u_m / sp.sqrt(u_m.dot(u_m))
    v_p, v_m = v_p / v_p.dot(u_p), v_m / v_m.dot(u_m)
    return Modes(W0, (lp, lm), (u_p, u_m), (v_p, v_m))


_Z = (n_x, n_y, q1_dot, q2_dot)


def _quadratic(e: sp.Expr, slow) -> tuple:
    """``e`` (in ``n, omega``) as ``e0(slow) + sum_m m * {(i, j): c}`` quadratic in ``z = (q, q_dot)``."""
    back = {omega_x: q2_dot + n_x * omega_z, omega_y: n_y * omega_z - q1_dot}
    e0 = sp.S.Zero
    quad: dict = {}
    for mono, c in terms(sp.sympify(e).xreplace(back), _Z + tuple(slow)).items():
        zpart, spart = mono.as_independent(*slow, as_Add=False)
        if zpart == 1:
            e0 += c * spart
            continue
        idx = []
        for f in sp.Mul.make_args(zpart):
            b, k = f.as_base_exp()
            idx += [_Z.index(b)] * int(k)
        if len(idx) != 2:
            raise ValueError(f"not quadratic in the rocking: {mono}")
        key = tuple(sorted(idx))
        quad.setdefault(spart, {})[key] = quad.get(spart, {}).get(key, sp.S.Zero) + c
    return e0, quad


def _mode_average(quad: dict, u, w2) -> sp.Expr:
    """Average of ``sum c_ij z_i z_j`` over one period of the mode ``q = u cos(theta)`` (unit amplitude):
    ``<q_i q_j> = u_i u_j/2``, ``<q_dot_i q_dot_j> = Omega^2 u_i u_j/2``, ``<q_i q_dot_j> = 0``."""
    total = sp.S.Zero
    for (i, j), c in quad.items():
        if i < 2 and j < 2:
            total += c * u[i] * u[j] / 2
        elif i >= 2 and j >= 2:
            total += c * w2 * u[i - 2] * u[j - 2] / 2
    return total


def amplitude(red: SmallTiltSystem) -> SmallTiltSystem:
    """The ``amplitude`` fidelity: first-order averaging of ``red`` over its two rocking modes."""
    form = tilt_form(red)
    W, V, S, slow = form["W"], form["V"], form["S"], form["slow"]
    md = modes(W.get(sp.S.One, sp.zeros(2, 2)))
    growth, kappa = [], []
    for u, v, w2 in zip(md.u, md.v, md.omega2):
        growth.append({m: -(v.T * Vm * u)[0] / 2 for m, Vm in V.items()})
        kappa.append({m: _mode_average(quad, u, w2) for m, quad in S.items()})
    A = (A_pitch, A_roll)

    def poly(d):
        return sp.Add(*(c * m for m, c in d.items()))

    rates = [poly(growth[0]) * A_pitch, poly(growth[1]) * A_roll,
             form["spin"] + poly(kappa[0]) * A_pitch**2 + poly(kappa[1]) * A_roll**2]
    rates = [fill(r, red.body) for r in rates]
    # averaged energy: the reduced energy averaged over each mode (the same averages as the spin equation)
    ex = _expansion(red.body)
    K = sp.hessian(red.body.mass * red.body.gravity * ex["height"][2], [n_x, n_y]).applyfunc(sp.factor)
    J_zz = ex["M"][0][2, 2]
    e0, e_quad = _quadratic(red.energy, form["slow"])
    energy = e0 + sum((a**2 * sp.Add(*(m * _mode_average(quad, u, w2) for m, quad in e_quad.items()))
                       for u, w2, a in zip(md.u, md.omega2, A)), sp.S.Zero)
    energy = fill(energy, red.body)
    sigma = red.body.sigma if isinstance(red.body.sigma, sp.Symbol) else None
    power = sp.S.Zero
    if sigma is not None:  # -dE/dt from the damping terms of the rates
        state = (A_pitch, A_roll, omega_z)
        power = -sum((sp.diff(energy, x) * (r - r.xreplace({sigma: 0})) for x, r in zip(state, rates)), sp.S.Zero)
    coefficients = {"growth": tuple(growth), "kappa": tuple(kappa), "modes": md, "K": K, "J_zz": J_zz,
                    "spin": form["spin"], "slow": slow}
    return SmallTiltSystem(
        spec=red.spec, state=AMPLITUDE_STATE, accelerations=(), mass_matrix=sp.Matrix([]),
        forcing=sp.Matrix([]), explicit=sp.Matrix([]), multipliers=sp.Matrix([]),
        multipliers_implicit=sp.Matrix([]), energy=energy, pose_rates={}, body=red.body, contact=red.contact,
        height=red.height, power=power, omega_dot=None, fidelity="amplitude", rates=rates, dropped=red.dropped,
        coefficients=coefficients,
    )


def moffatt_tokieda(amp: SmallTiltSystem) -> dict:
    """``lambda``, ``mu`` and the scalings that put the averaged equations into Moffatt & Tokieda's form.

    Limit: no dissipation, and the spin-dependent part of the spin equation's
    coefficients negligible (``kappa_k(omega_z) -> kappa_k(0)``, i.e. the spin
    small against the rocking frequencies).  Then, with ``n = omega_z``,
    ``P = p A_pitch``, ``R = r A_roll``::

        P' = lambda n P,  R' = -mu n R,  n' = mu R^2 - lambda P^2,
        lambda = growth_pitch / omega_z,  mu = -growth_roll / omega_z,
        p^2 = -kappa_pitch(0)/lambda,  r^2 = kappa_roll(0)/mu,

    with the first integrals ``n^2 + P^2 + R^2`` and ``P^mu R^lambda``.
    Returns expressions in the body's parameters.
    """
    growth, kappa = amp.coefficients["growth"], amp.coefficients["kappa"]
    lam = growth[0].get(omega_z, sp.S.Zero)
    mu = -growth[1].get(omega_z, sp.S.Zero)
    k_p, k_r = (k.get(sp.S.One, sp.S.Zero) for k in kappa)
    body = amp.body

    def f(e):
        return fill(e, body)

    return {"lambda": f(lam), "mu": f(mu), "p2": f(-k_p / lam), "r2": f(k_r / mu), "kappa0": (f(k_p), f(k_r)),
            "growth": tuple({m: f(c) for m, c in g.items()} for g in growth),
            "kappa": tuple({m: f(c) for m, c in k.items()} for k in kappa)}


def build(body: rigid.RigidBody) -> dict:
    """``{(name, fidelity): system}``: ``full``, and ``reduced`` and ``amplitude`` when ``body.small`` is set."""
    full = rigid.derive(body)
    out = {(body.name, "full"): full}
    if body.small:
        red = reduced(full)
        out[(body.name, "reduced")] = red
        out[(body.name, "amplitude")] = amplitude(red)
    return out
