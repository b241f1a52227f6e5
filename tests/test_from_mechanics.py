"""``knifeedge.derive.from_mechanics``: models written with ``sympy.physics.mechanics``, converted.

The default tier checks the conversion on a small model (the Chaplygin sleigh: its Lagrangian,
constraint and reduced equations against the textbook's) and every refusal; the peer checks, the field's own models
derived and compiled and run against their authors' own equations, are in
``tests/test_mechanics_peers.py`` (slow tier).
"""
import pytest
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point, ReferenceFrame,
                                     RigidBody, dot, dynamicsymbols, inertia)

from knifeedge.derive import MechanicsConversionError, derive, from_mechanics
from knifeedge.derive import t as ke_t

t = dynamicsymbols._t


def _sleigh(torque=None, force=None):
    """The Chaplygin sleigh by Kane's method: a body on the table, its knife edge at P = (x, y) along B.x,
    its mass centre G at a distance a ahead of P on the blade; the blade cannot slide sideways."""
    x, y, phi, u1, u2, u3 = dynamicsymbols("x y phi u1 u2 u3")
    m, a, I, g = sp.symbols("m a I g", positive=True)
    N, O = ReferenceFrame("N"), Point("O")
    O.set_vel(N, 0)
    B = N.orientnew("B", "Axis", [phi, N.z])
    P = O.locatenew("P", x * N.x + y * N.y)
    P.set_vel(N, u1 * N.x + u2 * N.y)
    G = P.locatenew("G", a * B.x)
    B.set_ang_vel(N, u3 * N.z)
    G.v2pt_theory(P, N, B)
    body = RigidBody("sleigh", G, B, m, (inertia(B, 0, 0, I), G))
    loads = [(G, -m * g * N.z)]
    loads += [(B, torque * N.z)] if torque is not None else []
    loads += [(G, force * N.x)] if force is not None else []
    km = KanesMethod(N, [x, y, phi], [u1, u3], kd_eqs=[x.diff(t) - u1, y.diff(t) - u2, phi.diff(t) - u3],
                     u_dependent=[u2], velocity_constraints=[P.vel(N).dot(B.y)])
    km.kanes_equations([body], loads)
    return km, (x, y, phi, u3, m, a, I, g)


def test_the_sleigh_gets_its_lagrangian_constraint_and_textbook_equations():
    """T = m |v_G|^2 / 2 + I phi_dot^2 / 2, the blade's lateral velocity as the constraint; with v the
    forward speed and omega = phi_dot the reduced equations are v' = a omega^2, omega' = -m a v omega /
    (I + m a^2) (A. M. Bloch, *Nonholonomic Mechanics and Control*, section 1.7)."""
    km, (x, y, phi, u3, m, a, I, g) = _sleigh()
    spec = from_mechanics(km, name="sleigh", cyclic={x: 0, y: 0, phi: 0}, units={x: "m", phi.diff(t): "rad/s"})
    X, Y, PHI, XD, YD, PHID = sp.symbols("x y phi x_dot y_dot phi_dot", real=True)
    assert spec.coordinates == (X, Y, PHI) and spec.velocities == (XD, YD, PHID)
    assert spec.dependent == (Y,) and spec.params == (I, a, m) and spec.forces == ()
    vG = sp.Matrix([XD - a * sp.sin(PHI) * PHID, YD + a * sp.cos(PHI) * PHID])
    assert sp.simplify(spec.lagrangian - (m * vG.dot(vG) / 2 + I * PHID**2 / 2)) == 0
    assert sp.simplify(spec.constraints[0] - (-sp.sin(PHI) * XD + sp.cos(PHI) * YD)) == 0
    assert spec.units == {X: "m", PHID: "rad/s"} and spec.pose == (X, Y, PHI)
    system = derive(spec)
    assert system.state == (XD, PHID)  # at the representative heading 0, x_dot is the forward speed v
    assert sp.simplify(system.explicit[0] - a * PHID**2) == 0
    assert sp.simplify(system.explicit[1] + m * a * XD * PHID / (I + m * a**2)) == 0


