"""two_mode, fidelity full: exact consequences of the model's Lagrangian and constraints, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from derivation/models.py (model 'two_mode',
constraints Const22, Const23) through derivation/engine.py.
Accelerations and multipliers in closed form (symbolic elimination of the multipliers).
SymPy 1.14.0; input hash sha256:406415af61462d8f033eb9ab4d86b2adb817abb97f10006b2550c613b0a3e4a0

Two-mode knife edge (paper section III): tilts theta1, theta2; the contact is the lowest point of a circle of radius D whose plane makes the chiral angle alpha with the bar (Const22, Const23).

State vector ``s`` (closed state; the pose follows by quadrature):
    s[0] = theta1       [rad]
    s[1] = theta2       [rad]
    s[2] = theta1_dot   [rad/time]
    s[3] = theta2_dot   [rad/time]
    s[4] = phi_dot      [rad/time]
Pose-extended state (``*_pose`` functions) appends:
    s[5] = phi          [rad]
    s[6] = x            [length]
    s[7] = y            [length]
Parameter vector ``p``:
    p[0] = g            [length/time^2]
    p[1] = ell          [length]
    p[2] = L            [length]
    p[3] = D            [length]
    p[4] = alpha        [rad]
Multipliers (constraint forces in the normalization of the Lagrangian, e.g. per unit mass),
in the order Const22, Const23.  Energy in the same normalization.
"""
import math

import numpy as np
from numba import njit

MODEL = 'two_mode'
FIDELITY = 'full'
#: what this fidelity is
FIDELITY_DOC = "exact consequences of the model's Lagrangian and constraints, nothing dropped"
STATE_NAMES = ('theta1', 'theta2', 'theta1_dot', 'theta2_dot', 'phi_dot')
#: unit of each state (``time`` is the unit of t)
STATE_UNITS = ('rad', 'rad', 'rad/time', 'rad/time', 'rad/time')
POSE_NAMES = ('phi', 'x', 'y')
POSE_UNITS = ('rad', 'length', 'length')
#: what the pose coordinates mean
POSE_DOC = 'phi: heading of the bar; (x, y): position of the centre of the bar on the table'
PARAM_NAMES = ('g', 'ell', 'L', 'D', 'alpha')
PARAM_UNITS = ('length/time^2', 'length', 'length', 'length', 'rad')
#: admissible values of each parameter: 'positive' (> 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive', 'positive', 'positive', 'real')
#: default parameter set and initial state (the CLI's defaults); empty if the model declares none
DEFAULT_PARAMS = {'g': 1.0, 'ell': 1.0, 'L': 2.0, 'D': 0.5, 'alpha': 0.7853981633974483}
DEFAULT_STATE = {'theta1': 0.001, 'theta2': 0.001, 'theta1_dot': 0.0, 'theta2_dot': 0.0, 'phi_dot': 0.1}
#: (coordinate, rate) pairs of the state
RATE_PAIRS = (('theta1', 'theta1_dot'), ('theta2', 'theta2_dot'))
#: the small coordinates (tilts) of the small-angle fidelities
TILT_NAMES = ('theta1', 'theta2')
#: states (or EVENT_NAMES) whose zero crossings are reported as ``reversal_times``
REVERSAL_EVENTS = ('phi_dot',)
#: scalar functions of the state returned by ``event_values(s, p)``
EVENT_NAMES = ()
#: largest |value| of each named state where this fidelity holds (empty: everywhere)
VALIDITY = {}
VALIDITY_DOC = ''
MULTIPLIER_NAMES = ('Const22', 'Const23')
#: non-conservative forces: the module has ``power_dissipated(s, p)``
HAS_DISSIPATION = False
#: model-specific helpers defined at the end of this module
EXPORTS = ()
INPUT_HASH = '406415af61462d8f033eb9ab4d86b2adb817abb97f10006b2550c613b0a3e4a0'
SYMPY_VERSION = '1.14.0'
#: how the multipliers are eliminated: "symbolic" (closed form) or "numeric" (a linear solve at every call)
ELIMINATION = 'symbolic'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 152, 'constants': 107, 'rhs_q': 65, 'rhs_pose': 166, 'rhs_pose_q': 76, 'pose_rates': 13, 'energy': 58, 'multipliers': 166, 'frequencies': 12}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (152 operations)."""
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (L*L)
    _c1 = 2*_c0
    _c2 = (ell*ell)
    _c3 = _c0 + _c2
    _c4 = _c3*g
    _c5 = math.sin(2*alpha)
    _c6 = D*phi_dot
    _c7 = _c6*theta1_dot
    _c8 = (D*D)
    _c9 = math.cos(alpha)
    _c10 = math.sin(alpha)
    _c11 = 2*_c2
    _c12 = (theta2*theta2*theta2)
    _c13 = (_c9*_c9)
    _c14 = (_c10*_c10)
    _c15 = _c13*_c2
    _c16 = _c8*g*(theta1*theta1*theta1)
    _c17 = 3*_c15
    _c18 = (theta2*theta2)
    _c19 = _c18*g
    _c20 = _c8*theta1
    _c21 = (theta1*theta1)
    _c22 = -_c2
    _c23 = 8*_c0
    _c24 = (_c10*_c10*_c10*_c10)
    _c25 = 8*_c21*_c8
    _c26 = (_c10*_c10*_c10)*_c9
    _c27 = _c26*theta2
    _c28 = math.cos(4*alpha) - 1
    _c29 = 1/(_c0*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))
    _c30 = g*theta2
    _c31 = _c23*_c7
    _c32 = 4*_c5
    _c33 = _c19*_c32
    _c34 = _c6*theta2_dot
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = 4*_c29*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - _c10*_c11*_c12*_c8*(_c9*_c9*_c9)*g - 2*_c13*_c19*_c20*(_c0 - _c11 + _c17) - 2*_c14*_c16*(_c0 + _c15) + _c21*_c5*_c8*g*theta2*(_c1 + _c17 + _c22))/ell
    ds[3] = _c29*ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c25*_c30*(3*_c14 - 2) - _c14*_c31 - 8*_c16*_c26 - _c20*_c33*(3*_c13 - 2) - _c23*_c30)
    ds[4] = D*_c29*(_c0*_c28*_c34*theta2 - _c2*_c33 + _c21*_c32*_c4 + _c23*_c26*_c34*theta1 - _c24*_c31*theta1 + _c27*_c31 - 8*_c30*theta1*(_c0*_c13 + 2*_c15 + _c22))


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 5."""
    ds = np.empty(5)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 30 parameter-only subexpressions of the right-hand side (107 operations)."""
    q = np.empty(35)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    q[0] = g
    q[1] = ell
    q[2] = L
    q[3] = D
    q[4] = alpha
    _c0 = (D*D)
    _c1 = math.cos(4*alpha) - 1
    _c2 = _c0*_c1
    _c3 = math.sin(alpha)
    _c4 = (_c3*_c3*_c3*_c3)
    _c5 = 8*_c0
    _c6 = math.cos(alpha)
    _c7 = (_c3*_c3*_c3)*_c6
    _c8 = (L*L)
    _c9 = 8*_c8
    _c10 = (ell*ell)
    _c11 = 2*_c8
    _c12 = _c10 + _c8
    _c13 = _c12*g
    _c14 = (_c6*_c6)
    _c15 = _c10*_c14
    _c16 = (_c3*_c3)
    _c17 = _c16*g
    _c18 = 2*_c0
    _c19 = -_c10
    _c20 = 3*_c15
    _c21 = math.sin(2*alpha)
    _c22 = _c21*g
    _c23 = _c0*_c22
    _c24 = D*_c8
    _c25 = _c21*_c24
    _c26 = 2*_c10
    _c27 = 1/_c8
    _c28 = D*_c9
    q[5] = -_c2
    q[6] = _c4*_c5
    q[7] = -16*_c0*_c7
    q[8] = 8*_c10 + _c9
    q[9] = -_c11*_c13
    q[10] = -_c17*_c18*(_c15 + _c8)
    q[11] = _c23*(_c11 + _c19 + _c20)
    q[12] = -_c12*_c25
    q[13] = -_c14*_c18*g*(_c20 - _c26 + _c8)
    q[14] = -_c0*_c26*_c3*(_c6*_c6*_c6)*g
    q[15] = D*_c11*_c12*_c14
    q[16] = 4*_c27/ell
    q[17] = -_c9*g
    q[18] = _c2*g
    q[19] = -_c16*_c28
    q[20] = -_c5*_c7*g
    q[21] = 4*_c25
    q[22] = -_c17*_c5*(3*_c16 - 2)
    q[23] = -4*_c23*(3*_c14 - 2)
    q[24] = _c27*ell
    q[25] = -8*g*(_c14*_c8 + 2*_c15 + _c19)
    q[26] = -4*_c10*_c22
    q[27] = 4*_c13*_c21
    q[28] = _c1*_c24
    q[29] = -_c28*_c4
    q[30] = _c28*_c7
    q[31] = D*_c27
    q[32] = _c6
    q[33] = -_c3
    q[34] = -D
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (65 operations)."""
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    g = q[0]
    ell = q[1]
    L = q[2]
    D = q[3]
    alpha = q[4]
    _k0 = q[5]
    _k1 = q[6]
    _k2 = q[7]
    _k3 = q[8]
    _k4 = q[9]
    _k5 = q[10]
    _k6 = q[11]
    _k7 = q[12]
    _k8 = q[13]
    _k9 = q[14]
    _k10 = q[15]
    _k11 = q[16]
    _k12 = q[17]
    _k13 = q[18]
    _k14 = q[19]
    _k15 = q[20]
    _k16 = q[21]
    _k17 = q[22]
    _k18 = q[23]
    _k19 = q[24]
    _k20 = q[25]
    _k21 = q[26]
    _k22 = q[27]
    _k23 = q[28]
    _k24 = q[29]
    _k25 = q[30]
    _k26 = q[31]
    _k27 = q[32]
    _k28 = q[33]
    _k29 = q[34]
    _c0 = theta1*theta2
    _c1 = (theta2*theta2)
    _c2 = (theta1*theta1)
    _c3 = 1/(_c0*_k2 + _c1*_k0 + _c2*_k1 + _k3)
    _c4 = phi_dot*theta2_dot
    _c5 = phi_dot*theta1_dot
    _c6 = (theta1*theta1*theta1)
    _c7 = (theta2*theta2*theta2)
    _c8 = _c2*theta2
    _c9 = _c1*theta1
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = _c3*_k11*(_c4*_k10 + _c5*_k7 + _c6*_k5 + _c7*_k9 + _c8*_k6 + _c9*_k8 + _k4*theta1)
    ds[3] = _c3*_k19*(_c4*_k16 + _c5*_k14 + _c6*_k15 + _c7*_k13 + _c8*_k17 + _c9*_k18 + _k12*theta2)
    ds[4] = _c3*_k26*(_c0*_k20 + _c1*_k21 + _c2*_k22 + _c4*_k23*theta2 + _c4*_k25*theta1 + _c5*_k24*theta1 + _c5*_k25*theta2)


