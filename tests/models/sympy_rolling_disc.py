"""The rolling disc of SymPy's own tests, by Kane's method, handed to knifeedge with ``from_mechanics``.

The model below is ``_create_rolling_disc`` of ``sympy/physics/mechanics/tests/test_kane5.py``
(SymPy 1.14.0, BSD licence) as its authors wrote it: five coordinates (the body-fixed
z-x-y angles ``q1, q2`` of an intermediate frame, the disc's rotation ``q3`` about its
axle, the contact point ``(q4, q5)``), three independent speeds (the disc's angular
velocity in its own frame) and two dependent ones (the contact point's velocity), the
rolling condition as two velocity constraints.  Only the last lines are knifeedge's.
"""
from sympy import symbols
from sympy.physics.mechanics import (KanesMethod, ReferenceFrame, RigidBody, cross, dynamicsymbols, inertia)

from knifeedge.derive import from_mechanics

# ---- sympy/physics/mechanics/tests/test_kane5.py, _create_rolling_disc (verbatim but for the return)
t = dynamicsymbols._t
q1, q2, q3, q4, q5, u1, u2, u3, u4, u5 = dynamicsymbols('q1:6 u1:6')
g, r, m = symbols('g r m')
# Define bodies and frames
ground = RigidBody('ground')
disc = RigidBody('disk', mass=m)
disc.inertia = (m * r ** 2 / 4 * inertia(disc.frame, 1, 2, 1),
                disc.masscenter)
ground.masscenter.set_vel(ground.frame, 0)
disc.masscenter.set_vel(disc.frame, 0)
int_frame = ReferenceFrame('int_frame')
# Orient frames
int_frame.orient_body_fixed(ground.frame, (q1, q2, 0), 'zxy')
disc.frame.orient_axis(int_frame, int_frame.y, q3)
g_w_d = disc.frame.ang_vel_in(ground.frame)
disc.frame.set_ang_vel(ground.frame,
                       u1 * disc.x + u2 * disc.y + u3 * disc.z)
# Define points
cp = ground.masscenter.locatenew('contact_point',
                                 q4 * ground.x + q5 * ground.y)
cp.set_vel(ground.frame, u4 * ground.x + u5 * ground.y)
disc.masscenter.set_pos(cp, r * int_frame.z)
disc.masscenter.set_vel(ground.frame, cross(
    disc.frame.ang_vel_in(ground.frame), disc.masscenter.pos_from(cp)))
# Define kinematic differential equations
kdes = [g_w_d.dot(disc.x) - u1, g_w_d.dot(disc.y) - u2,
        g_w_d.dot(disc.z) - u3, q4.diff(t) - u4, q5.diff(t) - u5]
# Define nonholonomic constraints
v0 = cp.vel(ground.frame) + cross(
    disc.frame.ang_vel_in(int_frame), cp.pos_from(disc.masscenter))
fnh = [v0.dot(ground.x), v0.dot(ground.y)]
# Define loads
loads = [(disc.masscenter, -disc.mass * g * ground.z)]
bodies = [disc]

# ---- test_kane_rolling_disc_lu: the KanesMethod
KANE = KanesMethod(ground.frame, [q1, q2, q3, q4, q5], [u1, u2, u3], kdes, u_dependent=[u4, u5],
                   velocity_constraints=fnh, bodies=bodies, forcelist=loads,
                   explicit_kinematics=False, constraint_solver='LU')
KANE.kanes_equations()

# ---- knifeedge: the same model for its engine.  The dynamics depends on the lean q2 only.
MODEL = from_mechanics(
    KANE, name="sympy_rolling_disc", cyclic={q1: 0, q3: 0, q4: 0, q5: 0},
    units={q1: "rad", q2: "rad", q3: "rad", q4: "m", q5: "m", g: "m/s^2", r: "m", m: "kg"},
    # test_kane5.py's parameters (g, r, m) = (9.81, 0.26, 3.43); rolling at 8 rad/s, leaned by 0.1 rad
    defaults={g: 9.81, r: 0.26, m: 3.43, q2: 0.1, q3.diff(t): 8.0},
    time_unit="s",
    description="SymPy's rolling disc (test_kane5.py, Kane's method) converted by from_mechanics.",
)
