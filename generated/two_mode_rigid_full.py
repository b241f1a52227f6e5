"""two_mode_rigid, fidelity full: rigid body rolling without slipping, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/rigid_emit.py (make derive) from the rigid body 'two_mode_rigid'
through derivation/rigid.py (Lagrange-d'Alembert in body quasi-velocities).
SymPy 1.14.0; input hash sha256:9c0aecf3f2e536089088558f11d805276c25d0d4f023d98f2e9ef89cec572345

Chiral knife edge of the paper's section III as the real rigid body: massless inverted-U bar of half-length L, masses M/2 a distance ell below its ends, contact at the lowest point of a circle of radius D in a vertical plane at the chiral angle alpha to the bar; per unit mass, exact in the tilts.

State vector ``s`` (closed state; the pose follows by quadrature):
    s[0] = n_x          [1]
    s[1] = n_y          [1]
    s[2] = n_z          [1]
    s[3] = omega_x      [rad/s]
    s[4] = omega_y      [rad/s]
    s[5] = omega_z      [rad/s]
    s[6] = omega_n      [rad/s]
Pose-extended state (``*_pose`` functions) appends:
    s[7] = psi          [rad]
    s[8] = x            [m]
    s[9] = y            [m]
Parameter vector ``p``:
    p[0] = g            [length/time^2] positive
    p[1] = ell          [length] positive
    p[2] = L            [length] positive
    p[3] = D            [length] positive
    p[4] = alpha        [rad] real
Presets:

Multipliers: the contact force on the body in body axes, contact_force_x, contact_force_y, contact_force_z.
Energy and ``power_dissipated`` in the units of the parameters (J and W for SI parameters).
"""
import math

import numpy as np
from numba import njit

MODEL = 'two_mode_rigid'
FIDELITY = 'full'
#: what this fidelity is
FIDELITY_DOC = "rigid body rolling without slipping, exact in the orientation (derivation/rigid.py)"
STATE_NAMES = ('n_x', 'n_y', 'n_z', 'omega_x', 'omega_y', 'omega_z', 'omega_n')
#: unit of each state
STATE_UNITS = ('1', '1', '1', 'rad/s', 'rad/s', 'rad/s', 'rad/s')
POSE_NAMES = ('psi', 'x', 'y')
POSE_UNITS = ('rad', 'm', 'm')
#: what the pose coordinates mean
POSE_DOC = "psi: heading of the horizontal projection of the body axis (1, 0, 0); (x, y): centre of mass"
PARAM_NAMES = ('g', 'ell', 'L', 'D', 'alpha')
PARAM_UNITS = ('length/time^2', 'length', 'length', 'length', 'rad')
#: admissible values of each parameter: 'positive' (> 0), 'nonnegative' (>= 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive', 'positive', 'positive', 'real')
#: default parameter set and initial state (the CLI's defaults)
DEFAULT_PARAMS = {'g': 1.0, 'ell': 1.0, 'L': 2.0, 'D': 0.5, 'alpha': 0.7853981633974483}
DEFAULT_STATE = {'n_x': -0.009999000149975006, 'n_y': 0.009999000149975006, 'n_z': 0.9999000149975006, 'omega_x': -0.001, 'omega_y': 0.001, 'omega_z': 0.1, 'omega_n': 0.10000999950005002}
#: (coordinate, rate) pairs of the state: none (n and omega are not coordinate and rate)
RATE_PAIRS = ()
TILT_NAMES = ()
#: the vertical spin omega . n (carried as a state), whose zero crossings are the spin reversals
REVERSAL_EVENTS = ('omega_n',)
EVENT_NAMES = ()
#: largest |value| of each named state where this fidelity holds (empty: everywhere)
VALIDITY = {}
VALIDITY_DOC = ''
MULTIPLIER_NAMES = ('contact_force_x', 'contact_force_y', 'contact_force_z')
#: non-conservative forces (the torque -sigma omega): the module has ``power_dissipated(s, p)``
HAS_DISSIPATION = False
#: model-specific helpers: named parameter sets and the initial state from the physical description
EXPORTS = ('PRESETS', 'PRESET_SOURCES', 'initial_state')
#: named parameter sets (SI units); sources in PRESET_SOURCES
PRESETS = {}
PRESET_SOURCES = {}
#: the model file the body comes from
SOURCE = 'knifeedge.derive.rigid_knife_edge'
INPUT_HASH = '9c0aecf3f2e536089088558f11d805276c25d0d4f023d98f2e9ef89cec572345'
SYMPY_VERSION = '1.14.0'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 253, 'constants': 25, 'rhs_q': 221, 'rhs_pose': 293, 'rhs_pose_q': 261, 'pose_rates': 73, 'energy': 56, 'multipliers': 267}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (253 operations)."""
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = n_y*omega_z - n_z*omega_y
    _c1 = -n_x*omega_z + n_z*omega_x
    _c2 = n_x*omega_y - n_y*omega_x
    _c3 = (n_z*n_z)
    _c4 = math.sin(alpha)
    _c5 = math.cos(alpha)
    _c6 = -_c4*n_x + _c5*n_y
    _c7 = _c4*_c6 + n_x
    _c8 = (_c7*_c7)
    _c9 = -_c5*_c6 + n_y
    _c10 = (_c9*_c9)
    _c11 = _c10 + _c3 + _c8
    _c12 = 1/math.sqrt(_c11)
    _c13 = D*_c12
    _c14 = D - _c13*n_z + ell
    _c15 = (_c14*_c14)
    _c16 = (D*D*D*D)
    _c17 = (1.0/(_c11*_c11))
    _c18 = _c10*_c16*_c17*_c8
    _c19 = -_c14
    _c20 = (D*D)
    _c21 = 1/_c11
    _c22 = _c20*_c21
    _c23 = _c10*_c22
    _c24 = (L*L)
    _c25 = _c22*_c8
    _c26 = _c24 + _c25
    _c27 = _c23 + _c26
    _c28 = _c15 + _c23
    _c29 = _c14*_c19
    _c30 = _c26 - _c29
    _c31 = _c15*_c25
    _c32 = 1/(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)
    _c33 = _c11**((-3.0/2.0))
    _c34 = (D*D*D)
    _c35 = _c14*_c33*_c34
    _c36 = _c10*_c7
    _c37 = _c13*_c7
    _c38 = _c14*_c30*_c37
    _c39 = _c24*omega_x
    _c40 = _c13*_c9
    _c41 = -_c14*omega_y - _c40*omega_z
    _c42 = -_c37*omega_y + _c40*omega_x
    _c43 = _c4*_c5
    _c44 = (_c5*_c5)
    _c45 = -_c43*_c7 - (1.0/2.0)*_c9*(2 - 2*_c44)
    _c46 = D*_c33
    _c47 = _c46*n_z
    _c48 = (_c4*_c4)
    _c49 = -_c43*_c9 - (1.0/2.0)*_c7*(2 - 2*_c48)
    _c50 = -_c0*_c47*_c49 - _c1*_c45*_c47 + _c2*(-_c13 + _c3*_c46)
    _c51 = _c46*_c7
    _c52 = _c2*n_z
    _c53 = _c13*_c43
    _c54 = _c0*(-_c13*(1 - _c48) - _c49*_c51) + _c1*(-_c45*_c51 - _c53) + _c51*_c52
    _c55 = _c41*omega_z - _c42*omega_x + _c50*omega_x - _c54*omega_z + g*n_y
    _c56 = _c14*omega_x + _c37*omega_z
    _c57 = _c46*_c9
    _c58 = _c0*(-_c49*_c57 - _c53) + _c1*(-_c13*(1 - _c44) - _c45*_c57) + _c52*_c57
    _c59 = _c42*omega_y - _c50*omega_y - _c56*omega_z + _c58*omega_z + g*n_x
    _c60 = D*_c12*_c59*_c9 - _c37*_c55 - _c39*omega_y
    _c61 = _c22*_c7*_c9
    _c62 = -_c41*omega_y + _c54*omega_y + _c56*omega_x - _c58*omega_x + g*n_z
    _c63 = _c14*_c59 + _c37*_c62 + _c39*omega_z
    _c64 = -_c14*_c55 - _c40*_c62
    _c65 = _c32*(_c60*(-_c35*_c36 - _c38) + _c63*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c64*(_c23*_c29 + _c27*_c30))
    _c66 = _c35*_c8*_c9
    _c67 = _c32*(_c60*(-_c14*_c28*_c40 - _c66) + _c63*(_c27*_c28 - _c31) + _c64*(_c15*_c61 + _c27*_c61))
    _c68 = _c32*(_c60*(-_c18 + _c28*_c30) + _c63*(D*_c12*_c19*_c28*_c9 - _c66) + _c64*(_c19*_c33*_c34*_c36 - _c38))
    ds[0] = _c0
    ds[1] = _c1
    ds[2] = _c2
    ds[3] = _c65
    ds[4] = _c67
    ds[5] = _c68
    ds[6] = _c65*n_x + _c67*n_y + _c68*n_z


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 7."""
    ds = np.empty(7)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 21 parameter-only subexpressions of the right-hand side (25 operations)."""
    q = np.empty(26)
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
    _c0 = math.cos(alpha)
    _c1 = math.sin(alpha)
    _c2 = D + ell
    _c3 = (D*D)
    _c4 = (L*L)
    _c5 = (D*D*D*D)
    _c6 = (_c1*_c1) - 1
    _c7 = _c0*_c1
    _c8 = (_c0*_c0) - 1
    _c9 = (D*D*D)
    q[5] = _c0
    q[6] = -_c1
    q[7] = _c1
    q[8] = -_c0
    q[9] = -D
    q[10] = _c2
    q[11] = _c3
    q[12] = -_c2
    q[13] = _c4
    q[14] = -_c3
    q[15] = -_c5
    q[16] = _c5
    q[17] = _c6
    q[18] = -_c7
    q[19] = _c8
    q[20] = D*_c6
    q[21] = -D*_c7
    q[22] = D*_c8
    q[23] = -_c9
    q[24] = -_c4
    q[25] = _c9
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (221 operations)."""
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
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
    _c0 = n_y*omega_z - n_z*omega_y
    _c1 = -n_x*omega_z + n_z*omega_x
    _c2 = n_x*omega_y - n_y*omega_x
    _c3 = _k0*n_y + _k1*n_x
    _c4 = _c3*_k2 + n_x
    _c5 = (_c4*_c4)
    _c6 = (n_z*n_z)
    _c7 = _c3*_k3 + n_y
    _c8 = (_c7*_c7)
    _c9 = _c5 + _c6 + _c8
    _c10 = 1/math.sqrt(_c9)
    _c11 = _c10*_k4
    _c12 = _c11*n_z + _k5
    _c13 = (_c12*_c12)
    _c14 = _c13*_c5
    _c15 = (1.0/(_c9*_c9))
    _c16 = _c15*_c8*_k10
    _c17 = D*_c10
    _c18 = _c17*n_z + _k7
    _c19 = _c12*_c18
    _c20 = 1/_c9
    _c21 = _c20*_k6
    _c22 = _c21*_c8
    _c23 = _c21*_c5 + _k8
    _c24 = _c22 + _c23
    _c25 = _c16*_c5
    _c26 = _c13 + _c22
    _c27 = _c19*_c22
    _c28 = -_c19 + _c23
    _c29 = _c20*_k9
    _c30 = _c14*_c29
    _c31 = _c24*_c28
    _c32 = 1/(_c14*_c16 + _c15*_c19*_c5*_c8*_k11 + _c24*_c25 + _c26*_c27 + _c26*_c31 + _c28*_c30)
    _c33 = _c9**((-3.0/2.0))
    _c34 = _c12*_c33*_k18
    _c35 = _c4*_c8
    _c36 = _c11*_c4
    _c37 = _c12*_c28*_c36
    _c38 = _c17*_c4
    _c39 = _c12*omega_x + _c38*omega_z
    _c40 = _c17*_c7
    _c41 = _c36*omega_y + _c40*omega_x
    _c42 = _c4*_k12 + _c7*_k13
    _c43 = _c33*_k4
    _c44 = _c43*n_z
    _c45 = _c4*_k13 + _c7*_k14
    _c46 = D*_c33
    _c47 = _c0*_c42*_c44 + _c1*_c44*_c45 + _c2*(_c11 + _c46*_c6)
    _c48 = _c2*_c46*n_z
    _c49 = _c10*_k16
    _c50 = _c43*_c7
    _c51 = _c0*(_c42*_c50 + _c49) + _c1*(_c10*_k17 + _c45*_c50) + _c48*_c7
    _c52 = -_c39*omega_z + _c41*omega_y - _c47*omega_y + _c51*omega_z + g*n_x
    _c53 = _c11*_c7
    _c54 = -_c12*omega_y + _c53*omega_z
    _c55 = _c4*_c43
    _c56 = _c0*(_c10*_k15 + _c42*_c55) + _c1*(_c45*_c55 + _c49) + _c4*_c48
    _c57 = -_c41*omega_x + _c47*omega_x + _c54*omega_z - _c56*omega_z + g*n_y
    _c58 = _c36*_c57 + _c40*_c52 + _k19*omega_x*omega_y
    _c59 = _c4*_c7
    _c60 = _c21*_c59
    _c61 = _c24*_c60
    _c62 = _c39*omega_x - _c51*omega_x - _c54*omega_y + _c56*omega_y + g*n_z
    _c63 = _c12*_c52 + _c38*_c62 + _k8*omega_x*omega_z
    _c64 = -_c12*_c57 + _c53*_c62
    _c65 = _c32*(_c58*(_c34*_c35 + _c37) + _c63*(_c19*_c29*_c59 + _c61) + _c64*(_c27 + _c31))
    _c66 = _c34*_c5*_c7
    _c67 = _c32*(_c58*(_c12*_c26*_c53 + _c66) + _c63*(_c24*_c26 + _c30) + _c64*(_c13*_c60 + _c61))
    _c68 = _c32*(_c58*(_c25 + _c26*_c28) + _c63*(_c18*_c26*_c40 + _c66) + _c64*(_c18*_c33*_c35*_k20 + _c37))
    ds[0] = _c0
    ds[1] = _c1
    ds[2] = _c2
    ds[3] = _c65
    ds[4] = _c67
    ds[5] = _c68
    ds[6] = _c65*n_x + _c67*n_y + _c68*n_z


