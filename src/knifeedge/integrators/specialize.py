"""Specialize a kernel template to one generated model and cache the compiled result.

A kernel module is the template's text with its ``# knifeedge:rhs`` line
replaced by an import of the model's right-hand side, its
``# knifeedge:variant`` line by the chosen variant and its ``# knifeedge:n``
line by the state size (a compile-time constant, so LLVM unrolls the loops
over the state).  In the adaptive template, the bodies of the functions
marked ``# knifeedge:attempt`` (the stages of a step), ``# knifeedge:error``
(the error norm) and ``# knifeedge:stages`` (a dense-output stage)
are replaced by straight-line code with the tableau's coefficients as
literals.  The error norm and the dense stages sum in the generic loop's
order; the stages of a step are summed as ``y + (h a_0) K_0 + ...`` so
that fused multiply-adds shorten the chain of dependent operations (the
results differ from SciPy's ``y + h (a_0 K_0 + ...)`` by round-off).  It is written once to
``<cache>/kernels/`` under a name carrying a hash of everything it depends on
(template and helper sources, the generated module's source, numba and
Python versions), imported from there, and its ``@njit(cache=True)``
functions keep their machine code in the ``__pycache__`` beside it, so a
second process loads instead of compiling.

The cache directory is ``$KNIFEEDGE_CACHE_DIR`` if set, else
``$XDG_CACHE_HOME/knifeedge`` (default ``~/.cache/knifeedge``); when that is
not writable, a per-user folder in the system temporary directory.
"""
from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
import tempfile
from pathlib import Path
from types import ModuleType

import numba

_HERE = Path(__file__).resolve().parent
TEMPLATES = ("erk", "fixed")
#: sources every kernel depends on besides its template
_DEPENDENCIES = ("common.py", "dop853_tableau.py", "rk_tableaus.py", "specialize.py")
RHS_MARK = "# knifeedge:rhs"
VARIANT_MARK = "# knifeedge:variant"
N_MARK = "# knifeedge:n"
STAGES_MARK = "# knifeedge:stages"
ATTEMPT_MARK = "# knifeedge:attempt"
ERROR_MARK = "# knifeedge:error"
_LOADED: dict = {}


def cache_dir() -> Path:
    """The writable folder holding specialized kernels (created if needed)."""
    env = os.environ.get("KNIFEEDGE_CACHE_DIR")
    if env:
        candidates = [Path(env)]
    else:
        xdg = os.environ.get("XDG_CACHE_HOME")
        base = Path(xdg) if xdg else Path.home() / ".cache"
        candidates = [base / "knifeedge"]
    uid = os.getuid() if hasattr(os, "getuid") else "user"
    candidates.append(Path(tempfile.gettempdir()) / f"knifeedge-cache-{uid}")
    for c in candidates:
        try:
            (c / "kernels").mkdir(parents=True, exist_ok=True)
            probe = c / "kernels" / f".probe-{os.getpid()}"
            probe.write_text("")
            probe.unlink()
            return c
        except OSError:
            continue
    raise OSError(f"no writable cache directory for compiled kernels among {[str(c) for c in candidates]}; "
                  "set KNIFEEDGE_CACHE_DIR")


