"""two_mode, fidelity reduced: degree-2 Taylor polynomial of the full vector field in the tilts and tilt rates (tilt equations to O(theta), spin equation to O(theta^2)).

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from derivation/models.py (model 'two_mode',
constraints Const22, Const23) through derivation/engine.py and derivation/truncation.py.
Accelerations and multipliers in closed form (symbolic elimination of the multipliers).
SymPy 1.14.0; input hash sha256:f7374d753b8c57fe8fe6f9f65bf38f36b508a3823eeec6143b4eaeab7462f235

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
FIDELITY = 'reduced'
#: what this fidelity is
FIDELITY_DOC = 'degree-2 Taylor polynomial of the full vector field in the tilts and tilt rates (tilt equations to O(theta), spin equation to O(theta^2))'
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
VALIDITY = {'theta1': 0.6, 'theta2': 0.6}
VALIDITY_DOC = "small tilts: up to this bound the first spin reversal of the small-angle fidelities is within 0.1% of the full model's; the amplitude fidelity also needs the spin rate small against the tilt frequencies"
MULTIPLIER_NAMES = ('Const22', 'Const23')
#: non-conservative forces: the module has ``power_dissipated(s, p)``
HAS_DISSIPATION = False
#: model-specific helpers defined at the end of this module
EXPORTS = ()
INPUT_HASH = 'f7374d753b8c57fe8fe6f9f65bf38f36b508a3823eeec6143b4eaeab7462f235'
SYMPY_VERSION = '1.14.0'
#: how the multipliers are eliminated: "symbolic" (closed form) or "numeric" (a linear solve at every call)
ELIMINATION = 'symbolic'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 80, 'constants': 52, 'rhs_q': 35, 'rhs_pose': 91, 'rhs_pose_q': 46, 'pose_rates': 13, 'energy': 58, 'multipliers': 56, 'frequencies': 12}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (80 operations)."""
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
    _c0 = 2*g
    _c1 = math.sin(2*alpha)
    _c2 = D*phi_dot
    _c3 = math.cos(alpha)
    _c4 = (_c3*_c3)
    _c5 = (L*L)
    _c6 = (ell*ell)
    _c7 = _c5 + _c6
    _c8 = 1/_c7
    _c9 = math.sin(alpha)
    _c10 = _c2*theta1_dot
    _c11 = 4*_c1*g
    _c12 = 8*theta1
    _c13 = _c10*_c5
    _c14 = _c2*_c5*theta2_dot
    _c15 = _c3*(_c9*_c9*_c9)
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = ((1.0/2.0))*(2*D*_c4*phi_dot*theta2_dot - _c0*theta1 - _c1*_c2*theta1_dot)/ell
    ds[3] = ((1.0/2.0))*_c8*ell*(D*_c1*phi_dot*theta2_dot - _c0*theta2 - 2*_c10*(_c9*_c9))
    ds[4] = ((1.0/8.0))*D*_c8*(-_c11*_c6*(theta2*theta2) + _c11*_c7*(theta1*theta1) - _c12*_c13*(_c9*_c9*_c9*_c9) + _c12*_c14*_c15 - _c12*g*theta2*(_c4*_c5 + 2*_c4*_c6 - _c6) + 8*_c13*_c15*theta2 + _c14*theta2*(math.cos(4*alpha) - 1))/_c5


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 5."""
    ds = np.empty(5)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 17 parameter-only subexpressions of the right-hand side (52 operations)."""
    q = np.empty(22)
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
    _c0 = math.sin(2*alpha)
    _c1 = D*_c0
    _c2 = math.cos(alpha)
    _c3 = (_c2*_c2)
    _c4 = 2*D
    _c5 = math.sin(alpha)
    _c6 = (L*L)
    _c7 = (ell*ell)
    _c8 = _c6 + _c7
    _c9 = 1/_c8
    _c10 = 4*_c0*g
    _c11 = D*_c6
    _c12 = 8*_c11
    q[5] = -2*g
    q[6] = -_c1
    q[7] = _c3*_c4
    q[8] = ((1.0/2.0))/ell
    q[9] = _c1
    q[10] = -_c4*(_c5*_c5)
    q[11] = ((1.0/2.0))*_c9*ell
    q[12] = -8*g*(_c3*_c6 + 2*_c3*_c7 - _c7)
    q[13] = -_c10*_c7
    q[14] = _c10*_c8
    q[15] = _c11*(math.cos(4*alpha) - 1)
    q[16] = -_c12*(_c5*_c5*_c5*_c5)
    q[17] = _c12*_c2*(_c5*_c5*_c5)
    q[18] = ((1.0/8.0))*D*_c9/_c6
    q[19] = _c2
    q[20] = -_c5
    q[21] = -D
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (35 operations)."""
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
    _c0 = phi_dot*theta1_dot
    _c1 = phi_dot*theta2_dot
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = _k3*(_c0*_k1 + _c1*_k2 + _k0*theta1)
    ds[3] = _k6*(_c0*_k5 + _c1*_k4 + _k0*theta2)
    ds[4] = _k13*(_c0*_k11*theta1 + _c0*_k12*theta2 + _c1*_k10*theta2 + _c1*_k12*theta1 + _k7*theta1*theta2 + _k8*(theta2*theta2) + _k9*(theta1*theta1))


@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds`` (91 operations)."""
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
    _c0 = 2*g
    _c1 = math.sin(2*alpha)
    _c2 = D*phi_dot
    _c3 = math.cos(alpha)
    _c4 = (_c3*_c3)
    _c5 = (L*L)
    _c6 = (ell*ell)
    _c7 = _c5 + _c6
    _c8 = 1/_c7
    _c9 = math.sin(alpha)
    _c10 = _c2*theta1_dot
    _c11 = 4*_c1*g
    _c12 = 8*theta1
    _c13 = _c10*_c5
    _c14 = _c2*_c5*theta2_dot
    _c15 = (_c9*_c9*_c9)
    _c16 = alpha + phi
    _c17 = _c2*(_c3*theta2 - _c9*theta1)
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = ((1.0/2.0))*(2*D*_c4*phi_dot*theta2_dot - _c0*theta1 - _c1*_c2*theta1_dot)/ell
    ds[3] = ((1.0/2.0))*_c8*ell*(D*_c1*phi_dot*theta2_dot - _c0*theta2 - 2*_c10*(_c9*_c9))
    ds[4] = ((1.0/8.0))*D*_c8*(-_c11*_c6*(theta2*theta2) + _c11*_c7*(theta1*theta1) - _c12*_c13*(_c9*_c9*_c9*_c9) + _c12*_c14*_c15*_c3 - _c12*g*theta2*(_c4*_c5 + 2*_c4*_c6 - _c6) + 8*_c13*_c15*_c3*theta2 + _c14*theta2*(math.cos(4*alpha) - 1))/_c5
    ds[5] = phi_dot
    ds[6] = _c17*math.sin(_c16)
    ds[7] = -_c17*math.cos(_c16)


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length 8."""
    ds = np.empty(8)
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p`` (46 operations)."""
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
    _c0 = phi_dot*theta1_dot
    _c1 = phi_dot*theta2_dot
    _c2 = alpha + phi
    _c3 = phi_dot*(_k14*theta2 + _k15*theta1)
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = _k3*(_c0*_k1 + _c1*_k2 + _k0*theta1)
    ds[3] = _k6*(_c0*_k5 + _c1*_k4 + _k0*theta2)
    ds[4] = _k13*(_c0*_k11*theta1 + _c0*_k12*theta2 + _c1*_k10*theta2 + _c1*_k12*theta1 + _k7*theta1*theta2 + _k8*(theta2*theta2) + _k9*(theta1*theta1))
    ds[5] = phi_dot
    ds[6] = D*_c3*math.sin(_c2)
    ds[7] = _c3*_k16*math.cos(_c2)


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
    """Lagrange multipliers (contact forces per unit mass) Const22, Const23 (56 operations)."""
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
    _c2 = _c0 + _c1
    _c3 = 1/_c2
    _c4 = math.cos(alpha)
    _c5 = _c2*theta1
    _c6 = math.sin(alpha)
    _c7 = _c6*g
    _c8 = (phi_dot*phi_dot)
    _c9 = _c0*ell + (ell*ell*ell)
    _c10 = D*_c0*(_c6*_c6) + _c9
    _c11 = _c4*phi_dot
    out[0] = _c3*(D*_c2*_c4*_c8*theta2 - D*_c5*_c6*_c8 + _c1*_c4*g*theta2 - _c10*_c11*theta1_dot - _c5*_c7 + _c6*phi_dot*theta2_dot*(D*_c0*(_c4*_c4) - _c9))
    out[1] = _c3*(-_c1*_c7*theta2 - _c10*_c11*theta2_dot + _c10*_c6*phi_dot*theta1_dot - _c4*_c5*g)
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
OP_COUNTS.update(jacobian=156, jacobian_p=453, jvp_once=148, jvp_column=34)