def test_loads_that_are_not_constant_become_generalized_forces():
    """A viscous torque -c phi_dot about the vertical gives Q_phi = -c phi_dot; a force F along N.x at G,
    constant, is a potential -F x_G."""
    c, F = sp.symbols("c F")
    u3 = dynamicsymbols("u3")
    km, (x, y, phi, u3, m, a, I, g) = _sleigh(torque=-c * u3)
    spec = from_mechanics(km, name="damped_sleigh", cyclic={x: 0, y: 0, phi: 0})
    PHI, PHID = sp.symbols("phi phi_dot", real=True)
    assert [sp.simplify(f) for f in spec.forces] == [0, 0, -c * PHID]
    km, (x, y, phi, u3, m, a, I, g) = _sleigh(force=F)
    pushed = from_mechanics(km, name="pushed_sleigh", cyclic={x: 0, y: 0, phi: 0})
    base = from_mechanics(_sleigh()[0], name="sleigh", cyclic={x: 0, y: 0, phi: 0})
    X = sp.Symbol("x", real=True)
    assert sp.simplify(pushed.lagrangian - base.lagrangian - F * (X + a * sp.cos(PHI))) == 0


def test_a_model_without_velocity_constraints_is_refused_with_the_reason():
    """sympy's test_lagrange.py rolling disc has none: its rolling condition is substituted into the
    Lagrangian, which gives wrong equations (sympy#27631)."""
    q = dynamicsymbols("q")
    m, l, g = sp.symbols("m l g", positive=True)
    N, O = ReferenceFrame("N"), Point("O")
    O.set_vel(N, 0)
    P = Particle("P", O.locatenew("P", l * (sp.sin(q) * N.x - sp.cos(q) * N.y)), m)
    P.point.set_vel(N, P.point.pos_from(O).dt(N))
    P.potential_energy = -m * g * l * sp.cos(q)
    lm = LagrangesMethod(Lagrangian(N, P), [q], frame=N)
    with pytest.raises(MechanicsConversionError, match="no velocity constraint.*sympy#27631"):
        from_mechanics(lm, name="pendulum", cyclic={})


def test_specified_quantities_become_inputs(tmp_path):
    """A torque ``f(t)`` on the sleigh, a specified quantity, is the model's input ``f``: the compiled model
    with a piecewise-linear ``f`` given at run time against the author's own equations (Kane's
    ``mass_matrix_full``/``forcing_full`` through ``lambdify``, the dependent speed u2 solved with them),
    integrated with the same input by SciPy interval by interval."""
    import numpy as np
    from scipy.integrate import solve_ivp

    import knifeedge as ke
    from knifeedge.derive import emit
    from knifeedge.derive.cli import derive_specs

    f = dynamicsymbols("f")
    km, (x, y, phi, u3, m, a, I, g) = _sleigh(torque=f)
    X, PHI, XD, YD, v = sp.symbols("x phi x_dot y_dot v", real=True)
    spec = from_mechanics(km, name="steered", cyclic={x: 0, y: 0, phi: 0},
                          quasi_velocities=((v, XD, XD * sp.cos(PHI) + YD * sp.sin(PHI)),))
    assert spec.inputs == (sp.Symbol("f", real=True),) and set(spec.params) == {I, a, m}
    emit.write_all(tmp_path, derive_specs([spec]), registry=False)
    model = ke.load("steered", path=tmp_path, pose=True)
    assert model.input_names == ("f",) and model.state_names == ("v", "phi_dot", "x", "y", "phi")
    values = {I: 0.7, a: 0.4, m: 1.3, g: 9.81}
    F = sp.Symbol("F")
    states = list(km.q) + list(km.u)
    swap = {**{s: sp.Symbol(f"s{i}") for i, s in enumerate(states)}, f: F}
    M = sp.lambdify([*swap.values()], km.mass_matrix_full.subs(values).xreplace(swap))
    rhs = sp.lambdify([*swap.values()], km.forcing_full.subs(values).xreplace(swap))
    ts, us = np.array([0.0, 0.8, 2.1, 2.5, 4.0]), np.array([0.2, -0.5, 0.4, 0.0, 0.3])

    def kane(t, z):
        args = [*z, np.interp(t, ts, us)]
        return np.linalg.solve(np.array(M(*args), dtype=float), np.array(rhs(*args), dtype=float).ravel())

    t0, t1 = 0.3, 4.0
    phi0, v0, w0 = 0.2, 0.5, 0.1  # heading, forward speed, turning rate; u2 from the constraint
    z = np.array([0.0, 0.0, phi0, v0 * np.cos(phi0), w0, v0 * np.sin(phi0)])
    t_eval = np.linspace(t0, t1, 9)
    kept = []
    for lo, hi in zip([t0, 0.8, 2.1, 2.5], [0.8, 2.1, 2.5, t1]):
        sol = solve_ivp(kane, (lo, hi), z, method="DOP853", rtol=1e-13, atol=1e-15, dense_output=True)
        inside = t_eval[(t_eval >= lo) & ((t_eval < hi) | (hi == t1))]
        kept.append(sol.sol(inside))
        z = sol.y[:, -1]
    want = np.concatenate(kept, axis=1)
    p = model.params({str(k): v for k, v in values.items() if k != g})
    r = ke.simulate(model, [v0, w0, 0.0, 0.0, phi0], (t0, t1), p, method="scipy:DOP853", t_eval=t_eval,
                    rtol=1e-12, atol=1e-14, inputs={"f": (ts, us)})
    assert r.success, r.message
    forward = want[3] * np.cos(want[2]) + want[5] * np.sin(want[2])
    assert np.max(np.abs(r["v"] - forward)) < 1e-9 and np.max(np.abs(r["phi_dot"] - want[4])) < 1e-9
    assert np.max(np.abs(r["x"] - want[0])) < 1e-9 and np.max(np.abs(r["phi"] - want[2])) < 1e-9
    assert np.ptp(want[4]) > 0.1  # the torque turned the sleigh