def kernel_source(template: str, variant: int, rhs_module: str, rhs_name: str, n_state: int) -> str:
    """Text of the kernel module for a template specialized to ``rhs_module.rhs_name`` on ``n_state`` states."""
    if template not in TEMPLATES:
        raise ValueError(f"unknown kernel template {template!r}; known: {TEMPLATES}")
    if isinstance(n_state, bool) or not isinstance(n_state, int) or n_state < 1:
        raise ValueError(f"`n_state` must be a positive integer, got {n_state!r}")
    lines = (_HERE / "templates" / f"{template}.py").read_text().splitlines()
    out, seen = [], set()
    for line in lines:
        if line.rstrip().endswith(RHS_MARK):
            line = f"from {rhs_module} import constants as _constants, {rhs_name} as _rhs  {RHS_MARK}"
            seen.add(RHS_MARK)
        elif VARIANT_MARK in line:
            line = f"VARIANT = {int(variant)}  {VARIANT_MARK}"
            seen.add(VARIANT_MARK)
        elif N_MARK in line and line.startswith("N ="):
            line = f"N = {n_state}  {N_MARK}"
            seen.add(N_MARK)
        out.append(line)
    if seen != {RHS_MARK, VARIANT_MARK, N_MARK}:
        raise RuntimeError(f"kernel template {template}.py lacks one of its {RHS_MARK!r}, {VARIANT_MARK!r}, "
                           f"{N_MARK!r} lines")
    if template == "erk":
        tableau = _erk_tableau(variant)
        out = _replace_body(out, STAGES_MARK, _stage_body(tableau["A"], tableau["n_stages"]))
        out = _replace_body(out, ATTEMPT_MARK, _attempt_body(tableau["A"], tableau["C"], tableau["n_stages"]))
        out = _replace_body(out, ERROR_MARK, _error_body(tableau, variant))
    header = (f"# Specialized kernel: template {template}.py, variant {variant}, rhs {rhs_module}.{rhs_name}, "
              f"{n_state} states.\n")
    return header + "\n".join(out) + "\n"


def _erk_tableau(variant: int) -> dict:
    """The tables the ``erk`` template uses for ``variant`` (row ``n_stages`` of ``A`` holds the weights)."""
    import numpy as np

    from . import dop853_tableau, rk_tableaus

    if variant == 0:
        t = dop853_tableau
        return {"A": t.A, "C": t.C, "E5": t.E5, "E3": t.E3, "n_stages": t.N_STAGES}
    A = np.zeros((7, 7))
    A[:6, :5] = rk_tableaus.DP54_A
    A[6, :6] = rk_tableaus.DP54_B
    C = np.append(rk_tableaus.DP54_C, 1.0)
    return {"A": A, "C": C, "E5": rk_tableaus.DP54_E, "E3": None, "n_stages": 6}


def _sum(coefficients) -> str:
    """``c0 * K[0, i] + c1 * K[1, i] + ...`` over the nonzero coefficients, left to right (``0.0`` if none)."""
    terms = [f"{float(c)!r} * K[{j}, i]" for j, c in enumerate(coefficients) if c != 0.0]
    return " + ".join(terms) if terms else "0.0"


def _stage_body(A, n_stages: int) -> list:
    """Body of ``_stage_state(K, s, y, h, out)``: one branch per dense-output stage ``s > n_stages``.

    Once :func:`_attempt_body` has written the step's stages, the dense
    output is its only caller; a method without extra stages gets an empty body.
    """
    body = []
    for s in range(n_stages + 1, A.shape[0]):
        body.append(f"    {'if' if not body else 'elif'} s == {s}:")
        body.append("        for i in range(N):")
        body.append(f"            out[i] = y[i] + h * ({_sum(A[s, :s])})")
    return body or ["    pass"]


def _attempt_body(A, C, n_stages: int) -> list:
    """Body of ``_attempt(t, t_new, y, h, q, K, work, y_new)``: every stage of one step, in sequence.

    A stage state is ``y + (h a_0) K_0 + ... + (h a_{s-1}) K_{s-1}``, summed
    oldest stage first, so that (with fused multiply-adds) only the last
    term waits for the stage just computed: the stages are a chain of
    dependent right-hand-side calls, and this keeps the arithmetic between
    two of them to one operation.
    """
    body = []
    for s in range(1, n_stages + 1):
        last = s == n_stages
        target = "y_new" if last else "work"
        terms = [f"(h * {float(c)!r}) * K[{j}, i]" for j, c in enumerate(A[s, :s]) if c != 0.0]
        body.append("    for i in range(N):")
        body.append(f"        {target}[i] = y[i] + {' + '.join(terms)}")
        body.append(f"    _rhs({'t_new' if last else f't + {float(C[s])!r} * h'}, {target}, q, K[{s}])")
    return body


