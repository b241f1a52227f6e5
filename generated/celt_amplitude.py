"""celt, fidelity amplitude: first-order average over the two rocking modes (pitch, roll) of the reduced equations: tilt amplitudes of the normal modes and the spin (derivation/rigid_small.py).

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/rigid_small_emit.py (make derive) from the rigid body 'celt'
through derivation/rigid.py and derivation/rigid_small.py.
SymPy 1.14.0; input hash sha256:a197a23b0ac802bbf9bdf23fb00c13614a9708fb3d3171c5d138bd534ca64f83

Classical rattleback (celt): a rigid body with an ellipsoidal bottom (semi-axes a, b, c along the body axes x, y, z; centre of mass a distance h below the ellipsoid's centre), inertia tensor about the centre of mass with entries I_xx..I_yz in body axes, rolling without slipping on a horizontal table under gravity g, dissipation torque -sigma*omega.  State: upward vertical n and angular velocity omega in body axes, vertical spin omega_n = omega.n; pose: heading psi of the body x axis, centre of mass (x, y).

Parameters set to zero at this fidelity (the upright spin must be an equilibrium): I_xz, I_yz.

State vector ``s``:
    s[0] = A_pitch      [rad]
    s[1] = A_roll       [rad]
    s[2] = omega_z      [rad/s]
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
FIDELITY = 'amplitude'
#: what this fidelity is
FIDELITY_DOC = 'first-order average over the two rocking modes (pitch, roll) of the reduced equations: tilt amplitudes of the normal modes and the spin (derivation/rigid_small.py)'
STATE_NAMES = ('A_pitch', 'A_roll', 'omega_z')
STATE_UNITS = ('rad', 'rad', 'rad/s')
POSE_NAMES = ()
POSE_UNITS = ()
POSE_DOC = ''
PARAM_NAMES = ('a', 'b', 'c', 'h', 'm', 'g', 'I_xx', 'I_yy', 'I_zz', 'I_xy', 'sigma')
PARAM_UNITS = ('m', 'm', 'm', 'm', 'kg', 'm/s^2', 'kg m^2', 'kg m^2', 'kg m^2', 'kg m^2', 'N m s')
#: admissible values of each parameter: 'positive' (> 0), 'nonnegative' (>= 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'positive', 'real', 'nonnegative')
DEFAULT_PARAMS = {'a': 0.2, 'b': 0.03, 'c': 0.02, 'h': 0.01, 'm': 1.0, 'g': 9.81, 'I_xx': 0.0002, 'I_yy': 0.0016, 'I_zz': 0.0017, 'I_xy': 2e-05, 'sigma': 0.0}
DEFAULT_STATE = {'A_pitch': 0.00010039478659855185, 'A_roll': 9.258939059585094e-05, 'omega_z': 0.2}
RATE_PAIRS = ()
TILT_NAMES = ('A_pitch', 'A_roll')
#: the vertical spin (omega_z: omega . n to second order in the tilts), whose zero crossings are the reversals
REVERSAL_EVENTS = ('omega_z',)
EVENT_NAMES = ()
#: largest |value| of each named state where this fidelity holds
VALIDITY = {'A_pitch': 0.003, 'A_roll': 0.03}
VALIDITY_DOC = 'small tilt amplitudes (the bounds of the reduced fidelity), non-resonant rocking modes, and a spin slow against the rocking frequencies (first-order averaging)'
MULTIPLIER_NAMES = ()
HAS_DISSIPATION = True
EXPORTS = ('PRESETS', 'PRESET_SOURCES', 'initial_state', 'modes', 'moffatt_tokieda')
PRESETS = {'kane_levinson_1982': {'a': 0.2, 'b': 0.03, 'c': 0.02, 'h': 0.01, 'm': 1.0, 'g': 9.81, 'I_xx': 0.0002, 'I_yy': 0.0016, 'I_zz': 0.0017, 'I_xy': 2e-05, 'sigma': 0.0}, 'schoemer': {'a': 1.618033988749895, 'b': 1.0, 'c': 1.0, 'h': 0.1875, 'm': 0.2, 'g': 9.81, 'I_xx': 0.05796875, 'I_yy': 0.09032943, 'I_zz': 0.12236068, 'I_xy': -0.025, 'sigma': 0.0}}
PRESET_SOURCES = {'kane_levinson_1982': 'Kane & Levinson, Int. J. Non-Linear Mech. 17 (1982) 175-186', 'schoemer': "E. Schoemer's rattleback (golden-ratio ellipsoid)"}
SOURCE = 'knifeedge.derive.celt'
INPUT_HASH = 'a197a23b0ac802bbf9bdf23fb00c13614a9708fb3d3171c5d138bd534ca64f83'
SYMPY_VERSION = '1.14.0'
OP_COUNTS = {'rhs': 688, 'constants': 669, 'rhs_q': 22, 'energy': 208, 'power_dissipated': 780, 'modes': 133, 'moffatt_tokieda': 351}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (688 operations)."""
    A_pitch = s[0]
    A_roll = s[1]
    omega_z = s[2]
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
    _c0 = (I_xy*I_xy)
    _c1 = (c*c)
    _c2 = _c1*m
    _c3 = (h*h)
    _c4 = _c3*m
    _c5 = h*m
    _c6 = 2*_c5*c
    _c7 = (m*m)
    _c8 = (h*h*h)
    _c9 = 4*_c7
    _c10 = _c9*h
    _c11 = _c1*_c7
    _c12 = 1/(I_xx*I_yy + I_xx*_c2 + I_xx*_c4 - I_xx*_c6 + I_yy*_c2 + I_yy*_c4 - I_yy*_c6 - _c0 - _c10*(c*c*c) + 6*_c11*_c3 + _c7*(c*c*c*c) + _c7*(h*h*h*h) - _c8*_c9*c)
    _c13 = I_xy*_c12
    _c14 = (b*b)
    _c15 = _c14*m
    _c16 = _c13*_c15
    _c17 = 1/c
    _c18 = _c17*g
    _c19 = _c16*_c18
    _c20 = _c13*g
    _c21 = _c20*_c5
    _c22 = c*m
    _c23 = _c20*_c22
    _c24 = _c21 - _c23
    _c25 = _c19 + _c24
    _c26 = (a*a)
    _c27 = _c26*m
    _c28 = _c13*_c27
    _c29 = _c18*_c28 + _c24
    _c30 = (_c29*_c29)
    _c31 = _c2 + _c4 - _c6
    _c32 = I_yy + _c31
    _c33 = _c12*_c32
    _c34 = _c22*g
    _c35 = _c33*_c34
    _c36 = ((1.0/2.0))*_c35
    _c37 = _c5*g
    _c38 = _c33*_c37
    _c39 = ((1.0/2.0))*_c38
    _c40 = _c15*_c18*_c33
    _c41 = ((1.0/2.0))*_c40
    _c42 = I_xx + _c31
    _c43 = _c12*_c42
    _c44 = _c37*_c43
    _c45 = _c34*_c43
    _c46 = _c18*_c27*_c43
    _c47 = ((1.0/2.0))*math.sqrt(_c29*(4*_c19 + 4*_c21 - 4*_c23) + ((_c35 - _c38 - _c40 + _c44 - _c45 + _c46)*(_c35 - _c38 - _c40 + _c44 - _c45 + _c46)))
    _c48 = ((1.0/2.0))*_c44 - (1.0/2.0)*_c45 + ((1.0/2.0))*_c46
    _c49 = _c47 + _c48
    _c50 = _c36 - _c39 - _c41 + _c49
    _c51 = (_c50*_c50)
    _c52 = _c30 + _c51
    _c53 = 1/math.sqrt(_c52)
    _c54 = _c25*_c29
    _c55 = 1/(_c51*_c53 + _c53*_c54)
    _c56 = _c25*_c55
    _c57 = _c50*_c55
    _c58 = ((1.0/2.0))*_c53
    _c59 = _c29*_c58
    _c60 = _c50*_c58
    _c61 = _c17*_c5
    _c62 = _c13*_c14
    _c63 = _c61*_c62
    _c64 = -I_zz*_c13 + _c13*_c2 + _c13*_c4 - _c13*_c6
    _c65 = -I_xx*_c13 + I_xy*_c12*_c14*m - _c13*_c32 - _c63 - _c64
    _c66 = _c0*_c12
    _c67 = _c66 + 1
    _c68 = _c14*_c43
    _c69 = _c61*_c68
    _c70 = -_c12*_c14*_c42*m + _c69
    _c71 = -I_xx*_c43 + I_zz*_c12*_c42 + 2*_c12*_c42*c*h*m - _c2*_c43 - _c4*_c43 - _c67 - _c70
    _c72 = _c27*_c33
    _c73 = _c26*_c61
    _c74 = _c33*_c73
    _c75 = I_yy*_c33 - I_zz*_c33 + _c2*_c33 + _c33*_c4 - _c33*_c6 + _c67 - _c72 + _c74
    _c76 = I_yy*_c13 + _c13*_c42 + _c13*_c73 - _c28 + _c64
    _c77 = (_c25*_c25)
    _c78 = -_c50
    _c79 = (_c78*_c78)
    _c80 = _c77 + _c79
    _c81 = 1/math.sqrt(_c80)
    _c82 = 1/(_c54*_c81 + _c79*_c81)
    _c83 = _c29*_c82
    _c84 = _c78*_c82
    _c85 = ((1.0/2.0))*_c81
    _c86 = _c25*_c85
    _c87 = _c78*_c85
    _c88 = 1/I_zz
    _c89 = omega_z*sigma
    _c90 = I_xy*_c88
    _c91 = _c12*_c90
    _c92 = _c7*_c91
    _c93 = _c14*_c92
    _c94 = c*g
    _c95 = (b*b*b*b)
    _c96 = _c92*_c95
    _c97 = 1/_c1
    _c98 = _c97*g*h
    _c99 = _c18*_c3
    _c100 = 2*I_xy*_c12*_c14*_c7*_c88*g*h + I_xy*_c12*_c17*_c7*_c88*_c95*g - _c93*_c94 - _c93*_c99 - _c96*_c98
    _c101 = ((1.0/2.0))/_c52
    _c102 = _c101*_c30
    _c103 = -_c36 + _c39 + _c41
    _c104 = _c103 + _c49
    _c105 = _c104*_c90
    _c106 = _c26*_c92
    _c107 = 2*g*h
    _c108 = (a*a*a*a)
    _c109 = _c108*_c92
    _c110 = -_c106*_c107 + _c106*_c94 + _c106*_c99 - _c109*_c18 + _c109*_c98
    _c111 = _c101*_c51
    _c112 = _c88*m
    _c113 = _c112*_c14
    _c114 = _c112*_c26
    _c115 = _c33*_c7
    _c116 = _c26*_c88
    _c117 = _c115*_c116
    _c118 = _c43*_c7
    _c119 = _c118*_c14*_c88
    _c120 = _c116*_c14
    _c121 = _c118*_c120
    _c122 = _c115*_c120
    _c123 = -_c107*_c117 + _c107*_c119 + _c113*_c18 - _c114*_c18 + _c117*_c94 + _c117*_c99 - _c119*_c94 - _c119*_c99 + _c121*_c18 - _c121*_c98 - _c122*_c18 + _c122*_c98
    _c124 = _c101*_c29*_c50
    _c125 = I_xx*_c88
    _c126 = I_yy*_c88
    _c127 = -_c125 + _c126
    _c128 = (1.0/(I_zz*I_zz))
    _c129 = _c118*_c128*_c95
    _c130 = _c3*_c97
    _c131 = -_c113*_c43 + 2*_c12*_c128*_c17*_c42*_c7*_c95*h + _c12*_c14*_c17*_c42*_c88*h*m + _c128*_c95*_c97*m - _c129*_c130 - _c129
    _c132 = _c108*_c115*_c128
    _c133 = 2*_c108*_c12*_c128*_c17*_c32*_c7*h + _c108*_c128*_c97*m - _c114*_c33 + _c12*_c17*_c26*_c32*_c88*h*m - _c130*_c132 - _c132
    _c134 = _c15*_c91
    _c135 = _c73*_c91
    _c136 = _c14*_c61*_c91
    _c137 = _c128*_c26*_c62
    _c138 = 2*_c137*_c7
    _c139 = -_c10*_c137*_c17 + _c130*_c138 + _c134 - _c135 - _c136 + _c138 + _c27*_c91
    _c140 = (omega_z*omega_z)
    _c141 = 3*c
    _c142 = 3*_c3
    _c143 = _c17*h
    _c144 = 2*_c143
    _c145 = _c17*_c8
    _c146 = _c15*_c43
    _c147 = -I_yy*_c134 + I_yy*_c136 - _c11*_c14*_c91 + _c130*_c96 + _c141*_c93*h - _c142*_c93 - _c144*_c96 + _c145*_c93 - _c146*_c90 + _c16 - _c63 + _c69*_c90 + _c90 + _c96
    _c148 = _c141*h
    _c149 = I_xx*I_xy*_c12*_c26*_c88*m - I_xx*_c135 + I_xy*_c1*_c12*_c26*_c7*_c88 + 2*I_xy*_c108*_c12*_c17*_c7*_c88*h + I_xy*_c12*_c17*_c26*h*m + 3*I_xy*_c12*_c26*_c3*_c7*_c88 + I_xy*_c12*_c26*_c32*_c88*m - _c106*_c145 - _c106*_c148 - _c109*_c130 - _c109 - _c28 - _c74*_c90 - _c90
    _c150 = I_xx*_c12*_c14*_c17*_c42*_c88*h*m + I_yy*_c12*_c26*_c32*_c88*m + _c0*_c12*_c14*_c17*_c88*h*m + _c0*_c12*_c26*_c88*m + _c1*_c12*_c26*_c32*_c7*_c88 - _c11*_c68*_c88 - _c113*_c143 - _c113*_c66 - _c114*_c143*_c66 - _c114 - _c117*_c145 - _c117*_c148 - _c119*_c142 + 2*_c12*_c14*_c17*_c26*_c32*_c7*_c88*h + _c12*_c14*_c17*_c42*_c7*_c8*_c88 + _c12*_c14*_c26*_c3*_c42*_c7*_c88*_c97 + _c12*_c14*_c26*_c42*_c7*_c88 + 3*_c12*_c14*_c42*_c7*_c88*c*h + _c12*_c17*_c26*_c32*h*m + 3*_c12*_c26*_c3*_c32*_c7*_c88 - _c121*_c144 - _c122*_c130 - _c122 - _c125*_c146 + _c125 - _c126*_c74 - _c126 + _c14*_c88*m + _c17*_c26*_c88*h*m - _c70 - _c72
    _c151 = ((1.0/2.0))/_c80
    _c152 = _c151*_c77
    _c153 = _c103 - _c47 + _c48
    _c154 = _c153*_c90
    _c155 = _c151*_c79
    _c156 = _c151*_c25*_c78
    ds[0] = A_pitch*(omega_z*(-_c59*(_c56*_c65 + _c57*_c71) - _c60*(_c56*_c75 + _c57*_c76)) + sigma*(-_c59*(_c13*_c57 + _c33*_c56) - _c60*(_c13*_c56 + _c43*_c57)))
    ds[1] = A_roll*(omega_z*(-_c86*(_c75*_c84 + _c76*_c83) - _c87*(_c65*_c84 + _c71*_c83)) + sigma*(-_c86*(_c13*_c84 + _c43*_c83) - _c87*(_c13*_c83 + _c33*_c84)))
    ds[2] = (A_pitch*A_pitch)*(_c100*_c102 - _c102*_c105 + _c104*_c124*_c127 + _c105*_c111 + _c110*_c111 + _c123*_c124 + _c140*(_c102*_c147 + _c111*_c149 + _c124*_c150) + _c89*(_c102*_c131 + _c111*_c133 + _c124*_c139)) + (A_roll*A_roll)*(_c100*_c155 + _c110*_c152 + _c123*_c156 + _c127*_c153*_c156 + _c140*(_c147*_c155 + _c149*_c152 + _c150*_c156) + _c152*_c154 - _c154*_c155 + _c89*(_c131*_c155 + _c133*_c152 + _c139*_c156)) - _c88*_c89


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 3."""
    ds = np.empty(3)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 11 parameter-only subexpressions of the right-hand side (669 operations)."""
    q = np.empty(22)
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
    _c0 = (I_xy*I_xy)
    _c1 = (c*c)
    _c2 = _c1*m
    _c3 = (h*h)
    _c4 = _c3*m
    _c5 = h*m
    _c6 = 2*_c5*c
    _c7 = (m*m)
    _c8 = (h*h*h)
    _c9 = 4*_c7
    _c10 = _c9*h
    _c11 = _c1*_c7
    _c12 = 1/(I_xx*I_yy + I_xx*_c2 + I_xx*_c4 - I_xx*_c6 + I_yy*_c2 + I_yy*_c4 - I_yy*_c6 - _c0 - _c10*(c*c*c) + 6*_c11*_c3 + _c7*(c*c*c*c) + _c7*(h*h*h*h) - _c8*_c9*c)
    _c13 = I_xy*_c12
    _c14 = _c2 + _c4 - _c6
    _c15 = I_yy + _c14
    _c16 = (b*b)
    _c17 = 1/c
    _c18 = _c17*_c5
    _c19 = _c13*_c16
    _c20 = _c18*_c19
    _c21 = -I_zz*_c13 + _c13*_c2 + _c13*_c4 - _c13*_c6
    _c22 = -I_xx*_c13 + I_xy*_c12*_c16*m - _c13*_c15 - _c20 - _c21
    _c23 = _c16*m
    _c24 = _c13*_c23
    _c25 = _c17*g
    _c26 = _c24*_c25
    _c27 = _c13*g
    _c28 = _c27*_c5
    _c29 = c*m
    _c30 = _c27*_c29
    _c31 = _c28 - _c30
    _c32 = _c26 + _c31
    _c33 = (a*a)
    _c34 = _c33*m
    _c35 = _c13*_c34
    _c36 = _c25*_c35 + _c31
    _c37 = (_c36*_c36)
    _c38 = _c12*_c15
    _c39 = _c29*g
    _c40 = _c38*_c39
    _c41 = ((1.0/2.0))*_c40
    _c42 = _c5*g
    _c43 = _c38*_c42
    _c44 = ((1.0/2.0))*_c43
    _c45 = _c23*_c25*_c38
    _c46 = ((1.0/2.0))*_c45
    _c47 = I_xx + _c14
    _c48 = _c12*_c47
    _c49 = _c42*_c48
    _c50 = _c39*_c48
    _c51 = _c25*_c34*_c48
    _c52 = ((1.0/2.0))*math.sqrt(_c36*(4*_c26 + 4*_c28 - 4*_c30) + ((_c40 - _c43 - _c45 + _c49 - _c50 + _c51)*(_c40 - _c43 - _c45 + _c49 - _c50 + _c51)))
    _c53 = ((1.0/2.0))*_c49 - (1.0/2.0)*_c50 + ((1.0/2.0))*_c51
    _c54 = _c52 + _c53
    _c55 = _c41 - _c44 - _c46 + _c54
    _c56 = (_c55*_c55)
    _c57 = _c37 + _c56
    _c58 = 1/math.sqrt(_c57)
    _c59 = _c32*_c36
    _c60 = 1/(_c56*_c58 + _c58*_c59)
    _c61 = _c32*_c60
    _c62 = _c0*_c12
    _c63 = _c62 + 1
    _c64 = _c16*_c48
    _c65 = _c18*_c64
    _c66 = -_c12*_c16*_c47*m + _c65
    _c67 = -I_xx*_c48 + I_zz*_c12*_c47 + 2*_c12*_c47*c*h*m - _c2*_c48 - _c4*_c48 - _c63 - _c66
    _c68 = _c55*_c60
    _c69 = ((1.0/2.0))*_c58
    _c70 = _c36*_c69
    _c71 = _c34*_c38
    _c72 = _c18*_c33
    _c73 = _c38*_c72
    _c74 = I_yy*_c38 - I_zz*_c38 + _c2*_c38 + _c38*_c4 - _c38*_c6 + _c63 - _c71 + _c73
    _c75 = I_yy*_c13 + _c13*_c47 + _c13*_c72 + _c21 - _c35
    _c76 = _c55*_c69
    _c77 = (_c32*_c32)
    _c78 = -_c55
    _c79 = (_c78*_c78)
    _c80 = _c77 + _c79
    _c81 = 1/math.sqrt(_c80)
    _c82 = 1/(_c59*_c81 + _c79*_c81)
    _c83 = _c36*_c82
    _c84 = _c78*_c82
    _c85 = ((1.0/2.0))*_c81
    _c86 = _c32*_c85
    _c87 = _c78*_c85
    _c88 = 1/I_zz
    _c89 = I_xy*_c88
    _c90 = (b*b*b*b)
    _c91 = _c12*_c89
    _c92 = _c7*_c91
    _c93 = _c90*_c92
    _c94 = _c23*_c91
    _c95 = _c16*_c92
    _c96 = 3*c
    _c97 = _c16*_c18*_c91
    _c98 = 3*_c3
    _c99 = _c17*h
    _c100 = 2*_c99
    _c101 = _c17*_c8
    _c102 = 1/_c1
    _c103 = _c102*_c3
    _c104 = _c23*_c48
    _c105 = -I_yy*_c94 + I_yy*_c97 - _c100*_c93 + _c101*_c95 + _c103*_c93 - _c104*_c89 - _c11*_c16*_c91 - _c20 + _c24 + _c65*_c89 + _c89 + _c93 + _c95*_c96*h - _c95*_c98
    _c106 = ((1.0/2.0))/_c57
    _c107 = _c106*_c37
    _c108 = (a*a*a*a)
    _c109 = _c108*_c92
    _c110 = _c33*_c92
    _c111 = _c96*h
    _c112 = _c72*_c91
    _c113 = I_xx*I_xy*_c12*_c33*_c88*m - I_xx*_c112 + I_xy*_c1*_c12*_c33*_c7*_c88 + 2*I_xy*_c108*_c12*_c17*_c7*_c88*h + I_xy*_c12*_c15*_c33*_c88*m + I_xy*_c12*_c17*_c33*h*m + 3*I_xy*_c12*_c3*_c33*_c7*_c88 - _c101*_c110 - _c103*_c109 - _c109 - _c110*_c111 - _c35 - _c73*_c89 - _c89
    _c114 = _c106*_c56
    _c115 = I_yy*_c88
    _c116 = I_xx*_c88
    _c117 = _c88*m
    _c118 = _c117*_c33
    _c119 = _c117*_c16
    _c120 = _c38*_c7
    _c121 = _c33*_c88
    _c122 = _c121*_c16
    _c123 = _c120*_c122
    _c124 = _c48*_c7
    _c125 = _c124*_c16*_c88
    _c126 = _c120*_c121
    _c127 = _c122*_c124
    _c128 = I_xx*_c12*_c16*_c17*_c47*_c88*h*m + I_yy*_c12*_c15*_c33*_c88*m + _c0*_c12*_c16*_c17*_c88*h*m + _c0*_c12*_c33*_c88*m + _c1*_c12*_c15*_c33*_c7*_c88 - _c100*_c127 - _c101*_c126 + _c102*_c12*_c16*_c3*_c33*_c47*_c7*_c88 - _c103*_c123 - _c104*_c116 - _c11*_c64*_c88 - _c111*_c126 - _c115*_c73 - _c115 + _c116 - _c118*_c62*_c99 - _c118 - _c119*_c62 - _c119*_c99 + 2*_c12*_c15*_c16*_c17*_c33*_c7*_c88*h + _c12*_c15*_c17*_c33*h*m + 3*_c12*_c15*_c3*_c33*_c7*_c88 + _c12*_c16*_c17*_c47*_c7*_c8*_c88 + _c12*_c16*_c33*_c47*_c7*_c88 + 3*_c12*_c16*_c47*_c7*_c88*c*h - _c123 - _c125*_c98 + _c16*_c88*m + _c17*_c33*_c88*h*m - _c66 - _c71
    _c129 = _c106*_c36*_c55
    _c130 = (1.0/(I_zz*I_zz))
    _c131 = _c124*_c130*_c90
    _c132 = _c102*_c130*_c90*m - _c103*_c131 - _c119*_c48 + 2*_c12*_c130*_c17*_c47*_c7*_c90*h + _c12*_c16*_c17*_c47*_c88*h*m - _c131
    _c133 = _c108*_c120*_c130
    _c134 = _c102*_c108*_c130*m - _c103*_c133 + 2*_c108*_c12*_c130*_c15*_c17*_c7*h - _c118*_c38 + _c12*_c15*_c17*_c33*_c88*h*m - _c133
    _c135 = _c130*_c19*_c33
    _c136 = 2*_c135*_c7
    _c137 = -_c10*_c135*_c17 + _c103*_c136 - _c112 + _c136 + _c34*_c91 + _c94 - _c97
    _c138 = c*g
    _c139 = _c102*g*h
    _c140 = _c25*_c3
    _c141 = 2*I_xy*_c12*_c16*_c7*_c88*g*h + I_xy*_c12*_c17*_c7*_c88*_c90*g - _c138*_c95 - _c139*_c93 - _c140*_c95
    _c142 = -_c41 + _c44 + _c46
    _c143 = _c142 + _c54
    _c144 = _c143*_c89
    _c145 = 2*g*h
    _c146 = _c109*_c139 - _c109*_c25 + _c110*_c138 + _c110*_c140 - _c110*_c145
    _c147 = -_c118*_c25 + _c119*_c25 + _c123*_c139 - _c123*_c25 - _c125*_c138 - _c125*_c140 + _c125*_c145 + _c126*_c138 + _c126*_c140 - _c126*_c145 - _c127*_c139 + _c127*_c25
    _c148 = _c115 - _c116
    _c149 = ((1.0/2.0))/_c80
    _c150 = _c149*_c77
    _c151 = _c149*_c79
    _c152 = _c149*_c32*_c78
    _c153 = _c142 - _c52 + _c53
    _c154 = _c153*_c89
    q[11] = -_c70*(_c22*_c61 + _c67*_c68) - _c76*(_c61*_c74 + _c68*_c75)
    q[12] = sigma*(-_c70*(_c13*_c68 + _c38*_c61) - _c76*(_c13*_c61 + _c48*_c68))
    q[13] = -_c86*(_c74*_c84 + _c75*_c83) - _c87*(_c22*_c84 + _c67*_c83)
    q[14] = sigma*(-_c86*(_c13*_c84 + _c48*_c83) - _c87*(_c13*_c83 + _c38*_c84))
    q[15] = _c105*_c107 + _c113*_c114 + _c128*_c129
    q[16] = sigma*(_c107*_c132 + _c114*_c134 + _c129*_c137)
    q[17] = _c107*_c141 - _c107*_c144 + _c114*_c144 + _c114*_c146 + _c129*_c143*_c148 + _c129*_c147
    q[18] = _c105*_c151 + _c113*_c150 + _c128*_c152
    q[19] = sigma*(_c132*_c151 + _c134*_c150 + _c137*_c152)
    q[20] = _c141*_c151 + _c146*_c150 + _c147*_c152 + _c148*_c152*_c153 + _c150*_c154 - _c151*_c154
    q[21] = -_c88*sigma
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (22 operations)."""
    A_pitch = s[0]
    A_roll = s[1]
    omega_z = s[2]
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
    _c0 = (omega_z*omega_z)
    ds[0] = A_pitch*(_k0*omega_z + _k1)
    ds[1] = A_roll*(_k2*omega_z + _k3)
    ds[2] = (A_pitch*A_pitch)*(_c0*_k4 + _k5*omega_z + _k6) + (A_roll*A_roll)*(_c0*_k7 + _k8*omega_z + _k9) + _k10*omega_z


@njit(cache=True)
def energy(s, p):
    """Mechanical energy to the order of this fidelity (208 operations)."""
    A_pitch = s[0]
    A_roll = s[1]
    omega_z = s[2]
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
    _c0 = c*m
    _c1 = _c0*g
    _c2 = g*h*m
    _c3 = (omega_z*omega_z)
    _c4 = (b*b)*m
    _c5 = 1/c
    _c6 = _c5*g
    _c7 = ((1.0/2.0))*_c6
    _c8 = _c4*_c7
    _c9 = ((1.0/2.0))*_c2
    _c10 = ((1.0/2.0))*_c1
    _c11 = -_c10 + _c9
    _c12 = _c11 + _c8
    _c13 = (c*c)
    _c14 = _c13*m
    _c15 = (h*h)
    _c16 = _c15*m
    _c17 = _c0*h
    _c18 = 2*_c17
    _c19 = (m*m)
    _c20 = 4*_c19
    _c21 = 1/(I_xx*I_yy + I_xx*_c14 + I_xx*_c16 - I_xx*_c18 - (I_xy*I_xy) + I_yy*_c14 + I_yy*_c16 - I_yy*_c18 + 6*_c13*_c15*_c19 + _c19*(c*c*c*c) + _c19*(h*h*h*h) - _c20*(c*c*c)*h - _c20*c*(h*h*h))
    _c22 = I_xy*_c21
    _c23 = (a*a)*m
    _c24 = _c23*_c6
    _c25 = _c2*_c22
    _c26 = _c1*_c22
    _c27 = _c25 - _c26
    _c28 = _c22*_c24 + _c27
    _c29 = (_c28*_c28)
    _c30 = _c14 + _c16 - _c18
    _c31 = I_yy + _c30
    _c32 = _c21*_c31
    _c33 = _c10*_c32
    _c34 = _c32*_c9
    _c35 = _c32*_c8
    _c36 = _c4*_c6
    _c37 = _c22*_c36
    _c38 = _c1*_c21
    _c39 = I_xx + _c30
    _c40 = _c2*_c21
    _c41 = _c21*_c39
    _c42 = ((1.0/2.0))*math.sqrt(_c28*(4*_c25 - 4*_c26 + 4*_c37) + ((_c24*_c41 + _c31*_c38 - _c31*_c40 - _c32*_c36 - _c38*_c39 + _c39*_c40)*(_c24*_c41 + _c31*_c38 - _c31*_c40 - _c32*_c36 - _c38*_c39 + _c39*_c40)))
    _c43 = _c23*_c7
    _c44 = -_c10*_c41 + _c41*_c43 + _c41*_c9
    _c45 = _c42 + _c44
    _c46 = _c33 - _c34 - _c35 + _c45
    _c47 = (_c46*_c46)
    _c48 = ((1.0/2.0))/(_c29 + _c47)
    _c49 = _c29*_c48
    _c50 = _c11 + _c43
    _c51 = _c47*_c48
    _c52 = ((1.0/2.0))*_c14 + ((1.0/2.0))*_c16 - _c17
    _c53 = ((1.0/2.0))*I_xx + _c52
    _c54 = -_c33 + _c34 + _c35
    _c55 = _c45 + _c54
    _c56 = ((1.0/2.0))*I_yy + _c52
    _c57 = I_xy*_c28*_c46*_c48
    _c58 = ((1.0/2.0))*m/_c13
    _c59 = _c5*h
    _c60 = _c4*_c59 - _c4 + _c56 + _c58*(b*b*b*b)
    _c61 = _c23*_c59 - _c23 + _c53 + _c58*(a*a*a*a)
    _c62 = _c27 + _c37
    _c63 = (_c62*_c62)
    _c64 = -_c46
    _c65 = (_c64*_c64)
    _c66 = ((1.0/2.0))/(_c63 + _c65)
    _c67 = _c63*_c66
    _c68 = _c65*_c66
    _c69 = -_c42 + _c44 + _c54
    _c70 = I_xy*_c62*_c64*_c66
    energy = (A_pitch*A_pitch)*(_c12*_c49 + _c3*(_c49*_c60 + _c51*_c61 + _c57) + _c49*_c53*_c55 + _c50*_c51 + _c51*_c55*_c56 - _c55*_c57) + (A_roll*A_roll)*(_c12*_c68 + _c3*(_c60*_c68 + _c61*_c67 + _c70) + _c50*_c67 + _c53*_c68*_c69 + _c56*_c67*_c69 - _c69*_c70) + ((1.0/2.0))*I_zz*_c3 + _c1 - _c2
    return energy


@njit(cache=True)
def power_dissipated(s, p):
    """Power removed by the damping torque, to the order of this fidelity (780 operations)."""
    A_pitch = s[0]
    A_roll = s[1]
    omega_z = s[2]
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
    _c0 = (b*b)
    _c1 = _c0*m
    _c2 = 1/c
    _c3 = ((1.0/2.0))*g
    _c4 = _c2*_c3
    _c5 = _c1*_c4
    _c6 = h*m
    _c7 = _c3*_c6
    _c8 = c*m
    _c9 = _c3*_c8
    _c10 = _c7 - _c9
    _c11 = _c10 + _c5
    _c12 = (a*a)
    _c13 = _c12*m
    _c14 = (I_xy*I_xy)
    _c15 = (c*c)
    _c16 = _c15*m
    _c17 = (h*h)
    _c18 = _c17*m
    _c19 = _c6*c
    _c20 = 2*_c19
    _c21 = (m*m)
    _c22 = (h*h*h)
    _c23 = 4*_c21
    _c24 = _c23*h
    _c25 = _c15*_c21
    _c26 = 1/(I_xx*I_yy + I_xx*_c16 + I_xx*_c18 - I_xx*_c20 + I_yy*_c16 + I_yy*_c18 - I_yy*_c20 - _c14 + 6*_c17*_c25 + _c21*(c*c*c*c) + _c21*(h*h*h*h) - _c22*_c23*c - _c24*(c*c*c))
    _c27 = I_xy*_c26
    _c28 = _c13*_c27
    _c29 = _c2*g
    _c30 = _c27*g
    _c31 = _c30*_c6
    _c32 = _c30*_c8
    _c33 = _c31 - _c32
    _c34 = _c28*_c29 + _c33
    _c35 = (_c34*_c34)
    _c36 = _c16 + _c18 - _c20
    _c37 = I_yy + _c36
    _c38 = _c26*_c37
    _c39 = _c38*_c9
    _c40 = _c38*_c7
    _c41 = _c38*_c5
    _c42 = _c1*_c27
    _c43 = _c29*_c42
    _c44 = _c8*g
    _c45 = I_xx + _c36
    _c46 = _c26*_c45
    _c47 = _c6*g
    _c48 = _c29*_c46
    _c49 = _c29*_c38
    _c50 = ((1.0/2.0))*math.sqrt(_c34*(4*_c31 - 4*_c32 + 4*_c43) + ((-_c1*_c49 + _c13*_c48 + _c38*_c44 - _c38*_c47 - _c44*_c46 + _c46*_c47)*(-_c1*_c49 + _c13*_c48 + _c38*_c44 - _c38*_c47 - _c44*_c46 + _c46*_c47)))
    _c51 = _c13*_c4
    _c52 = _c46*_c51 + _c46*_c7 - _c46*_c9
    _c53 = _c50 + _c52
    _c54 = _c39 - _c40 - _c41 + _c53
    _c55 = (_c54*_c54)
    _c56 = _c35 + _c55
    _c57 = ((1.0/2.0))/_c56
    _c58 = _c35*_c57
    _c59 = _c10 + _c51
    _c60 = _c55*_c57
    _c61 = ((1.0/2.0))*_c16 + ((1.0/2.0))*_c18 - _c19
    _c62 = ((1.0/2.0))*I_xx + _c61
    _c63 = -_c39 + _c40 + _c41
    _c64 = _c53 + _c63
    _c65 = _c58*_c64
    _c66 = ((1.0/2.0))*I_yy + _c61
    _c67 = _c60*_c64
    _c68 = _c34*_c54*_c57
    _c69 = I_xy*_c68
    _c70 = (omega_z*omega_z)
    _c71 = (b*b*b*b)
    _c72 = 1/_c15
    _c73 = ((1.0/2.0))*_c72*m
    _c74 = _c2*h
    _c75 = _c1*_c74
    _c76 = -_c1 + _c66 + _c71*_c73 + _c75
    _c77 = (a*a*a*a)
    _c78 = _c13*_c74
    _c79 = -_c13 + _c62 + _c73*_c77 + _c78
    _c80 = _c58*_c76 + _c60*_c79 + _c69
    _c81 = _c27*_c75
    _c82 = -I_zz*_c27 + _c16*_c27 + _c18*_c27 - _c20*_c27
    _c83 = -I_xx*_c27 + I_xy*_c0*_c26*m - _c27*_c37 - _c81 - _c82
    _c84 = _c33 + _c43
    _c85 = 1/math.sqrt(_c56)
    _c86 = _c34*_c84
    _c87 = 1/(_c55*_c85 + _c85*_c86)
    _c88 = _c84*_c87
    _c89 = _c14*_c26
    _c90 = _c89 + 1
    _c91 = _c46*_c75
    _c92 = -_c0*_c26*_c45*m + _c91
    _c93 = -I_xx*_c46 + I_zz*_c26*_c45 - _c16*_c46 - _c18*_c46 + 2*_c26*_c45*c*h*m - _c90 - _c92
    _c94 = _c54*_c87
    _c95 = ((1.0/2.0))*_c85
    _c96 = _c34*_c95
    _c97 = _c13*_c38
    _c98 = _c38*_c78
    _c99 = I_yy*_c38 - I_zz*_c38 + _c16*_c38 + _c18*_c38 - _c20*_c38 + _c90 - _c97 + _c98
    _c100 = I_yy*_c27 + _c27*_c45 + _c27*_c78 - _c28 + _c82
    _c101 = _c54*_c95
    _c102 = omega_z*(-_c101*(_c100*_c94 + _c88*_c99) - _c96*(_c83*_c88 + _c93*_c94))
    _c103 = (_c84*_c84)
    _c104 = -_c54
    _c105 = (_c104*_c104)
    _c106 = _c103 + _c105
    _c107 = ((1.0/2.0))/_c106
    _c108 = _c103*_c107
    _c109 = _c105*_c107
    _c110 = -_c50 + _c52 + _c63
    _c111 = _c108*_c110
    _c112 = _c109*_c110
    _c113 = _c104*_c107*_c84
    _c114 = I_xy*_c113
    _c115 = _c108*_c79 + _c109*_c76 + _c114
    _c116 = 1/math.sqrt(_c106)
    _c117 = 1/(_c105*_c116 + _c116*_c86)
    _c118 = _c117*_c34
    _c119 = _c104*_c117
    _c120 = ((1.0/2.0))*_c116
    _c121 = _c120*_c84
    _c122 = _c104*_c120
    _c123 = omega_z*(-_c121*(_c100*_c118 + _c119*_c99) - _c122*(_c118*_c93 + _c119*_c83))
    _c124 = (A_pitch*A_pitch)
    _c125 = 2*omega_z
    _c126 = (A_roll*A_roll)
    _c127 = 1/I_zz
    _c128 = omega_z*sigma
    _c129 = I_xy*_c127
    _c130 = _c129*_c26
    _c131 = _c0*_c21
    _c132 = _c130*_c131
    _c133 = c*g
    _c134 = _c21*_c71
    _c135 = _c130*_c134
    _c136 = _c72*g*h
    _c137 = _c17*_c29
    _c138 = 2*I_xy*_c0*_c127*_c21*_c26*g*h + I_xy*_c127*_c2*_c21*_c26*_c71*g - _c132*_c133 - _c132*_c137 - _c135*_c136
    _c139 = _c12*_c130
    _c140 = _c133*_c21
    _c141 = _c139*_c21
    _c142 = 2*g*h
    _c143 = _c21*_c77
    _c144 = _c130*_c143
    _c145 = _c136*_c144 + _c137*_c141 + _c139*_c140 - _c141*_c142 - _c144*_c29
    _c146 = _c1*_c127
    _c147 = _c127*_c13
    _c148 = _c12*_c127
    _c149 = _c148*_c38
    _c150 = _c149*_c21
    _c151 = _c127*_c46
    _c152 = _c131*_c151
    _c153 = _c131*_c148
    _c154 = _c153*_c38
    _c155 = _c153*_c46
    _c156 = -_c127*_c131*_c17*_c48 - _c133*_c152 + _c136*_c154 - _c136*_c155 + _c140*_c149 - _c142*_c150 + _c142*_c152 + _c146*_c29 - _c147*_c29 + _c148*_c17*_c21*_c49 + _c153*_c48 - _c153*_c49
    _c157 = I_xx*_c127
    _c158 = I_yy*_c127
    _c159 = -_c157 + _c158
    _c160 = _c1*_c130
    _c161 = 3*c
    _c162 = _c130*_c75
    _c163 = 3*_c17
    _c164 = 2*_c74
    _c165 = _c2*_c22
    _c166 = _c17*_c72
    _c167 = _c1*_c46
    _c168 = -I_yy*_c160 + I_yy*_c162 - _c0*_c130*_c25 - _c129*_c167 + _c129*_c91 + _c129 + _c132*_c161*h - _c132*_c163 + _c132*_c165 - _c135*_c164 + _c135*_c166 + _c135 + _c42 - _c81
    _c169 = _c161*h
    _c170 = _c130*_c78
    _c171 = _c165*_c21
    _c172 = I_xx*I_xy*_c12*_c127*_c26*m - I_xx*_c170 + I_xy*_c12*_c127*_c15*_c21*_c26 + 3*I_xy*_c12*_c127*_c17*_c21*_c26 + I_xy*_c12*_c127*_c26*_c37*m + I_xy*_c12*_c2*_c26*h*m + 2*I_xy*_c127*_c2*_c21*_c26*_c77*h - _c129*_c98 - _c129 - _c139*_c171 - _c141*_c169 - _c144*_c166 - _c144 - _c28
    _c173 = I_xx*_c0*_c127*_c2*_c26*_c45*h*m + I_yy*_c12*_c127*_c26*_c37*m + _c0*_c12*_c127*_c17*_c21*_c26*_c45*_c72 + 2*_c0*_c12*_c127*_c2*_c21*_c26*_c37*h + _c0*_c12*_c127*_c21*_c26*_c45 + _c0*_c127*_c14*_c2*_c26*h*m + _c0*_c127*_c2*_c21*_c22*_c26*_c45 + 3*_c0*_c127*_c21*_c26*_c45*c*h + _c0*_c127*m - _c0*_c151*_c25 + _c12*_c127*_c14*_c26*m + _c12*_c127*_c15*_c21*_c26*_c37 + 3*_c12*_c127*_c17*_c21*_c26*_c37 + _c12*_c127*_c2*h*m + _c12*_c2*_c26*_c37*h*m - _c146*_c74 - _c146*_c89 - _c147*_c74*_c89 - _c147 - _c149*_c171 - _c150*_c169 - _c152*_c163 - _c154*_c166 - _c154 - _c155*_c164 - _c157*_c167 + _c157 - _c158*_c98 - _c158 - _c92 - _c97
    _c174 = -_c129*_c65 + _c129*_c67 + _c138*_c58 + _c145*_c60 + _c156*_c68 + _c159*_c64*_c68 + _c70*(_c168*_c58 + _c172*_c60 + _c173*_c68)
    _c175 = _c108*_c145 + _c109*_c138 + _c110*_c113*_c159 + _c111*_c129 - _c112*_c129 + _c113*_c156 + _c70*(_c108*_c172 + _c109*_c168 + _c113*_c173)
    _c176 = (1.0/(I_zz*I_zz))
    _c177 = _c134*_c176*_c46
    _c178 = _c0*_c127*_c2*_c26*_c45*h*m - _c146*_c46 - _c166*_c177 + 2*_c176*_c2*_c21*_c26*_c45*_c71*h + _c176*_c71*_c72*m - _c177
    _c179 = _c143*_c176*_c38
    _c180 = _c12*_c127*_c2*_c26*_c37*h*m - _c147*_c38 - _c166*_c179 + 2*_c176*_c2*_c21*_c26*_c37*_c77*h + _c176*_c72*_c77*m - _c179
    _c181 = _c12*_c176*_c27
    _c182 = 2*_c131*_c181
    _c183 = -_c0*_c181*_c2*_c24 + _c13*_c130 + _c160 - _c162 + _c166*_c182 - _c170 + _c182
    power = -2*A_pitch*(-A_pitch*_c102 + A_pitch*(_c102 + sigma*(-_c101*(_c27*_c88 + _c46*_c94) - _c96*(_c27*_c94 + _c38*_c88))))*(_c11*_c58 + _c59*_c60 + _c62*_c65 - _c64*_c69 + _c66*_c67 + _c70*_c80) - 2*A_roll*(-A_roll*_c123 + A_roll*(_c123 + sigma*(-_c121*(_c118*_c46 + _c119*_c27) - _c122*(_c118*_c27 + _c119*_c38))))*(_c108*_c59 + _c109*_c11 - _c110*_c114 + _c111*_c66 + _c112*_c62 + _c115*_c70) - (I_zz*omega_z + _c115*_c125*_c126 + _c124*_c125*_c80)*(-_c124*_c174 + _c124*(_c128*(_c178*_c58 + _c180*_c60 + _c183*_c68) + _c174) - _c126*_c175 + _c126*(_c128*(_c108*_c180 + _c109*_c178 + _c113*_c183) + _c175) - _c127*_c128)
    return power


@njit(cache=True)
def multipliers(s, p):
    """No multipliers at this fidelity (the contact force is not kept)."""
    return np.empty(0)


@njit(cache=True)
def modes(p):
    """Rocking modes without spin and damping: squared frequencies (pitch, roll), unit shapes u_k and left vectors v_k (v_k . u_k = 1) of W0 in the tilt (n_x, n_y) (133 operations)."""
    out = np.empty(10)
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
    _c0 = (c*c)
    _c1 = _c0*m
    _c2 = (h*h)
    _c3 = _c2*m
    _c4 = c*m
    _c5 = 2*_c4*h
    _c6 = (m*m)
    _c7 = 4*_c6
    _c8 = g/(I_xx*I_yy + I_xx*_c1 + I_xx*_c3 - I_xx*_c5 - (I_xy*I_xy) + I_yy*_c1 + I_yy*_c3 - I_yy*_c5 + 6*_c0*_c2*_c6 + _c6*(c*c*c*c) + _c6*(h*h*h*h) - _c7*(c*c*c)*h - _c7*c*(h*h*h))
    _c9 = _c8*m
    _c10 = _c9/c
    _c11 = _c10*(a*a)
    _c12 = _c9*h
    _c13 = I_xy*_c12
    _c14 = _c4*_c8
    _c15 = I_xy*_c14
    _c16 = _c13 - _c15
    _c17 = I_xy*_c11 + _c16
    _c18 = _c10*(b*b)
    _c19 = I_xy*_c18
    _c20 = _c1 + _c3 - _c5
    _c21 = I_yy + _c20
    _c22 = _c14*_c21
    _c23 = I_xx + _c20
    _c24 = _c12*_c23
    _c25 = _c14*_c23
    _c26 = _c12*_c21
    _c27 = _c11*_c23
    _c28 = _c18*_c21
    _c29 = ((1.0/2.0))*math.sqrt(_c17*(4*_c13 - 4*_c15 + 4*_c19) + ((_c22 + _c24 - _c25 - _c26 + _c27 - _c28)*(_c22 + _c24 - _c25 - _c26 + _c27 - _c28)))
    _c30 = ((1.0/2.0))*_c24
    _c31 = -(1.0/2.0)*_c25
    _c32 = ((1.0/2.0))*_c27
    _c33 = _c29 + _c30 + _c31 + _c32
    _c34 = ((1.0/2.0))*_c26
    _c35 = ((1.0/2.0))*_c22
    _c36 = ((1.0/2.0))*_c28
    _c37 = _c34 - _c35 + _c36
    _c38 = _c33 - _c34 + _c35 - _c36
    _c39 = (_c38*_c38)
    _c40 = 1/math.sqrt((_c17*_c17) + _c39)
    _c41 = _c17*_c40
    _c42 = _c16 + _c19
    _c43 = -_c38
    _c44 = (_c43*_c43)
    _c45 = 1/math.sqrt((_c42*_c42) + _c44)
    _c46 = _c42*_c45
    _c47 = 1/(_c39*_c40 + _c41*_c42)
    _c48 = 1/(_c17*_c46 + _c44*_c45)
    out[0] = _c33 + _c37
    out[1] = -_c29 + _c30 + _c31 + _c32 + _c37
    out[2] = _c38*_c40
    out[3] = _c41
    out[4] = _c46
    out[5] = _c43*_c45
    out[6] = _c38*_c47
    out[7] = _c42*_c47
    out[8] = _c17*_c48
    out[9] = _c43*_c48
    return out[:2], out[2:6].reshape(2, 2), out[6:10].reshape(2, 2)


@njit(cache=True)
def moffatt_tokieda(p):
    """Moffatt & Tokieda's (lambda, mu) and the squared scalings (p^2, r^2) with P = p A_pitch, R = r A_roll, n = omega_z (351 operations)."""
    out = np.empty(4)
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
    _c0 = (I_xy*I_xy)
    _c1 = (c*c)
    _c2 = _c1*m
    _c3 = (h*h)
    _c4 = _c3*m
    _c5 = h*m
    _c6 = 2*_c5*c
    _c7 = (m*m)
    _c8 = 4*_c7
    _c9 = _c3*_c7
    _c10 = 1/(I_xx*I_yy + I_xx*_c2 + I_xx*_c4 - I_xx*_c6 + I_yy*_c2 + I_yy*_c4 - I_yy*_c6 - _c0 + 6*_c1*_c9 + _c7*(c*c*c*c) + _c7*(h*h*h*h) - _c8*(c*c*c)*h - _c8*c*(h*h*h))
    _c11 = I_xy*_c10
    _c12 = (a*a)
    _c13 = _c12*m
    _c14 = _c11*_c13
    _c15 = 1/c
    _c16 = _c15*g
    _c17 = _c11*g
    _c18 = _c17*_c5
    _c19 = c*m
    _c20 = _c17*_c19
    _c21 = _c18 - _c20
    _c22 = _c14*_c16 + _c21
    _c23 = _c2 + _c4 - _c6
    _c24 = I_yy + _c23
    _c25 = (b*b)
    _c26 = _c15*_c5
    _c27 = _c25*_c26
    _c28 = -I_zz*_c11 + _c11*_c2 + _c11*_c4 - _c11*_c6
    _c29 = -I_xx*_c11 + I_xy*_c10*_c25*m - _c11*_c24 - _c11*_c27 - _c28
    _c30 = _c25*m
    _c31 = _c11*_c16*_c30
    _c32 = _c21 + _c31
    _c33 = (_c22*_c22)
    _c34 = _c10*_c24
    _c35 = _c19*g
    _c36 = _c34*_c35
    _c37 = ((1.0/2.0))*_c36
    _c38 = _c5*g
    _c39 = _c34*_c38
    _c40 = ((1.0/2.0))*_c39
    _c41 = _c16*_c30*_c34
    _c42 = ((1.0/2.0))*_c41
    _c43 = I_xx + _c23
    _c44 = _c10*_c43
    _c45 = _c38*_c44
    _c46 = _c35*_c44
    _c47 = _c13*_c16*_c44
    _c48 = ((1.0/2.0))*math.sqrt(_c22*(4*_c18 - 4*_c20 + 4*_c31) + ((_c36 - _c39 - _c41 + _c45 - _c46 + _c47)*(_c36 - _c39 - _c41 + _c45 - _c46 + _c47)))
    _c49 = ((1.0/2.0))*_c45 - (1.0/2.0)*_c46 + ((1.0/2.0))*_c47
    _c50 = _c48 + _c49
    _c51 = _c37 - _c40 - _c42 + _c50
    _c52 = (_c51*_c51)
    _c53 = _c33 + _c52
    _c54 = 1/math.sqrt(_c53)
    _c55 = _c22*_c32
    _c56 = 1/(_c52*_c54 + _c54*_c55)
    _c57 = _c32*_c56
    _c58 = _c0*_c10 + 1
    _c59 = -I_xx*_c44 + I_zz*_c10*_c43 + _c10*_c25*_c43*m + 2*_c10*_c43*c*h*m - _c2*_c44 - _c27*_c44 - _c4*_c44 - _c58
    _c60 = _c51*_c56
    _c61 = ((1.0/2.0))*_c54
    _c62 = _c12*_c26
    _c63 = I_yy*_c34 - I_zz*_c34 - _c13*_c34 + _c2*_c34 + _c34*_c4 - _c34*_c6 + _c34*_c62 + _c58
    _c64 = I_yy*_c11 + _c11*_c43 + _c11*_c62 - _c14 + _c28
    _c65 = -_c22*_c61*(_c29*_c57 + _c59*_c60) - _c51*_c61*(_c57*_c63 + _c60*_c64)
    _c66 = (_c32*_c32)
    _c67 = -_c51
    _c68 = (_c67*_c67)
    _c69 = _c66 + _c68
    _c70 = 1/math.sqrt(_c69)
    _c71 = 1/(_c55*_c70 + _c68*_c70)
    _c72 = _c22*_c71
    _c73 = _c67*_c71
    _c74 = ((1.0/2.0))*_c70
    _c75 = _c32*_c74*(_c63*_c73 + _c64*_c72) + _c67*_c74*(_c29*_c73 + _c59*_c72)
    _c76 = 1/I_zz
    _c77 = _c7*_c76
    _c78 = _c17*_c77
    _c79 = _c78*c
    _c80 = (b*b*b*b)
    _c81 = 1/_c1
    _c82 = _c78*h
    _c83 = _c81*_c82
    _c84 = _c15*_c17*_c76*_c9
    _c85 = I_xy*_c10*_c15*_c7*_c76*_c80*g + 2*I_xy*_c10*_c25*_c7*_c76*g*h - _c25*_c79 - _c25*_c84 - _c80*_c83
    _c86 = 1/_c53
    _c87 = ((1.0/2.0))*_c86
    _c88 = -_c37 + _c40 + _c42
    _c89 = _c50 + _c88
    _c90 = (a*a*a*a)
    _c91 = _c12*_c79 - 2*_c12*_c82 + _c12*_c84 - _c15*_c78*_c90 + _c83*_c90
    _c92 = _c52*_c87
    _c93 = _c16*_c76
    _c94 = _c12*_c34
    _c95 = _c77*g
    _c96 = _c95*c
    _c97 = _c95*h
    _c98 = 2*_c97
    _c99 = _c25*_c44
    _c100 = _c7*_c93
    _c101 = _c12*_c99
    _c102 = _c9*_c93
    _c103 = _c25*_c94
    _c104 = _c81*_c97
    _c105 = _c100*_c101 - _c100*_c103 - _c101*_c104 + _c102*_c94 - _c102*_c99 + _c103*_c104 - _c13*_c93 + _c30*_c93 + _c94*_c96 - _c94*_c98 - _c96*_c99 + _c98*_c99
    _c106 = _c22*_c51*_c87
    _c107 = I_xy*_c76
    _c108 = -I_xx*_c76 + I_yy*_c76
    _c109 = ((1.0/2.0))/_c69
    _c110 = _c109*_c66
    _c111 = -_c48 + _c49 + _c88
    _c112 = _c107*_c111
    _c113 = _c109*_c68
    _c114 = _c109*_c32*_c67
    out[0] = _c65
    out[1] = _c75
    out[2] = (((1.0/2.0))*I_xy*_c33*_c76*_c86*_c89 - _c105*_c106 - _c106*_c108*_c89 - _c107*_c89*_c92 - _c33*_c85*_c87 - _c91*_c92)/_c65
    out[3] = (_c105*_c114 + _c108*_c111*_c114 + _c110*_c112 + _c110*_c91 - _c112*_c113 + _c113*_c85)/_c75
    return out


