"""The Whipple bicycle of SymPy's ``test_kane3.py`` with the coordinates a Lagrangian needs.

SymPy's ``sympy/physics/mechanics/tests/test_kane3.py::test_bicycle`` (Meijaard, Papadopoulos, Ruina
& Schwab 2007, *Proc. R. Soc. A* 463, 1955-1982) writes the bicycle for Kane's method with the
rear contact point fixed in the inertial frame and the wheels' rotation angles left out (the
speeds u3, u6 have no coordinates): its velocities already contain the rolling constraints, so
``from_mechanics`` refuses it as written (no kinematic differential equation for u3, u6).  Below is
the same bicycle, with the same frames, points, bodies, inertias, names and geometry, given what a
Lagrangian needs: the rear contact point at (x, y) on the ground, the wheels' angles q3, q6, each
body's frame oriented, and the rolling conditions stated as velocity constraints (the velocity of
each wheel's material point at its contact, in the yaw frame's x and y; and its z component at the
front, the rate of the configuration constraint that keeps the front contact on the ground, which
is test_kane3's ``conlist_coord``).
"""
import math

from sympy import symbols
from sympy.physics.mechanics import KanesMethod, Point, ReferenceFrame, RigidBody, dot, dynamicsymbols, inertia

from knifeedge.derive import from_mechanics
from knifeedge.derive.steady import Steady

q1, q2, q3, q4, q5, q6, x, y = dynamicsymbols('q1 q2 q3 q4 q5 q6 x y')
u1, u2, u3, u4, u5, u6, ux, uy = dynamicsymbols('u1 u2 u3 u4 u5 u6 ux uy')
t = dynamicsymbols._t

WFrad, WRrad, htangle, forkoffset = symbols('WFrad WRrad htangle forkoffset')
forklength, framelength, forkcg1 = symbols('forklength framelength forkcg1')
forkcg3, framecg1, framecg3, Iwr11 = symbols('forkcg3 framecg1 framecg3 Iwr11')
Iwr22, Iwf11, Iwf22, Iframe11 = symbols('Iwr22 Iwf11 Iwf22 Iframe11')
Iframe22, Iframe33, Iframe31, Ifork11 = symbols('Iframe22 Iframe33 Iframe31 Ifork11')
Ifork22, Ifork33, Ifork31, g = symbols('Ifork22 Ifork33 Ifork31 g')
mframe, mfork, mwf, mwr = symbols('mframe mfork mwf mwr')

N = ReferenceFrame('N')
Y = N.orientnew('Y', 'Axis', [q1, N.z])
R = Y.orientnew('R', 'Axis', [q2, Y.x])
Frame = R.orientnew('Frame', 'Axis', [q4 + htangle, R.y])
WR = Frame.orientnew('WR', 'Axis', [q3, Frame.y])
TempFrame = Frame.orientnew('TempFrame', 'Axis', [-htangle, Frame.y])
Fork = Frame.orientnew('Fork', 'Axis', [q5, Frame.x])
TempFork = Fork.orientnew('TempFork', 'Axis', [-htangle, Fork.y])
WF = Fork.orientnew('WF', 'Axis', [q6, Fork.y])

O = Point('O')
O.set_vel(N, 0)
WR_cont = O.locatenew('WR_cont', x * N.x + y * N.y)
WR_mc = WR_cont.locatenew('WR_mc', WRrad * R.z)
Steer = WR_mc.locatenew('Steer', framelength * Frame.z)
Frame_mc = WR_mc.locatenew('Frame_mc', - framecg1 * Frame.x + framecg3 * Frame.z)
Fork_mc = Steer.locatenew('Fork_mc', - forkcg1 * Fork.x + forkcg3 * Fork.z)
WF_mc = Steer.locatenew('WF_mc', forklength * Fork.x + forkoffset * Fork.z)
WF_cont = WF_mc.locatenew('WF_cont', WFrad * (dot(Fork.y, Y.z) * Fork.y - Y.z).normalize())

WR_cont.set_vel(N, ux * N.x + uy * N.y)
WR_mc.v2pt_theory(WR_cont, N, R)
Steer.v2pt_theory(WR_mc, N, Frame)
Frame_mc.v2pt_theory(WR_mc, N, Frame)
Fork_mc.v2pt_theory(Steer, N, Fork)
WF_mc.v2pt_theory(Steer, N, Fork)

Frame_I = (inertia(TempFrame, Iframe11, Iframe22, Iframe33, 0, 0, Iframe31), Frame_mc)
Fork_I = (inertia(TempFork, Ifork11, Ifork22, Ifork33, 0, 0, Ifork31), Fork_mc)
WR_I = (inertia(Frame, Iwr11, Iwr22, Iwr11), WR_mc)
WF_I = (inertia(Fork, Iwf11, Iwf22, Iwf11), WF_mc)
BodyFrame = RigidBody('BodyFrame', Frame_mc, Frame, mframe, Frame_I)
BodyFork = RigidBody('BodyFork', Fork_mc, Fork, mfork, Fork_I)
BodyWR = RigidBody('BodyWR', WR_mc, WR, mwr, WR_I)
BodyWF = RigidBody('BodyWF', WF_mc, WF, mwf, WF_I)

