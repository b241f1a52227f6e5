"""celt, fidelity reduced: small tilts, spin kept: rocking accelerations to first order in the tilts, spin acceleration to second order (derivation/rigid_small.py).

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/rigid_small_emit.py (make derive) from the rigid body 'celt'
through derivation/rigid.py and derivation/rigid_small.py.
SymPy 1.14.0; input hash sha256:5c990ef58147e72c6c1cd35844724ec64353f81d2f3aa891d3b8b6b988c8c88e

Classical rattleback (celt): a rigid body with an ellipsoidal bottom (semi-axes a, b, c along the body axes x, y, z; centre of mass a distance h below the ellipsoid's centre), inertia tensor about the centre of mass with entries I_xx..I_yz in body axes, rolling without slipping on a horizontal table under gravity g, dissipation torque -sigma*omega.  State: upward vertical n and angular velocity omega in body axes, vertical spin omega_n = omega.n; pose: heading psi of the body x axis, centre of mass (x, y).

Parameters set to zero at this fidelity (the upright spin must be an equilibrium): I_xz, I_yz.

State vector ``s``:
    s[0] = n_x          [1]
    s[1] = n_y          [1]
    s[2] = omega_x      [rad/s]
    s[3] = omega_y      [rad/s]
    s[4] = omega_z      [rad/s]
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
    p[10] = sigma        [N m s] nonnegative
Presets:
    kane_levinson_1982: Kane & Levinson, Int. J. Non-Linear Mech. 17 (1982) 175-186
    schoemer: E. Schoemer's rattleback (golden-ratio ellipsoid)
"""
import math

import numpy as np
from numba import njit

