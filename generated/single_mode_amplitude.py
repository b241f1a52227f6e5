"""single_mode, fidelity amplitude: first-order averaged slow flow of the reduced equations.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.
Produced by derivation/emit.py (make derive) from derivation/models.py (model 'single_mode')
through derivation/engine.py, derivation/truncation.py and derivation/averaging.py.
SymPy 1.14.0; input hash sha256:2c27168306428a86f6dd83380d6ab8bf7de99b6712af683b865f91201f0ff67d

Single-mode knife edge (paper section II): a massless bar of length 2L on the table, two masses M/2 hanging at distance ell from its ends; one tilt theta, the contact point shifted by D*theta along the bar (vinculo1, vinculo2).

Tilts theta_i = A_i cos(psi_i), theta_i_dot = -omega_i A_i sin(psi_i), averaged
over independent fast phases psi_i, leading order in (spin rate)/omega.
Averaged phase drifts: d(beta_1)/dt = 0 (the phases do not enter the slow flow).

State vector ``s``:
    s[0] = A_theta      [rad]
    s[1] = A_phi        [rad/time]
Parameter vector ``p``:
    p[0] = g            [length/time^2]
    p[1] = ell          [length]
    p[2] = L            [length]
    p[3] = D            [length]
Slow flow:
    dA_theta/dt = A_phi*A_theta*D/(2*ell)
    dA_phi/dt = -A_theta**2*D*g/(2*L**2)
Invariants (conserved by the slow flow):
    energy: A_phi**2*L**2/2 + A_theta**2*ell*g/2
No pose and no multipliers at this fidelity.
"""
import math

import numpy as np
from numba import njit

MODEL = 'single_mode'
FIDELITY = 'amplitude'
#: what this fidelity is
FIDELITY_DOC = 'first-order averaged slow flow of the reduced equations'
STATE_NAMES = ('A_theta', 'A_phi')
#: unit of each state (``time`` is the unit of t)
STATE_UNITS = ('rad', 'rad/time')
POSE_NAMES = ()
POSE_UNITS = ()
#: what the pose coordinates mean
POSE_DOC = ''
PARAM_NAMES = ('g', 'ell', 'L', 'D')
PARAM_UNITS = ('length/time^2', 'length', 'length', 'length')
#: admissible values of each parameter: 'positive' (> 0) or 'real' (any finite value)
PARAM_DOMAINS = ('positive', 'positive', 'positive', 'positive')
#: default parameter set and initial state (the CLI's defaults); empty if the model declares none
DEFAULT_PARAMS = {'g': 1.0, 'ell': 1.0, 'L': 1.0, 'D': 1.0}
DEFAULT_STATE = {'A_theta': 0.001, 'A_phi': 0.1}
#: (coordinate, rate) pairs of the state
RATE_PAIRS = ()
#: the small coordinates (tilts) of the small-angle fidelities
TILT_NAMES = ('A_theta',)
#: states (or EVENT_NAMES) whose zero crossings are reported as ``reversal_times``
REVERSAL_EVENTS = ('A_phi',)
#: scalar functions of the state returned by ``event_values(s, p)``
EVENT_NAMES = ()
#: largest |value| of each named state where this fidelity holds (empty: everywhere)
VALIDITY = {'A_theta': 0.21}
VALIDITY_DOC = "small tilts: up to this bound the first spin reversal of the small-angle fidelities is within 0.1% of the full model's; the amplitude fidelity also needs the spin rate small against the tilt frequencies"
MULTIPLIER_NAMES = ()
#: non-conservative forces: the module has ``power_dissipated(s, p)``
HAS_DISSIPATION = False
#: model-specific helpers defined at the end of this module
EXPORTS = ()
#: conserved quantities returned by ``invariants`` (``energy`` is the averaged energy per unit mass)
INVARIANT_NAMES = ('energy',)
INPUT_HASH = '2c27168306428a86f6dd83380d6ab8bf7de99b6712af683b865f91201f0ff67d'
SYMPY_VERSION = '1.14.0'
#: floating-point operation counts of each function body (SymPy count_ops after CSE)
OP_COUNTS = {'rhs': 10, 'constants': 6, 'rhs_q': 4, 'energy': 9, 'invariants': 9, 'frequencies': 5, 'growth_rates': 2, 'drive_rates': 5}


@njit(cache=True)
def rhs_into(t, s, p, ds):
    """Write d(state)/dt into ``ds`` (10 operations)."""
    A_theta = s[0]
    A_phi = s[1]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _c0 = ((1.0/2.0))*D
    ds[0] = A_phi*A_theta*_c0/ell
    ds[1] = -(A_theta*A_theta)*_c0*g/(L*L)