def test_rates_of_specified_quantities_are_refused_with_the_reason():
    f = dynamicsymbols("f")
    km, (x, y, phi, *_) = _sleigh(torque=f.diff(t))
    with pytest.raises(MechanicsConversionError, match=r"rates of the specified quantities \['f\(t\)'\]"):
        from_mechanics(km, name="driven", cyclic={x: 0, y: 0, phi: 0})


def test_explicit_time_is_the_engines_time():
    """The sleigh turned by a torque tau(t) = c cos(w t): with v the forward speed and omega = phi_dot,
    v' = a omega^2, omega' = (tau - m a v omega) / (I + m a^2) (A. M. Bloch, *Nonholonomic Mechanics and
    Control*, section 1.7, with the torque about the vertical added to the angular momentum balance)."""
    c, w = sp.symbols("c w", positive=True)
    km, (x, y, phi, u3, m, a, I, g) = _sleigh(torque=c * sp.cos(w * t))
    spec = from_mechanics(km, name="driven", cyclic={x: 0, y: 0, phi: 0})
    assert set(spec.params) == {I, a, c, m, w}
    XD, PHID = sp.symbols("x_dot phi_dot", real=True)
    system = derive(spec)
    assert system.time_dependent
    tau = c * sp.cos(w * ke_t)
    assert sp.simplify(system.explicit[0] - a * PHID**2) == 0
    assert sp.simplify(system.explicit[1] - (tau - m * a * XD * PHID) / (I + m * a**2)) == 0


def _cartesian_pendulum():
    """sympy's test_lagrange.py ``test_nonminimal_pendulum`` as written there: a particle at (q1, q2),
    the rod's length as the configuration constraint, gravity along N.x as a force."""
    q1, q2 = dynamicsymbols("q1:3")
    L, m = sp.symbols("L, m")
    g = 9.8
    N = ReferenceFrame("N")
    pN = Point("N*")
    pN.set_vel(N, 0)
    P = pN.locatenew("P1", q1 * N.x + q2 * N.y)
    P.set_vel(N, P.pos_from(pN).dt(N))
    pP = Particle("pP", P, m)
    f_c = sp.Matrix([q1**2 + q2**2 - L**2])
    LM = LagrangesMethod(Lagrangian(N, pP), [q1, q2], hol_coneqs=f_c, forcelist=[(P, m * g * N.x)], frame=N)
    return LM, (q1, q2, L, m)


def _on_the_circle(q1v, L, rate):
    """A state on the constraint manifold: q2 > 0 solved from q1, q2_dot from the constraint's rate."""
    q2v = (L**2 - q1v**2) ** 0.5
    return q1v, q2v, rate, -q1v * rate / q2v