MODEL = 'celt'
FIDELITY = 'reduced'
#: what this fidelity is
FIDELITY_DOC = 'small tilts, spin kept: rocking accelerations to first order in the tilts, spin acceleration to second order (derivation/rigid_small.py)'
STATE_NAMES = ('n_x', 'n_y', 'omega_x', 'omega_y', 'omega_z')
STATE_UNITS = ('1', '1', 'rad/s', 'rad/s', 'rad/s')
POSE_NAMES = ()
POSE_UNITS = ()
POSE_DOC = ''
PARAM_NAMES = ('a', 'b', 'c', 'h', 'm', 'g', 'I_xx', 'I_yy', 'I_zz', 'I_xy', 'sigma')
PARAM_UNITS = ('m', 'm', 'm', 'm', 'kg', 'm/s^2', 'kg m^2', 'kg m^2', 'kg m^2', 'kg m^2', 'N m s')
#: admissible values of each parameter: 'positive' (> 0), 'nonnegative' (>= 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'real', 'nonnegative')
DEFAULT_PARAMS = {'a': 0.2, 'b': 0.03, 'c': 0.02, 'h': 0.01, 'm': 1.0, 'g': 9.81, 'I_xx': 0.0002, 'I_yy': 0.0016, 'I_zz': 0.0017, 'I_xy': 2e-05, 'sigma': 0.0}
DEFAULT_STATE = {'n_x': 9.999999900000002e-05, 'n_y': 9.999999900000002e-05, 'omega_x': 0.0, 'omega_y': 0.0, 'omega_z': 0.2}
RATE_PAIRS = ()
TILT_NAMES = ('n_x', 'n_y')
#: the vertical spin (omega_z: omega . n to second order in the tilts), whose zero crossings are the reversals
REVERSAL_EVENTS = ('omega_z',)
EVENT_NAMES = ()
#: largest |value| of each named state where this fidelity holds
VALIDITY = {'n_x': 0.003, 'n_y': 0.03}
VALIDITY_DOC = "small tilts (terms of third order dropped): the expansion parameters are (a/c)^2 |n_x| and (b/c)^2 |n_y| for an ellipsoid; the bounds suit the Kane-Levinson celt (a/c = 10, b/c = 1.5), whose rocking accelerations are then within about 1 % of the full model's; the upright spin must be an equilibrium (I_xz = I_yz = 0)"
MULTIPLIER_NAMES = ()
HAS_DISSIPATION = True
EXPORTS = ('PRESETS', 'PRESET_SOURCES', 'initial_state')
PRESETS = {'kane_levinson_1982': {'a': 0.2, 'b': 0.03, 'c': 0.02, 'h': 0.01, 'm': 1.0, 'g': 9.81, 'I_xx': 0.0002, 'I_yy': 0.0016, 'I_zz': 0.0017, 'I_xy': 2e-05, 'sigma': 0.0}, 'schoemer': {'a': 1.618033988749895, 'b': 1.0, 'c': 1.0, 'h': 0.1875, 'm': 0.2, 'g': 9.81, 'I_xx': 0.05796875, 'I_yy': 0.09032943, 'I_zz': 0.12236068, 'I_xy': -0.025, 'sigma': 0.0}}
PRESET_SOURCES = {'kane_levinson_1982': 'Kane & Levinson, Int. J. Non-Linear Mech. 17 (1982) 175-186', 'schoemer': "E. Schoemer's rattleback (golden-ratio ellipsoid)"}
SOURCE = 'knifeedge.derive.celt'
INPUT_HASH = '5c990ef58147e72c6c1cd35844724ec64353f81d2f3aa891d3b8b6b988c8c88e'
SYMPY_VERSION = '1.14.0'
OP_COUNTS = {'rhs': 606, 'constants': 511, 'rhs_q': 108, 'energy': 85, 'power_dissipated': 6}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (606 operations)."""
    n_x = s[0]
    n_y = s[1]
    omega_x = s[2]
    omega_y = s[3]
    omega_z = s[4]
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
    sigma = p[10]
    _c0 = n_y*omega_z
    _c1 = n_x*omega_z
    _c2 = (I_xy*I_xy)
    _c3 = (c*c)
    _c4 = _c3*m
    _c5 = (h*h)
    _c6 = _c5*m
    _c7 = c*m
    _c8 = 2*h
    _c9 = _c7*_c8
    _c10 = (m*m)
    _c11 = (h*h*h)
    _c12 = 4*_c10
    _c13 = _c12*h
    _c14 = _c10*_c3
    _c15 = 1/(I_xx*I_yy + I_xx*_c4 + I_xx*_c6 - I_xx*_c9 + I_yy*_c4 + I_yy*_c6 - I_yy*_c9 + _c10*(c*c*c*c) + _c10*(h*h*h*h) - _c11*_c12*c - _c13*(c*c*c) + 6*_c14*_c5 - _c2)
    _c16 = I_xy*_c15
    _c17 = _c16*sigma
    _c18 = _c4 + _c6 - _c9
    _c19 = I_yy + _c18
    _c20 = _c15*_c19
    _c21 = _c20*sigma
    _c22 = 1/I_zz
    _c23 = _c22*sigma
    _c24 = (b*b)
    _c25 = _c16*m
    _c26 = _c24*_c25
    _c27 = 1/c
    _c28 = _c27*h
    _c29 = _c26*_c28
    _c30 = _c23*_c26 - _c23*_c29
    _c31 = (a*a)
    _c32 = _c20*m
    _c33 = _c31*_c32
    _c34 = _c15*_c19*_c22*_c27*_c31*h*m*sigma - _c23*_c33
    _c35 = _c25*_c31
    _c36 = _c27*g
    _c37 = g*h
    _c38 = _c7*g
    _c39 = -_c16*_c38 + _c25*_c37
    _c40 = _c24*_c32
    _c41 = -_c26 + _c29
    _c42 = _c28*_c35
    _c43 = _c35 - _c42
    _c44 = -_c41 - _c43
    _c45 = (omega_z*omega_z)
    _c46 = _c45*n_x
    _c47 = _c28*_c33
    _c48 = _c45*n_y
    _c49 = _c16*_c19
    _c50 = -I_zz*_c16 + _c16*_c4 + _c16*_c6 - _c16*_c9
    _c51 = omega_x*omega_z
    _c52 = _c15*_c2
    _c53 = -_c33 + _c47
    _c54 = omega_y*omega_z
    _c55 = I_xx + _c18
    _c56 = _c15*_c55
    _c57 = _c56*sigma
    _c58 = _c23*_c35 - _c23*_c42
    _c59 = _c56*m
    _c60 = _c24*_c59
    _c61 = _c15*_c22*_c24*_c27*_c55*h*m*sigma - _c23*_c60
    _c62 = _c31*_c59
    _c63 = _c28*_c60 - _c60
    _c64 = _c16*_c55
    _c65 = I_xy*_c22
    _c66 = I_xx*_c22
    _c67 = I_yy*_c22
    _c68 = (1.0/(I_zz*I_zz))
    _c69 = _c24*_c31
    _c70 = _c17*_c68*_c69
    _c71 = 2*_c10*_c70
    _c72 = 1/_c3
    _c73 = _c5*_c72
    _c74 = (n_x*n_x)
    _c75 = (a*a*a*a)
    _c76 = _c68*_c75
    _c77 = _c10*_c21
    _c78 = (n_y*n_y)
    _c79 = (b*b*b*b)
    _c80 = _c68*_c79
    _c81 = _c10*_c57
    _c82 = c*g
    _c83 = _c10*_c22
    _c84 = _c16*_c83
    _c85 = _c31*_c84
    _c86 = _c8*g
    _c87 = _c75*_c84
    _c88 = _c37*_c72
    _c89 = _c36*_c5
    _c90 = _c24*_c82
    _c91 = _c79*_c84
    _c92 = _c24*_c84
    _c93 = _c69*_c84
    _c94 = _c27*_c8
    _c95 = _c93*_c94
    _c96 = _c73*_c93
    _c97 = _c93 - _c95 + _c96
    _c98 = _c22*m
    _c99 = _c24*_c98
    _c100 = _c31*_c98
    _c101 = _c20*_c83
    _c102 = _c101*_c31
    _c103 = _c56*_c83
    _c104 = _c103*_c24
    _c105 = _c103*_c69
    _c106 = _c101*_c69
    _c107 = _c14*_c22
    _c108 = _c107*_c24
    _c109 = 3*_c5
    _c110 = _c11*_c27
    _c111 = 3*c*h
    _c112 = _c28*_c99
    _c113 = _c100*_c28
    _c114 = _c72*_c98
    _c115 = _c114*_c75
    _c116 = _c101*_c75
    _c117 = _c116*_c73
    _c118 = _c116*_c94
    _c119 = _c103*_c79
    _c120 = _c114*_c79 - _c119*_c73 + _c119*_c94 - _c119
    ds[0] = _c0 - omega_y
    ds[1] = -_c1 + omega_x
    ds[2] = _c0*_c30 + _c1*_c34 + _c17*omega_y - _c21*omega_x + _c44*_c46 + _c48*(_c28*_c40 + _c33 - _c40 - _c47) + _c51*(I_xx*_c16 + _c41 + _c49 + _c50) + _c54*(I_yy*_c20 - I_zz*_c20 + _c20*_c4 + _c20*_c6 - _c20*_c9 + _c52 + _c53) + n_x*(-_c35*_c36 - _c39) + n_y*(_c15*_c19*c*g*m - _c32*_c37 - _c36*_c40)
    ds[3] = _c0*_c61 + _c1*_c58 + _c17*omega_x + _c44*_c48 + _c46*(-_c28*_c62 + _c62 + _c63) + _c51*(-I_xx*_c56 + I_zz*_c15*_c55 + 2*_c15*_c55*c*h*m - _c4*_c56 - _c52 - _c56*_c6 - _c63) + _c54*(-I_yy*_c16 + _c35 - _c42 - _c50 - _c64) - _c57*omega_y + n_x*(_c36*_c62 + _c37*_c59 - _c38*_c56) + n_y*(_c26*_c36 + _c39)
    ds[4] = _c0*n_x*(-_c13*_c27*_c70 + _c71*_c73 + _c71) + _c0*omega_x*(I_xx*_c15*_c22*_c24*_c27*_c55*h*m + _c10*_c11*_c15*_c22*_c24*_c27*_c55 + 3*_c10*_c15*_c22*_c24*_c55*c*h - _c104*_c109 - _c108*_c56 - _c112 - _c120 + _c15*_c2*_c22*_c24*_c27*h*m + _c22*_c24*m - _c52*_c99 - _c60*_c66 - _c63) + _c0*omega_y*(-_c108*_c16 - _c109*_c92 + _c110*_c92 + _c111*_c92 + _c112*_c64 - _c26*_c67 + _c26 + _c29*_c67 - _c29 - _c64*_c99 + _c97) + _c1*omega_x*(I_xx*I_xy*_c15*_c22*_c31*m + I_xy*_c10*_c15*_c22*_c3*_c31 + 3*I_xy*_c10*_c15*_c22*_c31*_c5 + I_xy*_c15*_c19*_c22*_c31*m - _c110*_c85 - _c111*_c85 - _c113*_c49 - _c42*_c66 - _c43 - _c97) + _c1*omega_y*(_c100*_c52 - _c100 + _c102*_c109 - _c102*_c110 - _c102*_c111 + _c107*_c20*_c31 - _c113*_c52 + _c113 + _c115 - _c116 - _c117 + _c118 + _c33*_c67 - _c47*_c67 + _c53) - _c23*omega_z + _c30*n_y*omega_x + _c34*n_x*omega_x + _c45*_c74*(2*I_xy*_c10*_c15*_c22*_c27*_c75*h - _c73*_c87 - _c87 + _c93 - _c95 + _c96) + _c45*_c78*(I_xy*_c10*_c15*_c22*_c5*_c72*_c79 + I_xy*_c10*_c15*_c22*_c79 - _c91*_c94 - _c97) + _c46*n_y*(_c105*_c73 - _c105*_c94 + _c105 - _c106*_c73 + _c106*_c94 - _c106 - _c115 + _c116 + _c117 - _c118 + _c120) + _c58*n_x*omega_y + _c61*n_y*omega_y - _c65*(omega_x*omega_x) + _c65*(omega_y*omega_y) + _c74*omega_z*(2*_c10*_c15*_c19*_c27*_c68*_c75*h*sigma - _c5*_c72*_c76*_c77 + _c68*_c72*_c75*m*sigma - _c76*_c77) + _c74*(-_c36*_c87 + _c82*_c85 - _c85*_c86 + _c85*_c89 + _c87*_c88) + _c78*omega_z*(2*_c10*_c15*_c27*_c55*_c68*_c79*h*sigma - _c5*_c72*_c80*_c81 + _c68*_c72*_c79*m*sigma - _c80*_c81) + _c78*(2*I_xy*_c10*_c15*_c22*_c24*g*h + I_xy*_c10*_c15*_c22*_c27*_c79*g - _c84*_c90 - _c88*_c91 - _c89*_c92) + n_x*n_y*(-_c100*_c36 + _c102*_c82 - _c102*_c86 + _c102*_c89 - _c103*_c90 + _c104*_c86 - _c104*_c89 + _c105*_c36 - _c105*_c88 - _c106*_c36 + _c106*_c88 + _c36*_c99) + omega_x*omega_y*(_c66 - _c67)


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 5."""
    ds = np.empty(5)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 35 parameter-only subexpressions of the right-hand side (511 operations)."""
    q = np.empty(46)
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
    sigma = p[10]
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
    q[10] = sigma
    _c0 = (a*a)
    _c1 = (I_xy*I_xy)
    _c2 = (c*c)
    _c3 = _c2*m
    _c4 = (h*h)
    _c5 = _c4*m
    _c6 = c*m
    _c7 = 2*h
    _c8 = _c6*_c7
    _c9 = (m*m)
    _c10 = (h*h*h)
    _c11 = 4*_c9
    _c12 = _c11*h
    _c13 = _c2*_c9
    _c14 = 1/(I_xx*I_yy + I_xx*_c3 + I_xx*_c5 - I_xx*_c8 + I_yy*_c3 + I_yy*_c5 - I_yy*_c8 - _c1 - _c10*_c11*c - _c12*(c*c*c) + 6*_c13*_c4 + _c9*(c*c*c*c) + _c9*(h*h*h*h))
    _c15 = I_xy*_c14
    _c16 = _c15*m
    _c17 = _c0*_c16
    _c18 = 1/c
    _c19 = _c18*g
    _c20 = g*h
    _c21 = _c6*g
    _c22 = -_c15*_c21 + _c16*_c20
    _c23 = _c3 + _c5 - _c8
    _c24 = I_yy + _c23
    _c25 = _c14*_c24
    _c26 = _c25*m
    _c27 = (b*b)
    _c28 = _c26*_c27
    _c29 = 1/I_zz
    _c30 = _c29*sigma
    _c31 = _c0*_c26
    _c32 = _c16*_c27
    _c33 = _c18*h
    _c34 = _c32*_c33
    _c35 = -_c32 + _c34
    _c36 = _c17*_c33
    _c37 = _c17 - _c36
    _c38 = I_xy*_c29
    _c39 = _c14*_c38
    _c40 = _c39*m*sigma
    _c41 = _c27*_c40
    _c42 = _c31*_c33
    _c43 = -I_zz*_c15 + _c15*_c3 + _c15*_c5 - _c15*_c8
    _c44 = _c1*_c14
    _c45 = -_c31 + _c42
    _c46 = _c15*sigma
    _c47 = _c25*sigma
    _c48 = I_xx + _c23
    _c49 = _c14*_c48
    _c50 = _c49*m
    _c51 = _c0*_c50
    _c52 = _c0*_c40
    _c53 = _c27*_c50
    _c54 = _c33*_c53
    _c55 = -_c53 + _c54
    _c56 = _c49*sigma
    _c57 = c*g
    _c58 = _c0*_c39
    _c59 = _c58*_c9
    _c60 = _c7*g
    _c61 = (a*a*a*a)
    _c62 = _c61*_c9
    _c63 = _c39*_c62
    _c64 = 1/_c2
    _c65 = _c20*_c64
    _c66 = _c19*_c4
    _c67 = _c27*_c9
    _c68 = _c57*_c67
    _c69 = (b*b*b*b)
    _c70 = _c69*_c9
    _c71 = _c39*_c70
    _c72 = _c39*_c67
    _c73 = _c29*m
    _c74 = _c27*_c73
    _c75 = _c0*_c73
    _c76 = _c25*_c29
    _c77 = _c0*_c76
    _c78 = _c77*_c9
    _c79 = _c29*_c49
    _c80 = _c67*_c79
    _c81 = _c0*_c67
    _c82 = _c79*_c81
    _c83 = _c76*_c81
    _c84 = I_xx*_c29
    _c85 = I_yy*_c29
    _c86 = (1.0/(I_zz*I_zz))
    _c87 = _c61*_c86
    _c88 = _c47*_c9
    _c89 = _c69*_c86
    _c90 = _c56*_c9
    _c91 = _c58*_c67
    _c92 = _c4*_c64
    _c93 = _c18*_c7
    _c94 = _c91*_c93
    _c95 = _c91*_c92
    _c96 = _c91 - _c94 + _c95
    _c97 = _c46*_c86
    _c98 = 2*_c81*_c97
    _c99 = _c64*_c73
    _c100 = _c61*_c99
    _c101 = _c62*_c76
    _c102 = _c101*_c92
    _c103 = _c101*_c93
    _c104 = _c70*_c79
    _c105 = -_c104*_c92 + _c104*_c93 - _c104 + _c69*_c99
    _c106 = _c10*_c18
    _c107 = 3*c*h
    _c108 = _c33*_c75
    _c109 = 3*_c4
    _c110 = _c13*_c27
    _c111 = I_yy*_c27*_c39*m
    q[11] = -_c17*_c19 - _c22
    q[12] = _c14*_c24*c*g*m - _c19*_c28 - _c20*_c26
    q[13] = _c0*_c14*_c18*_c24*_c29*h*m*sigma - _c30*_c31
    q[14] = -_c35 - _c37
    q[15] = -_c33*_c41 + _c41
    q[16] = _c28*_c33 - _c28 + _c31 - _c42
    q[17] = I_xx*_c15 + _c15*_c24 + _c35 + _c43
    q[18] = I_yy*_c25 - I_zz*_c25 + _c25*_c3 + _c25*_c5 - _c25*_c8 + _c44 + _c45
    q[19] = _c46
    q[20] = -_c47
    q[21] = _c19*_c51 + _c20*_c50 - _c21*_c49
    q[22] = _c19*_c32 + _c22
    q[23] = -_c33*_c52 + _c52
    q[24] = -_c33*_c51 + _c51 + _c55
    q[25] = _c14*_c18*_c27*_c29*_c48*h*m*sigma - _c30*_c53
    q[26] = -I_xx*_c49 + I_zz*_c14*_c48 + 2*_c14*_c48*c*h*m - _c3*_c49 - _c44 - _c49*_c5 - _c55
    q[27] = -I_yy*_c15 - _c15*_c48 + _c17 - _c36 - _c43
    q[28] = -_c56
    q[29] = -_c19*_c63 + _c57*_c59 - _c59*_c60 + _c59*_c66 + _c63*_c65
    q[30] = I_xy*_c14*_c18*_c29*_c69*_c9*g + 2*I_xy*_c14*_c27*_c29*_c9*g*h - _c39*_c68 - _c65*_c71 - _c66*_c72
    q[31] = _c38
    q[32] = _c19*_c74 - _c19*_c75 + _c19*_c82 - _c19*_c83 + _c57*_c78 - _c60*_c78 + _c60*_c80 - _c65*_c82 + _c65*_c83 + _c66*_c78 - _c66*_c80 - _c68*_c79
    q[33] = _c84 - _c85
    q[34] = 2*_c14*_c18*_c24*_c61*_c86*_c9*h*sigma - _c4*_c64*_c87*_c88 + _c61*_c64*_c86*m*sigma - _c87*_c88
    q[35] = 2*_c14*_c18*_c48*_c69*_c86*_c9*h*sigma - _c4*_c64*_c89*_c90 + _c64*_c69*_c86*m*sigma - _c89*_c90
    q[36] = 2*I_xy*_c14*_c18*_c29*_c61*_c9*h - _c63*_c92 - _c63 + _c91 - _c94 + _c95
    q[37] = I_xy*_c14*_c29*_c4*_c64*_c69*_c9 + I_xy*_c14*_c29*_c69*_c9 - _c71*_c93 - _c96
    q[38] = -_c38
    q[39] = -_c30
    q[40] = -_c0*_c12*_c18*_c27*_c97 + _c92*_c98 + _c98
    q[41] = -_c100 + _c101 + _c102 - _c103 + _c105 + _c82*_c92 - _c82*_c93 + _c82 - _c83*_c92 + _c83*_c93 - _c83
    q[42] = I_xx*I_xy*_c0*_c14*_c29*m - I_xx*_c33*_c58*m + I_xy*_c0*_c14*_c2*_c29*_c9 + I_xy*_c0*_c14*_c24*_c29*m + 3*I_xy*_c0*_c14*_c29*_c4*_c9 - _c106*_c59 - _c107*_c59 - _c37 - _c38*_c42 - _c96
    q[43] = _c100 - _c101 - _c102 + _c103 - _c106*_c78 - _c107*_c78 - _c108*_c44 + _c108 + _c109*_c78 + _c13*_c77 + _c31*_c85 - _c42*_c85 + _c44*_c75 + _c45 - _c75
    q[44] = I_xx*_c14*_c18*_c27*_c29*_c48*h*m + _c1*_c14*_c18*_c27*_c29*h*m + _c10*_c14*_c18*_c27*_c29*_c48*_c9 - _c105 - _c109*_c80 - _c110*_c79 + 3*_c14*_c27*_c29*_c48*_c9*c*h + _c27*_c29*m - _c33*_c74 - _c44*_c74 - _c53*_c84 - _c55
    q[45] = _c106*_c72 + _c107*_c72 - _c109*_c72 - _c110*_c39 + _c111*_c33 - _c111 + _c32 - _c34 - _c38*_c53 + _c38*_c54 + _c96
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (108 operations)."""
    n_x = s[0]
    n_y = s[1]
    omega_x = s[2]
    omega_y = s[3]
    omega_z = s[4]
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
    sigma = q[10]
    _k0 = q[11]
    _k1 = q[12]
    _k2 = q[13]
    _k3 = q[14]
    _k4 = q[15]
    _k5 = q[16]
    _k6 = q[17]
    _k7 = q[18]
    _k8 = q[19]
    _k9 = q[20]
    _k10 = q[21]
    _k11 = q[22]
    _k12 = q[23]
    _k13 = q[24]
    _k14 = q[25]
    _k15 = q[26]
    _k16 = q[27]
    _k17 = q[28]
    _k18 = q[29]
    _k19 = q[30]
    _k20 = q[31]
    _k21 = q[32]
    _k22 = q[33]
    _k23 = q[34]
    _k24 = q[35]
    _k25 = q[36]
    _k26 = q[37]
    _k27 = q[38]
    _k28 = q[39]
    _k29 = q[40]
    _k30 = q[41]
    _k31 = q[42]
    _k32 = q[43]
    _k33 = q[44]
    _k34 = q[45]
    _c0 = n_y*omega_z
    _c1 = n_x*omega_z
    _c2 = omega_x*omega_z
    _c3 = omega_y*omega_z
    _c4 = (omega_z*omega_z)
    _c5 = _c4*n_x
    _c6 = _c4*n_y
    _c7 = (n_x*n_x)
    _c8 = (n_y*n_y)
    ds[0] = _c0 - omega_y
    ds[1] = -_c1 + omega_x
    ds[2] = _c0*_k4 + _c1*_k2 + _c2*_k6 + _c3*_k7 + _c5*_k3 + _c6*_k5 + _k0*n_x + _k1*n_y + _k8*omega_y + _k9*omega_x
    ds[3] = _c0*_k14 + _c1*_k12 + _c2*_k15 + _c3*_k16 + _c5*_k13 + _c6*_k3 + _k10*n_x + _k11*n_y + _k17*omega_y + _k8*omega_x
    ds[4] = _c0*_k29*n_x + _c0*_k33*omega_x + _c0*_k34*omega_y + _c1*_k31*omega_x + _c1*_k32*omega_y + _c4*_c7*_k25 + _c4*_c8*_k26 + _c5*_k30*n_y + _c7*_k18 + _c7*_k23*omega_z + _c8*_k19 + _c8*_k24*omega_z + _k12*n_x*omega_y + _k14*n_y*omega_y + _k2*n_x*omega_x + _k20*(omega_y*omega_y) + _k21*n_x*n_y + _k22*omega_x*omega_y + _k27*(omega_x*omega_x) + _k28*omega_z + _k4*n_y*omega_x


