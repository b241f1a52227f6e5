"""rolling_disk, fidelity reduced: degree-2 Taylor polynomial of the full vector field in the tilts and tilt rates (tilt equations to O(theta), spin equation to O(theta^2)).

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from examples/rolling_disk.py (model 'rolling_disk',
constraints no_slip_along, no_slip_across) through derivation/engine.py and derivation/truncation.py.
SymPy 1.14.0; input hash sha256:eb8b7b6f2a2c5ddd69a8425e2af00f1d5d06632dd3fad08e587b7bb340b700f2

Uniform thin disk of radius r rolling without slipping on a horizontal table: heading q1, lean q2 from the vertical, rotation q3 about the axle, contact point (x, y).

State vector ``s`` (closed state; the pose follows by quadrature):
    s[0] = q2           [rad]
    s[1] = q2_dot       [rad/time]
    s[2] = q1_dot       [rad/time]
    s[3] = q3_dot       [rad/time]
Pose-extended state (``*_pose`` functions) appends:
    s[4] = q1           [rad]
    s[5] = q3           [rad]
    s[6] = x            [length]
    s[7] = y            [length]
Parameter vector ``p``:
    p[0] = g            [length/time^2]
    p[1] = r            [length]
Multipliers (constraint forces in the normalization of the Lagrangian, e.g. per unit mass),
in the order no_slip_along, no_slip_across.  Energy in the same normalization.
"""
import math

import numpy as np
from numba import njit

MODEL = 'rolling_disk'
FIDELITY = 'reduced'
#: what this fidelity is
FIDELITY_DOC = 'degree-2 Taylor polynomial of the full vector field in the tilts and tilt rates (tilt equations to O(theta), spin equation to O(theta^2))'
STATE_NAMES = ('q2', 'q2_dot', 'q1_dot', 'q3_dot')
#: unit of each state (``time`` is the unit of t)
STATE_UNITS = ('rad', 'rad/time', 'rad/time', 'rad/time')
POSE_NAMES = ('q1', 'q3', 'x', 'y')
POSE_UNITS = ('rad', 'rad', 'length', 'length')
#: what the pose coordinates mean
POSE_DOC = 'q1: heading; q3: rotation about the axle; (x, y): contact point on the table'
PARAM_NAMES = ('g', 'r')
PARAM_UNITS = ('length/time^2', 'length')
#: admissible values of each parameter: 'positive' (> 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive')
#: default parameter set and initial state (the CLI's defaults); empty if the model declares none
DEFAULT_PARAMS = {'g': 1.0, 'r': 1.0}
DEFAULT_STATE = {'q2': 0.1, 'q2_dot': 0.0, 'q1_dot': 0.0, 'q3_dot': 2.0}
#: (coordinate, rate) pairs of the state
RATE_PAIRS = (('q2', 'q2_dot'),)
#: the small coordinates (tilts) of the small-angle fidelities
TILT_NAMES = ('q2',)
#: states (or EVENT_NAMES) whose zero crossings are reported as ``reversal_times``
REVERSAL_EVENTS = ()
#: scalar functions of the state returned by ``event_values(s, p)``
EVENT_NAMES = ()
#: largest |value| of each named state where this fidelity holds (empty: everywhere)
VALIDITY = {}
VALIDITY_DOC = ''
MULTIPLIER_NAMES = ('no_slip_along', 'no_slip_across')
#: non-conservative forces: the module has ``power_dissipated(s, p)``
HAS_DISSIPATION = False
#: model-specific helpers defined at the end of this module
EXPORTS = ()
INPUT_HASH = 'eb8b7b6f2a2c5ddd69a8425e2af00f1d5d06632dd3fad08e587b7bb340b700f2'
SYMPY_VERSION = '1.14.0'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 27, 'constants': 7, 'rhs_q': 22, 'rhs_pose': 32, 'rhs_pose_q': 27, 'pose_rates': 5, 'energy': 26, 'multipliers': 16}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (27 operations)."""
    q2 = s[0]
    q2_dot = s[1]
    q1_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    _c0 = q1_dot*r
    ds[0] = q2_dot
    ds[1] = ((1.0/5.0))*(-3*_c0*(q2*q2)*q3_dot + 6*_c0*q3_dot + 4*g*q2 + 5*(q1_dot*q1_dot)*q2*r)/r
    ds[2] = -2*q2_dot*q3_dot
    ds[3] = ((1.0/3.0))*q2_dot*(-5*q1_dot + 6*q2*q3_dot)


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 4."""
    ds = np.empty(4)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 5 parameter-only subexpressions of the right-hand side (7 operations)."""
    q = np.empty(7)
    g = p[0]
    r = p[1]
    q[0] = g
    q[1] = r
    q[2] = 4*g
    q[3] = 5*r
    q[4] = 6*r
    q[5] = -3*r
    q[6] = ((1.0/5.0))/r
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (22 operations)."""
    q2 = s[0]
    q2_dot = s[1]
    q1_dot = s[2]
    q3_dot = s[3]
    g = q[0]
    r = q[1]
    _k0 = q[2]
    _k1 = q[3]
    _k2 = q[4]
    _k3 = q[5]
    _k4 = q[6]
    _c0 = q1_dot*q3_dot
    ds[0] = q2_dot
    ds[1] = _k4*(_c0*_k2 + _c0*_k3*(q2*q2) + _k0*q2 + _k1*(q1_dot*q1_dot)*q2)
    ds[2] = -2*q2_dot*q3_dot
    ds[3] = ((1.0/3.0))*q2_dot*(-5*q1_dot + 6*q2*q3_dot)


