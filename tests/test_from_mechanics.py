"""``knifeedge.derive.from_mechanics``: models written with ``sympy.physics.mechanics``, converted.

The default tier checks the conversion on the smallest models (the pendulum's Lagrangian
against the textbook's) and every refusal; the peer checks, the field's own models
derived and compiled and run against their authors' own equations, are in
``tests/test_mechanics_peers.py`` (slow tier).
"""
import pytest
import sympy as sp
import sympy.physics.vector
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point, ReferenceFrame,
                                     RigidBody, dot, dynamicsymbols, inertia)

from knifeedge.derive import MechanicsConversionError, from_mechanics

t = dynamicsymbols._t


def _pendulum(force=None, frame=None):
    """A particle on a massless rod of length l hanging from O, by Kane's method (sympy's own tutorial setup)."""
    q, u = dynamicsymbols("q u")
    m, l, g = sp.symbols("m l g", positive=True)
    N, O = frame or ReferenceFrame("N"), Point("O")
    O.set_vel(N, 0)
    P = Particle("P", O.locatenew("P", l * (sp.sin(q) * N.x - sp.cos(q) * N.y)), m)
    P.point.set_vel(N, P.point.pos_from(O).dt(N).subs(q.diff(t), u))
    if force is not None and not isinstance(force, sp.physics.vector.Vector):
        force = force * N.x
    loads = [(P.point, -m * g * N.y)] + ([(P.point, force)] if force is not None else [])
    km = KanesMethod(N, [q], [u], kd_eqs=[q.diff(t) - u])
    km.kanes_equations([P], loads)
    return km, (q, m, l, g)


def test_a_pendulum_gets_the_textbook_lagrangian():
    """L = m l^2 q_dot^2 / 2 + m g l cos q (any mechanics text): gravity, constant in N, is a potential."""
    km, (q, m, l, g) = _pendulum()
    spec = from_mechanics(km, name="pendulum", cyclic={})
    qs, qd = sp.symbols("q q_dot", real=True)
    assert spec.coordinates == (qs,) and spec.velocities == (qd,) and spec.params == (g, l, m)
    assert sp.simplify(spec.lagrangian - (m * l**2 * qd**2 / 2 + m * g * l * sp.cos(qs))) == 0
    assert spec.forces == () and spec.constraints == ()


def test_a_force_that_is_not_constant_becomes_a_generalized_force():
    """A viscous drag -c v on the bob (v = l u, tangent to the circle) gives Q = -c l^2 q_dot."""
    c, u = sp.Symbol("c"), dynamicsymbols("u")
    q = dynamicsymbols("q")
    l = sp.Symbol("l", positive=True)
    N = ReferenceFrame("N")
    drag = -c * l * u * (sp.cos(q) * N.x + sp.sin(q) * N.y)
    km, (q, m, l, g) = _pendulum(force=drag, frame=N)
    spec = from_mechanics(km, name="damped", cyclic={}, units={q: "rad"})
    qs, qd = sp.symbols("q q_dot", real=True)
    assert sp.simplify(spec.forces[0] + c * l**2 * qd) == 0
    assert sp.simplify(spec.lagrangian - (m * l**2 * qd**2 / 2 + m * g * l * sp.cos(qs))) == 0
    assert spec.units == {sp.Symbol("q", real=True): "rad"}


def test_specified_quantities_and_explicit_time_are_refused_with_the_reason():
    f = dynamicsymbols("f")
    km, _ = _pendulum(force=f)
    with pytest.raises(MechanicsConversionError, match=r"specified quantities \['f\(t\)'\].*`inputs`"):
        from_mechanics(km, name="driven", cyclic={})
    km, _ = _pendulum(force=sp.cos(t))
    with pytest.raises(MechanicsConversionError, match="explicitly on time"):
        from_mechanics(km, name="driven", cyclic={})


def test_holonomic_constraints_are_refused_with_the_reason():
    """The pendulum in Cartesian coordinates with the rod's length as a configuration constraint."""
    x, y = dynamicsymbols("x y")
    m, l, g = sp.symbols("m l g", positive=True)
    N, O = ReferenceFrame("N"), Point("O")
    O.set_vel(N, 0)
    P = Particle("P", O.locatenew("P", x * N.x + y * N.y), m)
    P.point.set_vel(N, x.diff(t) * N.x + y.diff(t) * N.y)
    P.potential_energy = m * g * y
    lm = LagrangesMethod(Lagrangian(N, P), [x, y], hol_coneqs=[x**2 + y**2 - l**2], frame=N)
    with pytest.raises(MechanicsConversionError, match="holonomic .*configuration.* constraints"):
        from_mechanics(lm, name="cartesian_pendulum", cyclic={})


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
    km, _ = _pendulum()
    with pytest.raises(TypeError, match="`method_or_system` must be"):
        from_mechanics(object(), name="x", cyclic={})
    with pytest.raises(ValueError, match="`name` must be a Python identifier"):
        from_mechanics(km, name="not a name", cyclic={})
    with pytest.raises(ValueError, match="`cyclic` must be a mapping"):
        from_mechanics(km, name="ok", cyclic=[1])
