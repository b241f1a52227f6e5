"""Run-time inputs: quantities a model declares as ``inputs`` (a control torque), given to ``simulate``.

``simulate(model, y0, t_span, p, inputs={"tau": value})`` takes, per input:

- a number: the input is constant;
- samples ``(t_array, u_array)``: the input is the **piecewise-linear** interpolant of the samples (straight
  lines between consecutive samples, which must cover the run's ``t_span``);
- a function of the time ``u(t)``, called at every evaluation of the right-hand side at the true time: on the
  compiled methods a ``numba.njit`` function (``knifeedge.simulate.driven_model``: the compiled right-hand
  side calls it), on the SciPy methods (``method="scipy:..."``) any Python callable.  A model that reads the input's rate (an input
  in a constraint, ``INPUT_RATES_READ``) takes a pair ``(u, du_dt)`` of functions on the compiled methods.

The generated functions read each input from parameter slots appended to ``p``, in which it is affine in
the time (``derivation/input_slots.py``: ``input_t0``, then ``<u>_value`` and ``<u>_rate`` per input).  A
run with samples is therefore made of one run per interval between consecutive sample times (over which
every input is affine): exact for the piecewise-linear input, with a restart of the integrator where the
input's slope jumps (``knifeedge.simulate._run_segments``).  Constants need one interval.  A function input
on a compiled method writes its value (and rate) at every evaluation into the slots of ``q = constants(p)``,
which holds each slot as ``p`` does (``derivation/input_slots.py``), before the model's right-hand side reads
them: one compiled right-hand side (``knifeedge.simulate.driven_model``) for every compiled method.
"""
from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
from numba.core.registry import CPUDispatcher

from . import _validate

KINDS = ("constant", "samples", "function")


class Inputs:
    """The validated inputs of a run: one entry per name of ``model.input_names``, in that order.

    ``kinds[i]`` is one of :data:`KINDS`; ``data[i]`` a float, a pair of arrays ``(t, u)`` (increasing
    times) or a pair ``(u, du_dt)`` of callables (``du_dt`` None when not given).
    """

    def __init__(self, names: tuple, kinds: tuple, data: tuple, rates_read: tuple = ()):
        self.names, self.kinds, self.data, self.rates_read = names, kinds, data, tuple(rates_read)

    def __repr__(self) -> str:
        return f"Inputs({', '.join(f'{n}: {k}' for n, k in zip(self.names, self.kinds))})"

    @property
    def has_function(self) -> bool:
        return "function" in self.kinds

    def functions(self, n_params: int) -> tuple:
        """``(slot, u, du_dt)`` of each function input: the index in ``p`` of its value slot (after ``n_params``
        parameters), the function and its rate (``None`` where the model does not read the rate)."""
        return tuple((n_params + 1 + 2 * i, data[0], data[1] if name in self.rates_read else None)
                     for i, (name, kind, data) in enumerate(zip(self.names, self.kinds, self.data))
                     if kind == "function")

    def breakpoints(self, t0: float, t1: float) -> np.ndarray:
        """``t0``, the sample times strictly inside ``(t0, t1)`` of every sampled input, and ``t1``."""
        inside = [d[0][(d[0] > t0) & (d[0] < t1)] for k, d in zip(self.kinds, self.data) if k == "samples"]
        return np.unique(np.concatenate([[t0, t1], *inside]))

    def slots(self, starts: np.ndarray) -> np.ndarray:
        """The slots of the intervals that start at ``starts`` (no sample time inside an interval), one row each:
        ``[ta, u_1(ta), rate_1, u_2(ta), rate_2, ...]``; a function's are zeros (a compiled run writes them at
        every evaluation, ``simulate.driven_model``)."""
        out = np.empty((starts.size, 1 + 2 * len(self.names)))
        out[:, 0] = starts
        for i, (kind, data) in enumerate(zip(self.kinds, self.data)):
            if kind == "constant":
                out[:, 1 + 2 * i], out[:, 2 + 2 * i] = data, 0.0
            elif kind == "samples":
                out[:, 1 + 2 * i], out[:, 2 + 2 * i] = _interpolated(data, starts)
            else:
                out[:, 1 + 2 * i], out[:, 2 + 2 * i] = 0.0, 0.0
        return out

    def at(self, t: float) -> np.ndarray:
        """The slots at the time ``t``: ``[t, u_1(t), du_1/dt(t), ...]`` (the rate of samples: of the interval
        that starts at ``t``; of a function: its ``du_dt``, else a central difference, when the model reads it)."""
        out = [t]
        for name, kind, data in zip(self.names, self.kinds, self.data):
            if kind == "constant":
                out += [data, 0.0]
            elif kind == "samples":
                value, rate = _interpolated(data, np.array([t]))
                out += [value[0], rate[0]]
            else:
                f, df = data
                rate = 0.0
                if name in self.rates_read:
                    rate = _call(df, t, name) if df is not None else _rate(f, t, name)
                out += [_call(f, t, name), rate]
        return np.array(out)

    def parameters(self, p: np.ndarray, t) -> np.ndarray:
        """``p`` with the slots at ``t`` appended: shape (n_p + slots,) for one time, (n_times, ...) for several."""
        t_arr = np.asarray(t, dtype=float)
        if t_arr.ndim == 0:
            return np.concatenate([p, self.at(float(t_arr))])
        return np.array([np.concatenate([p, self.at(float(s))]) for s in t_arr.ravel()])

    def cover(self, t0: float, t1: float, what: str = "the run's `t_span`") -> None:
        """Refuse samples that do not cover ``[t0, t1]``."""
        for name, kind, data in zip(self.names, self.kinds, self.data):
            if kind == "samples" and (data[0][0] > t0 or data[0][-1] < t1):
                raise ValueError(f"`inputs[{name!r}]`: its samples cover [{data[0][0]:g}, {data[0][-1]:g}], "
                                 f"{what} needs [{t0:g}, {t1:g}]; give samples over the whole interval")


