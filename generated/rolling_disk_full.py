"""rolling_disk, fidelity full: exact consequences of the model's Lagrangian and constraints, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from examples/rolling_disk.py (model 'rolling_disk',
constraints no_slip_along, no_slip_across) through derivation/engine.py.
Accelerations and multipliers in closed form (symbolic elimination of the multipliers).
SymPy 1.14.0; input hash sha256:c5fb861b568f147a5a04f5f4c5078e231d6eb89995660bc5dfc2da7d25ed478b

Uniform thin disk of radius r rolling without slipping on a horizontal table: heading q1, lean q2 from the vertical, rotation q3 about the axle, contact point (x, y).

State vector ``s`` (closed state; the pose follows by quadrature):
    s[0] = q2           [rad]
    s[1] = q1_dot       [rad/s]
    s[2] = q2_dot       [rad/s]
    s[3] = q3_dot       [rad/s]
Pose-extended state (``*_pose`` functions) appends:
    s[4] = q1           [rad]
    s[5] = q3           [rad]
    s[6] = x            [m]
    s[7] = y            [m]
Parameter vector ``p``:
    p[0] = g            [m/s^2]
    p[1] = r            [m]
Multipliers (constraint forces in the normalization of the Lagrangian, e.g. per unit mass),
in the order no_slip_along, no_slip_across.  Energy in the same normalization.
"""
import math

import numpy as np
from numba import njit