@njit(cache=True)
def jacobian(s, p):
    """d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape (5, 5) (156 operations)."""
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
    _c0 = 2*g
    _c1 = math.sin(2*alpha)
    _c2 = D*phi_dot
    _c3 = math.cos(alpha)
    _c4 = (_c3*_c3)
    _c5 = (L*L)
    _c6 = (ell*ell)
    _c7 = _c5 + _c6
    _c8 = 1/_c7
    _c9 = math.sin(alpha)
    _c10 = _c2*theta1_dot
    _d10_4 = D*theta1_dot
    _c11 = 4*_c1*g
    _c12 = 8*theta1
    _c13 = _c10*_c5
    _d13_2 = _c2*_c5
    _d13_4 = _c5*_d10_4
    _c14 = _c2*_c5*theta2_dot
    _d14_3 = _c2*_c5
    _d14_4 = D*_c5*theta2_dot
    _c15 = _c3*(_c9*_c9*_c9)
    out[0, 2] = 1
    out[1, 3] = 1
    out[2, 0] = -(1.0/2.0)*_c0/ell
    out[2, 2] = -(1.0/2.0)*_c1*_c2/ell
    out[2, 3] = D*_c4*phi_dot/ell
    out[2, 4] = -(1.0/2.0)*D*_c1*theta1_dot/ell + D*_c4*theta2_dot/ell
    out[3, 1] = -(1.0/2.0)*_c0*_c8*ell
    out[3, 2] = -_c2*_c8*(_c9*_c9)*ell
    out[3, 3] = ((1.0/2.0))*D*_c1*_c8*ell*phi_dot
    out[3, 4] = ((1.0/2.0))*D*_c1*_c8*ell*theta2_dot - _c8*(_c9*_c9)*_d10_4*ell
    out[4, 0] = ((1.0/4.0))*D*_c11*_c7*_c8*theta1/_c5 + D*_c8*(-_c13*(_c9*_c9*_c9*_c9) + _c14*_c15 - g*theta2*(_c4*_c5 + 2*_c4*_c6 - _c6))/_c5
    out[4, 1] = ((1.0/8.0))*D*_c8*(-2*_c11*_c6*theta2 - _c12*g*(_c4*_c5 + 2*_c4*_c6 - _c6) + 8*_c13*_c15 + _c14*(math.cos(4*alpha) - 1))/_c5
    out[4, 2] = ((1.0/8.0))*D*_c8*_d13_2*(-_c12*(_c9*_c9*_c9*_c9) + 8*_c15*theta2)/_c5
    out[4, 3] = ((1.0/8.0))*D*_c8*_d14_3*(_c12*_c15 + theta2*(math.cos(4*alpha) - 1))/_c5
    out[4, 4] = ((1.0/8.0))*D*_c8*_d13_4*(-_c12*(_c9*_c9*_c9*_c9) + 8*_c15*theta2)/_c5 + ((1.0/8.0))*D*_c8*_d14_4*(_c12*_c15 + theta2*(math.cos(4*alpha) - 1))/_c5
    return out