def _interpolated(samples: tuple, times: np.ndarray) -> tuple:
    """``(u, du/dt)`` of the piecewise-linear interpolant of ``samples = (t, u)`` at ``times`` (the rate of the
    interval that starts at each time)."""
    ts, us = samples
    j = np.clip(np.searchsorted(ts, times, side="right") - 1, 0, ts.size - 2)
    rate = (us[j + 1] - us[j]) / (ts[j + 1] - ts[j])
    return us[j] + rate * (times - ts[j]), rate


def _call(f, t: float, name: str) -> float:
    v = f(t)
    try:
        v = float(v)
    except (TypeError, ValueError):
        raise ValueError(f"`inputs[{name!r}]` is a function that returned {v!r} at t = {t:g}; it must return "
                         f"one real number") from None
    if not math.isfinite(v):
        raise ValueError(f"`inputs[{name!r}]` returned the non-finite value {v!r} at t = {t:g}")
    return v


def _rate(f, t: float, name: str) -> float:
    """``du/dt`` of a function input by a fourth-order central difference (step 1e-3 (1 + |t|))."""
    h = 1e-3 * (1.0 + abs(t))
    return (8 * (_call(f, t + h, name) - _call(f, t - h, name)) - (_call(f, t + 2 * h, name)
                                                                     - _call(f, t - 2 * h, name))) / (12 * h)


def _samples(value, name: str) -> tuple:
    ts, us = value
    ts = _validate.real_array(ts, f"the sample times of `inputs[{name!r}]`")
    us = _validate.real_array(us, f"the sample values of `inputs[{name!r}]`")
    if ts.ndim != 1 or us.shape != ts.shape or ts.size < 2:
        raise ValueError(f"`inputs[{name!r}]` samples must be two 1-D arrays (t, u) of the same length, at least "
                         f"2; got shapes {ts.shape} and {us.shape}")
    if not (np.isfinite(ts).all() and np.isfinite(us).all()):
        raise ValueError(f"`inputs[{name!r}]` samples must be finite")
    if (np.diff(ts) <= 0).any():
        raise ValueError(f"`inputs[{name!r}]` sample times must be strictly increasing")
    return np.ascontiguousarray(ts), np.ascontiguousarray(us)


def _one(value, name: str) -> tuple:
    """``(kind, data)`` of one input's value."""
    if callable(value):
        return "function", (value, None)
    if isinstance(value, (tuple, list)) and len(value) == 2 and all(map(callable, value)):
        return "function", tuple(value)  # the input and its rate du/dt
    if isinstance(value, (tuple, list)) and len(value) == 2 and not isinstance(value[0], (str, bytes)):
        return "samples", _samples(value, name)
    if isinstance(value, (str, bytes, bool, np.bool_)) or np.ndim(value) != 0:
        raise ValueError(f"`inputs[{name!r}]` must be a number, samples (t_array, u_array) or a function of the "
                         f"time; got {type(value).__name__} {value!r:.80}")
    return "constant", _validate.finite(value, f"`inputs[{name!r}]`")


def check(model, inputs) -> Inputs | None:
    """The validated ``inputs`` of a run of ``model`` (``None`` for a model without inputs).

    Raises ``ValueError`` naming ``inputs`` for a missing, unknown or mis-shaped entry.
    """
    names = tuple(getattr(model, "input_names", ()))
    if not names:
        if inputs:
            raise ValueError(f"`inputs`: {model.name} declares no inputs; got {sorted(map(str, inputs))}")
        return None
    if inputs is None:
        raise ValueError(f"{model.name} has inputs {names}: pass `inputs` = {{name: number, (t_array, u_array) "
                         f"or a function of t}}")
    if not isinstance(inputs, Mapping):
        raise ValueError(f"`inputs` must be a mapping {{name: value}} for {names}, got {type(inputs).__name__}")
    missing = [n for n in names if n not in inputs]
    extra = [n for n in inputs if n not in names]
    if missing or extra:
        parts = ([f"missing {missing}"] if missing else []) + ([f"unknown {extra}"] if extra else [])
        raise ValueError(f"`inputs` of {model.name}: {', '.join(parts)}; expected exactly {names}")
    kinds, data = zip(*(_one(inputs[n], n) for n in names))
    return Inputs(names, kinds, data, getattr(model.module, "INPUT_RATES_READ", ()))


