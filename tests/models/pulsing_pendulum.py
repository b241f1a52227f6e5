"""SymPy's non-minimal (Cartesian) pendulum, with a rod whose length pulses in time.

sympy/physics/mechanics/tests/test_lagrange.py ``test_nonminimal_pendulum`` as written there (a
particle at (q1, q2), gravity along N.x as a force, the rod's length as ``hol_coneqs``), with the
length ``L (1 + e sin(w t))`` instead of ``L``: a holonomic, rheonomic constraint.  Only the last
lines are knifeedge's; q1 (along gravity, near L while the rod hangs) is the dependent coordinate,
since q2 crosses 0 at every swing.
"""
from sympy import Matrix, sin, symbols
from sympy.physics.mechanics import LagrangesMethod, Lagrangian, Particle, Point, ReferenceFrame, dynamicsymbols

from knifeedge.derive import from_mechanics

q1, q2 = dynamicsymbols('q1:3')
L, m, e, w = symbols('L, m, e, w')
t = dynamicsymbols._t
g = 9.8
N = ReferenceFrame('N')
pN = Point('N*')
pN.set_vel(N, 0)
P = pN.locatenew('P1', q1*N.x + q2*N.y)
P.set_vel(N, P.pos_from(pN).dt(N))
pP = Particle('pP', P, m)
f_c = Matrix([q1**2 + q2**2 - (L * (1 + e * sin(w * t)))**2])
LAGRANGE = LagrangesMethod(Lagrangian(N, pP), [q1, q2], hol_coneqs=f_c, forcelist=[(P, m*g*N.x)], frame=N)

# ---- knifeedge's lines
MODEL = from_mechanics(LAGRANGE, name="pulsing_pendulum", cyclic={}, dependent=[q1],
                       units={q1: "m", q2: "m", L: "m", m: "kg", w: "1/s"})
