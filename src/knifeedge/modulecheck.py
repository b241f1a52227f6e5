"""A generated module is what its header says: its own content hash and its declared sizes, checked before it runs.

Every module the emitter writes ends with a line ``MODULE_SHA256 = '<hex>'``,
the SHA-256 of the file's bytes before that line (:func:`seal`, applied by
``derivation/emit.py``'s ``write_all`` to every module it writes).  Before
``knifeedge.load`` imports a module -- built in or from a user's folder --
:func:`check` verifies that hash, then reads the module's text (without
running it) and compares the sizes it declares (``STATE_NAMES``,
``POSE_NAMES``, ``PARAM_NAMES``, their units, ``MULTIPLIER_NAMES``,
``EVENT_NAMES``) with what its functions read and write: the compiled kernels
do not check bounds, so a module whose right-hand side writes fewer or more
entries than its state has would read or write past the state.

Importing a module runs its code: these checks make sure it is the code the
emitter wrote, not that the code is harmless.  Load only models you trust.
"""
from __future__ import annotations

import ast
import hashlib
import re

#: the last line of every generated module
_SEAL = re.compile(rb"MODULE_SHA256 = '([0-9a-f]{64})'\n\Z")
_COMMENT = "#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ\n"


def seal(text: str) -> str:
    """``text`` (a module's source) followed by the line ``MODULE_SHA256 = '<sha256 of everything above>'``.

    The digest is of the UTF-8 bytes: write the result with ``encoding="utf-8"``.
    """
    body = (text if text.endswith("\n") else text + "\n") + _COMMENT
    return body + f"MODULE_SHA256 = {hashlib.sha256(body.encode('utf-8')).hexdigest()!r}\n"


def sealed_ok(data: bytes) -> bool:
    """True if ``data`` ends with a ``MODULE_SHA256`` line that matches the bytes above it."""
    start = data.rfind(b"\nMODULE_SHA256 = ") + 1
    match = _SEAL.match(data, start) if start > 0 else None
    return match is not None and hashlib.sha256(data[:start]).hexdigest() == match.group(1).decode()


def check(data: bytes, where: str, remedy: str, expect: tuple | None = None) -> None:
    """Raise ``ValueError`` unless ``data`` is a sealed generated module whose declared sizes fit its functions.

    ``where`` names the file in the message, ``remedy`` says how to regenerate it; ``expect``: the
    ``(MODEL, FIDELITY)`` the module must declare.
    """
    if not sealed_ok(data):
        raise ValueError(
            f"generated module {where} does not match its own content hash (MODULE_SHA256, its last line): it was "
            f"edited after knifeedge wrote it, or written by an older knifeedge or by something else. knifeedge does "
            f"not run it. Regenerate it ({remedy})")
    text = data.decode("utf-8")
    declared = tuple(_literals(text[:text.find("\ndef ")]).get(k) for k in ("MODEL", "FIDELITY"))
    if expect is not None and declared != tuple(expect):
        raise ValueError(f"{where} declares model {declared[0]!r} at fidelity {declared[1]!r}, not {expect[0]!r} at "
                         f"{expect[1]!r}: a module is loaded under the name it was written for; knifeedge does not "
                         f"run it")
    problems = size_problems(text)
    if problems:
        raise ValueError(f"generated module {where} is inconsistent ({'; '.join(problems)}); knifeedge does not run "
                         f"it. Regenerate it ({remedy})")


# -- the declared sizes against the functions, read from the text ---------------------------------------------------
#: functions the runtime calls with arrays sized by the declarations: name -> (state argument, pose included)
_STATE_FUNCTIONS = {"rhs_into": (1, False), "rhs_q_into": (1, False), "rhs_pose_into": (1, True),
                    "rhs_pose_q_into": (1, True), "energy": (0, False), "multipliers": (0, False),
                    "pose_rates": (0, True), "body_points": (0, True), "body_outlines": (0, True),
                    "event_values": (0, False), "power_dissipated": (0, False), "invariants": (0, False)}
#: functions that fill a new array: name -> (what its size must be)
_NEW_ARRAYS = {"rhs": "state", "rhs_pose": "state+pose", "multipliers": "MULTIPLIER_NAMES",
               "event_values": "EVENT_NAMES", "pose_rates": "POSE_NAMES"}


_DEF = re.compile(r"def (\w+)\(([^)]*)\):")
_LITERAL = re.compile(r"^([A-Z_]+) = (.+)$", re.M)


