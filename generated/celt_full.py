"""celt, fidelity full: rigid body rolling without slipping, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/rigid_emit.py (make derive) from the rigid body 'celt'
through derivation/rigid.py (Lagrange-d'Alembert in body quasi-velocities).
SymPy 1.14.0; input hash sha256:093c896a7fa122b0b0d20343f6d7f4fed5316c05e332fd6586662ad84e04d32f

Classical rattleback (celt): a rigid body with an ellipsoidal bottom (semi-axes a, b, c along the body axes x, y, z; centre of mass a distance h below the ellipsoid's centre), inertia tensor about the centre of mass with entries I_xx..I_yz in body axes, rolling without slipping on a horizontal table under gravity g, dissipation torque -sigma*omega.  State: upward vertical n and angular velocity omega in body axes, vertical spin omega_n = omega.n; pose: heading psi of the body x axis, centre of mass (x, y).

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
    p[0] = a            [m] positive
    p[1] = b            [m] positive
    p[2] = c            [m] positive
    p[3] = h            [m] positive
    p[4] = m            [kg] positive
    p[5] = g            [m/s^2] positive
    p[6] = I_xx         [kg m^2] positive
    p[7] = I_yy         [kg m^2] positive
    p[8] = I_zz         [kg m^2] positive
    p[9] = I_xy         [kg m^2] real
    p[10] = I_xz         [kg m^2] real
    p[11] = I_yz         [kg m^2] real
    p[12] = sigma        [N m s] nonnegative
Presets:
    kane_levinson_1982: Kane & Levinson, Int. J. Non-Linear Mech. 17 (1982) 175-186
    schoemer: E. Schoemer's rattleback (golden-ratio ellipsoid)
Multipliers: the contact force on the body in body axes, contact_force_x, contact_force_y, contact_force_z.
Energy and ``power_dissipated`` in the units of the parameters (J and W for SI parameters).
"""
import math

import numpy as np
from numba import njit