@njit(cache=True)
def rhs(t, s, p):
    """Return d(state)/dt as a new array of length 2."""
    ds = np.empty(2)
    rhs_into(t, s, p, ds)
    return ds


@njit(cache=True)
def constants(p):
    """``q``: the parameters, then the 2 parameter-only subexpressions of the right-hand side (6 operations)."""
    q = np.empty(6)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    q[0] = g
    q[1] = ell
    q[2] = L
    q[3] = D
    _c0 = ((1.0/2.0))*D
    q[4] = _c0/ell
    q[5] = -_c0*g/(L*L)
    return q


@njit(cache=True)
def rhs_q_into(t, s, q, ds):
    """``rhs_into`` with ``q = constants(p)`` in place of ``p`` (4 operations)."""
    A_theta = s[0]
    A_phi = s[1]
    g = q[0]
    ell = q[1]
    L = q[2]
    D = q[3]
    _k0 = q[4]
    _k1 = q[5]
    ds[0] = A_phi*A_theta*_k0
    ds[1] = (A_theta*A_theta)*_k1


@njit(cache=True)
def energy(s, p):
    """Averaged energy per unit mass, a conserved quantity of the slow flow (9 operations)."""
    A_theta = s[0]
    A_phi = s[1]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    energy = ((1.0/2.0))*(A_phi*A_phi)*(L*L) + ((1.0/2.0))*(A_theta*A_theta)*ell*g
    return energy


@njit(cache=True)
def invariants(s, p):
    """Conserved quantities ['energy'] (9 operations)."""
    out = np.empty(1)
    A_theta = s[0]
    A_phi = s[1]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    out[0] = ((1.0/2.0))*(A_phi*A_phi)*(L*L) + ((1.0/2.0))*(A_theta*A_theta)*ell*g
    return out


@njit(cache=True)
def frequencies(p):
    """Angular frequencies omega_i of the tilts theta at zero spin (5 operations)."""
    out = np.empty(1)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    out[0] = math.sqrt(g)/math.sqrt(ell)
    return out


@njit(cache=True)
def growth_rates(p):
    """c_i in d(A_i)/dt = c_i A_phi A_i [dimensionless] (2 operations)."""
    out = np.empty(1)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    out[0] = ((1.0/2.0))*D/ell
    return out


@njit(cache=True)
def drive_rates(p):
    """k_i in d(A_phi)/dt = sum_i k_i A_i^2 [1/time^2] (5 operations)."""
    out = np.empty(1)
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    out[0] = -(1.0/2.0)*D*g/(L*L)
    return out


#: operation counts of the Jacobians and of the Jacobian-vector product, once and per column (derivation/jacobian.py)
OP_COUNTS.update(jacobian=11, jacobian_p=26, jvp_once=19, jvp_column=4)

@njit(cache=True)
def jacobian(s, p):
    """d(state rate)/d(state): J[i, j] = d rhs_i / d s_j, shape (2, 2) (11 operations)."""
    out = np.zeros((2, 2))
    A_theta = s[0]
    A_phi = s[1]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _c0 = ((1.0/2.0))*D
    out[0, 0] = A_phi*_c0/ell
    out[0, 1] = A_theta*_c0/ell
    out[1, 0] = -2*A_theta*_c0*g/(L*L)
    return out


@njit(cache=True)
def jacobian_p(s, p):
    """d(state rate)/d(parameters): J[i, j] = d rhs_i / d p_j, shape (2, 4) (26 operations)."""
    out = np.zeros((2, 4))
    A_theta = s[0]
    A_phi = s[1]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _c0 = ((1.0/2.0))*D
    out[0, 1] = -A_phi*A_theta*_c0/(ell*ell)
    out[0, 3] = ((1.0/2.0))*A_phi*A_theta/ell
    out[1, 0] = -(A_theta*A_theta)*_c0/(L*L)
    out[1, 2] = 2*(A_theta*A_theta)*_c0*g/(L*L*L)
    out[1, 3] = -(1.0/2.0)*(A_theta*A_theta)*g/(L*L)
    return out


@njit(cache=True)
def jvp_into(s, p, _V, ds, out):
    """Write d(state)/dt into ``ds`` and ``J(s) _V`` into ``out`` (``_V``, ``out``: (2, k)), the derivatives of the rates along the columns of ``_V`` by forward mode through the right-hand side (19 operations once, 4 per column)."""
    A_theta = s[0]
    A_phi = s[1]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _c0 = ((1.0/2.0))*D
    _p0 = _c0/ell
    _k0 = A_phi*_p0
    _k1 = A_theta*_p0
    _k2 = -2*A_theta*_c0*g/(L*L)
    ds[0] = A_phi*A_theta*_c0/ell
    ds[1] = -(A_theta*A_theta)*_c0*g/(L*L)
    for _j in range(_V.shape[1]):
        _v0 = _V[0, _j]
        _v1 = _V[1, _j]
        out[0, _j] = _k0*_v0 + _k1*_v1
        out[1, _j] = _k2*_v0