def test_holonomic_constraints_of_lagranges_method_are_the_engines():
    """The accelerations and the dependent rate against LagrangesMethod's own ``rhs()`` (sympy's equations)."""
    LM, (q1, q2, L, m) = _cartesian_pendulum()
    spec = from_mechanics(LM, name="cartesian_pendulum", cyclic={})
    Q1, Q2 = sp.symbols("q1 q2", real=True)
    assert spec.constraints == () and spec.holonomic == (Q1**2 + Q2**2 - L**2,) and spec.dependent == (Q2,)
    system = derive(spec)
    assert system.state == (Q1, Q2, sp.Symbol("q1_dot", real=True))
    LM.form_lagranges_equations()
    theirs = LM.rhs()
    x, y, xd, yd = _on_the_circle(0.6, 1.3, 0.7)
    at = {q1: x, q2: y, q1.diff(t): xd, q2.diff(t): yd, L: 1.3, m: 2.1}
    ours = dict(zip(sp.symbols("q1 q2 q1_dot", real=True), (x, y, xd)))
    ours.update({L: 1.3, m: 2.1})
    assert float(system.explicit[0].xreplace(ours)) == pytest.approx(float(theirs[2].xreplace(at)), rel=1e-12)
    assert float(system.dependent_rates[Q2].xreplace(ours)) == pytest.approx(yd, rel=1e-12)


def test_configuration_constraints_of_kanes_method_are_the_engines():
    """The same pendulum by Kane's method, with q2 dependent (``q_dependent``, ``configuration_constraints``)
    and the constraint's rate among the velocity constraints, as KanesMethod expects: the engine
    differentiates the configuration constraint itself, so no velocity constraint remains."""
    q1, q2, u1, u2 = dynamicsymbols("q1 q2 u1 u2")
    L, m, g = sp.symbols("L m g", positive=True)
    N, O = ReferenceFrame("N"), Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", q1 * N.x + q2 * N.y)
    P.set_vel(N, u1 * N.x + u2 * N.y)
    km = KanesMethod(N, [q1], [u1], kd_eqs=[q1.diff(t) - u1, q2.diff(t) - u2], q_dependent=[q2],
                     configuration_constraints=[q1**2 + q2**2 - L**2], u_dependent=[u2],
                     velocity_constraints=[q1 * u1 + q2 * u2])
    km.kanes_equations([Particle("pP", P, m)], [(P, m * g * N.x)])
    spec = from_mechanics(km, name="kane_pendulum", cyclic={})
    Q1, Q2 = sp.symbols("q1 q2", real=True)
    assert spec.constraints == () and spec.dependent == (Q2,) and len(spec.holonomic) == 1
    system = derive(spec)
    theirs = km.rhs()  # q1', q2', u1', u2'
    x, y, xd, yd = _on_the_circle(0.6, 1.3, 0.7)
    at = {q1: x, q2: y, u1: xd, u2: yd, L: 1.3, m: 2.1, g: 9.8}
    ours = dict(zip(sp.symbols("q1 q2 q1_dot", real=True), (x, y, xd)))
    ours.update({L: 1.3, m: 2.1, g: 9.8})
    assert float(system.explicit[0].xreplace(ours)) == pytest.approx(float(theirs[2].xreplace(at)), rel=1e-12)