@njit(cache=True)
def jacobian_p(s, p):
    """d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape (5, 5) (453 operations)."""
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
    _c0 = 2*g
    _c1 = math.sin(2*alpha)
    _d1_4 = 2*math.cos(2*alpha)
    _c2 = D*phi_dot
    _c3 = math.cos(alpha)
    _d3_4 = -math.sin(alpha)
    _c4 = (_c3*_c3)
    _d4_4 = 2*_c3*_d3_4
    _c5 = (L*L)
    _d5_2 = 2*L
    _c6 = (ell*ell)
    _d6_1 = 2*ell
    _c7 = _c5 + _c6
    _c8 = 1/_c7
    _d8_1 = -_d6_1/(_c7*_c7)
    _d8_2 = -_d5_2/(_c7*_c7)
    _c9 = math.sin(alpha)
    _d9_4 = math.cos(alpha)
    _c10 = _c2*theta1_dot
    _d10_3 = phi_dot*theta1_dot
    _c11 = 4*_c1*g
    _d11_0 = 4*_c1
    _d11_4 = 4*_d1_4*g
    _c12 = 8*theta1
    _c13 = _c10*_c5
    _d13_2 = _c10*_d5_2
    _d13_3 = _c5*_d10_3
    _c14 = _c2*_c5*theta2_dot
    _d14_2 = _c2*_d5_2*theta2_dot
    _d14_3 = _c5*phi_dot*theta2_dot
    _c15 = _c3*(_c9*_c9*_c9)
    _d15_4 = 3*_c3*(_c9*_c9)*_d9_4 + (_c9*_c9*_c9)*_d3_4
    out[2, 0] = -theta1/ell
    out[2, 1] = -(1.0/2.0)*(2*D*_c4*phi_dot*theta2_dot - _c0*theta1 - _c1*_c2*theta1_dot)/(ell*ell)
    out[2, 3] = -(1.0/2.0)*_c1*phi_dot*theta1_dot/ell + _c4*phi_dot*theta2_dot/ell
    out[2, 4] = D*_d4_4*phi_dot*theta2_dot/ell - (1.0/2.0)*_c2*_d1_4*theta1_dot/ell
    out[3, 0] = -_c8*ell*theta2
    out[3, 1] = ((1.0/2.0))*_c8*(D*_c1*phi_dot*theta2_dot - _c0*theta2 - 2*_c10*(_c9*_c9)) + ((1.0/2.0))*_d8_1*ell*(D*_c1*phi_dot*theta2_dot - _c0*theta2 - 2*_c10*(_c9*_c9))
    out[3, 2] = ((1.0/2.0))*_d8_2*ell*(D*_c1*phi_dot*theta2_dot - _c0*theta2 - 2*_c10*(_c9*_c9))
    out[3, 3] = ((1.0/2.0))*_c1*_c8*ell*phi_dot*theta2_dot - _c8*(_c9*_c9)*_d10_3*ell
    out[3, 4] = ((1.0/2.0))*D*_c8*_d1_4*ell*phi_dot*theta2_dot - 2*_c10*_c8*_c9*_d9_4*ell
    out[4, 0] = -(1.0/8.0)*D*_c12*_c8*theta2*(_c4*_c5 + 2*_c4*_c6 - _c6)/_c5 + ((1.0/8.0))*D*_c8*_d11_0*(-_c6*(theta2*theta2) + _c7*(theta1*theta1))/_c5
    out[4, 1] = ((1.0/8.0))*D*_c11*_c8*_d6_1*(theta1*theta1)/_c5 + ((1.0/8.0))*D*_c8*_d6_1*(-_c11*(theta2*theta2) - _c12*g*theta2*(2*_c4 - 1))/_c5 + ((1.0/8.0))*D*_d8_1*(-_c11*_c6*(theta2*theta2) + _c11*_c7*(theta1*theta1) - _c12*_c13*(_c9*_c9*_c9*_c9) + _c12*_c14*_c15 - _c12*g*theta2*(_c4*_c5 + 2*_c4*_c6 - _c6) + 8*_c13*_c15*theta2 + _c14*theta2*(math.cos(4*alpha) - 1))/_c5
    out[4, 2] = ((1.0/8.0))*D*_c11*_c8*_d5_2*(theta1*theta1)/_c5 + ((1.0/8.0))*D*_c8*_d13_2*(-_c12*(_c9*_c9*_c9*_c9) + 8*_c15*theta2)/_c5 + ((1.0/8.0))*D*_c8*_d14_2*(_c12*_c15 + theta2*(math.cos(4*alpha) - 1))/_c5 + ((1.0/8.0))*D*_d8_2*(-_c11*_c6*(theta2*theta2) + _c11*_c7*(theta1*theta1) - _c12*_c13*(_c9*_c9*_c9*_c9) + _c12*_c14*_c15 - _c12*g*theta2*(_c4*_c5 + 2*_c4*_c6 - _c6) + 8*_c13*_c15*theta2 + _c14*theta2*(math.cos(4*alpha) - 1))/_c5 + _d5_2*(-(1.0/8.0)*D*_c12*_c4*_c8*g*theta2/_c5 - (1.0/8.0)*D*_c8*(-_c11*_c6*(theta2*theta2) + _c11*_c7*(theta1*theta1) - _c12*_c13*(_c9*_c9*_c9*_c9) + _c12*_c14*_c15 - _c12*g*theta2*(_c4*_c5 + 2*_c4*_c6 - _c6) + 8*_c13*_c15*theta2 + _c14*theta2*(math.cos(4*alpha) - 1))/(_c5*_c5))
    out[4, 3] = ((1.0/8.0))*D*_c8*_d13_3*(-_c12*(_c9*_c9*_c9*_c9) + 8*_c15*theta2)/_c5 + ((1.0/8.0))*D*_c8*_d14_3*(_c12*_c15 + theta2*(math.cos(4*alpha) - 1))/_c5 + ((1.0/8.0))*_c8*(-_c11*_c6*(theta2*theta2) + _c11*_c7*(theta1*theta1) - _c12*_c13*(_c9*_c9*_c9*_c9) + _c12*_c14*_c15 - _c12*g*theta2*(_c4*_c5 + 2*_c4*_c6 - _c6) + 8*_c13*_c15*theta2 + _c14*theta2*(math.cos(4*alpha) - 1))/_c5
    out[4, 4] = -(1.0/2.0)*D*_c12*_c13*_c8*(_c9*_c9*_c9)*_d9_4/_c5 - (1.0/8.0)*D*_c12*_c8*_d4_4*g*theta2*(_c5 + 2*_c6)/_c5 - (1.0/2.0)*D*_c14*_c8*theta2*math.sin(4*alpha)/_c5 + ((1.0/8.0))*D*_c8*_d11_4*(-_c6*(theta2*theta2) + _c7*(theta1*theta1))/_c5 + ((1.0/8.0))*D*_c8*_d15_4*(_c12*_c14 + 8*_c13*theta2)/_c5
    return out


