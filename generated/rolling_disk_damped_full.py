"""rolling_disk_damped, fidelity full: exact consequences of the model's Lagrangian and constraints, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from examples/rolling_disk.py (model 'rolling_disk_damped',
constraints no_slip_along, no_slip_across) through derivation/engine.py.
Accelerations and multipliers in closed form (symbolic elimination of the multipliers).
SymPy 1.14.0; input hash sha256:cb7c1d33188ff2b3831947b098c2b59635f27bac4b2e5cd1f836f0cd1907a848

Uniform thin disk of radius r rolling without slipping on a horizontal table, its rotation resisted by a viscous torque -c r^2 omega per unit mass (Rayleigh function c r^2 |omega|^2/2).

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
    p[2] = c            [1/s]
Multipliers (constraint forces in the normalization of the Lagrangian, e.g. per unit mass),
in the order no_slip_along, no_slip_across.  Energy in the same normalization.
"""
import math

import numpy as np
from numba import njit

MODEL = 'rolling_disk_damped'
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
PARAM_NAMES = ('g', 'r', 'c')
PARAM_UNITS = ('m/s^2', 'm', '1/s')
#: admissible values of each parameter: 'positive' (> 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive', 'positive')
#: default parameter set and initial state (the CLI's defaults); empty if the model declares none
DEFAULT_PARAMS = {'g': 9.81, 'r': 0.1, 'c': 0.1}
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
HAS_DISSIPATION = True
#: model-specific helpers defined at the end of this module
EXPORTS = ()
INPUT_HASH = 'cb7c1d33188ff2b3831947b098c2b59635f27bac4b2e5cd1f836f0cd1907a848'
SYMPY_VERSION = '1.14.0'
#: how the multipliers are eliminated: "symbolic" (closed form) or "numeric" (a linear solve at every call)
ELIMINATION = 'symbolic'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 182, 'constants': 20, 'rhs_q': 178, 'rhs_pose': 186, 'rhs_pose_q': 183, 'pose_rates': 5, 'energy': 45, 'multipliers': 195, 'power_dissipated': 19}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (182 operations)."""
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    c = p[2]
    _c0 = math.sin(q2)
    _c1 = _c0**6
    _c2 = q2_dot*q3_dot
    _c3 = _c1*_c2
    _c4 = math.cos(q2)
    _c5 = _c4**6
    _c6 = _c2*_c5
    _c7 = c*q1_dot
    _c8 = (_c4*_c4*_c4)
    _c9 = 2*_c8
    _c10 = _c4**5
    _c11 = 8*_c10
    _c12 = 4*_c2
    _c13 = (_c0*_c0)
    _c14 = 2*_c13
    _c15 = _c4*_c7
    _c16 = (_c0*_c0*_c0*_c0)
    _c17 = 8*_c16
    _c18 = 16*_c13
    _c19 = _c7*_c8
    _c20 = (_c4*_c4*_c4*_c4)
    _c21 = _c13*_c20
    _c22 = 3*_c2
    _c23 = (_c4*_c4)
    _c24 = _c16*_c23
    _c25 = 24*_c2
    _c26 = 1/(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)
    _c27 = _c26/_c4
    _c28 = _c0**5
    _c29 = 4*g
    _c30 = _c0*_c20
    _c31 = c*q2_dot*r
    _c32 = 4*_c31
    _c33 = q1_dot*q3_dot*r
    _c34 = 6*_c33
    _c35 = (_c0*_c0*_c0)
    _c36 = _c23*_c35
    _c37 = (q1_dot*q1_dot)*r
    _c38 = 5*_c37
    _c39 = _c13*_c23
    _c40 = 18*_c33
    _c41 = c*q3_dot
    _c42 = q1_dot*q2_dot
    _c43 = 5*_c42
    _c44 = 20*_c42
    _c45 = 6*_c2
    _c46 = _c4*_c41
    _c47 = 72*_c2
    ds[0] = q2_dot
    ds[1] = -2*_c27*(_c0**8*_c12 + _c11*_c7 + _c12*_c4**8 + _c14*_c15 + _c15*_c17 + _c16*_c20*_c25 + _c18*_c19 + _c18*_c6 + _c21*_c22 + _c22*_c24 + 16*_c23*_c3 + _c3 + _c6 + _c7*_c9)
    ds[2] = _c26*(_c0*_c10*_c38 + _c1*_c34*_c4 + _c10*_c13*_c40 - _c16*_c32 + _c16*_c40*_c8 - _c20*_c32 + _c28*_c29 + _c28*_c38*_c4 + _c29*_c30 - 8*_c31*_c39 + _c34*_c4**7 + 10*_c35*_c37*_c8 + 8*_c36*g)/r
    ds[3] = ((1.0/3.0))*_c27*(_c0**7*_c25 + 10*_c0*_c15 + 40*_c0*_c19 + 24*_c0*_c6 - _c11*_c41 - _c14*_c46 + 40*_c15*_c35 - _c17*_c46 - _c18*_c41*_c8 + 12*_c2*_c36 + _c20*_c35*_c47 - _c20*_c43 - 40*_c21*_c42 + _c23*_c28*_c47 - _c24*_c44 + _c28*_c45 + _c30*_c45 - _c39*_c43 - _c41*_c9 - _c44*_c5)


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 4."""
    ds = np.empty(4)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 17 parameter-only subexpressions of the right-hand side (20 operations)."""
    q = np.empty(20)
    g = p[0]
    r = p[1]
    c = p[2]
    q[0] = g
    q[1] = r
    q[2] = c
    _c0 = 2*c
    _c1 = 8*c
    _c2 = 16*c
    q[3] = _c0
    q[4] = _c1
    q[5] = _c2
    q[6] = 4*g
    q[7] = 8*g
    q[8] = -4*c*r
    q[9] = 5*r
    q[10] = 6*r
    q[11] = 10*r
    q[12] = -_c1*r
    q[13] = 18*r
    q[14] = 1/r
    q[15] = -_c1
    q[16] = -_c0
    q[17] = -_c2
    q[18] = 10*c
    q[19] = 40*c
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (178 operations)."""
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = q[0]
    r = q[1]
    c = q[2]
    _k0 = q[3]
    _k1 = q[4]
    _k2 = q[5]
    _k3 = q[6]
    _k4 = q[7]
    _k5 = q[8]
    _k6 = q[9]
    _k7 = q[10]
    _k8 = q[11]
    _k9 = q[12]
    _k10 = q[13]
    _k11 = q[14]
    _k12 = q[15]
    _k13 = q[16]
    _k14 = q[17]
    _k15 = q[18]
    _k16 = q[19]
    _c0 = math.cos(q2)
    _c1 = (_c0*_c0*_c0)
    _c2 = _k0*q1_dot
    _c3 = _c0**5
    _c4 = _k1*q1_dot
    _c5 = math.sin(q2)
    _c6 = _c5**6
    _c7 = q2_dot*q3_dot
    _c8 = _c6*_c7
    _c9 = _c0**6
    _c10 = _c7*_c9
    _c11 = 4*_c7
    _c12 = (_c5*_c5)
    _c13 = _c0*_c12
    _c14 = (_c5*_c5*_c5*_c5)
    _c15 = _c0*_c14
    _c16 = _c1*_c12
    _c17 = (_c0*_c0*_c0*_c0)
    _c18 = _c12*_c17
    _c19 = 3*_c7
    _c20 = (_c0*_c0)
    _c21 = _c14*_c20
    _c22 = 24*_c7
    _c23 = _c12*_c20
    _c24 = 1/(_c14 + _c17 + 12*_c18 + 12*_c21 + 2*_c23 + 4*_c6 + 4*_c9)
    _c25 = _c24/_c0
    _c26 = _c5**5
    _c27 = _k5*q2_dot
    _c28 = _c17*_c5
    _c29 = q1_dot*q3_dot
    _c30 = _c29*_k7
    _c31 = (_c5*_c5*_c5)
    _c32 = _c20*_c31
    _c33 = (q1_dot*q1_dot)
    _c34 = _c33*_k6
    _c35 = _c23*q2_dot
    _c36 = _c29*_k10
    _c37 = _k12*q3_dot
    _c38 = _k13*q3_dot
    _c39 = _c5*q1_dot
    _c40 = q1_dot*q2_dot
    _c41 = 20*_c40
    _c42 = 6*_c7
    _c43 = 72*_c7
    ds[0] = q2_dot
    ds[1] = -2*_c25*(_c0**8*_c11 + _c1*_c2 + 16*_c10*_c12 + _c10 + _c11*_c5**8 + _c13*_c2 + _c14*_c17*_c22 + _c15*_c4 + _c16*_k2*q1_dot + _c18*_c19 + _c19*_c21 + 16*_c20*_c8 + _c3*_c4 + _c8)
    ds[2] = _c24*_k11*(_c0**7*_c30 + _c0*_c26*_c34 + _c0*_c30*_c6 + _c1*_c14*_c36 + _c1*_c31*_c33*_k8 + _c12*_c3*_c36 + _c14*_c27 + _c17*_c27 + _c26*_k3 + _c28*_k3 + _c3*_c34*_c5 + _c32*_k4 + _c35*_k9)
    ds[3] = ((1.0/3.0))*_c25*(_c0*_c31*_k16*q1_dot + _c0*_c39*_k15 + _c1*_c38 + _c1*_c39*_k16 + 24*_c10*_c5 + _c13*_c38 + _c15*_c37 + _c16*_k14*q3_dot + _c17*_c31*_c43 - 5*_c17*_c40 - 40*_c18*_c40 + _c20*_c26*_c43 - _c21*_c41 + _c22*_c5**7 + _c26*_c42 + _c28*_c42 + _c3*_c37 + 12*_c32*_c7 - 5*_c35*q1_dot - _c41*_c9)