def _error_body(tableau: dict, variant: int) -> list:
    """Body of ``_error_norm(K, h, scale, work5, work3)`` with the estimators' coefficients as literals."""
    n = tableau["n_stages"] + 1
    body = []
    if variant == 0:  # DOP853: the 5th- and 3rd-order estimates combined as in Hairer's code
        body += [
            "    n5 = 0.0",
            "    n3 = 0.0",
            "    for i in range(N):",
            f"        e5 = ({_sum(tableau['E5'])}) / scale[i]",
            f"        e3 = ({_sum(tableau['E3'])}) / scale[i]",
            "        n5 += e5 * e5",
            "        n3 += e3 * e3",
            "    if n5 == 0.0 and n3 == 0.0:",
            "        return 0.0",
            "    return abs(h) * n5 / np.sqrt((n5 + 0.01 * n3) * N)",
        ]
    else:  # root mean square of the one estimate
        body += [
            "    s2 = 0.0",
            "    for i in range(N):",
            f"        e = ({_sum(tableau['E5'])}) / scale[i]",
            "        s2 += e * e",
            "    return abs(h) * np.sqrt(s2 / N)",
        ]
    return body


def _replace_body(lines: list, mark: str, body: list) -> list:
    """Replace the body of the function whose ``def`` line ends with ``mark`` (its docstring is kept)."""
    try:
        start = next(k for k, line in enumerate(lines) if line.rstrip().endswith(mark))
    except StopIteration:
        raise RuntimeError(f"kernel template lacks a function marked {mark!r}") from None
    end = start + 1
    while end < len(lines) and (lines[end].startswith(" ") or not lines[end].strip()):
        end += 1
    while not lines[end - 1].strip():
        end -= 1
    doc_end = start + 1
    if lines[doc_end].strip().startswith('"""'):
        while not (lines[doc_end].rstrip().endswith('"""') and (doc_end > start + 1
                                                               or lines[doc_end].strip().count('"""') == 2)):
            doc_end += 1
        doc_end += 1
    return lines[:doc_end] + body + lines[end:]


def _key(source: str, rhs_file: str) -> str:
    h = hashlib.sha256(source.encode())
    for dep in _DEPENDENCIES:
        h.update((_HERE / dep).read_bytes())
    h.update(Path(rhs_file).read_bytes())
    h.update(f"numba {numba.__version__} python {sys.version}".encode())
    return h.hexdigest()[:20]


def is_compiled(module: ModuleType) -> bool:
    """Whether numba's cache beside a kernel module holds machine code of its ``solve``."""
    path = Path(module.__file__)
    return any((path.parent / "__pycache__").glob(f"{path.stem}.solve-*.nbi"))


def load_kernel(template: str, variant: int, rhs_module: ModuleType, rhs_name: str, n_state: int) -> ModuleType:
    """Import (writing it first if needed) the kernel module for a model's right-hand side.

    Raises if the kernel cannot be written or imported: there is no slow fallback.
    """
    source = kernel_source(template, variant, rhs_module.__name__, rhs_name, n_state)
    key = _key(source, rhs_module.__file__)
    stem = f"{template}{variant}_{rhs_module.__name__.rsplit('.', 1)[-1]}_{rhs_name}_{key}"
    if stem in _LOADED:
        return _LOADED[stem]
    folder = cache_dir() / "kernels"
    path = folder / f"{stem}.py"
    if not path.exists() or path.read_text() != source:
        tmp = folder / f".{stem}.{os.getpid()}.tmp"
        tmp.write_text(source)
        os.replace(tmp, path)
    name = f"knifeedge_kernels.{stem}"
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except BaseException:
        del sys.modules[name]
        raise
    _LOADED[stem] = module
    return module
