"""two_mode, fidelity reduced: degree-2 Taylor polynomial of the full vector field in the tilts and tilt rates (tilt equations to O(theta), spin equation to O(theta^2)).

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from derivation/models.py (model 'two_mode',
constraints Const22, Const23) through derivation/engine.py and derivation/truncation.py.
Accelerations and multipliers in closed form (symbolic elimination of the multipliers).
SymPy 1.14.0; input hash sha256:d3bb1c77e3103d772fbcef629c362357d761bd272b83faa97a2d642bba4c7de9

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
INPUT_HASH = 'd3bb1c77e3103d772fbcef629c362357d761bd272b83faa97a2d642bba4c7de9'
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


#: operation counts of the Jacobians (derivation/jacobian.py)
OP_COUNTS.update(jacobian=156, jacobian_p=453)

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
MODULE_SHA256 = '7f78f8c182202677093dc3ea61087f38d4cd22086e8fd5aa01f25e42b4e4c11c'