@njit(cache=True)
def jvp_into(s, p, _V, ds, out):
    """Write d(state)/dt into ``ds`` and ``J(s) _V`` into ``out`` (``_V``, ``out``: (5, k)), the derivatives of the rates along the columns of ``_V`` by forward mode through the right-hand side (148 operations once, 34 per column)."""
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
    _c0 = 2*g
    _c1 = math.sin(2*alpha)
    _c2 = D*phi_dot
    _c3 = math.cos(alpha)
    _c4 = (_c3*_c3)
    _c5 = (L*L)
    _c6 = (ell*ell)
    _c7 = _c5 + _c6
    _c8 = 1/_c7
    _c9 = math.sin(alpha)
    _c10 = _c2*theta1_dot
    _c11 = 4*_c1*g
    _c12 = 8*theta1
    _c13 = _c10*_c5
    _c14 = _c2*_c5*theta2_dot
    _c15 = _c3*(_c9*_c9*_c9)
    _p0 = 1/ell
    _p1 = ((1.0/2.0))*_p0
    _p2 = _c1*_p1
    _p3 = D*phi_dot
    _p4 = _c4*_p0
    _p5 = D*theta2_dot
    _p6 = _c8*ell
    _p7 = ((1.0/2.0))*_p6
    _p8 = _c1*_p7
    _p9 = (_c9*_c9*_c9*_c9)
    _p10 = 2*_c6
    _p11 = g*(_c4*_c5 + _c4*_p10 - _c6)
    _p12 = D*_c8/_c5
    _p13 = ((1.0/8.0))*_p12
    _p14 = math.cos(4*alpha) - 1
    _k0 = _c2*_c5
    _k1 = _c5*theta2_dot
    _k2 = -_c0*_p1
    _k3 = -_c2*_p2
    _k4 = -_p2*theta1_dot
    _k5 = _p3*_p4
    _k6 = _p4*_p5
    _k7 = -(_c9*_c9)*_p6
    _k8 = -_c0*_p7
    _k9 = _p3*_p8
    _k10 = _p5*_p8
    _k11 = _p13*(-_c13*_p9 + _c14*_c15 - _p11*theta2)
    _k12 = _p13*(-_c12*_p9 + 8*_c15*theta2)
    _k13 = _p13*(_c12*_c15 + _p14*theta2)
    _k14 = _p13*(-_c11*_p10*theta2 - _c12*_p11 + 8*_c13*_c15 + _c14*_p14)
    _k15 = ((1.0/4.0))*_c11*_c7*_p12*theta1
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = ((1.0/2.0))*(2*D*_c4*phi_dot*theta2_dot - _c0*theta1 - _c1*_c2*theta1_dot)/ell
    ds[3] = ((1.0/2.0))*_c8*ell*(D*_c1*phi_dot*theta2_dot - _c0*theta2 - 2*_c10*(_c9*_c9))
    ds[4] = ((1.0/8.0))*D*_c8*(-_c11*_c6*(theta2*theta2) + _c11*_c7*(theta1*theta1) - _c12*_c13*(_c9*_c9*_c9*_c9) + _c12*_c14*_c15 - _c12*g*theta2*(_c4*_c5 + 2*_c4*_c6 - _c6) + 8*_c13*_c15*theta2 + _c14*theta2*(math.cos(4*alpha) - 1))/_c5
    for _j in range(_V.shape[1]):
        _v0 = _V[0, _j]
        _v1 = _V[1, _j]
        _v2 = _V[2, _j]
        _v3 = _V[3, _j]
        _v4 = _V[4, _j]
        _t2 = D*_v4
        _t10 = _c2*_v2 + _t2*theta1_dot
        _t12 = 8*_v0
        _t13 = _c5*_t10
        _t14 = _k0*_v3 + _k1*_t2
        out[0, _j] = _v2
        out[1, _j] = _v3
        out[2, _j] = _k2*_v0 + _k3*_v2 + _k4*_t2 + _k5*_v3 + _k6*_v4
        out[3, _j] = _k10*_v4 + _k7*_t10 + _k8*_v1 + _k9*_v3
        out[4, _j] = _k11*_t12 + _k12*_t13 + _k13*_t14 + _k14*_v1 + _k15*_v0


