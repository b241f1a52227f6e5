"""The differential-drive robot of pydy issue #127, handed to knifeedge with ``from_mechanics``.

pydy#127 ("Codegen doesn't work for systems with non-eliminable lagrange multipliers",
https://github.com/pydy/pydy/issues/127) names this model as its test case: PyDy's
example ``examples/differential_drive/Differential Drive.ipynb`` (pydy master, 90305f0).
The cells below are the notebook's model as its author wrote it (``LagrangesMethod``: two
wheels and a body, the wheels rolling without slipping as three velocity constraints in
``x_dot, y_dot, theta_dot``, the wheels' torques as forces at the hubs).  The notebook
then adds a motor model whose currents are states and whose voltages are inputs; that
part is not mechanics and is left out: the torques ``tau_1, tau_2`` stay the constant
symbols of the ``forcelist``.  Only the last lines are knifeedge's.
"""
from sympy import Matrix, solve, symbols
from sympy.physics.mechanics import (LagrangesMethod, Lagrangian, Point, ReferenceFrame, RigidBody,
                                     dynamicsymbols, inertia)

from knifeedge.derive import from_mechanics

# ---- the notebook's cells, in order (pydy examples/differential_drive/Differential Drive.ipynb)
# Inertial Reference Frame
N = ReferenceFrame('N')

# Define a world coordinate origin
O = Point('O')
O.set_vel(N, 0)

theta = dynamicsymbols('theta')                      # Rotation about N.z
x, y = dynamicsymbols('x, y')                        # Coordinates of robot in World Frame
phi1, phi2 = dynamicsymbols('phi_1, phi_2')          # Angular displacement of wheel

# Create q and dq vectors
q = Matrix([x, y, theta, phi1, phi2])
dq = q.diff()

# Constants for the wheels
r = symbols('r')                                     # Radius of wheel
m_w = symbols('m_w')                                 # Mass of the wheel
t_w = symbols('t_w')                                 # Thickness of the wheel

# Constants for the Robot Body
w = symbols('w')                                     # 2*w is the width of the wheel base
d = symbols('d')                                     # Distance between axel and center of mass
m_b = symbols('m_b')                                 # Mass of the body
Ixx, Iyy, Izz = symbols('Ixx, Iyy, Izz')             # Moments of inertia of body

# Robot Reference Frame
R = N.orientnew('R', 'Axis', [theta, N.z])

# Center of wheel base
Cw = O.locatenew('Cw', x*N.x + y*N.y)

# Set the velocity of point Cw
Cw.set_vel(N, x.diff()*N.x + y.diff()*N.y)

# Points at wheel hubs
H1 = Cw.locatenew('H1', -w*R.y)
H2 = Cw.locatenew('H2', w*R.y)

# Set the velocity of points H1 and H2
H1.v2pt_theory(Cw, N, R)
H2.v2pt_theory(Cw, N, R)

# Create reference frames for wheels 1 and 2
W1 = R.orientnew('W1', 'Axis', [phi1, R.y])
W2 = R.orientnew('W2', 'Axis', [phi2, R.y])

# Calculate inertia of the wheel
Iw = inertia(R, m_w*(3*r**2 + t_w**2)/12, m_w*r**2/2, m_w*(3*r**2 + t_w**2)/12)

# Create rigid bodies for wheels
Wheel1 = RigidBody('Wheel1', H1, W1, m_w, (Iw, H1))
Wheel2 = RigidBody('Wheel2', H2, W2, m_w, (Iw, H2))

# Calculate inertia of body
Ib = inertia(R, Ixx, Iyy, Izz)

# Center of mass of body
Cm = Cw.locatenew('Cm', d*R.x)
Cm.v2pt_theory(Cw, N, R)

# Create a rigid body object for body
Body = RigidBody('Body', Cm, R, m_b, (Ib, Cm))

# Create two points, where the wheels contact the ground
C1 = H1.locatenew('C1', -r*R.z)
C2 = H2.locatenew('C2', -r*R.z)
# Calculate velocity of points
C1.v2pt_theory(H1, N, W1)
C2.v2pt_theory(H2, N, W2)

# Express the velocity of points in the inertial frame
con1 = C1.vel(N).express(N).args[0][0]
con2 = C2.vel(N).express(N).args[0][0]
# Create a matrix of constraints
constraints = con1.col_join(con2)

# Solve for dx, dy, and dtheta in terms of dphi1 and dphi2
sol = solve(constraints, dq[:3])

# Split the resulting dict into a rhs and lhs, that are equivalent
sol_rhs = Matrix(list(sol.values()))
sol_lhs = Matrix(list(sol.keys()))

# Since sol_rhs = sol_lhs --> sol_rhs - sol_lhs = 0
# This forms the basis of our constraint matrix.
# Combining, and solving for a linear representation:
c = (sol_rhs - sol_lhs).jacobian(dq[:5])

# Constraint Equations
coneqs = (c*dq)

# Define forces on system:
T1, T2 = symbols('tau_1, tau_2')              # Torques from the wheels
fl = [(H1, T1/r*R.x),
      (H2, T2/r*R.x)]

Lag = Lagrangian(N, Wheel1, Wheel2, Body)

lm = LagrangesMethod(Lag, q, nonhol_coneqs=coneqs, forcelist=fl, frame=N)
LAGRANGE = lm

# ---- knifeedge: the same model for its engine.  Nothing depends on where the robot is, where it
# heads, or how far its wheels have turned: every coordinate is cyclic; the closed state is the
# two wheel rates.
MODEL = from_mechanics(
    lm, name="differential_drive",
    cyclic={x: 0, y: 0, theta: 0, phi1: 0, phi2: 0},
    units={x: "m", y: "m", theta: "rad", phi1: "rad", phi2: "rad", r: "m", m_w: "kg", t_w: "m", w: "m", d: "m",
           m_b: "kg", Izz: "kg m^2", T1: "N m", T2: "N m"},
    # the notebook's constants (Izz, t_w, m_w, r, m_b, w) = (5, 0.15, 2.0, 0.15, 50.0, 0.6); its d = 0;
    # torques of about what its motors give at the end of its first run
    defaults={Izz: 5.0, t_w: 0.15, m_w: 2.0, r: 0.15, m_b: 50.0, w: 0.6, d: 0.0, T1: 1.2, T2: 1.0},
    param_domains={d: "real", T1: "real", T2: "real"},
    time_unit="s",
    description="The differential-drive robot of pydy#127 (PyDy's example, LagrangesMethod) converted by "
                "from_mechanics; constant wheel torques tau_1, tau_2.",
)