MODEL = 'celt'
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
PARAM_NAMES = ('a', 'b', 'c', 'h', 'm', 'g', 'I_xx', 'I_yy', 'I_zz', 'I_xy', 'I_xz', 'I_yz', 'sigma')
PARAM_UNITS = ('m', 'm', 'm', 'm', 'kg', 'm/s^2', 'kg m^2', 'kg m^2', 'kg m^2', 'kg m^2', 'kg m^2', 'kg m^2', 'N m s')
#: admissible values of each parameter: 'positive' (> 0), 'nonnegative' (>= 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'real', 'real', 'real', 'nonnegative')
#: default parameter set and initial state (the CLI's defaults)
DEFAULT_PARAMS = {'a': 0.2, 'b': 0.03, 'c': 0.02, 'h': 0.01, 'm': 1.0, 'g': 9.81, 'I_xx': 0.0002, 'I_yy': 0.0016, 'I_zz': 0.0017, 'I_xy': 2e-05, 'I_xz': 0.0, 'I_yz': 0.0, 'sigma': 0.0}
DEFAULT_STATE = {'n_x': 0.00872620041809352, 'n_y': 0.008726500418107894, 'n_z': 0.9999238479087875, 'omega_x': 0.0, 'omega_y': 0.0, 'omega_z': 5.0, 'omega_n': 4.999619239543938}
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
HAS_DISSIPATION = True
#: model-specific helpers: named parameter sets and the initial state from the physical description
EXPORTS = ('PRESETS', 'PRESET_SOURCES', 'initial_state')
#: named parameter sets (SI units); sources in PRESET_SOURCES
PRESETS = {'kane_levinson_1982': {'a': 0.2, 'b': 0.03, 'c': 0.02, 'h': 0.01, 'm': 1.0, 'g': 9.81, 'I_xx': 0.0002, 'I_yy': 0.0016, 'I_zz': 0.0017, 'I_xy': 2e-05, 'I_xz': 0.0, 'I_yz': 0.0, 'sigma': 0.0}, 'schoemer': {'a': 1.618033988749895, 'b': 1.0, 'c': 1.0, 'h': 0.1875, 'm': 0.2, 'g': 9.81, 'I_xx': 0.05796875, 'I_yy': 0.09032943, 'I_zz': 0.12236068, 'I_xy': -0.025, 'I_xz': 0.0, 'I_yz': 0.0, 'sigma': 0.0}}
PRESET_SOURCES = {'kane_levinson_1982': 'Kane & Levinson, Int. J. Non-Linear Mech. 17 (1982) 175-186', 'schoemer': "E. Schoemer's rattleback (golden-ratio ellipsoid)"}
#: the model file the body comes from
SOURCE = 'knifeedge.derive.celt'
INPUT_HASH = '093c896a7fa122b0b0d20343f6d7f4fed5316c05e332fd6586662ad84e04d32f'
SYMPY_VERSION = '1.14.0'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 247, 'constants': 23, 'rhs_q': 250, 'rhs_pose': 285, 'rhs_pose_q': 286, 'pose_rates': 71, 'energy': 72, 'multipliers': 265, 'power_dissipated': 6}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (247 operations)."""
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    a = p[0]
    b = p[1]
    c = p[2]
    h = p[3]
    m = p[4]
    g = p[5]
    I_xx = p[6]
    I_yy = p[7]
    I_zz = p[8]
    I_xy = p[9]
    I_xz = p[10]
    I_yz = p[11]
    sigma = p[12]
    _c0 = n_y*omega_z
    _c1 = _c0 - n_z*omega_y
    _c2 = n_x*omega_z
    _c3 = -_c2 + n_z*omega_x
    _c4 = n_x*omega_y
    _c5 = _c4 - n_y*omega_x
    _c6 = (a*a)
    _c7 = (n_x*n_x)
    _c8 = (b*b)
    _c9 = (n_y*n_y)
    _c10 = (c*c)
    _c11 = (n_z*n_z)
    _c12 = _c10*_c11 + _c6*_c7 + _c8*_c9
    _c13 = m/_c12
    _c14 = _c8*n_y
    _c15 = _c6*n_x
    _c16 = _c14*_c15
    _c17 = I_xy - _c13*_c16
    _c18 = (_c17*_c17)
    _c19 = _c7*(a*a*a*a)
    _c20 = _c13*_c19
    _c21 = _c9*(b*b*b*b)
    _c22 = _c13*_c21
    _c23 = I_zz + _c20 + _c22
    _c24 = 1/math.sqrt(_c12)
    _c25 = _c10*_c24
    _c26 = _c25*n_z - h
    _c27 = -_c26
    _c28 = _c27*m
    _c29 = _c24*_c6
    _c30 = _c29*n_x
    _c31 = I_xz + _c28*_c30
    _c32 = _c24*_c8
    _c33 = _c32*n_y
    _c34 = I_yz + _c28*_c33
    _c35 = (_c31*_c31)
    _c36 = I_yy + _c20 - _c26*_c28
    _c37 = I_yz - _c26*_c33*m
    _c38 = I_xx + _c22 + (_c27*_c27)*m
    _c39 = _c34*_c37
    _c40 = 1/(_c17*_c31*_c34 + _c17*_c31*_c37 - _c18*_c23 + _c23*_c36*_c38 - _c35*_c36 - _c38*_c39)
    _c41 = _c17*_c23
    _c42 = I_xz*omega_x + I_yz*omega_y + I_zz*omega_z
    _c43 = I_xx*omega_x + I_xy*omega_y + I_xz*omega_z
    _c44 = g*m
    _c45 = m*(_c24*_c8*n_y*omega_x - _c29*_c4)
    _c46 = _c2*_c29 + _c27*omega_x
    _c47 = m*omega_z
    _c48 = _c12**((-3.0/2.0))
    _c49 = _c1*_c48
    _c50 = _c10*n_z
    _c51 = _c15*_c50
    _c52 = _c14*_c48*_c50
    _c53 = _c3*_c52 + _c49*_c51 + _c5*(_c11*_c48*(c*c*c*c) - _c25)
    _c54 = _c16*_c49 + _c3*(_c21*_c48 - _c32) + _c5*_c52
    _c55 = _c44*n_x + _c45*omega_y - _c46*_c47 + m*(-_c53*omega_y + _c54*omega_z)
    _c56 = -_c0*_c32 - _c27*omega_y
    _c57 = _c1*(_c19*_c48 - _c29) + _c16*_c3*_c48 + _c48*_c5*_c51
    _c58 = _c44*n_z + _c46*m*omega_x - _c56*m*omega_y + m*(-_c54*omega_x + _c57*omega_y)
    _c59 = _c27*_c55 + _c30*_c58 + _c42*omega_x - _c43*omega_z - omega_y*sigma
    _c60 = -_c31*_c36
    _c61 = I_xy*omega_x + I_yy*omega_y + I_yz*omega_z
    _c62 = _c44*n_y - _c45*omega_x + _c47*_c56 + m*(_c53*omega_x - _c57*omega_z)
    _c63 = _c24*_c55*_c8*n_y - _c30*_c62 + _c43*omega_y - _c61*omega_x - omega_z*sigma
    _c64 = -_c27*_c62 - _c33*_c58 - _c42*omega_y + _c61*omega_z - omega_x*sigma
    _c65 = _c40*(_c59*(_c31*_c37 - _c41) + _c63*(_c17*_c34 + _c60) + _c64*(_c23*_c36 - _c39))
    _c66 = _c17*_c31
    _c67 = _c40*(_c59*(_c23*_c38 - _c35) + _c63*(-_c34*_c38 + _c66) + _c64*(_c31*_c34 - _c41))
    _c68 = _c40*(_c59*(-_c37*_c38 + _c66) + _c63*(-_c18 + _c36*_c38) + _c64*(_c17*_c37 + _c60))
    ds[0] = _c1
    ds[1] = _c3
    ds[2] = _c5
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
    """``q``: the parameters, then the 22 parameter-only subexpressions of the right-hand side (23 operations)."""
    q = np.empty(35)
    a = p[0]
    b = p[1]
    c = p[2]
    h = p[3]
    m = p[4]
    g = p[5]
    I_xx = p[6]
    I_yy = p[7]
    I_zz = p[8]
    I_xy = p[9]
    I_xz = p[10]
    I_yz = p[11]
    sigma = p[12]
    q[0] = a
    q[1] = b
    q[2] = c
    q[3] = h
    q[4] = m
    q[5] = g
    q[6] = I_xx
    q[7] = I_yy
    q[8] = I_zz
    q[9] = I_xy
    q[10] = I_xz
    q[11] = I_yz
    q[12] = sigma
    _c0 = (a*a)
    _c1 = (b*b)
    _c2 = (c*c)
    _c3 = _c0*m
    _c4 = (a*a*a*a)
    _c5 = (b*b*b*b)
    _c6 = _c1*m
    q[13] = _c0
    q[14] = _c1
    q[15] = _c2
    q[16] = -_c1*_c3
    q[17] = _c4*m
    q[18] = _c5*m
    q[19] = -_c2
    q[20] = _c3
    q[21] = -h
    q[22] = -m
    q[23] = _c6
    q[24] = -_c6
    q[25] = -sigma
    q[26] = -_c1
    q[27] = _c5
    q[28] = _c0*_c1
    q[29] = _c1*_c2
    q[30] = (c*c*c*c)
    q[31] = _c0*_c2
    q[32] = g*m
    q[33] = -_c0
    q[34] = _c4
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (250 operations)."""
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    a = q[0]
    b = q[1]
    c = q[2]
    h = q[3]
    m = q[4]
    g = q[5]
    I_xx = q[6]
    I_yy = q[7]
    I_zz = q[8]
    I_xy = q[9]
    I_xz = q[10]
    I_yz = q[11]
    sigma = q[12]
    _k0 = q[13]
    _k1 = q[14]
    _k2 = q[15]
    _k3 = q[16]
    _k4 = q[17]
    _k5 = q[18]
    _k6 = q[19]
    _k7 = q[20]
    _k8 = q[21]
    _k9 = q[22]
    _k10 = q[23]
    _k11 = q[24]
    _k12 = q[25]
    _k13 = q[26]
    _k14 = q[27]
    _k15 = q[28]
    _k16 = q[29]
    _k17 = q[30]
    _k18 = q[31]
    _k19 = q[32]
    _k20 = q[33]
    _k21 = q[34]
    _c0 = n_y*omega_z
    _c1 = _c0 - n_z*omega_y
    _c2 = n_x*omega_z
    _c3 = -_c2 + n_z*omega_x
    _c4 = n_x*omega_y
    _c5 = n_y*omega_x
    _c6 = _c4 - _c5
    _c7 = (n_x*n_x)
    _c8 = (n_y*n_y)
    _c9 = (n_z*n_z)
    _c10 = _c7*_k0 + _c8*_k1 + _c9*_k2
    _c11 = 1/_c10
    _c12 = n_x*n_y
    _c13 = I_xy + _c11*_c12*_k3
    _c14 = (_c13*_c13)
    _c15 = _c11*_c7*_k4
    _c16 = _c11*_c8*_k5
    _c17 = I_zz + _c15 + _c16
    _c18 = 1/math.sqrt(_c10)
    _c19 = _c18*_k6
    _c20 = _c19*n_z + h
    _c21 = _c18*_c20
    _c22 = I_xz + _c21*_k7*n_x
    _c23 = I_yz + _c21*_k10*n_y
    _c24 = _c18*_k2*n_z + _k8
    _c25 = _c18*n_y
    _c26 = I_yz + _c24*_c25*_k11
    _c27 = (_c22*_c22)
    _c28 = I_yy + _c15 + _c20*_c24*_k9
    _c29 = I_xx + _c16 + (_c20*_c20)*m
    _c30 = _c23*_c26
    _c31 = 1/(_c13*_c22*_c23 + _c13*_c22*_c26 - _c14*_c17 + _c17*_c28*_c29 - _c27*_c28 - _c29*_c30)
    _c32 = _c13*_c17
    _c33 = I_xz*omega_x + I_yz*omega_y + I_zz*omega_z
    _c34 = I_xx*omega_x + I_xy*omega_y + I_xz*omega_z
    _c35 = _c18*_k20
    _c36 = _c18*_c5*_k1 + _c35*_c4
    _c37 = _c18*_k0
    _c38 = _c2*_c37 + _c20*omega_x
    _c39 = _k16*n_y
    _c40 = _c10**((-3.0/2.0))
    _c41 = _c3*_c40
    _c42 = _c1*_c40
    _c43 = _k18*n_x
    _c44 = _c39*_c41*n_z + _c42*_c43*n_z + _c6*(_c19 + _c40*_c9*_k17)
    _c45 = _c12*_k15
    _c46 = _c40*_c6*n_z
    _c47 = _c18*_k13
    _c48 = _c3*(_c40*_c8*_k14 + _c47) + _c39*_c46 + _c42*_c45
    _c49 = _c36*m*omega_y + _c38*_k9*omega_z + _k19*n_x + m*(-_c44*omega_y + _c48*omega_z)
    _c50 = _c0*_c47 - _c20*omega_y
    _c51 = _c1*(_c35 + _c40*_c7*_k21) + _c41*_c45 + _c43*_c46
    _c52 = _c38*m*omega_x + _c50*_k9*omega_y + _k19*n_z + m*(-_c48*omega_x + _c51*omega_y)
    _c53 = _c20*_c49 + _c33*omega_x - _c34*omega_z + _c37*_c52*n_x + _k12*omega_y
    _c54 = -_c22*_c28
    _c55 = I_xy*omega_x + I_yy*omega_y + I_yz*omega_z
    _c56 = _c36*_k9*omega_x + _c50*m*omega_z + _k19*n_y + m*(_c44*omega_x - _c51*omega_z)
    _c57 = _c25*_c49*_k1 + _c34*omega_y + _c35*_c56*n_x - _c55*omega_x + _k12*omega_z
    _c58 = -_c20*_c56 - _c33*omega_y + _c47*_c52*n_y + _c55*omega_z + _k12*omega_x
    _c59 = _c31*(_c53*(_c22*_c26 - _c32) + _c57*(_c13*_c23 + _c54) + _c58*(_c17*_c28 - _c30))
    _c60 = _c13*_c22
    _c61 = _c31*(_c53*(_c17*_c29 - _c27) + _c57*(-_c23*_c29 + _c60) + _c58*(_c22*_c23 - _c32))
    _c62 = _c31*(_c53*(-_c26*_c29 + _c60) + _c57*(-_c14 + _c28*_c29) + _c58*(_c13*_c26 + _c54))
    ds[0] = _c1
    ds[1] = _c3
    ds[2] = _c6
    ds[3] = _c59
    ds[4] = _c61
    ds[5] = _c62
    ds[6] = _c59*n_x + _c61*n_y + _c62*n_z