@njit(cache=True)
def energy(s, p):
    """Mechanical energy to the order of this fidelity (85 operations)."""
    n_x = s[0]
    n_y = s[1]
    omega_x = s[2]
    omega_y = s[3]
    omega_z = s[4]
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
    sigma = p[10]
    _c0 = g*m
    _c1 = _c0*c
    _c2 = _c0*h
    _c3 = (omega_x*omega_x)
    _c4 = ((1.0/2.0))*_c3
    _c5 = (omega_y*omega_y)
    _c6 = ((1.0/2.0))*_c5
    _c7 = ((1.0/2.0))*(omega_z*omega_z)
    _c8 = (n_x*n_x)
    _c9 = ((1.0/2.0))*_c1
    _c10 = (n_y*n_y)
    _c11 = h*m
    _c12 = _c11*c
    _c13 = ((1.0/2.0))*_c2
    _c14 = (c*c)
    _c15 = _c4*m
    _c16 = _c6*m
    _c17 = (h*h)
    _c18 = m*omega_z
    _c19 = (a*a)
    _c20 = _c19*n_x*omega_x
    _c21 = (b*b)
    _c22 = _c21*n_y*omega_y
    _c23 = 1/c
    _c24 = _c11*_c23*omega_z
    _c25 = ((1.0/2.0))*_c0*_c23
    _c26 = _c7*m/_c14
    energy = I_xx*_c4 + I_xy*omega_x*omega_y + I_yy*_c6 + I_zz*_c7 + _c1 + _c10*_c13 + _c10*_c21*_c25 + _c10*_c26*(b*b*b*b) - _c10*_c9 - _c12*_c3 - _c12*_c5 + _c13*_c8 + _c14*_c15 + _c14*_c16 + _c15*_c17 + _c16*_c17 - _c18*_c20 - _c18*_c22 + _c19*_c25*_c8 - _c2 + _c20*_c24 + _c22*_c24 + _c26*_c8*(a*a*a*a) - _c8*_c9
    return energy