MODEL = 'rolling_disk'
FIDELITY = 'full'
#: what this fidelity is
FIDELITY_DOC = "exact consequences of the model's Lagrangian and constraints, nothing dropped"
STATE_NAMES = ('q2', 'q1_dot', 'q2_dot', 'q3_dot')
#: unit of each state (``time`` is the unit of t)
STATE_UNITS = ('rad', 'rad/s', 'rad/s', 'rad/s')
POSE_NAMES = ('q1', 'q3', 'x', 'y')
POSE_UNITS = ('rad', 'rad', 'm', 'm')
#: what the pose coordinates mean
POSE_DOC = 'heading q1, rotation q3 about the axle, contact point (x, y) on the table'
PARAM_NAMES = ('g', 'r')
PARAM_UNITS = ('m/s^2', 'm')
#: admissible values of each parameter: 'positive' (> 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive')
#: default parameter set and initial state (the CLI's defaults); empty if the model declares none
DEFAULT_PARAMS = {'g': 9.81, 'r': 0.1}
DEFAULT_STATE = {'q2': 0.05, 'q1_dot': 0.0, 'q2_dot': 0.0, 'q3_dot': 8.0}
#: (coordinate, rate) pairs of the state
RATE_PAIRS = (('q2', 'q2_dot'),)
#: the small coordinates (tilts) of the small-angle fidelities
TILT_NAMES = ()
#: states (or EVENT_NAMES) whose zero crossings are reported as ``reversal_times``
REVERSAL_EVENTS = ()
#: scalar functions of the state returned by ``event_values(s, p)``
EVENT_NAMES = ()
#: largest |value| of each named state where this fidelity holds (empty: everywhere)
VALIDITY = {'q2': 1.5707963267948966}
VALIDITY_DOC = 'the disk lies flat on the table at |q2| = pi/2; beyond, it would pass through it'
MULTIPLIER_NAMES = ('no_slip_along', 'no_slip_across')
#: non-conservative forces: the module has ``power_dissipated(s, p)``
HAS_DISSIPATION = False
#: model-specific helpers defined at the end of this module
EXPORTS = ()
INPUT_HASH = 'c5fb861b568f147a5a04f5f4c5078e231d6eb89995660bc5dfc2da7d25ed478b'
SYMPY_VERSION = '1.14.0'
#: how the multipliers are eliminated: "symbolic" (closed form) or "numeric" (a linear solve at every call)
ELIMINATION = 'symbolic'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 129, 'constants': 7, 'rhs_q': 125, 'rhs_pose': 134, 'rhs_pose_q': 130, 'pose_rates': 5, 'energy': 45, 'multipliers': 113}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (129 operations)."""
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    _c0 = math.sin(q2)
    _c1 = _c0**6
    _c2 = math.cos(q2)
    _c3 = _c2**6
    _c4 = (_c0*_c0)
    _c5 = (_c2*_c2*_c2*_c2)
    _c6 = _c4*_c5
    _c7 = (_c2*_c2)
    _c8 = (_c0*_c0*_c0*_c0)
    _c9 = _c7*_c8
    _c10 = _c4*_c7
    _c11 = 1/(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)
    _c12 = _c11*q2_dot/_c2
    _c13 = _c0**5
    _c14 = 4*g
    _c15 = _c0*_c5
    _c16 = 6*q3_dot
    _c17 = q1_dot*r
    _c18 = _c16*_c17
    _c19 = (_c0*_c0*_c0)
    _c20 = _c19*_c7
    _c21 = _c2**5
    _c22 = (q1_dot*q1_dot)*r
    _c23 = 5*_c22
    _c24 = 18*_c17*q3_dot
    _c25 = (_c2*_c2*_c2)
    _c26 = 5*q1_dot
    _c27 = 20*q1_dot
    _c28 = 24*q3_dot
    _c29 = 72*q3_dot
    ds[0] = q2_dot
    ds[1] = -2*_c12*q3_dot*(4*_c0**8 + 16*_c1*_c7 + _c1 + 4*_c2**8 + 16*_c3*_c4 + _c3 + 24*_c5*_c8 + 3*_c6 + 3*_c9)
    ds[2] = _c11*(_c0*_c21*_c23 + _c1*_c18*_c2 + _c13*_c14 + _c13*_c2*_c23 + _c14*_c15 + _c18*_c2**7 + 10*_c19*_c22*_c25 + 8*_c20*g + _c21*_c24*_c4 + _c24*_c25*_c8)/r
    ds[3] = ((1.0/3.0))*_c12*(_c0**7*_c28 + _c0*_c28*_c3 - _c10*_c26 + _c13*_c16 + _c13*_c29*_c7 + _c15*_c16 + _c19*_c29*_c5 + 12*_c20*q3_dot - _c26*_c5 - _c27*_c3 - _c27*_c9 - 40*_c6*q1_dot)


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 4."""
    ds = np.empty(4)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 7 parameter-only subexpressions of the right-hand side (7 operations)."""
    q = np.empty(9)
    g = p[0]
    r = p[1]
    q[0] = g
    q[1] = r
    q[2] = 4*g
    q[3] = 8*g
    q[4] = 5*r
    q[5] = 6*r
    q[6] = 10*r
    q[7] = 18*r
    q[8] = 1/r
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (125 operations)."""
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = q[0]
    r = q[1]
    _k0 = q[2]
    _k1 = q[3]
    _k2 = q[4]
    _k3 = q[5]
    _k4 = q[6]
    _k5 = q[7]
    _k6 = q[8]
    _c0 = math.sin(q2)
    _c1 = _c0**6
    _c2 = math.cos(q2)
    _c3 = _c2**6
    _c4 = (_c0*_c0)
    _c5 = (_c2*_c2*_c2*_c2)
    _c6 = _c4*_c5
    _c7 = (_c2*_c2)
    _c8 = (_c0*_c0*_c0*_c0)
    _c9 = _c7*_c8
    _c10 = _c4*_c7
    _c11 = 1/(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)
    _c12 = _c11*q2_dot/_c2
    _c13 = _c0**5
    _c14 = _c0*_c5
    _c15 = q1_dot*q3_dot
    _c16 = _c15*_k3
    _c17 = (_c0*_c0*_c0)
    _c18 = _c17*_c7
    _c19 = _c2**5
    _c20 = (q1_dot*q1_dot)
    _c21 = _c20*_k2
    _c22 = _c15*_k5
    _c23 = (_c2*_c2*_c2)
    _c24 = 5*q1_dot
    _c25 = 20*q1_dot
    _c26 = 6*q3_dot
    _c27 = 24*q3_dot
    _c28 = 72*q3_dot
    ds[0] = q2_dot
    ds[1] = -2*_c12*q3_dot*(4*_c0**8 + 16*_c1*_c7 + _c1 + 4*_c2**8 + 16*_c3*_c4 + _c3 + 24*_c5*_c8 + 3*_c6 + 3*_c9)
    ds[2] = _c11*_k6*(_c0*_c19*_c21 + _c1*_c16*_c2 + _c13*_c2*_c21 + _c13*_k0 + _c14*_k0 + _c16*_c2**7 + _c17*_c20*_c23*_k4 + _c18*_k1 + _c19*_c22*_c4 + _c22*_c23*_c8)
    ds[3] = ((1.0/3.0))*_c12*(_c0**7*_c27 + _c0*_c27*_c3 - _c10*_c24 + _c13*_c26 + _c13*_c28*_c7 + _c14*_c26 + _c17*_c28*_c5 + 12*_c18*q3_dot - _c24*_c5 - _c25*_c3 - _c25*_c9 - 40*_c6*q1_dot)