@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds`` (285 operations)."""
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
    a = p[0]
    b = p[1]
    c = p[2]
    h = p[3]
    m = p[4]
    g = p[5]
    I_xx = p[6]
    I_yy = p[7]
    I_zz = p[8]
    I_xy = p[9]
    I_xz = p[10]
    I_yz = p[11]
    sigma = p[12]
    _c0 = n_y*omega_z
    _c1 = _c0 - n_z*omega_y
    _c2 = n_x*omega_z
    _c3 = -_c2 + n_z*omega_x
    _c4 = n_x*omega_y
    _c5 = _c4 - n_y*omega_x
    _c6 = (a*a)
    _c7 = (n_x*n_x)
    _c8 = (b*b)
    _c9 = (n_y*n_y)
    _c10 = (c*c)
    _c11 = (n_z*n_z)
    _c12 = _c10*_c11 + _c6*_c7 + _c8*_c9
    _c13 = m/_c12
    _c14 = _c8*n_y
    _c15 = _c6*n_x
    _c16 = _c14*_c15
    _c17 = I_xy - _c13*_c16
    _c18 = (_c17*_c17)
    _c19 = _c7*(a*a*a*a)
    _c20 = _c13*_c19
    _c21 = _c9*(b*b*b*b)
    _c22 = _c13*_c21
    _c23 = I_zz + _c20 + _c22
    _c24 = 1/math.sqrt(_c12)
    _c25 = _c10*_c24
    _c26 = _c25*n_z - h
    _c27 = -_c26
    _c28 = _c27*m
    _c29 = _c24*_c6
    _c30 = _c29*n_x
    _c31 = I_xz + _c28*_c30
    _c32 = _c24*_c8
    _c33 = _c32*n_y
    _c34 = I_yz + _c28*_c33
    _c35 = (_c31*_c31)
    _c36 = I_yy + _c20 - _c26*_c28
    _c37 = I_yz - _c26*_c33*m
    _c38 = I_xx + _c22 + (_c27*_c27)*m
    _c39 = _c34*_c37
    _c40 = 1/(_c17*_c31*_c34 + _c17*_c31*_c37 - _c18*_c23 + _c23*_c36*_c38 - _c35*_c36 - _c38*_c39)
    _c41 = _c17*_c23
    _c42 = I_xz*omega_x + I_yz*omega_y + I_zz*omega_z
    _c43 = I_xx*omega_x + I_xy*omega_y + I_xz*omega_z
    _c44 = g*m
    _c45 = _c24*_c8*n_y*omega_x - _c29*_c4
    _c46 = _c45*m
    _c47 = _c2*_c29 + _c27*omega_x
    _c48 = m*omega_z
    _c49 = _c12**((-3.0/2.0))
    _c50 = _c1*_c49
    _c51 = _c10*n_z
    _c52 = _c15*_c51
    _c53 = _c14*_c49*_c51
    _c54 = _c3*_c53 + _c5*(_c11*_c49*(c*c*c*c) - _c25) + _c50*_c52
    _c55 = _c16*_c50 + _c3*(_c21*_c49 - _c32) + _c5*_c53
    _c56 = _c44*n_x + _c46*omega_y - _c47*_c48 + m*(-_c54*omega_y + _c55*omega_z)
    _c57 = -_c0*_c32 - _c27*omega_y
    _c58 = _c1*(_c19*_c49 - _c29) + _c16*_c3*_c49 + _c49*_c5*_c52
    _c59 = _c44*n_z + _c47*m*omega_x - _c57*m*omega_y + m*(-_c55*omega_x + _c58*omega_y)
    _c60 = _c27*_c56 + _c30*_c59 + _c42*omega_x - _c43*omega_z - omega_y*sigma
    _c61 = -_c31*_c36
    _c62 = I_xy*omega_x + I_yy*omega_y + I_yz*omega_z
    _c63 = _c44*n_y - _c46*omega_x + _c48*_c57 + m*(_c54*omega_x - _c58*omega_z)
    _c64 = _c24*_c56*_c8*n_y - _c30*_c63 + _c43*omega_y - _c62*omega_x - omega_z*sigma
    _c65 = -_c27*_c63 - _c33*_c59 - _c42*omega_y + _c62*omega_z - omega_x*sigma
    _c66 = _c40*(_c60*(_c31*_c37 - _c41) + _c64*(_c17*_c34 + _c61) + _c65*(_c23*_c36 - _c39))
    _c67 = _c17*_c31
    _c68 = _c40*(_c60*(_c23*_c38 - _c35) + _c64*(-_c34*_c38 + _c67) + _c65*(_c31*_c34 - _c41))
    _c69 = _c40*(_c60*(-_c37*_c38 + _c67) + _c64*(-_c18 + _c36*_c38) + _c65*(_c17*_c37 + _c61))
    _c70 = _c11 + _c9
    _c71 = math.sin(psi)
    _c72 = 1/math.sqrt(_c70)
    _c73 = _c7*_c72
    _c74 = 1 - _c7
    _c75 = _c72*_c74
    _c76 = _c45*(-_c73*n_y - _c75*n_y) + _c47*(_c73*n_z + _c75*n_z)
    _c77 = math.cos(psi)
    _c78 = _c72*n_x
    _c79 = -_c45*_c78*n_z - _c47*_c78*n_y + _c57*_c72*_c74
    ds[0] = _c1
    ds[1] = _c3
    ds[2] = _c5
    ds[3] = _c66
    ds[4] = _c68
    ds[5] = _c69
    ds[6] = _c66*n_x + _c68*n_y + _c69*n_z
    ds[7] = (n_y*omega_y + n_z*omega_z)/_c70
    ds[8] = -_c71*_c76 + _c77*_c79
    ds[9] = _c71*_c79 + _c76*_c77


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length 10."""
    ds = np.empty(10)
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p`` (286 operations)."""
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
    a = q[0]
    b = q[1]
    c = q[2]
    h = q[3]
    m = q[4]
    g = q[5]
    I_xx = q[6]
    I_yy = q[7]
    I_zz = q[8]
    I_xy = q[9]
    I_xz = q[10]
    I_yz = q[11]
    sigma = q[12]
    _k0 = q[13]
    _k1 = q[14]
    _k2 = q[15]
    _k3 = q[16]
    _k4 = q[17]
    _k5 = q[18]
    _k6 = q[19]
    _k7 = q[20]
    _k8 = q[21]
    _k9 = q[22]
    _k10 = q[23]
    _k11 = q[24]
    _k12 = q[25]
    _k13 = q[26]
    _k14 = q[27]
    _k15 = q[28]
    _k16 = q[29]
    _k17 = q[30]
    _k18 = q[31]
    _k19 = q[32]
    _k20 = q[33]
    _k21 = q[34]
    _c0 = n_y*omega_z
    _c1 = _c0 - n_z*omega_y
    _c2 = n_x*omega_z
    _c3 = -_c2 + n_z*omega_x
    _c4 = n_x*omega_y
    _c5 = n_y*omega_x
    _c6 = _c4 - _c5
    _c7 = (n_x*n_x)
    _c8 = (n_y*n_y)
    _c9 = (n_z*n_z)
    _c10 = _c7*_k0 + _c8*_k1 + _c9*_k2
    _c11 = 1/_c10
    _c12 = n_x*n_y
    _c13 = I_xy + _c11*_c12*_k3
    _c14 = (_c13*_c13)
    _c15 = _c11*_c7*_k4
    _c16 = _c11*_c8*_k5
    _c17 = I_zz + _c15 + _c16
    _c18 = 1/math.sqrt(_c10)
    _c19 = _c18*_k6
    _c20 = _c19*n_z + h
    _c21 = _c18*_c20
    _c22 = I_xz + _c21*_k7*n_x
    _c23 = I_yz + _c21*_k10*n_y
    _c24 = _c18*_k2*n_z + _k8
    _c25 = _c18*n_y
    _c26 = I_yz + _c24*_c25*_k11
    _c27 = (_c22*_c22)
    _c28 = I_yy + _c15 + _c20*_c24*_k9
    _c29 = I_xx + _c16 + (_c20*_c20)*m
    _c30 = _c23*_c26
    _c31 = 1/(_c13*_c22*_c23 + _c13*_c22*_c26 - _c14*_c17 + _c17*_c28*_c29 - _c27*_c28 - _c29*_c30)
    _c32 = _c13*_c17
    _c33 = I_xz*omega_x + I_yz*omega_y + I_zz*omega_z
    _c34 = I_xx*omega_x + I_xy*omega_y + I_xz*omega_z
    _c35 = _c18*_k20
    _c36 = _c18*_c5*_k1 + _c35*_c4
    _c37 = _c18*_k0
    _c38 = _c2*_c37 + _c20*omega_x
    _c39 = _k16*n_y*n_z
    _c40 = _c10**((-3.0/2.0))
    _c41 = _c3*_c40
    _c42 = _c1*_c40
    _c43 = n_x*n_z
    _c44 = _c43*_k18
    _c45 = _c39*_c41 + _c42*_c44 + _c6*(_c19 + _c40*_c9*_k17)
    _c46 = _c12*_k15
    _c47 = _c40*_c6
    _c48 = _c18*_k13
    _c49 = _c3*(_c40*_c8*_k14 + _c48) + _c39*_c47 + _c42*_c46
    _c50 = _c36*m*omega_y + _c38*_k9*omega_z + _k19*n_x + m*(-_c45*omega_y + _c49*omega_z)
    _c51 = _c0*_c48 - _c20*omega_y
    _c52 = _c1*(_c35 + _c40*_c7*_k21) + _c41*_c46 + _c44*_c47
    _c53 = _c38*m*omega_x + _c51*_k9*omega_y + _k19*n_z + m*(-_c49*omega_x + _c52*omega_y)
    _c54 = _c20*_c50 + _c33*omega_x - _c34*omega_z + _c37*_c53*n_x + _k12*omega_y
    _c55 = -_c22*_c28
    _c56 = I_xy*omega_x + I_yy*omega_y + I_yz*omega_z
    _c57 = _c36*_k9*omega_x + _c51*m*omega_z + _k19*n_y + m*(_c45*omega_x - _c52*omega_z)
    _c58 = _c25*_c50*_k1 + _c34*omega_y + _c35*_c57*n_x - _c56*omega_x + _k12*omega_z
    _c59 = -_c20*_c57 - _c33*omega_y + _c48*_c53*n_y + _c56*omega_z + _k12*omega_x
    _c60 = _c31*(_c54*(_c22*_c26 - _c32) + _c58*(_c13*_c23 + _c55) + _c59*(_c17*_c28 - _c30))
    _c61 = _c13*_c22
    _c62 = _c31*(_c54*(_c17*_c29 - _c27) + _c58*(-_c23*_c29 + _c61) + _c59*(_c22*_c23 - _c32))
    _c63 = _c31*(_c54*(-_c26*_c29 + _c61) + _c58*(-_c14 + _c28*_c29) + _c59*(_c13*_c26 + _c55))
    _c64 = _c8 + _c9
    _c65 = math.sin(psi)
    _c66 = 1/math.sqrt(_c64)
    _c67 = _c66*_c7
    _c68 = 1 - _c7
    _c69 = _c66*_c68
    _c70 = _c36*(-_c67*n_y - _c69*n_y) + _c38*(_c67*n_z + _c69*n_z)
    _c71 = math.cos(psi)
    _c72 = -_c12*_c38*_c66 - _c36*_c43*_c66 + _c51*_c66*_c68
    ds[0] = _c1
    ds[1] = _c3
    ds[2] = _c6
    ds[3] = _c60
    ds[4] = _c62
    ds[5] = _c63
    ds[6] = _c60*n_x + _c62*n_y + _c63*n_z
    ds[7] = (n_y*omega_y + n_z*omega_z)/_c64
    ds[8] = -_c65*_c70 + _c71*_c72
    ds[9] = _c65*_c72 + _c70*_c71


@njit(cache=True)
def pose_rates(s, p):
    """Return (psi_dot, x_dot, y_dot) at the pose-extended state ``s`` (71 operations)."""
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
    a = p[0]
    b = p[1]
    c = p[2]
    h = p[3]
    m = p[4]
    g = p[5]
    I_xx = p[6]
    I_yy = p[7]
    I_zz = p[8]
    I_xy = p[9]
    I_xz = p[10]
    I_yz = p[11]
    sigma = p[12]
    _c0 = (n_y*n_y)
    _c1 = (n_z*n_z)
    _c2 = _c0 + _c1
    _c3 = math.sin(psi)
    _c4 = (n_x*n_x)
    _c5 = 1/math.sqrt(_c2)
    _c6 = _c4*_c5
    _c7 = 1 - _c4
    _c8 = _c5*_c7
    _c9 = (a*a)
    _c10 = (b*b)
    _c11 = (c*c)
    _c12 = 1/math.sqrt(_c0*_c10 + _c1*_c11 + _c4*_c9)
    _c13 = _c9*n_x
    _c14 = _c10*_c12*n_y*omega_x - _c12*_c13*omega_y
    _c15 = _c12*omega_z
    _c16 = -_c11*_c12*n_z + h
    _c17 = _c13*_c15 + _c16*omega_x
    _c18 = _c14*(-_c6*n_y - _c8*n_y) + _c17*(_c6*n_z + _c8*n_z)
    _c19 = math.cos(psi)
    _c20 = _c5*n_x
    _c21 = -_c14*_c20*n_z - _c17*_c20*n_y + _c5*_c7*(-_c10*_c15*n_y - _c16*omega_y)
    out[0] = (n_y*omega_y + n_z*omega_z)/_c2
    out[1] = -_c18*_c3 + _c19*_c21
    out[2] = _c18*_c19 + _c21*_c3
    return out


@njit(cache=True)
def energy(s, p):
    """Mechanical energy (72 operations)."""
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    a = p[0]
    b = p[1]
    c = p[2]
    h = p[3]
    m = p[4]
    g = p[5]
    I_xx = p[6]
    I_yy = p[7]
    I_zz = p[8]
    I_xy = p[9]
    I_xz = p[10]
    I_yz = p[11]
    sigma = p[12]
    _c0 = (a*a)
    _c1 = _c0*(n_x*n_x)
    _c2 = (b*b)
    _c3 = _c2*(n_y*n_y)
    _c4 = (c*c)
    _c5 = 1/math.sqrt(_c1 + _c3 + _c4*(n_z*n_z))
    _c6 = -_c4*_c5*n_z + h
    _c7 = _c0*n_x
    _c8 = _c5*omega_z
    energy = g*m*(_c1*_c5 + _c3*_c5 - _c6*n_z) + ((1.0/2.0))*m*(((_c6*omega_x + _c7*_c8)*(_c6*omega_x + _c7*_c8)) + ((-_c2*_c8*n_y - _c6*omega_y)*(-_c2*_c8*n_y - _c6*omega_y)) + ((_c2*_c5*n_y*omega_x - _c5*_c7*omega_y)*(_c2*_c5*n_y*omega_x - _c5*_c7*omega_y))) + ((1.0/2.0))*omega_x*(I_xx*omega_x + I_xy*omega_y + I_xz*omega_z) + ((1.0/2.0))*omega_y*(I_xy*omega_x + I_yy*omega_y + I_yz*omega_z) + ((1.0/2.0))*omega_z*(I_xz*omega_x + I_yz*omega_y + I_zz*omega_z)
    return energy


@njit(cache=True)
def power_dissipated(s, p):
    """Power dissipated by the damping torque (6 operations)."""
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    a = p[0]
    b = p[1]
    c = p[2]
    h = p[3]
    m = p[4]
    g = p[5]
    I_xx = p[6]
    I_yy = p[7]
    I_zz = p[8]
    I_xy = p[9]
    I_xz = p[10]
    I_yz = p[11]
    sigma = p[12]
    power = sigma*((omega_x*omega_x) + (omega_y*omega_y) + (omega_z*omega_z))
    return power


@njit(cache=True)
def multipliers(s, p):
    """Contact force on the body in body axes (265 operations)."""
    out = np.empty(3)
    n_x = s[0]
    n_y = s[1]
    n_z = s[2]
    omega_x = s[3]
    omega_y = s[4]
    omega_z = s[5]
    omega_n = s[6]
    a = p[0]
    b = p[1]
    c = p[2]
    h = p[3]
    m = p[4]
    g = p[5]
    I_xx = p[6]
    I_yy = p[7]
    I_zz = p[8]
    I_xy = p[9]
    I_xz = p[10]
    I_yz = p[11]
    sigma = p[12]
    _c0 = (c*c)
    _c1 = (a*a)
    _c2 = (n_x*n_x)
    _c3 = (b*b)
    _c4 = (n_y*n_y)
    _c5 = (n_z*n_z)
    _c6 = _c0*_c5 + _c1*_c2 + _c3*_c4
    _c7 = 1/math.sqrt(_c6)
    _c8 = _c0*_c7
    _c9 = _c8*n_z - h
    _c10 = -_c9
    _c11 = _c10*m
    _c12 = _c1*_c7
    _c13 = _c12*n_x
    _c14 = I_xz + _c11*_c13
    _c15 = (_c14*_c14)
    _c16 = _c2*(a*a*a*a)
    _c17 = m/_c6
    _c18 = _c16*_c17
    _c19 = _c4*(b*b*b*b)
    _c20 = _c17*_c19
    _c21 = I_zz + _c18 + _c20
    _c22 = I_xx + (_c10*_c10)*m + _c20
    _c23 = I_xz*omega_x + I_yz*omega_y + I_zz*omega_z
    _c24 = I_xx*omega_x + I_xy*omega_y + I_xz*omega_z
    _c25 = n_y*omega_z
    _c26 = _c25 - n_z*omega_y
    _c27 = _c1*n_x
    _c28 = _c26*_c27
    _c29 = _c6**((-3.0/2.0))
    _c30 = _c0*n_z
    _c31 = _c29*_c30
    _c32 = n_x*omega_z
    _c33 = -_c32 + n_z*omega_x
    _c34 = _c29*_c3*n_y
    _c35 = _c30*_c34
    _c36 = n_x*omega_y
    _c37 = _c36 - n_y*omega_x
    _c38 = _c28*_c31 + _c33*_c35 + _c37*(_c29*_c5*(c*c*c*c) - _c8)
    _c39 = _c3*_c7
    _c40 = _c28*_c34 + _c33*(_c19*_c29 - _c39) + _c35*_c37
    _c41 = _c38*omega_y - _c40*omega_z
    _c42 = g*m
    _c43 = -_c12*_c36 + _c3*_c7*n_y*omega_x
    _c44 = m*omega_y
    _c45 = m*(_c10*omega_x + _c12*_c32)
    _c46 = _c42*n_x + _c43*_c44 - _c45*omega_z
    _c47 = -_c41*m + _c46
    _c48 = _c26*(-_c12 + _c16*_c29) + _c27*_c31*_c37 + _c27*_c33*_c34
    _c49 = _c40*omega_x - _c48*omega_y
    _c50 = -_c10*omega_y - _c25*_c39
    _c51 = _c42*n_z - _c44*_c50 + _c45*omega_x
    _c52 = -_c49*m + _c51
    _c53 = _c10*_c47 + _c13*_c52 + _c23*omega_x - _c24*omega_z - omega_y*sigma
    _c54 = I_xy - _c17*_c27*_c3*n_y
    _c55 = _c14*_c54
    _c56 = _c39*n_y
    _c57 = I_yz + _c11*_c56
    _c58 = _c22*_c57
    _c59 = I_xy*omega_x + I_yy*omega_y + I_yz*omega_z
    _c60 = _c38*omega_x - _c48*omega_z
    _c61 = _c42*n_y - _c43*m*omega_x + _c50*m*omega_z
    _c62 = _c60*m + _c61
    _c63 = -_c13*_c62 + _c24*omega_y + _c3*_c47*_c7*n_y - _c59*omega_x - omega_z*sigma
    _c64 = _c21*_c54
    _c65 = -_c10*_c62 - _c23*omega_y - _c52*_c56 + _c59*omega_z - omega_x*sigma
    _c66 = _c53*(-_c15 + _c21*_c22) + _c63*(_c55 - _c58) + _c65*(_c14*_c57 - _c64)
    _c67 = (_c54*_c54)
    _c68 = I_yy - _c11*_c9 + _c18
    _c69 = I_yz - _c56*_c9*m
    _c70 = 1/(_c14*_c54*_c57 + _c14*_c54*_c69 - _c15*_c68 + _c21*_c22*_c68 - _c21*_c67 - _c58*_c69)
    _c71 = _c10*_c70
    _c72 = -_c14*_c68
    _c73 = _c70*(_c53*(-_c22*_c69 + _c55) + _c63*(_c22*_c68 - _c67) + _c65*(_c54*_c69 + _c72))
    _c74 = _c53*(_c14*_c69 - _c64) + _c63*(_c54*_c57 + _c72) + _c65*(_c21*_c68 - _c57*_c69)
    out[0] = _c46 + m*(-_c41 - _c56*_c73 - _c66*_c71)
    out[1] = _c61 + m*(_c13*_c73 + _c60 + _c71*_c74)
    out[2] = _c51 + m*(-_c13*_c66*_c70 + _c3*_c7*_c70*_c74*n_y - _c49)
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
    a = p[0]
    b = p[1]
    c = p[2]
    h = p[3]
    m = p[4]
    g = p[5]
    I_xx = p[6]
    I_yy = p[7]
    I_zz = p[8]
    I_xy = p[9]
    I_xz = p[10]
    I_yz = p[11]
    sigma = p[12]
    _c0 = 7.61465737367355e-5*(a*a)
    _c1 = 7.61518095472372e-5*(b*b)
    _c2 = 0.999847701616716*(c*c)
    _c3 = 1/math.sqrt(_c0 + _c1 + _c2)
    out[0] = m
    out[1] = g
    out[2] = sigma
    out[3] = I_xx
    out[4] = I_xy
    out[5] = I_xz
    out[6] = I_xy
    out[7] = I_yy
    out[8] = I_yz
    out[9] = I_xz
    out[10] = I_yz
    out[11] = I_zz
    out[12] = _c0*_c3 + _c1*_c3 + _c2*_c3 - 0.999923847908788*h
    return (out[0], out[1], out[2], (out[3:6], out[6:9], out[9:12]), out[12])



#: how to draw the body (derivation/drawing.py): names of the rows of ``body_points``,
#: segments between them, the contact point, the point masses, the tilts a picture may
#: magnify, the outline curves of ``body_outlines``
DRAWING = {'points': ('G', 'C', 'E', 'axis1_minus', 'axis1_plus', 'axis2_minus', 'axis2_plus', 'axis3_minus', 'axis3_plus'), 'segments': (('axis1_minus', 'axis1_plus'), ('axis2_minus', 'axis2_plus'), ('axis3_minus', 'axis3_plus')), 'contact': 'C', 'masses': ('G',), 'magnify': ('n_x', 'n_y'), 'outlines': ('section_xy', 'section_xz', 'section_yz'), 'description': "rattleback: the principal sections of its ellipsoid (semi-axes a, b, c, centre E a height h above the centre of mass G), its principal axes of inertia through G (turned by the chirality delta from the ellipsoid's axes), the contact point C; tilts magnified by scaling n_x, n_y"}


@njit(cache=True)
def body_points(s, p):
    """World coordinates (z up, table z = 0) of DRAWING["points"] at the pose-extended state ``s``; shape (9, 3) (182 operations)."""
    out = np.empty((9, 3))
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
    a = p[0]
    b = p[1]
    c = p[2]
    h = p[3]
    m = p[4]
    g = p[5]
    I_xx = p[6]
    I_yy = p[7]
    I_zz = p[8]
    I_xy = p[9]
    I_xz = p[10]
    I_yz = p[11]
    sigma = p[12]
    _c0 = (a*a)
    _c1 = (n_x*n_x)
    _c2 = (n_y*n_y)
    _c3 = (n_z*n_z)
    _c4 = _c1 + _c2 + _c3
    _c5 = 1/_c4
    _c6 = _c1*_c5
    _c7 = _c0*_c6
    _c8 = (b*b)
    _c9 = _c2*_c5*_c8
    _c10 = (c*c)
    _c11 = 1/math.sqrt(_c10*_c3*_c5 + _c7 + _c9)
    _c12 = -h
    _c13 = 1/math.sqrt(_c4)
    _c14 = _c13*n_z
    _c15 = -_c10*_c11*_c14 - _c12
    _c16 = _c14*_c15
    _c17 = _c11*_c7 + _c11*_c9 - _c16
    _c18 = -x
    _c19 = math.cos(psi)
    _c20 = math.sqrt(1 - _c6)
    _c21 = _c19*_c20
    _c22 = _c13*n_x
    _c23 = _c0*_c11*_c22
    _c24 = 1/_c20
    _c25 = _c24*n_y
    _c26 = _c5*n_x
    _c27 = _c19*_c26
    _c28 = math.sin(psi)
    _c29 = _c1/_c4**((3.0/2.0))
    _c30 = _c24*n_z
    _c31 = _c14*_c20 + _c29*_c30
    _c32 = -_c25*_c27 - _c28*_c31
    _c33 = _c13*n_y
    _c34 = _c11*_c33*_c8
    _c35 = -_c20*_c33 - _c25*_c29
    _c36 = -_c27*_c30 - _c28*_c35
    _c37 = -y
    _c38 = _c20*_c28
    _c39 = _c26*_c28
    _c40 = _c19*_c31 - _c25*_c39
    _c41 = _c19*_c35 - _c30*_c39
    _c42 = 1/_c0
    _c43 = ((1.0/2.0))*math.atan2(-2*I_xy, -I_xx + I_yy)
    _c44 = math.cos(_c43)
    _c45 = (_c44*_c44)
    _c46 = 1/_c8
    _c47 = math.sin(_c43)
    _c48 = (_c47*_c47)
    _c49 = 1/math.sqrt(_c42*_c45 + _c46*_c48)
    _c50 = _c47*_c49
    _c51 = _c44*_c49
    _c52 = _c21*_c51 + _c32*_c50
    _c53 = _c38*_c51 + _c40*_c50
    _c54 = _c22*_c51 + _c33*_c50
    _c55 = 1/math.sqrt(_c42*_c48 + _c45*_c46)
    _c56 = _c47*_c55
    _c57 = _c21*_c56
    _c58 = _c44*_c55
    _c59 = _c32*_c58
    _c60 = _c38*_c56
    _c61 = _c40*_c58
    _c62 = _c22*_c56
    _c63 = _c33*_c58
    _c64 = -_c12 - c
    _c65 = c + h
    out[0, 0] = x
    out[0, 1] = y
    out[0, 2] = _c17
    out[1, 0] = _c15*_c36 - _c18 - _c21*_c23 - _c32*_c34
    out[1, 1] = _c15*_c41 - _c23*_c38 - _c34*_c40 - _c37
    out[1, 2] = 0
    out[2, 0] = _c36*h + x
    out[2, 1] = _c41*h + y
    out[2, 2] = _c14*h + _c17
    out[3, 0] = -_c18 - _c52
    out[3, 1] = -_c37 - _c53
    out[3, 2] = _c0*_c1*_c11*_c5 + _c11*_c2*_c5*_c8 - _c16 - _c54
    out[4, 0] = _c52 + x
    out[4, 1] = _c53 + y
    out[4, 2] = _c17 + _c54
    out[5, 0] = _c57 - _c59 + x
    out[5, 1] = _c60 - _c61 + y
    out[5, 2] = _c17 + _c62 - _c63
    out[6, 0] = -_c57 + _c59 + x
    out[6, 1] = -_c60 + _c61 + y
    out[6, 2] = _c17 - _c62 + _c63
    out[7, 0] = _c36*_c64 + x
    out[7, 1] = _c41*_c64 + y
    out[7, 2] = _c14*_c64 + _c17
    out[8, 0] = _c36*_c65 + x
    out[8, 1] = _c41*_c65 + y
    out[8, 2] = _c14*_c65 + _c17
    return out


@njit(cache=True)
def body_outlines(s, p, uu):
    """World coordinates of the curves DRAWING["outlines"] at the parameters ``uu`` in [0, 2 pi); shape (3, len(uu), 3) (114 operations)."""
    out = np.empty((3, uu.shape[0], 3))
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
    a = p[0]
    b = p[1]
    c = p[2]
    h = p[3]
    m = p[4]
    g = p[5]
    I_xx = p[6]
    I_yy = p[7]
    I_zz = p[8]
    I_xy = p[9]
    I_xz = p[10]
    I_yz = p[11]
    sigma = p[12]
    for j in range(uu.shape[0]):
        u = uu[j]
        _c0 = math.cos(psi)
        _c1 = (n_x*n_x)
        _c2 = (n_y*n_y)
        _c3 = (n_z*n_z)
        _c4 = _c1 + _c2 + _c3
        _c5 = 1/_c4
        _c6 = _c1*_c5
        _c7 = math.sqrt(1 - _c6)
        _c8 = math.cos(u)
        _c9 = _c8*a
        _c10 = _c7*_c9
        _c11 = _c0*_c10
        _c12 = 1/_c7
        _c13 = _c12*n_z
        _c14 = _c5*n_x
        _c15 = _c0*_c14
        _c16 = math.sin(psi)
        _c17 = 1/math.sqrt(_c4)
        _c18 = _c17*_c7
        _c19 = _c12*n_y
        _c20 = _c1/_c4**((3.0/2.0))
        _c21 = -_c18*n_y - _c19*_c20
        _c22 = -_c13*_c15 - _c16*_c21
        _c23 = _c13*_c20 + _c18*n_z
        _c24 = -_c15*_c19 - _c16*_c23
        _c25 = math.sin(u)
        _c26 = _c25*b
        _c27 = _c10*_c16
        _c28 = _c14*_c16
        _c29 = _c0*_c21 - _c13*_c28
        _c30 = _c0*_c23 - _c19*_c28
        _c31 = _c17*n_z
        _c32 = _c17*_c9*n_x
        _c33 = _c17*n_y
        _c34 = _c6*(a*a)
        _c35 = _c2*_c5*(b*b)
        _c36 = (c*c)
        _c37 = 1/math.sqrt(_c3*_c36*_c5 + _c34 + _c35)
        _c38 = _c34*_c37
        _c39 = _c35*_c37
        _c40 = -_c31*(-_c31*_c36*_c37 + h)
        _c41 = _c25*c + h
        _c42 = _c22*_c41 + x
        _c43 = _c29*_c41 + y
        _c44 = _c31*_c41 + _c38 + _c39 + _c40
        _c45 = _c8*b
        out[0, j, 0] = _c11 + _c22*h + _c24*_c26 + x
        out[0, j, 1] = _c26*_c30 + _c27 + _c29*h + y
        out[0, j, 2] = _c26*_c33 + _c31*h + _c32 + _c38 + _c39 + _c40
        out[1, j, 0] = _c11 + _c42
        out[1, j, 1] = _c27 + _c43
        out[1, j, 2] = _c32 + _c44
        out[2, j, 0] = _c24*_c45 + _c42
        out[2, j, 1] = _c30*_c45 + _c43
        out[2, j, 2] = _c33*_c45 + _c44
    return out
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '5ad641e5f09612f277513d007b88fd14cb961a14eff539c4427f69c9517695b8'