@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds`` (32 operations)."""
    q2 = s[0]
    q2_dot = s[1]
    q1_dot = s[2]
    q3_dot = s[3]
    q1 = s[4]
    q3 = s[5]
    x = s[6]
    y = s[7]
    g = p[0]
    r = p[1]
    _c0 = q3_dot*r
    ds[0] = q2_dot
    ds[1] = ((1.0/5.0))*(-3*_c0*q1_dot*(q2*q2) + 4*g*q2 + 5*(q1_dot*q1_dot)*q2*r + 6*q1_dot*q3_dot*r)/r
    ds[2] = -2*q2_dot*q3_dot
    ds[3] = ((1.0/3.0))*q2_dot*(-5*q1_dot + 6*q2*q3_dot)
    ds[4] = q1_dot
    ds[5] = q3_dot
    ds[6] = _c0*math.cos(q1)
    ds[7] = _c0*math.sin(q1)


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length 8."""
    ds = np.empty(8)
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p`` (27 operations)."""
    q2 = s[0]
    q2_dot = s[1]
    q1_dot = s[2]
    q3_dot = s[3]
    q1 = s[4]
    q3 = s[5]
    x = s[6]
    y = s[7]
    g = q[0]
    r = q[1]
    _k0 = q[2]
    _k1 = q[3]
    _k2 = q[4]
    _k3 = q[5]
    _k4 = q[6]
    _c0 = q1_dot*q3_dot
    _c1 = q3_dot*r
    ds[0] = q2_dot
    ds[1] = _k4*(_c0*_k2 + _c0*_k3*(q2*q2) + _k0*q2 + _k1*(q1_dot*q1_dot)*q2)
    ds[2] = -2*q2_dot*q3_dot
    ds[3] = ((1.0/3.0))*q2_dot*(-5*q1_dot + 6*q2*q3_dot)
    ds[4] = q1_dot
    ds[5] = q3_dot
    ds[6] = _c1*math.cos(q1)
    ds[7] = _c1*math.sin(q1)


@njit(cache=True)
def pose_rates(s, p):
    """Return the rates (q1_dot, q3_dot, x_dot, y_dot) of the pose at the pose-extended state ``s`` (5 operations)."""
    out = np.empty(4)
    q2 = s[0]
    q2_dot = s[1]
    q1_dot = s[2]
    q3_dot = s[3]
    q1 = s[4]
    q3 = s[5]
    x = s[6]
    y = s[7]
    g = p[0]
    r = p[1]
    _c0 = q3_dot*r
    out[0] = q1_dot
    out[1] = q3_dot
    out[2] = _c0*math.cos(q1)
    out[3] = _c0*math.sin(q1)
    return out


@njit(cache=True)
def energy(s, p):
    """Energy per unit mass (26 operations)."""
    q2 = s[0]
    q2_dot = s[1]
    q1_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    _c0 = (q1_dot*q1_dot)*r
    _c1 = (q2*q2)
    energy = ((1.0/8.0))*r*(5*_c0*_c1 + _c0 - 4*_c1*g + 8*g + 12*q1_dot*q2*q3_dot*r + 5*(q2_dot*q2_dot)*r + 6*(q3_dot*q3_dot)*r)
    return energy


@njit(cache=True)
def multipliers(s, p):
    """Lagrange multipliers (contact forces per unit mass) no_slip_along, no_slip_across (16 operations)."""
    out = np.empty(2)
    q2 = s[0]
    q2_dot = s[1]
    q1_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    _c0 = q1_dot*r
    out[0] = ((1.0/3.0))*_c0*q2_dot
    out[1] = -(1.0/5.0)*_c0*q3_dot - (4.0/5.0)*g*q2 + ((6.0/5.0))*q1_dot*(q2*q2)*q3_dot*r
    return out


#: this model has no drawing (derivation/drawing.py)
DRAWING = None
