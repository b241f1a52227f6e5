"""two_mode, fidelity amplitude: first-order averaged slow flow of the reduced equations.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from derivation/models.py (model 'two_mode')
through derivation/engine.py, derivation/truncation.py and derivation/averaging.py.
SymPy 1.14.0; input hash sha256:9fa561905a8fde9ac51a0147d4edcd4b8cc08563fb2bfd889eb59449d9472bf4

Two-mode knife edge (paper section III): tilts theta1, theta2; the contact is the lowest point of a circle of radius D whose plane makes the chiral angle alpha with the bar (Const22, Const23).

Tilts theta_i = A_i cos(psi_i), theta_i_dot = -omega_i A_i sin(psi_i), averaged
over independent fast phases psi_i, leading order in (spin rate)/omega.
Averaged phase drifts: d(beta_1)/dt = 0, d(beta_2)/dt = 0 (the phases do not enter the slow flow).

State vector ``s``:
    s[0] = A1           [rad]
    s[1] = A2           [rad]
    s[2] = A_phi        [rad/time]
Parameter vector ``p``:
    p[0] = g            [length/time^2]
    p[1] = ell          [length]
    p[2] = L            [length]
    p[3] = D            [length]
    p[4] = alpha        [rad]
Slow flow:
    dA1/dt = -A1*A_phi*D*sin(2*alpha)/(4*ell)
    dA2/dt = A2*A_phi*D*ell*sin(2*alpha)/(4*(L**2 + ell**2))
    dA_phi/dt = D*g*(A1**2*(L**2 + ell**2) - A2**2*ell**2)*sin(2*alpha)/(4*L**2*(L**2 + ell**2))
Invariants (conserved by the slow flow):
    energy: A1**2*ell*g/2 + A2**2*ell*g/2 + A_phi**2*L**2/2
    log_A1_A2: ell**2*log(A1)/(L**2 + ell**2) + log(A2)
No pose and no multipliers at this fidelity.
"""
import math

import numpy as np
from numba import njit

MODEL = 'two_mode'
FIDELITY = 'amplitude'
#: what this fidelity is
FIDELITY_DOC = 'first-order averaged slow flow of the reduced equations'
STATE_NAMES = ('A1', 'A2', 'A_phi')
#: unit of each state (``time`` is the unit of t)
STATE_UNITS = ('rad', 'rad', 'rad/time')
POSE_NAMES = ()
POSE_UNITS = ()
#: what the pose coordinates mean
POSE_DOC = ''
PARAM_NAMES = ('g', 'ell', 'L', 'D', 'alpha')
PARAM_UNITS = ('length/time^2', 'length', 'length', 'length', 'rad')
#: admissible values of each parameter: 'positive' (> 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive', 'positive', 'positive', 'real')
#: default parameter set and initial state (the CLI's defaults); empty if the model declares none
DEFAULT_PARAMS = {'g': 1.0, 'ell': 1.0, 'L': 2.0, 'D': 0.5, 'alpha': 0.7853981633974483}
DEFAULT_STATE = {'A1': 0.001, 'A2': 0.001, 'A_phi': 0.1}
#: (coordinate, rate) pairs of the state
RATE_PAIRS = ()
#: the small coordinates (tilts) of the small-angle fidelities
TILT_NAMES = ('A1', 'A2')
#: states (or EVENT_NAMES) whose zero crossings are reported as ``reversal_times``
REVERSAL_EVENTS = ('A_phi',)
#: scalar functions of the state returned by ``event_values(s, p)``
EVENT_NAMES = ()
#: largest |value| of each named state where this fidelity holds (empty: everywhere)
VALIDITY = {'A1': 0.6, 'A2': 0.6}
VALIDITY_DOC = "small tilts: up to this bound the first spin reversal of the small-angle fidelities is within 0.1% of the full model's; the amplitude fidelity also needs the spin rate small against the tilt frequencies"
MULTIPLIER_NAMES = ()
#: non-conservative forces: the module has ``power_dissipated(s, p)``
HAS_DISSIPATION = False
#: model-specific helpers defined at the end of this module
EXPORTS = ()
#: conserved quantities returned by ``invariants`` (``energy`` is the averaged energy per unit mass)
INVARIANT_NAMES = ('energy', 'log_A1_A2')
INPUT_HASH = '9fa561905a8fde9ac51a0147d4edcd4b8cc08563fb2bfd889eb59449d9472bf4'
SYMPY_VERSION = '1.14.0'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 24, 'constants': 14, 'rhs_q': 10, 'energy': 12, 'invariants': 19, 'frequencies': 12, 'growth_rates': 11, 'drive_rates': 12}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (24 operations)."""
    A1 = s[0]
    A2 = s[1]
    A_phi = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = ((1.0/4.0))*D*math.sin(2*alpha)
    _c1 = A_phi*_c0
    _c2 = (L*L)
    _c3 = (ell*ell)
    _c4 = _c2 + _c3
    _c5 = 1/_c4
    ds[0] = -A1*_c1/ell
    ds[1] = A2*_c1*_c5*ell
    ds[2] = _c0*_c5*g*((A1*A1)*_c4 - (A2*A2)*_c3)/_c2


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 3."""
    ds = np.empty(3)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 5 parameter-only subexpressions of the right-hand side (14 operations)."""
    q = np.empty(10)
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
    _c0 = ((1.0/4.0))*D*math.sin(2*alpha)
    _c1 = (L*L)
    _c2 = (ell*ell)
    _c3 = _c1 + _c2
    _c4 = _c0/_c3
    q[5] = -_c0/ell
    q[6] = _c4*ell
    q[7] = _c3
    q[8] = -_c2
    q[9] = _c4*g/_c1
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (10 operations)."""
    A1 = s[0]
    A2 = s[1]
    A_phi = s[2]
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
    ds[0] = A1*A_phi*_k0
    ds[1] = A2*A_phi*_k1
    ds[2] = _k4*((A1*A1)*_k2 + (A2*A2)*_k3)