@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds`` (293 operations)."""
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    psi = s[7]
    x = s[8]
    y = s[9]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = n_y*omega_z - n_z*omega_y
    _c1 = -n_x*omega_z + n_z*omega_x
    _c2 = n_x*omega_y - n_y*omega_x
    _c3 = (n_z*n_z)
    _c4 = math.sin(alpha)
    _c5 = math.cos(alpha)
    _c6 = -_c4*n_x + _c5*n_y
    _c7 = _c4*_c6 + n_x
    _c8 = (_c7*_c7)
    _c9 = -_c5*_c6 + n_y
    _c10 = (_c9*_c9)
    _c11 = _c10 + _c3 + _c8
    _c12 = 1/math.sqrt(_c11)
    _c13 = D*_c12
    _c14 = D - _c13*n_z + ell
    _c15 = (_c14*_c14)
    _c16 = (D*D*D*D)
    _c17 = (1.0/(_c11*_c11))
    _c18 = _c10*_c16*_c17*_c8
    _c19 = -_c14
    _c20 = (D*D)
    _c21 = 1/_c11
    _c22 = _c20*_c21
    _c23 = _c10*_c22
    _c24 = (L*L)
    _c25 = _c22*_c8
    _c26 = _c24 + _c25
    _c27 = _c23 + _c26
    _c28 = _c15 + _c23
    _c29 = _c14*_c19
    _c30 = _c26 - _c29
    _c31 = _c15*_c25
    _c32 = 1/(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)
    _c33 = _c11**((-3.0/2.0))
    _c34 = (D*D*D)
    _c35 = _c14*_c33*_c34
    _c36 = _c10*_c7
    _c37 = _c13*_c7
    _c38 = _c14*_c30*_c37
    _c39 = _c24*omega_x
    _c40 = _c13*_c9
    _c41 = -_c14*omega_y - _c40*omega_z
    _c42 = -_c37*omega_y + _c40*omega_x
    _c43 = _c4*_c5
    _c44 = (_c5*_c5)
    _c45 = -_c43*_c7 - (1.0/2.0)*_c9*(2 - 2*_c44)
    _c46 = D*_c33
    _c47 = _c46*n_z
    _c48 = (_c4*_c4)
    _c49 = -_c43*_c9 - (1.0/2.0)*_c7*(2 - 2*_c48)
    _c50 = -_c0*_c47*_c49 - _c1*_c45*_c47 + _c2*(-_c13 + _c3*_c46)
    _c51 = _c46*_c7
    _c52 = _c2*n_z
    _c53 = _c13*_c43
    _c54 = _c0*(-_c13*(1 - _c48) - _c49*_c51) + _c1*(-_c45*_c51 - _c53) + _c51*_c52
    _c55 = _c41*omega_z - _c42*omega_x + _c50*omega_x - _c54*omega_z + g*n_y
    _c56 = _c14*omega_x + _c37*omega_z
    _c57 = _c46*_c9
    _c58 = _c0*(-_c49*_c57 - _c53) + _c1*(-_c13*(1 - _c44) - _c45*_c57) + _c52*_c57
    _c59 = _c42*omega_y - _c50*omega_y - _c56*omega_z + _c58*omega_z + g*n_x
    _c60 = D*_c12*_c59*_c9 - _c37*_c55 - _c39*omega_y
    _c61 = _c22*_c7*_c9
    _c62 = -_c41*omega_y + _c54*omega_y + _c56*omega_x - _c58*omega_x + g*n_z
    _c63 = _c14*_c59 + _c37*_c62 + _c39*omega_z
    _c64 = -_c14*_c55 - _c40*_c62
    _c65 = _c32*(_c60*(-_c35*_c36 - _c38) + _c63*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c64*(_c23*_c29 + _c27*_c30))
    _c66 = _c35*_c8*_c9
    _c67 = _c32*(_c60*(-_c14*_c28*_c40 - _c66) + _c63*(_c27*_c28 - _c31) + _c64*(_c15*_c61 + _c27*_c61))
    _c68 = _c32*(_c60*(-_c18 + _c28*_c30) + _c63*(D*_c12*_c19*_c28*_c9 - _c66) + _c64*(_c19*_c33*_c34*_c36 - _c38))
    _c69 = _c3 + (n_y*n_y)
    _c70 = math.sin(psi)
    _c71 = 1/math.sqrt(_c69)
    _c72 = (n_x*n_x)
    _c73 = _c71*_c72
    _c74 = 1 - _c72
    _c75 = _c71*_c74
    _c76 = _c42*(-_c73*n_y - _c75*n_y) + _c56*(_c73*n_z + _c75*n_z)
    _c77 = math.cos(psi)
    _c78 = _c71*n_x
    _c79 = _c41*_c71*_c74 - _c42*_c78*n_z - _c56*_c78*n_y
    ds[0] = _c0
    ds[1] = _c1
    ds[2] = _c2
    ds[3] = _c65
    ds[4] = _c67
    ds[5] = _c68
    ds[6] = _c65*n_x + _c67*n_y + _c68*n_z
    ds[7] = (n_y*omega_y + n_z*omega_z)/_c69
    ds[8] = -_c70*_c76 + _c77*_c79
    ds[9] = _c70*_c79 + _c76*_c77


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length 10."""
    ds = np.empty(10)
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p`` (261 operations)."""
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    psi = s[7]
    x = s[8]
    y = s[9]
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
    _c0 = n_y*omega_z - n_z*omega_y
    _c1 = -n_x*omega_z + n_z*omega_x
    _c2 = n_x*omega_y - n_y*omega_x
    _c3 = _k0*n_y + _k1*n_x
    _c4 = _c3*_k2 + n_x
    _c5 = (_c4*_c4)
    _c6 = (n_z*n_z)
    _c7 = _c3*_k3 + n_y
    _c8 = (_c7*_c7)
    _c9 = _c5 + _c6 + _c8
    _c10 = 1/math.sqrt(_c9)
    _c11 = _c10*_k4
    _c12 = _c11*n_z + _k5
    _c13 = (_c12*_c12)
    _c14 = _c13*_c5
    _c15 = (1.0/(_c9*_c9))
    _c16 = _c15*_c8*_k10
    _c17 = D*_c10
    _c18 = _c17*n_z + _k7
    _c19 = _c12*_c18
    _c20 = 1/_c9
    _c21 = _c20*_k6
    _c22 = _c21*_c8
    _c23 = _c21*_c5 + _k8
    _c24 = _c22 + _c23
    _c25 = _c16*_c5
    _c26 = _c13 + _c22
    _c27 = _c19*_c22
    _c28 = -_c19 + _c23
    _c29 = _c20*_k9
    _c30 = _c14*_c29
    _c31 = _c24*_c28
    _c32 = 1/(_c14*_c16 + _c15*_c19*_c5*_c8*_k11 + _c24*_c25 + _c26*_c27 + _c26*_c31 + _c28*_c30)
    _c33 = _c9**((-3.0/2.0))
    _c34 = _c12*_c33*_k18
    _c35 = _c4*_c8
    _c36 = _c11*_c4
    _c37 = _c12*_c28*_c36
    _c38 = _c17*_c4
    _c39 = _c12*omega_x + _c38*omega_z
    _c40 = _c17*_c7
    _c41 = _c36*omega_y + _c40*omega_x
    _c42 = _c4*_k12 + _c7*_k13
    _c43 = _c33*_k4
    _c44 = _c43*n_z
    _c45 = _c4*_k13 + _c7*_k14
    _c46 = D*_c33
    _c47 = _c0*_c42*_c44 + _c1*_c44*_c45 + _c2*(_c11 + _c46*_c6)
    _c48 = _c2*_c46*n_z
    _c49 = _c10*_k16
    _c50 = _c43*_c7
    _c51 = _c0*(_c42*_c50 + _c49) + _c1*(_c10*_k17 + _c45*_c50) + _c48*_c7
    _c52 = -_c39*omega_z + _c41*omega_y - _c47*omega_y + _c51*omega_z + g*n_x
    _c53 = _c11*_c7
    _c54 = -_c12*omega_y + _c53*omega_z
    _c55 = _c4*_c43
    _c56 = _c0*(_c10*_k15 + _c42*_c55) + _c1*(_c45*_c55 + _c49) + _c4*_c48
    _c57 = -_c41*omega_x + _c47*omega_x + _c54*omega_z - _c56*omega_z + g*n_y
    _c58 = _c36*_c57 + _c40*_c52 + _k19*omega_x*omega_y
    _c59 = _c4*_c7
    _c60 = _c21*_c59
    _c61 = _c24*_c60
    _c62 = _c39*omega_x - _c51*omega_x - _c54*omega_y + _c56*omega_y + g*n_z
    _c63 = _c12*_c52 + _c38*_c62 + _k8*omega_x*omega_z
    _c64 = -_c12*_c57 + _c53*_c62
    _c65 = _c32*(_c58*(_c34*_c35 + _c37) + _c63*(_c19*_c29*_c59 + _c61) + _c64*(_c27 + _c31))
    _c66 = _c34*_c5*_c7
    _c67 = _c32*(_c58*(_c12*_c26*_c53 + _c66) + _c63*(_c24*_c26 + _c30) + _c64*(_c13*_c60 + _c61))
    _c68 = _c32*(_c58*(_c25 + _c26*_c28) + _c63*(_c18*_c26*_c40 + _c66) + _c64*(_c18*_c33*_c35*_k20 + _c37))
    _c69 = _c6 + (n_y*n_y)
    _c70 = math.sin(psi)
    _c71 = 1/math.sqrt(_c69)
    _c72 = (n_x*n_x)
    _c73 = _c71*_c72
    _c74 = 1 - _c72
    _c75 = _c71*_c74
    _c76 = _c39*(_c73*n_z + _c75*n_z) + _c41*(-_c73*n_y - _c75*n_y)
    _c77 = math.cos(psi)
    _c78 = _c71*n_x
    _c79 = -_c39*_c78*n_y - _c41*_c78*n_z + _c54*_c71*_c74
    ds[0] = _c0
    ds[1] = _c1
    ds[2] = _c2
    ds[3] = _c65
    ds[4] = _c67
    ds[5] = _c68
    ds[6] = _c65*n_x + _c67*n_y + _c68*n_z
    ds[7] = (n_y*omega_y + n_z*omega_z)/_c69
    ds[8] = -_c70*_c76 + _c77*_c79
    ds[9] = _c70*_c79 + _c76*_c77


@njit(cache=True)
def pose_rates(s, p):
    """Return (psi_dot, x_dot, y_dot) at the pose-extended state ``s`` (73 operations)."""
    out = np.empty(3)
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    psi = s[7]
    x = s[8]
    y = s[9]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (n_z*n_z)
    _c1 = _c0 + (n_y*n_y)
    _c2 = math.sin(psi)
    _c3 = 1/math.sqrt(_c1)
    _c4 = (n_x*n_x)
    _c5 = _c3*_c4
    _c6 = 1 - _c4
    _c7 = _c3*_c6
    _c8 = math.sin(alpha)
    _c9 = math.cos(alpha)
    _c10 = -_c8*n_x + _c9*n_y
    _c11 = _c10*_c8 + n_x
    _c12 = -_c10*_c9 + n_y
    _c13 = D/math.sqrt(_c0 + (_c11*_c11) + (_c12*_c12))
    _c14 = D - _c13*n_z + ell
    _c15 = _c13*omega_z
    _c16 = _c11*_c15 + _c14*omega_x
    _c17 = -_c11*_c13*omega_y + _c12*_c13*omega_x
    _c18 = _c16*(_c5*n_z + _c7*n_z) + _c17*(-_c5*n_y - _c7*n_y)
    _c19 = math.cos(psi)
    _c20 = _c3*n_x
    _c21 = -_c16*_c20*n_y - _c17*_c20*n_z + _c3*_c6*(-_c12*_c15 - _c14*omega_y)
    out[0] = (n_y*omega_y + n_z*omega_z)/_c1
    out[1] = -_c18*_c2 + _c19*_c21
    out[2] = _c18*_c19 + _c2*_c21
    return out


@njit(cache=True)
def energy(s, p):
    """Mechanical energy (56 operations)."""
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = ((1.0/2.0))*(L*L)
    _c1 = math.sin(alpha)
    _c2 = math.cos(alpha)
    _c3 = -_c1*n_x + _c2*n_y
    _c4 = _c1*_c3 + n_x
    _c5 = -_c2*_c3 + n_y
    _c6 = D/math.sqrt((_c4*_c4) + (_c5*_c5) + (n_z*n_z))
    _c7 = D - _c6*n_z + ell
    _c8 = _c6*omega_z
    _c9 = _c5*_c6
    _c10 = _c4*_c6
    energy = _c0*(omega_y*omega_y) + _c0*(omega_z*omega_z) + g*(_c10*n_x - _c7*n_z + _c9*n_y) + ((1.0/2.0))*((-_c10*omega_y + _c9*omega_x)*(-_c10*omega_y + _c9*omega_x)) + ((1.0/2.0))*((_c4*_c8 + _c7*omega_x)*(_c4*_c8 + _c7*omega_x)) + ((1.0/2.0))*((-_c5*_c8 - _c7*omega_y)*(-_c5*_c8 - _c7*omega_y))
    return energy




@njit(cache=True)
def multipliers(s, p):
    """Contact force on the body in body axes (267 operations)."""
    out = np.empty(3)
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (n_z*n_z)
    _c1 = math.sin(alpha)
    _c2 = math.cos(alpha)
    _c3 = -_c1*n_x + _c2*n_y
    _c4 = _c1*_c3 + n_x
    _c5 = (_c4*_c4)
    _c6 = -_c2*_c3 + n_y
    _c7 = (_c6*_c6)
    _c8 = _c0 + _c5 + _c7
    _c9 = 1/math.sqrt(_c8)
    _c10 = D*_c9
    _c11 = D - _c10*n_z + ell
    _c12 = _c10*_c4
    _c13 = _c11*omega_x + _c12*omega_z
    _c14 = _c13*omega_z
    _c15 = _c10*_c6
    _c16 = -_c12*omega_y + _c15*omega_x
    _c17 = -n_x*omega_z + n_z*omega_x
    _c18 = _c1*_c2
    _c19 = (_c2*_c2)
    _c20 = -_c18*_c4 - (1.0/2.0)*_c6*(2 - 2*_c19)
    _c21 = _c8**((-3.0/2.0))
    _c22 = D*_c21
    _c23 = _c22*n_z
    _c24 = n_y*omega_z - n_z*omega_y
    _c25 = (_c1*_c1)
    _c26 = -_c18*_c6 - (1.0/2.0)*_c4*(2 - 2*_c25)
    _c27 = n_x*omega_y - n_y*omega_x
    _c28 = -_c17*_c20*_c23 - _c23*_c24*_c26 + _c27*(_c0*_c22 - _c10)
    _c29 = _c28*omega_y
    _c30 = _c22*_c6
    _c31 = _c27*n_z
    _c32 = _c10*_c18
    _c33 = _c17*(-_c10*(1 - _c19) - _c20*_c30) + _c24*(-_c26*_c30 - _c32) + _c30*_c31
    _c34 = (D*D*D)*_c21
    _c35 = _c11*_c34
    _c36 = _c35*_c5*_c6
    _c37 = (_c11*_c11)
    _c38 = (D*D)
    _c39 = 1/_c8
    _c40 = _c38*_c39
    _c41 = _c40*_c7
    _c42 = _c37 + _c41
    _c43 = (L*L)
    _c44 = _c43*omega_x
    _c45 = -_c11*omega_y - _c15*omega_z
    _c46 = _c22*_c4
    _c47 = _c17*(-_c20*_c46 - _c32) + _c24*(-_c10*(1 - _c25) - _c26*_c46) + _c31*_c46
    _c48 = -_c16*omega_x + _c28*omega_x + _c45*omega_z - _c47*omega_z + g*n_y
    _c49 = -_c14 + _c16*omega_y - _c29 + _c33*omega_z + g*n_x
    _c50 = D*_c49*_c6*_c9 - _c12*_c48 - _c44*omega_y
    _c51 = _c4*_c40*_c6
    _c52 = _c40*_c5
    _c53 = _c43 + _c52
    _c54 = _c41 + _c53
    _c55 = _c13*omega_x - _c33*omega_x - _c45*omega_y + _c47*omega_y + g*n_z
    _c56 = -_c11*_c48 - _c15*_c55
    _c57 = _c37*_c52
    _c58 = _c11*_c49 + _c12*_c55 + _c44*omega_z
    _c59 = _c50*(-_c11*_c15*_c42 - _c36) + _c56*(_c37*_c51 + _c51*_c54) + _c58*(_c42*_c54 - _c57)
    _c60 = (D*D*D*D)
    _c61 = (1.0/(_c8*_c8))
    _c62 = _c5*_c60*_c61*_c7
    _c63 = -_c11
    _c64 = _c11*_c63
    _c65 = _c53 - _c64
    _c66 = 1/(_c11*_c38*_c39*_c42*_c63*_c7 + _c11*_c5*_c60*_c61*_c63*_c7 - _c37*_c62 + _c42*_c54*_c65 - _c54*_c62 - _c57*_c65)
    _c67 = _c11*_c66
    _c68 = _c4*_c7
    _c69 = _c11*_c12*_c65
    _c70 = _c66*(_c50*(_c42*_c65 - _c62) + _c56*(_c34*_c63*_c68 - _c69) + _c58*(D*_c42*_c6*_c63*_c9 - _c36))
    _c71 = _c50*(-_c35*_c68 - _c69) + _c56*(_c41*_c64 + _c54*_c65) + _c58*(_c38*_c39*_c4*_c54*_c6 - _c51*_c64)
    out[0] = -_c14 - _c15*_c70 + _c16*omega_y - _c29 + _c33*omega_z - _c59*_c67 + g*n_x
    out[1] = _c12*_c70 + _c48 + _c67*_c71
    out[2] = -_c12*_c59*_c66 + _c15*_c66*_c71 + _c55
    return out


def initial_state(n0=(0.0, 0.0, 1.0), omega0=(0.0, 0.0, 0.0), pose=None):
    """Closed state (or pose-extended state) from the physical description.

    Parameters
    ----------
    n0 : upward vertical in body axes (normalized here); for tilts ``al``
        (about the body x axis) and ``be`` (about the body y axis),
        ``n0 = (cos(al) sin(be), sin(al), cos(al) cos(be))``.  Any direction
        is accepted (these coordinates have no singular orientation).
    omega0 : angular velocity in body axes [rad/s].
    pose : optional ``(psi, x, y)`` (heading [rad], centre of mass [m]); when
        given the pose-extended state is returned.

    Returns
    -------
    ndarray of shape (7,) (or (10,) with ``pose``) in the order of
    ``STATE_NAMES`` (+ ``POSE_NAMES``); ``omega_n = omega0 . n0``.
    """
    for name, value in (("n0", n0), ("omega0", omega0)):
        try:  # no strings, complex numbers (their imaginary part would be lost), bools or other objects
            items = [] if isinstance(value, (str, bytes)) else np.asarray(value, dtype=object).ravel().tolist()
        except (TypeError, ValueError):  # ragged
            items = []
        if not items or not all(isinstance(x, (int, float, np.integer, np.floating))
                                and not isinstance(x, (bool, np.bool_)) for x in items):
            raise TypeError(f"`{name}` must be 3 real numbers, got {value!r}")
    n0 = np.array(n0, dtype=float)
    omega0 = np.array(omega0, dtype=float)
    if n0.shape != (3,) or not np.isfinite(n0).all():
        raise ValueError(f"`n0` must be 3 finite numbers (the upward vertical in body axes), got {n0!r}")
    if omega0.shape != (3,) or not np.isfinite(omega0).all():
        raise ValueError(f"`omega0` must be 3 finite numbers (angular velocity in body axes), got {omega0!r}")
    norm = math.sqrt(float(n0 @ n0))
    if not norm > 0:
        raise ValueError("`n0` must not be the zero vector")
    n0 = n0 / norm
    s = np.concatenate([n0, omega0, [float(omega0 @ n0)]])
    if pose is None:
        return s
    pose = np.array(pose, dtype=float)
    if pose.shape != (3,) or not np.isfinite(pose).all():
        raise ValueError(f"`pose` must be 3 finite numbers (psi, x, y), got {pose!r}")
    return np.concatenate([s, pose])


def body_values(p):
    """``(mass, gravity, sigma, inertia, height)`` of the body at the parameters ``p``: what
    ``knifeedge.bodies.problems`` checks (``height``: of the centre of mass above the table at rest; ``None`` for
    a body that hangs below the edge it balances on)."""
    out = [0.0] * 13
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (L*L)
    out[0] = 1
    out[1] = g
    out[2] = 0
    out[3] = 0
    out[4] = 0
    out[5] = 0
    out[6] = 0
    out[7] = _c0
    out[8] = 0
    out[9] = 0
    out[10] = 0
    out[11] = _c0
    out[12] = 0
    return (out[0], out[1], out[2], (out[3:6], out[6:9], out[9:12]), None)



#: how to draw the body (derivation/drawing.py): names of the rows of ``body_points``,
#: segments between them, the contact point, the point masses, the tilts a picture may
#: magnify, the outline curves of ``body_outlines``
DRAWING = {'points': ('O', 'end_minus', 'end_plus', 'mass_minus', 'mass_plus', 'C', 'circle_centre'), 'segments': (('end_minus', 'end_plus'), ('end_minus', 'mass_minus'), ('end_plus', 'mass_plus'), ('O', 'circle_centre')), 'contact': 'C', 'masses': ('mass_minus', 'mass_plus'), 'magnify': ('n_x', 'n_y'), 'outlines': ('contact_circle',), 'description': 'inverted-U bar of half-length L (middle point O), masses M/2 hanging ell below its ends, the contact circle of radius D at the chiral angle alpha, contact point C its lowest point; tilts magnified by scaling n_x, n_y'}


@njit(cache=True)
def body_points(s, p):
    """World coordinates (z up, table z = 0) of DRAWING["points"] at the pose-extended state ``s``; shape (7, 3) (122 operations)."""
    out = np.empty((7, 3))
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    psi = s[7]
    x = s[8]
    y = s[9]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = math.cos(psi)
    _c1 = (n_x*n_x)
    _c2 = (n_z*n_z)
    _c3 = _c1 + _c2 + (n_y*n_y)
    _c4 = 1/_c3
    _c5 = math.sqrt(-_c1*_c4 + 1)
    _c6 = 1/_c5
    _c7 = _c6*n_z
    _c8 = _c4*n_x
    _c9 = _c7*_c8
    _c10 = math.sin(psi)
    _c11 = 1/math.sqrt(_c3)
    _c12 = _c11*n_y
    _c13 = _c6*n_y
    _c14 = _c1/_c3**((3.0/2.0))
    _c15 = -_c12*_c5 - _c13*_c14
    _c16 = -_c0*_c9 - _c10*_c15
    _c17 = _c16*ell + x
    _c18 = _c0*_c15 - _c10*_c9
    _c19 = _c18*ell + y
    _c20 = _c11*n_z
    _c21 = _c11*n_x
    _c22 = math.sin(alpha)
    _c23 = math.cos(alpha)
    _c24 = _c11*_c23*n_y - _c21*_c22
    _c25 = _c21 + _c22*_c24
    _c26 = _c12 - _c23*_c24
    _c27 = D/math.sqrt(_c2*_c4 + (_c25*_c25) + (_c26*_c26))
    _c28 = D + ell
    _c29 = -_c20*_c27 + _c28
    _c30 = _c25*_c27
    _c31 = _c26*_c27
    _c32 = _c12*_c31 - _c20*_c29 + _c21*_c30
    _c33 = _c20*ell + _c32
    _c34 = L*_c5
    _c35 = _c0*_c34
    _c36 = _c10*_c34
    _c37 = L*_c21
    _c38 = -_c37
    _c39 = -x
    _c40 = -y
    _c41 = _c30*_c5
    _c42 = _c13*_c8
    _c43 = _c14*_c7 + _c20*_c5
    out[0, 0] = _c17
    out[0, 1] = _c19
    out[0, 2] = _c33
    out[1, 0] = _c17 - _c35
    out[1, 1] = _c19 - _c36
    out[1, 2] = _c33 + _c38
    out[2, 0] = _c17 + _c35
    out[2, 1] = _c19 + _c36
    out[2, 2] = _c33 + _c37
    out[3, 0] = -_c35 - _c39
    out[3, 1] = -_c36 - _c40
    out[3, 2] = _c32 + _c38
    out[4, 0] = _c35 + x
    out[4, 1] = _c36 + y
    out[4, 2] = _c32 + _c37
    out[5, 0] = -_c0*_c41 + _c16*_c29 - _c31*(-_c0*_c42 - _c10*_c43) - _c39
    out[5, 1] = -_c10*_c41 + _c18*_c29 - _c31*(_c0*_c43 - _c10*_c42) - _c40
    out[5, 2] = 0
    out[6, 0] = _c16*_c28 + x
    out[6, 1] = _c18*_c28 + y
    out[6, 2] = _c20*_c28 + _c32
    return out


@njit(cache=True)
def body_outlines(s, p, uu):
    """World coordinates of the curves DRAWING["outlines"] at the parameters ``uu`` in [0, 2 pi); shape (1, len(uu), 3) (102 operations)."""
    out = np.empty((1, uu.shape[0], 3))
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    psi = s[7]
    x = s[8]
    y = s[9]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    for j in range(uu.shape[0]):
        u = uu[j]
        _c0 = math.cos(psi)
        _c1 = (n_x*n_x)
        _c2 = (n_z*n_z)
        _c3 = _c1 + _c2 + (n_y*n_y)
        _c4 = 1/_c3
        _c5 = math.sqrt(-_c1*_c4 + 1)
        _c6 = math.cos(alpha)
        _c7 = D*math.sin(u)
        _c8 = _c6*_c7
        _c9 = _c5*_c8
        _c10 = 1/_c5
        _c11 = _c10*n_y
        _c12 = _c4*n_x
        _c13 = _c0*_c12
        _c14 = math.sin(psi)
        _c15 = 1/math.sqrt(_c3)
        _c16 = _c15*n_z
        _c17 = _c1/_c3**((3.0/2.0))
        _c18 = _c10*n_z
        _c19 = _c16*_c5 + _c17*_c18
        _c20 = math.sin(alpha)
        _c21 = _c20*_c7
        _c22 = D + ell
        _c23 = -D*math.cos(u) + _c22
        _c24 = _c15*n_y
        _c25 = -_c11*_c17 - _c24*_c5
        _c26 = _c12*_c14
        _c27 = _c15*n_x
        _c28 = _c15*_c6*n_y - _c20*_c27
        _c29 = _c20*_c28 + _c27
        _c30 = _c24 - _c28*_c6
        _c31 = D/math.sqrt(_c2*_c4 + (_c29*_c29) + (_c30*_c30))
        out[0, j, 0] = _c0*_c9 + _c21*(-_c11*_c13 - _c14*_c19) + _c23*(-_c13*_c18 - _c14*_c25) + x
        out[0, j, 1] = _c14*_c9 + _c21*(_c0*_c19 - _c11*_c26) + _c23*(_c0*_c25 - _c18*_c26) + y
        out[0, j, 2] = _c16*_c23 - _c16*(-_c16*_c31 + _c22) + _c21*_c24 + _c24*_c30*_c31 + _c27*_c29*_c31 + _c27*_c8
    return out


#: operation counts of the Jacobians (derivation/jacobian.py)
OP_COUNTS.update(jacobian=3053, jacobian_p=2358)

@njit(cache=True)
def jacobian(s, p):
    """d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape (7, 7) (3053 operations)."""
    out = np.zeros((7, 7))
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = n_y*omega_z - n_z*omega_y
    _d0_2 = -omega_y
    _d0_4 = -n_z
    _c1 = -n_x*omega_z + n_z*omega_x
    _d1_0 = -omega_z
    _d1_5 = -n_x
    _c2 = n_x*omega_y - n_y*omega_x
    _d2_1 = -omega_x
    _d2_3 = -n_y
    _c3 = (n_z*n_z)
    _d3_2 = 2*n_z
    _c4 = math.sin(alpha)
    _c5 = math.cos(alpha)
    _c6 = -_c4*n_x + _c5*n_y
    _d6_0 = -_c4
    _c7 = _c4*_c6 + n_x
    _d7_0 = _c4*_d6_0 + 1
    _d7_1 = _c4*_c5
    _c8 = (_c7*_c7)
    _d8_0 = 2*_c7*_d7_0
    _d8_1 = 2*_c7*_d7_1
    _c9 = -_c5*_c6 + n_y
    _d9_0 = -_c5*_d6_0
    _d9_1 = 1 - (_c5*_c5)
    _c10 = (_c9*_c9)
    _d10_0 = 2*_c9*_d9_0
    _d10_1 = 2*_c9*_d9_1
    _c11 = _c10 + _c3 + _c8
    _d11_0 = _d10_0 + _d8_0
    _d11_1 = _d10_1 + _d8_1
    _c12 = 1/math.sqrt(_c11)
    _d12_0 = -(1.0/2.0)*_d11_0/_c11**((3.0/2.0))
    _d12_1 = -(1.0/2.0)*_d11_1/_c11**((3.0/2.0))
    _d12_2 = -(1.0/2.0)*_d3_2/_c11**((3.0/2.0))
    _c13 = D*_c12
    _d13_0 = D*_d12_0
    _d13_1 = D*_d12_1
    _d13_2 = D*_d12_2
    _c14 = D - _c13*n_z + ell
    _d14_0 = -_d13_0*n_z
    _d14_1 = -_d13_1*n_z
    _d14_2 = -_c13 - _d13_2*n_z
    _c15 = (_c14*_c14)
    _d15_0 = 2*_c14*_d14_0
    _d15_1 = 2*_c14*_d14_1
    _d15_2 = 2*_c14*_d14_2
    _c16 = (D*D*D*D)
    _c17 = (1.0/(_c11*_c11))
    _d17_0 = -2*_d11_0/(_c11*_c11*_c11)
    _d17_1 = -2*_d11_1/(_c11*_c11*_c11)
    _d17_2 = -2*_d3_2/(_c11*_c11*_c11)
    _c18 = _c10*_c16*_c17*_c8
    _d18_0 = _c10*_c16*_c17*_d8_0 + _c10*_c16*_c8*_d17_0 + _c16*_c17*_c8*_d10_0
    _d18_1 = _c10*_c16*_c17*_d8_1 + _c10*_c16*_c8*_d17_1 + _c16*_c17*_c8*_d10_1
    _d18_2 = _c10*_c16*_c8*_d17_2
    _c19 = -_c14
    _d19_0 = -_d14_0
    _d19_1 = -_d14_1
    _d19_2 = -_d14_2
    _c20 = (D*D)
    _c21 = 1/_c11
    _d21_0 = -_d11_0/(_c11*_c11)
    _d21_1 = -_d11_1/(_c11*_c11)
    _d21_2 = -_d3_2/(_c11*_c11)
    _c22 = _c20*_c21
    _d22_0 = _c20*_d21_0
    _d22_1 = _c20*_d21_1
    _d22_2 = _c20*_d21_2
    _c23 = _c10*_c22
    _d23_0 = _c10*_d22_0 + _c22*_d10_0
    _d23_1 = _c10*_d22_1 + _c22*_d10_1
    _d23_2 = _c10*_d22_2
    _c24 = (L*L)
    _c25 = _c22*_c8
    _d25_0 = _c22*_d8_0 + _c8*_d22_0
    _d25_1 = _c22*_d8_1 + _c8*_d22_1
    _d25_2 = _c8*_d22_2
    _c26 = _c24 + _c25
    _c27 = _c23 + _c26
    _d27_0 = _d23_0 + _d25_0
    _d27_1 = _d23_1 + _d25_1
    _d27_2 = _d23_2 + _d25_2
    _c28 = _c15 + _c23
    _d28_0 = _d15_0 + _d23_0
    _d28_1 = _d15_1 + _d23_1
    _d28_2 = _d15_2 + _d23_2
    _c29 = _c14*_c19
    _d29_0 = _c14*_d19_0 + _c19*_d14_0
    _d29_1 = _c14*_d19_1 + _c19*_d14_1
    _d29_2 = _c14*_d19_2 + _c19*_d14_2
    _c30 = _c26 - _c29
    _d30_0 = _d25_0 - _d29_0
    _d30_1 = _d25_1 - _d29_1
    _d30_2 = _d25_2 - _d29_2
    _c31 = _c15*_c25
    _d31_0 = _c15*_d25_0 + _c25*_d15_0
    _d31_1 = _c15*_d25_1 + _c25*_d15_1
    _d31_2 = _c15*_d25_2 + _c25*_d15_2
    _c32 = 1/(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)
    _d32_0 = -_c10*_c14*_c16*_c17*_c19*_d8_0/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) - _c10*_c14*_c16*_c19*_c8*_d17_0/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) - _c10*_c14*_c19*_c20*_c28*_d21_0/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c18*_d15_0/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c30*_d31_0/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d10_0*(-_c14*_c16*_c17*_c19*_c8 - _c14*_c19*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d14_0*(-_c10*_c16*_c17*_c19*_c8 - _c10*_c19*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d18_0*(_c15 + _c27)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d19_0*(-_c10*_c14*_c16*_c17*_c8 - _c10*_c14*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d27_0*(_c18 - _c28*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d28_0*(-_c10*_c14*_c19*_c20*_c21 - _c27*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d30_0*(-_c27*_c28 + _c31)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31))
    _d32_1 = -_c10*_c14*_c16*_c17*_c19*_d8_1/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) - _c10*_c14*_c16*_c19*_c8*_d17_1/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) - _c10*_c14*_c19*_c20*_c28*_d21_1/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c18*_d15_1/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c30*_d31_1/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d10_1*(-_c14*_c16*_c17*_c19*_c8 - _c14*_c19*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d14_1*(-_c10*_c16*_c17*_c19*_c8 - _c10*_c19*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d18_1*(_c15 + _c27)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d19_1*(-_c10*_c14*_c16*_c17*_c8 - _c10*_c14*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d27_1*(_c18 - _c28*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d28_1*(-_c10*_c14*_c19*_c20*_c21 - _c27*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d30_1*(-_c27*_c28 + _c31)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31))
    _d32_2 = -_c10*_c14*_c16*_c19*_c8*_d17_2/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) - _c10*_c14*_c19*_c20*_c28*_d21_2/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c18*_d15_2/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c30*_d31_2/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d14_2*(-_c10*_c16*_c17*_c19*_c8 - _c10*_c19*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d18_2*(_c15 + _c27)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d19_2*(-_c10*_c14*_c16*_c17*_c8 - _c10*_c14*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d27_2*(_c18 - _c28*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d28_2*(-_c10*_c14*_c19*_c20*_c21 - _c27*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d30_2*(-_c27*_c28 + _c31)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31))
    _c33 = _c11**((-3.0/2.0))
    _d33_0 = -(3.0/2.0)*_d11_0/_c11**((5.0/2.0))
    _d33_1 = -(3.0/2.0)*_d11_1/_c11**((5.0/2.0))
    _d33_2 = -(3.0/2.0)*_d3_2/_c11**((5.0/2.0))
    _c34 = (D*D*D)
    _c35 = _c14*_c33*_c34
    _d35_0 = _c14*_c34*_d33_0 + _c33*_c34*_d14_0
    _d35_1 = _c14*_c34*_d33_1 + _c33*_c34*_d14_1
    _d35_2 = _c14*_c34*_d33_2 + _c33*_c34*_d14_2
    _c36 = _c10*_c7
    _d36_0 = _c10*_d7_0 + _c7*_d10_0
    _d36_1 = _c10*_d7_1 + _c7*_d10_1
    _c37 = _c13*_c7
    _d37_0 = _c13*_d7_0 + _c7*_d13_0
    _d37_1 = _c13*_d7_1 + _c7*_d13_1
    _d37_2 = _c7*_d13_2
    _c38 = _c14*_c30*_c37
    _d38_0 = _c14*_c30*_d37_0 + _c14*_c37*_d30_0 + _c30*_c37*_d14_0
    _d38_1 = _c14*_c30*_d37_1 + _c14*_c37*_d30_1 + _c30*_c37*_d14_1
    _d38_2 = _c14*_c30*_d37_2 + _c14*_c37*_d30_2 + _c30*_c37*_d14_2
    _c39 = _c24*omega_x
    _c40 = _c13*_c9
    _d40_0 = _c13*_d9_0 + _c9*_d13_0
    _d40_1 = _c13*_d9_1 + _c9*_d13_1
    _d40_2 = _c9*_d13_2
    _c41 = -_c14*omega_y - _c40*omega_z
    _d41_0 = -_d14_0*omega_y - _d40_0*omega_z
    _d41_1 = -_d14_1*omega_y - _d40_1*omega_z
    _d41_2 = -_d14_2*omega_y - _d40_2*omega_z
    _d41_4 = -_c14
    _d41_5 = -_c40
    _c42 = -_c37*omega_y + _c40*omega_x
    _d42_0 = -_d37_0*omega_y + _d40_0*omega_x
    _d42_1 = -_d37_1*omega_y + _d40_1*omega_x
    _d42_2 = -_d37_2*omega_y + _d40_2*omega_x
    _d42_4 = -_c37
    _c43 = _c4*_c5
    _c44 = (_c5*_c5)
    _c45 = -_c43*_c7 - (1.0/2.0)*_c9*(2 - 2*_c44)
    _d45_0 = -_c43*_d7_0 + _d9_0*(_c44 - 1)
    _d45_1 = -_c43*_d7_1 + _d9_1*(_c44 - 1)
    _c46 = D*_c33
    _d46_0 = D*_d33_0
    _d46_1 = D*_d33_1
    _d46_2 = D*_d33_2
    _c47 = _c46*n_z
    _d47_0 = _d46_0*n_z
    _d47_1 = _d46_1*n_z
    _d47_2 = _c46 + _d46_2*n_z
    _c48 = (_c4*_c4)
    _c49 = -_c43*_c9 - (1.0/2.0)*_c7*(2 - 2*_c48)
    _d49_0 = -_c43*_d9_0 + _d7_0*(_c48 - 1)
    _d49_1 = -_c43*_d9_1 + _d7_1*(_c48 - 1)
    _c50 = -_c0*_c47*_c49 - _c1*_c45*_c47 + _c2*(-_c13 + _c3*_c46)
    _d50_0 = -_c0*_c47*_d49_0 - _c1*_c47*_d45_0 + _c2*_c3*_d46_0 - _c2*_d13_0 - _c45*_c47*_d1_0 + _d47_0*(-_c0*_c49 - _c1*_c45) + omega_y*(-_c13 + _c3*_c46)
    _d50_1 = -_c0*_c47*_d49_1 - _c1*_c47*_d45_1 + _c2*_c3*_d46_1 - _c2*_d13_1 - _c47*_c49*omega_z + _d2_1*(-_c13 + _c3*_c46) + _d47_1*(-_c0*_c49 - _c1*_c45)
    _d50_2 = _c2*_c3*_d46_2 + _c2*_c46*_d3_2 - _c2*_d13_2 - _c45*_c47*omega_x - _c47*_c49*_d0_2 + _d47_2*(-_c0*_c49 - _c1*_c45)
    _d50_3 = -_c45*_c47*n_z + _d2_3*(-_c13 + _c3*_c46)
    _d50_4 = -_c47*_c49*_d0_4 + n_x*(-_c13 + _c3*_c46)
    _d50_5 = -_c45*_c47*_d1_5 - _c47*_c49*n_y
    _c51 = _c46*_c7
    _d51_0 = _c46*_d7_0 + _c7*_d46_0
    _d51_1 = _c46*_d7_1 + _c7*_d46_1
    _d51_2 = _c7*_d46_2
    _c52 = _c2*n_z
    _d52_0 = n_z*omega_y
    _d52_1 = _d2_1*n_z
    _d52_3 = _d2_3*n_z
    _d52_4 = n_x*n_z
    _c53 = _c13*_c43
    _d53_0 = _c43*_d13_0
    _d53_1 = _c43*_d13_1
    _d53_2 = _c43*_d13_2
    _c54 = _c0*(-_c13*(1 - _c48) - _c49*_c51) + _c1*(-_c45*_c51 - _c53) + _c51*_c52
    _d54_0 = -_c0*_c51*_d49_0 + _c0*_d13_0*(_c48 - 1) - _c1*_c51*_d45_0 - _c1*_d53_0 + _c51*_d52_0 + _d1_0*(-_c45*_c51 - _c53) + _d51_0*(-_c0*_c49 - _c1*_c45 + _c52)
    _d54_1 = -_c0*_c51*_d49_1 + _c0*_d13_1*(_c48 - 1) - _c1*_c51*_d45_1 - _c1*_d53_1 + _c51*_d52_1 + _d51_1*(-_c0*_c49 - _c1*_c45 + _c52) + omega_z*(-_c13*(1 - _c48) - _c49*_c51)
    _d54_2 = _c0*_d13_2*(_c48 - 1) - _c1*_d53_2 + _c2*_c51 + _d0_2*(-_c13*(1 - _c48) - _c49*_c51) + _d51_2*(-_c0*_c49 - _c1*_c45 + _c52) + omega_x*(-_c45*_c51 - _c53)
    _d54_3 = _c51*_d52_3 + n_z*(-_c45*_c51 - _c53)
    _d54_4 = _c51*_d52_4 + _d0_4*(-_c13*(1 - _c48) - _c49*_c51)
    _d54_5 = _d1_5*(-_c45*_c51 - _c53) + n_y*(-_c13*(1 - _c48) - _c49*_c51)
    _c55 = _c41*omega_z - _c42*omega_x + _c50*omega_x - _c54*omega_z + g*n_y
    _d55_0 = _d41_0*omega_z - _d42_0*omega_x + _d50_0*omega_x - _d54_0*omega_z
    _d55_1 = _d41_1*omega_z - _d42_1*omega_x + _d50_1*omega_x - _d54_1*omega_z + g
    _d55_2 = _d41_2*omega_z - _d42_2*omega_x + _d50_2*omega_x - _d54_2*omega_z
    _d55_3 = -_c40*omega_x - _c42 + _c50 + _d50_3*omega_x - _d54_3*omega_z
    _d55_4 = _d41_4*omega_z - _d42_4*omega_x + _d50_4*omega_x - _d54_4*omega_z
    _d55_5 = _c41 - _c54 + _d41_5*omega_z + _d50_5*omega_x - _d54_5*omega_z
    _c56 = _c14*omega_x + _c37*omega_z
    _d56_0 = _d14_0*omega_x + _d37_0*omega_z
    _d56_1 = _d14_1*omega_x + _d37_1*omega_z
    _d56_2 = _d14_2*omega_x + _d37_2*omega_z
    _c57 = _c46*_c9
    _d57_0 = _c46*_d9_0 + _c9*_d46_0
    _d57_1 = _c46*_d9_1 + _c9*_d46_1
    _d57_2 = _c9*_d46_2
    _c58 = _c0*(-_c49*_c57 - _c53) + _c1*(-_c13*(1 - _c44) - _c45*_c57) + _c52*_c57
    _d58_0 = -_c0*_c57*_d49_0 - _c0*_d53_0 - _c1*_c57*_d45_0 + _c1*_d13_0*(_c44 - 1) + _c57*_d52_0 + _d1_0*(-_c13*(1 - _c44) - _c45*_c57) + _d57_0*(-_c0*_c49 - _c1*_c45 + _c52)
    _d58_1 = -_c0*_c57*_d49_1 - _c0*_d53_1 - _c1*_c57*_d45_1 + _c1*_d13_1*(_c44 - 1) + _c57*_d52_1 + _d57_1*(-_c0*_c49 - _c1*_c45 + _c52) + omega_z*(-_c49*_c57 - _c53)
    _d58_2 = -_c0*_d53_2 + _c1*_d13_2*(_c44 - 1) + _c2*_c57 + _d0_2*(-_c49*_c57 - _c53) + _d57_2*(-_c0*_c49 - _c1*_c45 + _c52) + omega_x*(-_c13*(1 - _c44) - _c45*_c57)
    _d58_3 = _c57*_d52_3 + n_z*(-_c13*(1 - _c44) - _c45*_c57)
    _d58_4 = _c57*_d52_4 + _d0_4*(-_c49*_c57 - _c53)
    _d58_5 = _d1_5*(-_c13*(1 - _c44) - _c45*_c57) + n_y*(-_c49*_c57 - _c53)
    _c59 = _c42*omega_y - _c50*omega_y - _c56*omega_z + _c58*omega_z + g*n_x
    _d59_0 = _d42_0*omega_y - _d50_0*omega_y - _d56_0*omega_z + _d58_0*omega_z + g
    _d59_1 = _d42_1*omega_y - _d50_1*omega_y - _d56_1*omega_z + _d58_1*omega_z
    _d59_2 = _d42_2*omega_y - _d50_2*omega_y - _d56_2*omega_z + _d58_2*omega_z
    _d59_3 = -_c14*omega_z + _c40*omega_y - _d50_3*omega_y + _d58_3*omega_z
    _d59_4 = _c42 - _c50 + _d42_4*omega_y - _d50_4*omega_y + _d58_4*omega_z
    _d59_5 = -_c37*omega_z - _c56 + _c58 - _d50_5*omega_y + _d58_5*omega_z
    _c60 = D*_c12*_c59*_c9 - _c37*_c55 - _c39*omega_y
    _d60_0 = D*_c12*_c59*_d9_0 + D*_c12*_c9*_d59_0 + D*_c59*_c9*_d12_0 - _c37*_d55_0 - _c55*_d37_0
    _d60_1 = D*_c12*_c59*_d9_1 + D*_c12*_c9*_d59_1 + D*_c59*_c9*_d12_1 - _c37*_d55_1 - _c55*_d37_1
    _d60_2 = D*_c12*_c9*_d59_2 + D*_c59*_c9*_d12_2 - _c37*_d55_2 - _c55*_d37_2
    _d60_3 = D*_c12*_c9*_d59_3 - _c24*omega_y - _c37*_d55_3
    _d60_4 = D*_c12*_c9*_d59_4 - _c37*_d55_4 - _c39
    _d60_5 = D*_c12*_c9*_d59_5 - _c37*_d55_5
    _c61 = _c22*_c7*_c9
    _d61_0 = _c22*_c7*_d9_0 + _c22*_c9*_d7_0 + _c7*_c9*_d22_0
    _d61_1 = _c22*_c7*_d9_1 + _c22*_c9*_d7_1 + _c7*_c9*_d22_1
    _d61_2 = _c7*_c9*_d22_2
    _c62 = -_c41*omega_y + _c54*omega_y + _c56*omega_x - _c58*omega_x + g*n_z
    _d62_0 = -_d41_0*omega_y + _d54_0*omega_y + _d56_0*omega_x - _d58_0*omega_x
    _d62_1 = -_d41_1*omega_y + _d54_1*omega_y + _d56_1*omega_x - _d58_1*omega_x
    _d62_2 = -_d41_2*omega_y + _d54_2*omega_y + _d56_2*omega_x - _d58_2*omega_x + g
    _d62_3 = _c14*omega_x + _c56 - _c58 + _d54_3*omega_y - _d58_3*omega_x
    _d62_4 = -_c41 + _c54 - _d41_4*omega_y + _d54_4*omega_y - _d58_4*omega_x
    _d62_5 = _c37*omega_x - _d41_5*omega_y + _d54_5*omega_y - _d58_5*omega_x
    _c63 = _c14*_c59 + _c37*_c62 + _c39*omega_z
    _d63_0 = _c14*_d59_0 + _c37*_d62_0 + _c59*_d14_0 + _c62*_d37_0
    _d63_1 = _c14*_d59_1 + _c37*_d62_1 + _c59*_d14_1 + _c62*_d37_1
    _d63_2 = _c14*_d59_2 + _c37*_d62_2 + _c59*_d14_2 + _c62*_d37_2
    _d63_3 = _c14*_d59_3 + _c24*omega_z + _c37*_d62_3
    _d63_4 = _c14*_d59_4 + _c37*_d62_4
    _d63_5 = _c14*_d59_5 + _c37*_d62_5 + _c39
    _c64 = -_c14*_c55 - _c40*_c62
    _d64_0 = -_c14*_d55_0 - _c40*_d62_0 - _c55*_d14_0 - _c62*_d40_0
    _d64_1 = -_c14*_d55_1 - _c40*_d62_1 - _c55*_d14_1 - _c62*_d40_1
    _d64_2 = -_c14*_d55_2 - _c40*_d62_2 - _c55*_d14_2 - _c62*_d40_2
    _d64_3 = -_c14*_d55_3 - _c40*_d62_3
    _d64_4 = -_c14*_d55_4 - _c40*_d62_4
    _d64_5 = -_c14*_d55_5 - _c40*_d62_5
    _c65 = _c32*(_c60*(-_c35*_c36 - _c38) + _c63*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c64*(_c23*_c29 + _c27*_c30))
    _d65_0 = _c20*_c21*_c27*_c32*_c63*_c7*_d9_0 + _c20*_c21*_c27*_c32*_c63*_c9*_d7_0 + _c20*_c27*_c32*_c63*_c7*_c9*_d21_0 + _c27*_c32*_c64*_d30_0 - _c29*_c32*_c63*_d61_0 + _c29*_c32*_c64*_d23_0 - _c32*_c35*_c60*_d36_0 - _c32*_c36*_c60*_d35_0 - _c32*_c60*_d38_0 + _c32*_d27_0*(_c20*_c21*_c63*_c7*_c9 + _c30*_c64) + _c32*_d29_0*(_c23*_c64 - _c61*_c63) + _c32*_d60_0*(-_c35*_c36 - _c38) + _c32*_d63_0*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c32*_d64_0*(_c23*_c29 + _c27*_c30) + _d32_0*(_c60*(-_c35*_c36 - _c38) + _c63*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c64*(_c23*_c29 + _c27*_c30))
    _d65_1 = _c20*_c21*_c27*_c32*_c63*_c7*_d9_1 + _c20*_c21*_c27*_c32*_c63*_c9*_d7_1 + _c20*_c27*_c32*_c63*_c7*_c9*_d21_1 + _c27*_c32*_c64*_d30_1 - _c29*_c32*_c63*_d61_1 + _c29*_c32*_c64*_d23_1 - _c32*_c35*_c60*_d36_1 - _c32*_c36*_c60*_d35_1 - _c32*_c60*_d38_1 + _c32*_d27_1*(_c20*_c21*_c63*_c7*_c9 + _c30*_c64) + _c32*_d29_1*(_c23*_c64 - _c61*_c63) + _c32*_d60_1*(-_c35*_c36 - _c38) + _c32*_d63_1*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c32*_d64_1*(_c23*_c29 + _c27*_c30) + _d32_1*(_c60*(-_c35*_c36 - _c38) + _c63*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c64*(_c23*_c29 + _c27*_c30))
    _d65_2 = _c20*_c27*_c32*_c63*_c7*_c9*_d21_2 + _c27*_c32*_c64*_d30_2 - _c29*_c32*_c63*_d61_2 + _c29*_c32*_c64*_d23_2 - _c32*_c36*_c60*_d35_2 - _c32*_c60*_d38_2 + _c32*_d27_2*(_c20*_c21*_c63*_c7*_c9 + _c30*_c64) + _c32*_d29_2*(_c23*_c64 - _c61*_c63) + _c32*_d60_2*(-_c35*_c36 - _c38) + _c32*_d63_2*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c32*_d64_2*(_c23*_c29 + _c27*_c30) + _d32_2*(_c60*(-_c35*_c36 - _c38) + _c63*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c64*(_c23*_c29 + _c27*_c30))
    _d65_3 = _c32*_d60_3*(-_c35*_c36 - _c38) + _c32*_d63_3*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c32*_d64_3*(_c23*_c29 + _c27*_c30)
    _d65_4 = _c32*_d60_4*(-_c35*_c36 - _c38) + _c32*_d63_4*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c32*_d64_4*(_c23*_c29 + _c27*_c30)
    _d65_5 = _c32*_d60_5*(-_c35*_c36 - _c38) + _c32*_d63_5*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c32*_d64_5*(_c23*_c29 + _c27*_c30)
    _c66 = _c35*_c8*_c9
    _d66_0 = _c35*_c8*_d9_0 + _c35*_c9*_d8_0 + _c8*_c9*_d35_0
    _d66_1 = _c35*_c8*_d9_1 + _c35*_c9*_d8_1 + _c8*_c9*_d35_1
    _d66_2 = _c8*_c9*_d35_2
    _c67 = _c32*(_c60*(-_c14*_c28*_c40 - _c66) + _c63*(_c27*_c28 - _c31) + _c64*(_c15*_c61 + _c27*_c61))
    _d67_0 = -_c14*_c28*_c32*_c60*_d40_0 - _c28*_c32*_c40*_c60*_d14_0 - _c32*_c60*_d66_0 + _c32*_c61*_c64*_d15_0 - _c32*_c63*_d31_0 + _c32*_c64*_d61_0*(_c15 + _c27) + _c32*_d27_0*(_c28*_c63 + _c61*_c64) + _c32*_d28_0*(-_c14*_c40*_c60 + _c27*_c63) + _c32*_d60_0*(-_c14*_c28*_c40 - _c66) + _c32*_d63_0*(_c27*_c28 - _c31) + _c32*_d64_0*(_c15*_c61 + _c27*_c61) + _d32_0*(_c60*(-_c14*_c28*_c40 - _c66) + _c63*(_c27*_c28 - _c31) + _c64*(_c15*_c61 + _c27*_c61))
    _d67_1 = -_c14*_c28*_c32*_c60*_d40_1 - _c28*_c32*_c40*_c60*_d14_1 - _c32*_c60*_d66_1 + _c32*_c61*_c64*_d15_1 - _c32*_c63*_d31_1 + _c32*_c64*_d61_1*(_c15 + _c27) + _c32*_d27_1*(_c28*_c63 + _c61*_c64) + _c32*_d28_1*(-_c14*_c40*_c60 + _c27*_c63) + _c32*_d60_1*(-_c14*_c28*_c40 - _c66) + _c32*_d63_1*(_c27*_c28 - _c31) + _c32*_d64_1*(_c15*_c61 + _c27*_c61) + _d32_1*(_c60*(-_c14*_c28*_c40 - _c66) + _c63*(_c27*_c28 - _c31) + _c64*(_c15*_c61 + _c27*_c61))
    _d67_2 = -_c14*_c28*_c32*_c60*_d40_2 - _c28*_c32*_c40*_c60*_d14_2 - _c32*_c60*_d66_2 + _c32*_c61*_c64*_d15_2 - _c32*_c63*_d31_2 + _c32*_c64*_d61_2*(_c15 + _c27) + _c32*_d27_2*(_c28*_c63 + _c61*_c64) + _c32*_d28_2*(-_c14*_c40*_c60 + _c27*_c63) + _c32*_d60_2*(-_c14*_c28*_c40 - _c66) + _c32*_d63_2*(_c27*_c28 - _c31) + _c32*_d64_2*(_c15*_c61 + _c27*_c61) + _d32_2*(_c60*(-_c14*_c28*_c40 - _c66) + _c63*(_c27*_c28 - _c31) + _c64*(_c15*_c61 + _c27*_c61))
    _d67_3 = _c32*_d60_3*(-_c14*_c28*_c40 - _c66) + _c32*_d63_3*(_c27*_c28 - _c31) + _c32*_d64_3*(_c15*_c61 + _c27*_c61)
    _d67_4 = _c32*_d60_4*(-_c14*_c28*_c40 - _c66) + _c32*_d63_4*(_c27*_c28 - _c31) + _c32*_d64_4*(_c15*_c61 + _c27*_c61)
    _d67_5 = _c32*_d60_5*(-_c14*_c28*_c40 - _c66) + _c32*_d63_5*(_c27*_c28 - _c31) + _c32*_d64_5*(_c15*_c61 + _c27*_c61)
    _c68 = _c32*(_c60*(-_c18 + _c28*_c30) + _c63*(D*_c12*_c19*_c28*_c9 - _c66) + _c64*(_c19*_c33*_c34*_c36 - _c38))
    _d68_0 = D*_c12*_c19*_c28*_c32*_c63*_d9_0 + D*_c19*_c28*_c32*_c63*_c9*_d12_0 + _c19*_c32*_c33*_c34*_c64*_d36_0 + _c19*_c32*_c34*_c36*_c64*_d33_0 + _c28*_c32*_c60*_d30_0 - _c32*_c60*_d18_0 - _c32*_c63*_d66_0 - _c32*_c64*_d38_0 + _c32*_d19_0*(D*_c12*_c28*_c63*_c9 + _c33*_c34*_c36*_c64) + _c32*_d28_0*(D*_c12*_c19*_c63*_c9 + _c30*_c60) + _c32*_d60_0*(-_c18 + _c28*_c30) + _c32*_d63_0*(D*_c12*_c19*_c28*_c9 - _c66) + _c32*_d64_0*(_c19*_c33*_c34*_c36 - _c38) + _d32_0*(_c60*(-_c18 + _c28*_c30) + _c63*(D*_c12*_c19*_c28*_c9 - _c66) + _c64*(_c19*_c33*_c34*_c36 - _c38))
    _d68_1 = D*_c12*_c19*_c28*_c32*_c63*_d9_1 + D*_c19*_c28*_c32*_c63*_c9*_d12_1 + _c19*_c32*_c33*_c34*_c64*_d36_1 + _c19*_c32*_c34*_c36*_c64*_d33_1 + _c28*_c32*_c60*_d30_1 - _c32*_c60*_d18_1 - _c32*_c63*_d66_1 - _c32*_c64*_d38_1 + _c32*_d19_1*(D*_c12*_c28*_c63*_c9 + _c33*_c34*_c36*_c64) + _c32*_d28_1*(D*_c12*_c19*_c63*_c9 + _c30*_c60) + _c32*_d60_1*(-_c18 + _c28*_c30) + _c32*_d63_1*(D*_c12*_c19*_c28*_c9 - _c66) + _c32*_d64_1*(_c19*_c33*_c34*_c36 - _c38) + _d32_1*(_c60*(-_c18 + _c28*_c30) + _c63*(D*_c12*_c19*_c28*_c9 - _c66) + _c64*(_c19*_c33*_c34*_c36 - _c38))
    _d68_2 = D*_c19*_c28*_c32*_c63*_c9*_d12_2 + _c19*_c32*_c34*_c36*_c64*_d33_2 + _c28*_c32*_c60*_d30_2 - _c32*_c60*_d18_2 - _c32*_c63*_d66_2 - _c32*_c64*_d38_2 + _c32*_d19_2*(D*_c12*_c28*_c63*_c9 + _c33*_c34*_c36*_c64) + _c32*_d28_2*(D*_c12*_c19*_c63*_c9 + _c30*_c60) + _c32*_d60_2*(-_c18 + _c28*_c30) + _c32*_d63_2*(D*_c12*_c19*_c28*_c9 - _c66) + _c32*_d64_2*(_c19*_c33*_c34*_c36 - _c38) + _d32_2*(_c60*(-_c18 + _c28*_c30) + _c63*(D*_c12*_c19*_c28*_c9 - _c66) + _c64*(_c19*_c33*_c34*_c36 - _c38))
    _d68_3 = _c32*_d60_3*(-_c18 + _c28*_c30) + _c32*_d63_3*(D*_c12*_c19*_c28*_c9 - _c66) + _c32*_d64_3*(_c19*_c33*_c34*_c36 - _c38)
    _d68_4 = _c32*_d60_4*(-_c18 + _c28*_c30) + _c32*_d63_4*(D*_c12*_c19*_c28*_c9 - _c66) + _c32*_d64_4*(_c19*_c33*_c34*_c36 - _c38)
    _d68_5 = _c32*_d60_5*(-_c18 + _c28*_c30) + _c32*_d63_5*(D*_c12*_c19*_c28*_c9 - _c66) + _c32*_d64_5*(_c19*_c33*_c34*_c36 - _c38)
    out[0, 1] = omega_z
    out[0, 2] = _d0_2
    out[0, 4] = _d0_4
    out[0, 5] = n_y
    out[1, 0] = _d1_0
    out[1, 2] = omega_x
    out[1, 3] = n_z
    out[1, 5] = _d1_5
    out[2, 0] = omega_y
    out[2, 1] = _d2_1
    out[2, 3] = _d2_3
    out[2, 4] = n_x
    out[3, 0] = _d65_0
    out[3, 1] = _d65_1
    out[3, 2] = _d65_2
    out[3, 3] = _d65_3
    out[3, 4] = _d65_4
    out[3, 5] = _d65_5
    out[4, 0] = _d67_0
    out[4, 1] = _d67_1
    out[4, 2] = _d67_2
    out[4, 3] = _d67_3
    out[4, 4] = _d67_4
    out[4, 5] = _d67_5
    out[5, 0] = _d68_0
    out[5, 1] = _d68_1
    out[5, 2] = _d68_2
    out[5, 3] = _d68_3
    out[5, 4] = _d68_4
    out[5, 5] = _d68_5
    out[6, 0] = _c65 + _d65_0*n_x + _d67_0*n_y + _d68_0*n_z
    out[6, 1] = _c67 + _d65_1*n_x + _d67_1*n_y + _d68_1*n_z
    out[6, 2] = _c68 + _d65_2*n_x + _d67_2*n_y + _d68_2*n_z
    out[6, 3] = _d65_3*n_x + _d67_3*n_y + _d68_3*n_z
    out[6, 4] = _d65_4*n_x + _d67_4*n_y + _d68_4*n_z
    out[6, 5] = _d65_5*n_x + _d67_5*n_y + _d68_5*n_z
    return out


@njit(cache=True)
def jacobian_p(s, p):
    """d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape (7, 5) (2358 operations)."""
    out = np.zeros((7, 5))
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = n_y*omega_z - n_z*omega_y
    _c1 = -n_x*omega_z + n_z*omega_x
    _c2 = n_x*omega_y - n_y*omega_x
    _c3 = (n_z*n_z)
    _c4 = math.sin(alpha)
    _d4_4 = math.cos(alpha)
    _c5 = math.cos(alpha)
    _d5_4 = -math.sin(alpha)
    _c6 = -_c4*n_x + _c5*n_y
    _d6_4 = -_d4_4*n_x + _d5_4*n_y
    _c7 = _c4*_c6 + n_x
    _d7_4 = _c4*_d6_4 + _c6*_d4_4
    _c8 = (_c7*_c7)
    _d8_4 = 2*_c7*_d7_4
    _c9 = -_c5*_c6 + n_y
    _d9_4 = -_c5*_d6_4 - _c6*_d5_4
    _c10 = (_c9*_c9)
    _d10_4 = 2*_c9*_d9_4
    _c11 = _c10 + _c3 + _c8
    _d11_4 = _d10_4 + _d8_4
    _c12 = 1/math.sqrt(_c11)
    _d12_4 = -(1.0/2.0)*_d11_4/_c11**((3.0/2.0))
    _c13 = D*_c12
    _d13_4 = D*_d12_4
    _c14 = D - _c13*n_z + ell
    _d14_3 = -_c12*n_z + 1
    _d14_4 = -_d13_4*n_z
    _c15 = (_c14*_c14)
    _d15_1 = 2*_c14
    _d15_3 = 2*_c14*_d14_3
    _d15_4 = 2*_c14*_d14_4
    _c16 = (D*D*D*D)
    _d16_3 = 4*(D*D*D)
    _c17 = (1.0/(_c11*_c11))
    _d17_4 = -2*_d11_4/(_c11*_c11*_c11)
    _c18 = _c10*_c16*_c17*_c8
    _d18_3 = _c10*_c17*_c8*_d16_3
    _d18_4 = _c10*_c16*_c17*_d8_4 + _c10*_c16*_c8*_d17_4 + _c16*_c17*_c8*_d10_4
    _c19 = -_c14
    _d19_3 = -_d14_3
    _d19_4 = -_d14_4
    _c20 = (D*D)
    _d20_3 = 2*D
    _c21 = 1/_c11
    _d21_4 = -_d11_4/(_c11*_c11)
    _c22 = _c20*_c21
    _d22_3 = _c21*_d20_3
    _d22_4 = _c20*_d21_4
    _c23 = _c10*_c22
    _d23_3 = _c10*_d22_3
    _d23_4 = _c10*_d22_4 + _c22*_d10_4
    _c24 = (L*L)
    _d24_2 = 2*L
    _c25 = _c22*_c8
    _d25_3 = _c8*_d22_3
    _d25_4 = _c22*_d8_4 + _c8*_d22_4
    _c26 = _c24 + _c25
    _c27 = _c23 + _c26
    _d27_3 = _d23_3 + _d25_3
    _d27_4 = _d23_4 + _d25_4
    _c28 = _c15 + _c23
    _d28_3 = _d15_3 + _d23_3
    _d28_4 = _d15_4 + _d23_4
    _c29 = _c14*_c19
    _d29_1 = -_c14 + _c19
    _d29_3 = _c14*_d19_3 + _c19*_d14_3
    _d29_4 = _c14*_d19_4 + _c19*_d14_4
    _c30 = _c26 - _c29
    _d30_1 = -_d29_1
    _d30_3 = _d25_3 - _d29_3
    _d30_4 = _d25_4 - _d29_4
    _c31 = _c15*_c25
    _d31_1 = _c25*_d15_1
    _d31_3 = _c15*_d25_3 + _c25*_d15_3
    _d31_4 = _c15*_d25_4 + _c25*_d15_4
    _c32 = 1/(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)
    _d32_1 = _c18*_d15_1/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c30*_d31_1/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d15_1*(-_c10*_c14*_c19*_c20*_c21 - _c27*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d30_1*(-_c27*_c28 + _c31)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) - (-_c10*_c14*_c16*_c17*_c8 - _c10*_c14*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + (-_c10*_c16*_c17*_c19*_c8 - _c10*_c19*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31))
    _d32_2 = _d24_2*(_c18 - _c28*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d24_2*(-_c27*_c28 + _c31)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31))
    _d32_3 = -_c10*_c14*_c17*_c19*_c8*_d16_3/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) - _c10*_c14*_c19*_c21*_c28*_d20_3/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c18*_d15_3/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c30*_d31_3/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d14_3*(-_c10*_c16*_c17*_c19*_c8 - _c10*_c19*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d18_3*(_c15 + _c27)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d19_3*(-_c10*_c14*_c16*_c17*_c8 - _c10*_c14*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d27_3*(_c18 - _c28*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d28_3*(-_c10*_c14*_c19*_c20*_c21 - _c27*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d30_3*(-_c27*_c28 + _c31)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31))
    _d32_4 = -_c10*_c14*_c16*_c17*_c19*_d8_4/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) - _c10*_c14*_c16*_c19*_c8*_d17_4/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) - _c10*_c14*_c19*_c20*_c28*_d21_4/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c18*_d15_4/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _c30*_d31_4/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d10_4*(-_c14*_c16*_c17*_c19*_c8 - _c14*_c19*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d14_4*(-_c10*_c16*_c17*_c19*_c8 - _c10*_c19*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d18_4*(_c15 + _c27)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d19_4*(-_c10*_c14*_c16*_c17*_c8 - _c10*_c14*_c20*_c21*_c28)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d27_4*(_c18 - _c28*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d28_4*(-_c10*_c14*_c19*_c20*_c21 - _c27*_c30)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)) + _d30_4*(-_c27*_c28 + _c31)/((_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31)*(_c10*_c14*_c16*_c17*_c19*_c8 + _c10*_c14*_c19*_c20*_c21*_c28 - _c15*_c18 - _c18*_c27 + _c27*_c28*_c30 - _c30*_c31))
    _c33 = _c11**((-3.0/2.0))
    _d33_4 = -(3.0/2.0)*_d11_4/_c11**((5.0/2.0))
    _c34 = (D*D*D)
    _d34_3 = 3*(D*D)
    _c35 = _c14*_c33*_c34
    _d35_1 = _c33*_c34
    _d35_3 = _c14*_c33*_d34_3 + _c33*_c34*_d14_3
    _d35_4 = _c14*_c34*_d33_4 + _c33*_c34*_d14_4
    _c36 = _c10*_c7
    _d36_4 = _c10*_d7_4 + _c7*_d10_4
    _c37 = _c13*_c7
    _d37_3 = _c12*_c7
    _d37_4 = _c13*_d7_4 + _c7*_d13_4
    _c38 = _c14*_c30*_c37
    _d38_1 = _c14*_c37*_d30_1 + _c30*_c37
    _d38_2 = _c14*_c37*_d24_2
    _d38_3 = _c14*_c30*_d37_3 + _c14*_c37*_d30_3 + _c30*_c37*_d14_3
    _d38_4 = _c14*_c30*_d37_4 + _c14*_c37*_d30_4 + _c30*_c37*_d14_4
    _c39 = _c24*omega_x
    _d39_2 = _d24_2*omega_x
    _c40 = _c13*_c9
    _d40_3 = _c12*_c9
    _d40_4 = _c13*_d9_4 + _c9*_d13_4
    _c41 = -_c14*omega_y - _c40*omega_z
    _d41_1 = -omega_y
    _d41_3 = -_d14_3*omega_y - _d40_3*omega_z
    _d41_4 = -_d14_4*omega_y - _d40_4*omega_z
    _c42 = -_c37*omega_y + _c40*omega_x
    _d42_3 = -_d37_3*omega_y + _d40_3*omega_x
    _d42_4 = -_d37_4*omega_y + _d40_4*omega_x
    _c43 = _c4*_c5
    _d43_4 = _c4*_d5_4 + _c5*_d4_4
    _c44 = (_c5*_c5)
    _d44_4 = 2*_c5*_d5_4
    _c45 = -_c43*_c7 - (1.0/2.0)*_c9*(2 - 2*_c44)
    _d45_4 = -_c43*_d7_4 - _c7*_d43_4 + _c9*_d44_4 + _d9_4*(_c44 - 1)
    _c46 = D*_c33
    _d46_4 = D*_d33_4
    _c47 = _c46*n_z
    _d47_3 = _c33*n_z
    _d47_4 = _d46_4*n_z
    _c48 = (_c4*_c4)
    _d48_4 = 2*_c4*_d4_4
    _c49 = -_c43*_c9 - (1.0/2.0)*_c7*(2 - 2*_c48)
    _d49_4 = -_c43*_d9_4 + _c7*_d48_4 - _c9*_d43_4 + _d7_4*(_c48 - 1)
    _c50 = -_c0*_c47*_c49 - _c1*_c45*_c47 + _c2*(-_c13 + _c3*_c46)
    _d50_3 = -_c12*_c2 + _c2*_c3*_c33 + _d47_3*(-_c0*_c49 - _c1*_c45)
    _d50_4 = -_c0*_c47*_d49_4 - _c1*_c47*_d45_4 + _c2*_c3*_d46_4 - _c2*_d13_4 + _d47_4*(-_c0*_c49 - _c1*_c45)
    _c51 = _c46*_c7
    _d51_3 = _c33*_c7
    _d51_4 = _c46*_d7_4 + _c7*_d46_4
    _c52 = _c2*n_z
    _c53 = _c13*_c43
    _d53_3 = _c12*_c43
    _d53_4 = _c13*_d43_4 + _c43*_d13_4
    _c54 = _c0*(-_c13*(1 - _c48) - _c49*_c51) + _c1*(-_c45*_c51 - _c53) + _c51*_c52
    _d54_3 = _c0*_c12*(_c48 - 1) - _c1*_d53_3 + _d51_3*(-_c0*_c49 - _c1*_c45 + _c52)
    _d54_4 = _c0*_c13*_d48_4 - _c0*_c51*_d49_4 + _c0*_d13_4*(_c48 - 1) - _c1*_c51*_d45_4 - _c1*_d53_4 + _d51_4*(-_c0*_c49 - _c1*_c45 + _c52)
    _c55 = _c41*omega_z - _c42*omega_x + _c50*omega_x - _c54*omega_z + g*n_y
    _d55_1 = _d41_1*omega_z
    _d55_3 = _d41_3*omega_z - _d42_3*omega_x + _d50_3*omega_x - _d54_3*omega_z
    _d55_4 = _d41_4*omega_z - _d42_4*omega_x + _d50_4*omega_x - _d54_4*omega_z
    _c56 = _c14*omega_x + _c37*omega_z
    _d56_3 = _d14_3*omega_x + _d37_3*omega_z
    _d56_4 = _d14_4*omega_x + _d37_4*omega_z
    _c57 = _c46*_c9
    _d57_3 = _c33*_c9
    _d57_4 = _c46*_d9_4 + _c9*_d46_4
    _c58 = _c0*(-_c49*_c57 - _c53) + _c1*(-_c13*(1 - _c44) - _c45*_c57) + _c52*_c57
    _d58_3 = -_c0*_d53_3 + _c1*_c12*(_c44 - 1) + _d57_3*(-_c0*_c49 - _c1*_c45 + _c52)
    _d58_4 = -_c0*_c57*_d49_4 - _c0*_d53_4 + _c1*_c13*_d44_4 - _c1*_c57*_d45_4 + _c1*_d13_4*(_c44 - 1) + _d57_4*(-_c0*_c49 - _c1*_c45 + _c52)
    _c59 = _c42*omega_y - _c50*omega_y - _c56*omega_z + _c58*omega_z + g*n_x
    _d59_1 = -omega_x*omega_z
    _d59_3 = _d42_3*omega_y - _d50_3*omega_y - _d56_3*omega_z + _d58_3*omega_z
    _d59_4 = _d42_4*omega_y - _d50_4*omega_y - _d56_4*omega_z + _d58_4*omega_z
    _c60 = D*_c12*_c59*_c9 - _c37*_c55 - _c39*omega_y
    _d60_0 = D*_c12*_c9*n_x - _c37*n_y
    _d60_1 = D*_c12*_c9*_d59_1 - _c37*_d55_1
    _d60_2 = -_d39_2*omega_y
    _d60_3 = D*_c12*_c9*_d59_3 + _c12*_c59*_c9 - _c37*_d55_3 - _c55*_d37_3
    _d60_4 = D*_c12*_c59*_d9_4 + D*_c12*_c9*_d59_4 + D*_c59*_c9*_d12_4 - _c37*_d55_4 - _c55*_d37_4
    _c61 = _c22*_c7*_c9
    _d61_3 = _c7*_c9*_d22_3
    _d61_4 = _c22*_c7*_d9_4 + _c22*_c9*_d7_4 + _c7*_c9*_d22_4
    _c62 = -_c41*omega_y + _c54*omega_y + _c56*omega_x - _c58*omega_x + g*n_z
    _d62_1 = -_d41_1*omega_y + (omega_x*omega_x)
    _d62_3 = -_d41_3*omega_y + _d54_3*omega_y + _d56_3*omega_x - _d58_3*omega_x
    _d62_4 = -_d41_4*omega_y + _d54_4*omega_y + _d56_4*omega_x - _d58_4*omega_x
    _c63 = _c14*_c59 + _c37*_c62 + _c39*omega_z
    _d63_0 = _c14*n_x + _c37*n_z
    _d63_1 = _c14*_d59_1 + _c37*_d62_1 + _c59
    _d63_2 = _d39_2*omega_z
    _d63_3 = _c14*_d59_3 + _c37*_d62_3 + _c59*_d14_3 + _c62*_d37_3
    _d63_4 = _c14*_d59_4 + _c37*_d62_4 + _c59*_d14_4 + _c62*_d37_4
    _c64 = -_c14*_c55 - _c40*_c62
    _d64_0 = -_c14*n_y - _c40*n_z
    _d64_1 = -_c14*_d55_1 - _c40*_d62_1 - _c55
    _d64_3 = -_c14*_d55_3 - _c40*_d62_3 - _c55*_d14_3 - _c62*_d40_3
    _d64_4 = -_c14*_d55_4 - _c40*_d62_4 - _c55*_d14_4 - _c62*_d40_4
    _d65_0 = _c32*_d60_0*(-_c35*_c36 - _c38) + _c32*_d63_0*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c32*_d64_0*(_c23*_c29 + _c27*_c30)
    _d65_1 = _c27*_c32*_c64*_d30_1 - _c32*_c36*_c60*_d35_1 - _c32*_c60*_d38_1 + _c32*_d29_1*(_c23*_c64 - _c61*_c63) + _c32*_d60_1*(-_c35*_c36 - _c38) + _c32*_d63_1*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c32*_d64_1*(_c23*_c29 + _c27*_c30) + _d32_1*(_c60*(-_c35*_c36 - _c38) + _c63*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c64*(_c23*_c29 + _c27*_c30))
    _d65_2 = _c27*_c32*_c64*_d24_2 - _c32*_c60*_d38_2 + _c32*_d24_2*(_c20*_c21*_c63*_c7*_c9 + _c30*_c64) + _c32*_d60_2*(-_c35*_c36 - _c38) + _c32*_d63_2*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _d32_2*(_c60*(-_c35*_c36 - _c38) + _c63*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c64*(_c23*_c29 + _c27*_c30))
    _d65_3 = _c21*_c27*_c32*_c63*_c7*_c9*_d20_3 + _c27*_c32*_c64*_d30_3 - _c29*_c32*_c63*_d61_3 + _c29*_c32*_c64*_d23_3 - _c32*_c36*_c60*_d35_3 - _c32*_c60*_d38_3 + _c32*_d27_3*(_c20*_c21*_c63*_c7*_c9 + _c30*_c64) + _c32*_d29_3*(_c23*_c64 - _c61*_c63) + _c32*_d60_3*(-_c35*_c36 - _c38) + _c32*_d63_3*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c32*_d64_3*(_c23*_c29 + _c27*_c30) + _d32_3*(_c60*(-_c35*_c36 - _c38) + _c63*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c64*(_c23*_c29 + _c27*_c30))
    _d65_4 = _c20*_c21*_c27*_c32*_c63*_c7*_d9_4 + _c20*_c21*_c27*_c32*_c63*_c9*_d7_4 + _c20*_c27*_c32*_c63*_c7*_c9*_d21_4 + _c27*_c32*_c64*_d30_4 - _c29*_c32*_c63*_d61_4 + _c29*_c32*_c64*_d23_4 - _c32*_c35*_c60*_d36_4 - _c32*_c36*_c60*_d35_4 - _c32*_c60*_d38_4 + _c32*_d27_4*(_c20*_c21*_c63*_c7*_c9 + _c30*_c64) + _c32*_d29_4*(_c23*_c64 - _c61*_c63) + _c32*_d60_4*(-_c35*_c36 - _c38) + _c32*_d63_4*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c32*_d64_4*(_c23*_c29 + _c27*_c30) + _d32_4*(_c60*(-_c35*_c36 - _c38) + _c63*(_c20*_c21*_c27*_c7*_c9 - _c29*_c61) + _c64*(_c23*_c29 + _c27*_c30))
    _c66 = _c35*_c8*_c9
    _d66_1 = _c8*_c9*_d35_1
    _d66_3 = _c8*_c9*_d35_3
    _d66_4 = _c35*_c8*_d9_4 + _c35*_c9*_d8_4 + _c8*_c9*_d35_4
    _d67_0 = _c32*_d60_0*(-_c14*_c28*_c40 - _c66) + _c32*_d63_0*(_c27*_c28 - _c31) + _c32*_d64_0*(_c15*_c61 + _c27*_c61)
    _d67_1 = -_c28*_c32*_c40*_c60 - _c32*_c60*_d66_1 + _c32*_c61*_c64*_d15_1 - _c32*_c63*_d31_1 + _c32*_d15_1*(-_c14*_c40*_c60 + _c27*_c63) + _c32*_d60_1*(-_c14*_c28*_c40 - _c66) + _c32*_d63_1*(_c27*_c28 - _c31) + _c32*_d64_1*(_c15*_c61 + _c27*_c61) + _d32_1*(_c60*(-_c14*_c28*_c40 - _c66) + _c63*(_c27*_c28 - _c31) + _c64*(_c15*_c61 + _c27*_c61))
    _d67_2 = _c32*_d24_2*(_c28*_c63 + _c61*_c64) + _c32*_d60_2*(-_c14*_c28*_c40 - _c66) + _c32*_d63_2*(_c27*_c28 - _c31) + _d32_2*(_c60*(-_c14*_c28*_c40 - _c66) + _c63*(_c27*_c28 - _c31) + _c64*(_c15*_c61 + _c27*_c61))
    _d67_3 = -_c14*_c28*_c32*_c60*_d40_3 - _c28*_c32*_c40*_c60*_d14_3 - _c32*_c60*_d66_3 + _c32*_c61*_c64*_d15_3 - _c32*_c63*_d31_3 + _c32*_c64*_d61_3*(_c15 + _c27) + _c32*_d27_3*(_c28*_c63 + _c61*_c64) + _c32*_d28_3*(-_c14*_c40*_c60 + _c27*_c63) + _c32*_d60_3*(-_c14*_c28*_c40 - _c66) + _c32*_d63_3*(_c27*_c28 - _c31) + _c32*_d64_3*(_c15*_c61 + _c27*_c61) + _d32_3*(_c60*(-_c14*_c28*_c40 - _c66) + _c63*(_c27*_c28 - _c31) + _c64*(_c15*_c61 + _c27*_c61))
    _d67_4 = -_c14*_c28*_c32*_c60*_d40_4 - _c28*_c32*_c40*_c60*_d14_4 - _c32*_c60*_d66_4 + _c32*_c61*_c64*_d15_4 - _c32*_c63*_d31_4 + _c32*_c64*_d61_4*(_c15 + _c27) + _c32*_d27_4*(_c28*_c63 + _c61*_c64) + _c32*_d28_4*(-_c14*_c40*_c60 + _c27*_c63) + _c32*_d60_4*(-_c14*_c28*_c40 - _c66) + _c32*_d63_4*(_c27*_c28 - _c31) + _c32*_d64_4*(_c15*_c61 + _c27*_c61) + _d32_4*(_c60*(-_c14*_c28*_c40 - _c66) + _c63*(_c27*_c28 - _c31) + _c64*(_c15*_c61 + _c27*_c61))
    _d68_0 = _c32*_d60_0*(-_c18 + _c28*_c30) + _c32*_d63_0*(D*_c12*_c19*_c28*_c9 - _c66) + _c32*_d64_0*(_c19*_c33*_c34*_c36 - _c38)
    _d68_1 = _c28*_c32*_c60*_d30_1 - _c32*_c63*_d66_1 - _c32*_c64*_d38_1 + _c32*_d15_1*(D*_c12*_c19*_c63*_c9 + _c30*_c60) + _c32*_d60_1*(-_c18 + _c28*_c30) + _c32*_d63_1*(D*_c12*_c19*_c28*_c9 - _c66) + _c32*_d64_1*(_c19*_c33*_c34*_c36 - _c38) - _c32*(D*_c12*_c28*_c63*_c9 + _c33*_c34*_c36*_c64) + _d32_1*(_c60*(-_c18 + _c28*_c30) + _c63*(D*_c12*_c19*_c28*_c9 - _c66) + _c64*(_c19*_c33*_c34*_c36 - _c38))
    _d68_2 = _c28*_c32*_c60*_d24_2 - _c32*_c64*_d38_2 + _c32*_d60_2*(-_c18 + _c28*_c30) + _c32*_d63_2*(D*_c12*_c19*_c28*_c9 - _c66) + _d32_2*(_c60*(-_c18 + _c28*_c30) + _c63*(D*_c12*_c19*_c28*_c9 - _c66) + _c64*(_c19*_c33*_c34*_c36 - _c38))
    _d68_3 = _c12*_c19*_c28*_c32*_c63*_c9 + _c19*_c32*_c33*_c36*_c64*_d34_3 + _c28*_c32*_c60*_d30_3 - _c32*_c60*_d18_3 - _c32*_c63*_d66_3 - _c32*_c64*_d38_3 + _c32*_d19_3*(D*_c12*_c28*_c63*_c9 + _c33*_c34*_c36*_c64) + _c32*_d28_3*(D*_c12*_c19*_c63*_c9 + _c30*_c60) + _c32*_d60_3*(-_c18 + _c28*_c30) + _c32*_d63_3*(D*_c12*_c19*_c28*_c9 - _c66) + _c32*_d64_3*(_c19*_c33*_c34*_c36 - _c38) + _d32_3*(_c60*(-_c18 + _c28*_c30) + _c63*(D*_c12*_c19*_c28*_c9 - _c66) + _c64*(_c19*_c33*_c34*_c36 - _c38))
    _d68_4 = D*_c12*_c19*_c28*_c32*_c63*_d9_4 + D*_c19*_c28*_c32*_c63*_c9*_d12_4 + _c19*_c32*_c33*_c34*_c64*_d36_4 + _c19*_c32*_c34*_c36*_c64*_d33_4 + _c28*_c32*_c60*_d30_4 - _c32*_c60*_d18_4 - _c32*_c63*_d66_4 - _c32*_c64*_d38_4 + _c32*_d19_4*(D*_c12*_c28*_c63*_c9 + _c33*_c34*_c36*_c64) + _c32*_d28_4*(D*_c12*_c19*_c63*_c9 + _c30*_c60) + _c32*_d60_4*(-_c18 + _c28*_c30) + _c32*_d63_4*(D*_c12*_c19*_c28*_c9 - _c66) + _c32*_d64_4*(_c19*_c33*_c34*_c36 - _c38) + _d32_4*(_c60*(-_c18 + _c28*_c30) + _c63*(D*_c12*_c19*_c28*_c9 - _c66) + _c64*(_c19*_c33*_c34*_c36 - _c38))
    out[3, 0] = _d65_0
    out[3, 1] = _d65_1
    out[3, 2] = _d65_2
    out[3, 3] = _d65_3
    out[3, 4] = _d65_4
    out[4, 0] = _d67_0
    out[4, 1] = _d67_1
    out[4, 2] = _d67_2
    out[4, 3] = _d67_3
    out[4, 4] = _d67_4
    out[5, 0] = _d68_0
    out[5, 1] = _d68_1
    out[5, 2] = _d68_2
    out[5, 3] = _d68_3
    out[5, 4] = _d68_4
    out[6, 0] = _d65_0*n_x + _d67_0*n_y + _d68_0*n_z
    out[6, 1] = _d65_1*n_x + _d67_1*n_y + _d68_1*n_z
    out[6, 2] = _d65_2*n_x + _d67_2*n_y + _d68_2*n_z
    out[6, 3] = _d65_3*n_x + _d67_3*n_y + _d68_3*n_z
    out[6, 4] = _d65_4*n_x + _d67_4*n_y + _d68_4*n_z
    return out



#: families of steady motions (derivation/steady.py): name -> the family's parameter ``value`` (``value_state`` is
#: the state equal to it), what the motion is, and names of the modes by their largest state
STEADY_FAMILIES = {'steady_spin': {'value': 'Omega', 'value_state': 'omega_z', 'description': 'upright spin about the body z axis (n = e_z) at the rate Omega', 'mode_names': {'A_pitch': 'pitch', 'A_roll': 'roll', 'n_x': 'pitch', 'n_y': 'roll'}}}


@njit(cache=True)
def steady_state(_family, _value, p):
    """Row 0: the closed state of family number ``_family`` of STEADY_FAMILIES at ``_value``; row 1: its derivative
    in ``_value`` (the family's tangent)."""
    out = np.zeros((2, 7))
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    if _family == 0:
        Omega = _value
        out[0, 2] = 1
        out[0, 5] = Omega
        out[0, 6] = Omega
        out[1, 5] = 1
        out[1, 6] = 1

    return out


#: functions of the closed state fixed by construction; their gradients are not physical directions
STATE_INVARIANTS = ('|n|^2 = 1 (n is a unit vector)', 'omega_n = omega . n (the spin carried as a state)')


@njit(cache=True)
def invariant_gradients(s, p):
    """Gradients of STATE_INVARIANTS, shape (2, 7)."""
    out = np.zeros((2, 7))
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    out[0, 0] = 2*n_x
    out[0, 1] = 2*n_y
    out[0, 2] = 2*n_z
    out[1, 0] = -omega_x
    out[1, 1] = -omega_y
    out[1, 2] = -omega_z
    out[1, 3] = -n_x
    out[1, 4] = -n_y
    out[1, 5] = -n_z
    out[1, 6] = 1
    return out
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '76f6a420fd9df636d5bb749219124b3e54bfd7fd1a9fdf9ffc4ce0541a76a35a'
