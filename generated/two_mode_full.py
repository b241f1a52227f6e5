"""two_mode, fidelity full: exact consequences of the model's Lagrangian and constraints, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from derivation/models.py (model 'two_mode',
constraints Const22, Const23) through derivation/engine.py.
Accelerations and multipliers in closed form (symbolic elimination of the multipliers).
SymPy 1.14.0; input hash sha256:eb95511228026750b53dc310e44b768f23868ef446ef08d841cb8ee68cb6f393

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
INPUT_HASH = 'eb95511228026750b53dc310e44b768f23868ef446ef08d841cb8ee68cb6f393'
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


#: operation counts of the Jacobians (derivation/jacobian.py)
OP_COUNTS.update(jacobian=549, jacobian_p=1260)

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
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '734da675d48ca8b5fde9e7effe38f869d255192de46a1e8e6b9a23311b8742cd'