@njit(cache=True)
def energy(s, p):
    """Averaged energy per unit mass, a conserved quantity of the slow flow (12 operations)."""
    A1 = s[0]
    A2 = s[1]
    A_phi = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = ((1.0/2.0))*ell*g
    energy = (A1*A1)*_c0 + (A2*A2)*_c0 + ((1.0/2.0))*(A_phi*A_phi)*(L*L)
    return energy


@njit(cache=True)
def invariants(s, p):
    """Conserved quantities ['energy', 'log_A1_A2'] (19 operations)."""
    out = np.empty(2)
    A1 = s[0]
    A2 = s[1]
    A_phi = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = ((1.0/2.0))*ell*g
    _c1 = (L*L)
    _c2 = (ell*ell)
    out[0] = (A1*A1)*_c0 + (A2*A2)*_c0 + ((1.0/2.0))*(A_phi*A_phi)*_c1
    out[1] = _c2*math.log(A1)/(_c1 + _c2) + math.log(A2)
    return out


@njit(cache=True)
def frequencies(p):
    """Angular frequencies omega_i of the tilts theta1, theta2 at zero spin (12 operations)."""
    out = np.empty(2)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = math.sqrt(ell)
    _c1 = math.sqrt(g)
    out[0] = _c1/_c0
    out[1] = _c0*_c1/math.sqrt((L*L) + (ell*ell))
    return out


@njit(cache=True)
def growth_rates(p):
    """c_i in d(A_i)/dt = c_i A_phi A_i [dimensionless] (11 operations)."""
    out = np.empty(2)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = ((1.0/4.0))*D*math.sin(2*alpha)
    out[0] = -_c0/ell
    out[1] = _c0*ell/((L*L) + (ell*ell))
    return out


@njit(cache=True)
def drive_rates(p):
    """k_i in d(A_phi)/dt = sum_i k_i A_i^2 [1/time^2] (12 operations)."""
    out = np.empty(2)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = (L*L)
    _c1 = ((1.0/4.0))*D*g*math.sin(2*alpha)/_c0
    _c2 = (ell*ell)
    out[0] = _c1
    out[1] = -_c1*_c2/(_c0 + _c2)
    return out


#: operation counts of the Jacobians and of the Jacobian-vector product, once and per column (derivation/jacobian.py)
OP_COUNTS.update(jacobian=32, jacobian_p=127, jvp_once=41, jvp_column=10)

@njit(cache=True)
def jacobian(s, p):
    """d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape (3, 3) (32 operations)."""
    out = np.zeros((3, 3))
    A1 = s[0]
    A2 = s[1]
    A_phi = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = ((1.0/4.0))*D*math.sin(2*alpha)
    _c1 = A_phi*_c0
    _c2 = (L*L)
    _c3 = (ell*ell)
    _c4 = _c2 + _c3
    _c5 = 1/_c4
    out[0, 0] = -_c1/ell
    out[0, 2] = -A1*_c0/ell
    out[1, 1] = _c1*_c5*ell
    out[1, 2] = A2*_c0*_c5*ell
    out[2, 0] = 2*A1*_c0*_c4*_c5*g/_c2
    out[2, 1] = -2*A2*_c0*_c3*_c5*g/_c2
    return out