# the wheels' material points at the contacts: no slip
rear = WR_mc.vel(N) + (WR.ang_vel_in(N) ^ WR_cont.pos_from(WR_mc))
front = WF_mc.vel(N) + (WF.ang_vel_in(N) ^ WF_cont.pos_from(WF_mc))
qs = (q1, q2, q3, q4, q5, q6, x, y)
us = (u1, u2, u3, u4, u5, u6, ux, uy)
kd = [q.diff(t) - u for q, u in zip(qs, us)]
conlist_speed = [(rear & Y.x).subs(dict(zip([q.diff(t) for q in qs], us))),
                 (rear & Y.y).subs(dict(zip([q.diff(t) for q in qs], us))),
                 (front & Y.x).subs(dict(zip([q.diff(t) for q in qs], us))),
                 (front & Y.y).subs(dict(zip([q.diff(t) for q in qs], us))),
                 (front & Y.z).subs(dict(zip([q.diff(t) for q in qs], us)))]
conlist_coord = [WF_cont.pos_from(WR_cont) & Y.z]
FL = [(Frame_mc, -mframe * g * Y.z), (Fork_mc, -mfork * g * Y.z), (WF_mc, -mwf * g * Y.z),
      (WR_mc, -mwr * g * Y.z)]
BL = [BodyFrame, BodyFork, BodyWR, BodyWF]

KANE = KanesMethod(N, q_ind=[q1, q2, q3, q5, q6, x, y], q_dependent=[q4], configuration_constraints=conlist_coord,
                   u_ind=[u2, u3, u5], u_dependent=[ux, uy, u1, u4, u6], velocity_constraints=conlist_speed,
                   kd_eqs=kd, bodies=BL, forcelist=FL)

# ---- knifeedge's lines
# The benchmark's parameters in this model's geometry, converted exactly as test_kane3.py converts them (Meijaard et
# al. 2007, Table 1: wheelbase 1.02 m, trail 0.08 m, head angle pi/2 - pi/10, ...); at these values the front
# contact is on the ground upright at zero pitch, q4 = 0.
HTA = math.pi / 2 - math.pi / 10
_rake = -(0.08 * math.sin(HTA) - 0.35 * math.cos(HTA))
_tempa, _tempb = 0.7 - 0.35, 1.02 - 0.9
_tempc = math.sqrt(_tempa**2 + _tempb**2)
_fork_length = 1.02 * math.cos(HTA) - (0.35 - 0.3) * math.sin(HTA)
BENCHMARK = {
    "WFrad": 0.35, "WRrad": 0.3, "htangle": HTA, "forkoffset": _rake, "forklength": _fork_length,
    "framelength": 1.02 * math.sin(HTA) - (_rake - (0.35 - 0.3) * math.cos(HTA)),
    "forkcg1": _tempc * math.cos((math.pi / 2 - HTA) - math.acos(_tempa / _tempc)) - _fork_length,
    "forkcg3": _rake + _tempc * math.sin(math.pi / 2 - HTA - math.acos(_tempa / _tempc)),
    "framecg1": (0.9 - 0.3 - (0.3 / math.sin(HTA)) * math.cos(HTA)) * math.sin(HTA),
    "framecg3": 0.3 / math.sin(HTA) + (0.9 - 0.3 - 0.3 / math.sin(HTA) * math.cos(HTA)) * math.cos(HTA),
    "Iwr11": 0.0603, "Iwr22": 0.12, "Iwf11": 0.1405, "Iwf22": 0.28, "Ifork11": 0.05892, "Ifork22": 0.06,
    "Ifork33": 0.00708, "Ifork31": 0.00756, "Iframe11": 9.2, "Iframe22": 11.0, "Iframe33": 2.8,
    "Iframe31": -2.4, "mfork": 4.0, "mframe": 85.0, "mwf": 3.0, "mwr": 2.0, "g": 9.81}

v = symbols('v', real=True)
STRAIGHT = Steady(
    "straight_running", v, {"q3_dot": v / WRrad},
    "upright straight running at the forward speed v (rear wheel rate v/WRrad; lean, steer and pitch zero: the "
    "pitch is zero where the parameters put the front contact on the ground upright at q4 = 0, as the benchmark's do)",
    {"q2": "lean", "q2_dot": "lean", "q5": "steer", "q5_dot": "steer"})

MODEL = from_mechanics(
    KANE, name="whipple_bicycle", cyclic={x: 0, y: 0, q1: 0, q3: 0, q6: 0}, elimination="numeric",
    defaults=BENCHMARK, steady=(STRAIGHT,), units={"x": "m", "y": "m"}, time_unit="s",
    description="The Whipple bicycle of SymPy's test_kane3.py (Meijaard et al. 2007), with the rear contact "
                "point and the wheels' angles as coordinates.")
