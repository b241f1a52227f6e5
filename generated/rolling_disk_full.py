"""rolling_disk, fidelity full: exact consequences of the model's Lagrangian and constraints, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from examples/rolling_disk.py (model 'rolling_disk',
constraints no_slip_along, no_slip_across) through derivation/engine.py.
Accelerations and multipliers in closed form (symbolic elimination of the multipliers).
SymPy 1.14.0; input hash sha256:7154390682f5b63c57cf9f3fd598d0a6ccf240c5b224d5ab287c1f715bf20e20

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
INPUT_HASH = '7154390682f5b63c57cf9f3fd598d0a6ccf240c5b224d5ab287c1f715bf20e20'
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


#: operation counts of the Jacobians and of the Jacobian-vector product, once and per column (derivation/jacobian.py)
OP_COUNTS.update(jacobian=643, jacobian_p=109, jvp_once=369, jvp_column=150)

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


@njit(cache=True)
def jvp_into(s, p, _V, ds, out):
    """Write d(state)/dt into ``ds`` and ``J(s) _V`` into ``out`` (``_V``, ``out``: (4, k)), the derivatives of the rates along the columns of ``_V`` by forward mode through the right-hand side (369 operations once, 150 per column)."""
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
    _p0 = (_c11*_c11)
    _p1 = 1/_c2
    _p2 = (_c2*_c2)
    _p3 = _c12*q3_dot
    _p4 = 16*_c7
    _p5 = 16*_c4
    _p6 = 8*_c0**8 + 2*_c1*_p4 + 2*_c1 + 8*_c2**8 + 2*_c3*_p5 + 2*_c3 + 48*_c5*_c8 + 6*_c6 + 6*_c9
    _p7 = _c0**7
    _p8 = 64*_p3
    _p9 = _c2**7
    _p10 = 48*_p3
    _p11 = 32*_p3
    _p12 = 2*_p3
    _p13 = 1/r
    _p14 = 8*g
    _p15 = _c0*_c23
    _p16 = _c1*_c2
    _p17 = _c2*_c23
    _p18 = _c24*_c4
    _p19 = _c25*_c8
    _p20 = 10*_c19
    _p21 = _c22*_p20
    _p22 = _c11*_p13
    _p23 = _c21*_p22
    _p24 = _c25*_p22
    _p25 = ((1.0/3.0))*_c26
    _p26 = ((1.0/3.0))*_c16
    _p27 = 4*_c20
    _p28 = ((1.0/3.0))*_c27
    _p29 = ((40.0/3.0))*_c6
    _p30 = _c28*_c3
    _p31 = _c29*_c7
    _p32 = _c19*_c5
    _p33 = ((1.0/3.0))*_c12
    _p34 = _c29*_p33
    _k0 = math.cos(q2)
    _k1 = 6*_c0**5
    _k2 = -math.sin(q2)
    _k3 = 6*_c2**5
    _k4 = 2*_c0
    _k5 = 4*(_c2*_c2*_c2)
    _k6 = 2*_c2
    _k7 = 4*(_c0*_c0*_c0)
    _k8 = -_p0
    _k9 = -12*_p0
    _k10 = -4*_p0
    _k11 = -2*_p0
    _k12 = _c11*_p1
    _k13 = _p1*q2_dot
    _k14 = -_c11*q2_dot/_p2
    _k15 = 5*(_c0*_c0*_c0*_c0)
    _k16 = 3*(_c0*_c0)
    _k17 = 5*(_c2*_c2*_c2*_c2)
    _k18 = 2*q1_dot*r
    _k19 = 18*_c17
    _k20 = 18*q3_dot
    _k21 = 3*_p2
    _k22 = -6*_p3
    _k23 = -_c12*_p6
    _k24 = -_p6*q3_dot
    _k25 = -_p7*_p8
    _k26 = -_p8*_p9
    _k27 = -_c5*_p10
    _k28 = -_c8*_p10
    _k29 = -_c1*_p11
    _k30 = -_c3*_p11
    _k31 = -_p12*(_p4 + 1)
    _k32 = -_p12*(_p5 + 1)
    _k33 = _p13*(_c13*_c14 + _c13*_p17 + _c14*_c15 + _c18*_p16 + _c18*_p9 + _c20*_p14 + _c21*_p15 + _c21*_p18 + _c24*_p19 + _c25*_p21)
    _k34 = _c14*_p22
    _k35 = _p22*(_c14 + _p17)
    _k36 = _p22*(_p16 + _p9)
    _k37 = _p22*(_c1*_c18 + _c13*_c23 + 7*_c18*_c2**6)
    _k38 = _p22*(_p15 + _p18)
    _k39 = _p22*(_c0*_c21 + _c13*_c2)
    _k40 = _p22*(_c21*_c4 + _p19)
    _k41 = _p22*(_c24*_c8 + _p21)
    _k42 = _p14*_p22
    _k43 = _c18*_c2*_p22
    _k44 = _c23*_p23
    _k45 = _c24*_p23
    _k46 = _c24*_p24
    _k47 = _p20*_p24
    _k48 = 10*_c22*_p24
    _k49 = ((1.0/3.0))*_c0*_p30 - _c10*_p25 + _c13*_p26 + ((1.0/3.0))*_c13*_p31 + _c15*_p26 + ((1.0/3.0))*_c28*_p7 + ((1.0/3.0))*_c29*_p32 - _c3*_p28 - _c5*_p25 - _c9*_p28 + _p27*q3_dot - _p29*q1_dot
    _k50 = _c12*_p27
    _k51 = 4*_p3
    _k52 = -_c12*_p29
    _k53 = -(40.0/3.0)*_c12*q1_dot
    _k54 = -_c12*_p25
    _k55 = -_c12*_p28
    _k56 = _c12*_p26
    _k57 = _p33*(7*_c0**6*_c28 + _p30)
    _k58 = _p33*(_c16 + _p31)
    _k59 = _p33*(_c13 + _c15)
    _k60 = _p33*(-_c10 - _c5)
    _k61 = _p33*(-_c3 - _c9)
    _k62 = _p33*(_c0*_c3 + _p7)
    _k63 = _p33*(_c13*_c7 + _p32)
    _k64 = _p33*(_c0*_c28 - _c27)
    _k65 = _p33*(_c19*_c29 - _c26)
    _k66 = _c13*_p34
    _k67 = _c5*_p34
    ds[0] = q2_dot
    ds[1] = -2*_c12*q3_dot*(4*_c0**8 + 16*_c1*_c7 + _c1 + 4*_c2**8 + 16*_c3*_c4 + _c3 + 24*_c5*_c8 + 3*_c6 + 3*_c9)
    ds[2] = _c11*(_c0*_c21*_c23 + _c1*_c18*_c2 + _c13*_c14 + _c13*_c2*_c23 + _c14*_c15 + _c18*_c2**7 + 10*_c19*_c22*_c25 + 8*_c20*g + _c21*_c24*_c4 + _c24*_c25*_c8)/r
    ds[3] = ((1.0/3.0))*_c12*(_c0**7*_c28 + _c0*_c28*_c3 - _c10*_c26 + _c13*_c16 + _c13*_c29*_c7 + _c15*_c16 + _c19*_c29*_c5 + 12*_c20*q3_dot - _c26*_c5 - _c27*_c3 - _c27*_c9 - 40*_c6*q1_dot)
    for _j in range(_V.shape[1]):
        _v0 = _V[0, _j]
        _v1 = _V[1, _j]
        _v2 = _V[2, _j]
        _v3 = _V[3, _j]
        _t0 = _k0*_v0
        _t1 = _k1*_t0
        _t2 = _k2*_v0
        _t3 = _k3*_t2
        _t4 = _k4*_t0
        _t5 = _k5*_t2
        _t6 = _c4*_t5 + _c5*_t4
        _t7 = _k6*_t2
        _t8 = _k7*_t0
        _t9 = _c7*_t8 + _c8*_t7
        _t10 = _c4*_t7 + _c7*_t4
        _t11 = _k10*_t1 + _k10*_t3 + _k11*_t10 + _k8*_t5 + _k8*_t8 + _k9*_t6 + _k9*_t9
        _t12 = _k12*_v2 + _k13*_t11 + _k14*_t2
        _t13 = _k15*_t0
        _t15 = _c0*_t5 + _c5*_t0
        _t16 = 6*_v3
        _t17 = _v1*r
        _t18 = _c16*_t17 + _c17*_t16
        _t19 = _k16*_t0
        _t20 = _c19*_t7 + _c7*_t19
        _t21 = _k17*_t2
        _t22 = _k18*_v1
        _t23 = 5*_t22
        _t24 = _k19*_v3 + _k20*_t17
        _t25 = _k21*_t2
        _t26 = 5*_v1
        _t27 = 20*_v1
        _t28 = 24*_v3
        _t29 = 72*_v3
        out[0, _j] = _v2
        out[1, _j] = _k22*_t6 + _k22*_t9 + _k23*_v3 + _k24*_t12 + _k25*_t0 + _k26*_t2 + _k27*_t8 + _k28*_t5 + _k29*_t7 + _k30*_t4 + _k31*_t1 + _k32*_t3
        out[2, _j] = _k33*_t11 + _k34*_t15 + _k35*_t13 + _k36*_t18 + _k37*_t2 + _k38*_t21 + _k39*_t23 + _k40*_t24 + _k41*_t25 + _k42*_t20 + _k43*_t1 + _k44*_t0 + _k45*_t4 + _k46*_t8 + _k47*_t22 + _k48*_t19
        out[3, _j] = _k49*_t12 + _k50*_v3 + _k51*_t20 + _k52*_v1 + _k53*_t6 + _k54*_t10 + _k55*_t9 + _k56*_t15 + _k57*_t0 + _k58*_t13 + _k59*_t16 + _k60*_t26 + _k61*_t27 + _k62*_t28 + _k63*_t29 + _k64*_t3 + _k65*_t5 + _k66*_t7 + _k67*_t19


@njit(cache=True)
def jvp1_into(s, p, _v, ds, _dv):
    """``jvp_into`` of one column: d(state)/dt into ``ds`` and ``J(s) _v`` into ``_dv`` (vectors of length 4; 519 operations)."""
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
    _p0 = (_c11*_c11)
    _p1 = 1/_c2
    _p2 = (_c2*_c2)
    _p3 = _c12*q3_dot
    _p4 = 16*_c7
    _p5 = 16*_c4
    _p6 = 8*_c0**8 + 2*_c1*_p4 + 2*_c1 + 8*_c2**8 + 2*_c3*_p5 + 2*_c3 + 48*_c5*_c8 + 6*_c6 + 6*_c9
    _p7 = _c0**7
    _p8 = 64*_p3
    _p9 = _c2**7
    _p10 = 48*_p3
    _p11 = 32*_p3
    _p12 = 2*_p3
    _p13 = 1/r
    _p14 = 8*g
    _p15 = _c0*_c23
    _p16 = _c1*_c2
    _p17 = _c2*_c23
    _p18 = _c24*_c4
    _p19 = _c25*_c8
    _p20 = 10*_c19
    _p21 = _c22*_p20
    _p22 = _c11*_p13
    _p23 = _c21*_p22
    _p24 = _c25*_p22
    _p25 = ((1.0/3.0))*_c26
    _p26 = ((1.0/3.0))*_c16
    _p27 = 4*_c20
    _p28 = ((1.0/3.0))*_c27
    _p29 = ((40.0/3.0))*_c6
    _p30 = _c28*_c3
    _p31 = _c29*_c7
    _p32 = _c19*_c5
    _p33 = ((1.0/3.0))*_c12
    _p34 = _c29*_p33
    _k0 = math.cos(q2)
    _k1 = 6*_c0**5
    _k2 = -math.sin(q2)
    _k3 = 6*_c2**5
    _k4 = 2*_c0
    _k5 = 4*(_c2*_c2*_c2)
    _k6 = 2*_c2
    _k7 = 4*(_c0*_c0*_c0)
    _k8 = -_p0
    _k9 = -12*_p0
    _k10 = -4*_p0
    _k11 = -2*_p0
    _k12 = _c11*_p1
    _k13 = _p1*q2_dot
    _k14 = -_c11*q2_dot/_p2
    _k15 = 5*(_c0*_c0*_c0*_c0)
    _k16 = 3*(_c0*_c0)
    _k17 = 5*(_c2*_c2*_c2*_c2)
    _k18 = 2*q1_dot*r
    _k19 = 18*_c17
    _k20 = 18*q3_dot
    _k21 = 3*_p2
    _k22 = -6*_p3
    _k23 = -_c12*_p6
    _k24 = -_p6*q3_dot
    _k25 = -_p7*_p8
    _k26 = -_p8*_p9
    _k27 = -_c5*_p10
    _k28 = -_c8*_p10
    _k29 = -_c1*_p11
    _k30 = -_c3*_p11
    _k31 = -_p12*(_p4 + 1)
    _k32 = -_p12*(_p5 + 1)
    _k33 = _p13*(_c13*_c14 + _c13*_p17 + _c14*_c15 + _c18*_p16 + _c18*_p9 + _c20*_p14 + _c21*_p15 + _c21*_p18 + _c24*_p19 + _c25*_p21)
    _k34 = _c14*_p22
    _k35 = _p22*(_c14 + _p17)
    _k36 = _p22*(_p16 + _p9)
    _k37 = _p22*(_c1*_c18 + _c13*_c23 + 7*_c18*_c2**6)
    _k38 = _p22*(_p15 + _p18)
    _k39 = _p22*(_c0*_c21 + _c13*_c2)
    _k40 = _p22*(_c21*_c4 + _p19)
    _k41 = _p22*(_c24*_c8 + _p21)
    _k42 = _p14*_p22
    _k43 = _c18*_c2*_p22
    _k44 = _c23*_p23
    _k45 = _c24*_p23
    _k46 = _c24*_p24
    _k47 = _p20*_p24
    _k48 = 10*_c22*_p24
    _k49 = ((1.0/3.0))*_c0*_p30 - _c10*_p25 + _c13*_p26 + ((1.0/3.0))*_c13*_p31 + _c15*_p26 + ((1.0/3.0))*_c28*_p7 + ((1.0/3.0))*_c29*_p32 - _c3*_p28 - _c5*_p25 - _c9*_p28 + _p27*q3_dot - _p29*q1_dot
    _k50 = _c12*_p27
    _k51 = 4*_p3
    _k52 = -_c12*_p29
    _k53 = -(40.0/3.0)*_c12*q1_dot
    _k54 = -_c12*_p25
    _k55 = -_c12*_p28
    _k56 = _c12*_p26
    _k57 = _p33*(7*_c0**6*_c28 + _p30)
    _k58 = _p33*(_c16 + _p31)
    _k59 = _p33*(_c13 + _c15)
    _k60 = _p33*(-_c10 - _c5)
    _k61 = _p33*(-_c3 - _c9)
    _k62 = _p33*(_c0*_c3 + _p7)
    _k63 = _p33*(_c13*_c7 + _p32)
    _k64 = _p33*(_c0*_c28 - _c27)
    _k65 = _p33*(_c19*_c29 - _c26)
    _k66 = _c13*_p34
    _k67 = _c5*_p34
    ds[0] = q2_dot
    ds[1] = -2*_c12*q3_dot*(4*_c0**8 + 16*_c1*_c7 + _c1 + 4*_c2**8 + 16*_c3*_c4 + _c3 + 24*_c5*_c8 + 3*_c6 + 3*_c9)
    ds[2] = _c11*(_c0*_c21*_c23 + _c1*_c18*_c2 + _c13*_c14 + _c13*_c2*_c23 + _c14*_c15 + _c18*_c2**7 + 10*_c19*_c22*_c25 + 8*_c20*g + _c21*_c24*_c4 + _c24*_c25*_c8)/r
    ds[3] = ((1.0/3.0))*_c12*(_c0**7*_c28 + _c0*_c28*_c3 - _c10*_c26 + _c13*_c16 + _c13*_c29*_c7 + _c15*_c16 + _c19*_c29*_c5 + 12*_c20*q3_dot - _c26*_c5 - _c27*_c3 - _c27*_c9 - 40*_c6*q1_dot)
    _v0 = _v[0]
    _v1 = _v[1]
    _v2 = _v[2]
    _v3 = _v[3]
    _t0 = _k0*_v0
    _t1 = _k1*_t0
    _t2 = _k2*_v0
    _t3 = _k3*_t2
    _t4 = _k4*_t0
    _t5 = _k5*_t2
    _t6 = _c4*_t5 + _c5*_t4
    _t7 = _k6*_t2
    _t8 = _k7*_t0
    _t9 = _c7*_t8 + _c8*_t7
    _t10 = _c4*_t7 + _c7*_t4
    _t11 = _k10*_t1 + _k10*_t3 + _k11*_t10 + _k8*_t5 + _k8*_t8 + _k9*_t6 + _k9*_t9
    _t12 = _k12*_v2 + _k13*_t11 + _k14*_t2
    _t13 = _k15*_t0
    _t15 = _c0*_t5 + _c5*_t0
    _t16 = 6*_v3
    _t17 = _v1*r
    _t18 = _c16*_t17 + _c17*_t16
    _t19 = _k16*_t0
    _t20 = _c19*_t7 + _c7*_t19
    _t21 = _k17*_t2
    _t22 = _k18*_v1
    _t23 = 5*_t22
    _t24 = _k19*_v3 + _k20*_t17
    _t25 = _k21*_t2
    _t26 = 5*_v1
    _t27 = 20*_v1
    _t28 = 24*_v3
    _t29 = 72*_v3
    _dv[0] = _v2
    _dv[1] = _k22*_t6 + _k22*_t9 + _k23*_v3 + _k24*_t12 + _k25*_t0 + _k26*_t2 + _k27*_t8 + _k28*_t5 + _k29*_t7 + _k30*_t4 + _k31*_t1 + _k32*_t3
    _dv[2] = _k33*_t11 + _k34*_t15 + _k35*_t13 + _k36*_t18 + _k37*_t2 + _k38*_t21 + _k39*_t23 + _k40*_t24 + _k41*_t25 + _k42*_t20 + _k43*_t1 + _k44*_t0 + _k45*_t4 + _k46*_t8 + _k47*_t22 + _k48*_t19
    _dv[3] = _k49*_t12 + _k50*_v3 + _k51*_t20 + _k52*_v1 + _k53*_t6 + _k54*_t10 + _k55*_t9 + _k56*_t15 + _k57*_t0 + _k58*_t13 + _k59*_t16 + _k60*_t26 + _k61*_t27 + _k62*_t28 + _k63*_t29 + _k64*_t3 + _k65*_t5 + _k66*_t7 + _k67*_t19



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
        '  %v9 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  %v10 = load double, ptr %v9\n'
        '  %v11 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  %v12 = load double, ptr %v11\n'
        '  %v13 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  %v14 = load double, ptr %v13\n'
        '  %v15 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  %v16 = load double, ptr %v15\n'
        '  %v17 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  %v18 = load double, ptr %v17\n'
        '  %v19 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  %v20 = load double, ptr %v19\n'
        '  %v21 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  %v22 = load double, ptr %v21\n'
        '  %v23 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  %v24 = load double, ptr %v23\n'
        '  %v25 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  %v26 = load double, ptr %v25\n'
        '  %v27 = call double @llvm.sin.f64(double %v2)\n'
        '  %v28 = fmul double %v27, %v27\n'
        '  %v29 = fmul double 0x3FF0000000000000, %v28\n'
        '  %v30 = fmul double %v28, %v28\n'
        '  %v31 = fmul double %v29, %v30\n'
        '  %v32 = call double @llvm.cos.f64(double %v2)\n'
        '  %v33 = fmul double %v32, %v32\n'
        '  %v34 = fmul double 0x3FF0000000000000, %v33\n'
        '  %v35 = fmul double %v33, %v33\n'
        '  %v36 = fmul double %v34, %v35\n'
        '  %v37 = fmul double %v27, %v27\n'
        '  %v38 = fmul double %v32, %v32\n'
        '  %v39 = fmul double %v38, %v32\n'
        '  %v40 = fmul double %v39, %v32\n'
        '  %v41 = fmul double %v37, %v40\n'
        '  %v42 = fmul double %v32, %v32\n'
        '  %v43 = fmul double %v27, %v27\n'
        '  %v44 = fmul double %v43, %v27\n'
        '  %v45 = fmul double %v44, %v27\n'
        '  %v46 = fmul double %v42, %v45\n'
        '  %v47 = fmul double %v37, %v42\n'
        '  %v48 = fmul double 0x4010000000000000, %v31\n'
        '  %v49 = fmul double 0x4000000000000000, %v47\n'
        '  %v50 = fadd double %v48, %v49\n'
        '  %v51 = fmul double 0x4010000000000000, %v36\n'
        '  %v52 = fadd double %v50, %v51\n'
        '  %v53 = fadd double %v52, %v40\n'
        '  %v54 = fmul double 0x4028000000000000, %v41\n'
        '  %v55 = fadd double %v53, %v54\n'
        '  %v56 = fadd double %v55, %v45\n'
        '  %v57 = fmul double 0x4028000000000000, %v46\n'
        '  %v58 = fadd double %v56, %v57\n'
        '  %v59 = fdiv double 0x3FF0000000000000, %v58\n'
        '  %v60 = fmul double %v59, %v6\n'
        '  %v61 = fdiv double %v60, %v32\n'
        '  %v62 = fmul double 0x3FF0000000000000, %v27\n'
        '  %v63 = fmul double %v27, %v27\n'
        '  %v64 = fmul double %v63, %v63\n'
        '  %v65 = fmul double %v62, %v64\n'
        '  %v66 = fmul double %v27, %v40\n'
        '  %v67 = fmul double %v4, %v8\n'
        '  %v68 = fmul double %v67, %v20\n'
        '  %v69 = fmul double %v27, %v27\n'
        '  %v70 = fmul double %v69, %v27\n'
        '  %v71 = fmul double %v70, %v42\n'
        '  %v72 = fmul double 0x3FF0000000000000, %v32\n'
        '  %v73 = fmul double %v32, %v32\n'
        '  %v74 = fmul double %v73, %v73\n'
        '  %v75 = fmul double %v72, %v74\n'
        '  %v76 = fmul double %v4, %v4\n'
        '  %v77 = fmul double %v76, %v18\n'
        '  %v78 = fmul double %v67, %v24\n'
        '  %v79 = fmul double %v32, %v32\n'
        '  %v80 = fmul double %v79, %v32\n'
        '  %v81 = fmul double 0x4014000000000000, %v4\n'
        '  %v82 = fmul double 0x4034000000000000, %v4\n'
        '  %v83 = fmul double 0x4018000000000000, %v8\n'
        '  %v84 = fmul double 0x4038000000000000, %v8\n'
        '  %v85 = fmul double 0x4052000000000000, %v8\n'
        '  %v86 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v6, ptr %v86\n'
        '  %v87 = fmul double 0xC000000000000000, %v61\n'
        '  %v88 = fmul double %v87, %v8\n'
        '  %v89 = fmul double %v27, %v27\n'
        '  %v90 = fmul double %v89, %v89\n'
        '  %v91 = fmul double %v90, %v90\n'
        '  %v92 = fmul double 0x3FF0000000000000, %v91\n'
        '  %v93 = fmul double 0x4010000000000000, %v92\n'
        '  %v94 = fmul double 0x4030000000000000, %v31\n'
        '  %v95 = fmul double %v94, %v42\n'
        '  %v96 = fadd double %v93, %v95\n'
        '  %v97 = fadd double %v96, %v31\n'
        '  %v98 = fmul double %v32, %v32\n'
        '  %v99 = fmul double %v98, %v98\n'
        '  %v100 = fmul double %v99, %v99\n'
        '  %v101 = fmul double 0x3FF0000000000000, %v100\n'
        '  %v102 = fmul double 0x4010000000000000, %v101\n'
        '  %v103 = fadd double %v97, %v102\n'
        '  %v104 = fmul double 0x4030000000000000, %v36\n'
        '  %v105 = fmul double %v104, %v37\n'
        '  %v106 = fadd double %v103, %v105\n'
        '  %v107 = fadd double %v106, %v36\n'
        '  %v108 = fmul double 0x4038000000000000, %v40\n'
        '  %v109 = fmul double %v108, %v45\n'
        '  %v110 = fadd double %v107, %v109\n'
        '  %v111 = fmul double 0x4008000000000000, %v41\n'
        '  %v112 = fadd double %v110, %v111\n'
        '  %v113 = fmul double 0x4008000000000000, %v46\n'
        '  %v114 = fadd double %v112, %v113\n'
        '  %v115 = fmul double %v88, %v114\n'
        '  %v116 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v115, ptr %v116\n'
        '  %v117 = fmul double %v59, %v26\n'
        '  %v118 = fmul double %v27, %v75\n'
        '  %v119 = fmul double %v118, %v77\n'
        '  %v120 = fmul double %v31, %v68\n'
        '  %v121 = fmul double %v120, %v32\n'
        '  %v122 = fadd double %v119, %v121\n'
        '  %v123 = fmul double %v65, %v32\n'
        '  %v124 = fmul double %v123, %v77\n'
        '  %v125 = fadd double %v122, %v124\n'
        '  %v126 = fmul double %v65, %v14\n'
        '  %v127 = fadd double %v125, %v126\n'
        '  %v128 = fmul double %v66, %v14\n'
        '  %v129 = fadd double %v127, %v128\n'
        '  %v130 = fmul double 0x3FF0000000000000, %v32\n'
        '  %v131 = fmul double %v32, %v32\n'
        '  %v132 = fmul double %v130, %v131\n'
        '  %v133 = fmul double %v131, %v131\n'
        '  %v134 = fmul double %v132, %v133\n'
        '  %v135 = fmul double %v68, %v134\n'
        '  %v136 = fadd double %v129, %v135\n'
        '  %v137 = fmul double %v70, %v76\n'
        '  %v138 = fmul double %v137, %v80\n'
        '  %v139 = fmul double %v138, %v22\n'
        '  %v140 = fadd double %v136, %v139\n'
        '  %v141 = fmul double %v71, %v16\n'
        '  %v142 = fadd double %v140, %v141\n'
        '  %v143 = fmul double %v75, %v78\n'
        '  %v144 = fmul double %v143, %v37\n'
        '  %v145 = fadd double %v142, %v144\n'
        '  %v146 = fmul double %v78, %v80\n'
        '  %v147 = fmul double %v146, %v45\n'
        '  %v148 = fadd double %v145, %v147\n'
        '  %v149 = fmul double %v117, %v148\n'
        '  %v150 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v149, ptr %v150\n'
        '  %v151 = fmul double 0x3FD5555555555555, %v61\n'
        '  %v152 = fmul double 0x3FF0000000000000, %v27\n'
        '  %v153 = fmul double %v27, %v27\n'
        '  %v154 = fmul double %v152, %v153\n'
        '  %v155 = fmul double %v153, %v153\n'
        '  %v156 = fmul double %v154, %v155\n'
        '  %v157 = fmul double %v156, %v84\n'
        '  %v158 = fmul double %v27, %v84\n'
        '  %v159 = fmul double %v158, %v36\n'
        '  %v160 = fadd double %v157, %v159\n'
        '  %v161 = fmul double %v47, %v81\n'
        '  %v162 = fsub double %v160, %v161\n'
        '  %v163 = fmul double %v65, %v83\n'
        '  %v164 = fadd double %v162, %v163\n'
        '  %v165 = fmul double %v65, %v85\n'
        '  %v166 = fmul double %v165, %v42\n'
        '  %v167 = fadd double %v164, %v166\n'
        '  %v168 = fmul double %v66, %v83\n'
        '  %v169 = fadd double %v167, %v168\n'
        '  %v170 = fmul double %v70, %v85\n'
        '  %v171 = fmul double %v170, %v40\n'
        '  %v172 = fadd double %v169, %v171\n'
        '  %v173 = fmul double 0x4028000000000000, %v71\n'
        '  %v174 = fmul double %v173, %v8\n'
        '  %v175 = fadd double %v172, %v174\n'
        '  %v176 = fmul double %v81, %v40\n'
        '  %v177 = fsub double %v175, %v176\n'
        '  %v178 = fmul double %v82, %v36\n'
        '  %v179 = fsub double %v177, %v178\n'
        '  %v180 = fmul double %v82, %v46\n'
        '  %v181 = fsub double %v179, %v180\n'
        '  %v182 = fmul double 0x4044000000000000, %v41\n'
        '  %v183 = fmul double %v182, %v4\n'
        '  %v184 = fsub double %v181, %v183\n'
        '  %v185 = fmul double %v151, %v184\n'
        '  %v186 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v185, ptr %v186\n'
        '  ret i32 0\n'
        '}\n'
        'declare double @llvm.cos.f64(double)\n'
        'declare double @llvm.sin.f64(double)\n'
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
        '  %v35 = call double @llvm.sin.f64(double %v2)\n'
        '  %v36 = fmul double %v35, %v35\n'
        '  %v37 = fmul double 0x3FF0000000000000, %v36\n'
        '  %v38 = fmul double %v36, %v36\n'
        '  %v39 = fmul double %v37, %v38\n'
        '  %v40 = call double @llvm.cos.f64(double %v2)\n'
        '  %v41 = fmul double %v40, %v40\n'
        '  %v42 = fmul double 0x3FF0000000000000, %v41\n'
        '  %v43 = fmul double %v41, %v41\n'
        '  %v44 = fmul double %v42, %v43\n'
        '  %v45 = fmul double %v35, %v35\n'
        '  %v46 = fmul double %v40, %v40\n'
        '  %v47 = fmul double %v46, %v40\n'
        '  %v48 = fmul double %v47, %v40\n'
        '  %v49 = fmul double %v45, %v48\n'
        '  %v50 = fmul double %v40, %v40\n'
        '  %v51 = fmul double %v35, %v35\n'
        '  %v52 = fmul double %v51, %v35\n'
        '  %v53 = fmul double %v52, %v35\n'
        '  %v54 = fmul double %v50, %v53\n'
        '  %v55 = fmul double %v45, %v50\n'
        '  %v56 = fmul double 0x4010000000000000, %v39\n'
        '  %v57 = fmul double 0x4000000000000000, %v55\n'
        '  %v58 = fadd double %v56, %v57\n'
        '  %v59 = fmul double 0x4010000000000000, %v44\n'
        '  %v60 = fadd double %v58, %v59\n'
        '  %v61 = fadd double %v60, %v48\n'
        '  %v62 = fmul double 0x4028000000000000, %v49\n'
        '  %v63 = fadd double %v61, %v62\n'
        '  %v64 = fadd double %v63, %v53\n'
        '  %v65 = fmul double 0x4028000000000000, %v54\n'
        '  %v66 = fadd double %v64, %v65\n'
        '  %v67 = fdiv double 0x3FF0000000000000, %v66\n'
        '  %v68 = fmul double %v67, %v6\n'
        '  %v69 = fdiv double %v68, %v40\n'
        '  %v70 = fmul double 0x3FF0000000000000, %v35\n'
        '  %v71 = fmul double %v35, %v35\n'
        '  %v72 = fmul double %v71, %v71\n'
        '  %v73 = fmul double %v70, %v72\n'
        '  %v74 = fmul double %v35, %v48\n'
        '  %v75 = fmul double %v4, %v8\n'
        '  %v76 = fmul double %v75, %v28\n'
        '  %v77 = fmul double %v35, %v35\n'
        '  %v78 = fmul double %v77, %v35\n'
        '  %v79 = fmul double %v78, %v50\n'
        '  %v80 = fmul double 0x3FF0000000000000, %v40\n'
        '  %v81 = fmul double %v40, %v40\n'
        '  %v82 = fmul double %v81, %v81\n'
        '  %v83 = fmul double %v80, %v82\n'
        '  %v84 = fmul double %v4, %v4\n'
        '  %v85 = fmul double %v84, %v26\n'
        '  %v86 = fmul double %v75, %v32\n'
        '  %v87 = fmul double %v40, %v40\n'
        '  %v88 = fmul double %v87, %v40\n'
        '  %v89 = fmul double 0x4014000000000000, %v4\n'
        '  %v90 = fmul double 0x4034000000000000, %v4\n'
        '  %v91 = fmul double 0x4018000000000000, %v8\n'
        '  %v92 = fmul double 0x4038000000000000, %v8\n'
        '  %v93 = fmul double 0x4052000000000000, %v8\n'
        '  %v94 = fmul double %v8, %v20\n'
        '  %v95 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v6, ptr %v95\n'
        '  %v96 = fmul double 0xC000000000000000, %v69\n'
        '  %v97 = fmul double %v96, %v8\n'
        '  %v98 = fmul double %v35, %v35\n'
        '  %v99 = fmul double %v98, %v98\n'
        '  %v100 = fmul double %v99, %v99\n'
        '  %v101 = fmul double 0x3FF0000000000000, %v100\n'
        '  %v102 = fmul double 0x4010000000000000, %v101\n'
        '  %v103 = fmul double 0x4030000000000000, %v39\n'
        '  %v104 = fmul double %v103, %v50\n'
        '  %v105 = fadd double %v102, %v104\n'
        '  %v106 = fadd double %v105, %v39\n'
        '  %v107 = fmul double %v40, %v40\n'
        '  %v108 = fmul double %v107, %v107\n'
        '  %v109 = fmul double %v108, %v108\n'
        '  %v110 = fmul double 0x3FF0000000000000, %v109\n'
        '  %v111 = fmul double 0x4010000000000000, %v110\n'
        '  %v112 = fadd double %v106, %v111\n'
        '  %v113 = fmul double 0x4030000000000000, %v44\n'
        '  %v114 = fmul double %v113, %v45\n'
        '  %v115 = fadd double %v112, %v114\n'
        '  %v116 = fadd double %v115, %v44\n'
        '  %v117 = fmul double 0x4038000000000000, %v48\n'
        '  %v118 = fmul double %v117, %v53\n'
        '  %v119 = fadd double %v116, %v118\n'
        '  %v120 = fmul double 0x4008000000000000, %v49\n'
        '  %v121 = fadd double %v119, %v120\n'
        '  %v122 = fmul double 0x4008000000000000, %v54\n'
        '  %v123 = fadd double %v121, %v122\n'
        '  %v124 = fmul double %v97, %v123\n'
        '  %v125 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v124, ptr %v125\n'
        '  %v126 = fmul double %v67, %v34\n'
        '  %v127 = fmul double %v35, %v83\n'
        '  %v128 = fmul double %v127, %v85\n'
        '  %v129 = fmul double %v39, %v76\n'
        '  %v130 = fmul double %v129, %v40\n'
        '  %v131 = fadd double %v128, %v130\n'
        '  %v132 = fmul double %v73, %v40\n'
        '  %v133 = fmul double %v132, %v85\n'
        '  %v134 = fadd double %v131, %v133\n'
        '  %v135 = fmul double %v73, %v22\n'
        '  %v136 = fadd double %v134, %v135\n'
        '  %v137 = fmul double %v74, %v22\n'
        '  %v138 = fadd double %v136, %v137\n'
        '  %v139 = fmul double 0x3FF0000000000000, %v40\n'
        '  %v140 = fmul double %v40, %v40\n'
        '  %v141 = fmul double %v139, %v140\n'
        '  %v142 = fmul double %v140, %v140\n'
        '  %v143 = fmul double %v141, %v142\n'
        '  %v144 = fmul double %v76, %v143\n'
        '  %v145 = fadd double %v138, %v144\n'
        '  %v146 = fmul double %v78, %v84\n'
        '  %v147 = fmul double %v146, %v88\n'
        '  %v148 = fmul double %v147, %v30\n'
        '  %v149 = fadd double %v145, %v148\n'
        '  %v150 = fmul double %v79, %v24\n'
        '  %v151 = fadd double %v149, %v150\n'
        '  %v152 = fmul double %v83, %v86\n'
        '  %v153 = fmul double %v152, %v45\n'
        '  %v154 = fadd double %v151, %v153\n'
        '  %v155 = fmul double %v86, %v88\n'
        '  %v156 = fmul double %v155, %v53\n'
        '  %v157 = fadd double %v154, %v156\n'
        '  %v158 = fmul double %v126, %v157\n'
        '  %v159 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v158, ptr %v159\n'
        '  %v160 = fmul double 0x3FD5555555555555, %v69\n'
        '  %v161 = fmul double 0x3FF0000000000000, %v35\n'
        '  %v162 = fmul double %v35, %v35\n'
        '  %v163 = fmul double %v161, %v162\n'
        '  %v164 = fmul double %v162, %v162\n'
        '  %v165 = fmul double %v163, %v164\n'
        '  %v166 = fmul double %v165, %v92\n'
        '  %v167 = fmul double %v35, %v92\n'
        '  %v168 = fmul double %v167, %v44\n'
        '  %v169 = fadd double %v166, %v168\n'
        '  %v170 = fmul double %v55, %v89\n'
        '  %v171 = fsub double %v169, %v170\n'
        '  %v172 = fmul double %v73, %v91\n'
        '  %v173 = fadd double %v171, %v172\n'
        '  %v174 = fmul double %v73, %v93\n'
        '  %v175 = fmul double %v174, %v50\n'
        '  %v176 = fadd double %v173, %v175\n'
        '  %v177 = fmul double %v74, %v91\n'
        '  %v178 = fadd double %v176, %v177\n'
        '  %v179 = fmul double %v78, %v93\n'
        '  %v180 = fmul double %v179, %v48\n'
        '  %v181 = fadd double %v178, %v180\n'
        '  %v182 = fmul double 0x4028000000000000, %v79\n'
        '  %v183 = fmul double %v182, %v8\n'
        '  %v184 = fadd double %v181, %v183\n'
        '  %v185 = fmul double %v89, %v48\n'
        '  %v186 = fsub double %v184, %v185\n'
        '  %v187 = fmul double %v90, %v44\n'
        '  %v188 = fsub double %v186, %v187\n'
        '  %v189 = fmul double %v90, %v54\n'
        '  %v190 = fsub double %v188, %v189\n'
        '  %v191 = fmul double 0x4044000000000000, %v49\n'
        '  %v192 = fmul double %v191, %v4\n'
        '  %v193 = fsub double %v190, %v192\n'
        '  %v194 = fmul double %v160, %v193\n'
        '  %v195 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v194, ptr %v195\n'
        '  %v196 = getelementptr inbounds double, ptr %ds, i64 4\n'
        '  store double %v4, ptr %v196\n'
        '  %v197 = getelementptr inbounds double, ptr %ds, i64 5\n'
        '  store double %v8, ptr %v197\n'
        '  %v198 = call double @llvm.cos.f64(double %v10)\n'
        '  %v199 = fmul double %v94, %v198\n'
        '  %v200 = getelementptr inbounds double, ptr %ds, i64 6\n'
        '  store double %v199, ptr %v200\n'
        '  %v201 = call double @llvm.sin.f64(double %v10)\n'
        '  %v202 = fmul double %v94, %v201\n'
        '  %v203 = getelementptr inbounds double, ptr %ds, i64 7\n'
        '  store double %v202, ptr %v203\n'
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
        '  %v5 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  store double %v2, ptr %v5\n'
        '  %v6 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  store double %v4, ptr %v6\n'
        '  %v7 = fmul double 0x4010000000000000, %v2\n'
        '  %v8 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  store double %v7, ptr %v8\n'
        '  %v9 = fmul double 0x4020000000000000, %v2\n'
        '  %v10 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  store double %v9, ptr %v10\n'
        '  %v11 = fmul double 0x4014000000000000, %v4\n'
        '  %v12 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  store double %v11, ptr %v12\n'
        '  %v13 = fmul double 0x4018000000000000, %v4\n'
        '  %v14 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  store double %v13, ptr %v14\n'
        '  %v15 = fmul double 0x4024000000000000, %v4\n'
        '  %v16 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  store double %v15, ptr %v16\n'
        '  %v17 = fmul double 0x4032000000000000, %v4\n'
        '  %v18 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  store double %v17, ptr %v18\n'
        '  %v19 = fdiv double 0x3FF0000000000000, %v4\n'
        '  %v20 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  store double %v19, ptr %v20\n'
        '  ret void\n'
        '}\n'
        '\n'
    ),
}
#: how many parameters the IR of ``constants`` reads
LLVM_IR_READS = 2
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = 'b471ba941e464c581c1f5d7378b125ec2e92f674efcf690c8baa93bba271c74d'