def _literals(text: str) -> dict:
    """The one-line literal assignments of the module's top level (``STATE_NAMES = (...)``)."""
    out = {}
    for name, value in _LITERAL.findall(text):
        try:
            out[name] = ast.literal_eval(value)
        except (ValueError, SyntaxError):
            pass
    return out


def _indices(body: str, name: str, store: bool = False) -> set:
    """Constant subscripts of ``name`` in a function's text (those assigned to, if ``store``)."""
    pattern = rf"^\s+{name}\[(\d+)\] = " if store else rf"\b{name}\[(\d+)\]"
    return {int(i) for i in re.findall(pattern, body, re.M)}


def _functions(text: str) -> dict:
    """The top-level functions of a module's text: ``{name: (argument names, body text)}``."""
    out, lines = {}, None
    for line in text.split("\n"):
        match = _DEF.match(line)
        if match:
            lines = []
            out[match.group(1)] = ([a.split("=")[0].strip() for a in match.group(2).split(",")], lines)
        elif line[:1].strip():  # anything else at column 0 ends the function
            lines = None
        elif lines is not None:
            lines.append(line)
    return {name: (args, "\n".join(body)) for name, (args, body) in out.items()}


def _new_array_size(body: str):
    """``K`` of the one ``np.empty(K)`` of a function (``None`` if it has none or several)."""
    sizes = re.findall(r"np\.empty\((\d+)\)", body)
    return int(sizes[0]) if len(sizes) == 1 else None


def size_problems(text: str) -> list:
    """What a module's text declares that its functions contradict (empty: nothing), as sentences.

    Reads the text (a regular expression per function: a module's text is checked in about a millisecond),
    never runs it.
    """
    lit = _literals(text)
    fns = _functions(text)
    names = {k: lit.get(k) for k in ("STATE_NAMES", "POSE_NAMES", "PARAM_NAMES", "MULTIPLIER_NAMES", "EVENT_NAMES")}
    bad = [k for k, v in names.items() if not isinstance(v, tuple)]
    if bad:
        return [f"{', '.join(bad)} must be tuples written as literals"]
    problems = [f"{k} has {len(lit.get(k, ()))} entries for {len(names[of])} {of}"
                for k, of in (("STATE_UNITS", "STATE_NAMES"), ("POSE_UNITS", "POSE_NAMES"),
                              ("PARAM_UNITS", "PARAM_NAMES"), ("PARAM_DOMAINS", "PARAM_NAMES"))
                if not isinstance(lit.get(k), tuple) or len(lit[k]) != len(names[of])]
    n, npose, n_par = len(names["STATE_NAMES"]), len(names["POSE_NAMES"]), len(names["PARAM_NAMES"])
    inputs = lit.get("INPUT_NAMES", ())
    if not isinstance(inputs, tuple):
        return ["INPUT_NAMES must be a tuple written as a literal"]
    n_par += 1 + 2 * len(inputs) if inputs else 0  # the inputs' slots after the parameters (input_slots.py)
    sizes = {"state": n, "state+pose": n + npose, **{k: len(v) for k, v in names.items()}}
    n_q = _new_array_size(fns["constants"][1]) if "constants" in fns else None
    for name, (at, pose) in _STATE_FUNCTIONS.items():
        args, body = fns.get(name, ((), ""))
        if len(args) < at + 2:
            continue
        # a potential in a coordinate dropped by a symmetry makes ``energy`` read the pose (ENERGY_NEEDS_POSE)
        size = n + npose if pose or (name == "energy" and lit.get("ENERGY_NEEDS_POSE") is True) else n
        n_params = n_q if name.endswith("q_into") else n_par
        if any(i >= size for i in _indices(body, args[at])):
            problems.append(f"{name} reads the state past its {size} declared entries")
        if n_params is not None and any(i >= n_params for i in _indices(body, args[at + 1])):
            problems.append(f"{name} reads its parameters past their {n_params} entries")
        if name.endswith("_into") and (len(args) < 4 or _indices(body, args[3], store=True) != set(range(size))):
            problems.append(f"{name} does not write exactly the {size} rates of the declared state")
    for name, what in _NEW_ARRAYS.items():
        if name in fns and _new_array_size(fns[name][1]) not in (None, sizes[what]):
            problems.append(f"{name} returns {_new_array_size(fns[name][1])} values for {sizes[what]} {what}")
    if "constants" in fns:
        args, body = fns["constants"]
        if n_q is None or any(i >= n_par for i in _indices(body, args[0])):
            problems.append(f"constants does not read {n_par} parameters into one new array")
    return problems
