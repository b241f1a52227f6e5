"""rolling_disk_damped, fidelity full: exact consequences of the model's Lagrangian and constraints, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from examples/rolling_disk.py (model 'rolling_disk_damped',
constraints no_slip_along, no_slip_across) through derivation/engine.py.
Accelerations and multipliers in closed form (symbolic elimination of the multipliers).
SymPy 1.14.0; input hash sha256:58ad02687afa17689ec1a7eaf177fcfbdd310550f6040f09835824737efa2b18

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
INPUT_HASH = '58ad02687afa17689ec1a7eaf177fcfbdd310550f6040f09835824737efa2b18'
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


#: operation counts of the Jacobians and of the Jacobian-vector product, once and per column (derivation/jacobian.py)
OP_COUNTS.update(jacobian=910, jacobian_p=191, jvp_once=519, jvp_column=228)

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


@njit(cache=True)
def jvp_into(s, p, _V, ds, out):
    """Write d(state)/dt into ``ds`` and ``J(s) _V`` into ``out`` (``_V``, ``out``: (4, k)), the derivatives of the rates along the columns of ``_V`` by forward mode through the right-hand side (519 operations once, 228 per column)."""
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
    _p0 = (_c4*_c4)
    _p1 = (_c26*_c26)
    _p2 = q1_dot*r
    _p3 = 2*_c6
    _p4 = 2*_c7
    _p5 = 2*_c15
    _p6 = 2*_c18
    _p7 = 2*_c22
    _p8 = 32*_c3
    _p9 = _c16*_c20
    _p10 = _c0**8
    _p11 = 2*_c12
    _p12 = _c4**8
    _p13 = 2*_c27
    _p14 = _c14 + _c17
    _p15 = _c11 + _c9
    _p16 = _c0**7
    _p17 = 16*_c12*_c27
    _p18 = _c4**7
    _p19 = _c25*_p13
    _p20 = 1/r
    _p21 = 8*_c31
    _p22 = 8*g
    _p23 = _c0*_c38
    _p24 = _c1*_c4
    _p25 = _c13*_c40
    _p26 = _c38*_c4
    _p27 = 10*_c35
    _p28 = _c37*_p27
    _p29 = _c26*_p20
    _p30 = _c10*_p29
    _p31 = _c8*_p29
    _p32 = ((40.0/3.0))*_c0
    _p33 = 8*_c0
    _p34 = ((1.0/3.0))*_c41
    _p35 = ((1.0/3.0))*_c46
    _p36 = 4*_c2
    _p37 = ((1.0/3.0))*_c43
    _p38 = ((40.0/3.0))*_c21
    _p39 = ((1.0/3.0))*_c44
    _p40 = ((1.0/3.0))*_c45
    _p41 = _c18*_c8
    _p42 = _c35*_c47
    _p43 = _c23*_c47
    _p44 = ((1.0/3.0))*_p16
    _p45 = _c27*_p34
    _p46 = ((1.0/3.0))*_c27
    _k0 = math.cos(q2)
    _k1 = 6*_c0**5
    _k2 = -math.sin(q2)
    _k3 = 6*_c4**5
    _k4 = 3*_p0
    _k5 = 5*(_c4*_c4*_c4*_c4)
    _k6 = 2*_c0
    _k7 = 4*(_c0*_c0*_c0)
    _k8 = 4*(_c4*_c4*_c4)
    _k9 = 2*_c4
    _k10 = -_p1
    _k11 = -12*_p1
    _k12 = -4*_p1
    _k13 = -_c14*_p1
    _k14 = -_c23*_p1
    _k15 = 1/_c4
    _k16 = -_c26/_p0
    _k17 = 5*(_c0*_c0*_c0*_c0)
    _k18 = c*r
    _k19 = q3_dot*r
    _k20 = _p2
    _k21 = 3*(_c0*_c0)
    _k22 = 2*_p2
    _k23 = -_c11*_p4 - _c14*_p5 - _c17*_p5 - _c18*_p3 - _c19*_p6 - _c21*_p7 - _c23*_p8 - _c24*_p7 - 2*_c25*_p9 - 2*_c3 - _c9*_p4 - _p10*_p11 - _p11*_p12 - _p3
    _k24 = -_c27*_p8
    _k25 = -_c27*_p5
    _k26 = -_c27*_p6
    _k27 = -_c27*_p7
    _k28 = -_c27*_p4
    _k29 = -_p13*(_p10 + _p12)
    _k30 = -_p13*_p14
    _k31 = -_p13*(_c19 + _c6)
    _k32 = -_p13*(_c21 + _c24)
    _k33 = -_p13*(16*_c23 + 1)
    _k34 = -_p13*(_c18 + 1)
    _k35 = -_p13*_p15
    _k36 = -_p16*_p17
    _k37 = -_p17*_p18
    _k38 = -_p13*_p9
    _k39 = -_c16*_p19
    _k40 = -_c20*_p19
    _k41 = _p20*(_c10*_p23 + _c10*_p25 - _c16*_c32 + _c16*_c40*_c8 - _c20*_c32 + _c28*_c29 + _c28*_p26 + _c29*_c30 + _c34*_p18 + _c34*_p24 + _c36*_p22 - _c39*_p21 + _c8*_p28)
    _k42 = _c29*_p29
    _k43 = _p29*(_p23 + _p25)
    _k44 = _p29*(-_c32 + _c40*_c8)
    _k45 = _p29*(_c29 + _p26)
    _k46 = _p29*(-_c16 - _c20)
    _k47 = _p29*(_p18 + _p24)
    _k48 = _p29*(_c0*_c10 + _c28*_c4)
    _k49 = _p29*(_c1*_c34 + _c28*_c38 + 7*_c34*_c4**6)
    _k50 = _p29*(_c10*_c13 + _c16*_c8)
    _k51 = _p29*(_c16*_c40 + _p28)
    _k52 = -_c32*_p29
    _k53 = -_p21*_p29
    _k54 = -8*_c39*_p29
    _k55 = _p22*_p29
    _k56 = _c38*_p30
    _k57 = _c40*_p30
    _k58 = _c34*_c4*_p29
    _k59 = _p27*_p31
    _k60 = 10*_c37*_p31
    _k61 = ((10.0/3.0))*_c0*_c15 - _c11*_p34 - _c14*_p35 + ((40.0/3.0))*_c15*_c35 - _c17*_p35 + _c19*_p32 - _c20*_p37 + ((1.0/3.0))*_c20*_p42 - _c24*_p39 + _c25*_p44 + _c28*_p40 + ((1.0/3.0))*_c28*_p43 + _c30*_p40 + _c36*_p36 - _c39*_p37 - _c42*_p38 - _c5*_p39 + _c6*_p33 - _c9*_p34 - _p34*_p41
    _k62 = _c27*_p36
    _k63 = 4*_c27*_c36
    _k64 = _c27*_p33
    _k65 = -_c27*_p38
    _k66 = -(40.0/3.0)*_c27*_c42
    _k67 = -_p45
    _k68 = -_c27*_p37
    _k69 = -_c27*_p39
    _k70 = -_c27*_p35
    _k71 = _c27*_p40
    _k72 = _p46*(7*_c0**6*_c25 + 10*_c15 + 40*_c19 + 24*_c6)
    _k73 = _p46*(10*_c0 + 40*_c35)
    _k74 = _p46*(-_c43 + _p42)
    _k75 = _c27*_p44
    _k76 = _p46*(_c45 + _p43)
    _k77 = _p46*(40*_c15 + _c20*_c47)
    _k78 = _p46*(-_p15 - _p41)
    _k79 = _p46*(-_c20 - _c39)
    _k80 = _p46*(-_c24 - _c5)
    _k81 = _p46*(_c28 + _c30)
    _k82 = -_p14*_p46
    _k83 = _p46*(_c20*_c35 + _c23*_c28)
    _k84 = _c27*_p32
    _k85 = -_c18*_p45
    _k86 = -_c8*_p45
    _k87 = _c28*_c47*_p46
    ds[0] = q2_dot
    ds[1] = -2*_c27*(_c0**8*_c12 + _c11*_c7 + _c12*_c4**8 + _c14*_c15 + _c15*_c17 + _c16*_c20*_c25 + _c18*_c19 + _c18*_c6 + _c21*_c22 + _c22*_c24 + 16*_c23*_c3 + _c3 + _c6 + _c7*_c9)
    ds[2] = _c26*(_c0*_c10*_c38 + _c1*_c34*_c4 + _c10*_c13*_c40 - _c16*_c32 + _c16*_c40*_c8 - _c20*_c32 + _c28*_c29 + _c28*_c38*_c4 + _c29*_c30 - 8*_c31*_c39 + _c34*_c4**7 + 10*_c35*_c37*_c8 + 8*_c36*g)/r
    ds[3] = ((1.0/3.0))*_c27*(_c0**7*_c25 + 10*_c0*_c15 + 40*_c0*_c19 + 24*_c0*_c6 - _c11*_c41 - _c14*_c46 + 40*_c15*_c35 - _c17*_c46 - _c18*_c41*_c8 + 12*_c2*_c36 + _c20*_c35*_c47 - _c20*_c43 - 40*_c21*_c42 + _c23*_c28*_c47 - _c24*_c44 + _c28*_c45 + _c30*_c45 - _c39*_c43 - _c41*_c9 - _c44*_c5)
    for _j in range(_V.shape[1]):
        _v0 = _V[0, _j]
        _v1 = _V[1, _j]
        _v2 = _V[2, _j]
        _v3 = _V[3, _j]
        _t0 = _k0*_v0
        _t1 = _k1*_t0
        _t2 = _v2*q3_dot + _v3*q2_dot
        _t3 = _c1*_t2 + _c2*_t1
        _t4 = _k2*_v0
        _t5 = _k3*_t4
        _t6 = _c2*_t5 + _c5*_t2
        _t7 = _v1*c
        _t8 = _k4*_t4
        _t9 = 2*_t8
        _t10 = _k5*_t4
        _t11 = 8*_t10
        _t12 = 4*_t2
        _t13 = _k6*_t0
        _t14 = 2*_t13
        _t15 = _c4*_t7 + _c7*_t4
        _t16 = _k7*_t0
        _t17 = 8*_t16
        _t18 = 16*_t13
        _t19 = _c7*_t8 + _c8*_t7
        _t20 = _k8*_t4
        _t21 = _c13*_t20 + _c20*_t13
        _t22 = 3*_t2
        _t23 = _k9*_t4
        _t24 = _c16*_t23 + _c23*_t16
        _t25 = 24*_t2
        _t26 = _k10*_t16 + _k10*_t20 + _k11*_t21 + _k11*_t24 + _k12*_t1 + _k12*_t5 + _k13*_t23 + _k14*_t14
        _t27 = _k15*_t26 + _k16*_t4
        _t28 = _k17*_t0
        _t30 = _c0*_t20 + _c20*_t0
        _t31 = _k18*_v2
        _t32 = 4*_t31
        _t33 = _k19*_v1 + _k20*_v3
        _t34 = 6*_t33
        _t35 = _k21*_t0
        _t36 = _c23*_t35 + _c35*_t23
        _t37 = _k22*_v1
        _t38 = 5*_t37
        _t39 = _c13*_t23 + _c23*_t13
        _t40 = 18*_t33
        _t41 = _v3*c
        _t42 = _v1*q2_dot + _v2*q1_dot
        _t43 = 5*_t42
        _t44 = 20*_t42
        _t45 = 6*_t2
        _t46 = _c4*_t41 + _c41*_t4
        _t47 = 72*_t2
        out[0, _j] = _v2
        out[1, _j] = _k23*_t27 + _k24*_t23 + _k25*_t14 + _k25*_t17 + _k26*_t19 + _k27*_t21 + _k27*_t24 + _k28*_t11 + _k28*_t9 + _k29*_t12 + _k30*_t15 + _k31*_t18 + _k32*_t22 + _k33*_t3 + _k34*_t6 + _k35*_t7 + _k36*_t0 + _k37*_t4 + _k38*_t25 + _k39*_t20 + _k40*_t16
        out[2, _j] = _k41*_t26 + _k42*_t30 + _k43*_t10 + _k44*_t16 + _k45*_t28 + _k46*_t32 + _k47*_t34 + _k48*_t38 + _k49*_t4 + _k50*_t40 + _k51*_t8 + _k52*_t20 + _k53*_t39 + _k54*_t31 + _k55*_t36 + _k56*_t0 + _k57*_t13 + _k58*_t1 + _k59*_t37 + _k60*_t35
        out[3, _j] = _k61*_t27 + _k62*_t36 + _k63*_t2 + _k64*_t6 + _k65*_t42 + _k66*_t21 + _k67*_t11 + _k67*_t9 + _k68*_t39 + _k69*_t24 + _k69*_t5 + _k70*_t14 + _k70*_t17 + _k71*_t30 + _k72*_t0 + _k73*_t15 + _k74*_t20 + _k75*_t25 + _k76*_t28 + _k77*_t35 + _k78*_t41 + _k79*_t43 + _k80*_t44 + _k81*_t45 + _k82*_t46 + _k83*_t47 + _k84*_t19 + _k85*_t8 + _k86*_t18 + _k87*_t23


@njit(cache=True)
def jvp1_into(s, p, _v, ds, _dv):
    """``jvp_into`` of one column: d(state)/dt into ``ds`` and ``J(s) _v`` into ``_dv`` (vectors of length 4; 747 operations)."""
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
    _p0 = (_c4*_c4)
    _p1 = (_c26*_c26)
    _p2 = q1_dot*r
    _p3 = 2*_c6
    _p4 = 2*_c7
    _p5 = 2*_c15
    _p6 = 2*_c18
    _p7 = 2*_c22
    _p8 = 32*_c3
    _p9 = _c16*_c20
    _p10 = _c0**8
    _p11 = 2*_c12
    _p12 = _c4**8
    _p13 = 2*_c27
    _p14 = _c14 + _c17
    _p15 = _c11 + _c9
    _p16 = _c0**7
    _p17 = 16*_c12*_c27
    _p18 = _c4**7
    _p19 = _c25*_p13
    _p20 = 1/r
    _p21 = 8*_c31
    _p22 = 8*g
    _p23 = _c0*_c38
    _p24 = _c1*_c4
    _p25 = _c13*_c40
    _p26 = _c38*_c4
    _p27 = 10*_c35
    _p28 = _c37*_p27
    _p29 = _c26*_p20
    _p30 = _c10*_p29
    _p31 = _c8*_p29
    _p32 = ((40.0/3.0))*_c0
    _p33 = 8*_c0
    _p34 = ((1.0/3.0))*_c41
    _p35 = ((1.0/3.0))*_c46
    _p36 = 4*_c2
    _p37 = ((1.0/3.0))*_c43
    _p38 = ((40.0/3.0))*_c21
    _p39 = ((1.0/3.0))*_c44
    _p40 = ((1.0/3.0))*_c45
    _p41 = _c18*_c8
    _p42 = _c35*_c47
    _p43 = _c23*_c47
    _p44 = ((1.0/3.0))*_p16
    _p45 = _c27*_p34
    _p46 = ((1.0/3.0))*_c27
    _k0 = math.cos(q2)
    _k1 = 6*_c0**5
    _k2 = -math.sin(q2)
    _k3 = 6*_c4**5
    _k4 = 3*_p0
    _k5 = 5*(_c4*_c4*_c4*_c4)
    _k6 = 2*_c0
    _k7 = 4*(_c0*_c0*_c0)
    _k8 = 4*(_c4*_c4*_c4)
    _k9 = 2*_c4
    _k10 = -_p1
    _k11 = -12*_p1
    _k12 = -4*_p1
    _k13 = -_c14*_p1
    _k14 = -_c23*_p1
    _k15 = 1/_c4
    _k16 = -_c26/_p0
    _k17 = 5*(_c0*_c0*_c0*_c0)
    _k18 = c*r
    _k19 = q3_dot*r
    _k20 = _p2
    _k21 = 3*(_c0*_c0)
    _k22 = 2*_p2
    _k23 = -_c11*_p4 - _c14*_p5 - _c17*_p5 - _c18*_p3 - _c19*_p6 - _c21*_p7 - _c23*_p8 - _c24*_p7 - 2*_c25*_p9 - 2*_c3 - _c9*_p4 - _p10*_p11 - _p11*_p12 - _p3
    _k24 = -_c27*_p8
    _k25 = -_c27*_p5
    _k26 = -_c27*_p6
    _k27 = -_c27*_p7
    _k28 = -_c27*_p4
    _k29 = -_p13*(_p10 + _p12)
    _k30 = -_p13*_p14
    _k31 = -_p13*(_c19 + _c6)
    _k32 = -_p13*(_c21 + _c24)
    _k33 = -_p13*(16*_c23 + 1)
    _k34 = -_p13*(_c18 + 1)
    _k35 = -_p13*_p15
    _k36 = -_p16*_p17
    _k37 = -_p17*_p18
    _k38 = -_p13*_p9
    _k39 = -_c16*_p19
    _k40 = -_c20*_p19
    _k41 = _p20*(_c10*_p23 + _c10*_p25 - _c16*_c32 + _c16*_c40*_c8 - _c20*_c32 + _c28*_c29 + _c28*_p26 + _c29*_c30 + _c34*_p18 + _c34*_p24 + _c36*_p22 - _c39*_p21 + _c8*_p28)
    _k42 = _c29*_p29
    _k43 = _p29*(_p23 + _p25)
    _k44 = _p29*(-_c32 + _c40*_c8)
    _k45 = _p29*(_c29 + _p26)
    _k46 = _p29*(-_c16 - _c20)
    _k47 = _p29*(_p18 + _p24)
    _k48 = _p29*(_c0*_c10 + _c28*_c4)
    _k49 = _p29*(_c1*_c34 + _c28*_c38 + 7*_c34*_c4**6)
    _k50 = _p29*(_c10*_c13 + _c16*_c8)
    _k51 = _p29*(_c16*_c40 + _p28)
    _k52 = -_c32*_p29
    _k53 = -_p21*_p29
    _k54 = -8*_c39*_p29
    _k55 = _p22*_p29
    _k56 = _c38*_p30
    _k57 = _c40*_p30
    _k58 = _c34*_c4*_p29
    _k59 = _p27*_p31
    _k60 = 10*_c37*_p31
    _k61 = ((10.0/3.0))*_c0*_c15 - _c11*_p34 - _c14*_p35 + ((40.0/3.0))*_c15*_c35 - _c17*_p35 + _c19*_p32 - _c20*_p37 + ((1.0/3.0))*_c20*_p42 - _c24*_p39 + _c25*_p44 + _c28*_p40 + ((1.0/3.0))*_c28*_p43 + _c30*_p40 + _c36*_p36 - _c39*_p37 - _c42*_p38 - _c5*_p39 + _c6*_p33 - _c9*_p34 - _p34*_p41
    _k62 = _c27*_p36
    _k63 = 4*_c27*_c36
    _k64 = _c27*_p33
    _k65 = -_c27*_p38
    _k66 = -(40.0/3.0)*_c27*_c42
    _k67 = -_p45
    _k68 = -_c27*_p37
    _k69 = -_c27*_p39
    _k70 = -_c27*_p35
    _k71 = _c27*_p40
    _k72 = _p46*(7*_c0**6*_c25 + 10*_c15 + 40*_c19 + 24*_c6)
    _k73 = _p46*(10*_c0 + 40*_c35)
    _k74 = _p46*(-_c43 + _p42)
    _k75 = _c27*_p44
    _k76 = _p46*(_c45 + _p43)
    _k77 = _p46*(40*_c15 + _c20*_c47)
    _k78 = _p46*(-_p15 - _p41)
    _k79 = _p46*(-_c20 - _c39)
    _k80 = _p46*(-_c24 - _c5)
    _k81 = _p46*(_c28 + _c30)
    _k82 = -_p14*_p46
    _k83 = _p46*(_c20*_c35 + _c23*_c28)
    _k84 = _c27*_p32
    _k85 = -_c18*_p45
    _k86 = -_c8*_p45
    _k87 = _c28*_c47*_p46
    ds[0] = q2_dot
    ds[1] = -2*_c27*(_c0**8*_c12 + _c11*_c7 + _c12*_c4**8 + _c14*_c15 + _c15*_c17 + _c16*_c20*_c25 + _c18*_c19 + _c18*_c6 + _c21*_c22 + _c22*_c24 + 16*_c23*_c3 + _c3 + _c6 + _c7*_c9)
    ds[2] = _c26*(_c0*_c10*_c38 + _c1*_c34*_c4 + _c10*_c13*_c40 - _c16*_c32 + _c16*_c40*_c8 - _c20*_c32 + _c28*_c29 + _c28*_c38*_c4 + _c29*_c30 - 8*_c31*_c39 + _c34*_c4**7 + 10*_c35*_c37*_c8 + 8*_c36*g)/r
    ds[3] = ((1.0/3.0))*_c27*(_c0**7*_c25 + 10*_c0*_c15 + 40*_c0*_c19 + 24*_c0*_c6 - _c11*_c41 - _c14*_c46 + 40*_c15*_c35 - _c17*_c46 - _c18*_c41*_c8 + 12*_c2*_c36 + _c20*_c35*_c47 - _c20*_c43 - 40*_c21*_c42 + _c23*_c28*_c47 - _c24*_c44 + _c28*_c45 + _c30*_c45 - _c39*_c43 - _c41*_c9 - _c44*_c5)
    _v0 = _v[0]
    _v1 = _v[1]
    _v2 = _v[2]
    _v3 = _v[3]
    _t0 = _k0*_v0
    _t1 = _k1*_t0
    _t2 = _v2*q3_dot + _v3*q2_dot
    _t3 = _c1*_t2 + _c2*_t1
    _t4 = _k2*_v0
    _t5 = _k3*_t4
    _t6 = _c2*_t5 + _c5*_t2
    _t7 = _v1*c
    _t8 = _k4*_t4
    _t9 = 2*_t8
    _t10 = _k5*_t4
    _t11 = 8*_t10
    _t12 = 4*_t2
    _t13 = _k6*_t0
    _t14 = 2*_t13
    _t15 = _c4*_t7 + _c7*_t4
    _t16 = _k7*_t0
    _t17 = 8*_t16
    _t18 = 16*_t13
    _t19 = _c7*_t8 + _c8*_t7
    _t20 = _k8*_t4
    _t21 = _c13*_t20 + _c20*_t13
    _t22 = 3*_t2
    _t23 = _k9*_t4
    _t24 = _c16*_t23 + _c23*_t16
    _t25 = 24*_t2
    _t26 = _k10*_t16 + _k10*_t20 + _k11*_t21 + _k11*_t24 + _k12*_t1 + _k12*_t5 + _k13*_t23 + _k14*_t14
    _t27 = _k15*_t26 + _k16*_t4
    _t28 = _k17*_t0
    _t30 = _c0*_t20 + _c20*_t0
    _t31 = _k18*_v2
    _t32 = 4*_t31
    _t33 = _k19*_v1 + _k20*_v3
    _t34 = 6*_t33
    _t35 = _k21*_t0
    _t36 = _c23*_t35 + _c35*_t23
    _t37 = _k22*_v1
    _t38 = 5*_t37
    _t39 = _c13*_t23 + _c23*_t13
    _t40 = 18*_t33
    _t41 = _v3*c
    _t42 = _v1*q2_dot + _v2*q1_dot
    _t43 = 5*_t42
    _t44 = 20*_t42
    _t45 = 6*_t2
    _t46 = _c4*_t41 + _c41*_t4
    _t47 = 72*_t2
    _dv[0] = _v2
    _dv[1] = _k23*_t27 + _k24*_t23 + _k25*_t14 + _k25*_t17 + _k26*_t19 + _k27*_t21 + _k27*_t24 + _k28*_t11 + _k28*_t9 + _k29*_t12 + _k30*_t15 + _k31*_t18 + _k32*_t22 + _k33*_t3 + _k34*_t6 + _k35*_t7 + _k36*_t0 + _k37*_t4 + _k38*_t25 + _k39*_t20 + _k40*_t16
    _dv[2] = _k41*_t26 + _k42*_t30 + _k43*_t10 + _k44*_t16 + _k45*_t28 + _k46*_t32 + _k47*_t34 + _k48*_t38 + _k49*_t4 + _k50*_t40 + _k51*_t8 + _k52*_t20 + _k53*_t39 + _k54*_t31 + _k55*_t36 + _k56*_t0 + _k57*_t13 + _k58*_t1 + _k59*_t37 + _k60*_t35
    _dv[3] = _k61*_t27 + _k62*_t36 + _k63*_t2 + _k64*_t6 + _k65*_t42 + _k66*_t21 + _k67*_t11 + _k67*_t9 + _k68*_t39 + _k69*_t24 + _k69*_t5 + _k70*_t14 + _k70*_t17 + _k71*_t30 + _k72*_t0 + _k73*_t15 + _k74*_t20 + _k75*_t25 + _k76*_t28 + _k77*_t35 + _k78*_t41 + _k79*_t43 + _k80*_t44 + _k81*_t45 + _k82*_t46 + _k83*_t47 + _k84*_t19 + _k85*_t8 + _k86*_t18 + _k87*_t23



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
        '  %v27 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  %v28 = load double, ptr %v27\n'
        '  %v29 = getelementptr inbounds double, ptr %q, i64 10\n'
        '  %v30 = load double, ptr %v29\n'
        '  %v31 = getelementptr inbounds double, ptr %q, i64 11\n'
        '  %v32 = load double, ptr %v31\n'
        '  %v33 = getelementptr inbounds double, ptr %q, i64 12\n'
        '  %v34 = load double, ptr %v33\n'
        '  %v35 = getelementptr inbounds double, ptr %q, i64 13\n'
        '  %v36 = load double, ptr %v35\n'
        '  %v37 = getelementptr inbounds double, ptr %q, i64 14\n'
        '  %v38 = load double, ptr %v37\n'
        '  %v39 = getelementptr inbounds double, ptr %q, i64 15\n'
        '  %v40 = load double, ptr %v39\n'
        '  %v41 = getelementptr inbounds double, ptr %q, i64 16\n'
        '  %v42 = load double, ptr %v41\n'
        '  %v43 = getelementptr inbounds double, ptr %q, i64 17\n'
        '  %v44 = load double, ptr %v43\n'
        '  %v45 = getelementptr inbounds double, ptr %q, i64 18\n'
        '  %v46 = load double, ptr %v45\n'
        '  %v47 = getelementptr inbounds double, ptr %q, i64 19\n'
        '  %v48 = load double, ptr %v47\n'
        '  %v49 = call double @llvm.cos.f64(double %v2)\n'
        '  %v50 = fmul double %v49, %v49\n'
        '  %v51 = fmul double %v50, %v49\n'
        '  %v52 = fmul double %v16, %v4\n'
        '  %v53 = fmul double 0x3FF0000000000000, %v49\n'
        '  %v54 = fmul double %v49, %v49\n'
        '  %v55 = fmul double %v54, %v54\n'
        '  %v56 = fmul double %v53, %v55\n'
        '  %v57 = fmul double %v18, %v4\n'
        '  %v58 = call double @llvm.sin.f64(double %v2)\n'
        '  %v59 = fmul double %v58, %v58\n'
        '  %v60 = fmul double 0x3FF0000000000000, %v59\n'
        '  %v61 = fmul double %v59, %v59\n'
        '  %v62 = fmul double %v60, %v61\n'
        '  %v63 = fmul double %v6, %v8\n'
        '  %v64 = fmul double %v62, %v63\n'
        '  %v65 = fmul double %v49, %v49\n'
        '  %v66 = fmul double 0x3FF0000000000000, %v65\n'
        '  %v67 = fmul double %v65, %v65\n'
        '  %v68 = fmul double %v66, %v67\n'
        '  %v69 = fmul double %v63, %v68\n'
        '  %v70 = fmul double 0x4010000000000000, %v63\n'
        '  %v71 = fmul double %v58, %v58\n'
        '  %v72 = fmul double %v49, %v71\n'
        '  %v73 = fmul double %v58, %v58\n'
        '  %v74 = fmul double %v73, %v58\n'
        '  %v75 = fmul double %v74, %v58\n'
        '  %v76 = fmul double %v49, %v75\n'
        '  %v77 = fmul double %v51, %v71\n'
        '  %v78 = fmul double %v49, %v49\n'
        '  %v79 = fmul double %v78, %v49\n'
        '  %v80 = fmul double %v79, %v49\n'
        '  %v81 = fmul double %v71, %v80\n'
        '  %v82 = fmul double 0x4008000000000000, %v63\n'
        '  %v83 = fmul double %v49, %v49\n'
        '  %v84 = fmul double %v75, %v83\n'
        '  %v85 = fmul double 0x4038000000000000, %v63\n'
        '  %v86 = fmul double %v71, %v83\n'
        '  %v87 = fadd double %v75, %v80\n'
        '  %v88 = fmul double 0x4028000000000000, %v81\n'
        '  %v89 = fadd double %v87, %v88\n'
        '  %v90 = fmul double 0x4028000000000000, %v84\n'
        '  %v91 = fadd double %v89, %v90\n'
        '  %v92 = fmul double 0x4000000000000000, %v86\n'
        '  %v93 = fadd double %v91, %v92\n'
        '  %v94 = fmul double 0x4010000000000000, %v62\n'
        '  %v95 = fadd double %v93, %v94\n'
        '  %v96 = fmul double 0x4010000000000000, %v68\n'
        '  %v97 = fadd double %v95, %v96\n'
        '  %v98 = fdiv double 0x3FF0000000000000, %v97\n'
        '  %v99 = fdiv double %v98, %v49\n'
        '  %v100 = fmul double 0x3FF0000000000000, %v58\n'
        '  %v101 = fmul double %v58, %v58\n'
        '  %v102 = fmul double %v101, %v101\n'
        '  %v103 = fmul double %v100, %v102\n'
        '  %v104 = fmul double %v26, %v6\n'
        '  %v105 = fmul double %v80, %v58\n'
        '  %v106 = fmul double %v4, %v8\n'
        '  %v107 = fmul double %v106, %v30\n'
        '  %v108 = fmul double %v58, %v58\n'
        '  %v109 = fmul double %v108, %v58\n'
        '  %v110 = fmul double %v83, %v109\n'
        '  %v111 = fmul double %v4, %v4\n'
        '  %v112 = fmul double %v111, %v28\n'
        '  %v113 = fmul double %v86, %v6\n'
        '  %v114 = fmul double %v106, %v36\n'
        '  %v115 = fmul double %v40, %v8\n'
        '  %v116 = fmul double %v42, %v8\n'
        '  %v117 = fmul double %v58, %v4\n'
        '  %v118 = fmul double %v4, %v6\n'
        '  %v119 = fmul double 0x4034000000000000, %v118\n'
        '  %v120 = fmul double 0x4018000000000000, %v63\n'
        '  %v121 = fmul double 0x4052000000000000, %v63\n'
        '  %v122 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v6, ptr %v122\n'
        '  %v123 = fmul double 0xC000000000000000, %v99\n'
        '  %v124 = fmul double %v49, %v49\n'
        '  %v125 = fmul double %v124, %v124\n'
        '  %v126 = fmul double %v125, %v125\n'
        '  %v127 = fmul double 0x3FF0000000000000, %v126\n'
        '  %v128 = fmul double %v127, %v70\n'
        '  %v129 = fmul double %v51, %v52\n'
        '  %v130 = fadd double %v128, %v129\n'
        '  %v131 = fmul double 0x4030000000000000, %v69\n'
        '  %v132 = fmul double %v131, %v71\n'
        '  %v133 = fadd double %v130, %v132\n'
        '  %v134 = fadd double %v133, %v69\n'
        '  %v135 = fmul double %v58, %v58\n'
        '  %v136 = fmul double %v135, %v135\n'
        '  %v137 = fmul double %v136, %v136\n'
        '  %v138 = fmul double 0x3FF0000000000000, %v137\n'
        '  %v139 = fmul double %v70, %v138\n'
        '  %v140 = fadd double %v134, %v139\n'
        '  %v141 = fmul double %v72, %v52\n'
        '  %v142 = fadd double %v140, %v141\n'
        '  %v143 = fmul double %v75, %v80\n'
        '  %v144 = fmul double %v143, %v85\n'
        '  %v145 = fadd double %v142, %v144\n'
        '  %v146 = fmul double %v76, %v57\n'
        '  %v147 = fadd double %v145, %v146\n'
        '  %v148 = fmul double %v77, %v20\n'
        '  %v149 = fmul double %v148, %v4\n'
        '  %v150 = fadd double %v147, %v149\n'
        '  %v151 = fmul double %v81, %v82\n'
        '  %v152 = fadd double %v150, %v151\n'
        '  %v153 = fmul double %v82, %v84\n'
        '  %v154 = fadd double %v152, %v153\n'
        '  %v155 = fmul double 0x4030000000000000, %v83\n'
        '  %v156 = fmul double %v155, %v64\n'
        '  %v157 = fadd double %v154, %v156\n'
        '  %v158 = fmul double %v56, %v57\n'
        '  %v159 = fadd double %v157, %v158\n'
        '  %v160 = fadd double %v159, %v64\n'
        '  %v161 = fmul double %v123, %v160\n'
        '  %v162 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v161, ptr %v162\n'
        '  %v163 = fmul double %v98, %v38\n'
        '  %v164 = fmul double 0x3FF0000000000000, %v49\n'
        '  %v165 = fmul double %v49, %v49\n'
        '  %v166 = fmul double %v164, %v165\n'
        '  %v167 = fmul double %v165, %v165\n'
        '  %v168 = fmul double %v166, %v167\n'
        '  %v169 = fmul double %v168, %v107\n'
        '  %v170 = fmul double %v49, %v103\n'
        '  %v171 = fmul double %v170, %v112\n'
        '  %v172 = fadd double %v169, %v171\n'
        '  %v173 = fmul double %v49, %v107\n'
        '  %v174 = fmul double %v173, %v62\n'
        '  %v175 = fadd double %v172, %v174\n'
        '  %v176 = fmul double %v51, %v75\n'
        '  %v177 = fmul double %v176, %v114\n'
        '  %v178 = fadd double %v175, %v177\n'
        '  %v179 = fmul double %v51, %v109\n'
        '  %v180 = fmul double %v179, %v111\n'
        '  %v181 = fmul double %v180, %v32\n'
        '  %v182 = fadd double %v178, %v181\n'
        '  %v183 = fmul double %v71, %v56\n'
        '  %v184 = fmul double %v183, %v114\n'
        '  %v185 = fadd double %v182, %v184\n'
        '  %v186 = fmul double %v75, %v104\n'
        '  %v187 = fadd double %v185, %v186\n'
        '  %v188 = fmul double %v80, %v104\n'
        '  %v189 = fadd double %v187, %v188\n'
        '  %v190 = fmul double %v103, %v22\n'
        '  %v191 = fadd double %v189, %v190\n'
        '  %v192 = fmul double %v105, %v22\n'
        '  %v193 = fadd double %v191, %v192\n'
        '  %v194 = fmul double %v56, %v112\n'
        '  %v195 = fmul double %v194, %v58\n'
        '  %v196 = fadd double %v193, %v195\n'
        '  %v197 = fmul double %v110, %v24\n'
        '  %v198 = fadd double %v196, %v197\n'
        '  %v199 = fmul double %v113, %v34\n'
        '  %v200 = fadd double %v198, %v199\n'
        '  %v201 = fmul double %v163, %v200\n'
        '  %v202 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v201, ptr %v202\n'
        '  %v203 = fmul double 0x3FD5555555555555, %v99\n'
        '  %v204 = fmul double %v49, %v109\n'
        '  %v205 = fmul double %v204, %v48\n'
        '  %v206 = fmul double %v205, %v4\n'
        '  %v207 = fmul double %v49, %v117\n'
        '  %v208 = fmul double %v207, %v46\n'
        '  %v209 = fadd double %v206, %v208\n'
        '  %v210 = fmul double %v51, %v116\n'
        '  %v211 = fadd double %v209, %v210\n'
        '  %v212 = fmul double %v51, %v117\n'
        '  %v213 = fmul double %v212, %v48\n'
        '  %v214 = fadd double %v211, %v213\n'
        '  %v215 = fmul double 0x4038000000000000, %v69\n'
        '  %v216 = fmul double %v215, %v58\n'
        '  %v217 = fadd double %v214, %v216\n'
        '  %v218 = fmul double %v72, %v116\n'
        '  %v219 = fadd double %v217, %v218\n'
        '  %v220 = fmul double %v76, %v115\n'
        '  %v221 = fadd double %v219, %v220\n'
        '  %v222 = fmul double %v77, %v44\n'
        '  %v223 = fmul double %v222, %v8\n'
        '  %v224 = fadd double %v221, %v223\n'
        '  %v225 = fmul double %v80, %v109\n'
        '  %v226 = fmul double %v225, %v121\n'
        '  %v227 = fadd double %v224, %v226\n'
        '  %v228 = fmul double 0x4014000000000000, %v80\n'
        '  %v229 = fmul double %v228, %v118\n'
        '  %v230 = fsub double %v227, %v229\n'
        '  %v231 = fmul double 0x4044000000000000, %v81\n'
        '  %v232 = fmul double %v231, %v118\n'
        '  %v233 = fsub double %v230, %v232\n'
        '  %v234 = fmul double %v83, %v103\n'
        '  %v235 = fmul double %v234, %v121\n'
        '  %v236 = fadd double %v233, %v235\n'
        '  %v237 = fmul double %v84, %v119\n'
        '  %v238 = fsub double %v236, %v237\n'
        '  %v239 = fmul double 0x3FF0000000000000, %v58\n'
        '  %v240 = fmul double %v58, %v58\n'
        '  %v241 = fmul double %v239, %v240\n'
        '  %v242 = fmul double %v240, %v240\n'
        '  %v243 = fmul double %v241, %v242\n'
        '  %v244 = fmul double %v85, %v243\n'
        '  %v245 = fadd double %v238, %v244\n'
        '  %v246 = fmul double %v103, %v120\n'
        '  %v247 = fadd double %v245, %v246\n'
        '  %v248 = fmul double %v105, %v120\n'
        '  %v249 = fadd double %v247, %v248\n'
        '  %v250 = fmul double %v56, %v115\n'
        '  %v251 = fadd double %v249, %v250\n'
        '  %v252 = fmul double 0x4028000000000000, %v110\n'
        '  %v253 = fmul double %v252, %v63\n'
        '  %v254 = fadd double %v251, %v253\n'
        '  %v255 = fmul double 0x4014000000000000, %v113\n'
        '  %v256 = fmul double %v255, %v4\n'
        '  %v257 = fsub double %v254, %v256\n'
        '  %v258 = fmul double %v119, %v68\n'
        '  %v259 = fsub double %v257, %v258\n'
        '  %v260 = fmul double %v203, %v259\n'
        '  %v261 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v260, ptr %v261\n'
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
        '  %v57 = call double @llvm.cos.f64(double %v2)\n'
        '  %v58 = fmul double %v57, %v57\n'
        '  %v59 = fmul double %v58, %v57\n'
        '  %v60 = fmul double %v24, %v4\n'
        '  %v61 = fmul double 0x3FF0000000000000, %v57\n'
        '  %v62 = fmul double %v57, %v57\n'
        '  %v63 = fmul double %v62, %v62\n'
        '  %v64 = fmul double %v61, %v63\n'
        '  %v65 = fmul double %v26, %v4\n'
        '  %v66 = call double @llvm.sin.f64(double %v2)\n'
        '  %v67 = fmul double %v66, %v66\n'
        '  %v68 = fmul double 0x3FF0000000000000, %v67\n'
        '  %v69 = fmul double %v67, %v67\n'
        '  %v70 = fmul double %v68, %v69\n'
        '  %v71 = fmul double %v6, %v8\n'
        '  %v72 = fmul double %v70, %v71\n'
        '  %v73 = fmul double %v57, %v57\n'
        '  %v74 = fmul double 0x3FF0000000000000, %v73\n'
        '  %v75 = fmul double %v73, %v73\n'
        '  %v76 = fmul double %v74, %v75\n'
        '  %v77 = fmul double %v71, %v76\n'
        '  %v78 = fmul double 0x4010000000000000, %v71\n'
        '  %v79 = fmul double %v66, %v66\n'
        '  %v80 = fmul double %v57, %v79\n'
        '  %v81 = fmul double %v66, %v66\n'
        '  %v82 = fmul double %v81, %v66\n'
        '  %v83 = fmul double %v82, %v66\n'
        '  %v84 = fmul double %v57, %v83\n'
        '  %v85 = fmul double %v59, %v79\n'
        '  %v86 = fmul double %v57, %v57\n'
        '  %v87 = fmul double %v86, %v57\n'
        '  %v88 = fmul double %v87, %v57\n'
        '  %v89 = fmul double %v79, %v88\n'
        '  %v90 = fmul double 0x4008000000000000, %v71\n'
        '  %v91 = fmul double %v57, %v57\n'
        '  %v92 = fmul double %v83, %v91\n'
        '  %v93 = fmul double 0x4038000000000000, %v71\n'
        '  %v94 = fmul double %v79, %v91\n'
        '  %v95 = fadd double %v83, %v88\n'
        '  %v96 = fmul double 0x4028000000000000, %v89\n'
        '  %v97 = fadd double %v95, %v96\n'
        '  %v98 = fmul double 0x4028000000000000, %v92\n'
        '  %v99 = fadd double %v97, %v98\n'
        '  %v100 = fmul double 0x4000000000000000, %v94\n'
        '  %v101 = fadd double %v99, %v100\n'
        '  %v102 = fmul double 0x4010000000000000, %v70\n'
        '  %v103 = fadd double %v101, %v102\n'
        '  %v104 = fmul double 0x4010000000000000, %v76\n'
        '  %v105 = fadd double %v103, %v104\n'
        '  %v106 = fdiv double 0x3FF0000000000000, %v105\n'
        '  %v107 = fdiv double %v106, %v57\n'
        '  %v108 = fmul double 0x3FF0000000000000, %v66\n'
        '  %v109 = fmul double %v66, %v66\n'
        '  %v110 = fmul double %v109, %v109\n'
        '  %v111 = fmul double %v108, %v110\n'
        '  %v112 = fmul double %v34, %v6\n'
        '  %v113 = fmul double %v88, %v66\n'
        '  %v114 = fmul double %v4, %v8\n'
        '  %v115 = fmul double %v114, %v38\n'
        '  %v116 = fmul double %v66, %v66\n'
        '  %v117 = fmul double %v116, %v66\n'
        '  %v118 = fmul double %v91, %v117\n'
        '  %v119 = fmul double %v4, %v4\n'
        '  %v120 = fmul double %v119, %v36\n'
        '  %v121 = fmul double %v94, %v6\n'
        '  %v122 = fmul double %v114, %v44\n'
        '  %v123 = fmul double %v48, %v8\n'
        '  %v124 = fmul double %v50, %v8\n'
        '  %v125 = fmul double %v66, %v4\n'
        '  %v126 = fmul double %v4, %v6\n'
        '  %v127 = fmul double 0x4034000000000000, %v126\n'
        '  %v128 = fmul double 0x4018000000000000, %v71\n'
        '  %v129 = fmul double 0x4052000000000000, %v71\n'
        '  %v130 = fmul double %v8, %v20\n'
        '  %v131 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v6, ptr %v131\n'
        '  %v132 = fmul double 0xC000000000000000, %v107\n'
        '  %v133 = fmul double %v57, %v57\n'
        '  %v134 = fmul double %v133, %v133\n'
        '  %v135 = fmul double %v134, %v134\n'
        '  %v136 = fmul double 0x3FF0000000000000, %v135\n'
        '  %v137 = fmul double %v136, %v78\n'
        '  %v138 = fmul double %v59, %v60\n'
        '  %v139 = fadd double %v137, %v138\n'
        '  %v140 = fmul double 0x4030000000000000, %v77\n'
        '  %v141 = fmul double %v140, %v79\n'
        '  %v142 = fadd double %v139, %v141\n'
        '  %v143 = fadd double %v142, %v77\n'
        '  %v144 = fmul double %v66, %v66\n'
        '  %v145 = fmul double %v144, %v144\n'
        '  %v146 = fmul double %v145, %v145\n'
        '  %v147 = fmul double 0x3FF0000000000000, %v146\n'
        '  %v148 = fmul double %v78, %v147\n'
        '  %v149 = fadd double %v143, %v148\n'
        '  %v150 = fmul double %v80, %v60\n'
        '  %v151 = fadd double %v149, %v150\n'
        '  %v152 = fmul double %v83, %v88\n'
        '  %v153 = fmul double %v152, %v93\n'
        '  %v154 = fadd double %v151, %v153\n'
        '  %v155 = fmul double %v84, %v65\n'
        '  %v156 = fadd double %v154, %v155\n'
        '  %v157 = fmul double %v85, %v28\n'
        '  %v158 = fmul double %v157, %v4\n'
        '  %v159 = fadd double %v156, %v158\n'
        '  %v160 = fmul double %v89, %v90\n'
        '  %v161 = fadd double %v159, %v160\n'
        '  %v162 = fmul double %v90, %v92\n'
        '  %v163 = fadd double %v161, %v162\n'
        '  %v164 = fmul double 0x4030000000000000, %v91\n'
        '  %v165 = fmul double %v164, %v72\n'
        '  %v166 = fadd double %v163, %v165\n'
        '  %v167 = fmul double %v64, %v65\n'
        '  %v168 = fadd double %v166, %v167\n'
        '  %v169 = fadd double %v168, %v72\n'
        '  %v170 = fmul double %v132, %v169\n'
        '  %v171 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v170, ptr %v171\n'
        '  %v172 = fmul double %v106, %v46\n'
        '  %v173 = fmul double 0x3FF0000000000000, %v57\n'
        '  %v174 = fmul double %v57, %v57\n'
        '  %v175 = fmul double %v173, %v174\n'
        '  %v176 = fmul double %v174, %v174\n'
        '  %v177 = fmul double %v175, %v176\n'
        '  %v178 = fmul double %v177, %v115\n'
        '  %v179 = fmul double %v57, %v111\n'
        '  %v180 = fmul double %v179, %v120\n'
        '  %v181 = fadd double %v178, %v180\n'
        '  %v182 = fmul double %v57, %v115\n'
        '  %v183 = fmul double %v182, %v70\n'
        '  %v184 = fadd double %v181, %v183\n'
        '  %v185 = fmul double %v59, %v83\n'
        '  %v186 = fmul double %v185, %v122\n'
        '  %v187 = fadd double %v184, %v186\n'
        '  %v188 = fmul double %v59, %v117\n'
        '  %v189 = fmul double %v188, %v119\n'
        '  %v190 = fmul double %v189, %v40\n'
        '  %v191 = fadd double %v187, %v190\n'
        '  %v192 = fmul double %v79, %v64\n'
        '  %v193 = fmul double %v192, %v122\n'
        '  %v194 = fadd double %v191, %v193\n'
        '  %v195 = fmul double %v83, %v112\n'
        '  %v196 = fadd double %v194, %v195\n'
        '  %v197 = fmul double %v88, %v112\n'
        '  %v198 = fadd double %v196, %v197\n'
        '  %v199 = fmul double %v111, %v30\n'
        '  %v200 = fadd double %v198, %v199\n'
        '  %v201 = fmul double %v113, %v30\n'
        '  %v202 = fadd double %v200, %v201\n'
        '  %v203 = fmul double %v64, %v120\n'
        '  %v204 = fmul double %v203, %v66\n'
        '  %v205 = fadd double %v202, %v204\n'
        '  %v206 = fmul double %v118, %v32\n'
        '  %v207 = fadd double %v205, %v206\n'
        '  %v208 = fmul double %v121, %v42\n'
        '  %v209 = fadd double %v207, %v208\n'
        '  %v210 = fmul double %v172, %v209\n'
        '  %v211 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v210, ptr %v211\n'
        '  %v212 = fmul double 0x3FD5555555555555, %v107\n'
        '  %v213 = fmul double %v57, %v117\n'
        '  %v214 = fmul double %v213, %v56\n'
        '  %v215 = fmul double %v214, %v4\n'
        '  %v216 = fmul double %v57, %v125\n'
        '  %v217 = fmul double %v216, %v54\n'
        '  %v218 = fadd double %v215, %v217\n'
        '  %v219 = fmul double %v59, %v124\n'
        '  %v220 = fadd double %v218, %v219\n'
        '  %v221 = fmul double %v59, %v125\n'
        '  %v222 = fmul double %v221, %v56\n'
        '  %v223 = fadd double %v220, %v222\n'
        '  %v224 = fmul double 0x4038000000000000, %v77\n'
        '  %v225 = fmul double %v224, %v66\n'
        '  %v226 = fadd double %v223, %v225\n'
        '  %v227 = fmul double %v80, %v124\n'
        '  %v228 = fadd double %v226, %v227\n'
        '  %v229 = fmul double %v84, %v123\n'
        '  %v230 = fadd double %v228, %v229\n'
        '  %v231 = fmul double %v85, %v52\n'
        '  %v232 = fmul double %v231, %v8\n'
        '  %v233 = fadd double %v230, %v232\n'
        '  %v234 = fmul double %v88, %v117\n'
        '  %v235 = fmul double %v234, %v129\n'
        '  %v236 = fadd double %v233, %v235\n'
        '  %v237 = fmul double 0x4014000000000000, %v88\n'
        '  %v238 = fmul double %v237, %v126\n'
        '  %v239 = fsub double %v236, %v238\n'
        '  %v240 = fmul double 0x4044000000000000, %v89\n'
        '  %v241 = fmul double %v240, %v126\n'
        '  %v242 = fsub double %v239, %v241\n'
        '  %v243 = fmul double %v91, %v111\n'
        '  %v244 = fmul double %v243, %v129\n'
        '  %v245 = fadd double %v242, %v244\n'
        '  %v246 = fmul double %v92, %v127\n'
        '  %v247 = fsub double %v245, %v246\n'
        '  %v248 = fmul double 0x3FF0000000000000, %v66\n'
        '  %v249 = fmul double %v66, %v66\n'
        '  %v250 = fmul double %v248, %v249\n'
        '  %v251 = fmul double %v249, %v249\n'
        '  %v252 = fmul double %v250, %v251\n'
        '  %v253 = fmul double %v93, %v252\n'
        '  %v254 = fadd double %v247, %v253\n'
        '  %v255 = fmul double %v111, %v128\n'
        '  %v256 = fadd double %v254, %v255\n'
        '  %v257 = fmul double %v113, %v128\n'
        '  %v258 = fadd double %v256, %v257\n'
        '  %v259 = fmul double %v64, %v123\n'
        '  %v260 = fadd double %v258, %v259\n'
        '  %v261 = fmul double 0x4028000000000000, %v118\n'
        '  %v262 = fmul double %v261, %v71\n'
        '  %v263 = fadd double %v260, %v262\n'
        '  %v264 = fmul double 0x4014000000000000, %v121\n'
        '  %v265 = fmul double %v264, %v4\n'
        '  %v266 = fsub double %v263, %v265\n'
        '  %v267 = fmul double %v127, %v76\n'
        '  %v268 = fsub double %v266, %v267\n'
        '  %v269 = fmul double %v212, %v268\n'
        '  %v270 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v269, ptr %v270\n'
        '  %v271 = getelementptr inbounds double, ptr %ds, i64 4\n'
        '  store double %v4, ptr %v271\n'
        '  %v272 = getelementptr inbounds double, ptr %ds, i64 5\n'
        '  store double %v8, ptr %v272\n'
        '  %v273 = call double @llvm.cos.f64(double %v10)\n'
        '  %v274 = fmul double %v130, %v273\n'
        '  %v275 = getelementptr inbounds double, ptr %ds, i64 6\n'
        '  store double %v274, ptr %v275\n'
        '  %v276 = call double @llvm.sin.f64(double %v10)\n'
        '  %v277 = fmul double %v130, %v276\n'
        '  %v278 = getelementptr inbounds double, ptr %ds, i64 7\n'
        '  store double %v277, ptr %v278\n'
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
        '  %v7 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  store double %v2, ptr %v7\n'
        '  %v8 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  store double %v4, ptr %v8\n'
        '  %v9 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  store double %v6, ptr %v9\n'
        '  %v10 = fmul double 0x4000000000000000, %v6\n'
        '  %v11 = fmul double 0x4020000000000000, %v6\n'
        '  %v12 = fmul double 0x4030000000000000, %v6\n'
        '  %v13 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  store double %v10, ptr %v13\n'
        '  %v14 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  store double %v11, ptr %v14\n'
        '  %v15 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  store double %v12, ptr %v15\n'
        '  %v16 = fmul double 0x4010000000000000, %v2\n'
        '  %v17 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  store double %v16, ptr %v17\n'
        '  %v18 = fmul double 0x4020000000000000, %v2\n'
        '  %v19 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  store double %v18, ptr %v19\n'
        '  %v20 = fmul double 0xC010000000000000, %v6\n'
        '  %v21 = fmul double %v20, %v4\n'
        '  %v22 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  store double %v21, ptr %v22\n'
        '  %v23 = fmul double 0x4014000000000000, %v4\n'
        '  %v24 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  store double %v23, ptr %v24\n'
        '  %v25 = fmul double 0x4018000000000000, %v4\n'
        '  %v26 = getelementptr inbounds double, ptr %q, i64 10\n'
        '  store double %v25, ptr %v26\n'
        '  %v27 = fmul double 0x4024000000000000, %v4\n'
        '  %v28 = getelementptr inbounds double, ptr %q, i64 11\n'
        '  store double %v27, ptr %v28\n'
        '  %v29 = fneg double %v11\n'
        '  %v30 = fmul double %v29, %v4\n'
        '  %v31 = getelementptr inbounds double, ptr %q, i64 12\n'
        '  store double %v30, ptr %v31\n'
        '  %v32 = fmul double 0x4032000000000000, %v4\n'
        '  %v33 = getelementptr inbounds double, ptr %q, i64 13\n'
        '  store double %v32, ptr %v33\n'
        '  %v34 = fdiv double 0x3FF0000000000000, %v4\n'
        '  %v35 = getelementptr inbounds double, ptr %q, i64 14\n'
        '  store double %v34, ptr %v35\n'
        '  %v36 = fneg double %v11\n'
        '  %v37 = getelementptr inbounds double, ptr %q, i64 15\n'
        '  store double %v36, ptr %v37\n'
        '  %v38 = fneg double %v10\n'
        '  %v39 = getelementptr inbounds double, ptr %q, i64 16\n'
        '  store double %v38, ptr %v39\n'
        '  %v40 = fneg double %v12\n'
        '  %v41 = getelementptr inbounds double, ptr %q, i64 17\n'
        '  store double %v40, ptr %v41\n'
        '  %v42 = fmul double 0x4024000000000000, %v6\n'
        '  %v43 = getelementptr inbounds double, ptr %q, i64 18\n'
        '  store double %v42, ptr %v43\n'
        '  %v44 = fmul double 0x4044000000000000, %v6\n'
        '  %v45 = getelementptr inbounds double, ptr %q, i64 19\n'
        '  store double %v44, ptr %v45\n'
        '  ret void\n'
        '}\n'
        '\n'
    ),
}
#: how many parameters the IR of ``constants`` reads
LLVM_IR_READS = 3
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = 'd49a08d222e9020586413092d231b97ff76e4a1b0099ab2c1f788e00dba45f5d'