@njit(cache=True)
def jacobian_p(s, p):
    """d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape (3, 5) (127 operations)."""
    out = np.zeros((3, 5))
    A1 = s[0]
    A2 = s[1]
    A_phi = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = ((1.0/4.0))*D*math.sin(2*alpha)
    _d0_3 = ((1.0/4.0))*math.sin(2*alpha)
    _d0_4 = ((1.0/2.0))*D*math.cos(2*alpha)
    _c1 = A_phi*_c0
    _d1_3 = A_phi*_d0_3
    _d1_4 = A_phi*_d0_4
    _c2 = (L*L)
    _d2_2 = 2*L
    _c3 = (ell*ell)
    _d3_1 = 2*ell
    _c4 = _c2 + _c3
    _c5 = 1/_c4
    _d5_1 = -_d3_1/(_c4*_c4)
    _d5_2 = -_d2_2/(_c4*_c4)
    out[0, 1] = A1*_c1/(ell*ell)
    out[0, 3] = -A1*_d1_3/ell
    out[0, 4] = -A1*_d1_4/ell
    out[1, 1] = A2*_c1*_c5 + A2*_c1*_d5_1*ell
    out[1, 2] = A2*_c1*_d5_2*ell
    out[1, 3] = A2*_c5*_d1_3*ell
    out[1, 4] = A2*_c5*_d1_4*ell
    out[2, 0] = _c0*_c5*((A1*A1)*_c4 - (A2*A2)*_c3)/_c2
    out[2, 1] = (A1*A1)*_c0*_c5*_d3_1*g/_c2 - (A2*A2)*_c0*_c5*_d3_1*g/_c2 + _c0*_d5_1*g*((A1*A1)*_c4 - (A2*A2)*_c3)/_c2
    out[2, 2] = (A1*A1)*_c0*_c5*_d2_2*g/_c2 + _c0*_d5_2*g*((A1*A1)*_c4 - (A2*A2)*_c3)/_c2 - _c0*_c5*_d2_2*g*((A1*A1)*_c4 - (A2*A2)*_c3)/(_c2*_c2)
    out[2, 3] = _c5*_d0_3*g*((A1*A1)*_c4 - (A2*A2)*_c3)/_c2
    out[2, 4] = _c5*_d0_4*g*((A1*A1)*_c4 - (A2*A2)*_c3)/_c2
    return out


@njit(cache=True)
def jvp_into(s, p, _V, ds, out):
    """Write d(state)/dt into ``ds`` and ``J(s) _V`` into ``out`` (``_V``, ``out``: (3, k)), the derivatives of the rates along the columns of ``_V`` by forward mode through the right-hand side (41 operations once, 10 per column)."""
    A1 = s[0]
    A2 = s[1]
    A_phi = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = ((1.0/4.0))*D*math.sin(2*alpha)
    _c1 = A_phi*_c0
    _c2 = (L*L)
    _c3 = (ell*ell)
    _c4 = _c2 + _c3
    _c5 = 1/_c4
    _p0 = 1/ell
    _p1 = _c5*ell
    _p2 = 2*_c0*_c5*g/_c2
    _k0 = -_c1*_p0
    _k1 = -A1*_p0
    _k2 = _c1*_p1
    _k3 = A2*_p1
    _k4 = -A2*_c3*_p2
    _k5 = A1*_c4*_p2
    ds[0] = -A1*_c1/ell
    ds[1] = A2*_c1*_c5*ell
    ds[2] = _c0*_c5*g*((A1*A1)*_c4 - (A2*A2)*_c3)/_c2
    for _j in range(_V.shape[1]):
        _v0 = _V[0, _j]
        _v1 = _V[1, _j]
        _v2 = _V[2, _j]
        _t1 = _c0*_v2
        out[0, _j] = _k0*_v0 + _k1*_t1
        out[1, _j] = _k2*_v1 + _k3*_t1
        out[2, _j] = _k4*_v1 + _k5*_v0