def _param_vector(p):
    if isinstance(p, dict):
        missing = [k for k in PARAM_NAMES if k not in p]
        if missing:
            raise ValueError(f"`p` lacks {missing}")
        p = [p[k] for k in PARAM_NAMES]
    p = np.array(p, dtype=float)
    if p.shape != (len(PARAM_NAMES),) or not np.isfinite(p).all():
        raise ValueError(f"`p` must be {len(PARAM_NAMES)} finite numbers in the order of PARAM_NAMES")
    return p


def initial_state(n0=(0.0, 0.0, 1.0), omega0=(0.0, 0.0, 0.0), p=None):
    """State ``(A_pitch, A_roll, omega_z)`` from the physical description and the parameters ``p``.

    The tilt ``q = (n_x, n_y)`` of ``n0`` (normalized) and its rate ``q_dot = (n_y omega_z - omega_y,
    omega_x - n_x omega_z)`` are projected on the rocking modes (``modes(p)``):
    ``y_k = v_k . q``, ``A_k = sqrt(y_k^2 + (v_k . q_dot / Omega_k)^2)``.
    """
    if p is None:
        raise ValueError("`p` (the parameters) is needed: the modes depend on them")
    p = _param_vector(p)
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
    q = n0[:2]
    q_dot = np.array([n0[1] * omega0[2] - omega0[1], omega0[0] - n0[0] * omega0[2]])
    w2, u, v = modes(p)
    amps = [math.hypot(float(v[k] @ q), float(v[k] @ q_dot) / math.sqrt(w2[k])) for k in range(2)]
    return np.array([amps[0], amps[1], omega0[2]])


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
MODULE_SHA256 = 'a110af1d55fb78976fb1e15644abe6970a457f541daca7e2294acc4a43d8243d'
