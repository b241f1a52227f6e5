"""two_mode_rigid, fidelity full: rigid body rolling without slipping, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/rigid_emit.py (make derive) from the rigid body 'two_mode_rigid'
through derivation/rigid.py (Lagrange-d'Alembert in body quasi-velocities).
SymPy 1.14.0; input hash sha256:f355910e678615ca72412f545cf777000e15b973ef99b129c242b11e01455c1e

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
INPUT_HASH = 'f355910e678615ca72412f545cf777000e15b973ef99b129c242b11e01455c1e'
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
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '25c128421b16295d9a0aadc21cca6aa9dcae47452b0a5049849e435312073826'