@njit(cache=True)
def power_dissipated(s, p):
    """Power removed by the damping torque, to the order of this fidelity (6 operations)."""
    n_x = s[0]
    n_y = s[1]
    omega_x = s[2]
    omega_y = s[3]
    omega_z = s[4]
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
    sigma = p[10]
    power = sigma*((omega_x*omega_x) + (omega_y*omega_y) + (omega_z*omega_z))
    return power


@njit(cache=True)
def multipliers(s, p):
    """No multipliers at this fidelity (the contact force is not kept)."""
    return np.empty(0)


def initial_state(n0=(0.0, 0.0, 1.0), omega0=(0.0, 0.0, 0.0)):
    """State ``(n_x, n_y, omega_x, omega_y, omega_z)`` from the physical description.

    ``n0``: upward vertical in body axes (normalized here; ``n_z`` is not a state of this fidelity);
    ``omega0``: angular velocity in body axes [rad/s].
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
    return np.array([n0[0], n0[1], omega0[0], omega0[1], omega0[2]])


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
    sigma = p[10]
    _c0 = 7.61465737367355e-5*(a*a)
    _c1 = 7.61518095472372e-5*(b*b)
    _c2 = 0.999847701616716*(c*c)
    _c3 = 1/math.sqrt(_c0 + _c1 + _c2)
    out[0] = m
    out[1] = g
    out[2] = sigma
    out[3] = I_xx
    out[4] = I_xy
    out[5] = 0
    out[6] = I_xy
    out[7] = I_yy
    out[8] = 0
    out[9] = 0
    out[10] = 0
    out[11] = I_zz
    out[12] = _c0*_c3 + _c1*_c3 + _c2*_c3 - 0.999923847908788*h
    return (out[0], out[1], out[2], (out[3:6], out[6:9], out[9:12]), out[12])
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '1163d3ac3cbbde58b4112a469407b4c91a25ebbec5e96ff666671d3a3fa44fb7'
