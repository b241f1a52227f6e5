"""Families of steady motions and invariants of the closed state, written into every generated module as data.

A model declares its families of steady motions (``ModelSpec.steady``, ``RigidBody.steady``): each is a
:class:`Steady`, the closed state along a one-parameter family of motions the flow keeps on the family: equilibria
of the closed state (a steady spin of a knife edge or a celt, upright rolling of a disk, straight running of a
sleigh), or, with damping, the same states drifting along the family (the spin decaying).  States the family does not
name are zero there; names that are not states of a fidelity are ignored (one declaration serves every fidelity),
and a family none of whose names is a state of a fidelity is left out of that module.

The emitted block (:func:`block_source`) holds

- ``STEADY_FAMILIES``: ``{name: {"value", "value_state", "description", "mode_names"}}``;
- ``steady_state(k, value, p)``: shape (2, n), the closed state of family number ``k`` (in the order of
  ``STEADY_FAMILIES``) at ``value`` and its derivative with respect to ``value`` (the family's tangent);
- ``STATE_INVARIANTS``: names of functions of the closed state fixed by construction (the rigid bodies' ``n . n = 1``
  and ``omega_n = omega . n``), and ``invariant_gradients(s, p)``, shape (len(STATE_INVARIANTS), n), their
  gradients: the directions the physical phase space leaves out.

The runtime (``knifeedge.stability``) reads only these.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from .codegen import code as _code, unpack as _unpack


@dataclass(frozen=True)
class Steady:
    """A one-parameter family of steady motions (equilibria of the closed state).

    name : identifier (``"steady_spin"``).
    value : the symbol of the family's parameter (``Omega``).
    state : ``{state symbol or name: expression of value and the parameters}``; the other states are zero.
    description : what the motion is.
    mode_names : ``{state name: label}`` naming the modes by their largest component (``{"n_x": "pitch"}``).
    """

    name: str
    value: sp.Symbol
    state: dict
    description: str = ""
    mode_names: dict = field(default_factory=dict)


def block_source(families, state, params, invariants=None, rename=None) -> str:
    """Source of ``STEADY_FAMILIES``, ``steady_state``, ``STATE_INVARIANTS`` and ``invariant_gradients``.

    Parameters
    ----------
    families : the model's :class:`Steady` declarations.
    state, params : symbols of the closed state ``s`` and of ``p``, in order.
    invariants : ``{name: expression of the state}`` fixed by construction (default none).
    rename : ``{declared name: state name}`` (the amplitude fidelity's spin ``phi_dot -> A_phi``).
    """
    from .names import identifier

    rename = rename or {}
    names = [str(x) for x in state]
    meta, bodies = {}, []
    for fam in families:
        values = {rename.get(str(k), str(k)): sp.sympify(v) for k, v in fam.state.items()}
        values = {k: v for k, v in values.items() if k in names}
        if not values:
            continue
        exprs = [values.get(nm, sp.Integer(0)) for nm in names]
        bad = set().union(*(e.free_symbols for e in exprs)) - set(params) - {fam.value}
        if bad:
            raise ValueError(f"steady family {fam.name!r}: undeclared symbols {sorted(map(str, bad))}")
        value_state = next((nm for nm, e in zip(names, exprs) if e == fam.value), "")
        meta[fam.name] = {"value": str(fam.value), "value_state": value_state,
                          "description": fam.description,
                          "mode_names": {rename.get(k, k): v for k, v in sorted(fam.mode_names.items())}}
        lines = [f"        out[0, {i}] = {_code(e)}" for i, e in enumerate(exprs) if e != 0]
        lines += [f"        out[1, {i}] = {_code(sp.diff(e, fam.value))}" for i, e in enumerate(exprs)
                  if sp.diff(e, fam.value) != 0]
        bodies.append((str(fam.value), lines))
    nl = "\n"
    branches = "".join(f"    {'if' if k == 0 else 'elif'} _family == {k}:\n        {identifier(v)} = _value\n"
                       f"{nl.join(lines)}\n"
                       for k, (v, lines) in enumerate(bodies))
    invariants = invariants or {}
    inv_lines = [f"    out[{i}, {j}] = {_code(d)}" for i, e in enumerate(invariants.values())
                 for j, x in enumerate(state) if (d := sp.diff(e, x)) != 0]
    n = len(names)
    unpack = _unpack(names, "s") + _unpack([str(q) for q in params], "p")
    return f'''


#: families of steady motions (derivation/steady.py): name -> the family's parameter ``value`` (``value_state`` is
#: the state equal to it), what the motion is, and names of the modes by their largest state
STEADY_FAMILIES = {meta!r}


@njit(cache=True)
def steady_state(_family, _value, p):
    """Row 0: the closed state of family number ``_family`` of STEADY_FAMILIES at ``_value``; row 1: its derivative
    in ``_value`` (the family's tangent)."""
    out = np.zeros((2, {n}))
{nl.join(_unpack([str(q) for q in params], "p"))}
{branches or "    pass"}
    return out


#: functions of the closed state fixed by construction; their gradients are not physical directions
STATE_INVARIANTS = {tuple(invariants)!r}


@njit(cache=True)
def invariant_gradients(s, p):
    """Gradients of STATE_INVARIANTS, shape ({len(invariants)}, {n})."""
    out = np.zeros(({len(invariants)}, {n}))
{nl.join(unpack)}
{nl.join(inv_lines)}
    return out
'''


#: the steady spin about the body z axis of a rigid body (upright, ``n = e_z``); every fidelity's names
UPRIGHT_SPIN = Steady(
    "steady_spin", sp.Symbol("Omega", real=True), {"n_z": 1, "omega_z": sp.Symbol("Omega", real=True),
                                                    "omega_n": sp.Symbol("Omega", real=True)},
    "upright spin about the body z axis (n = e_z) at the rate Omega",
    {"n_x": "pitch", "A_pitch": "pitch", "n_y": "roll", "A_roll": "roll"})


def holonomic_invariants(spec) -> dict:
    """The holonomic constraints ``f(q) = 0`` of a model (functions of its closed state): invariants of the flow
    (those holding the time are left out: their level sets move)."""
    from .names import t

    return {f"{label} = 0 (holonomic constraint)": f for label, f in zip(spec.holonomic_labels, spec.holonomic)
            if not f.has(t)}


def rigid_invariants(state) -> dict:
    """The invariants of a rigid body's closed state ``(n_x, n_y, n_z, omega_x, omega_y, omega_z, omega_n)``."""
    n, w, wn = state[0:3], state[3:6], state[6]
    return {"|n|^2 = 1 (n is a unit vector)": sum(c * c for c in n) - 1,
            "omega_n = omega . n (the spin carried as a state)": wn - sum(a * b for a, b in zip(w, n))}