@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds`` (134 operations)."""
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    q1 = s[4]
    q3 = s[5]
    x = s[6]
    y = s[7]
    g = p[0]
    r = p[1]
    _c0 = math.sin(q2)
    _c1 = _c0**6
    _c2 = math.cos(q2)
    _c3 = _c2**6
    _c4 = (_c0*_c0)
    _c5 = (_c2*_c2*_c2*_c2)
    _c6 = _c4*_c5
    _c7 = (_c2*_c2)
    _c8 = (_c0*_c0*_c0*_c0)
    _c9 = _c7*_c8
    _c10 = _c4*_c7
    _c11 = 1/(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)
    _c12 = _c11*q2_dot/_c2
    _c13 = _c0**5
    _c14 = 4*g
    _c15 = _c0*_c5
    _c16 = 6*q3_dot
    _c17 = _c16*q1_dot*r
    _c18 = (_c0*_c0*_c0)
    _c19 = _c18*_c7
    _c20 = _c2**5
    _c21 = (q1_dot*q1_dot)*r
    _c22 = 5*_c21
    _c23 = q3_dot*r
    _c24 = 18*_c23*q1_dot
    _c25 = (_c2*_c2*_c2)
    _c26 = 5*q1_dot
    _c27 = 20*q1_dot
    _c28 = 24*q3_dot
    _c29 = 72*q3_dot
    ds[0] = q2_dot
    ds[1] = -2*_c12*q3_dot*(4*_c0**8 + 16*_c1*_c7 + _c1 + 4*_c2**8 + 16*_c3*_c4 + _c3 + 24*_c5*_c8 + 3*_c6 + 3*_c9)
    ds[2] = _c11*(_c0*_c20*_c22 + _c1*_c17*_c2 + _c13*_c14 + _c13*_c2*_c22 + _c14*_c15 + _c17*_c2**7 + 10*_c18*_c21*_c25 + 8*_c19*g + _c20*_c24*_c4 + _c24*_c25*_c8)/r
    ds[3] = ((1.0/3.0))*_c12*(_c0**7*_c28 + _c0*_c28*_c3 - _c10*_c26 + _c13*_c16 + _c13*_c29*_c7 + _c15*_c16 + _c18*_c29*_c5 + 12*_c19*q3_dot - _c26*_c5 - _c27*_c3 - _c27*_c9 - 40*_c6*q1_dot)
    ds[4] = q1_dot
    ds[5] = q3_dot
    ds[6] = _c23*math.cos(q1)
    ds[7] = _c23*math.sin(q1)


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length 8."""
    ds = np.empty(8)
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p`` (130 operations)."""
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
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
    _k5 = q[7]
    _k6 = q[8]
    _c0 = math.sin(q2)
    _c1 = _c0**6
    _c2 = math.cos(q2)
    _c3 = _c2**6
    _c4 = (_c0*_c0)
    _c5 = (_c2*_c2*_c2*_c2)
    _c6 = _c4*_c5
    _c7 = (_c2*_c2)
    _c8 = (_c0*_c0*_c0*_c0)
    _c9 = _c7*_c8
    _c10 = _c4*_c7
    _c11 = 1/(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)
    _c12 = _c11*q2_dot/_c2
    _c13 = _c0**5
    _c14 = _c0*_c5
    _c15 = q1_dot*q3_dot
    _c16 = _c15*_k3
    _c17 = (_c0*_c0*_c0)
    _c18 = _c17*_c7
    _c19 = _c2**5
    _c20 = (q1_dot*q1_dot)
    _c21 = _c20*_k2
    _c22 = _c15*_k5
    _c23 = (_c2*_c2*_c2)
    _c24 = 5*q1_dot
    _c25 = 20*q1_dot
    _c26 = 6*q3_dot
    _c27 = 24*q3_dot
    _c28 = 72*q3_dot
    _c29 = q3_dot*r
    ds[0] = q2_dot
    ds[1] = -2*_c12*q3_dot*(4*_c0**8 + 16*_c1*_c7 + _c1 + 4*_c2**8 + 16*_c3*_c4 + _c3 + 24*_c5*_c8 + 3*_c6 + 3*_c9)
    ds[2] = _c11*_k6*(_c0*_c19*_c21 + _c1*_c16*_c2 + _c13*_c2*_c21 + _c13*_k0 + _c14*_k0 + _c16*_c2**7 + _c17*_c20*_c23*_k4 + _c18*_k1 + _c19*_c22*_c4 + _c22*_c23*_c8)
    ds[3] = ((1.0/3.0))*_c12*(_c0**7*_c27 + _c0*_c27*_c3 - _c10*_c24 + _c13*_c26 + _c13*_c28*_c7 + _c14*_c26 + _c17*_c28*_c5 + 12*_c18*q3_dot - _c24*_c5 - _c25*_c3 - _c25*_c9 - 40*_c6*q1_dot)
    ds[4] = q1_dot
    ds[5] = q3_dot
    ds[6] = _c29*math.cos(q1)
    ds[7] = _c29*math.sin(q1)


@njit(cache=True)
def pose_rates(s, p):
    """Return the rates (q1_dot, q3_dot, x_dot, y_dot) of the pose at the pose-extended state ``s`` (5 operations)."""
    out = np.empty(4)
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
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
    """Energy per unit mass (45 operations)."""
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    _c0 = math.cos(q2)
    _c1 = (q2_dot*q2_dot)*r
    _c2 = (_c0*_c0)
    _c3 = (q1_dot*q1_dot)*r
    _c4 = math.sin(q2)
    _c5 = 12*q1_dot*q3_dot*r
    _c6 = (_c4*_c4)
    _c7 = 4*_c1
    _c8 = (q3_dot*q3_dot)*r
    _c9 = 6*_c8
    energy = ((1.0/8.0))*r*((_c0*_c0*_c0*_c0)*_c9 + 8*_c0*g + _c1 + _c2*_c3 + _c2*_c4*_c5 + 12*_c2*_c6*_c8 + _c2*_c7 + 6*_c3*_c6 + (_c4*_c4*_c4*_c4)*_c9 + (_c4*_c4*_c4)*_c5 + _c6*_c7)
    return energy


@njit(cache=True)
def multipliers(s, p):
    """Lagrange multipliers (contact forces per unit mass) no_slip_along, no_slip_across (113 operations)."""
    out = np.empty(2)
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    _c0 = math.cos(q2)
    _c1 = q1_dot*r
    _c2 = math.sin(q2)
    _c3 = (_c2*_c2*_c2*_c2)
    _c4 = (_c0*_c0*_c0*_c0)
    _c5 = _c2**6
    _c6 = _c0**6
    _c7 = 4*_c6
    _c8 = (_c2*_c2)
    _c9 = (_c0*_c0)
    _c10 = 2*_c9
    _c11 = 12*_c4
    _c12 = 12*_c9
    _c13 = _c1*q3_dot
    _c14 = _c13*_c5
    _c15 = _c13*_c6
    _c16 = 4*g
    _c17 = _c2**5
    _c18 = (q1_dot*q1_dot)
    _c19 = _c17*r
    _c20 = _c18*_c19
    _c21 = (q2_dot*q2_dot)
    _c22 = _c19*_c21
    _c23 = _c18*r
    _c24 = 4*_c2**7
    _c25 = _c21*r
    _c26 = (_c2*_c2*_c2)
    _c27 = _c2*_c4
    _c28 = 3*_c13
    _c29 = _c23*_c26
    _c30 = _c25*_c26
    out[0] = ((1.0/3.0))*_c0*_c1*q2_dot
    out[1] = (-2*_c0**8*_c13 - _c0**5*_c16*_c2 - 8*(_c0*_c0*_c0)*_c26*g - _c0*_c16*_c17 + _c10*_c29 + _c10*_c30 + _c11*_c30 + _c12*_c22 + 4*_c13*_c2**8 + 6*_c13*_c3*_c4 + 10*_c14*_c9 + _c14 - 2*_c15*_c8 + _c15 - _c2*_c23*_c6 + _c2*_c25*_c7 + 7*_c20*_c9 + _c20 + _c22 + _c23*_c24 + _c23*_c27 + _c24*_c25 + _c25*_c27 + _c28*_c3*_c9 + _c28*_c4*_c8 + 2*_c29*_c4)/(_c10*_c8 + _c11*_c8 + _c12*_c3 + _c3 + _c4 + 4*_c5 + _c7)
    return out



#: how to draw the body (derivation/drawing.py): names of the rows of ``body_points``,
#: segments between them, the contact point, the point masses, the tilts a picture may
#: magnify, the outline curves of ``body_outlines``
DRAWING = {'points': ('C', 'centre', 'spoke_a', 'spoke_b', 'spoke_c', 'spoke_d', 'axle_a', 'axle_b'), 'segments': (('spoke_a', 'spoke_b'), ('spoke_c', 'spoke_d'), ('axle_a', 'axle_b')), 'contact': 'C', 'masses': ('centre',), 'magnify': ('q2',), 'outlines': ('rim',), 'description': 'disk: its rim, two diameters turning with it, the axle, the centre and the contact point', 'gauge': 'q1_dot'}


@njit(cache=True)
def body_points(s, p):
    """World coordinates (z up, table z = 0) of DRAWING["points"] at the pose-extended state ``s``; shape (8, 3) (63 operations)."""
    out = np.empty((8, 3))
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    q1 = s[4]
    q3 = s[5]
    x = s[6]
    y = s[7]
    g = p[0]
    r = p[1]
    _c0 = math.sin(q1)
    _c1 = math.sin(q2)
    _c2 = _c1*r
    _c3 = _c0*_c2 + x
    _c4 = math.cos(q1)
    _c5 = _c2*_c4
    _c6 = _c5 - y
    _c7 = math.cos(q2)
    _c8 = _c7*r
    _c9 = math.sin(q3)
    _c10 = _c4*_c9
    _c11 = math.cos(q3)
    _c12 = _c0*_c11
    _c13 = r*(_c1*_c12 + _c10)
    _c14 = _c0*_c9
    _c15 = r*(-_c1*_c11*_c4 + _c14)
    _c16 = -_c5 + y
    _c17 = _c11*_c8
    _c18 = -_c7*r
    _c19 = r*(-_c1*_c14 + _c11*_c4)
    _c20 = r*(_c1*_c10 + _c12)
    _c21 = _c8*_c9
    _c22 = ((1.0/3.0))*_c8
    _c23 = _c0*_c22
    _c24 = _c22*_c4
    _c25 = ((1.0/3.0))*_c2
    out[0, 0] = x
    out[0, 1] = y
    out[0, 2] = 0
    out[1, 0] = _c3
    out[1, 1] = -_c6
    out[1, 2] = _c8
    out[2, 0] = _c13 + _c3
    out[2, 1] = _c15 + _c16
    out[2, 2] = _c17 + _c8
    out[3, 0] = -_c13 + _c3
    out[3, 1] = -_c15 - _c6
    out[3, 2] = -_c17 - _c18
    out[4, 0] = _c19 + _c3
    out[4, 1] = _c16 + _c20
    out[4, 2] = -_c18 - _c21
    out[5, 0] = -_c19 + _c3
    out[5, 1] = -_c20 - _c6
    out[5, 2] = _c21 + _c8
    out[6, 0] = -_c23 + _c3
    out[6, 1] = _c16 + _c24
    out[6, 2] = _c25 + _c8
    out[7, 0] = _c23 + _c3
    out[7, 1] = -_c24 - _c6
    out[7, 2] = -_c18 - _c25
    return out


@njit(cache=True)
def body_outlines(s, p, uu):
    """World coordinates of the curves DRAWING["outlines"] at the parameters ``uu`` in [0, 2 pi); shape (1, len(uu), 3) (25 operations)."""
    out = np.empty((1, uu.shape[0], 3))
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    q1 = s[4]
    q3 = s[5]
    x = s[6]
    y = s[7]
    g = p[0]
    r = p[1]
    for j in range(uu.shape[0]):
        u = uu[j]
        _c0 = math.sin(q1)
        _c1 = math.sin(q2)
        _c2 = _c0*_c1
        _c3 = math.cos(q1)
        _c4 = math.cos(u)
        _c5 = math.sin(u)
        _c6 = _c1*_c3
        _c7 = r*math.cos(q2)
        out[0, j, 0] = _c2*r + r*(_c2*_c5 + _c3*_c4) + x
        out[0, j, 1] = -_c6*r + r*(_c0*_c4 - _c5*_c6) + y
        out[0, j, 2] = _c5*_c7 + _c7
    return out


#: operation counts of the Jacobians (derivation/jacobian.py)
OP_COUNTS.update(jacobian=643, jacobian_p=109)

@njit(cache=True)
def jacobian(s, p):
    """d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape (4, 4) (643 operations)."""
    out = np.zeros((4, 4))
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    _c0 = math.sin(q2)
    _d0_0 = math.cos(q2)
    _c1 = _c0**6
    _d1_0 = 6*_c0**5*_d0_0
    _c2 = math.cos(q2)
    _d2_0 = -math.sin(q2)
    _c3 = _c2**6
    _d3_0 = 6*_c2**5*_d2_0
    _c4 = (_c0*_c0)
    _d4_0 = 2*_c0*_d0_0
    _c5 = (_c2*_c2*_c2*_c2)
    _d5_0 = 4*(_c2*_c2*_c2)*_d2_0
    _c6 = _c4*_c5
    _d6_0 = _c4*_d5_0 + _c5*_d4_0
    _c7 = (_c2*_c2)
    _d7_0 = 2*_c2*_d2_0
    _c8 = (_c0*_c0*_c0*_c0)
    _d8_0 = 4*(_c0*_c0*_c0)*_d0_0
    _c9 = _c7*_c8
    _d9_0 = _c7*_d8_0 + _c8*_d7_0
    _c10 = _c4*_c7
    _d10_0 = _c4*_d7_0 + _c7*_d4_0
    _c11 = 1/(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)
    _d11_0 = -2*_d10_0/((4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)*(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)) - 4*_d1_0/((4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)*(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)) - 4*_d3_0/((4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)*(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)) - _d5_0/((4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)*(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)) - 12*_d6_0/((4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)*(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)) - _d8_0/((4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)*(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)) - 12*_d9_0/((4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)*(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9))
    _c12 = _c11*q2_dot/_c2
    _d12_0 = -_c11*_d2_0*q2_dot/(_c2*_c2) + _d11_0*q2_dot/_c2
    _d12_2 = _c11/_c2
    _c13 = _c0**5
    _d13_0 = 5*(_c0*_c0*_c0*_c0)*_d0_0
    _c14 = 4*g
    _c15 = _c0*_c5
    _d15_0 = _c0*_d5_0 + _c5*_d0_0
    _c16 = 6*q3_dot
    _c17 = q1_dot*r
    _c18 = _c16*_c17
    _d18_1 = _c16*r
    _d18_3 = 6*_c17
    _c19 = (_c0*_c0*_c0)
    _d19_0 = 3*(_c0*_c0)*_d0_0
    _c20 = _c19*_c7
    _d20_0 = _c19*_d7_0 + _c7*_d19_0
    _c21 = _c2**5
    _d21_0 = 5*(_c2*_c2*_c2*_c2)*_d2_0
    _c22 = (q1_dot*q1_dot)*r
    _d22_1 = 2*q1_dot*r
    _c23 = 5*_c22
    _d23_1 = 5*_d22_1
    _c24 = 18*_c17*q3_dot
    _d24_1 = 18*q3_dot*r
    _d24_3 = 18*_c17
    _c25 = (_c2*_c2*_c2)
    _d25_0 = 3*(_c2*_c2)*_d2_0
    _c26 = 5*q1_dot
    _c27 = 20*q1_dot
    _c28 = 24*q3_dot
    _c29 = 72*q3_dot
    out[0, 2] = 1
    out[1, 0] = -64*_c0**7*_c12*_d0_0*q3_dot - 32*_c1*_c12*_d7_0*q3_dot - 64*_c12*_c2**7*_d2_0*q3_dot - 32*_c12*_c3*_d4_0*q3_dot - 48*_c12*_c5*_d8_0*q3_dot - 48*_c12*_c8*_d5_0*q3_dot - 2*_c12*_d1_0*q3_dot*(16*_c7 + 1) - 2*_c12*_d3_0*q3_dot*(16*_c4 + 1) - 6*_c12*_d6_0*q3_dot - 6*_c12*_d9_0*q3_dot - 2*_d12_0*q3_dot*(4*_c0**8 + 16*_c1*_c7 + _c1 + 4*_c2**8 + 16*_c3*_c4 + _c3 + 24*_c5*_c8 + 3*_c6 + 3*_c9)
    out[1, 2] = -2*_d12_2*q3_dot*(4*_c0**8 + 16*_c1*_c7 + _c1 + 4*_c2**8 + 16*_c3*_c4 + _c3 + 24*_c5*_c8 + 3*_c6 + 3*_c9)
    out[1, 3] = -2*_c12*(4*_c0**8 + 16*_c1*_c7 + _c1 + 4*_c2**8 + 16*_c3*_c4 + _c3 + 24*_c5*_c8 + 3*_c6 + 3*_c9)
    out[2, 0] = _c11*_c14*_d15_0/r + _c11*_c18*_c2*_d1_0/r + _c11*_c21*_c23*_d0_0/r + _c11*_c21*_c24*_d4_0/r + 10*_c11*_c22*_c25*_d19_0/r + _c11*_c24*_c25*_d8_0/r + _c11*_d13_0*(_c14 + _c2*_c23)/r + 8*_c11*_d20_0*g/r + _c11*_d21_0*(_c0*_c23 + _c24*_c4)/r + _c11*_d25_0*(10*_c19*_c22 + _c24*_c8)/r + _c11*_d2_0*(_c1*_c18 + _c13*_c23 + 7*_c18*_c2**6)/r + _d11_0*(_c0*_c21*_c23 + _c1*_c18*_c2 + _c13*_c14 + _c13*_c2*_c23 + _c14*_c15 + _c18*_c2**7 + 10*_c19*_c22*_c25 + 8*_c20*g + _c21*_c24*_c4 + _c24*_c25*_c8)/r
    out[2, 1] = 10*_c11*_c19*_c25*_d22_1/r + _c11*_d18_1*(_c1*_c2 + _c2**7)/r + _c11*_d23_1*(_c0*_c21 + _c13*_c2)/r + _c11*_d24_1*(_c21*_c4 + _c25*_c8)/r
    out[2, 3] = _c11*_d18_3*(_c1*_c2 + _c2**7)/r + _c11*_d24_3*(_c21*_c4 + _c25*_c8)/r
    out[3, 0] = ((1.0/3.0))*_c12*_c13*_c29*_d7_0 + ((1.0/3.0))*_c12*_c16*_d15_0 - (1.0/3.0)*_c12*_c26*_d10_0 - (1.0/3.0)*_c12*_c27*_d9_0 + ((1.0/3.0))*_c12*_c29*_c5*_d19_0 + ((1.0/3.0))*_c12*_d0_0*(7*_c0**6*_c28 + _c28*_c3) + ((1.0/3.0))*_c12*_d13_0*(_c16 + _c29*_c7) + 4*_c12*_d20_0*q3_dot + ((1.0/3.0))*_c12*_d3_0*(_c0*_c28 - _c27) + ((1.0/3.0))*_c12*_d5_0*(_c19*_c29 - _c26) - (40.0/3.0)*_c12*_d6_0*q1_dot + _d12_0*(((1.0/3.0))*_c0**7*_c28 + ((1.0/3.0))*_c0*_c28*_c3 - (1.0/3.0)*_c10*_c26 + ((1.0/3.0))*_c13*_c16 + ((1.0/3.0))*_c13*_c29*_c7 + ((1.0/3.0))*_c15*_c16 + ((1.0/3.0))*_c19*_c29*_c5 + 4*_c20*q3_dot - (1.0/3.0)*_c26*_c5 - (1.0/3.0)*_c27*_c3 - (1.0/3.0)*_c27*_c9 - (40.0/3.0)*_c6*q1_dot)
    out[3, 1] = -(40.0/3.0)*_c12*_c6 + ((5.0/3.0))*_c12*(-_c10 - _c5) + ((20.0/3.0))*_c12*(-_c3 - _c9)
    out[3, 2] = _d12_2*(((1.0/3.0))*_c0**7*_c28 + ((1.0/3.0))*_c0*_c28*_c3 - (1.0/3.0)*_c10*_c26 + ((1.0/3.0))*_c13*_c16 + ((1.0/3.0))*_c13*_c29*_c7 + ((1.0/3.0))*_c15*_c16 + ((1.0/3.0))*_c19*_c29*_c5 + 4*_c20*q3_dot - (1.0/3.0)*_c26*_c5 - (1.0/3.0)*_c27*_c3 - (1.0/3.0)*_c27*_c9 - (40.0/3.0)*_c6*q1_dot)
    out[3, 3] = 4*_c12*_c20 + 8*_c12*(_c0**7 + _c0*_c3) + 2*_c12*(_c13 + _c15) + 24*_c12*(_c13*_c7 + _c19*_c5)
    return out


@njit(cache=True)
def jacobian_p(s, p):
    """d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape (4, 2) (109 operations)."""
    out = np.zeros((4, 2))
    q2 = s[0]
    q1_dot = s[1]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    _c0 = math.sin(q2)
    _c1 = _c0**6
    _c2 = math.cos(q2)
    _c3 = _c2**6
    _c4 = (_c0*_c0)
    _c5 = (_c2*_c2*_c2*_c2)
    _c6 = _c4*_c5
    _c7 = (_c2*_c2)
    _c8 = (_c0*_c0*_c0*_c0)
    _c9 = _c7*_c8
    _c10 = _c4*_c7
    _c11 = 1/(4*_c1 + 2*_c10 + 4*_c3 + _c5 + 12*_c6 + _c8 + 12*_c9)
    _c13 = _c0**5
    _c14 = 4*g
    _c15 = _c0*_c5
    _c16 = 6*q3_dot
    _c17 = q1_dot*r
    _c18 = _c16*_c17
    _d18_1 = _c16*q1_dot
    _c19 = (_c0*_c0*_c0)
    _c20 = _c19*_c7
    _c21 = _c2**5
    _c22 = (q1_dot*q1_dot)*r
    _d22_1 = (q1_dot*q1_dot)
    _c23 = 5*_c22
    _d23_1 = 5*_d22_1
    _c24 = 18*_c17*q3_dot
    _d24_1 = 18*q1_dot*q3_dot
    _c25 = (_c2*_c2*_c2)
    out[2, 0] = 8*_c11*_c20/r + 4*_c11*(_c13 + _c15)/r
    out[2, 1] = 10*_c11*_c19*_c25*_d22_1/r + _c11*_d18_1*(_c1*_c2 + _c2**7)/r + _c11*_d23_1*(_c0*_c21 + _c13*_c2)/r + _c11*_d24_1*(_c21*_c4 + _c25*_c8)/r - _c11*(_c0*_c21*_c23 + _c1*_c18*_c2 + _c13*_c14 + _c13*_c2*_c23 + _c14*_c15 + _c18*_c2**7 + 10*_c19*_c22*_c25 + 8*_c20*g + _c21*_c24*_c4 + _c24*_c25*_c8)/(r*r)
    return out



#: families of steady motions (derivation/steady.py): name -> the family's parameter ``value`` (``value_state`` is
#: the state equal to it), what the motion is, and names of the modes by their largest state
STEADY_FAMILIES = {'upright_rolling': {'value': 'Omega', 'value_state': 'q3_dot', 'description': 'upright rolling (q2 = 0) in a straight line at the axle rate Omega', 'mode_names': {'q2': 'lean', 'q2_dot': 'lean'}}}


@njit(cache=True)
def steady_state(_family, _value, p):
    """Row 0: the closed state of family number ``_family`` of STEADY_FAMILIES at ``_value``; row 1: its derivative
    in ``_value`` (the family's tangent)."""
    out = np.zeros((2, 4))
    g = p[0]
    r = p[1]
    if _family == 0:
        Omega = _value
        out[0, 3] = Omega
        out[1, 3] = 1

    return out


#: functions of the closed state fixed by construction; their gradients are not physical directions
STATE_INVARIANTS = ()


@njit(cache=True)
def invariant_gradients(s, p):
    """Gradients of STATE_INVARIANTS, shape (0, 4)."""
    out = np.zeros((0, 4))
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]

    return out
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = 'b55fff3435a12f15e3853dd773963a5a74a61c1ea91580991deddb12e0b68d80'