@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds`` (166 operations)."""
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    phi = s[5]
    x = s[6]
    y = s[7]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (L*L)
    _c1 = 2*_c0
    _c2 = (ell*ell)
    _c3 = _c0 + _c2
    _c4 = _c3*g
    _c5 = math.sin(2*alpha)
    _c6 = D*phi_dot
    _c7 = _c6*theta1_dot
    _c8 = math.sin(alpha)
    _c9 = (D*D)
    _c10 = math.cos(alpha)
    _c11 = 2*_c2
    _c12 = (theta2*theta2*theta2)
    _c13 = (_c10*_c10)
    _c14 = (_c8*_c8)
    _c15 = _c13*_c2
    _c16 = g*(theta1*theta1*theta1)
    _c17 = 2*_c9
    _c18 = 3*_c15
    _c19 = (theta2*theta2)
    _c20 = _c19*g
    _c21 = (theta1*theta1)
    _c22 = -_c2
    _c23 = 8*_c0
    _c24 = (_c8*_c8*_c8*_c8)
    _c25 = 8*_c21*_c9
    _c26 = _c10*theta2
    _c27 = (_c8*_c8*_c8)
    _c28 = _c27*_c9
    _c29 = math.cos(4*alpha) - 1
    _c30 = 1/(_c0*(-_c19*_c29*_c9 + 8*_c2 + _c23 + _c24*_c25 - 16*_c26*_c28*theta1))
    _c31 = g*theta2
    _c32 = _c23*_c7
    _c33 = 4*_c5
    _c34 = _c20*_c33
    _c35 = _c6*theta2_dot
    _c36 = alpha + phi
    _c37 = _c6*(_c10*theta2 - _c8*theta1)
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = 4*_c30*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - (_c10*_c10*_c10)*_c11*_c12*_c8*_c9*g - _c13*_c17*_c20*theta1*(_c0 - _c11 + _c18) - _c14*_c16*_c17*(_c0 + _c15) + _c21*_c5*_c9*g*theta2*(_c1 + _c18 + _c22))/ell
    ds[3] = _c30*ell*(4*D*_c0*_c5*phi_dot*theta2_dot - 8*_c10*_c16*_c28 + _c12*_c29*_c9*g - _c14*_c25*_c31*(3*_c14 - 2) - _c14*_c32 - _c23*_c31 - _c34*_c9*theta1*(3*_c13 - 2))
    ds[4] = D*_c30*(_c0*_c29*_c35*theta2 + _c10*_c23*_c27*_c35*theta1 - _c2*_c34 + _c21*_c33*_c4 - _c24*_c32*theta1 + _c26*_c27*_c32 - 8*_c31*theta1*(_c0*_c13 + 2*_c15 + _c22))
    ds[5] = phi_dot
    ds[6] = _c37*math.sin(_c36)
    ds[7] = -_c37*math.cos(_c36)


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length 8."""
    ds = np.empty(8)
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p`` (76 operations)."""
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    phi = s[5]
    x = s[6]
    y = s[7]
    g = q[0]
    ell = q[1]
    L = q[2]
    D = q[3]
    alpha = q[4]
    _k0 = q[5]
    _k1 = q[6]
    _k2 = q[7]
    _k3 = q[8]
    _k4 = q[9]
    _k5 = q[10]
    _k6 = q[11]
    _k7 = q[12]
    _k8 = q[13]
    _k9 = q[14]
    _k10 = q[15]
    _k11 = q[16]
    _k12 = q[17]
    _k13 = q[18]
    _k14 = q[19]
    _k15 = q[20]
    _k16 = q[21]
    _k17 = q[22]
    _k18 = q[23]
    _k19 = q[24]
    _k20 = q[25]
    _k21 = q[26]
    _k22 = q[27]
    _k23 = q[28]
    _k24 = q[29]
    _k25 = q[30]
    _k26 = q[31]
    _k27 = q[32]
    _k28 = q[33]
    _k29 = q[34]
    _c0 = theta1*theta2
    _c1 = (theta2*theta2)
    _c2 = (theta1*theta1)
    _c3 = 1/(_c0*_k2 + _c1*_k0 + _c2*_k1 + _k3)
    _c4 = phi_dot*theta2_dot
    _c5 = phi_dot*theta1_dot
    _c6 = (theta1*theta1*theta1)
    _c7 = (theta2*theta2*theta2)
    _c8 = _c2*theta2
    _c9 = _c1*theta1
    _c10 = alpha + phi
    _c11 = phi_dot*(_k27*theta2 + _k28*theta1)
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = _c3*_k11*(_c4*_k10 + _c5*_k7 + _c6*_k5 + _c7*_k9 + _c8*_k6 + _c9*_k8 + _k4*theta1)
    ds[3] = _c3*_k19*(_c4*_k16 + _c5*_k14 + _c6*_k15 + _c7*_k13 + _c8*_k17 + _c9*_k18 + _k12*theta2)
    ds[4] = _c3*_k26*(_c0*_k20 + _c1*_k21 + _c2*_k22 + _c4*_k23*theta2 + _c4*_k25*theta1 + _c5*_k24*theta1 + _c5*_k25*theta2)
    ds[5] = phi_dot
    ds[6] = D*_c11*math.sin(_c10)
    ds[7] = _c11*_k29*math.cos(_c10)


@njit(cache=True)
def pose_rates(s, p):
    """Return the rates (phi_dot, x_dot, y_dot) of the pose at the pose-extended state ``s`` (13 operations)."""
    out = np.empty(3)
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    phi = s[5]
    x = s[6]
    y = s[7]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = alpha + phi
    _c1 = D*phi_dot*(-theta1*math.sin(alpha) + theta2*math.cos(alpha))
    out[0] = phi_dot
    out[1] = _c1*math.sin(_c0)
    out[2] = -_c1*math.cos(_c0)
    return out


@njit(cache=True)
def energy(s, p):
    """Energy per unit mass (58 operations)."""
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (theta1*theta1)
    _c1 = ((1.0/2.0))*ell
    _c2 = _c1*g
    _c3 = (theta2*theta2)
    _c4 = (L*L)
    _c5 = ((1.0/2.0))*(phi_dot*phi_dot)
    _c6 = (ell*ell)
    _c7 = ((math.sin(alpha))*(math.sin(alpha)))
    _c8 = D*phi_dot
    _c9 = _c8*ell
    _c10 = math.sin(2*alpha)
    _c11 = _c10*theta1
    _c12 = _c1*_c8
    _c13 = ((math.cos(alpha))*(math.cos(alpha)))
    _c14 = (D*D)*_c5
    energy = _c0*_c14*_c7 + _c0*_c2 - _c10*_c12*theta2*theta2_dot + _c11*_c12*theta1_dot - _c11*_c14*theta2 + _c13*_c14*_c3 - _c13*_c9*theta1_dot*theta2 + _c2*_c3 + _c4*_c5 + ((1.0/2.0))*_c6*(theta1_dot*theta1_dot) + _c7*_c9*theta1*theta2_dot + ((1.0/2.0))*(theta2_dot*theta2_dot)*(_c4 + _c6)
    return energy


@njit(cache=True)
def multipliers(s, p):
    """Lagrange multipliers (contact forces per unit mass) Const22, Const23 (166 operations)."""
    out = np.empty(2)
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (L*L)
    _c1 = (ell*ell)
    _c2 = 8*_c1
    _c3 = (D*D)
    _c4 = 8*_c3
    _c5 = (theta1*theta1)
    _c6 = math.sin(alpha)
    _c7 = (_c6*_c6*_c6*_c6)
    _c8 = _c5*_c7
    _c9 = _c4*_c8
    _c10 = math.cos(alpha)
    _c11 = _c10*theta2
    _c12 = (_c6*_c6*_c6)
    _c13 = _c3*theta1
    _c14 = 16*_c13
    _c15 = _c12*_c14
    _c16 = math.cos(4*alpha) - 1
    _c17 = (theta2*theta2)
    _c18 = _c17*_c3
    _c19 = _c16*_c18
    _c20 = 1/(8*_c0 - _c11*_c15 - _c19 + _c2 + _c9)
    _c21 = _c10*g
    _c22 = _c2*theta2
    _c23 = (theta1*theta1*theta1)
    _c24 = _c6*g
    _c25 = 8*_c0 + 8*_c1
    _c26 = _c25*theta1
    _c27 = _c6**5
    _c28 = (phi_dot*phi_dot)
    _c29 = (D*D*D)*_c28
    _c30 = _c4*_c5
    _c31 = ell*phi_dot
    _c32 = D*_c28
    _c33 = math.sin(2*alpha)
    _c34 = _c10*theta2_dot
    _c35 = _c31*theta2
    _c36 = _c14*_c35*_c7
    _c37 = _c10*theta1_dot
    _c38 = _c31*_c9
    _c39 = _c19*_c31
    _c40 = _c6*theta2_dot
    _c41 = (_c10*_c10)
    _c42 = _c16*_c29
    _c43 = _c0*ell + (ell*ell*ell)
    _c44 = D*_c0*(_c6*_c6) + _c43
    _c45 = 8*phi_dot
    _c46 = _c44*_c45
    out[0] = _c20*(-_c10*_c42*(theta2*theta2*theta2) + _c11*_c25*_c32 + 24*_c11*_c29*_c8 - _c12*_c23*_c4*g + _c15*_c35*_c41*theta1_dot + 3*_c17*_c42*_c6*theta1 - 4*_c18*_c21*_c33*theta1 + _c21*_c22 - 8*_c23*_c27*_c29 - _c24*_c26 + _c24*_c30*_c33*theta2 - _c26*_c32*_c6 - _c27*_c30*_c31*theta2_dot + _c34*_c36 - _c37*_c38 + _c37*_c39 - _c37*_c46 + _c39*_c40 + _c40*_c45*(D*_c0*_c41 - _c43))
    out[1] = _c20*(_c10*_c16*_c17*_c3*ell*phi_dot*theta2_dot - 2*_c13*_c16*_c35*_c40 - _c21*_c26 - _c22*_c24 + 8*_c27*_c3*_c5*ell*phi_dot*theta1_dot - _c34*_c38 - _c34*_c46 - _c36*_c37 - _c39*_c6*theta1_dot + 8*_c44*_c6*phi_dot*theta1_dot)
    return out



#: how to draw the body (derivation/drawing.py): names of the rows of ``body_points``,
#: segments between them, the contact point, the point masses, the tilts a picture may
#: magnify, the outline curves of ``body_outlines``
DRAWING = {'points': ('O', 'end_minus', 'end_plus', 'mass_minus', 'mass_plus', 'C', 'circle_centre'), 'segments': (('end_minus', 'end_plus'), ('end_minus', 'mass_minus'), ('end_plus', 'mass_plus'), ('O', 'circle_centre')), 'contact': 'C', 'masses': ('mass_minus', 'mass_plus'), 'magnify': ('theta1', 'theta2'), 'outlines': ('contact_circle',), 'description': 'bar of length 2L (middle point O), masses M/2 hanging ell below its ends, the contact circle of radius D at the chiral angle alpha, contact point C its lowest point'}


@njit(cache=True)
def body_points(s, p):
    """World coordinates (z up, table z = 0) of DRAWING["points"] at the pose-extended state ``s``; shape (7, 3) (98 operations)."""
    out = np.empty((7, 3))
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    phi = s[5]
    x = s[6]
    y = s[7]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = math.cos(theta1)
    _c1 = math.cos(theta2)
    _c2 = math.sin(alpha)
    _c3 = math.sin(theta1)
    _c4 = _c2*_c3
    _c5 = math.cos(alpha)
    _c6 = math.sin(theta2)
    _c7 = _c0*_c6
    _c8 = _c4 - _c5*_c7
    _c9 = 1/math.sqrt((_c0*_c0)*(_c1*_c1) + (_c8*_c8))
    _c10 = _c0*_c1
    _c11 = -D*_c10*_c9 + D
    _c12 = -_c8
    _c13 = D*_c12*_c9
    _c14 = -D*_c0*_c12*_c5*_c6*_c9 + _c10*_c11 + _c13*_c4
    _c15 = math.cos(phi)
    _c16 = math.sin(phi)
    _c17 = _c16*_c6
    _c18 = _c1*_c15 - _c17*_c3
    _c19 = L*_c18
    _c20 = _c19 - x
    _c21 = _c1*_c16
    _c22 = _c15*_c6
    _c23 = _c21 + _c22*_c3
    _c24 = L*_c23
    _c25 = _c24 - y
    _c26 = L*_c7
    _c27 = _c14 - _c26
    _c28 = _c19 + x
    _c29 = _c24 + y
    _c30 = _c14 + _c26
    _c31 = _c21*_c3 + _c22
    _c32 = _c31*ell
    _c33 = -_c1*_c15*_c3 + _c17
    _c34 = _c33*ell
    _c35 = _c10*ell
    _c36 = _c0*_c13*_c2
    _c37 = _c13*_c5
    out[0, 0] = x
    out[0, 1] = y
    out[0, 2] = -_c14
    out[1, 0] = -_c20
    out[1, 1] = -_c25
    out[1, 2] = -_c27
    out[2, 0] = _c28
    out[2, 1] = _c29
    out[2, 2] = -_c30
    out[3, 0] = -_c20 - _c32
    out[3, 1] = -_c25 - _c34
    out[3, 2] = -_c27 - _c35
    out[4, 0] = _c28 - _c32
    out[4, 1] = _c29 - _c34
    out[4, 2] = -_c30 - _c35
    out[5, 0] = _c11*_c31 - _c16*_c36 + _c18*_c37 + x
    out[5, 1] = _c11*_c33 + _c15*_c36 + _c23*_c37 + y
    out[5, 2] = 0
    out[6, 0] = D*_c31 + x
    out[6, 1] = D*_c33 + y
    out[6, 2] = D*_c0*_c1 - _c14
    return out


@njit(cache=True)
def body_outlines(s, p, uu):
    """World coordinates of the curves DRAWING["outlines"] at the parameters ``uu`` in [0, 2 pi); shape (1, len(uu), 3) (77 operations)."""
    out = np.empty((1, uu.shape[0], 3))
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    phi = s[5]
    x = s[6]
    y = s[7]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    for j in range(uu.shape[0]):
        u = uu[j]
        _c0 = math.sin(phi)
        _c1 = math.sin(alpha)
        _c2 = math.cos(theta1)
        _c3 = math.sin(u)
        _c4 = D*_c3
        _c5 = _c1*_c2*_c4
        _c6 = math.cos(phi)
        _c7 = math.cos(theta2)
        _c8 = math.sin(theta1)
        _c9 = math.sin(theta2)
        _c10 = _c0*_c9
        _c11 = math.cos(alpha)
        _c12 = _c11*_c4
        _c13 = -D*math.cos(u) + D
        _c14 = _c6*_c9
        _c15 = _c0*_c7
        _c16 = _c11*_c2*_c9
        _c17 = _c2*_c7
        _c18 = _c1*_c8
        _c19 = -_c16 + _c18
        _c20 = 1/math.sqrt((_c19*_c19) + (_c2*_c2)*(_c7*_c7))
        _c21 = D*_c20
        _c22 = -_c19
        out[0, j, 0] = -_c0*_c5 + _c12*(-_c10*_c8 + _c6*_c7) + _c13*(_c14 + _c15*_c8) + x
        out[0, j, 1] = _c12*(_c14*_c8 + _c15) + _c13*(_c10 - _c6*_c7*_c8) + _c5*_c6 + y
        out[0, j, 2] = D*_c1*_c3*_c8 + D*_c11*_c2*_c20*_c22*_c9 + _c13*_c2*_c7 - _c16*_c4 - _c17*(D - _c17*_c21) - _c18*_c21*_c22
    return out


@njit(cache=True)
def frequencies(p):
    """Angular frequencies omega_i of the small oscillations of theta1, theta2 at zero spin [1/time] (12 operations)."""
    out = np.empty(2)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = math.sqrt(ell)
    _c1 = math.sqrt(g)
    out[0] = _c1/_c0
    out[1] = _c0*_c1/math.sqrt((L*L) + (ell*ell))
    return out


#: operation counts of the Jacobians and of the Jacobian-vector product, once and per column (derivation/jacobian.py)
OP_COUNTS.update(jacobian=549, jacobian_p=1260, jvp_once=350, jvp_column=82)

@njit(cache=True)
def jacobian(s, p):
    """d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape (5, 5) (549 operations)."""
    out = np.zeros((5, 5))
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (L*L)
    _c1 = 2*_c0
    _c2 = (ell*ell)
    _c3 = _c0 + _c2
    _c4 = _c3*g
    _c5 = math.sin(2*alpha)
    _c6 = D*phi_dot
    _c7 = _c6*theta1_dot
    _d7_4 = D*theta1_dot
    _c8 = (D*D)
    _c9 = math.cos(alpha)
    _c10 = math.sin(alpha)
    _c11 = 2*_c2
    _c12 = (theta2*theta2*theta2)
    _d12_1 = 3*(theta2*theta2)
    _c13 = (_c9*_c9)
    _c14 = (_c10*_c10)
    _c15 = _c13*_c2
    _c16 = _c8*g*(theta1*theta1*theta1)
    _d16_0 = 3*_c8*g*(theta1*theta1)
    _c17 = 3*_c15
    _c18 = (theta2*theta2)
    _d18_1 = 2*theta2
    _c19 = _c18*g
    _d19_1 = _d18_1*g
    _c20 = _c8*theta1
    _c21 = (theta1*theta1)
    _d21_0 = 2*theta1
    _c22 = -_c2
    _c23 = 8*_c0
    _c24 = (_c10*_c10*_c10*_c10)
    _c25 = 8*_c21*_c8
    _d25_0 = 8*_c8*_d21_0
    _c26 = (_c10*_c10*_c10)*_c9
    _c27 = _c26*theta2
    _c28 = math.cos(4*alpha) - 1
    _c29 = 1/(_c0*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))
    _d29_0 = -_c24*_d25_0/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))) + 16*_c27*_c8/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)))
    _d29_1 = 16*_c20*_c26/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))) + _c28*_c8*_d18_1/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)))
    _c30 = g*theta2
    _c31 = _c23*_c7
    _d31_2 = _c23*_c6
    _d31_4 = _c23*_d7_4
    _c32 = 4*_c5
    _c33 = _c19*_c32
    _d33_1 = _c32*_d19_1
    _c34 = _c6*theta2_dot
    _d34_4 = D*theta2_dot
    out[0, 2] = 1
    out[1, 3] = 1
    out[2, 0] = -4*_c1*_c29*_c4/ell - 8*_c13*_c19*_c29*_c8*(_c0 - _c11 + _c17)/ell - 8*_c14*_c29*_d16_0*(_c0 + _c15)/ell + 4*_c29*_c5*_c8*_d21_0*g*theta2*(_c1 + _c17 + _c22)/ell + 4*_d29_0*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - _c10*_c11*_c12*_c8*(_c9*_c9*_c9)*g - 2*_c13*_c19*_c20*(_c0 - _c11 + _c17) - 2*_c14*_c16*(_c0 + _c15) + _c21*_c5*_c8*g*theta2*(_c1 + _c17 + _c22))/ell
    out[2, 1] = -4*_c10*_c11*_c29*_c8*(_c9*_c9*_c9)*_d12_1*g/ell - 8*_c13*_c20*_c29*_d19_1*(_c0 - _c11 + _c17)/ell + 4*_c21*_c29*_c5*_c8*g*(_c1 + _c17 + _c22)/ell + 4*_d29_1*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - _c10*_c11*_c12*_c8*(_c9*_c9*_c9)*g - 2*_c13*_c19*_c20*(_c0 - _c11 + _c17) - 2*_c14*_c16*(_c0 + _c15) + _c21*_c5*_c8*g*theta2*(_c1 + _c17 + _c22))/ell
    out[2, 2] = -4*_c0*_c29*_c3*_c5*_c6/ell
    out[2, 3] = 8*D*_c0*_c13*_c29*_c3*phi_dot/ell
    out[2, 4] = 8*D*_c0*_c13*_c29*_c3*theta2_dot/ell - 4*_c0*_c29*_c3*_c5*_d7_4/ell
    out[3, 0] = -_c14*_c29*_c30*_d25_0*ell*(3*_c14 - 2) - 8*_c26*_c29*_d16_0*ell - _c29*_c33*_c8*ell*(3*_c13 - 2) + _d29_0*ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c25*_c30*(3*_c14 - 2) - _c14*_c31 - 8*_c16*_c26 - _c20*_c33*(3*_c13 - 2) - _c23*_c30)
    out[3, 1] = -_c20*_c29*_d33_1*ell*(3*_c13 - 2) + _c28*_c29*_c8*_d12_1*ell*g + _c29*ell*g*(-_c14*_c25*(3*_c14 - 2) - _c23) + _d29_1*ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c25*_c30*(3*_c14 - 2) - _c14*_c31 - 8*_c16*_c26 - _c20*_c33*(3*_c13 - 2) - _c23*_c30)
    out[3, 2] = -_c14*_c29*_d31_2*ell
    out[3, 3] = 4*D*_c0*_c29*_c5*ell*phi_dot
    out[3, 4] = 4*D*_c0*_c29*_c5*ell*theta2_dot - _c14*_c29*_d31_4*ell
    out[4, 0] = D*_c29*_c32*_c4*_d21_0 + D*_c29*(_c23*_c26*_c34 - _c24*_c31 - 8*_c30*(_c0*_c13 + 2*_c15 + _c22)) + D*_d29_0*(_c0*_c28*_c34*theta2 - _c2*_c33 + _c21*_c32*_c4 + _c23*_c26*_c34*theta1 - _c24*_c31*theta1 + _c27*_c31 - 8*_c30*theta1*(_c0*_c13 + 2*_c15 + _c22))
    out[4, 1] = D*_c0*_c28*_c29*_c34 - D*_c2*_c29*_d33_1 + D*_c26*_c29*_c31 - 8*D*_c29*g*theta1*(_c0*_c13 + 2*_c15 + _c22) + D*_d29_1*(_c0*_c28*_c34*theta2 - _c2*_c33 + _c21*_c32*_c4 + _c23*_c26*_c34*theta1 - _c24*_c31*theta1 + _c27*_c31 - 8*_c30*theta1*(_c0*_c13 + 2*_c15 + _c22))
    out[4, 2] = D*_c29*_d31_2*(-_c24*theta1 + _c27)
    out[4, 3] = D*_c29*_c6*(_c0*_c28*theta2 + _c23*_c26*theta1)
    out[4, 4] = D*_c29*_d31_4*(-_c24*theta1 + _c27) + D*_c29*_d34_4*(_c0*_c28*theta2 + _c23*_c26*theta1)
    return out


@njit(cache=True)
def jacobian_p(s, p):
    """d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape (5, 5) (1260 operations)."""
    out = np.zeros((5, 5))
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (L*L)
    _d0_2 = 2*L
    _c1 = 2*_c0
    _d1_2 = 2*_d0_2
    _c2 = (ell*ell)
    _d2_1 = 2*ell
    _c3 = _c0 + _c2
    _c4 = _c3*g
    _d4_1 = _d2_1*g
    _d4_2 = _d0_2*g
    _c5 = math.sin(2*alpha)
    _d5_4 = 2*math.cos(2*alpha)
    _c6 = D*phi_dot
    _c7 = _c6*theta1_dot
    _d7_3 = phi_dot*theta1_dot
    _c8 = (D*D)
    _d8_3 = 2*D
    _c9 = math.cos(alpha)
    _d9_4 = -math.sin(alpha)
    _c10 = math.sin(alpha)
    _d10_4 = math.cos(alpha)
    _c11 = 2*_c2
    _d11_1 = 2*_d2_1
    _c12 = (theta2*theta2*theta2)
    _c13 = (_c9*_c9)
    _d13_4 = 2*_c9*_d9_4
    _c14 = (_c10*_c10)
    _d14_4 = 2*_c10*_d10_4
    _c15 = _c13*_c2
    _d15_1 = _c13*_d2_1
    _d15_4 = _c2*_d13_4
    _c16 = _c8*g*(theta1*theta1*theta1)
    _d16_0 = _c8*(theta1*theta1*theta1)
    _d16_3 = _d8_3*g*(theta1*theta1*theta1)
    _c17 = 3*_c15
    _d17_1 = 3*_d15_1
    _d17_4 = 3*_d15_4
    _c18 = (theta2*theta2)
    _c19 = _c18*g
    _c20 = _c8*theta1
    _d20_3 = _d8_3*theta1
    _c21 = (theta1*theta1)
    _c22 = -_c2
    _d22_1 = -_d2_1
    _c23 = 8*_c0
    _d23_2 = 8*_d0_2
    _c24 = (_c10*_c10*_c10*_c10)
    _d24_4 = 4*(_c10*_c10*_c10)*_d10_4
    _c25 = 8*_c21*_c8
    _d25_3 = 8*_c21*_d8_3
    _c26 = (_c10*_c10*_c10)*_c9
    _d26_4 = (_c10*_c10*_c10)*_d9_4 + 3*(_c10*_c10)*_c9*_d10_4
    _c27 = _c26*theta2
    _d27_4 = _d26_4*theta2
    _c28 = math.cos(4*alpha) - 1
    _d28_4 = -4*math.sin(4*alpha)
    _c29 = 1/(_c0*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))
    _d29_1 = -8*_d2_1/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)))
    _d29_2 = -_d23_2/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))) - _d0_2/((_c0*_c0)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))
    _d29_3 = _c18*_c28*_d8_3/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))) - _c24*_d25_3/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))) + 16*_c27*_d20_3/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)))
    _d29_4 = _c18*_c8*_d28_4/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))) + 16*_c20*_d27_4/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))) - _c25*_d24_4/(_c0*((-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25)))
    _c30 = g*theta2
    _c31 = _c23*_c7
    _d31_2 = _c7*_d23_2
    _d31_3 = _c23*_d7_3
    _c32 = 4*_c5
    _d32_4 = 4*_d5_4
    _c33 = _c19*_c32
    _d33_0 = _c18*_c32
    _d33_4 = _c19*_d32_4
    _c34 = _c6*theta2_dot
    _d34_3 = phi_dot*theta2_dot
    out[2, 0] = -4*_c1*_c29*_c3*theta1/ell - 8*_c13*_c18*_c20*_c29*(_c0 - _c11 + _c17)/ell - 8*_c14*_c29*_d16_0*(_c0 + _c15)/ell + 4*_c29*(-_c10*_c11*_c12*_c8*(_c9*_c9*_c9) + _c21*_c5*_c8*theta2*(_c1 + _c17 + _c22))/ell
    out[2, 1] = -4*_c1*_c29*_d4_1*theta1/ell - 8*_c14*_c16*_c29*_d15_1/ell + 4*_c21*_c29*_c5*_c8*_d22_1*g*theta2/ell + 4*_c29*_d11_1*(-_c10*_c12*_c8*(_c9*_c9*_c9)*g + 2*_c13*_c19*_c20)/ell + 4*_c29*_d17_1*(-2*_c13*_c19*_c20 + _c21*_c5*_c8*g*theta2)/ell + 4*_c29*_d2_1*(2*D*_c0*_c13*phi_dot*theta2_dot - _c0*_c5*_c7)/ell - 4*_c29*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - _c10*_c11*_c12*_c8*(_c9*_c9*_c9)*g - 2*_c13*_c19*_c20*(_c0 - _c11 + _c17) - 2*_c14*_c16*(_c0 + _c15) + _c21*_c5*_c8*g*theta2*(_c1 + _c17 + _c22))/(ell*ell) + 4*_d29_1*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - _c10*_c11*_c12*_c8*(_c9*_c9*_c9)*g - 2*_c13*_c19*_c20*(_c0 - _c11 + _c17) - 2*_c14*_c16*(_c0 + _c15) + _c21*_c5*_c8*g*theta2*(_c1 + _c17 + _c22))/ell
    out[2, 2] = -4*_c1*_c29*_d4_2*theta1/ell + 4*_c29*_d0_2*(2*D*_c0*_c13*phi_dot*theta2_dot - _c0*_c5*_c7)/ell + 4*_c29*_d0_2*(2*D*_c13*_c3*phi_dot*theta2_dot - 2*_c13*_c19*_c20 - 2*_c14*_c16 - _c3*_c5*_c7)/ell + 4*_c29*_d1_2*(_c21*_c5*_c8*g*theta2 - _c4*theta1)/ell + 4*_d29_2*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - _c10*_c11*_c12*_c8*(_c9*_c9*_c9)*g - 2*_c13*_c19*_c20*(_c0 - _c11 + _c17) - 2*_c14*_c16*(_c0 + _c15) + _c21*_c5*_c8*g*theta2*(_c1 + _c17 + _c22))/ell
    out[2, 3] = 8*_c0*_c13*_c29*_c3*phi_dot*theta2_dot/ell - 4*_c0*_c29*_c3*_c5*_d7_3/ell - 8*_c13*_c19*_c29*_d20_3*(_c0 - _c11 + _c17)/ell - 8*_c14*_c29*_d16_3*(_c0 + _c15)/ell + 4*_c29*_d8_3*(-_c10*_c11*_c12*(_c9*_c9*_c9)*g + _c21*_c5*g*theta2*(_c1 + _c17 + _c22))/ell + 4*_d29_3*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - _c10*_c11*_c12*_c8*(_c9*_c9*_c9)*g - 2*_c13*_c19*_c20*(_c0 - _c11 + _c17) - 2*_c14*_c16*(_c0 + _c15) + _c21*_c5*_c8*g*theta2*(_c1 + _c17 + _c22))/ell
    out[2, 4] = -12*_c10*_c11*_c12*_c29*_c8*(_c9*_c9)*_d9_4*g/ell - 4*_c11*_c12*_c29*_c8*(_c9*_c9*_c9)*_d10_4*g/ell - 8*_c14*_c16*_c29*_d15_4/ell - 8*_c16*_c29*_d14_4*(_c0 + _c15)/ell + 4*_c29*_d13_4*(2*D*_c0*_c3*phi_dot*theta2_dot - 2*_c19*_c20*(_c0 - _c11 + _c17))/ell + 4*_c29*_d17_4*(-2*_c13*_c19*_c20 + _c21*_c5*_c8*g*theta2)/ell + 4*_c29*_d5_4*(-_c0*_c3*_c7 + _c21*_c8*g*theta2*(_c1 + _c17 + _c22))/ell + 4*_d29_4*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - _c10*_c11*_c12*_c8*(_c9*_c9*_c9)*g - 2*_c13*_c19*_c20*(_c0 - _c11 + _c17) - 2*_c14*_c16*(_c0 + _c15) + _c21*_c5*_c8*g*theta2*(_c1 + _c17 + _c22))/ell
    out[3, 0] = _c12*_c28*_c29*_c8*ell - _c20*_c29*_d33_0*ell*(3*_c13 - 2) - 8*_c26*_c29*_d16_0*ell + _c29*ell*theta2*(-_c14*_c25*(3*_c14 - 2) - _c23)
    out[3, 1] = _c29*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c25*_c30*(3*_c14 - 2) - _c14*_c31 - 8*_c16*_c26 - _c20*_c33*(3*_c13 - 2) - _c23*_c30) + _d29_1*ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c25*_c30*(3*_c14 - 2) - _c14*_c31 - 8*_c16*_c26 - _c20*_c33*(3*_c13 - 2) - _c23*_c30)
    out[3, 2] = 4*D*_c29*_c5*_d0_2*ell*phi_dot*theta2_dot - _c14*_c29*_d31_2*ell - _c29*_c30*_d23_2*ell + _d29_2*ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c25*_c30*(3*_c14 - 2) - _c14*_c31 - 8*_c16*_c26 - _c20*_c33*(3*_c13 - 2) - _c23*_c30)
    out[3, 3] = 4*_c0*_c29*_c5*ell*phi_dot*theta2_dot + _c12*_c28*_c29*_d8_3*ell*g - _c14*_c29*_c30*_d25_3*ell*(3*_c14 - 2) - _c14*_c29*_d31_3*ell - 8*_c26*_c29*_d16_3*ell - _c29*_c33*_d20_3*ell*(3*_c13 - 2) + _d29_3*ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c25*_c30*(3*_c14 - 2) - _c14*_c31 - 8*_c16*_c26 - _c20*_c33*(3*_c13 - 2) - _c23*_c30)
    out[3, 4] = 4*D*_c0*_c29*_d5_4*ell*phi_dot*theta2_dot + _c12*_c29*_c8*_d28_4*ell*g - 8*_c16*_c29*_d26_4*ell - 3*_c20*_c29*_c33*_d13_4*ell - _c20*_c29*_d33_4*ell*(3*_c13 - 2) + _c29*_d14_4*ell*(-3*_c14*_c25*_c30 - _c25*_c30*(3*_c14 - 2) - _c31) + _d29_4*ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c25*_c30*(3*_c14 - 2) - _c14*_c31 - 8*_c16*_c26 - _c20*_c33*(3*_c13 - 2) - _c23*_c30)
    out[4, 0] = -D*_c2*_c29*_d33_0 + D*_c21*_c29*_c3*_c32 - 8*D*_c29*theta1*theta2*(_c0*_c13 + 2*_c15 + _c22)
    out[4, 1] = D*_c21*_c29*_c32*_d4_1 - 16*D*_c29*_c30*_d15_1*theta1 - 8*D*_c29*_c30*_d22_1*theta1 - D*_c29*_c33*_d2_1 + D*_d29_1*(_c0*_c28*_c34*theta2 - _c2*_c33 + _c21*_c32*_c4 + _c23*_c26*_c34*theta1 - _c24*_c31*theta1 + _c27*_c31 - 8*_c30*theta1*(_c0*_c13 + 2*_c15 + _c22))
    out[4, 2] = D*_c21*_c29*_c32*_d4_2 + D*_c26*_c29*_c34*_d23_2*theta1 + D*_c29*_d0_2*(-8*_c13*_c30*theta1 + _c28*_c34*theta2) + D*_c29*_d31_2*(-_c24*theta1 + _c27) + D*_d29_2*(_c0*_c28*_c34*theta2 - _c2*_c33 + _c21*_c32*_c4 + _c23*_c26*_c34*theta1 - _c24*_c31*theta1 + _c27*_c31 - 8*_c30*theta1*(_c0*_c13 + 2*_c15 + _c22))
    out[4, 3] = D*_c29*_d31_3*(-_c24*theta1 + _c27) + D*_c29*_d34_3*(_c0*_c28*theta2 + _c23*_c26*theta1) + D*_d29_3*(_c0*_c28*_c34*theta2 - _c2*_c33 + _c21*_c32*_c4 + _c23*_c26*_c34*theta1 - _c24*_c31*theta1 + _c27*_c31 - 8*_c30*theta1*(_c0*_c13 + 2*_c15 + _c22)) + _c29*(_c0*_c28*_c34*theta2 - _c2*_c33 + _c21*_c32*_c4 + _c23*_c26*_c34*theta1 - _c24*_c31*theta1 + _c27*_c31 - 8*_c30*theta1*(_c0*_c13 + 2*_c15 + _c22))
    out[4, 4] = -8*D*_c0*_c29*_c30*_d13_4*theta1 + D*_c0*_c29*_c34*_d28_4*theta2 - D*_c2*_c29*_d33_4 + D*_c21*_c29*_c4*_d32_4 + D*_c23*_c29*_c34*_d26_4*theta1 - 16*D*_c29*_c30*_d15_4*theta1 - D*_c29*_c31*_d24_4*theta1 + D*_c29*_c31*_d27_4 + D*_d29_4*(_c0*_c28*_c34*theta2 - _c2*_c33 + _c21*_c32*_c4 + _c23*_c26*_c34*theta1 - _c24*_c31*theta1 + _c27*_c31 - 8*_c30*theta1*(_c0*_c13 + 2*_c15 + _c22))
    return out


@njit(cache=True)
def jvp_into(s, p, _V, ds, out):
    """Write d(state)/dt into ``ds`` and ``J(s) _V`` into ``out`` (``_V``, ``out``: (5, k)), the derivatives of the rates along the columns of ``_V`` by forward mode through the right-hand side (350 operations once, 82 per column)."""
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (L*L)
    _c1 = 2*_c0
    _c2 = (ell*ell)
    _c3 = _c0 + _c2
    _c4 = _c3*g
    _c5 = math.sin(2*alpha)
    _c6 = D*phi_dot
    _c7 = _c6*theta1_dot
    _c8 = (D*D)
    _c9 = math.cos(alpha)
    _c10 = math.sin(alpha)
    _c11 = 2*_c2
    _c12 = (theta2*theta2*theta2)
    _c13 = (_c9*_c9)
    _c14 = (_c10*_c10)
    _c15 = _c13*_c2
    _c16 = _c8*g*(theta1*theta1*theta1)
    _c17 = 3*_c15
    _c18 = (theta2*theta2)
    _c19 = _c18*g
    _c20 = _c8*theta1
    _c21 = (theta1*theta1)
    _c22 = -_c2
    _c23 = 8*_c0
    _c24 = (_c10*_c10*_c10*_c10)
    _c25 = 8*_c21*_c8
    _c26 = (_c10*_c10*_c10)*_c9
    _c27 = _c26*theta2
    _c28 = math.cos(4*alpha) - 1
    _c29 = 1/(_c0*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))
    _c30 = g*theta2
    _c31 = _c23*_c7
    _c32 = 4*_c5
    _c33 = _c19*_c32
    _c34 = _c6*theta2_dot
    _p0 = _c8*g
    _p1 = 16*_c20
    _p2 = _c28*_c8
    _p3 = 1/(_c0*((-_c18*_p2 + 8*_c2 + _c23 + _c24*_c25 - _c27*_p1)*(-_c18*_p2 + 8*_c2 + _c23 + _c24*_c25 - _c27*_p1)))
    _p4 = _c1*_c4
    _p5 = _c0*_c5
    _p6 = _c3*_p5
    _p7 = _c14*(_c0 + _c15)
    _p8 = _c10*_c11*(_c9*_c9*_c9)*_p0
    _p9 = _c0 - _c11 + _c17
    _p10 = _c13*_c19*_p9
    _p11 = _c1 + _c17 + _c22
    _p12 = 1/ell
    _p13 = 4*_p12
    _p14 = 8*_p12
    _p15 = _c29*_p14
    _p16 = _c29*_p13
    _p17 = D*_c29
    _p18 = _c0*_c13
    _p19 = _c3*_p14*_p17*_p18
    _p20 = 8*_c26
    _p21 = 3*_c13 - 2
    _p22 = _c20*_p21
    _p23 = _c14*(3*_c14 - 2)
    _p24 = _c25*_p23
    _p25 = _c29*ell
    _p26 = 4*D*_p25*_p5
    _p27 = _c32*_c4
    _p28 = _c24*theta1
    _p29 = _c0*_c28
    _p30 = _p29*theta2
    _p31 = _c23*_c26*theta1
    _p32 = 16*_c15 + 8*_c22 + 8*_p18
    _p33 = _c30*_p32
    _k0 = 3*(theta2*theta2)
    _k1 = 3*_p0*(theta1*theta1)
    _k2 = 2*theta2
    _k3 = 2*theta1
    _k4 = 8*_c8
    _k5 = -_c24*_p3
    _k6 = _p1*_p3
    _k7 = 16*_c27*_p3
    _k8 = _p2*_p3
    _k9 = _p13*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c12*_p8 - 2*_c16*_p7 - 2*_c20*_p10 + _c21*_c5*_c8*_p11*g*theta2 - _c7*_p6 - _p4*theta1)
    _k10 = -_p15*_p7
    _k11 = -_p16*_p4
    _k12 = -_p10*_p15
    _k13 = -_c13*_c20*_p15*_p9
    _k14 = -_p16*_p6
    _k15 = -_p16*_p8
    _k16 = _c21*_c5*_p0*_p11*_p16
    _k17 = _c5*_p0*_p11*_p16*theta2
    _k18 = _p19*phi_dot
    _k19 = _p19*theta2_dot
    _k20 = ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c31 - _c16*_p20 - _c23*_c30 - _c30*_p24 - _c33*_p22)
    _k21 = _p25*(-_c23 - _p24)
    _k22 = -_c14*_p25
    _k23 = -_p20*_p25
    _k24 = -_p22*_p25
    _k25 = -_c33*_p21*_p25
    _k26 = _p2*_p25*g
    _k27 = -_c30*_p23*_p25
    _k28 = _p26*phi_dot
    _k29 = _p26*theta2_dot
    _k30 = D*(-_c2*_c33 + _c21*_p27 + _c27*_c31 - _c31*_p28 + _c34*_p30 + _c34*_p31 - _p33*theta1)
    _k31 = _c31*_p17
    _k32 = _p17*(_c27 - _p28)
    _k33 = _p17*(_p30 + _p31)
    _k34 = _p17*(_c23*_c26*_c34 - _c24*_c31 - _p33)
    _k35 = -_c2*_p17
    _k36 = _p17*_p27
    _k37 = -_p17*_p32*theta1
    _k38 = _c34*_p17*_p29
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = 4*_c29*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - _c10*_c11*_c12*_c8*(_c9*_c9*_c9)*g - 2*_c13*_c19*_c20*(_c0 - _c11 + _c17) - 2*_c14*_c16*(_c0 + _c15) + _c21*_c5*_c8*g*theta2*(_c1 + _c17 + _c22))/ell
    ds[3] = _c29*ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c25*_c30*(3*_c14 - 2) - _c14*_c31 - 8*_c16*_c26 - _c20*_c33*(3*_c13 - 2) - _c23*_c30)
    ds[4] = D*_c29*(_c0*_c28*_c34*theta2 - _c2*_c33 + _c21*_c32*_c4 + _c23*_c26*_c34*theta1 - _c24*_c31*theta1 + _c27*_c31 - 8*_c30*theta1*(_c0*_c13 + 2*_c15 + _c22))
    for _j in range(_V.shape[1]):
        _v0 = _V[0, _j]
        _v1 = _V[1, _j]
        _v2 = _V[2, _j]
        _v3 = _V[3, _j]
        _v4 = _V[4, _j]
        _t6 = D*_v4
        _t7 = _c6*_v2 + _t6*theta1_dot
        _t12 = _k0*_v1
        _t16 = _k1*_v0
        _t18 = _k2*_v1
        _t19 = _t18*g
        _t20 = _c8*_v0
        _t21 = _k3*_v0
        _t25 = _k4*_t21
        _t27 = _c26*_v1
        _t29 = _k5*_t25 + _k6*_t27 + _k7*_t20 + _k8*_t18
        _t30 = _v1*g
        _t31 = _c23*_t7
        _t33 = _c32*_t19
        _t34 = _c6*_v3 + _t6*theta2_dot
        out[0, _j] = _v2
        out[1, _j] = _v3
        out[2, _j] = _k10*_t16 + _k11*_v0 + _k12*_t20 + _k13*_t19 + _k14*_t7 + _k15*_t12 + _k16*_v1 + _k17*_t21 + _k18*_v3 + _k19*_v4 + _k9*_t29
        out[3, _j] = _k20*_t29 + _k21*_t30 + _k22*_t31 + _k23*_t16 + _k24*_t33 + _k25*_t20 + _k26*_t12 + _k27*_t25 + _k28*_v3 + _k29*_v4
        out[4, _j] = _k30*_t29 + _k31*_t27 + _k32*_t31 + _k33*_t34 + _k34*_v0 + _k35*_t33 + _k36*_t21 + _k37*_t30 + _k38*_v1


@njit(cache=True)
def jvp1_into(s, p, _v, ds, _dv):
    """``jvp_into`` of one column: d(state)/dt into ``ds`` and ``J(s) _v`` into ``_dv`` (vectors of length 5; 432 operations)."""
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (L*L)
    _c1 = 2*_c0
    _c2 = (ell*ell)
    _c3 = _c0 + _c2
    _c4 = _c3*g
    _c5 = math.sin(2*alpha)
    _c6 = D*phi_dot
    _c7 = _c6*theta1_dot
    _c8 = (D*D)
    _c9 = math.cos(alpha)
    _c10 = math.sin(alpha)
    _c11 = 2*_c2
    _c12 = (theta2*theta2*theta2)
    _c13 = (_c9*_c9)
    _c14 = (_c10*_c10)
    _c15 = _c13*_c2
    _c16 = _c8*g*(theta1*theta1*theta1)
    _c17 = 3*_c15
    _c18 = (theta2*theta2)
    _c19 = _c18*g
    _c20 = _c8*theta1
    _c21 = (theta1*theta1)
    _c22 = -_c2
    _c23 = 8*_c0
    _c24 = (_c10*_c10*_c10*_c10)
    _c25 = 8*_c21*_c8
    _c26 = (_c10*_c10*_c10)*_c9
    _c27 = _c26*theta2
    _c28 = math.cos(4*alpha) - 1
    _c29 = 1/(_c0*(-_c18*_c28*_c8 + 8*_c2 - 16*_c20*_c27 + _c23 + _c24*_c25))
    _c30 = g*theta2
    _c31 = _c23*_c7
    _c32 = 4*_c5
    _c33 = _c19*_c32
    _c34 = _c6*theta2_dot
    _p0 = _c8*g
    _p1 = 16*_c20
    _p2 = _c28*_c8
    _p3 = 1/(_c0*((-_c18*_p2 + 8*_c2 + _c23 + _c24*_c25 - _c27*_p1)*(-_c18*_p2 + 8*_c2 + _c23 + _c24*_c25 - _c27*_p1)))
    _p4 = _c1*_c4
    _p5 = _c0*_c5
    _p6 = _c3*_p5
    _p7 = _c14*(_c0 + _c15)
    _p8 = _c10*_c11*(_c9*_c9*_c9)*_p0
    _p9 = _c0 - _c11 + _c17
    _p10 = _c13*_c19*_p9
    _p11 = _c1 + _c17 + _c22
    _p12 = 1/ell
    _p13 = 4*_p12
    _p14 = 8*_p12
    _p15 = _c29*_p14
    _p16 = _c29*_p13
    _p17 = D*_c29
    _p18 = _c0*_c13
    _p19 = _c3*_p14*_p17*_p18
    _p20 = 8*_c26
    _p21 = 3*_c13 - 2
    _p22 = _c20*_p21
    _p23 = _c14*(3*_c14 - 2)
    _p24 = _c25*_p23
    _p25 = _c29*ell
    _p26 = 4*D*_p25*_p5
    _p27 = _c32*_c4
    _p28 = _c24*theta1
    _p29 = _c0*_c28
    _p30 = _p29*theta2
    _p31 = _c23*_c26*theta1
    _p32 = 16*_c15 + 8*_c22 + 8*_p18
    _p33 = _c30*_p32
    _k0 = 3*(theta2*theta2)
    _k1 = 3*_p0*(theta1*theta1)
    _k2 = 2*theta2
    _k3 = 2*theta1
    _k4 = 8*_c8
    _k5 = -_c24*_p3
    _k6 = _p1*_p3
    _k7 = 16*_c27*_p3
    _k8 = _p2*_p3
    _k9 = _p13*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c12*_p8 - 2*_c16*_p7 - 2*_c20*_p10 + _c21*_c5*_c8*_p11*g*theta2 - _c7*_p6 - _p4*theta1)
    _k10 = -_p15*_p7
    _k11 = -_p16*_p4
    _k12 = -_p10*_p15
    _k13 = -_c13*_c20*_p15*_p9
    _k14 = -_p16*_p6
    _k15 = -_p16*_p8
    _k16 = _c21*_c5*_p0*_p11*_p16
    _k17 = _c5*_p0*_p11*_p16*theta2
    _k18 = _p19*phi_dot
    _k19 = _p19*theta2_dot
    _k20 = ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c31 - _c16*_p20 - _c23*_c30 - _c30*_p24 - _c33*_p22)
    _k21 = _p25*(-_c23 - _p24)
    _k22 = -_c14*_p25
    _k23 = -_p20*_p25
    _k24 = -_p22*_p25
    _k25 = -_c33*_p21*_p25
    _k26 = _p2*_p25*g
    _k27 = -_c30*_p23*_p25
    _k28 = _p26*phi_dot
    _k29 = _p26*theta2_dot
    _k30 = D*(-_c2*_c33 + _c21*_p27 + _c27*_c31 - _c31*_p28 + _c34*_p30 + _c34*_p31 - _p33*theta1)
    _k31 = _c31*_p17
    _k32 = _p17*(_c27 - _p28)
    _k33 = _p17*(_p30 + _p31)
    _k34 = _p17*(_c23*_c26*_c34 - _c24*_c31 - _p33)
    _k35 = -_c2*_p17
    _k36 = _p17*_p27
    _k37 = -_p17*_p32*theta1
    _k38 = _c34*_p17*_p29
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = 4*_c29*(2*D*_c0*_c13*_c3*phi_dot*theta2_dot - _c0*_c3*_c5*_c7 - _c1*_c4*theta1 - _c10*_c11*_c12*_c8*(_c9*_c9*_c9)*g - 2*_c13*_c19*_c20*(_c0 - _c11 + _c17) - 2*_c14*_c16*(_c0 + _c15) + _c21*_c5*_c8*g*theta2*(_c1 + _c17 + _c22))/ell
    ds[3] = _c29*ell*(4*D*_c0*_c5*phi_dot*theta2_dot + _c12*_c28*_c8*g - _c14*_c25*_c30*(3*_c14 - 2) - _c14*_c31 - 8*_c16*_c26 - _c20*_c33*(3*_c13 - 2) - _c23*_c30)
    ds[4] = D*_c29*(_c0*_c28*_c34*theta2 - _c2*_c33 + _c21*_c32*_c4 + _c23*_c26*_c34*theta1 - _c24*_c31*theta1 + _c27*_c31 - 8*_c30*theta1*(_c0*_c13 + 2*_c15 + _c22))
    _v0 = _v[0]
    _v1 = _v[1]
    _v2 = _v[2]
    _v3 = _v[3]
    _v4 = _v[4]
    _t6 = D*_v4
    _t7 = _c6*_v2 + _t6*theta1_dot
    _t12 = _k0*_v1
    _t16 = _k1*_v0
    _t18 = _k2*_v1
    _t19 = _t18*g
    _t20 = _c8*_v0
    _t21 = _k3*_v0
    _t25 = _k4*_t21
    _t27 = _c26*_v1
    _t29 = _k5*_t25 + _k6*_t27 + _k7*_t20 + _k8*_t18
    _t30 = _v1*g
    _t31 = _c23*_t7
    _t33 = _c32*_t19
    _t34 = _c6*_v3 + _t6*theta2_dot
    _dv[0] = _v2
    _dv[1] = _v3
    _dv[2] = _k10*_t16 + _k11*_v0 + _k12*_t20 + _k13*_t19 + _k14*_t7 + _k15*_t12 + _k16*_v1 + _k17*_t21 + _k18*_v3 + _k19*_v4 + _k9*_t29
    _dv[3] = _k20*_t29 + _k21*_t30 + _k22*_t31 + _k23*_t16 + _k24*_t33 + _k25*_t20 + _k26*_t12 + _k27*_t25 + _k28*_v3 + _k29*_v4
    _dv[4] = _k30*_t29 + _k31*_t27 + _k32*_t31 + _k33*_t34 + _k34*_v0 + _k35*_t33 + _k36*_t21 + _k37*_t30 + _k38*_v1



#: families of steady motions (derivation/steady.py): name -> the family's parameter ``value`` (``value_state`` is
#: the state equal to it), what the motion is, and names of the modes by their largest state
STEADY_FAMILIES = {'steady_spin': {'value': 'Omega', 'value_state': 'phi_dot', 'description': 'upright steady spin theta1 = theta2 = 0 at the rate Omega', 'mode_names': {'A1': 'theta1', 'A2': 'theta2', 'theta1': 'theta1', 'theta1_dot': 'theta1', 'theta2': 'theta2', 'theta2_dot': 'theta2'}}}


@njit(cache=True)
def steady_state(_family, _value, p):
    """Row 0: the closed state of family number ``_family`` of STEADY_FAMILIES at ``_value``; row 1: its derivative
    in ``_value`` (the family's tangent)."""
    out = np.zeros((2, 5))
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    if _family == 0:
        Omega = _value
        out[0, 4] = Omega
        out[1, 4] = 1

    return out


#: functions of the closed state fixed by construction; their gradients are not physical directions
STATE_INVARIANTS = ()


@njit(cache=True)
def invariant_gradients(s, p):
    """Gradients of STATE_INVARIANTS, shape (0, 5)."""
    out = np.zeros((0, 5))
    theta1 = s[0]
    theta2 = s[1]
    theta1_dot = s[2]
    theta2_dot = s[3]
    phi_dot = s[4]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]

    return out


