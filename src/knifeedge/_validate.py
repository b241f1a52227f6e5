"""One rule for numbers given to knifeedge, whatever their form.

A number is a real scalar: a Python ``int`` or ``float``, a NumPy integer or
floating scalar, or a 0-d array of those.  Refused with a ``TypeError`` that
names the argument: ``bool`` (``True`` is not a tilt of 1 rad), complex
numbers (the imaginary part would be lost), strings (``"1e-3"``) and any
other object.  An array of numbers follows the same rule element by element,
whether it is a list, a tuple or an ndarray (whose dtype must then be an
integer or floating one).  Values too large for a float are a ``ValueError``.
"""
from __future__ import annotations

import math

import numpy as np

_REAL = (int, float, np.integer, np.floating)


def real(v, what: str) -> float:
    """``v`` as a float if it is a real number (see the module), else ``TypeError`` naming ``what``."""
    if type(v) is float:  # the common case first
        return v
    if isinstance(v, np.ndarray) and v.ndim == 0 and v.dtype.kind in "iuf":
        v = v[()]
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, _REAL):
        raise TypeError(f"{what} must be a real number, got {_describe(v)}")
    try:
        return float(v)
    except OverflowError:
        raise ValueError(f"{what} is too large for a float, got {v!r}") from None


def finite(v, what: str) -> float:
    """``real(v)`` that is also finite."""
    x = real(v, what)
    if not math.isfinite(x):
        raise ValueError(f"{what} must be finite, got {v!r}")
    return x


def real_array(v, what: str) -> np.ndarray:
    """A new float64 array from an array-like of real numbers (see the module), else ``TypeError``."""
    if isinstance(v, np.ndarray):
        kind = v.dtype.kind
        if kind in "iuf":
            return np.array(v, dtype=float)
        if kind != "O":
            raise TypeError(f"{what} must contain real numbers, got an array of dtype {v.dtype}")
        arr = v
    else:
        if isinstance(v, (str, bytes)) or not hasattr(v, "__len__"):
            raise TypeError(f"{what} must be an array of real numbers, got {_describe(v)}")
        try:
            arr = np.asarray(v, dtype=object)
        except ValueError:  # ragged nesting
            raise ValueError(f"{what} must be a regular array of real numbers, got {v!r}") from None
    out = np.empty(arr.shape)
    flat = out.reshape(-1)
    for i, x in enumerate(arr.reshape(-1).tolist() if arr.dtype.kind != "O" else arr.reshape(-1)):
        flat[i] = real(x, f"every element of {what}")
    return out


def _describe(v) -> str:
    text = repr(v)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(v).__name__} {text}"
