"""single_mode, fidelity reduced: degree-2 Taylor polynomial of the full vector field in the tilts and tilt rates (tilt equations to O(theta), spin equation to O(theta^2)).

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from derivation/models.py (model 'single_mode',
constraints vinculo1, vinculo2) through derivation/engine.py and derivation/truncation.py.
Accelerations and multipliers in closed form (symbolic elimination of the multipliers).
SymPy 1.14.0; input hash sha256:db103aead09d93bdd320b613cfd0da1e6ee4a4924c2a957dc9ff96f88afcccc4

Single-mode knife edge (paper section II): a massless bar of length 2L on the table, two masses M/2 hanging at distance ell from its ends; one tilt theta, the contact point shifted by D*theta along the bar (vinculo1, vinculo2).

State vector ``s`` (closed state; the pose follows by quadrature):
    s[0] = theta        [rad]
    s[1] = theta_dot    [rad/time]
    s[2] = phi_dot      [rad/time]
Pose-extended state (``*_pose`` functions) appends:
    s[3] = phi          [rad]
    s[4] = x            [length]
    s[5] = y            [length]
Parameter vector ``p``:
    p[0] = g            [length/time^2]
    p[1] = ell          [length]
    p[2] = L            [length]
    p[3] = D            [length]
Multipliers (constraint forces in the normalization of the Lagrangian, e.g. per unit mass),
in the order vinculo1, vinculo2.  Energy in the same normalization.
"""
import math

import numpy as np
from numba import njit

MODEL = 'single_mode'
FIDELITY = 'reduced'
#: what this fidelity is
FIDELITY_DOC = 'degree-2 Taylor polynomial of the full vector field in the tilts and tilt rates (tilt equations to O(theta), spin equation to O(theta^2))'
STATE_NAMES = ('theta', 'theta_dot', 'phi_dot')
#: unit of each state (``time`` is the unit of t)
STATE_UNITS = ('rad', 'rad/time', 'rad/time')
POSE_NAMES = ('phi', 'x', 'y')
POSE_UNITS = ('rad', 'length', 'length')
#: what the pose coordinates mean
POSE_DOC = 'phi: heading of the bar; (x, y): position of the centre of the bar on the table'
PARAM_NAMES = ('g', 'ell', 'L', 'D')
PARAM_UNITS = ('length/time^2', 'length', 'length', 'length')
#: admissible values of each parameter: 'positive' (> 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive', 'positive', 'positive')
#: default parameter set and initial state (the CLI's defaults); empty if the model declares none
DEFAULT_PARAMS = {'g': 1.0, 'ell': 1.0, 'L': 1.0, 'D': 1.0}
DEFAULT_STATE = {'theta': 0.001, 'theta_dot': 0.0, 'phi_dot': 0.1}
#: (coordinate, rate) pairs of the state
RATE_PAIRS = (('theta', 'theta_dot'),)
#: the small coordinates (tilts) of the small-angle fidelities
TILT_NAMES = ('theta',)
#: states (or EVENT_NAMES) whose zero crossings are reported as ``reversal_times``
REVERSAL_EVENTS = ('phi_dot',)
#: scalar functions of the state returned by ``event_values(s, p)``
EVENT_NAMES = ()
#: largest |value| of each named state where this fidelity holds (empty: everywhere)
VALIDITY = {'theta': 0.21}
VALIDITY_DOC = "small tilts: up to this bound the first spin reversal of the small-angle fidelities is within 0.1% of the full model's; the amplitude fidelity also needs the spin rate small against the tilt frequencies"
MULTIPLIER_NAMES = ('vinculo1', 'vinculo2')
#: non-conservative forces: the module has ``power_dissipated(s, p)``
HAS_DISSIPATION = False
#: model-specific helpers defined at the end of this module
EXPORTS = ()
INPUT_HASH = 'db103aead09d93bdd320b613cfd0da1e6ee4a4924c2a957dc9ff96f88afcccc4'
SYMPY_VERSION = '1.14.0'
#: how the multipliers are eliminated: "symbolic" (closed form) or "numeric" (a linear solve at every call)
ELIMINATION = 'symbolic'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 11, 'constants': 7, 'rhs_q': 7, 'rhs_pose': 17, 'rhs_pose_q': 14, 'pose_rates': 7, 'energy': 23, 'multipliers': 7, 'frequencies': 5}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (11 operations)."""
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    ds[0] = theta_dot
    ds[1] = (D*phi_dot*theta_dot - g*theta)/ell
    ds[2] = -D*g*(theta*theta)/(L*L)


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 3."""
    ds = np.empty(3)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 4 parameter-only subexpressions of the right-hand side (7 operations)."""
    q = np.empty(8)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    q[0] = g
    q[1] = ell
    q[2] = L
    q[3] = D
    q[4] = -g
    q[5] = 1/ell
    q[6] = -D*g/(L*L)
    q[7] = -D
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (7 operations)."""
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    g = q[0]
    ell = q[1]
    L = q[2]
    D = q[3]
    _k0 = q[4]
    _k1 = q[5]
    _k2 = q[6]
    _k3 = q[7]
    ds[0] = theta_dot
    ds[1] = _k1*(D*phi_dot*theta_dot + _k0*theta)
    ds[2] = _k2*(theta*theta)


