"""chaplygin_sleigh, fidelity full: exact consequences of the model's Lagrangian and constraints, nothing dropped.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from derivation/sleigh.py (model 'chaplygin_sleigh',
constraints knife_edge) through derivation/engine.py.
Accelerations and multipliers in closed form (symbolic elimination of the multipliers).
SymPy 1.14.0; input hash sha256:d3d00ab5c8114248b873531ff9923386e03815ba1d2ddbddef663b005a54a3c3

Chaplygin sleigh: a rigid body on the plane with a knife edge at its rear contact point (x, y) that forbids sideways motion; heading phi, centre of mass at distance a ahead of the contact, radius of gyration k about the centre of mass; v is the speed along the axis.

State vector ``s`` (closed state; the pose follows by quadrature):
    s[0] = v            [length/time]
    s[1] = phi_dot      [rad/time]
Pose-extended state (``*_pose`` functions) appends:
    s[2] = phi          [rad]
    s[3] = x            [length]
    s[4] = y            [length]
Parameter vector ``p``:
    p[0] = a            [length]
    p[1] = k            [length]
Multipliers (constraint forces in the normalization of the Lagrangian, e.g. per unit mass),
in the order knife_edge.  Energy in the same normalization.
"""
import math

import numpy as np
from numba import njit

MODEL = 'chaplygin_sleigh'
FIDELITY = 'full'
#: what this fidelity is
FIDELITY_DOC = "exact consequences of the model's Lagrangian and constraints, nothing dropped"
STATE_NAMES = ('v', 'phi_dot')
#: unit of each state (``time`` is the unit of t)
STATE_UNITS = ('length/time', 'rad/time')
POSE_NAMES = ('phi', 'x', 'y')
POSE_UNITS = ('rad', 'length', 'length')
#: what the pose coordinates mean
POSE_DOC = "phi: heading of the sleigh's axis; (x, y): position of the contact point on the plane"
PARAM_NAMES = ('a', 'k')
PARAM_UNITS = ('length', 'length')
#: admissible values of each parameter: 'positive' (> 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive')
#: default parameter set and initial state (the CLI's defaults); empty if the model declares none
DEFAULT_PARAMS = {'a': 0.5, 'k': 0.8}
DEFAULT_STATE = {'v': 0.1, 'phi_dot': 0.5}
#: (coordinate, rate) pairs of the state
RATE_PAIRS = ()
#: the small coordinates (tilts) of the small-angle fidelities
TILT_NAMES = ()
#: states (or EVENT_NAMES) whose zero crossings are reported as ``reversal_times``
REVERSAL_EVENTS = ('phi_dot',)
#: scalar functions of the state returned by ``event_values(s, p)``
EVENT_NAMES = ()
#: largest |value| of each named state where this fidelity holds (empty: everywhere)
VALIDITY = {}
VALIDITY_DOC = ''
MULTIPLIER_NAMES = ('knife_edge',)
#: non-conservative forces: the module has ``power_dissipated(s, p)``
HAS_DISSIPATION = False
#: model-specific helpers defined at the end of this module
EXPORTS = ()
INPUT_HASH = 'd3d00ab5c8114248b873531ff9923386e03815ba1d2ddbddef663b005a54a3c3'
SYMPY_VERSION = '1.14.0'
#: how the multipliers are eliminated: "symbolic" (closed form) or "numeric" (a linear solve at every call)
ELIMINATION = 'symbolic'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 9, 'constants': 5, 'rhs_q': 4, 'rhs_pose': 13, 'rhs_pose_q': 8, 'pose_rates': 4, 'energy': 9, 'multipliers': 6}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (9 operations)."""
    v = s[0]
    phi_dot = s[1]
    a = p[0]
    k = p[1]
    ds[0] = a*(phi_dot*phi_dot)
    ds[1] = -a*phi_dot*v/((a*a) + (k*k))


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 2."""
    ds = np.empty(2)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 1 parameter-only subexpressions of the right-hand side (5 operations)."""
    q = np.empty(3)
    a = p[0]
    k = p[1]
    q[0] = a
    q[1] = k
    q[2] = -a/((a*a) + (k*k))
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (4 operations)."""
    v = s[0]
    phi_dot = s[1]
    a = q[0]
    k = q[1]
    _k0 = q[2]
    ds[0] = a*(phi_dot*phi_dot)
    ds[1] = _k0*phi_dot*v