def test_kinematics_with_an_unstated_constraint_are_refused_with_the_reason():
    """sympy's test_kane.py rolling disc: its contact point C is set fixed in N while the disc rolls.

    Kane's method is right with it (the speeds are those of the constrained motion), but its kinetic
    energy is the constrained one, and Lagrange's equations of it are wrong (sympy#27631).  The model
    below is ``test_rolling_disc`` of ``sympy/physics/mechanics/tests/test_kane.py`` (SymPy 1.14.0).
    """
    q1, q2, q3, u1, u2, u3 = dynamicsymbols('q1 q2 q3 u1 u2 u3')
    r, m, g = sp.symbols('r m g')
    N = ReferenceFrame('N')
    Y = N.orientnew('Y', 'Axis', [q1, N.z])
    L = Y.orientnew('L', 'Axis', [q2, Y.x])
    R = L.orientnew('R', 'Axis', [q3, L.y])
    w_R_N_qd = R.ang_vel_in(N)
    R.set_ang_vel(N, u1 * L.x + u2 * L.y + u3 * L.z)
    C = Point('C')
    C.set_vel(N, 0)
    Dmc = C.locatenew('Dmc', r * L.z)
    Dmc.v2pt_theory(C, N, R)
    I = inertia(L, m / 4 * r**2, m / 2 * r**2, m / 4 * r**2)
    kd = [dot(R.ang_vel_in(N) - w_R_N_qd, uv) for uv in L]
    ForceList = [(Dmc, - m * g * Y.z)]
    BodyD = RigidBody('BodyD', Dmc, R, m, (I, Dmc))
    KM = KanesMethod(N, q_ind=[q1, q2, q3], u_ind=[u1, u2, u3], kd_eqs=kd)
    KM.kanes_equations([BodyD], ForceList)
    with pytest.raises(MechanicsConversionError, match=r"velocity of Dmc .* not the time derivative of its "
                                                        r"position.*velocity constraints"):
        from_mechanics(KM, name="disc3", cyclic={q1: 0, q3: 0})


def test_bad_arguments_are_refused_before_any_work():
    km, _ = _sleigh()
    with pytest.raises(TypeError, match="`method_or_system` must be"):
        from_mechanics(object(), name="x", cyclic={})
    with pytest.raises(ValueError, match="`name` must be a Python identifier"):
        from_mechanics(km, name="not a name", cyclic={})
    with pytest.raises(ValueError, match="`cyclic` must be a mapping"):
        from_mechanics(km, name="ok", cyclic=[1])


def test_a_system_is_converted_like_its_kanes_method():
    """The sleigh as a sympy ``System`` (SymPy 1.13+): the same Lagrangian, constraint and equations."""
    from sympy.physics.mechanics import System

    x, y, phi, u1, u2, u3 = dynamicsymbols("x y phi u1 u2 u3")
    m, a, I = sp.symbols("m a I", positive=True)
    ground = RigidBody("ground")
    system = System.from_newtonian(ground)
    B = ReferenceFrame("B")
    B.orient_axis(ground.frame, ground.frame.z, phi)
    B.set_ang_vel(ground.frame, u3 * ground.frame.z)
    P = ground.masscenter.locatenew("P", x * ground.frame.x + y * ground.frame.y)
    P.set_vel(ground.frame, u1 * ground.frame.x + u2 * ground.frame.y)
    G = P.locatenew("G", a * B.x)
    G.v2pt_theory(P, ground.frame, B)
    system.add_coordinates(x, y, phi)
    system.add_speeds(u1, u3)
    system.add_speeds(u2, independent=False)
    system.add_kdes(x.diff(t) - u1, y.diff(t) - u2, phi.diff(t) - u3)
    system.add_bodies(RigidBody("sleigh", G, B, m, (inertia(B, 0, 0, I), G)))
    system.add_nonholonomic_constraints(P.vel(ground.frame).dot(B.y))
    spec = from_mechanics(system, name="sleigh", cyclic={x: 0, y: 0, phi: 0})
    kane = from_mechanics(_sleigh()[0], name="sleigh", cyclic={x: 0, y: 0, phi: 0})
    assert sp.simplify(spec.lagrangian - kane.lagrangian) == 0 and spec.constraints == kane.constraints
    XD, PHID = sp.symbols("x_dot phi_dot", real=True)
    assert sp.simplify(derive(spec).explicit[1] + m * a * XD * PHID / (I + m * a**2)) == 0


def test_the_origin_is_the_fixed_point_not_a_contact_point_set_at_rest():
    """PyDy's rattleback example sets its contact point's velocity to zero (the material point does not slip)
    while the point moves on the ground; the positions are those from the origin fixed in N, beyond it."""
    from knifeedge.derive.mechanics import _fixed_point

    x = dynamicsymbols("x")
    N = ReferenceFrame("N")
    origin = Point("origin")
    origin.set_vel(N, 0)
    contact = origin.locatenew("contact", x * N.x)
    contact.set_vel(N, 0)
    centre = contact.locatenew("centre", N.z)
    assert _fixed_point(centre, N) is origin
    assert _fixed_point(centre, N, contact) is contact  # a System's fixed_point is taken as given