@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds`` (17 operations)."""
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    phi = s[3]
    x = s[4]
    y = s[5]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _c0 = D*phi_dot
    _c1 = _c0*theta
    ds[0] = theta_dot
    ds[1] = (_c0*theta_dot - g*theta)/ell
    ds[2] = -D*g*(theta*theta)/(L*L)
    ds[3] = phi_dot
    ds[4] = _c1*math.sin(phi)
    ds[5] = -_c1*math.cos(phi)


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length 6."""
    ds = np.empty(6)
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p`` (14 operations)."""
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    phi = s[3]
    x = s[4]
    y = s[5]
    g = q[0]
    ell = q[1]
    L = q[2]
    D = q[3]
    _k0 = q[4]
    _k1 = q[5]
    _k2 = q[6]
    _k3 = q[7]
    _c0 = D*phi_dot
    ds[0] = theta_dot
    ds[1] = _k1*(_c0*theta_dot + _k0*theta)
    ds[2] = _k2*(theta*theta)
    ds[3] = phi_dot
    ds[4] = _c0*theta*math.sin(phi)
    ds[5] = _k3*phi_dot*theta*math.cos(phi)


@njit(cache=True)
def pose_rates(s, p):
    """Return the rates (phi_dot, x_dot, y_dot) of the pose at the pose-extended state ``s`` (7 operations)."""
    out = np.empty(3)
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    phi = s[3]
    x = s[4]
    y = s[5]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _c0 = D*phi_dot*theta
    out[0] = phi_dot
    out[1] = _c0*math.sin(phi)
    out[2] = -_c0*math.cos(phi)
    return out


@njit(cache=True)
def energy(s, p):
    """Energy per unit mass (23 operations)."""
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _c0 = (theta*theta)
    _c1 = ((1.0/2.0))*(phi_dot*phi_dot)
    energy = (D*D)*_c0*_c1 - D*ell*phi_dot*theta*theta_dot + (L*L)*_c1 + ((1.0/2.0))*_c0*ell*g + ((1.0/2.0))*(ell*ell)*(theta_dot*theta_dot)
    return energy


@njit(cache=True)
def multipliers(s, p):
    """Lagrange multipliers (contact forces per unit mass) vinculo1, vinculo2 (7 operations)."""
    out = np.empty(2)
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    out[0] = phi_dot*(D*phi_dot*theta - ell*theta_dot)
    out[1] = -g*theta
    return out



#: how to draw the body (derivation/drawing.py): names of the rows of ``body_points``,
#: segments between them, the contact point, the point masses, the tilts a picture may
#: magnify, the outline curves of ``body_outlines``
DRAWING = {'points': ('O', 'end_minus', 'end_plus', 'mass_minus', 'mass_plus', 'C'), 'segments': (('end_minus', 'end_plus'), ('end_minus', 'mass_minus'), ('end_plus', 'mass_plus')), 'contact': 'C', 'masses': ('mass_minus', 'mass_plus'), 'magnify': ('theta',), 'outlines': (), 'description': 'bar of length 2L on the table (middle point O), masses M/2 hanging ell below its ends, contact point C = O + D theta u_phi on the bar (vinculo1, vinculo2)'}


@njit(cache=True)
def body_points(s, p):
    """World coordinates (z up, table z = 0) of DRAWING["points"] at the pose-extended state ``s``; shape (6, 3) (27 operations)."""
    out = np.empty((6, 3))
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    phi = s[3]
    x = s[4]
    y = s[5]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _c0 = math.cos(phi)
    _c1 = L*_c0
    _c2 = _c1 - x
    _c3 = math.sin(phi)
    _c4 = L*_c3
    _c5 = _c1 + x
    _c6 = _c4 + y
    _c7 = ell*math.sin(theta)
    _c8 = _c3*_c7
    _c9 = _c0*_c7
    _c10 = -ell*math.cos(theta)
    _c11 = D*theta
    out[0, 0] = x
    out[0, 1] = y
    out[0, 2] = 0
    out[1, 0] = -_c2
    out[1, 1] = -_c4 + y
    out[1, 2] = 0
    out[2, 0] = _c5
    out[2, 1] = _c6
    out[2, 2] = 0
    out[3, 0] = -_c2 - _c8
    out[3, 1] = -_c4 + _c9 + y
    out[3, 2] = _c10
    out[4, 0] = _c5 - _c8
    out[4, 1] = _c6 + _c9
    out[4, 2] = _c10
    out[5, 0] = _c0*_c11 + x
    out[5, 1] = _c11*_c3 + y
    out[5, 2] = 0
    return out


@njit(cache=True)
def body_outlines(s, p, uu):
    """World coordinates of the curves DRAWING["outlines"] at the parameters ``uu`` in [0, 2 pi); shape (0, len(uu), 3) (0 operations)."""
    out = np.empty((0, uu.shape[0], 3))
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    phi = s[3]
    x = s[4]
    y = s[5]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]

    return out


@njit(cache=True)
def frequencies(p):
    """Angular frequencies omega_i of the small oscillations of theta at zero spin [1/time] (5 operations)."""
    out = np.empty(1)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    out[0] = math.sqrt(g)/math.sqrt(ell)
    return out


#: operation counts of the Jacobians and of the Jacobian-vector product, once and per column (derivation/jacobian.py)
OP_COUNTS.update(jacobian=12, jacobian_p=27, jvp_once=23, jvp_column=6)

@njit(cache=True)
def jacobian(s, p):
    """d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape (3, 3) (12 operations)."""
    out = np.zeros((3, 3))
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    out[0, 1] = 1
    out[1, 0] = -g/ell
    out[1, 1] = D*phi_dot/ell
    out[1, 2] = D*theta_dot/ell
    out[2, 0] = -2*D*g*theta/(L*L)
    return out


@njit(cache=True)
def jacobian_p(s, p):
    """d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape (3, 4) (27 operations)."""
    out = np.zeros((3, 4))
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    out[1, 0] = -theta/ell
    out[1, 1] = -(D*phi_dot*theta_dot - g*theta)/(ell*ell)
    out[1, 3] = phi_dot*theta_dot/ell
    out[2, 0] = -D*(theta*theta)/(L*L)
    out[2, 2] = 2*D*g*(theta*theta)/(L*L*L)
    out[2, 3] = -g*(theta*theta)/(L*L)
    return out


@njit(cache=True)
def jvp_into(s, p, _V, ds, out):
    """Write d(state)/dt into ``ds`` and ``J(s) _V`` into ``out`` (``_V``, ``out``: (3, k)), the derivatives of the rates along the columns of ``_V`` by forward mode through the right-hand side (23 operations once, 6 per column)."""
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _p0 = 1/ell
    _p1 = D*_p0
    _k0 = -_p0*g
    _k1 = _p1*phi_dot
    _k2 = _p1*theta_dot
    _k3 = -2*D*g*theta/(L*L)
    ds[0] = theta_dot
    ds[1] = (D*phi_dot*theta_dot - g*theta)/ell
    ds[2] = -D*g*(theta*theta)/(L*L)
    for _j in range(_V.shape[1]):
        _v0 = _V[0, _j]
        _v1 = _V[1, _j]
        _v2 = _V[2, _j]
        out[0, _j] = _v1
        out[1, _j] = _k0*_v0 + _k1*_v1 + _k2*_v2
        out[2, _j] = _k3*_v0


@njit(cache=True)
def jvp1_into(s, p, _v, ds, _dv):
    """``jvp_into`` of one column: d(state)/dt into ``ds`` and ``J(s) _v`` into ``_dv`` (vectors of length 3; 29 operations)."""
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _p0 = 1/ell
    _p1 = D*_p0
    _k0 = -_p0*g
    _k1 = _p1*phi_dot
    _k2 = _p1*theta_dot
    _k3 = -2*D*g*theta/(L*L)
    ds[0] = theta_dot
    ds[1] = (D*phi_dot*theta_dot - g*theta)/ell
    ds[2] = -D*g*(theta*theta)/(L*L)
    _v0 = _v[0]
    _v1 = _v[1]
    _v2 = _v[2]
    _dv[0] = _v1
    _dv[1] = _k0*_v0 + _k1*_v1 + _k2*_v2
    _dv[2] = _k3*_v0



#: families of steady motions (derivation/steady.py): name -> the family's parameter ``value`` (``value_state`` is
#: the state equal to it), what the motion is, and names of the modes by their largest state
STEADY_FAMILIES = {'steady_spin': {'value': 'Omega', 'value_state': 'phi_dot', 'description': 'upright steady spin theta = 0 at the rate Omega', 'mode_names': {'A_theta': 'tilt', 'theta': 'tilt', 'theta_dot': 'tilt'}}}


@njit(cache=True)
def steady_state(_family, _value, p):
    """Row 0: the closed state of family number ``_family`` of STEADY_FAMILIES at ``_value``; row 1: its derivative
    in ``_value`` (the family's tangent)."""
    out = np.zeros((2, 3))
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    if _family == 0:
        Omega = _value
        out[0, 2] = Omega
        out[1, 2] = 1

    return out


#: functions of the closed state fixed by construction; their gradients are not physical directions
STATE_INVARIANTS = ()


@njit(cache=True)
def invariant_gradients(s, p):
    """Gradients of STATE_INVARIANTS, shape (0, 3)."""
    out = np.zeros((0, 3))
    theta = s[0]
    theta_dot = s[1]
    phi_dot = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]

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
        '  %v7 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  %v8 = load double, ptr %v7\n'
        '  %v9 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  %v10 = load double, ptr %v9\n'
        '  %v11 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  %v12 = load double, ptr %v11\n'
        '  %v13 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  %v14 = load double, ptr %v13\n'
        '  %v15 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  %v16 = load double, ptr %v15\n'
        '  %v17 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  %v18 = load double, ptr %v17\n'
        '  %v19 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  %v20 = load double, ptr %v19\n'
        '  %v21 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  %v22 = load double, ptr %v21\n'
        '  %v23 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v4, ptr %v23\n'
        '  %v24 = fmul double %v14, %v6\n'
        '  %v25 = fmul double %v24, %v4\n'
        '  %v26 = fmul double %v16, %v2\n'
        '  %v27 = fadd double %v25, %v26\n'
        '  %v28 = fmul double %v18, %v27\n'
        '  %v29 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v28, ptr %v29\n'
        '  %v30 = fmul double %v2, %v2\n'
        '  %v31 = fmul double %v20, %v30\n'
        '  %v32 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v31, ptr %v32\n'
        '  ret i32 0\n'
        '}\n'
        '\n'
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
        '  %v13 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  %v14 = load double, ptr %v13\n'
        '  %v15 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  %v16 = load double, ptr %v15\n'
        '  %v17 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  %v18 = load double, ptr %v17\n'
        '  %v19 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  %v20 = load double, ptr %v19\n'
        '  %v21 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  %v22 = load double, ptr %v21\n'
        '  %v23 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  %v24 = load double, ptr %v23\n'
        '  %v25 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  %v26 = load double, ptr %v25\n'
        '  %v27 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  %v28 = load double, ptr %v27\n'
        '  %v29 = fmul double %v20, %v6\n'
        '  %v30 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v4, ptr %v30\n'
        '  %v31 = fmul double %v29, %v4\n'
        '  %v32 = fmul double %v22, %v2\n'
        '  %v33 = fadd double %v31, %v32\n'
        '  %v34 = fmul double %v24, %v33\n'
        '  %v35 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v34, ptr %v35\n'
        '  %v36 = fmul double %v2, %v2\n'
        '  %v37 = fmul double %v26, %v36\n'
        '  %v38 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v37, ptr %v38\n'
        '  %v39 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v6, ptr %v39\n'
        '  %v40 = fmul double %v29, %v2\n'
        '  %v41 = call double @llvm.sin.f64(double %v8)\n'
        '  %v42 = fmul double %v40, %v41\n'
        '  %v43 = getelementptr inbounds double, ptr %ds, i64 4\n'
        '  store double %v42, ptr %v43\n'
        '  %v44 = fmul double %v28, %v6\n'
        '  %v45 = fmul double %v44, %v2\n'
        '  %v46 = call double @llvm.cos.f64(double %v8)\n'
        '  %v47 = fmul double %v45, %v46\n'
        '  %v48 = getelementptr inbounds double, ptr %ds, i64 5\n'
        '  store double %v47, ptr %v48\n'
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
        '  %v7 = getelementptr inbounds double, ptr %p, i64 3\n'
        '  %v8 = load double, ptr %v7\n'
        '  %v9 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  store double %v2, ptr %v9\n'
        '  %v10 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  store double %v4, ptr %v10\n'
        '  %v11 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  store double %v6, ptr %v11\n'
        '  %v12 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  store double %v8, ptr %v12\n'
        '  %v13 = fneg double %v2\n'
        '  %v14 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  store double %v13, ptr %v14\n'
        '  %v15 = fdiv double 0x3FF0000000000000, %v4\n'
        '  %v16 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  store double %v15, ptr %v16\n'
        '  %v17 = fneg double %v8\n'
        '  %v18 = fmul double %v17, %v2\n'
        '  %v19 = fmul double %v6, %v6\n'
        '  %v20 = fdiv double %v18, %v19\n'
        '  %v21 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  store double %v20, ptr %v21\n'
        '  %v22 = fneg double %v8\n'
        '  %v23 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  store double %v22, ptr %v23\n'
        '  ret void\n'
        '}\n'
        '\n'
    ),
}
#: how many parameters the IR of ``constants`` reads
LLVM_IR_READS = 4
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '572e443030f92073a1a969b3afad858d25e8a4ddb0174d0827e2126ee68b1b37'
