"""two_mode_rigid, fidelity full: rigid body rolling without slipping, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/rigid_emit.py (make derive) from the rigid body 'two_mode_rigid'
through derivation/rigid.py (Lagrange-d'Alembert in body quasi-velocities).
SymPy 1.14.0; input hash sha256:e7974d078c323f9b448a1c3f7de1305140dcc7fa933e518a76db82449fe189e0

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
INPUT_HASH = 'e7974d078c323f9b448a1c3f7de1305140dcc7fa933e518a76db82449fe189e0'
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
        '  %v11 = getelementptr inbounds double, ptr %s, i64 5\n'
        '  %v12 = load double, ptr %v11\n'
        '  %v13 = getelementptr inbounds double, ptr %s, i64 6\n'
        '  %v14 = load double, ptr %v13\n'
        '  %v15 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  %v16 = load double, ptr %v15\n'
        '  %v17 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  %v18 = load double, ptr %v17\n'
        '  %v19 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  %v20 = load double, ptr %v19\n'
        '  %v21 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  %v22 = load double, ptr %v21\n'
        '  %v23 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  %v24 = load double, ptr %v23\n'
        '  %v25 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  %v26 = load double, ptr %v25\n'
        '  %v27 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  %v28 = load double, ptr %v27\n'
        '  %v29 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  %v30 = load double, ptr %v29\n'
        '  %v31 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  %v32 = load double, ptr %v31\n'
        '  %v33 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  %v34 = load double, ptr %v33\n'
        '  %v35 = getelementptr inbounds double, ptr %q, i64 10\n'
        '  %v36 = load double, ptr %v35\n'
        '  %v37 = getelementptr inbounds double, ptr %q, i64 11\n'
        '  %v38 = load double, ptr %v37\n'
        '  %v39 = getelementptr inbounds double, ptr %q, i64 12\n'
        '  %v40 = load double, ptr %v39\n'
        '  %v41 = getelementptr inbounds double, ptr %q, i64 13\n'
        '  %v42 = load double, ptr %v41\n'
        '  %v43 = getelementptr inbounds double, ptr %q, i64 14\n'
        '  %v44 = load double, ptr %v43\n'
        '  %v45 = getelementptr inbounds double, ptr %q, i64 15\n'
        '  %v46 = load double, ptr %v45\n'
        '  %v47 = getelementptr inbounds double, ptr %q, i64 16\n'
        '  %v48 = load double, ptr %v47\n'
        '  %v49 = getelementptr inbounds double, ptr %q, i64 17\n'
        '  %v50 = load double, ptr %v49\n'
        '  %v51 = getelementptr inbounds double, ptr %q, i64 18\n'
        '  %v52 = load double, ptr %v51\n'
        '  %v53 = getelementptr inbounds double, ptr %q, i64 19\n'
        '  %v54 = load double, ptr %v53\n'
        '  %v55 = getelementptr inbounds double, ptr %q, i64 20\n'
        '  %v56 = load double, ptr %v55\n'
        '  %v57 = getelementptr inbounds double, ptr %q, i64 21\n'
        '  %v58 = load double, ptr %v57\n'
        '  %v59 = getelementptr inbounds double, ptr %q, i64 22\n'
        '  %v60 = load double, ptr %v59\n'
        '  %v61 = getelementptr inbounds double, ptr %q, i64 23\n'
        '  %v62 = load double, ptr %v61\n'
        '  %v63 = getelementptr inbounds double, ptr %q, i64 24\n'
        '  %v64 = load double, ptr %v63\n'
        '  %v65 = getelementptr inbounds double, ptr %q, i64 25\n'
        '  %v66 = load double, ptr %v65\n'
        '  %v67 = fmul double %v4, %v12\n'
        '  %v68 = fmul double %v6, %v10\n'
        '  %v69 = fsub double %v67, %v68\n'
        '  %v70 = fneg double %v2\n'
        '  %v71 = fmul double %v70, %v12\n'
        '  %v72 = fmul double %v6, %v8\n'
        '  %v73 = fadd double %v71, %v72\n'
        '  %v74 = fmul double %v2, %v10\n'
        '  %v75 = fmul double %v4, %v8\n'
        '  %v76 = fsub double %v74, %v75\n'
        '  %v77 = fmul double %v26, %v4\n'
        '  %v78 = fmul double %v28, %v2\n'
        '  %v79 = fadd double %v77, %v78\n'
        '  %v80 = fmul double %v79, %v30\n'
        '  %v81 = fadd double %v80, %v2\n'
        '  %v82 = fmul double %v81, %v81\n'
        '  %v83 = fmul double %v6, %v6\n'
        '  %v84 = fmul double %v79, %v32\n'
        '  %v85 = fadd double %v84, %v4\n'
        '  %v86 = fmul double %v85, %v85\n'
        '  %v87 = fadd double %v82, %v83\n'
        '  %v88 = fadd double %v87, %v86\n'
        '  %v89 = call double @llvm.sqrt.f64(double %v88)\n'
        '  %v90 = fdiv double 0x3FF0000000000000, %v89\n'
        '  %v91 = fmul double %v90, %v34\n'
        '  %v92 = fmul double %v91, %v6\n'
        '  %v93 = fadd double %v92, %v36\n'
        '  %v94 = fmul double %v93, %v93\n'
        '  %v95 = fmul double %v94, %v82\n'
        '  %v96 = fmul double %v88, %v88\n'
        '  %v97 = fdiv double 0x3FF0000000000000, %v96\n'
        '  %v98 = fmul double %v97, %v86\n'
        '  %v99 = fmul double %v98, %v46\n'
        '  %v100 = fmul double %v22, %v90\n'
        '  %v101 = fmul double %v100, %v6\n'
        '  %v102 = fadd double %v101, %v40\n'
        '  %v103 = fmul double %v93, %v102\n'
        '  %v104 = fdiv double 0x3FF0000000000000, %v88\n'
        '  %v105 = fmul double %v104, %v38\n'
        '  %v106 = fmul double %v105, %v86\n'
        '  %v107 = fmul double %v105, %v82\n'
        '  %v108 = fadd double %v107, %v42\n'
        '  %v109 = fadd double %v106, %v108\n'
        '  %v110 = fmul double %v99, %v82\n'
        '  %v111 = fadd double %v94, %v106\n'
        '  %v112 = fmul double %v103, %v106\n'
        '  %v113 = fneg double %v103\n'
        '  %v114 = fadd double %v113, %v108\n'
        '  %v115 = fmul double %v104, %v44\n'
        '  %v116 = fmul double %v95, %v115\n'
        '  %v117 = fmul double %v109, %v114\n'
        '  %v118 = fmul double %v95, %v99\n'
        '  %v119 = fmul double %v97, %v103\n'
        '  %v120 = fmul double %v119, %v82\n'
        '  %v121 = fmul double %v120, %v86\n'
        '  %v122 = fmul double %v121, %v48\n'
        '  %v123 = fadd double %v118, %v122\n'
        '  %v124 = fmul double %v109, %v110\n'
        '  %v125 = fadd double %v123, %v124\n'
        '  %v126 = fmul double %v111, %v112\n'
        '  %v127 = fadd double %v125, %v126\n'
        '  %v128 = fmul double %v111, %v117\n'
        '  %v129 = fadd double %v127, %v128\n'
        '  %v130 = fmul double %v114, %v116\n'
        '  %v131 = fadd double %v129, %v130\n'
        '  %v132 = fdiv double 0x3FF0000000000000, %v131\n'
        '  %v133 = call double @llvm.pow.f64(double %v88, double 0xBFF8000000000000)\n'
        '  %v134 = fmul double %v93, %v133\n'
        '  %v135 = fmul double %v134, %v62\n'
        '  %v136 = fmul double %v81, %v86\n'
        '  %v137 = fmul double %v91, %v81\n'
        '  %v138 = fmul double %v93, %v114\n'
        '  %v139 = fmul double %v138, %v137\n'
        '  %v140 = fmul double %v100, %v81\n'
        '  %v141 = fmul double %v93, %v8\n'
        '  %v142 = fmul double %v140, %v12\n'
        '  %v143 = fadd double %v141, %v142\n'
        '  %v144 = fmul double %v100, %v85\n'
        '  %v145 = fmul double %v137, %v10\n'
        '  %v146 = fmul double %v144, %v8\n'
        '  %v147 = fadd double %v145, %v146\n'
        '  %v148 = fmul double %v81, %v50\n'
        '  %v149 = fmul double %v85, %v52\n'
        '  %v150 = fadd double %v148, %v149\n'
        '  %v151 = fmul double %v133, %v34\n'
        '  %v152 = fmul double %v151, %v6\n'
        '  %v153 = fmul double %v81, %v52\n'
        '  %v154 = fmul double %v85, %v54\n'
        '  %v155 = fadd double %v153, %v154\n'
        '  %v156 = fmul double %v22, %v133\n'
        '  %v157 = fmul double %v69, %v150\n'
        '  %v158 = fmul double %v157, %v152\n'
        '  %v159 = fmul double %v73, %v152\n'
        '  %v160 = fmul double %v159, %v155\n'
        '  %v161 = fadd double %v158, %v160\n'
        '  %v162 = fmul double %v156, %v83\n'
        '  %v163 = fadd double %v91, %v162\n'
        '  %v164 = fmul double %v76, %v163\n'
        '  %v165 = fadd double %v161, %v164\n'
        '  %v166 = fmul double %v76, %v156\n'
        '  %v167 = fmul double %v166, %v6\n'
        '  %v168 = fmul double %v90, %v58\n'
        '  %v169 = fmul double %v151, %v85\n'
        '  %v170 = fmul double %v150, %v169\n'
        '  %v171 = fadd double %v170, %v168\n'
        '  %v172 = fmul double %v69, %v171\n'
        '  %v173 = fmul double %v90, %v60\n'
        '  %v174 = fmul double %v155, %v169\n'
        '  %v175 = fadd double %v173, %v174\n'
        '  %v176 = fmul double %v73, %v175\n'
        '  %v177 = fadd double %v172, %v176\n'
        '  %v178 = fmul double %v167, %v85\n'
        '  %v179 = fadd double %v177, %v178\n'
        '  %v180 = fneg double %v143\n'
        '  %v181 = fmul double %v180, %v12\n'
        '  %v182 = fmul double %v147, %v10\n'
        '  %v183 = fadd double %v181, %v182\n'
        '  %v184 = fmul double %v165, %v10\n'
        '  %v185 = fsub double %v183, %v184\n'
        '  %v186 = fmul double %v179, %v12\n'
        '  %v187 = fadd double %v185, %v186\n'
        '  %v188 = fmul double %v16, %v2\n'
        '  %v189 = fadd double %v187, %v188\n'
        '  %v190 = fmul double %v91, %v85\n'
        '  %v191 = fneg double %v93\n'
        '  %v192 = fmul double %v191, %v10\n'
        '  %v193 = fmul double %v190, %v12\n'
        '  %v194 = fadd double %v192, %v193\n'
        '  %v195 = fmul double %v81, %v151\n'
        '  %v196 = fmul double %v90, %v56\n'
        '  %v197 = fmul double %v150, %v195\n'
        '  %v198 = fadd double %v196, %v197\n'
        '  %v199 = fmul double %v69, %v198\n'
        '  %v200 = fmul double %v155, %v195\n'
        '  %v201 = fadd double %v200, %v168\n'
        '  %v202 = fmul double %v73, %v201\n'
        '  %v203 = fadd double %v199, %v202\n'
        '  %v204 = fmul double %v81, %v167\n'
        '  %v205 = fadd double %v203, %v204\n'
        '  %v206 = fneg double %v147\n'
        '  %v207 = fmul double %v206, %v8\n'
        '  %v208 = fmul double %v165, %v8\n'
        '  %v209 = fadd double %v207, %v208\n'
        '  %v210 = fmul double %v194, %v12\n'
        '  %v211 = fadd double %v209, %v210\n'
        '  %v212 = fmul double %v205, %v12\n'
        '  %v213 = fsub double %v211, %v212\n'
        '  %v214 = fmul double %v16, %v4\n'
        '  %v215 = fadd double %v213, %v214\n'
        '  %v216 = fmul double %v137, %v215\n'
        '  %v217 = fmul double %v144, %v189\n'
        '  %v218 = fadd double %v216, %v217\n'
        '  %v219 = fmul double %v64, %v8\n'
        '  %v220 = fmul double %v219, %v10\n'
        '  %v221 = fadd double %v218, %v220\n'
        '  %v222 = fmul double %v81, %v85\n'
        '  %v223 = fmul double %v105, %v222\n'
        '  %v224 = fmul double %v109, %v223\n'
        '  %v225 = fmul double %v143, %v8\n'
        '  %v226 = fmul double %v179, %v8\n'
        '  %v227 = fsub double %v225, %v226\n'
        '  %v228 = fmul double %v194, %v10\n'
        '  %v229 = fsub double %v227, %v228\n'
        '  %v230 = fmul double %v205, %v10\n'
        '  %v231 = fadd double %v229, %v230\n'
        '  %v232 = fmul double %v16, %v6\n'
        '  %v233 = fadd double %v231, %v232\n'
        '  %v234 = fmul double %v93, %v189\n'
        '  %v235 = fmul double %v140, %v233\n'
        '  %v236 = fadd double %v234, %v235\n'
        '  %v237 = fmul double %v42, %v8\n'
        '  %v238 = fmul double %v237, %v12\n'
        '  %v239 = fadd double %v236, %v238\n'
        '  %v240 = fneg double %v93\n'
        '  %v241 = fmul double %v240, %v215\n'
        '  %v242 = fmul double %v190, %v233\n'
        '  %v243 = fadd double %v241, %v242\n'
        '  %v244 = fmul double %v135, %v136\n'
        '  %v245 = fadd double %v244, %v139\n'
        '  %v246 = fmul double %v221, %v245\n'
        '  %v247 = fmul double %v103, %v115\n'
        '  %v248 = fmul double %v247, %v222\n'
        '  %v249 = fadd double %v248, %v224\n'
        '  %v250 = fmul double %v239, %v249\n'
        '  %v251 = fadd double %v246, %v250\n'
        '  %v252 = fadd double %v112, %v117\n'
        '  %v253 = fmul double %v243, %v252\n'
        '  %v254 = fadd double %v251, %v253\n'
        '  %v255 = fmul double %v132, %v254\n'
        '  %v256 = fmul double %v135, %v82\n'
        '  %v257 = fmul double %v256, %v85\n'
        '  %v258 = fmul double %v93, %v111\n'
        '  %v259 = fmul double %v258, %v190\n'
        '  %v260 = fadd double %v259, %v257\n'
        '  %v261 = fmul double %v221, %v260\n'
        '  %v262 = fmul double %v109, %v111\n'
        '  %v263 = fadd double %v262, %v116\n'
        '  %v264 = fmul double %v239, %v263\n'
        '  %v265 = fadd double %v261, %v264\n'
        '  %v266 = fmul double %v94, %v223\n'
        '  %v267 = fadd double %v266, %v224\n'
        '  %v268 = fmul double %v243, %v267\n'
        '  %v269 = fadd double %v265, %v268\n'
        '  %v270 = fmul double %v132, %v269\n'
        '  %v271 = fmul double %v111, %v114\n'
        '  %v272 = fadd double %v110, %v271\n'
        '  %v273 = fmul double %v221, %v272\n'
        '  %v274 = fmul double %v102, %v111\n'
        '  %v275 = fmul double %v274, %v144\n'
        '  %v276 = fadd double %v275, %v257\n'
        '  %v277 = fmul double %v239, %v276\n'
        '  %v278 = fadd double %v273, %v277\n'
        '  %v279 = fmul double %v102, %v133\n'
        '  %v280 = fmul double %v279, %v136\n'
        '  %v281 = fmul double %v280, %v66\n'
        '  %v282 = fadd double %v281, %v139\n'
        '  %v283 = fmul double %v243, %v282\n'
        '  %v284 = fadd double %v278, %v283\n'
        '  %v285 = fmul double %v132, %v284\n'
        '  %v286 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v69, ptr %v286\n'
        '  %v287 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v73, ptr %v287\n'
        '  %v288 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v76, ptr %v288\n'
        '  %v289 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v255, ptr %v289\n'
        '  %v290 = getelementptr inbounds double, ptr %ds, i64 4\n'
        '  store double %v270, ptr %v290\n'
        '  %v291 = getelementptr inbounds double, ptr %ds, i64 5\n'
        '  store double %v285, ptr %v291\n'
        '  %v292 = fmul double %v255, %v2\n'
        '  %v293 = fmul double %v270, %v4\n'
        '  %v294 = fadd double %v292, %v293\n'
        '  %v295 = fmul double %v285, %v6\n'
        '  %v296 = fadd double %v294, %v295\n'
        '  %v297 = getelementptr inbounds double, ptr %ds, i64 6\n'
        '  store double %v296, ptr %v297\n'
        '  ret i32 0\n'
        '}\n'
        'declare double @llvm.pow.f64(double, double)\n'
        'declare double @llvm.sqrt.f64(double)\n'
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
        '  %v17 = getelementptr inbounds double, ptr %s, i64 8\n'
        '  %v18 = load double, ptr %v17\n'
        '  %v19 = getelementptr inbounds double, ptr %s, i64 9\n'
        '  %v20 = load double, ptr %v19\n'
        '  %v21 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  %v22 = load double, ptr %v21\n'
        '  %v23 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  %v24 = load double, ptr %v23\n'
        '  %v25 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  %v26 = load double, ptr %v25\n'
        '  %v27 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  %v28 = load double, ptr %v27\n'
        '  %v29 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  %v30 = load double, ptr %v29\n'
        '  %v31 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  %v32 = load double, ptr %v31\n'
        '  %v33 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  %v34 = load double, ptr %v33\n'
        '  %v35 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  %v36 = load double, ptr %v35\n'
        '  %v37 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  %v38 = load double, ptr %v37\n'
        '  %v39 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  %v40 = load double, ptr %v39\n'
        '  %v41 = getelementptr inbounds double, ptr %q, i64 10\n'
        '  %v42 = load double, ptr %v41\n'
        '  %v43 = getelementptr inbounds double, ptr %q, i64 11\n'
        '  %v44 = load double, ptr %v43\n'
        '  %v45 = getelementptr inbounds double, ptr %q, i64 12\n'
        '  %v46 = load double, ptr %v45\n'
        '  %v47 = getelementptr inbounds double, ptr %q, i64 13\n'
        '  %v48 = load double, ptr %v47\n'
        '  %v49 = getelementptr inbounds double, ptr %q, i64 14\n'
        '  %v50 = load double, ptr %v49\n'
        '  %v51 = getelementptr inbounds double, ptr %q, i64 15\n'
        '  %v52 = load double, ptr %v51\n'
        '  %v53 = getelementptr inbounds double, ptr %q, i64 16\n'
        '  %v54 = load double, ptr %v53\n'
        '  %v55 = getelementptr inbounds double, ptr %q, i64 17\n'
        '  %v56 = load double, ptr %v55\n'
        '  %v57 = getelementptr inbounds double, ptr %q, i64 18\n'
        '  %v58 = load double, ptr %v57\n'
        '  %v59 = getelementptr inbounds double, ptr %q, i64 19\n'
        '  %v60 = load double, ptr %v59\n'
        '  %v61 = getelementptr inbounds double, ptr %q, i64 20\n'
        '  %v62 = load double, ptr %v61\n'
        '  %v63 = getelementptr inbounds double, ptr %q, i64 21\n'
        '  %v64 = load double, ptr %v63\n'
        '  %v65 = getelementptr inbounds double, ptr %q, i64 22\n'
        '  %v66 = load double, ptr %v65\n'
        '  %v67 = getelementptr inbounds double, ptr %q, i64 23\n'
        '  %v68 = load double, ptr %v67\n'
        '  %v69 = getelementptr inbounds double, ptr %q, i64 24\n'
        '  %v70 = load double, ptr %v69\n'
        '  %v71 = getelementptr inbounds double, ptr %q, i64 25\n'
        '  %v72 = load double, ptr %v71\n'
        '  %v73 = fmul double %v4, %v12\n'
        '  %v74 = fmul double %v6, %v10\n'
        '  %v75 = fsub double %v73, %v74\n'
        '  %v76 = fneg double %v2\n'
        '  %v77 = fmul double %v76, %v12\n'
        '  %v78 = fmul double %v6, %v8\n'
        '  %v79 = fadd double %v77, %v78\n'
        '  %v80 = fmul double %v2, %v10\n'
        '  %v81 = fmul double %v4, %v8\n'
        '  %v82 = fsub double %v80, %v81\n'
        '  %v83 = fmul double %v32, %v4\n'
        '  %v84 = fmul double %v34, %v2\n'
        '  %v85 = fadd double %v83, %v84\n'
        '  %v86 = fmul double %v85, %v36\n'
        '  %v87 = fadd double %v86, %v2\n'
        '  %v88 = fmul double %v87, %v87\n'
        '  %v89 = fmul double %v6, %v6\n'
        '  %v90 = fmul double %v85, %v38\n'
        '  %v91 = fadd double %v90, %v4\n'
        '  %v92 = fmul double %v91, %v91\n'
        '  %v93 = fadd double %v88, %v89\n'
        '  %v94 = fadd double %v93, %v92\n'
        '  %v95 = call double @llvm.sqrt.f64(double %v94)\n'
        '  %v96 = fdiv double 0x3FF0000000000000, %v95\n'
        '  %v97 = fmul double %v96, %v40\n'
        '  %v98 = fmul double %v97, %v6\n'
        '  %v99 = fadd double %v98, %v42\n'
        '  %v100 = fmul double %v99, %v99\n'
        '  %v101 = fmul double %v100, %v88\n'
        '  %v102 = fmul double %v94, %v94\n'
        '  %v103 = fdiv double 0x3FF0000000000000, %v102\n'
        '  %v104 = fmul double %v103, %v92\n'
        '  %v105 = fmul double %v104, %v52\n'
        '  %v106 = fmul double %v28, %v96\n'
        '  %v107 = fmul double %v106, %v6\n'
        '  %v108 = fadd double %v107, %v46\n'
        '  %v109 = fmul double %v99, %v108\n'
        '  %v110 = fdiv double 0x3FF0000000000000, %v94\n'
        '  %v111 = fmul double %v110, %v44\n'
        '  %v112 = fmul double %v111, %v92\n'
        '  %v113 = fmul double %v111, %v88\n'
        '  %v114 = fadd double %v113, %v48\n'
        '  %v115 = fadd double %v112, %v114\n'
        '  %v116 = fmul double %v105, %v88\n'
        '  %v117 = fadd double %v100, %v112\n'
        '  %v118 = fmul double %v109, %v112\n'
        '  %v119 = fneg double %v109\n'
        '  %v120 = fadd double %v119, %v114\n'
        '  %v121 = fmul double %v110, %v50\n'
        '  %v122 = fmul double %v101, %v121\n'
        '  %v123 = fmul double %v115, %v120\n'
        '  %v124 = fmul double %v101, %v105\n'
        '  %v125 = fmul double %v103, %v109\n'
        '  %v126 = fmul double %v125, %v88\n'
        '  %v127 = fmul double %v126, %v92\n'
        '  %v128 = fmul double %v127, %v54\n'
        '  %v129 = fadd double %v124, %v128\n'
        '  %v130 = fmul double %v115, %v116\n'
        '  %v131 = fadd double %v129, %v130\n'
        '  %v132 = fmul double %v117, %v118\n'
        '  %v133 = fadd double %v131, %v132\n'
        '  %v134 = fmul double %v117, %v123\n'
        '  %v135 = fadd double %v133, %v134\n'
        '  %v136 = fmul double %v120, %v122\n'
        '  %v137 = fadd double %v135, %v136\n'
        '  %v138 = fdiv double 0x3FF0000000000000, %v137\n'
        '  %v139 = call double @llvm.pow.f64(double %v94, double 0xBFF8000000000000)\n'
        '  %v140 = fmul double %v99, %v139\n'
        '  %v141 = fmul double %v140, %v68\n'
        '  %v142 = fmul double %v87, %v92\n'
        '  %v143 = fmul double %v97, %v87\n'
        '  %v144 = fmul double %v99, %v120\n'
        '  %v145 = fmul double %v144, %v143\n'
        '  %v146 = fmul double %v106, %v87\n'
        '  %v147 = fmul double %v99, %v8\n'
        '  %v148 = fmul double %v146, %v12\n'
        '  %v149 = fadd double %v147, %v148\n'
        '  %v150 = fmul double %v106, %v91\n'
        '  %v151 = fmul double %v143, %v10\n'
        '  %v152 = fmul double %v150, %v8\n'
        '  %v153 = fadd double %v151, %v152\n'
        '  %v154 = fmul double %v87, %v56\n'
        '  %v155 = fmul double %v91, %v58\n'
        '  %v156 = fadd double %v154, %v155\n'
        '  %v157 = fmul double %v139, %v40\n'
        '  %v158 = fmul double %v157, %v6\n'
        '  %v159 = fmul double %v87, %v58\n'
        '  %v160 = fmul double %v91, %v60\n'
        '  %v161 = fadd double %v159, %v160\n'
        '  %v162 = fmul double %v28, %v139\n'
        '  %v163 = fmul double %v75, %v156\n'
        '  %v164 = fmul double %v163, %v158\n'
        '  %v165 = fmul double %v79, %v158\n'
        '  %v166 = fmul double %v165, %v161\n'
        '  %v167 = fadd double %v164, %v166\n'
        '  %v168 = fmul double %v162, %v89\n'
        '  %v169 = fadd double %v97, %v168\n'
        '  %v170 = fmul double %v82, %v169\n'
        '  %v171 = fadd double %v167, %v170\n'
        '  %v172 = fmul double %v82, %v162\n'
        '  %v173 = fmul double %v172, %v6\n'
        '  %v174 = fmul double %v96, %v64\n'
        '  %v175 = fmul double %v157, %v91\n'
        '  %v176 = fmul double %v156, %v175\n'
        '  %v177 = fadd double %v176, %v174\n'
        '  %v178 = fmul double %v75, %v177\n'
        '  %v179 = fmul double %v96, %v66\n'
        '  %v180 = fmul double %v161, %v175\n'
        '  %v181 = fadd double %v179, %v180\n'
        '  %v182 = fmul double %v79, %v181\n'
        '  %v183 = fadd double %v178, %v182\n'
        '  %v184 = fmul double %v173, %v91\n'
        '  %v185 = fadd double %v183, %v184\n'
        '  %v186 = fneg double %v149\n'
        '  %v187 = fmul double %v186, %v12\n'
        '  %v188 = fmul double %v153, %v10\n'
        '  %v189 = fadd double %v187, %v188\n'
        '  %v190 = fmul double %v171, %v10\n'
        '  %v191 = fsub double %v189, %v190\n'
        '  %v192 = fmul double %v185, %v12\n'
        '  %v193 = fadd double %v191, %v192\n'
        '  %v194 = fmul double %v22, %v2\n'
        '  %v195 = fadd double %v193, %v194\n'
        '  %v196 = fmul double %v97, %v91\n'
        '  %v197 = fneg double %v99\n'
        '  %v198 = fmul double %v197, %v10\n'
        '  %v199 = fmul double %v196, %v12\n'
        '  %v200 = fadd double %v198, %v199\n'
        '  %v201 = fmul double %v87, %v157\n'
        '  %v202 = fmul double %v96, %v62\n'
        '  %v203 = fmul double %v156, %v201\n'
        '  %v204 = fadd double %v202, %v203\n'
        '  %v205 = fmul double %v75, %v204\n'
        '  %v206 = fmul double %v161, %v201\n'
        '  %v207 = fadd double %v206, %v174\n'
        '  %v208 = fmul double %v79, %v207\n'
        '  %v209 = fadd double %v205, %v208\n'
        '  %v210 = fmul double %v87, %v173\n'
        '  %v211 = fadd double %v209, %v210\n'
        '  %v212 = fneg double %v153\n'
        '  %v213 = fmul double %v212, %v8\n'
        '  %v214 = fmul double %v171, %v8\n'
        '  %v215 = fadd double %v213, %v214\n'
        '  %v216 = fmul double %v200, %v12\n'
        '  %v217 = fadd double %v215, %v216\n'
        '  %v218 = fmul double %v211, %v12\n'
        '  %v219 = fsub double %v217, %v218\n'
        '  %v220 = fmul double %v22, %v4\n'
        '  %v221 = fadd double %v219, %v220\n'
        '  %v222 = fmul double %v143, %v221\n'
        '  %v223 = fmul double %v150, %v195\n'
        '  %v224 = fadd double %v222, %v223\n'
        '  %v225 = fmul double %v70, %v8\n'
        '  %v226 = fmul double %v225, %v10\n'
        '  %v227 = fadd double %v224, %v226\n'
        '  %v228 = fmul double %v87, %v91\n'
        '  %v229 = fmul double %v111, %v228\n'
        '  %v230 = fmul double %v115, %v229\n'
        '  %v231 = fmul double %v149, %v8\n'
        '  %v232 = fmul double %v185, %v8\n'
        '  %v233 = fsub double %v231, %v232\n'
        '  %v234 = fmul double %v200, %v10\n'
        '  %v235 = fsub double %v233, %v234\n'
        '  %v236 = fmul double %v211, %v10\n'
        '  %v237 = fadd double %v235, %v236\n'
        '  %v238 = fmul double %v22, %v6\n'
        '  %v239 = fadd double %v237, %v238\n'
        '  %v240 = fmul double %v99, %v195\n'
        '  %v241 = fmul double %v146, %v239\n'
        '  %v242 = fadd double %v240, %v241\n'
        '  %v243 = fmul double %v48, %v8\n'
        '  %v244 = fmul double %v243, %v12\n'
        '  %v245 = fadd double %v242, %v244\n'
        '  %v246 = fneg double %v99\n'
        '  %v247 = fmul double %v246, %v221\n'
        '  %v248 = fmul double %v196, %v239\n'
        '  %v249 = fadd double %v247, %v248\n'
        '  %v250 = fmul double %v141, %v142\n'
        '  %v251 = fadd double %v250, %v145\n'
        '  %v252 = fmul double %v227, %v251\n'
        '  %v253 = fmul double %v109, %v121\n'
        '  %v254 = fmul double %v253, %v228\n'
        '  %v255 = fadd double %v254, %v230\n'
        '  %v256 = fmul double %v245, %v255\n'
        '  %v257 = fadd double %v252, %v256\n'
        '  %v258 = fadd double %v118, %v123\n'
        '  %v259 = fmul double %v249, %v258\n'
        '  %v260 = fadd double %v257, %v259\n'
        '  %v261 = fmul double %v138, %v260\n'
        '  %v262 = fmul double %v141, %v88\n'
        '  %v263 = fmul double %v262, %v91\n'
        '  %v264 = fmul double %v99, %v117\n'
        '  %v265 = fmul double %v264, %v196\n'
        '  %v266 = fadd double %v265, %v263\n'
        '  %v267 = fmul double %v227, %v266\n'
        '  %v268 = fmul double %v115, %v117\n'
        '  %v269 = fadd double %v268, %v122\n'
        '  %v270 = fmul double %v245, %v269\n'
        '  %v271 = fadd double %v267, %v270\n'
        '  %v272 = fmul double %v100, %v229\n'
        '  %v273 = fadd double %v272, %v230\n'
        '  %v274 = fmul double %v249, %v273\n'
        '  %v275 = fadd double %v271, %v274\n'
        '  %v276 = fmul double %v138, %v275\n'
        '  %v277 = fmul double %v117, %v120\n'
        '  %v278 = fadd double %v116, %v277\n'
        '  %v279 = fmul double %v227, %v278\n'
        '  %v280 = fmul double %v108, %v117\n'
        '  %v281 = fmul double %v280, %v150\n'
        '  %v282 = fadd double %v281, %v263\n'
        '  %v283 = fmul double %v245, %v282\n'
        '  %v284 = fadd double %v279, %v283\n'
        '  %v285 = fmul double %v108, %v139\n'
        '  %v286 = fmul double %v285, %v142\n'
        '  %v287 = fmul double %v286, %v72\n'
        '  %v288 = fadd double %v287, %v145\n'
        '  %v289 = fmul double %v249, %v288\n'
        '  %v290 = fadd double %v284, %v289\n'
        '  %v291 = fmul double %v138, %v290\n'
        '  %v292 = fmul double %v4, %v4\n'
        '  %v293 = fadd double %v89, %v292\n'
        '  %v294 = call double @llvm.sin.f64(double %v16)\n'
        '  %v295 = call double @llvm.sqrt.f64(double %v293)\n'
        '  %v296 = fdiv double 0x3FF0000000000000, %v295\n'
        '  %v297 = fmul double %v2, %v2\n'
        '  %v298 = fmul double %v296, %v297\n'
        '  %v299 = fsub double 0x3FF0000000000000, %v297\n'
        '  %v300 = fmul double %v296, %v299\n'
        '  %v301 = fmul double %v298, %v6\n'
        '  %v302 = fmul double %v300, %v6\n'
        '  %v303 = fadd double %v301, %v302\n'
        '  %v304 = fmul double %v149, %v303\n'
        '  %v305 = fneg double %v298\n'
        '  %v306 = fmul double %v305, %v4\n'
        '  %v307 = fmul double %v300, %v4\n'
        '  %v308 = fsub double %v306, %v307\n'
        '  %v309 = fmul double %v153, %v308\n'
        '  %v310 = fadd double %v304, %v309\n'
        '  %v311 = call double @llvm.cos.f64(double %v16)\n'
        '  %v312 = fmul double %v296, %v2\n'
        '  %v313 = fneg double %v149\n'
        '  %v314 = fmul double %v313, %v312\n'
        '  %v315 = fmul double %v314, %v4\n'
        '  %v316 = fmul double %v153, %v312\n'
        '  %v317 = fmul double %v316, %v6\n'
        '  %v318 = fsub double %v315, %v317\n'
        '  %v319 = fmul double %v200, %v296\n'
        '  %v320 = fmul double %v319, %v299\n'
        '  %v321 = fadd double %v318, %v320\n'
        '  %v322 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v75, ptr %v322\n'
        '  %v323 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v79, ptr %v323\n'
        '  %v324 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v82, ptr %v324\n'
        '  %v325 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v261, ptr %v325\n'
        '  %v326 = getelementptr inbounds double, ptr %ds, i64 4\n'
        '  store double %v276, ptr %v326\n'
        '  %v327 = getelementptr inbounds double, ptr %ds, i64 5\n'
        '  store double %v291, ptr %v327\n'
        '  %v328 = fmul double %v261, %v2\n'
        '  %v329 = fmul double %v276, %v4\n'
        '  %v330 = fadd double %v328, %v329\n'
        '  %v331 = fmul double %v291, %v6\n'
        '  %v332 = fadd double %v330, %v331\n'
        '  %v333 = getelementptr inbounds double, ptr %ds, i64 6\n'
        '  store double %v332, ptr %v333\n'
        '  %v334 = fmul double %v4, %v10\n'
        '  %v335 = fmul double %v6, %v12\n'
        '  %v336 = fadd double %v334, %v335\n'
        '  %v337 = fdiv double %v336, %v293\n'
        '  %v338 = getelementptr inbounds double, ptr %ds, i64 7\n'
        '  store double %v337, ptr %v338\n'
        '  %v339 = fneg double %v294\n'
        '  %v340 = fmul double %v339, %v310\n'
        '  %v341 = fmul double %v311, %v321\n'
        '  %v342 = fadd double %v340, %v341\n'
        '  %v343 = getelementptr inbounds double, ptr %ds, i64 8\n'
        '  store double %v342, ptr %v343\n'
        '  %v344 = fmul double %v294, %v321\n'
        '  %v345 = fmul double %v310, %v311\n'
        '  %v346 = fadd double %v344, %v345\n'
        '  %v347 = getelementptr inbounds double, ptr %ds, i64 9\n'
        '  store double %v346, ptr %v347\n'
        '  ret i32 0\n'
        '}\n'
        'declare double @llvm.cos.f64(double)\n'
        'declare double @llvm.pow.f64(double, double)\n'
        'declare double @llvm.sin.f64(double)\n'
        'declare double @llvm.sqrt.f64(double)\n'
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
        '  %v16 = call double @llvm.cos.f64(double %v10)\n'
        '  %v17 = call double @llvm.sin.f64(double %v10)\n'
        '  %v18 = fadd double %v8, %v4\n'
        '  %v19 = fmul double %v8, %v8\n'
        '  %v20 = fmul double %v6, %v6\n'
        '  %v21 = fmul double %v8, %v8\n'
        '  %v22 = fmul double %v21, %v8\n'
        '  %v23 = fmul double %v22, %v8\n'
        '  %v24 = fmul double %v17, %v17\n'
        '  %v25 = fsub double %v24, 0x3FF0000000000000\n'
        '  %v26 = fmul double %v16, %v17\n'
        '  %v27 = fmul double %v16, %v16\n'
        '  %v28 = fsub double %v27, 0x3FF0000000000000\n'
        '  %v29 = fmul double %v8, %v8\n'
        '  %v30 = fmul double %v29, %v8\n'
        '  %v31 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  store double %v16, ptr %v31\n'
        '  %v32 = fneg double %v17\n'
        '  %v33 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  store double %v32, ptr %v33\n'
        '  %v34 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  store double %v17, ptr %v34\n'
        '  %v35 = fneg double %v16\n'
        '  %v36 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  store double %v35, ptr %v36\n'
        '  %v37 = fneg double %v8\n'
        '  %v38 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  store double %v37, ptr %v38\n'
        '  %v39 = getelementptr inbounds double, ptr %q, i64 10\n'
        '  store double %v18, ptr %v39\n'
        '  %v40 = getelementptr inbounds double, ptr %q, i64 11\n'
        '  store double %v19, ptr %v40\n'
        '  %v41 = fneg double %v18\n'
        '  %v42 = getelementptr inbounds double, ptr %q, i64 12\n'
        '  store double %v41, ptr %v42\n'
        '  %v43 = getelementptr inbounds double, ptr %q, i64 13\n'
        '  store double %v20, ptr %v43\n'
        '  %v44 = fneg double %v19\n'
        '  %v45 = getelementptr inbounds double, ptr %q, i64 14\n'
        '  store double %v44, ptr %v45\n'
        '  %v46 = fneg double %v23\n'
        '  %v47 = getelementptr inbounds double, ptr %q, i64 15\n'
        '  store double %v46, ptr %v47\n'
        '  %v48 = getelementptr inbounds double, ptr %q, i64 16\n'
        '  store double %v23, ptr %v48\n'
        '  %v49 = getelementptr inbounds double, ptr %q, i64 17\n'
        '  store double %v25, ptr %v49\n'
        '  %v50 = fneg double %v26\n'
        '  %v51 = getelementptr inbounds double, ptr %q, i64 18\n'
        '  store double %v50, ptr %v51\n'
        '  %v52 = getelementptr inbounds double, ptr %q, i64 19\n'
        '  store double %v28, ptr %v52\n'
        '  %v53 = fmul double %v8, %v25\n'
        '  %v54 = getelementptr inbounds double, ptr %q, i64 20\n'
        '  store double %v53, ptr %v54\n'
        '  %v55 = fneg double %v8\n'
        '  %v56 = fmul double %v55, %v26\n'
        '  %v57 = getelementptr inbounds double, ptr %q, i64 21\n'
        '  store double %v56, ptr %v57\n'
        '  %v58 = fmul double %v8, %v28\n'
        '  %v59 = getelementptr inbounds double, ptr %q, i64 22\n'
        '  store double %v58, ptr %v59\n'
        '  %v60 = fneg double %v30\n'
        '  %v61 = getelementptr inbounds double, ptr %q, i64 23\n'
        '  store double %v60, ptr %v61\n'
        '  %v62 = fneg double %v20\n'
        '  %v63 = getelementptr inbounds double, ptr %q, i64 24\n'
        '  store double %v62, ptr %v63\n'
        '  %v64 = getelementptr inbounds double, ptr %q, i64 25\n'
        '  store double %v30, ptr %v64\n'
        '  ret void\n'
        '}\n'
        'declare double @llvm.cos.f64(double)\n'
        'declare double @llvm.sin.f64(double)\n'
    ),
}
#: how many parameters the IR of ``constants`` reads
LLVM_IR_READS = 5
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '90bb7a42ba2e508682e6955f46f86d343e8cb5b35877584ccb78ef17911b2afe'