@njit(cache=True)
def rhs_pose_into(t, s, p, ds):
    """Write d(state, pose)/dt into ``ds`` (13 operations)."""
    v = s[0]
    phi_dot = s[1]
    phi = s[2]
    x = s[3]
    y = s[4]
    a = p[0]
    k = p[1]
    ds[0] = a*(phi_dot*phi_dot)
    ds[1] = -a*phi_dot*v/((a*a) + (k*k))
    ds[2] = phi_dot
    ds[3] = v*math.cos(phi)
    ds[4] = v*math.sin(phi)


@njit(cache=True)
def rhs_pose(t, s, p):
    """Return d(state, pose)/dt as a new array of length 5."""
    ds = np.empty(5)
    rhs_pose_into(t, s, p, ds)
    return ds


@njit(cache=True)
def rhs_pose_q_into(t, s, q, ds):
    """``rhs_pose_into`` with ``q = constants(p)`` in place of ``p`` (8 operations)."""
    v = s[0]
    phi_dot = s[1]
    phi = s[2]
    x = s[3]
    y = s[4]
    a = q[0]
    k = q[1]
    _k0 = q[2]
    ds[0] = a*(phi_dot*phi_dot)
    ds[1] = _k0*phi_dot*v
    ds[2] = phi_dot
    ds[3] = v*math.cos(phi)
    ds[4] = v*math.sin(phi)


@njit(cache=True)
def pose_rates(s, p):
    """Return the rates (phi_dot, x_dot, y_dot) of the pose at the pose-extended state ``s`` (4 operations)."""
    out = np.empty(3)
    v = s[0]
    phi_dot = s[1]
    phi = s[2]
    x = s[3]
    y = s[4]
    a = p[0]
    k = p[1]
    out[0] = phi_dot
    out[1] = v*math.cos(phi)
    out[2] = v*math.sin(phi)
    return out


@njit(cache=True)
def energy(s, p):
    """Energy per unit mass (9 operations)."""
    v = s[0]
    phi_dot = s[1]
    a = p[0]
    k = p[1]
    energy = ((1.0/2.0))*(phi_dot*phi_dot)*((a*a) + (k*k)) + ((1.0/2.0))*(v*v)
    return energy


@njit(cache=True)
def multipliers(s, p):
    """Lagrange multipliers (contact forces per unit mass) knife_edge (6 operations)."""
    out = np.empty(1)
    v = s[0]
    phi_dot = s[1]
    a = p[0]
    k = p[1]
    _c0 = (k*k)
    out[0] = _c0*phi_dot*v/(_c0 + (a*a))
    return out



#: how to draw the body (derivation/drawing.py): names of the rows of ``body_points``,
#: segments between them, the contact point, the point masses, the tilts a picture may
#: magnify, the outline curves of ``body_outlines``
DRAWING = {'points': ('C', 'blade_back', 'blade_front', 'blade_top', 'G', 'nose'), 'segments': (('blade_back', 'blade_front'), ('blade_top', 'C'), ('blade_top', 'G'), ('G', 'nose')), 'contact': 'C', 'masses': ('G',), 'magnify': (), 'outlines': ('body',), 'description': 'flat disc (radius sqrt(2) k, so its radius of gyration is k) with its centre of mass G a ahead of the knife edge at the contact C; the knife edge along the axis'}