@njit(cache=True)
def jvp1_into(s, p, _v, ds, _dv):
    """``jvp_into`` of one column: d(state)/dt into ``ds`` and ``J(s) _v`` into ``_dv`` (vectors of length 5; 182 operations)."""
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
    _c0 = 2*g
    _c1 = math.sin(2*alpha)
    _c2 = D*phi_dot
    _c3 = math.cos(alpha)
    _c4 = (_c3*_c3)
    _c5 = (L*L)
    _c6 = (ell*ell)
    _c7 = _c5 + _c6
    _c8 = 1/_c7
    _c9 = math.sin(alpha)
    _c10 = _c2*theta1_dot
    _c11 = 4*_c1*g
    _c12 = 8*theta1
    _c13 = _c10*_c5
    _c14 = _c2*_c5*theta2_dot
    _c15 = _c3*(_c9*_c9*_c9)
    _p0 = 1/ell
    _p1 = ((1.0/2.0))*_p0
    _p2 = _c1*_p1
    _p3 = D*phi_dot
    _p4 = _c4*_p0
    _p5 = D*theta2_dot
    _p6 = _c8*ell
    _p7 = ((1.0/2.0))*_p6
    _p8 = _c1*_p7
    _p9 = (_c9*_c9*_c9*_c9)
    _p10 = 2*_c6
    _p11 = g*(_c4*_c5 + _c4*_p10 - _c6)
    _p12 = D*_c8/_c5
    _p13 = ((1.0/8.0))*_p12
    _p14 = math.cos(4*alpha) - 1
    _k0 = _c2*_c5
    _k1 = _c5*theta2_dot
    _k2 = -_c0*_p1
    _k3 = -_c2*_p2
    _k4 = -_p2*theta1_dot
    _k5 = _p3*_p4
    _k6 = _p4*_p5
    _k7 = -(_c9*_c9)*_p6
    _k8 = -_c0*_p7
    _k9 = _p3*_p8
    _k10 = _p5*_p8
    _k11 = _p13*(-_c13*_p9 + _c14*_c15 - _p11*theta2)
    _k12 = _p13*(-_c12*_p9 + 8*_c15*theta2)
    _k13 = _p13*(_c12*_c15 + _p14*theta2)
    _k14 = _p13*(-_c11*_p10*theta2 - _c12*_p11 + 8*_c13*_c15 + _c14*_p14)
    _k15 = ((1.0/4.0))*_c11*_c7*_p12*theta1
    ds[0] = theta1_dot
    ds[1] = theta2_dot
    ds[2] = ((1.0/2.0))*(2*D*_c4*phi_dot*theta2_dot - _c0*theta1 - _c1*_c2*theta1_dot)/ell
    ds[3] = ((1.0/2.0))*_c8*ell*(D*_c1*phi_dot*theta2_dot - _c0*theta2 - 2*_c10*(_c9*_c9))
    ds[4] = ((1.0/8.0))*D*_c8*(-_c11*_c6*(theta2*theta2) + _c11*_c7*(theta1*theta1) - _c12*_c13*(_c9*_c9*_c9*_c9) + _c12*_c14*_c15 - _c12*g*theta2*(_c4*_c5 + 2*_c4*_c6 - _c6) + 8*_c13*_c15*theta2 + _c14*theta2*(math.cos(4*alpha) - 1))/_c5
    _v0 = _v[0]
    _v1 = _v[1]
    _v2 = _v[2]
    _v3 = _v[3]
    _v4 = _v[4]
    _t2 = D*_v4
    _t10 = _c2*_v2 + _t2*theta1_dot
    _t12 = 8*_v0
    _t13 = _c5*_t10
    _t14 = _k0*_v3 + _k1*_t2
    _dv[0] = _v2
    _dv[1] = _v3
    _dv[2] = _k2*_v0 + _k3*_v2 + _k4*_t2 + _k5*_v3 + _k6*_v4
    _dv[3] = _k10*_v4 + _k7*_t10 + _k8*_v1 + _k9*_v3
    _dv[4] = _k11*_t12 + _k12*_t13 + _k13*_t14 + _k14*_v1 + _k15*_v0



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
        '  %v55 = fmul double %v10, %v6\n'
        '  %v56 = fmul double %v10, %v8\n'
        '  %v57 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v6, ptr %v57\n'
        '  %v58 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v8, ptr %v58\n'
        '  %v59 = fmul double %v55, %v24\n'
        '  %v60 = fmul double %v56, %v26\n'
        '  %v61 = fadd double %v59, %v60\n'
        '  %v62 = fmul double %v22, %v2\n'
        '  %v63 = fadd double %v61, %v62\n'
        '  %v64 = fmul double %v28, %v63\n'
        '  %v65 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v64, ptr %v65\n'
        '  %v66 = fmul double %v55, %v32\n'
        '  %v67 = fmul double %v56, %v30\n'
        '  %v68 = fadd double %v66, %v67\n'
        '  %v69 = fmul double %v22, %v4\n'
        '  %v70 = fadd double %v68, %v69\n'
        '  %v71 = fmul double %v34, %v70\n'
        '  %v72 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v71, ptr %v72\n'
        '  %v73 = fmul double %v55, %v44\n'
        '  %v74 = fmul double %v73, %v2\n'
        '  %v75 = fmul double %v55, %v46\n'
        '  %v76 = fmul double %v75, %v4\n'
        '  %v77 = fadd double %v74, %v76\n'
        '  %v78 = fmul double %v56, %v42\n'
        '  %v79 = fmul double %v78, %v4\n'
        '  %v80 = fadd double %v77, %v79\n'
        '  %v81 = fmul double %v56, %v46\n'
        '  %v82 = fmul double %v81, %v2\n'
        '  %v83 = fadd double %v80, %v82\n'
        '  %v84 = fmul double %v36, %v2\n'
        '  %v85 = fmul double %v84, %v4\n'
        '  %v86 = fadd double %v83, %v85\n'
        '  %v87 = fmul double %v4, %v4\n'
        '  %v88 = fmul double %v38, %v87\n'
        '  %v89 = fadd double %v86, %v88\n'
        '  %v90 = fmul double %v2, %v2\n'
        '  %v91 = fmul double %v40, %v90\n'
        '  %v92 = fadd double %v89, %v91\n'
        '  %v93 = fmul double %v48, %v92\n'
        '  %v94 = getelementptr inbounds double, ptr %ds, i64 4\n'
        '  store double %v93, ptr %v94\n'
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
        '  %v61 = fmul double %v10, %v6\n'
        '  %v62 = fmul double %v10, %v8\n'
        '  %v63 = fadd double %v26, %v12\n'
        '  %v64 = fmul double %v56, %v4\n'
        '  %v65 = fmul double %v58, %v2\n'
        '  %v66 = fadd double %v64, %v65\n'
        '  %v67 = fmul double %v10, %v66\n'
        '  %v68 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v6, ptr %v68\n'
        '  %v69 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v8, ptr %v69\n'
        '  %v70 = fmul double %v61, %v30\n'
        '  %v71 = fmul double %v62, %v32\n'
        '  %v72 = fadd double %v70, %v71\n'
        '  %v73 = fmul double %v28, %v2\n'
        '  %v74 = fadd double %v72, %v73\n'
        '  %v75 = fmul double %v34, %v74\n'
        '  %v76 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v75, ptr %v76\n'
        '  %v77 = fmul double %v61, %v38\n'
        '  %v78 = fmul double %v62, %v36\n'
        '  %v79 = fadd double %v77, %v78\n'
        '  %v80 = fmul double %v28, %v4\n'
        '  %v81 = fadd double %v79, %v80\n'
        '  %v82 = fmul double %v40, %v81\n'
        '  %v83 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v82, ptr %v83\n'
        '  %v84 = fmul double %v61, %v50\n'
        '  %v85 = fmul double %v84, %v2\n'
        '  %v86 = fmul double %v61, %v52\n'
        '  %v87 = fmul double %v86, %v4\n'
        '  %v88 = fadd double %v85, %v87\n'
        '  %v89 = fmul double %v62, %v48\n'
        '  %v90 = fmul double %v89, %v4\n'
        '  %v91 = fadd double %v88, %v90\n'
        '  %v92 = fmul double %v62, %v52\n'
        '  %v93 = fmul double %v92, %v2\n'
        '  %v94 = fadd double %v91, %v93\n'
        '  %v95 = fmul double %v42, %v2\n'
        '  %v96 = fmul double %v95, %v4\n'
        '  %v97 = fadd double %v94, %v96\n'
        '  %v98 = fmul double %v4, %v4\n'
        '  %v99 = fmul double %v44, %v98\n'
        '  %v100 = fadd double %v97, %v99\n'
        '  %v101 = fmul double %v2, %v2\n'
        '  %v102 = fmul double %v46, %v101\n'
        '  %v103 = fadd double %v100, %v102\n'
        '  %v104 = fmul double %v54, %v103\n'
        '  %v105 = getelementptr inbounds double, ptr %ds, i64 4\n'
        '  store double %v104, ptr %v105\n'
        '  %v106 = getelementptr inbounds double, ptr %ds, i64 5\n'
        '  store double %v10, ptr %v106\n'
        '  %v107 = fmul double %v24, %v67\n'
        '  %v108 = call double @llvm.sin.f64(double %v63)\n'
        '  %v109 = fmul double %v107, %v108\n'
        '  %v110 = getelementptr inbounds double, ptr %ds, i64 6\n'
        '  store double %v109, ptr %v110\n'
        '  %v111 = fmul double %v67, %v60\n'
        '  %v112 = call double @llvm.cos.f64(double %v63)\n'
        '  %v113 = fmul double %v111, %v112\n'
        '  %v114 = getelementptr inbounds double, ptr %ds, i64 7\n'
        '  store double %v113, ptr %v114\n'
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
        '  %v16 = fmul double 0x4000000000000000, %v10\n'
        '  %v17 = call double @llvm.sin.f64(double %v16)\n'
        '  %v18 = fmul double %v8, %v17\n'
        '  %v19 = call double @llvm.cos.f64(double %v10)\n'
        '  %v20 = fmul double %v19, %v19\n'
        '  %v21 = fmul double 0x4000000000000000, %v8\n'
        '  %v22 = call double @llvm.sin.f64(double %v10)\n'
        '  %v23 = fmul double %v6, %v6\n'
        '  %v24 = fmul double %v4, %v4\n'
        '  %v25 = fadd double %v23, %v24\n'
        '  %v26 = fdiv double 0x3FF0000000000000, %v25\n'
        '  %v27 = fmul double 0x4010000000000000, %v17\n'
        '  %v28 = fmul double %v27, %v2\n'
        '  %v29 = fmul double %v8, %v23\n'
        '  %v30 = fmul double 0x4020000000000000, %v29\n'
        '  %v31 = fmul double 0xC000000000000000, %v2\n'
        '  %v32 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  store double %v31, ptr %v32\n'
        '  %v33 = fneg double %v18\n'
        '  %v34 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  store double %v33, ptr %v34\n'
        '  %v35 = fmul double %v20, %v21\n'
        '  %v36 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  store double %v35, ptr %v36\n'
        '  %v37 = fdiv double 0x3FE0000000000000, %v4\n'
        '  %v38 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  store double %v37, ptr %v38\n'
        '  %v39 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  store double %v18, ptr %v39\n'
        '  %v40 = fneg double %v21\n'
        '  %v41 = fmul double %v22, %v22\n'
        '  %v42 = fmul double %v40, %v41\n'
        '  %v43 = getelementptr inbounds double, ptr %q, i64 10\n'
        '  store double %v42, ptr %v43\n'
        '  %v44 = fmul double 0x3FE0000000000000, %v26\n'
        '  %v45 = fmul double %v44, %v4\n'
        '  %v46 = getelementptr inbounds double, ptr %q, i64 11\n'
        '  store double %v45, ptr %v46\n'
        '  %v47 = fmul double 0xC020000000000000, %v2\n'
        '  %v48 = fmul double %v20, %v23\n'
        '  %v49 = fmul double 0x4000000000000000, %v20\n'
        '  %v50 = fmul double %v49, %v24\n'
        '  %v51 = fadd double %v48, %v50\n'
        '  %v52 = fsub double %v51, %v24\n'
        '  %v53 = fmul double %v47, %v52\n'
        '  %v54 = getelementptr inbounds double, ptr %q, i64 12\n'
        '  store double %v53, ptr %v54\n'
        '  %v55 = fneg double %v28\n'
        '  %v56 = fmul double %v55, %v24\n'
        '  %v57 = getelementptr inbounds double, ptr %q, i64 13\n'
        '  store double %v56, ptr %v57\n'
        '  %v58 = fmul double %v28, %v25\n'
        '  %v59 = getelementptr inbounds double, ptr %q, i64 14\n'
        '  store double %v58, ptr %v59\n'
        '  %v60 = fmul double 0x4010000000000000, %v10\n'
        '  %v61 = call double @llvm.cos.f64(double %v60)\n'
        '  %v62 = fsub double %v61, 0x3FF0000000000000\n'
        '  %v63 = fmul double %v29, %v62\n'
        '  %v64 = getelementptr inbounds double, ptr %q, i64 15\n'
        '  store double %v63, ptr %v64\n'
        '  %v65 = fneg double %v30\n'
        '  %v66 = fmul double %v22, %v22\n'
        '  %v67 = fmul double %v66, %v22\n'
        '  %v68 = fmul double %v67, %v22\n'
        '  %v69 = fmul double %v65, %v68\n'
        '  %v70 = getelementptr inbounds double, ptr %q, i64 16\n'
        '  store double %v69, ptr %v70\n'
        '  %v71 = fmul double %v30, %v19\n'
        '  %v72 = fmul double %v22, %v22\n'
        '  %v73 = fmul double %v72, %v22\n'
        '  %v74 = fmul double %v71, %v73\n'
        '  %v75 = getelementptr inbounds double, ptr %q, i64 17\n'
        '  store double %v74, ptr %v75\n'
        '  %v76 = fmul double 0x3FC0000000000000, %v8\n'
        '  %v77 = fmul double %v76, %v26\n'
        '  %v78 = fdiv double %v77, %v23\n'
        '  %v79 = getelementptr inbounds double, ptr %q, i64 18\n'
        '  store double %v78, ptr %v79\n'
        '  %v80 = getelementptr inbounds double, ptr %q, i64 19\n'
        '  store double %v19, ptr %v80\n'
        '  %v81 = fneg double %v22\n'
        '  %v82 = getelementptr inbounds double, ptr %q, i64 20\n'
        '  store double %v81, ptr %v82\n'
        '  %v83 = fneg double %v8\n'
        '  %v84 = getelementptr inbounds double, ptr %q, i64 21\n'
        '  store double %v83, ptr %v84\n'
        '  ret void\n'
        '}\n'
        'declare double @llvm.cos.f64(double)\n'
        'declare double @llvm.sin.f64(double)\n'
    ),
}
#: how many parameters the IR of ``constants`` reads
LLVM_IR_READS = 5
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '871a213667c814f0747702e846957a6acaf5f1acbc2e8a662f2130d664acbbc9'