@njit(cache=True)
def jvp1_into(s, p, _v, ds, _dv):
    """``jvp_into`` of one column: d(state)/dt into ``ds`` and ``J(s) _v`` into ``_dv`` (vectors of length 2; 23 operations)."""
    A_theta = s[0]
    A_phi = s[1]
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    _c0 = ((1.0/2.0))*D
    _p0 = _c0/ell
    _k0 = A_phi*_p0
    _k1 = A_theta*_p0
    _k2 = -2*A_theta*_c0*g/(L*L)
    ds[0] = A_phi*A_theta*_c0/ell
    ds[1] = -(A_theta*A_theta)*_c0*g/(L*L)
    _v0 = _v[0]
    _v1 = _v[1]
    _dv[0] = _k0*_v0 + _k1*_v1
    _dv[1] = _k2*_v0



#: families of steady motions (derivation/steady.py): name -> the family's parameter ``value`` (``value_state`` is
#: the state equal to it), what the motion is, and names of the modes by their largest state
STEADY_FAMILIES = {'steady_spin': {'value': 'Omega', 'value_state': 'A_phi', 'description': 'upright steady spin theta = 0 at the rate Omega', 'mode_names': {'A_theta': 'tilt', 'theta_dot': 'tilt'}}}


@njit(cache=True)
def steady_state(_family, _value, p):
    """Row 0: the closed state of family number ``_family`` of STEADY_FAMILIES at ``_value``; row 1: its derivative
    in ``_value`` (the family's tangent)."""
    out = np.zeros((2, 2))
    g = p[0]
    ell = p[1]
    L = p[2]
    D = p[3]
    if _family == 0:
        Omega = _value
        out[0, 1] = Omega
        out[1, 1] = 1

    return out


#: functions of the closed state fixed by construction; their gradients are not physical directions
STATE_INVARIANTS = ()


@njit(cache=True)
def invariant_gradients(s, p):
    """Gradients of STATE_INVARIANTS, shape (0, 2)."""
    out = np.zeros((0, 2))
    A_theta = s[0]
    A_phi = s[1]
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
        '  %v5 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  %v6 = load double, ptr %v5\n'
        '  %v7 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  %v8 = load double, ptr %v7\n'
        '  %v9 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  %v10 = load double, ptr %v9\n'
        '  %v11 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  %v12 = load double, ptr %v11\n'
        '  %v13 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  %v14 = load double, ptr %v13\n'
        '  %v15 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  %v16 = load double, ptr %v15\n'
        '  %v17 = fmul double %v4, %v2\n'
        '  %v18 = fmul double %v17, %v14\n'
        '  %v19 = getelementptr inbounds double, ptr %ds, i64 0\n'
        '  store double %v18, ptr %v19\n'
        '  %v20 = fmul double %v2, %v2\n'
        '  %v21 = fmul double %v20, %v16\n'
        '  %v22 = getelementptr inbounds double, ptr %ds, i64 1\n'
        '  store double %v21, ptr %v22\n'
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
        '  %v9 = getelementptr inbounds double, ptr %q, i64 0\n'
        '  store double %v2, ptr %v9\n'
        '  %v10 = getelementptr inbounds double, ptr %q, i64 1\n'
        '  store double %v4, ptr %v10\n'
        '  %v11 = getelementptr inbounds double, ptr %q, i64 2\n'
        '  store double %v6, ptr %v11\n'
        '  %v12 = getelementptr inbounds double, ptr %q, i64 3\n'
        '  store double %v8, ptr %v12\n'
        '  %v13 = fmul double 0x3FE0000000000000, %v8\n'
        '  %v14 = fdiv double %v13, %v4\n'
        '  %v15 = getelementptr inbounds double, ptr %q, i64 4\n'
        '  store double %v14, ptr %v15\n'
        '  %v16 = fneg double %v13\n'
        '  %v17 = fmul double %v16, %v2\n'
        '  %v18 = fmul double %v6, %v6\n'
        '  %v19 = fdiv double %v17, %v18\n'
        '  %v20 = getelementptr inbounds double, ptr %q, i64 5\n'
        '  store double %v19, ptr %v20\n'
        '  ret void\n'
        '}\n'
        '\n'
    ),
}
#: how many parameters the IR of ``constants`` reads
LLVM_IR_READS = 4
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = 'b6362e21933571f7a60fc7f002704397cea66267f0c7fac8fcfef124346ab5c4'