@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds`` (186 operations)."""
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
    c = p[2]
    _c0 = math.sin(q2)
    _c1 = _c0**6
    _c2 = q2_dot*q3_dot
    _c3 = _c1*_c2
    _c4 = math.cos(q2)
    _c5 = _c4**6
    _c6 = _c2*_c5
    _c7 = c*q1_dot
    _c8 = (_c4*_c4*_c4)
    _c9 = 2*_c8
    _c10 = _c4**5
    _c11 = 8*_c10
    _c12 = 4*_c2
    _c13 = (_c0*_c0)
    _c14 = 2*_c13
    _c15 = _c4*_c7
    _c16 = (_c0*_c0*_c0*_c0)
    _c17 = 8*_c16
    _c18 = 16*_c13
    _c19 = _c7*_c8
    _c20 = (_c4*_c4*_c4*_c4)
    _c21 = _c13*_c20
    _c22 = 3*_c2
    _c23 = (_c4*_c4)
    _c24 = _c16*_c23
    _c25 = 24*_c2
    _c26 = 1/(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)
    _c27 = _c26/_c4
    _c28 = _c0**5
    _c29 = 4*g
    _c30 = _c0*_c20
    _c31 = c*q2_dot*r
    _c32 = 4*_c31
    _c33 = q3_dot*r
    _c34 = _c33*q1_dot
    _c35 = 6*_c34
    _c36 = (_c0*_c0*_c0)
    _c37 = _c23*_c36
    _c38 = (q1_dot*q1_dot)*r
    _c39 = 5*_c38
    _c40 = _c13*_c23
    _c41 = 18*_c34
    _c42 = c*q3_dot
    _c43 = q1_dot*q2_dot
    _c44 = 5*_c43
    _c45 = 20*_c43
    _c46 = 6*_c2
    _c47 = _c4*_c42
    _c48 = 72*_c2
    ds[0] = q2_dot
    ds[1] = -2*_c27*(_c0**8*_c12 + _c11*_c7 + _c12*_c4**8 + _c14*_c15 + _c15*_c17 + _c16*_c20*_c25 + _c18*_c19 + _c18*_c6 + _c21*_c22 + _c22*_c24 + 16*_c23*_c3 + _c3 + _c6 + _c7*_c9)
    ds[2] = _c26*(_c0*_c10*_c39 + _c1*_c35*_c4 + _c10*_c13*_c41 - _c16*_c32 + _c16*_c41*_c8 - _c20*_c32 + _c28*_c29 + _c28*_c39*_c4 + _c29*_c30 - 8*_c31*_c40 + _c35*_c4**7 + 10*_c36*_c38*_c8 + 8*_c37*g)/r
    ds[3] = ((1.0/3.0))*_c27*(_c0**7*_c25 + 10*_c0*_c15 + 40*_c0*_c19 + 24*_c0*_c6 - _c11*_c42 - _c14*_c47 + 40*_c15*_c36 - _c17*_c47 - _c18*_c42*_c8 + 12*_c2*_c37 + _c20*_c36*_c48 - _c20*_c44 - 40*_c21*_c43 + _c23*_c28*_c48 - _c24*_c45 + _c28*_c46 + _c30*_c46 - _c40*_c44 - _c42*_c9 - _c45*_c5)
    ds[4] = q1_dot
    ds[5] = q3_dot
    ds[6] = _c33*math.cos(q1)
    ds[7] = _c33*math.sin(q1)


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length 8."""
    ds = np.empty(8)
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p`` (183 operations)."""
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
    c = q[2]
    _k0 = q[3]
    _k1 = q[4]
    _k2 = q[5]
    _k3 = q[6]
    _k4 = q[7]
    _k5 = q[8]
    _k6 = q[9]
    _k7 = q[10]
    _k8 = q[11]
    _k9 = q[12]
    _k10 = q[13]
    _k11 = q[14]
    _k12 = q[15]
    _k13 = q[16]
    _k14 = q[17]
    _k15 = q[18]
    _k16 = q[19]
    _c0 = math.cos(q2)
    _c1 = (_c0*_c0*_c0)
    _c2 = _k0*q1_dot
    _c3 = _c0**5
    _c4 = _k1*q1_dot
    _c5 = math.sin(q2)
    _c6 = _c5**6
    _c7 = q2_dot*q3_dot
    _c8 = _c6*_c7
    _c9 = _c0**6
    _c10 = _c7*_c9
    _c11 = 4*_c7
    _c12 = (_c5*_c5)
    _c13 = _c0*_c12
    _c14 = (_c5*_c5*_c5*_c5)
    _c15 = _c0*_c14
    _c16 = _c1*_c12
    _c17 = (_c0*_c0*_c0*_c0)
    _c18 = _c12*_c17
    _c19 = 3*_c7
    _c20 = (_c0*_c0)
    _c21 = _c14*_c20
    _c22 = 24*_c7
    _c23 = _c12*_c20
    _c24 = 1/(_c14 + _c17 + 12*_c18 + 12*_c21 + 2*_c23 + 4*_c6 + 4*_c9)
    _c25 = _c24/_c0
    _c26 = _c5**5
    _c27 = _k5*q2_dot
    _c28 = _c17*_c5
    _c29 = q1_dot*q3_dot
    _c30 = _c29*_k7
    _c31 = (_c5*_c5*_c5)
    _c32 = _c20*_c31
    _c33 = (q1_dot*q1_dot)
    _c34 = _c33*_k6
    _c35 = _c23*q2_dot
    _c36 = _c29*_k10
    _c37 = _k12*q3_dot
    _c38 = _k13*q3_dot
    _c39 = _c5*q1_dot
    _c40 = q1_dot*q2_dot
    _c41 = 20*_c40
    _c42 = 6*_c7
    _c43 = 72*_c7
    _c44 = q3_dot*r
    ds[0] = q2_dot
    ds[1] = -2*_c25*(_c0**8*_c11 + _c1*_c2 + 16*_c10*_c12 + _c10 + _c11*_c5**8 + _c13*_c2 + _c14*_c17*_c22 + _c15*_c4 + _c16*_k2*q1_dot + _c18*_c19 + _c19*_c21 + 16*_c20*_c8 + _c3*_c4 + _c8)
    ds[2] = _c24*_k11*(_c0**7*_c30 + _c0*_c26*_c34 + _c0*_c30*_c6 + _c1*_c14*_c36 + _c1*_c31*_c33*_k8 + _c12*_c3*_c36 + _c14*_c27 + _c17*_c27 + _c26*_k3 + _c28*_k3 + _c3*_c34*_c5 + _c32*_k4 + _c35*_k9)
    ds[3] = ((1.0/3.0))*_c25*(_c0*_c31*_k16*q1_dot + _c0*_c39*_k15 + _c1*_c38 + _c1*_c39*_k16 + 24*_c10*_c5 + _c13*_c38 + _c15*_c37 + _c16*_k14*q3_dot + _c17*_c31*_c43 - 5*_c17*_c40 - 40*_c18*_c40 + _c20*_c26*_c43 - _c21*_c41 + _c22*_c5**7 + _c26*_c42 + _c28*_c42 + _c3*_c37 + 12*_c32*_c7 - 5*_c35*q1_dot - _c41*_c9)
    ds[4] = q1_dot
    ds[5] = q3_dot
    ds[6] = _c44*math.cos(q1)
    ds[7] = _c44*math.sin(q1)


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
    c = p[2]
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
    c = p[2]
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
    """Lagrange multipliers (contact forces per unit mass) no_slip_along, no_slip_across (195 operations)."""
    out = np.empty(2)
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    c = p[2]
    _c0 = math.sin(q2)
    _c1 = (_c0*_c0*_c0*_c0)
    _c2 = math.cos(q2)
    _c3 = (_c2*_c2*_c2*_c2)
    _c4 = _c0**6
    _c5 = _c2**6
    _c6 = 4*_c5
    _c7 = (_c2*_c2)
    _c8 = (_c0*_c0)
    _c9 = _c7*_c8
    _c10 = _c3*_c8
    _c11 = _c1*_c7
    _c12 = 1/(_c1 + 12*_c10 + 12*_c11 + _c3 + 4*_c4 + _c6 + 2*_c9)
    _c13 = 2*c
    _c14 = (_c0*_c0*_c0)
    _c15 = _c14*q1_dot
    _c16 = _c0**5
    _c17 = 8*c
    _c18 = _c17*q1_dot
    _c19 = _c13*q3_dot
    _c20 = _c17*q3_dot
    _c21 = _c2**5
    _c22 = _c0*_c3
    _c23 = c*q3_dot
    _c24 = 24*_c23
    _c25 = (_c2*_c2*_c2)
    _c26 = q1_dot*q3_dot*r
    _c27 = _c26*_c4
    _c28 = _c26*_c5
    _c29 = 4*g
    _c30 = (q1_dot*q1_dot)
    _c31 = _c16*r
    _c32 = _c30*_c31
    _c33 = (q2_dot*q2_dot)
    _c34 = _c31*_c33
    _c35 = q2_dot*r
    _c36 = 4*_c35*c
    _c37 = _c30*r
    _c38 = 4*_c0**7
    _c39 = _c33*r
    _c40 = 3*_c26
    _c41 = 2*_c14*_c37
    _c42 = _c14*_c39
    out[0] = ((1.0/3.0))*_c12*r*(-_c0*_c13*_c7*q1_dot - _c1*_c19 + _c1*_c2*q1_dot*q2_dot + 12*_c1*_c25*q1_dot*q2_dot - _c10*_c24 - _c11*_c24 - _c13*_c15 - 16*_c15*_c7*c - _c16*_c18 - _c18*_c22 - _c19*_c3 + 4*_c2**7*q1_dot*q2_dot + 4*_c2*_c4*q1_dot*q2_dot - _c20*_c4 - _c20*_c5 + 12*_c21*_c8*q1_dot*q2_dot + _c21*q1_dot*q2_dot - 4*_c23*_c9 + 2*_c25*_c8*q1_dot*q2_dot)
    out[1] = _c12*(4*_c0**8*_c26 - _c0*_c21*_c29 - _c0*_c37*_c5 + _c0*_c39*_c6 + _c1*_c2*_c36 + 6*_c1*_c26*_c3 + _c10*_c40 + _c11*_c40 - 8*_c14*_c25*g - _c16*_c2*_c29 + _c17*_c25*_c35*_c8 - 2*_c2**8*_c26 + _c21*_c36 + _c22*_c37 + _c22*_c39 + 10*_c27*_c7 + _c27 - 2*_c28*_c8 + _c28 + _c3*_c41 + 12*_c3*_c42 + 7*_c32*_c7 + _c32 + 12*_c34*_c7 + _c34 + _c37*_c38 + _c38*_c39 + _c41*_c7 + 2*_c42*_c7)
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
    c = p[2]
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
    c = p[2]
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


@njit(cache=True)
def power_dissipated(s, p):
    """Rate at which the non-conservative forces remove energy, -q_dot . Q (>= 0 for pure dissipation) (19 operations)."""
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    c = p[2]
    _c0 = math.sin(q2)
    _c1 = (q3_dot*q3_dot)
    power_dissipated = c*(r*r)*((_c0*_c0)*_c1 + 2*_c0*q1_dot*q3_dot + _c1*((math.cos(q2))*(math.cos(q2))) + (q1_dot*q1_dot) + (q2_dot*q2_dot))
    return power_dissipated


#: operation counts of the Jacobians (derivation/jacobian.py)
OP_COUNTS.update(jacobian=910, jacobian_p=191)

@njit(cache=True)
def jacobian(s, p):
    """d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape (4, 4) (910 operations)."""
    out = np.zeros((4, 4))
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    c = p[2]
    _c0 = math.sin(q2)
    _d0_0 = math.cos(q2)
    _c1 = _c0**6
    _d1_0 = 6*_c0**5*_d0_0
    _c2 = q2_dot*q3_dot
    _c3 = _c1*_c2
    _d3_0 = _c2*_d1_0
    _d3_2 = _c1*q3_dot
    _d3_3 = _c1*q2_dot
    _c4 = math.cos(q2)
    _d4_0 = -math.sin(q2)
    _c5 = _c4**6
    _d5_0 = 6*_c4**5*_d4_0
    _c6 = _c2*_c5
    _d6_0 = _c2*_d5_0
    _d6_2 = _c5*q3_dot
    _d6_3 = _c5*q2_dot
    _c7 = c*q1_dot
    _c8 = (_c4*_c4*_c4)
    _d8_0 = 3*(_c4*_c4)*_d4_0
    _c9 = 2*_c8
    _d9_0 = 2*_d8_0
    _c10 = _c4**5
    _d10_0 = 5*(_c4*_c4*_c4*_c4)*_d4_0
    _c11 = 8*_c10
    _d11_0 = 8*_d10_0
    _c12 = 4*_c2
    _d12_2 = 4*q3_dot
    _d12_3 = 4*q2_dot
    _c13 = (_c0*_c0)
    _d13_0 = 2*_c0*_d0_0
    _c14 = 2*_c13
    _d14_0 = 2*_d13_0
    _c15 = _c4*_c7
    _d15_0 = _c7*_d4_0
    _d15_1 = _c4*c
    _c16 = (_c0*_c0*_c0*_c0)
    _d16_0 = 4*(_c0*_c0*_c0)*_d0_0
    _c17 = 8*_c16
    _d17_0 = 8*_d16_0
    _c18 = 16*_c13
    _d18_0 = 16*_d13_0
    _c19 = _c7*_c8
    _d19_0 = _c7*_d8_0
    _d19_1 = _c8*c
    _c20 = (_c4*_c4*_c4*_c4)
    _d20_0 = 4*(_c4*_c4*_c4)*_d4_0
    _c21 = _c13*_c20
    _d21_0 = _c13*_d20_0 + _c20*_d13_0
    _c22 = 3*_c2
    _d22_2 = 3*q3_dot
    _d22_3 = 3*q2_dot
    _c23 = (_c4*_c4)
    _d23_0 = 2*_c4*_d4_0
    _c24 = _c16*_c23
    _d24_0 = _c16*_d23_0 + _c23*_d16_0
    _c25 = 24*_c2
    _d25_2 = 24*q3_dot
    _d25_3 = 24*q2_dot
    _c26 = 1/(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)
    _d26_0 = -_c14*_d23_0/((4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)*(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)) - _c23*_d14_0/((4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)*(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)) - _d16_0/((4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)*(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)) - 4*_d1_0/((4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)*(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)) - _d20_0/((4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)*(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)) - 12*_d21_0/((4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)*(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)) - 12*_d24_0/((4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)*(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)) - 4*_d5_0/((4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)*(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5))
    _c27 = _c26/_c4
    _d27_0 = -_c26*_d4_0/(_c4*_c4) + _d26_0/_c4
    _c28 = _c0**5
    _d28_0 = 5*(_c0*_c0*_c0*_c0)*_d0_0
    _c29 = 4*g
    _c30 = _c0*_c20
    _d30_0 = _c0*_d20_0 + _c20*_d0_0
    _c31 = c*q2_dot*r
    _d31_2 = c*r
    _c32 = 4*_c31
    _d32_2 = 4*_d31_2
    _c33 = q1_dot*q3_dot*r
    _d33_1 = q3_dot*r
    _d33_3 = q1_dot*r
    _c34 = 6*_c33
    _d34_1 = 6*_d33_1
    _d34_3 = 6*_d33_3
    _c35 = (_c0*_c0*_c0)
    _d35_0 = 3*(_c0*_c0)*_d0_0
    _c36 = _c23*_c35
    _d36_0 = _c23*_d35_0 + _c35*_d23_0
    _c37 = (q1_dot*q1_dot)*r
    _d37_1 = 2*q1_dot*r
    _c38 = 5*_c37
    _d38_1 = 5*_d37_1
    _c39 = _c13*_c23
    _d39_0 = _c13*_d23_0 + _c23*_d13_0
    _c40 = 18*_c33
    _d40_1 = 18*_d33_1
    _d40_3 = 18*_d33_3
    _c41 = c*q3_dot
    _c42 = q1_dot*q2_dot
    _c43 = 5*_c42
    _d43_1 = 5*q2_dot
    _d43_2 = 5*q1_dot
    _c44 = 20*_c42
    _d44_1 = 20*q2_dot
    _d44_2 = 20*q1_dot
    _c45 = 6*_c2
    _d45_2 = 6*q3_dot
    _d45_3 = 6*q2_dot
    _c46 = _c4*_c41
    _d46_0 = _c41*_d4_0
    _d46_3 = _c4*c
    _c47 = 72*_c2
    _d47_2 = 72*q3_dot
    _d47_3 = 72*q2_dot
    out[0, 2] = 1
    out[1, 0] = -16*_c0**7*_c12*_c27*_d0_0 - 16*_c12*_c27*_c4**7*_d4_0 - 2*_c15*_c27*_d14_0 - 2*_c15*_c27*_d17_0 - 2*_c16*_c25*_c27*_d20_0 - 2*_c18*_c27*_d19_0 - 2*_c20*_c25*_c27*_d16_0 - 2*_c22*_c27*_d21_0 - 2*_c22*_c27*_d24_0 - 32*_c27*_c3*_d23_0 - 2*_c27*_c7*_d11_0 - 2*_c27*_c7*_d9_0 - 2*_c27*_d15_0*(_c14 + _c17) - 2*_c27*_d18_0*(_c19 + _c6) - 2*_c27*_d3_0*(16*_c23 + 1) - 2*_c27*_d6_0*(_c18 + 1) + _d27_0*(-2*_c0**8*_c12 - 2*_c11*_c7 - 2*_c12*_c4**8 - 2*_c14*_c15 - 2*_c15*_c17 - 2*_c16*_c20*_c25 - 2*_c18*_c19 - 2*_c18*_c6 - 2*_c21*_c22 - 2*_c22*_c24 - 32*_c23*_c3 - 2*_c3 - 2*_c6 - 2*_c7*_c9)
    out[1, 1] = -2*_c18*_c27*_d19_1 - 2*_c27*_d15_1*(_c14 + _c17) - 2*_c27*c*(_c11 + _c9)
    out[1, 2] = -2*_c16*_c20*_c27*_d25_2 - 2*_c27*_d12_2*(_c0**8 + _c4**8) - 2*_c27*_d22_2*(_c21 + _c24) - 2*_c27*_d3_2*(16*_c23 + 1) - 2*_c27*_d6_2*(_c18 + 1)
    out[1, 3] = -2*_c16*_c20*_c27*_d25_3 - 2*_c27*_d12_3*(_c0**8 + _c4**8) - 2*_c27*_d22_3*(_c21 + _c24) - 2*_c27*_d3_3*(16*_c23 + 1) - 2*_c27*_d6_3*(_c18 + 1)
    out[2, 0] = _c10*_c26*_c38*_d0_0/r + _c10*_c26*_c40*_d13_0/r + _c26*_c29*_d30_0/r - 8*_c26*_c31*_d39_0/r - _c26*_c32*_d20_0/r + _c26*_c34*_c4*_d1_0/r + 10*_c26*_c37*_c8*_d35_0/r + _c26*_d10_0*(_c0*_c38 + _c13*_c40)/r + _c26*_d16_0*(-_c32 + _c40*_c8)/r + _c26*_d28_0*(_c29 + _c38*_c4)/r + 8*_c26*_d36_0*g/r + _c26*_d4_0*(_c1*_c34 + _c28*_c38 + 7*_c34*_c4**6)/r + _c26*_d8_0*(_c16*_c40 + 10*_c35*_c37)/r + _d26_0*(_c0*_c10*_c38 + _c1*_c34*_c4 + _c10*_c13*_c40 - _c16*_c32 + _c16*_c40*_c8 - _c20*_c32 + _c28*_c29 + _c28*_c38*_c4 + _c29*_c30 - 8*_c31*_c39 + _c34*_c4**7 + 10*_c35*_c37*_c8 + 8*_c36*g)/r
    out[2, 1] = 10*_c26*_c35*_c8*_d37_1/r + _c26*_d34_1*(_c1*_c4 + _c4**7)/r + _c26*_d38_1*(_c0*_c10 + _c28*_c4)/r + _c26*_d40_1*(_c10*_c13 + _c16*_c8)/r
    out[2, 2] = -8*_c26*_c39*_d31_2/r + _c26*_d32_2*(-_c16 - _c20)/r
    out[2, 3] = _c26*_d34_3*(_c1*_c4 + _c4**7)/r + _c26*_d40_3*(_c10*_c13 + _c16*_c8)/r
    out[3, 0] = ((40.0/3.0))*_c0*_c27*_d19_0 + 8*_c0*_c27*_d6_0 - (1.0/3.0)*_c18*_c27*_c41*_d8_0 + 4*_c2*_c27*_d36_0 + ((1.0/3.0))*_c27*_c28*_c47*_d23_0 - (1.0/3.0)*_c27*_c41*_c8*_d18_0 - (1.0/3.0)*_c27*_c41*_d11_0 - (1.0/3.0)*_c27*_c41*_d9_0 - (40.0/3.0)*_c27*_c42*_d21_0 - (1.0/3.0)*_c27*_c43*_d39_0 - (1.0/3.0)*_c27*_c44*_d24_0 - (1.0/3.0)*_c27*_c44*_d5_0 + ((1.0/3.0))*_c27*_c45*_d30_0 - (1.0/3.0)*_c27*_c46*_d14_0 - (1.0/3.0)*_c27*_c46*_d17_0 + ((1.0/3.0))*_c27*_d0_0*(7*_c0**6*_c25 + 10*_c15 + 40*_c19 + 24*_c6) + ((1.0/3.0))*_c27*_d15_0*(10*_c0 + 40*_c35) + ((1.0/3.0))*_c27*_d20_0*(_c35*_c47 - _c43) + ((1.0/3.0))*_c27*_d28_0*(_c23*_c47 + _c45) + ((1.0/3.0))*_c27*_d35_0*(40*_c15 + _c20*_c47) + ((1.0/3.0))*_c27*_d46_0*(-_c14 - _c17) + _d27_0*(((1.0/3.0))*_c0**7*_c25 + ((10.0/3.0))*_c0*_c15 + ((40.0/3.0))*_c0*_c19 + 8*_c0*_c6 - (1.0/3.0)*_c11*_c41 - (1.0/3.0)*_c14*_c46 + ((40.0/3.0))*_c15*_c35 - (1.0/3.0)*_c17*_c46 - (1.0/3.0)*_c18*_c41*_c8 + 4*_c2*_c36 + ((1.0/3.0))*_c20*_c35*_c47 - (1.0/3.0)*_c20*_c43 - (40.0/3.0)*_c21*_c42 + ((1.0/3.0))*_c23*_c28*_c47 - (1.0/3.0)*_c24*_c44 + ((1.0/3.0))*_c28*_c45 + ((1.0/3.0))*_c30*_c45 - (1.0/3.0)*_c39*_c43 - (1.0/3.0)*_c41*_c9 - (1.0/3.0)*_c44*_c5)
    out[3, 1] = ((40.0/3.0))*_c0*_c27*_d19_1 - (40.0/3.0)*_c21*_c27*q2_dot + ((1.0/3.0))*_c27*_d15_1*(10*_c0 + 40*_c35) + ((1.0/3.0))*_c27*_d43_1*(-_c20 - _c39) + ((1.0/3.0))*_c27*_d44_1*(-_c24 - _c5)
    out[3, 2] = ((1.0/3.0))*_c0**7*_c27*_d25_2 + 8*_c0*_c27*_d6_2 - (40.0/3.0)*_c21*_c27*q1_dot + 4*_c27*_c36*q3_dot + ((1.0/3.0))*_c27*_d43_2*(-_c20 - _c39) + ((1.0/3.0))*_c27*_d44_2*(-_c24 - _c5) + ((1.0/3.0))*_c27*_d45_2*(_c28 + _c30) + ((1.0/3.0))*_c27*_d47_2*(_c20*_c35 + _c23*_c28)
    out[3, 3] = ((1.0/3.0))*_c0**7*_c27*_d25_3 + 8*_c0*_c27*_d6_3 + 4*_c27*_c36*q2_dot + ((1.0/3.0))*_c27*_d45_3*(_c28 + _c30) + ((1.0/3.0))*_c27*_d46_3*(-_c14 - _c17) + ((1.0/3.0))*_c27*_d47_3*(_c20*_c35 + _c23*_c28) + ((1.0/3.0))*_c27*c*(-_c11 - _c18*_c8 - _c9)
    return out


@njit(cache=True)
def jacobian_p(s, p):
    """d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape (4, 3) (191 operations)."""
    out = np.zeros((4, 3))
    q2 = s[0]
    q1_dot = s[1]
    q2_dot = s[2]
    q3_dot = s[3]
    g = p[0]
    r = p[1]
    c = p[2]
    _c0 = math.sin(q2)
    _c1 = _c0**6
    _c4 = math.cos(q2)
    _c5 = _c4**6
    _c8 = (_c4*_c4*_c4)
    _c9 = 2*_c8
    _c10 = _c4**5
    _c11 = 8*_c10
    _c13 = (_c0*_c0)
    _c14 = 2*_c13
    _d15_2 = _c4*q1_dot
    _c16 = (_c0*_c0*_c0*_c0)
    _c17 = 8*_c16
    _c18 = 16*_c13
    _d19_2 = _c8*q1_dot
    _c20 = (_c4*_c4*_c4*_c4)
    _c21 = _c13*_c20
    _c23 = (_c4*_c4)
    _c24 = _c16*_c23
    _c26 = 1/(4*_c1 + _c14*_c23 + _c16 + _c20 + 12*_c21 + 12*_c24 + 4*_c5)
    _c27 = _c26/_c4
    _c28 = _c0**5
    _c29 = 4*g
    _c30 = _c0*_c20
    _c31 = c*q2_dot*r
    _d31_1 = c*q2_dot
    _d31_2 = q2_dot*r
    _c32 = 4*_c31
    _d32_1 = 4*_d31_1
    _d32_2 = 4*_d31_2
    _c33 = q1_dot*q3_dot*r
    _d33_1 = q1_dot*q3_dot
    _c34 = 6*_c33
    _d34_1 = 6*_d33_1
    _c35 = (_c0*_c0*_c0)
    _c36 = _c23*_c35
    _c37 = (q1_dot*q1_dot)*r
    _d37_1 = (q1_dot*q1_dot)
    _c38 = 5*_c37
    _d38_1 = 5*_d37_1
    _c39 = _c13*_c23
    _c40 = 18*_c33
    _d40_1 = 18*_d33_1
    _d46_2 = _c4*q3_dot
    out[1, 2] = -2*_c18*_c27*_d19_2 - 2*_c27*_d15_2*(_c14 + _c17) - 2*_c27*q1_dot*(_c11 + _c9)
    out[2, 0] = 8*_c26*_c36/r + 4*_c26*(_c28 + _c30)/r
    out[2, 1] = 10*_c26*_c35*_c8*_d37_1/r - 8*_c26*_c39*_d31_1/r + _c26*_d32_1*(-_c16 - _c20)/r + _c26*_d34_1*(_c1*_c4 + _c4**7)/r + _c26*_d38_1*(_c0*_c10 + _c28*_c4)/r + _c26*_d40_1*(_c10*_c13 + _c16*_c8)/r - _c26*(_c0*_c10*_c38 + _c1*_c34*_c4 + _c10*_c13*_c40 - _c16*_c32 + _c16*_c40*_c8 - _c20*_c32 + _c28*_c29 + _c28*_c38*_c4 + _c29*_c30 - 8*_c31*_c39 + _c34*_c4**7 + 10*_c35*_c37*_c8 + 8*_c36*g)/(r*r)
    out[2, 2] = -8*_c26*_c39*_d31_2/r + _c26*_d32_2*(-_c16 - _c20)/r
    out[3, 2] = ((40.0/3.0))*_c0*_c27*_d19_2 + ((1.0/3.0))*_c27*_d15_2*(10*_c0 + 40*_c35) + ((1.0/3.0))*_c27*_d46_2*(-_c14 - _c17) + ((1.0/3.0))*_c27*q3_dot*(-_c11 - _c18*_c8 - _c9)
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
    c = p[2]
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
    c = p[2]

    return out
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = 'ba248faf2af2138312ed9b2f6ad57019ac5005837f2fc5d9b689c1eedf6f2c3d'
