"""A user's names are data: the identifiers the generated code uses for them.

A generated module holds two kinds of identifiers: the emitter's own (the
arguments ``t, s, p, q, ds``, the results ``out``/``energy``/``power``, the
modules ``math``/``np``, the common subexpressions ``_c0, _c1, ...``, the
hoisted constants ``_k0, _k1, ...``, the functions of the module) and the
names of a model's symbols, which the user chose.  The two never meet:

- the emitter's own symbols are :class:`Own` symbols, printed as they are;
- a user's symbol is printed as :func:`identifier` of its name: the name
  itself when it is a plain ASCII identifier that is neither a Python
  keyword nor a builtin nor one of :data:`RESERVED` and does not start with
  ``_`` (every name of the package's own models), else ``_u_`` followed by
  the hexadecimal UTF-8 bytes of the name (``lambda`` -> ``_u_6c616d626461``,
  ``a b`` -> ``_u_612062``), which no other name maps to.

The user's names themselves stay what the module reports (``STATE_NAMES``,
``PARAM_NAMES``, ...).  What cannot be made safe is refused by
:func:`problems` when the spec is built: two names equal after Unicode
normalization (NFKC, as Python and most readers treat them).

The time of the integrator is :data:`t` (``knifeedge.derive.t``), an
:class:`Own` symbol printed ``t``: the argument of the right-hand side.
"""
from __future__ import annotations

import builtins
import keyword
import unicodedata

import sympy as sp


class Own(sp.Symbol):
    """A symbol of the emitter's own namespace (printed as its name, never equal to a user's symbol).

    The class is named ``Symbol`` so that SymPy's canonical ordering (which
    sorts by class name) and therefore the generated code do not change.
    """

    __slots__ = ()


Own.__name__ = Own.__qualname__ = "Symbol"

#: the time, argument ``t`` of every generated right-hand side
t = Own("t", real=True)

#: identifiers the generated code writes itself (besides Python's keywords and builtins and names starting with ``_``)
RESERVED = frozenset({
    "t", "s", "p", "q", "ds", "out", "u", "uu", "j", "np", "math", "njit", "numba", "energy", "power",
    "rhs", "rhs_into", "rhs_q_into", "rhs_pose", "rhs_pose_into", "rhs_pose_q_into", "constants", "pose_rates",
    "multipliers", "event_values", "power_dissipated", "frequencies", "invariants", "growth_rates", "drive_rates",
    "body_points", "body_outlines", "modes", "moffatt_tokieda", "initial_state",
})


def is_plain(name: str) -> bool:
    """``True`` when ``name`` can be written into generated code as it is."""
    return (name.isascii() and name.isidentifier() and not keyword.iskeyword(name) and not name.startswith("_")
            and name not in RESERVED and not hasattr(builtins, name))


def identifier(name: str) -> str:
    """The identifier generated code uses for the user's name ``name`` (see the module docstring)."""
    return name if is_plain(name) else "_u_" + name.encode("utf-8").hex()


def problems(names) -> list:
    """Sentences on the names that cannot be made safe.

    Distinct names equal after NFKC normalization, and names that the module's documentation could not
    show (empty, a quote, a backslash, an unprintable character).
    """
    seen: dict = {}
    for n in names:
        seen.setdefault(unicodedata.normalize("NFKC", n), set()).add(n)
    out = [f"the names {sorted(group)} are equal after Unicode normalization (NFKC) and would read as one name; "
           f"rename one of them" for group in seen.values() if len(group) > 1]
    bad = sorted(n for group in seen.values() for n in group
                 if not n or not n.isprintable() or '"' in n or "\\" in n)
    if bad:
        out.append(f"the names {bad} are empty or hold a quote, a backslash or an unprintable character, which the "
                   f"generated module's documentation cannot show; rename them")
    return out


Symbol = Own  # pickle finds the class by its name (``derivation.names.Symbol``)