@njit(cache=True)
def jvp1_into(s, p, _v, ds, _dv):
    """``jvp_into`` of one column: d(state)/dt into ``ds`` and ``J(s) _v`` into ``_dv`` (vectors of length 3; 51 operations)."""
    A1 = s[0]
    A2 = s[1]
    A_phi = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
    _c0 = ((1.0/4.0))*D*math.sin(2*alpha)
    _c1 = A_phi*_c0
    _c2 = (L*L)
    _c3 = (ell*ell)
    _c4 = _c2 + _c3
    _c5 = 1/_c4
    _p0 = 1/ell
    _p1 = _c5*ell
    _p2 = 2*_c0*_c5*g/_c2
    _k0 = -_c1*_p0
    _k1 = -A1*_p0
    _k2 = _c1*_p1
    _k3 = A2*_p1
    _k4 = -A2*_c3*_p2
    _k5 = A1*_c4*_p2
    ds[0] = -A1*_c1/ell
    ds[1] = A2*_c1*_c5*ell
    ds[2] = _c0*_c5*g*((A1*A1)*_c4 - (A2*A2)*_c3)/_c2
    _v0 = _v[0]
    _v1 = _v[1]
    _v2 = _v[2]
    _t1 = _c0*_v2
    _dv[0] = _k0*_v0 + _k1*_t1
    _dv[1] = _k2*_v1 + _k3*_t1
    _dv[2] = _k4*_v1 + _k5*_v0



#: families of steady motions (derivation/steady.py): name -> the family's parameter ``value`` (``value_state`` is
#: the state equal to it), what the motion is, and names of the modes by their largest state
STEADY_FAMILIES = {'steady_spin': {'value': 'Omega', 'value_state': 'A_phi', 'description': 'upright steady spin theta1 = theta2 = 0 at the rate Omega', 'mode_names': {'A1': 'theta1', 'A2': 'theta2', 'theta1_dot': 'theta1', 'theta2_dot': 'theta2'}}}


@njit(cache=True)
def steady_state(_family, _value, p):
    """Row 0: the closed state of family number ``_family`` of STEADY_FAMILIES at ``_value``; row 1: its derivative
    in ``_value`` (the family's tangent)."""
    out = np.zeros((2, 3))
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]
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
    A1 = s[0]
    A2 = s[1]
    A_phi = s[2]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    alpha = p[4]

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
        '  %v23 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  %v24 = load double, ptr %v23\n'
        '  %v25 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  %v26 = load double, ptr %v25\n'
        '  %v27 = fmul double %v2, %v6\n'
        '  %v28 = fmul double %v27, %v18\n'
        '  %v29 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v28, ptr %v29\n'
        '  %v30 = fmul double %v4, %v6\n'
        '  %v31 = fmul double %v30, %v20\n'
        '  %v32 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v31, ptr %v32\n'
        '  %v33 = fmul double %v2, %v2\n'
        '  %v34 = fmul double %v33, %v22\n'
        '  %v35 = fmul double %v4, %v4\n'
        '  %v36 = fmul double %v35, %v24\n'
        '  %v37 = fadd double %v34, %v36\n'
        '  %v38 = fmul double %v26, %v37\n'
        '  %v39 = getelementptr inbounds double, ptr %ds, i64 2\n'
        '  store double %v38, ptr %v39\n'
        '  ret i32 0\n'
        '}\n'
        '\n'
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
        '  %v16 = fmul double 0x3FD0000000000000, %v8\n'
        '  %v17 = fmul double 0x4000000000000000, %v10\n'
        '  %v18 = call double @llvm.sin.f64(double %v17)\n'
        '  %v19 = fmul double %v16, %v18\n'
        '  %v20 = fmul double %v6, %v6\n'
        '  %v21 = fmul double %v4, %v4\n'
        '  %v22 = fadd double %v20, %v21\n'
        '  %v23 = fdiv double %v19, %v22\n'
        '  %v24 = fneg double %v19\n'
        '  %v25 = fdiv double %v24, %v4\n'
        '  %v26 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  store double %v25, ptr %v26\n'
        '  %v27 = fmul double %v23, %v4\n'
        '  %v28 = getelementptr inbounds double, ptr %q, i64 6\n'
        '  store double %v27, ptr %v28\n'
        '  %v29 = getelementptr inbounds double, ptr %q, i64 7\n'
        '  store double %v22, ptr %v29\n'
        '  %v30 = fneg double %v21\n'
        '  %v31 = getelementptr inbounds double, ptr %q, i64 8\n'
        '  store double %v30, ptr %v31\n'
        '  %v32 = fmul double %v23, %v2\n'
        '  %v33 = fdiv double %v32, %v20\n'
        '  %v34 = getelementptr inbounds double, ptr %q, i64 9\n'
        '  store double %v33, ptr %v34\n'
        '  ret void\n'
        '}\n'
        'declare double @llvm.sin.f64(double)\n'
    ),
}
#: how many parameters the IR of ``constants`` reads
LLVM_IR_READS = 5
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = 'b3498ac502163cd2bc47fa0d4c2bda5c833dee196b82064814ea91293c65f2a8'
