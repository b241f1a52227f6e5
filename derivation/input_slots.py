"""Run-time inputs in the generated code: each input as parameter slots, affine in the time.

A model's ``inputs`` (:class:`~.engine.ModelSpec`) are given at run time as a
number, samples or a function of the time.  The generated functions read them
from slots appended to the parameter vector ``p``, after the model's own
parameters (``PARAM_NAMES``)::

    p[NP]             input_t0: the time origin of the slots
    p[NP + 1 + 2 i]   <u>_value: the value of input u at input_t0
    p[NP + 2 + 2 i]   <u>_rate: its rate, constant over the slots' interval

so that, in every function, ``u_i = p[NP + 1 + 2 i] + p[NP + 2 + 2 i] (t - p[NP])``
and ``du_i/dt = p[NP + 2 + 2 i]``.  Within an interval where the input is
affine in the time (a constant, or a piecewise-linear input between two
samples) the right-hand side is then exact, with the time the integrator
passes; ``knifeedge.simulate`` runs such inputs interval by interval.  For an
evaluation at one time ``t`` the slots are ``(t, u(t), du/dt(t))``.

:func:`lowered` rewrites a reduced system so: the inputs and their rates
replaced by the slots, which are appended to the spec's ``params`` as
:class:`Slot` symbols (``PARAM_NAMES`` leaves them out).
The emitter needs nothing else.
"""
from __future__ import annotations

import copy
import dataclasses

import sympy as sp

from . import names
from .codegen import const
from .names import t


class Slot(sp.Symbol):
    """A parameter slot of the inputs: printed as the name it has (like a user's name), never equal to one.

    Named ``Symbol`` for SymPy's canonical order (as :class:`.names.Own`).  The spec's contract refuses
    a user's name equal to a slot's (:func:`slot_names`).  Never hoisted into ``constants(p)``
    (:func:`.codegen.hoist_parameters`): ``q = constants(p)`` holds each slot as ``p`` does and no expression
    of one, so a compiled run can write an input's value at every evaluation into ``q``'s slots (a function
    of the time, ``knifeedge/inputs.py``).
    """

    __slots__ = ()
    hoistable = False


Slot.__name__ = Slot.__qualname__ = "Symbol"


def slot_names(inputs) -> tuple:
    """The names of the slots of ``inputs``: ``input_t0``, then ``<u>_value``, ``<u>_rate`` per input."""
    out = ["input_t0"]
    for u in inputs:
        ident = names.identifier(str(u))
        out += [f"{ident}_value", f"{ident}_rate"]
    return tuple(out)


def slots(spec) -> tuple:
    """The slot symbols of ``spec``'s inputs (:func:`slot_names`)."""
    return tuple(Slot(n, real=True) for n in slot_names(spec.inputs))


def substitution(spec) -> dict:
    """``{input: value + rate (t - t0), input rate: rate}`` in the slots of :func:`slots`."""
    origin, *rest = slots(spec)
    out = {}
    for k, (u, r) in enumerate(zip(spec.inputs, spec.input_rates)):
        value, rate = rest[2 * k], rest[2 * k + 1]
        out[u] = value + rate * (t - origin)
        out[r] = rate
    return out


def rates_read(system) -> tuple:
    """Names of the inputs whose rates the equations read (an input in a constraint)."""
    spec = system.spec
    exprs = [*system.explicit, *system.multipliers, *system.dependent_rates.values(),
             *(system.kkt.exprs() if system.kkt is not None else ())]
    return tuple(str(u) for u, r in zip(spec.inputs, spec.input_rates)
                 if any(sp.sympify(e).has(r) for e in exprs))


def lowered(system):
    """``system`` (an :class:`~.engine.ReducedSystem` with inputs) with the inputs in parameter slots.

    Returns a copy whose spec's ``params`` end with :func:`slots` and whose expressions hold the slots
    and the time in place of the inputs and their rates; the spec also carries ``input_rates_read``
    (:func:`rates_read`) for the module's metadata.
    """
    spec = system.spec
    read = rates_read(system)
    sub = substitution(spec)
    spec2 = copy.copy(spec)  # the frozen spec's fields, without its contract (the slots are not user symbols)
    object.__setattr__(spec2, "params", tuple(spec.params) + slots(spec))
    object.__setattr__(spec2, "input_rates_read", read)

    def low(e):
        return None if e is None else sp.sympify(e).xreplace(sub)

    def low_matrix(m):
        return m.applyfunc(low)

    kkt = system.kkt
    if kkt is not None:
        kkt = dataclasses.replace(kkt, mass=low_matrix(kkt.mass), forcing=low_matrix(kkt.forcing),
                                  constraint=low_matrix(kkt.constraint), bias=low_matrix(kkt.bias),
                                  constraint_general=low_matrix(kkt.constraint_general),
                                  unreduced=tuple(low_matrix(sp.Matrix(m)) for m in kkt.unreduced))
    return dataclasses.replace(
        system, spec=spec2, mass_matrix=low_matrix(system.mass_matrix), forcing=low_matrix(system.forcing),
        explicit=low_matrix(system.explicit), multipliers=low_matrix(system.multipliers),
        multipliers_implicit=low_matrix(system.multipliers_implicit), energy=low(system.energy),
        pose_rates={q: low(e) for q, e in system.pose_rates.items()}, power=low(system.power),
        power_input=low(system.power_input),
        dependent_rates={q: low(e) for q, e in system.dependent_rates.items()}, kkt=kkt)


def metadata(spec) -> tuple:
    """The metadata constants of a module with inputs (none without)."""
    if not getattr(spec, "inputs", ()):  # a rigid body has none
        return ()
    return (const("INPUT_NAMES", tuple(map(str, spec.inputs)),
                  "quantities given at run time (simulate(..., inputs={name: ...})); the functions read them from\n"
                  "slots after the parameters: p[NP] = time origin t0, then per input its value at t0 and its rate"),
            const("INPUT_RATES_READ", tuple(getattr(spec, "input_rates_read", ())),
                  "inputs whose rate du/dt the equations read (an input in a constraint)"))
