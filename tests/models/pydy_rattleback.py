"""PyDy's Kane-Levinson rattleback example, converted by ``from_mechanics``.

Source: the repository pydy/pydy, ``examples/rattleback/ellipsoid_no_slip.py`` (an ellipsoid rolling without
slip on a horizontal plane, after Kane & Levinson, "Realistic mathematical modeling of the rattleback", Int. J.
Non-Linear Mech. 17 (1982) 175-186).  The example forms Kane's equations by hand (partial velocities, generalized
active and inertia forces) and writes C code for a C++ integrator (``examples/rattleback/cpp``); it has no
``KanesMethod``.  Below, its symbols, frames, points, inertia, angular velocity, kinematic differential equations
and loads are the example's (same names and formulas); what a ``KanesMethod`` and a Lagrangian need is added
(marked "added"): the contact point ``P`` located from a point fixed in ``N`` by
the example's coordinates ``q3, q4`` (the example's ``qd_rhs`` integrates them), the speeds ``u3, u4`` of those
coordinates, and the rolling condition as two velocity constraints, which are the example's own last two
kinematic differential equations (``qd_rhs[3:]``: the contact point moves with the rate of change of its
position as seen in the body).  In the example, ``N.z`` (and ``Y.z``) points down: gravity is ``m g Y.z``.
"""
from sympy import cos, sin, sqrt, symbols, tan
from sympy.physics.mechanics import (KanesMethod, Point, ReferenceFrame, RigidBody, Vector, cross, dot,
                                     dynamicsymbols, inertia)

from knifeedge.derive import from_mechanics

# ---- the example's model (pydy/pydy examples/rattleback/ellipsoid_no_slip.py): its symbols, frames, points and
# formulas under its names
Vector.simp = False
t, g = symbols('t g')                   # time, gravity
a, b, c = symbols('a b c')              # the ellipsoid's semi-axes along R.x, R.y, R.z
d, e, f = symbols('d e f')              # the mass centre from the ellipsoid's centre, in R
s = symbols('s')                        # viscous torque coefficient
m, Ixx, Iyy, Izz, Ixy, Iyz, Ixz = symbols('m Ixx Iyy Izz Ixy Iyz Ixz')

q = dynamicsymbols('q:5')               # yaw, lean, pitch; the contact point's x, y
qd = [qi.diff(t) for qi in q]
u = dynamicsymbols('u:3')               # the body's angular velocity in R

N = ReferenceFrame('N')
Y = N.orientnew('Y', 'Axis', [q[0], N.z])
L = Y.orientnew('L', 'Axis', [q[1], Y.x])
R = L.orientnew('R', 'Axis', [q[2], L.y])
I = inertia(R, Ixx, Iyy, Izz, Ixy, Iyz, Ixz)
R.set_ang_vel(N, u[0]*R.x + u[1]*R.y + u[2]*R.z)

# added: the contact point located from a point fixed in N by q3, q4 (in the example P is a free point whose
# velocity is set to auxiliary speeds, zero in the motion: the material point at the contact does not slip)
NO = Point('NO')
NO.set_vel(N, 0)
P = NO.locatenew('P', q[3]*N.x + q[4]*N.y)
P.set_vel(N, 0)

# the ellipsoid's centre O from the contact point (Kane & Levinson 1982: the point of the surface whose normal is
# the vertical Y.z), the mass centre RO from O; their velocities as the example sets them
mu = [dot(rk, Y.z) for rk in R]
eps = sqrt((a*mu[0])**2 + (b*mu[1])**2 + (c*mu[2])**2)
O = P.locatenew('O', -a*a*mu[0]/eps*R.x - b*b*mu[1]/eps*R.y - c*c*mu[2]/eps*R.z)
O.set_vel(N, P.vel(N) + cross(R.ang_vel_in(N), O.pos_from(P)))
RO = O.locatenew('RO', d*R.x + e*R.y + f*R.z)
RO.set_vel(N, P.vel(N) + cross(R.ang_vel_in(N), RO.pos_from(P)))

# the example's kinematic differential equations: Euler angle rates from u, and the contact point's rates
qd_rhs = [(u[2]*cos(q[2]) - u[0]*sin(q[2]))/cos(q[1]),
          u[0]*cos(q[2]) + u[2]*sin(q[2]),
          u[1] + tan(q[1])*(u[0]*sin(q[2]) - u[2]*cos(q[2])),
          dot(P.pos_from(O).diff(t, R), N.x),
          dot(P.pos_from(O).diff(t, R), N.y)]

# the example's loads: gravity at the mass centre (N.z points down), a viscous torque (the contact force is the
# constraint's and does no work)
F_RO = m*g*Y.z
T_R = -s*R.ang_vel_in(N)

# ---- added: the KanesMethod.  Speeds u3, u4 of the contact point's coordinates, dependent through the
# example's own rolling kinematics qd_rhs[3:] (its q-dots replaced by its kinematic equations qd_rhs[:3])
u3, u4 = dynamicsymbols('u3 u4')
to_u = dict(zip(qd[:3], qd_rhs[:3]))
kd = [qd[i] - qd_rhs[i] for i in range(3)] + [qd[3] - u3, qd[4] - u4]
rolling = [u3 - qd_rhs[3].subs(to_u), u4 - qd_rhs[4].subs(to_u)]
body = RigidBody('rattleback', RO, R, m, (I, RO))
KANE = KanesMethod(N, q_ind=list(q), u_ind=list(u), u_dependent=[u3, u4], kd_eqs=kd, velocity_constraints=rolling,
                   bodies=[body], forcelist=[(RO, F_RO), (R, T_R)])

#: Kane & Levinson's rattleback (knifeedge's ``celt`` preset ``kane_levinson_1982``) in this example's body frame,
#: whose z axis points down (celt's points up: a half turn about x, so the product of inertia changes sign); the
#: mass centre 0.01 m below the ellipsoid's centre; PyDy's own simulation of this example (examples/rattleback/cpp/
#: ellipsoid_sim.cc) uses these values, Ixy = -0.00002 among them
KANE_LEVINSON = {"a": 0.20, "b": 0.03, "c": 0.02, "d": 0.0, "e": 0.0, "f": 0.01, "m": 1.0, "g": 9.81,
                 "Ixx": 2e-4, "Iyy": 1.6e-3, "Izz": 1.7e-3, "Ixy": -2e-5, "Iyz": 0.0, "Ixz": 0.0, "s": 0.0}

MODEL = from_mechanics(
    KANE, name="pydy_rattleback", cyclic={q[0]: 0, q[3]: 0, q[4]: 0}, elimination="numeric",
    defaults=KANE_LEVINSON, time_unit="s",
    units={"q0": "rad", "q1": "rad", "q2": "rad", "q3": "m", "q4": "m", "a": "m", "b": "m", "c": "m", "d": "m",
           "e": "m", "f": "m", "m": "kg", "g": "m/s^2", "s": "N m s",
           **{n: "kg m^2" for n in ("Ixx", "Iyy", "Izz", "Ixy", "Iyz", "Ixz")}},
    description="PyDy's Kane-Levinson rattleback (examples/rattleback/ellipsoid_no_slip.py): Euler angles yaw q0, "
                "lean q1, pitch q2, contact point (q3, q4), converted by from_mechanics.")