@njit(cache=True)
def body_points(s, p):
    """World coordinates (z up, table z = 0) of DRAWING["points"] at the pose-extended state ``s``; shape (6, 3) (22 operations)."""
    out = np.empty((6, 3))
    v = s[0]
    phi_dot = s[1]
    phi = s[2]
    x = s[3]
    y = s[4]
    a = p[0]
    k = p[1]
    _c0 = math.cos(phi)
    _c1 = ((1.0/2.0))*k
    _c2 = _c0*_c1
    _c3 = math.sin(phi)
    _c4 = _c1*_c3
    _c5 = ((1.0/3.0))*k
    _c6 = a + math.sqrt(2)*k
    out[0, 0] = x
    out[0, 1] = y
    out[0, 2] = 0
    out[1, 0] = -_c2 + x
    out[1, 1] = -_c4 + y
    out[1, 2] = 0
    out[2, 0] = _c2 + x
    out[2, 1] = _c4 + y
    out[2, 2] = 0
    out[3, 0] = x
    out[3, 1] = y
    out[3, 2] = _c5
    out[4, 0] = _c0*a + x
    out[4, 1] = _c3*a + y
    out[4, 2] = _c5
    out[5, 0] = _c0*_c6 + x
    out[5, 1] = _c3*_c6 + y
    out[5, 2] = _c5
    return out


@njit(cache=True)
def body_outlines(s, p, uu):
    """World coordinates of the curves DRAWING["outlines"] at the parameters ``uu`` in [0, 2 pi); shape (1, len(uu), 3) (19 operations)."""
    out = np.empty((1, uu.shape[0], 3))
    v = s[0]
    phi_dot = s[1]
    phi = s[2]
    x = s[3]
    y = s[4]
    a = p[0]
    k = p[1]
    for j in range(uu.shape[0]):
        u = uu[j]
        _c0 = math.sin(phi)
        _c1 = math.sqrt(2)*k
        _c2 = _c1*math.sin(u)
        _c3 = math.cos(phi)
        _c4 = _c1*math.cos(u) + a
        out[0, j, 0] = -_c0*_c2 + _c3*_c4 + x
        out[0, j, 1] = _c0*_c4 + _c2*_c3 + y
        out[0, j, 2] = ((1.0/3.0))*k
    return out


#: operation counts of the Jacobians and of the Jacobian-vector product, once and per column (derivation/jacobian.py)
OP_COUNTS.update(jacobian=14, jacobian_p=25, jvp_once=20, jvp_column=4)

@njit(cache=True)
def jacobian(s, p):
    """d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape (2, 2) (14 operations)."""
    out = np.zeros((2, 2))
    v = s[0]
    phi_dot = s[1]
    a = p[0]
    k = p[1]
    out[0, 1] = 2*a*phi_dot
    out[1, 0] = -a*phi_dot/((a*a) + (k*k))
    out[1, 1] = -a*v/((a*a) + (k*k))
    return out


@njit(cache=True)
def jacobian_p(s, p):
    """d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape (2, 2) (25 operations)."""
    out = np.zeros((2, 2))
    v = s[0]
    phi_dot = s[1]
    a = p[0]
    k = p[1]
    out[0, 0] = (phi_dot*phi_dot)
    out[1, 0] = 2*(a*a)*phi_dot*v/(((a*a) + (k*k))*((a*a) + (k*k))) - phi_dot*v/((a*a) + (k*k))
    out[1, 1] = 2*a*k*phi_dot*v/(((a*a) + (k*k))*((a*a) + (k*k)))
    return out


@njit(cache=True)
def jvp_into(s, p, _V, ds, out):
    """Write d(state)/dt into ``ds`` and ``J(s) _V`` into ``out`` (``_V``, ``out``: (2, k)), the derivatives of the rates along the columns of ``_V`` by forward mode through the right-hand side (20 operations once, 4 per column)."""
    v = s[0]
    phi_dot = s[1]
    a = p[0]
    k = p[1]
    _p0 = a*phi_dot
    _p1 = 1/((a*a) + (k*k))
    _k0 = 2*_p0
    _k1 = -_p0*_p1
    _k2 = -_p1*a*v
    ds[0] = a*(phi_dot*phi_dot)
    ds[1] = -a*phi_dot*v/((a*a) + (k*k))
    for _j in range(_V.shape[1]):
        _v0 = _V[0, _j]
        _v1 = _V[1, _j]
        out[0, _j] = _k0*_v1
        out[1, _j] = _k1*_v0 + _k2*_v1