#: LLVM IR of the functions above that are straight-line arithmetic, written by derivation/ir_emit.py
#: (the operations numba emits for them, in its order: the same bits); the runtime compiles it
LLVM_IR = {
    'rhs_q_into': (
        'define internal i32 @"rhs_q_into"(ptr nocapture %ret, ptr nocapture %exc, double %t, ptr nocapture %s, ptr nocapture %q, i64 %nq, ptr nocapture %ds) {\n'
        'entry:\n'
        '  %v1 = getelementptr inbounds double, ptr %s, i64 0\n'
        '  %v2 = load double, ptr %v1\n'
        '  %v3 = getelementptr inbounds double, ptr %s, i64 1\n'
        '  %v4 = load double, ptr %v3\n'
        '  %v5 = getelementptr inbounds double, ptr %s, i64 2\n'
        '  %v6 = load double, ptr %v5\n'
        '  %v7 = getelementptr inbounds double, ptr %s, i64 3\n'
        '  %v8 = load double, ptr %v7\n'
        '  %v9 = getelementptr inbounds double, ptr %s, i64 4\n'
        '  %v10 = load double, ptr %v9\n'
        '  %v11 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  %v12 = load double, ptr %v11\n'
        '  %v13 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  %v14 = load double, ptr %v13\n'
        '  %v15 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  %v16 = load double, ptr %v15\n'
        '  %v17 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  %v18 = load double, ptr %v17\n'
        '  %v19 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  %v20 = load double, ptr %v19\n'
        '  %v21 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  %v22 = load double, ptr %v21\n'
        '  %v23 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  %v24 = load double, ptr %v23\n'
        '  %v25 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  %v26 = load double, ptr %v25\n'
        '  %v27 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  %v28 = load double, ptr %v27\n'
        '  %v29 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  %v30 = load double, ptr %v29\n'
        '  %v31 = getelementptr inbounds double, ptr %q, i64 10\n'
        '  %v32 = load double, ptr %v31\n'
        '  %v33 = getelementptr inbounds double, ptr %q, i64 11\n'
        '  %v34 = load double, ptr %v33\n'
        '  %v35 = getelementptr inbounds double, ptr %q, i64 12\n'
        '  %v36 = load double, ptr %v35\n'
        '  %v37 = getelementptr inbounds double, ptr %q, i64 13\n'
        '  %v38 = load double, ptr %v37\n'
        '  %v39 = getelementptr inbounds double, ptr %q, i64 14\n'
        '  %v40 = load double, ptr %v39\n'
        '  %v41 = getelementptr inbounds double, ptr %q, i64 15\n'
        '  %v42 = load double, ptr %v41\n'
        '  %v43 = getelementptr inbounds double, ptr %q, i64 16\n'
        '  %v44 = load double, ptr %v43\n'
        '  %v45 = getelementptr inbounds double, ptr %q, i64 17\n'
        '  %v46 = load double, ptr %v45\n'
        '  %v47 = getelementptr inbounds double, ptr %q, i64 18\n'
        '  %v48 = load double, ptr %v47\n'
        '  %v49 = getelementptr inbounds double, ptr %q, i64 19\n'
        '  %v50 = load double, ptr %v49\n'
        '  %v51 = getelementptr inbounds double, ptr %q, i64 20\n'
        '  %v52 = load double, ptr %v51\n'
        '  %v53 = getelementptr inbounds double, ptr %q, i64 21\n'
        '  %v54 = load double, ptr %v53\n'
        '  %v55 = getelementptr inbounds double, ptr %q, i64 22\n'
        '  %v56 = load double, ptr %v55\n'
        '  %v57 = getelementptr inbounds double, ptr %q, i64 23\n'
        '  %v58 = load double, ptr %v57\n'
        '  %v59 = getelementptr inbounds double, ptr %q, i64 24\n'
        '  %v60 = load double, ptr %v59\n'
        '  %v61 = getelementptr inbounds double, ptr %q, i64 25\n'
        '  %v62 = load double, ptr %v61\n'
        '  %v63 = getelementptr inbounds double, ptr %q, i64 26\n'
        '  %v64 = load double, ptr %v63\n'
        '  %v65 = getelementptr inbounds double, ptr %q, i64 27\n'
        '  %v66 = load double, ptr %v65\n'
        '  %v67 = getelementptr inbounds double, ptr %q, i64 28\n'
        '  %v68 = load double, ptr %v67\n'
        '  %v69 = getelementptr inbounds double, ptr %q, i64 29\n'
        '  %v70 = load double, ptr %v69\n'
        '  %v71 = getelementptr inbounds double, ptr %q, i64 30\n'
        '  %v72 = load double, ptr %v71\n'
        '  %v73 = getelementptr inbounds double, ptr %q, i64 31\n'
        '  %v74 = load double, ptr %v73\n'
        '  %v75 = getelementptr inbounds double, ptr %q, i64 32\n'
        '  %v76 = load double, ptr %v75\n'
        '  %v77 = getelementptr inbounds double, ptr %q, i64 33\n'
        '  %v78 = load double, ptr %v77\n'
        '  %v79 = getelementptr inbounds double, ptr %q, i64 34\n'
        '  %v80 = load double, ptr %v79\n'
        '  %v81 = fmul double %v2, %v4\n'
        '  %v82 = fmul double %v4, %v4\n'
        '  %v83 = fmul double %v2, %v2\n'
        '  %v84 = fmul double %v81, %v26\n'
        '  %v85 = fmul double %v82, %v22\n'
        '  %v86 = fadd double %v84, %v85\n'
        '  %v87 = fmul double %v83, %v24\n'
        '  %v88 = fadd double %v86, %v87\n'
        '  %v89 = fadd double %v88, %v28\n'
        '  %v90 = fdiv double 0x3FF0000000000000, %v89\n'
        '  %v91 = fmul double %v10, %v8\n'
        '  %v92 = fmul double %v10, %v6\n'
        '  %v93 = fmul double %v2, %v2\n'
        '  %v94 = fmul double %v93, %v2\n'
        '  %v95 = fmul double %v4, %v4\n'
        '  %v96 = fmul double %v95, %v4\n'
        '  %v97 = fmul double %v83, %v4\n'
        '  %v98 = fmul double %v82, %v2\n'
        '  %v99 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v6, ptr %v99\n'
        '  %v100 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v8, ptr %v100\n'
        '  %v101 = fmul double %v90, %v44\n'
        '  %v102 = fmul double %v91, %v42\n'
        '  %v103 = fmul double %v92, %v36\n'
        '  %v104 = fadd double %v102, %v103\n'
        '  %v105 = fmul double %v94, %v32\n'
        '  %v106 = fadd double %v104, %v105\n'
        '  %v107 = fmul double %v96, %v40\n'
        '  %v108 = fadd double %v106, %v107\n'
        '  %v109 = fmul double %v97, %v34\n'
        '  %v110 = fadd double %v108, %v109\n'
        '  %v111 = fmul double %v98, %v38\n'
        '  %v112 = fadd double %v110, %v111\n'
        '  %v113 = fmul double %v30, %v2\n'
        '  %v114 = fadd double %v112, %v113\n'
        '  %v115 = fmul double %v101, %v114\n'
        '  %v116 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v115, ptr %v116\n'
        '  %v117 = fmul double %v90, %v60\n'
        '  %v118 = fmul double %v91, %v54\n'
        '  %v119 = fmul double %v92, %v50\n'
        '  %v120 = fadd double %v118, %v119\n'
        '  %v121 = fmul double %v94, %v52\n'
        '  %v122 = fadd double %v120, %v121\n'
        '  %v123 = fmul double %v96, %v48\n'
        '  %v124 = fadd double %v122, %v123\n'
        '  %v125 = fmul double %v97, %v56\n'
        '  %v126 = fadd double %v124, %v125\n'
        '  %v127 = fmul double %v98, %v58\n'
        '  %v128 = fadd double %v126, %v127\n'
        '  %v129 = fmul double %v46, %v4\n'
        '  %v130 = fadd double %v128, %v129\n'
        '  %v131 = fmul double %v117, %v130\n'
        '  %v132 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v131, ptr %v132\n'
        '  %v133 = fmul double %v90, %v74\n'
        '  %v134 = fmul double %v81, %v62\n'
        '  %v135 = fmul double %v82, %v64\n'
        '  %v136 = fadd double %v134, %v135\n'
        '  %v137 = fmul double %v83, %v66\n'
        '  %v138 = fadd double %v136, %v137\n'
        '  %v139 = fmul double %v91, %v68\n'
        '  %v140 = fmul double %v139, %v4\n'
        '  %v141 = fadd double %v138, %v140\n'
        '  %v142 = fmul double %v91, %v72\n'
        '  %v143 = fmul double %v142, %v2\n'
        '  %v144 = fadd double %v141, %v143\n'
        '  %v145 = fmul double %v92, %v70\n'
        '  %v146 = fmul double %v145, %v2\n'
        '  %v147 = fadd double %v144, %v146\n'
        '  %v148 = fmul double %v92, %v72\n'
        '  %v149 = fmul double %v148, %v4\n'
        '  %v150 = fadd double %v147, %v149\n'
        '  %v151 = fmul double %v133, %v150\n'
        '  %v152 = getelementptr inbounds double, ptr %ds, i64 4\n'
        '  store double %v151, ptr %v152\n'
        '  ret i32 0\n'
        '}\n'
        '\n'
    ),
    'rhs_pose_q_into': (
        'define internal i32 @"rhs_pose_q_into"(ptr nocapture %ret, ptr nocapture %exc, double %t, ptr nocapture %s, ptr nocapture %q, i64 %nq, ptr nocapture %ds) {\n'
        'entry:\n'
        '  %v1 = getelementptr inbounds double, ptr %s, i64 0\n'
        '  %v2 = load double, ptr %v1\n'
        '  %v3 = getelementptr inbounds double, ptr %s, i64 1\n'
        '  %v4 = load double, ptr %v3\n'
        '  %v5 = getelementptr inbounds double, ptr %s, i64 2\n'
        '  %v6 = load double, ptr %v5\n'
        '  %v7 = getelementptr inbounds double, ptr %s, i64 3\n'
        '  %v8 = load double, ptr %v7\n'
        '  %v9 = getelementptr inbounds double, ptr %s, i64 4\n'
        '  %v10 = load double, ptr %v9\n'
        '  %v11 = getelementptr inbounds double, ptr %s, i64 5\n'
        '  %v12 = load double, ptr %v11\n'
        '  %v13 = getelementptr inbounds double, ptr %s, i64 6\n'
        '  %v14 = load double, ptr %v13\n'
        '  %v15 = getelementptr inbounds double, ptr %s, i64 7\n'
        '  %v16 = load double, ptr %v15\n'
        '  %v17 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  %v18 = load double, ptr %v17\n'
        '  %v19 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  %v20 = load double, ptr %v19\n'
        '  %v21 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  %v22 = load double, ptr %v21\n'
        '  %v23 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  %v24 = load double, ptr %v23\n'
        '  %v25 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  %v26 = load double, ptr %v25\n'
        '  %v27 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  %v28 = load double, ptr %v27\n'
        '  %v29 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  %v30 = load double, ptr %v29\n'
        '  %v31 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  %v32 = load double, ptr %v31\n'
        '  %v33 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  %v34 = load double, ptr %v33\n'
        '  %v35 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  %v36 = load double, ptr %v35\n'
        '  %v37 = getelementptr inbounds double, ptr %q, i64 10\n'
        '  %v38 = load double, ptr %v37\n'
        '  %v39 = getelementptr inbounds double, ptr %q, i64 11\n'
        '  %v40 = load double, ptr %v39\n'
        '  %v41 = getelementptr inbounds double, ptr %q, i64 12\n'
        '  %v42 = load double, ptr %v41\n'
        '  %v43 = getelementptr inbounds double, ptr %q, i64 13\n'
        '  %v44 = load double, ptr %v43\n'
        '  %v45 = getelementptr inbounds double, ptr %q, i64 14\n'
        '  %v46 = load double, ptr %v45\n'
        '  %v47 = getelementptr inbounds double, ptr %q, i64 15\n'
        '  %v48 = load double, ptr %v47\n'
        '  %v49 = getelementptr inbounds double, ptr %q, i64 16\n'
        '  %v50 = load double, ptr %v49\n'
        '  %v51 = getelementptr inbounds double, ptr %q, i64 17\n'
        '  %v52 = load double, ptr %v51\n'
        '  %v53 = getelementptr inbounds double, ptr %q, i64 18\n'
        '  %v54 = load double, ptr %v53\n'
        '  %v55 = getelementptr inbounds double, ptr %q, i64 19\n'
        '  %v56 = load double, ptr %v55\n'
        '  %v57 = getelementptr inbounds double, ptr %q, i64 20\n'
        '  %v58 = load double, ptr %v57\n'
        '  %v59 = getelementptr inbounds double, ptr %q, i64 21\n'
        '  %v60 = load double, ptr %v59\n'
        '  %v61 = getelementptr inbounds double, ptr %q, i64 22\n'
        '  %v62 = load double, ptr %v61\n'
        '  %v63 = getelementptr inbounds double, ptr %q, i64 23\n'
        '  %v64 = load double, ptr %v63\n'
        '  %v65 = getelementptr inbounds double, ptr %q, i64 24\n'
        '  %v66 = load double, ptr %v65\n'
        '  %v67 = getelementptr inbounds double, ptr %q, i64 25\n'
        '  %v68 = load double, ptr %v67\n'
        '  %v69 = getelementptr inbounds double, ptr %q, i64 26\n'
        '  %v70 = load double, ptr %v69\n'
        '  %v71 = getelementptr inbounds double, ptr %q, i64 27\n'
        '  %v72 = load double, ptr %v71\n'
        '  %v73 = getelementptr inbounds double, ptr %q, i64 28\n'
        '  %v74 = load double, ptr %v73\n'
        '  %v75 = getelementptr inbounds double, ptr %q, i64 29\n'
        '  %v76 = load double, ptr %v75\n'
        '  %v77 = getelementptr inbounds double, ptr %q, i64 30\n'
        '  %v78 = load double, ptr %v77\n'
        '  %v79 = getelementptr inbounds double, ptr %q, i64 31\n'
        '  %v80 = load double, ptr %v79\n'
        '  %v81 = getelementptr inbounds double, ptr %q, i64 32\n'
        '  %v82 = load double, ptr %v81\n'
        '  %v83 = getelementptr inbounds double, ptr %q, i64 33\n'
        '  %v84 = load double, ptr %v83\n'
        '  %v85 = getelementptr inbounds double, ptr %q, i64 34\n'
        '  %v86 = load double, ptr %v85\n'
        '  %v87 = fmul double %v2, %v4\n'
        '  %v88 = fmul double %v4, %v4\n'
        '  %v89 = fmul double %v2, %v2\n'
        '  %v90 = fmul double %v87, %v32\n'
        '  %v91 = fmul double %v88, %v28\n'
        '  %v92 = fadd double %v90, %v91\n'
        '  %v93 = fmul double %v89, %v30\n'
        '  %v94 = fadd double %v92, %v93\n'
        '  %v95 = fadd double %v94, %v34\n'
        '  %v96 = fdiv double 0x3FF0000000000000, %v95\n'
        '  %v97 = fmul double %v10, %v8\n'
        '  %v98 = fmul double %v10, %v6\n'
        '  %v99 = fmul double %v2, %v2\n'
        '  %v100 = fmul double %v99, %v2\n'
        '  %v101 = fmul double %v4, %v4\n'
        '  %v102 = fmul double %v101, %v4\n'
        '  %v103 = fmul double %v89, %v4\n'
        '  %v104 = fmul double %v88, %v2\n'
        '  %v105 = fadd double %v26, %v12\n'
        '  %v106 = fmul double %v82, %v4\n'
        '  %v107 = fmul double %v84, %v2\n'
        '  %v108 = fadd double %v106, %v107\n'
        '  %v109 = fmul double %v10, %v108\n'
        '  %v110 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v6, ptr %v110\n'
        '  %v111 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v8, ptr %v111\n'
        '  %v112 = fmul double %v96, %v50\n'
        '  %v113 = fmul double %v97, %v48\n'
        '  %v114 = fmul double %v98, %v42\n'
        '  %v115 = fadd double %v113, %v114\n'
        '  %v116 = fmul double %v100, %v38\n'
        '  %v117 = fadd double %v115, %v116\n'
        '  %v118 = fmul double %v102, %v46\n'
        '  %v119 = fadd double %v117, %v118\n'
        '  %v120 = fmul double %v103, %v40\n'
        '  %v121 = fadd double %v119, %v120\n'
        '  %v122 = fmul double %v104, %v44\n'
        '  %v123 = fadd double %v121, %v122\n'
        '  %v124 = fmul double %v36, %v2\n'
        '  %v125 = fadd double %v123, %v124\n'
        '  %v126 = fmul double %v112, %v125\n'
        '  %v127 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v126, ptr %v127\n'
        '  %v128 = fmul double %v96, %v66\n'
        '  %v129 = fmul double %v97, %v60\n'
        '  %v130 = fmul double %v98, %v56\n'
        '  %v131 = fadd double %v129, %v130\n'
        '  %v132 = fmul double %v100, %v58\n'
        '  %v133 = fadd double %v131, %v132\n'
        '  %v134 = fmul double %v102, %v54\n'
        '  %v135 = fadd double %v133, %v134\n'
        '  %v136 = fmul double %v103, %v62\n'
        '  %v137 = fadd double %v135, %v136\n'
        '  %v138 = fmul double %v104, %v64\n'
        '  %v139 = fadd double %v137, %v138\n'
        '  %v140 = fmul double %v52, %v4\n'
        '  %v141 = fadd double %v139, %v140\n'
        '  %v142 = fmul double %v128, %v141\n'
        '  %v143 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v142, ptr %v143\n'
        '  %v144 = fmul double %v96, %v80\n'
        '  %v145 = fmul double %v87, %v68\n'
        '  %v146 = fmul double %v88, %v70\n'
        '  %v147 = fadd double %v145, %v146\n'
        '  %v148 = fmul double %v89, %v72\n'
        '  %v149 = fadd double %v147, %v148\n'
        '  %v150 = fmul double %v97, %v74\n'
        '  %v151 = fmul double %v150, %v4\n'
        '  %v152 = fadd double %v149, %v151\n'
        '  %v153 = fmul double %v97, %v78\n'
        '  %v154 = fmul double %v153, %v2\n'
        '  %v155 = fadd double %v152, %v154\n'
        '  %v156 = fmul double %v98, %v76\n'
        '  %v157 = fmul double %v156, %v2\n'
        '  %v158 = fadd double %v155, %v157\n'
        '  %v159 = fmul double %v98, %v78\n'
        '  %v160 = fmul double %v159, %v4\n'
        '  %v161 = fadd double %v158, %v160\n'
        '  %v162 = fmul double %v144, %v161\n'
        '  %v163 = getelementptr inbounds double, ptr %ds, i64 4\n'
        '  store double %v162, ptr %v163\n'
        '  %v164 = getelementptr inbounds double, ptr %ds, i64 5\n'
        '  store double %v10, ptr %v164\n'
        '  %v165 = fmul double %v24, %v109\n'
        '  %v166 = call double @llvm.sin.f64(double %v105)\n'
        '  %v167 = fmul double %v165, %v166\n'
        '  %v168 = getelementptr inbounds double, ptr %ds, i64 6\n'
        '  store double %v167, ptr %v168\n'
        '  %v169 = fmul double %v109, %v86\n'
        '  %v170 = call double @llvm.cos.f64(double %v105)\n'
        '  %v171 = fmul double %v169, %v170\n'
        '  %v172 = getelementptr inbounds double, ptr %ds, i64 7\n'
        '  store double %v171, ptr %v172\n'
        '  ret i32 0\n'
        '}\n'
        'declare double @llvm.cos.f64(double)\n'
        'declare double @llvm.sin.f64(double)\n'
    ),
    'constants': (
        'define internal void @"constants"(ptr nocapture readonly %p, ptr nocapture %q) {\n'
        'entry:\n'
        '  %v1 = getelementptr inbounds double, ptr %p, i64 0\n'
        '  %v2 = load double, ptr %v1\n'
        '  %v3 = getelementptr inbounds double, ptr %p, i64 1\n'
        '  %v4 = load double, ptr %v3\n'
        '  %v5 = getelementptr inbounds double, ptr %p, i64 2\n'
        '  %v6 = load double, ptr %v5\n'
        '  %v7 = getelementptr inbounds double, ptr %p, i64 3\n'
        '  %v8 = load double, ptr %v7\n'
        '  %v9 = getelementptr inbounds double, ptr %p, i64 4\n'
        '  %v10 = load double, ptr %v9\n'
        '  %v11 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  store double %v2, ptr %v11\n'
        '  %v12 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  store double %v4, ptr %v12\n'
        '  %v13 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  store double %v6, ptr %v13\n'
        '  %v14 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  store double %v8, ptr %v14\n'
        '  %v15 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  store double %v10, ptr %v15\n'
        '  %v16 = fmul double %v8, %v8\n'
        '  %v17 = fmul double 0x4010000000000000, %v10\n'
        '  %v18 = call double @llvm.cos.f64(double %v17)\n'
        '  %v19 = fsub double %v18, 0x3FF0000000000000\n'
        '  %v20 = fmul double %v16, %v19\n'
        '  %v21 = call double @llvm.sin.f64(double %v10)\n'
        '  %v22 = fmul double %v21, %v21\n'
        '  %v23 = fmul double %v22, %v21\n'
        '  %v24 = fmul double %v23, %v21\n'
        '  %v25 = fmul double 0x4020000000000000, %v16\n'
        '  %v26 = call double @llvm.cos.f64(double %v10)\n'
        '  %v27 = fmul double %v21, %v21\n'
        '  %v28 = fmul double %v27, %v21\n'
        '  %v29 = fmul double %v28, %v26\n'
        '  %v30 = fmul double %v6, %v6\n'
        '  %v31 = fmul double 0x4020000000000000, %v30\n'
        '  %v32 = fmul double %v4, %v4\n'
        '  %v33 = fmul double 0x4000000000000000, %v30\n'
        '  %v34 = fadd double %v32, %v30\n'
        '  %v35 = fmul double %v34, %v2\n'
        '  %v36 = fmul double %v26, %v26\n'
        '  %v37 = fmul double %v32, %v36\n'
        '  %v38 = fmul double %v21, %v21\n'
        '  %v39 = fmul double %v38, %v2\n'
        '  %v40 = fmul double 0x4000000000000000, %v16\n'
        '  %v41 = fneg double %v32\n'
        '  %v42 = fmul double 0x4008000000000000, %v37\n'
        '  %v43 = fmul double 0x4000000000000000, %v10\n'
        '  %v44 = call double @llvm.sin.f64(double %v43)\n'
        '  %v45 = fmul double %v44, %v2\n'
        '  %v46 = fmul double %v16, %v45\n'
        '  %v47 = fmul double %v8, %v30\n'
        '  %v48 = fmul double %v44, %v47\n'
        '  %v49 = fmul double 0x4000000000000000, %v32\n'
        '  %v50 = fdiv double 0x3FF0000000000000, %v30\n'
        '  %v51 = fmul double %v8, %v31\n'
        '  %v52 = fneg double %v20\n'
        '  %v53 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  store double %v52, ptr %v53\n'
        '  %v54 = fmul double %v24, %v25\n'
        '  %v55 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  store double %v54, ptr %v55\n'
        '  %v56 = fmul double 0xC030000000000000, %v16\n'
        '  %v57 = fmul double %v56, %v29\n'
        '  %v58 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  store double %v57, ptr %v58\n'
        '  %v59 = fmul double 0x4020000000000000, %v32\n'
        '  %v60 = fadd double %v59, %v31\n'
        '  %v61 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  store double %v60, ptr %v61\n'
        '  %v62 = fneg double %v33\n'
        '  %v63 = fmul double %v62, %v35\n'
        '  %v64 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  store double %v63, ptr %v64\n'
        '  %v65 = fneg double %v39\n'
        '  %v66 = fmul double %v65, %v40\n'
        '  %v67 = fadd double %v37, %v30\n'
        '  %v68 = fmul double %v66, %v67\n'
        '  %v69 = getelementptr inbounds double, ptr %q, i64 10\n'
        '  store double %v68, ptr %v69\n'
        '  %v70 = fadd double %v33, %v41\n'
        '  %v71 = fadd double %v70, %v42\n'
        '  %v72 = fmul double %v46, %v71\n'
        '  %v73 = getelementptr inbounds double, ptr %q, i64 11\n'
        '  store double %v72, ptr %v73\n'
        '  %v74 = fneg double %v34\n'
        '  %v75 = fmul double %v74, %v48\n'
        '  %v76 = getelementptr inbounds double, ptr %q, i64 12\n'
        '  store double %v75, ptr %v76\n'
        '  %v77 = fneg double %v36\n'
        '  %v78 = fmul double %v77, %v40\n'
        '  %v79 = fmul double %v78, %v2\n'
        '  %v80 = fsub double %v42, %v49\n'
        '  %v81 = fadd double %v80, %v30\n'
        '  %v82 = fmul double %v79, %v81\n'
        '  %v83 = getelementptr inbounds double, ptr %q, i64 13\n'
        '  store double %v82, ptr %v83\n'
        '  %v84 = fneg double %v16\n'
        '  %v85 = fmul double %v84, %v49\n'
        '  %v86 = fmul double %v85, %v21\n'
        '  %v87 = fmul double %v26, %v26\n'
        '  %v88 = fmul double %v87, %v26\n'
        '  %v89 = fmul double %v86, %v88\n'
        '  %v90 = fmul double %v89, %v2\n'
        '  %v91 = getelementptr inbounds double, ptr %q, i64 14\n'
        '  store double %v90, ptr %v91\n'
        '  %v92 = fmul double %v8, %v33\n'
        '  %v93 = fmul double %v92, %v34\n'
        '  %v94 = fmul double %v93, %v36\n'
        '  %v95 = getelementptr inbounds double, ptr %q, i64 15\n'
        '  store double %v94, ptr %v95\n'
        '  %v96 = fmul double 0x4010000000000000, %v50\n'
        '  %v97 = fdiv double %v96, %v4\n'
        '  %v98 = getelementptr inbounds double, ptr %q, i64 16\n'
        '  store double %v97, ptr %v98\n'
        '  %v99 = fneg double %v31\n'
        '  %v100 = fmul double %v99, %v2\n'
        '  %v101 = getelementptr inbounds double, ptr %q, i64 17\n'
        '  store double %v100, ptr %v101\n'
        '  %v102 = fmul double %v20, %v2\n'
        '  %v103 = getelementptr inbounds double, ptr %q, i64 18\n'
        '  store double %v102, ptr %v103\n'
        '  %v104 = fneg double %v38\n'
        '  %v105 = fmul double %v104, %v51\n'
        '  %v106 = getelementptr inbounds double, ptr %q, i64 19\n'
        '  store double %v105, ptr %v106\n'
        '  %v107 = fneg double %v25\n'
        '  %v108 = fmul double %v107, %v29\n'
        '  %v109 = fmul double %v108, %v2\n'
        '  %v110 = getelementptr inbounds double, ptr %q, i64 20\n'
        '  store double %v109, ptr %v110\n'
        '  %v111 = fmul double 0x4010000000000000, %v48\n'
        '  %v112 = getelementptr inbounds double, ptr %q, i64 21\n'
        '  store double %v111, ptr %v112\n'
        '  %v113 = fneg double %v39\n'
        '  %v114 = fmul double %v113, %v25\n'
        '  %v115 = fmul double 0x4008000000000000, %v38\n'
        '  %v116 = fsub double %v115, 0x4000000000000000\n'
        '  %v117 = fmul double %v114, %v116\n'
        '  %v118 = getelementptr inbounds double, ptr %q, i64 22\n'
        '  store double %v117, ptr %v118\n'
        '  %v119 = fmul double 0xC010000000000000, %v46\n'
        '  %v120 = fmul double 0x4008000000000000, %v36\n'
        '  %v121 = fsub double %v120, 0x4000000000000000\n'
        '  %v122 = fmul double %v119, %v121\n'
        '  %v123 = getelementptr inbounds double, ptr %q, i64 23\n'
        '  store double %v122, ptr %v123\n'
        '  %v124 = fmul double %v50, %v4\n'
        '  %v125 = getelementptr inbounds double, ptr %q, i64 24\n'
        '  store double %v124, ptr %v125\n'
        '  %v126 = fmul double 0xC020000000000000, %v2\n'
        '  %v127 = fmul double %v36, %v30\n'
        '  %v128 = fmul double 0x4000000000000000, %v37\n'
        '  %v129 = fadd double %v127, %v128\n'
        '  %v130 = fadd double %v129, %v41\n'
        '  %v131 = fmul double %v126, %v130\n'
        '  %v132 = getelementptr inbounds double, ptr %q, i64 25\n'
        '  store double %v131, ptr %v132\n'
        '  %v133 = fmul double 0xC010000000000000, %v32\n'
        '  %v134 = fmul double %v133, %v45\n'
        '  %v135 = getelementptr inbounds double, ptr %q, i64 26\n'
        '  store double %v134, ptr %v135\n'
        '  %v136 = fmul double 0x4010000000000000, %v35\n'
        '  %v137 = fmul double %v136, %v44\n'
        '  %v138 = getelementptr inbounds double, ptr %q, i64 27\n'
        '  store double %v137, ptr %v138\n'
        '  %v139 = fmul double %v19, %v47\n'
        '  %v140 = getelementptr inbounds double, ptr %q, i64 28\n'
        '  store double %v139, ptr %v140\n'
        '  %v141 = fneg double %v51\n'
        '  %v142 = fmul double %v141, %v24\n'
        '  %v143 = getelementptr inbounds double, ptr %q, i64 29\n'
        '  store double %v142, ptr %v143\n'
        '  %v144 = fmul double %v51, %v29\n'
        '  %v145 = getelementptr inbounds double, ptr %q, i64 30\n'
        '  store double %v144, ptr %v145\n'
        '  %v146 = fmul double %v8, %v50\n'
        '  %v147 = getelementptr inbounds double, ptr %q, i64 31\n'
        '  store double %v146, ptr %v147\n'
        '  %v148 = getelementptr inbounds double, ptr %q, i64 32\n'
        '  store double %v26, ptr %v148\n'
        '  %v149 = fneg double %v21\n'
        '  %v150 = getelementptr inbounds double, ptr %q, i64 33\n'
        '  store double %v149, ptr %v150\n'
        '  %v151 = fneg double %v8\n'
        '  %v152 = getelementptr inbounds double, ptr %q, i64 34\n'
        '  store double %v151, ptr %v152\n'
        '  ret void\n'
        '}\n'
        'declare double @llvm.cos.f64(double)\n'
        'declare double @llvm.sin.f64(double)\n'
    ),
}
#: how many parameters the IR of ``constants`` reads
LLVM_IR_READS = 5
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '1a27c4e947e238c7612f9797f24a002e9bf6b0be5500ccb20994c038f6240c98'
