"""Specialize a kernel template to one generated model and cache the compiled result.

A kernel module is the template's text with its ``# knifeedge:rhs`` line
replaced by an import of the model's right-hand side and its
``# knifeedge:variant`` line by the chosen variant.  It is written once to
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
STAGES_MARK = "# knifeedge:stages"
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


def kernel_source(template: str, variant: int, rhs_module: str, rhs_name: str) -> str:
    """Text of the kernel module for a template specialized to ``rhs_module.rhs_name``."""
    if template not in TEMPLATES:
        raise ValueError(f"unknown kernel template {template!r}; known: {TEMPLATES}")
    lines = (_HERE / "templates" / f"{template}.py").read_text().splitlines()
    out, seen = [], set()
    for line in lines:
        if line.rstrip().endswith(RHS_MARK):
            line = f"from {rhs_module} import {rhs_name} as _rhs  {RHS_MARK}"
            seen.add(RHS_MARK)
        elif VARIANT_MARK in line:
            line = f"VARIANT = {int(variant)}  {VARIANT_MARK}"
            seen.add(VARIANT_MARK)
        out.append(line)
    if seen != {RHS_MARK, VARIANT_MARK}:
        raise RuntimeError(f"kernel template {template}.py lacks its {RHS_MARK!r} or {VARIANT_MARK!r} line")
    if template == "erk":
        out = _unroll_stages(out, _erk_matrix(variant))
    header = f'# Specialized kernel: template {template}.py, variant {variant}, rhs {rhs_module}.{rhs_name}.\n'
    return header + "\n".join(out) + "\n"


def _erk_matrix(variant: int):
    """The stage matrix the ``erk`` template uses for ``variant`` (row ``N_STAGES`` holds the weights)."""
    import numpy as np

    from . import dop853_tableau, rk_tableaus

    if variant == 0:
        return dop853_tableau.A
    A = np.zeros((7, 7))
    A[:6, :5] = rk_tableaus.DP54_A
    A[6, :6] = rk_tableaus.DP54_B
    return A


def _unroll_stages(lines: list, A) -> list:
    """Replace the body of the function marked ``# knifeedge:stages`` by one branch per stage.

    Each branch sums the nonzero ``A[s, j] * K[j, i]`` left to right with the
    coefficients as literals (``repr`` round-trips), so the result is bit for
    bit the generic loop's, without its branches and table loads.
    """
    start = next(k for k, line in enumerate(lines) if line.rstrip().endswith(STAGES_MARK))
    end = start + 1
    while end < len(lines) and (lines[end].startswith(" ") or not lines[end].strip()):
        end += 1
    while not lines[end - 1].strip():
        end -= 1
    body = ["    n = y.size"]
    for s in range(1, A.shape[0]):
        terms = [f"{float(A[s, j])!r} * K[{j}, i]" for j in range(s) if A[s, j] != 0.0]
        body.append(f"    {'if' if s == 1 else 'elif'} s == {s}:")
        body.append("        for i in range(n):")
        body.append(f"            out[i] = y[i] + h * ({' + '.join(terms) if terms else '0.0'})")
    return lines[: start + 1] + body + lines[end:]


def _key(source: str, rhs_file: str) -> str:
    h = hashlib.sha256(source.encode())
    for dep in _DEPENDENCIES:
        h.update((_HERE / dep).read_bytes())
    h.update(Path(rhs_file).read_bytes())
    h.update(f"numba {numba.__version__} python {sys.version}".encode())
    return h.hexdigest()[:20]


def load_kernel(template: str, variant: int, rhs_module: ModuleType, rhs_name: str) -> ModuleType:
    """Import (writing it first if needed) the kernel module for a model's right-hand side.

    Raises if the kernel cannot be written or imported: there is no slow fallback.
    """
    source = kernel_source(template, variant, rhs_module.__name__, rhs_name)
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