def check_compiled(model, inp: Inputs, method: str) -> None:
    """Refuse, before any work, function inputs that the compiled ``method`` cannot call: a function that numba
    did not compile, a rate the model reads but was not given, a module whose ``constants(p)`` does not hold
    the slots as ``p`` does (derived before it did)."""
    if inp is None or not inp.has_function:
        return
    if not _slots_held(model.module):
        raise ValueError(f"`inputs`: the generated module of {model.name} ({model.module.__file__}) was written "
                         f"before its constants(p) held the input slots as p does, so its compiled methods cannot "
                         f"take a function input; derive it again (knifeedge derive FILE --out DIR), or sample "
                         f"the input, or use a SciPy method")
    for name, kind, data in zip(inp.names, inp.kinds, inp.data):
        if kind != "function":
            continue
        f, df = data
        if name in inp.rates_read and df is None:
            raise ValueError(f"`inputs[{name!r}]`: {model.name} reads the rate d{name}/dt (the input is in a "
                             f"constraint); on the compiled method {method!r} give the function with its "
                             f"derivative, inputs={{{name!r}: (u, du_dt)}}, both numba.njit functions of t")
        for g in (f, df) if df is not None else (f,):
            if not isinstance(g, CPUDispatcher):
                raise ValueError(f"`inputs[{name!r}]` is a Python function ({getattr(g, '__name__', g)!r}): the "
                                 f"compiled method {method!r} calls the input inside its compiled right-hand side. "
                                 f"Decorate it with @numba.njit (a function of t returning a float), sample it "
                                 f"(inputs={{{name!r}: (ts, f(ts))}}), or use a SciPy method "
                                 f"(method='scipy:DOP853'), which calls any Python function")
            _check_signature(g, name)


def _check_signature(f, name: str) -> None:
    """Refuse a numba function that does not compile as ``f(t: float) -> real number`` (compiling it now, once
    per process: milliseconds), instead of failing inside the kernel's compilation."""
    from numba import types
    from numba.core.errors import NumbaError

    try:
        f.compile((types.float64,))
    except (NumbaError, TypeError) as exc:
        first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
        raise ValueError(f"`inputs[{name!r}]`: numba cannot compile {f.__name__!r} as a function of the time t (one "
                         f"float): {first}") from None
    returns = [sig.return_type for sig in f.nopython_signatures if sig.args == (types.float64,)]
    if not returns or not isinstance(returns[0], (types.Float, types.Integer)):
        raise ValueError(f"`inputs[{name!r}]`: {f.__name__!r} returns {returns[0] if returns else 'nothing'} at a "
                         f"float t; it must return one real number")


def _slots_held(module) -> bool:
    """Whether ``q = module.constants(p)`` holds the input slots of ``p`` at the same places and nothing else
    of ``q`` depends on them (``derivation/input_slots.py``), as ``simulate.driven_model`` needs."""
    n_p = len(module.PARAM_NAMES)
    n = n_p + 1 + 2 * len(module.INPUT_NAMES)
    one, two = np.full(n, 0.75), np.full(n, 0.75)
    two[n_p:] = np.linspace(1.5, 2.5, n - n_p)
    with np.errstate(all="ignore"):
        q1, q2 = module.constants.py_func(one), module.constants.py_func(two)
    rest = np.r_[0:n_p, n:q1.size]
    return bool(np.array_equal(q2[n_p:n], two[n_p:]) and np.array_equal(q1[rest], q2[rest], equal_nan=True))


def read_samples(path, name: str) -> tuple:
    """Samples ``(t, u)`` of input ``name`` from a CSV file: two columns, time and value, one sample a row; a
    first row that is not numbers (a header such as ``t,tau``) is skipped."""
    from pathlib import Path

    path = Path(path)
    if not path.is_file():
        raise ValueError(f"`inputs[{name!r}]`: the samples file {str(path)!r} does not exist")
    rows = [line.strip() for line in path.read_text().splitlines() if line.strip()]
    try:
        float(rows[0].split(",")[0])
    except (ValueError, IndexError):
        rows = rows[1:]  # a header
    try:
        table = np.array([[float(x) for x in row.split(",")] for row in rows])
    except ValueError as exc:
        raise ValueError(f"`inputs[{name!r}]`: {path} must hold two columns of numbers (t, {name}): {exc}") from None
    if table.ndim != 2 or table.shape[1] != 2:
        raise ValueError(f"`inputs[{name!r}]`: {path} must hold two columns (t, {name}), one sample a row; got "
                         f"shape {table.shape}")
    return _samples((table[:, 0], table[:, 1]), name)