@njit(cache=True)
def jvp1_into(s, p, _v, ds, _dv):
    """``jvp_into`` of one column: d(state)/dt into ``ds`` and ``J(s) _v`` into ``_dv`` (vectors of length 2; 24 operations)."""
    v = s[0]
    phi_dot = s[1]
    a = p[0]
    k = p[1]
    _p0 = a*phi_dot
    _p1 = 1/((a*a) + (k*k))
    _k0 = 2*_p0
    _k1 = -_p0*_p1
    _k2 = -_p1*a*v
    ds[0] = a*(phi_dot*phi_dot)
    ds[1] = -a*phi_dot*v/((a*a) + (k*k))
    _v0 = _v[0]
    _v1 = _v[1]
    _dv[0] = _k0*_v1
    _dv[1] = _k1*_v0 + _k2*_v1



#: families of steady motions (derivation/steady.py): name -> the family's parameter ``value`` (``value_state`` is
#: the state equal to it), what the motion is, and names of the modes by their largest state
STEADY_FAMILIES = {'straight': {'value': 'V', 'value_state': 'v', 'description': 'straight running at the speed V (phi_dot = 0)', 'mode_names': {}}}


@njit(cache=True)
def steady_state(_family, _value, p):
    """Row 0: the closed state of family number ``_family`` of STEADY_FAMILIES at ``_value``; row 1: its derivative
    in ``_value`` (the family's tangent)."""
    out = np.zeros((2, 2))
    a = p[0]
    k = p[1]
    if _family == 0:
        V = _value
        out[0, 0] = V
        out[1, 0] = 1

    return out


#: functions of the closed state fixed by construction; their gradients are not physical directions
STATE_INVARIANTS = ()


@njit(cache=True)
def invariant_gradients(s, p):
    """Gradients of STATE_INVARIANTS, shape (0, 2)."""
    out = np.zeros((0, 2))
    v = s[0]
    phi_dot = s[1]
    a = p[0]
    k = p[1]

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
        '  %v5 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  %v6 = load double, ptr %v5\n'
        '  %v7 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  %v8 = load double, ptr %v7\n'
        '  %v9 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  %v10 = load double, ptr %v9\n'
        '  %v11 = fmul double %v4, %v4\n'
        '  %v12 = fmul double %v6, %v11\n'
        '  %v13 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v12, ptr %v13\n'
        '  %v14 = fmul double %v10, %v4\n'
        '  %v15 = fmul double %v14, %v2\n'
        '  %v16 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v15, ptr %v16\n'
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
        '  %v11 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  %v12 = load double, ptr %v11\n'
        '  %v13 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  %v14 = load double, ptr %v13\n'
        '  %v15 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  %v16 = load double, ptr %v15\n'
        '  %v17 = fmul double %v4, %v4\n'
        '  %v18 = fmul double %v12, %v17\n'
        '  %v19 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v18, ptr %v19\n'
        '  %v20 = fmul double %v16, %v4\n'
        '  %v21 = fmul double %v20, %v2\n'
        '  %v22 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v21, ptr %v22\n'
        '  %v23 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v4, ptr %v23\n'
        '  %v24 = call double @llvm.cos.f64(double %v6)\n'
        '  %v25 = fmul double %v2, %v24\n'
        '  %v26 = getelementptr inbounds double, ptr %ds, i64 3\n'
        '  store double %v25, ptr %v26\n'
        '  %v27 = call double @llvm.sin.f64(double %v6)\n'
        '  %v28 = fmul double %v2, %v27\n'
        '  %v29 = getelementptr inbounds double, ptr %ds, i64 4\n'
        '  store double %v28, ptr %v29\n'
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
        '  %v7 = fneg double %v2\n'
        '  %v8 = fmul double %v2, %v2\n'
        '  %v9 = fmul double %v4, %v4\n'
        '  %v10 = fadd double %v8, %v9\n'
        '  %v11 = fdiv double %v7, %v10\n'
        '  %v12 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  store double %v11, ptr %v12\n'
        '  ret void\n'
        '}\n'
        '\n'
    ),
}
#: how many parameters the IR of ``constants`` reads
LLVM_IR_READS = 2
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = '056c11ab05e97b4297ca7b624fe7f9417a3bf32930cb919921e6ce70a7d2e724'
