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

import glob
import hashlib
import importlib.util
import os
import pickle
import stat
import sys
import tempfile
import zlib
from pathlib import Path
from types import ModuleType

import numba

_HERE = Path(__file__).resolve().parent
TEMPLATES = ("erk", "fixed")
RHS_MARK = "# knifeedge:rhs"
VARIANT_MARK = "# knifeedge:variant"
N_MARK = "# knifeedge:n"
STAGES_MARK = "# knifeedge:stages"
ATTEMPT_MARK = "# knifeedge:attempt"
ERROR_MARK = "# knifeedge:error"
_LOADED: dict = {}


def cache_dir() -> Path:
    """The writable folder holding specialized kernels (created if needed).

    The fallback in the system temporary directory is created private
    (mode 0700) and refused when it is not a plain folder of this user that
    only this user can write to (a folder anyone can write to, or another
    user's, could hold files planted for this process to load).
    """
    env = os.environ.get("KNIFEEDGE_CACHE_DIR")
    if env:
        candidates = [Path(env)]
    else:
        xdg = os.environ.get("XDG_CACHE_HOME")
        base = Path(xdg) if xdg else Path.home() / ".cache"
        candidates = [base / "knifeedge"]
    uid = os.getuid() if hasattr(os, "getuid") else "user"
    fallback = Path(tempfile.gettempdir()) / f"knifeedge-cache-{uid}"
    candidates.append(fallback)
    refused = []
    for c in candidates:
        try:
            if c == fallback:
                _private_folder(c)
            (c / "kernels").mkdir(parents=True, exist_ok=True)
            probe = c / "kernels" / f".probe-{os.getpid()}"
            probe.write_text("")
            probe.unlink()
            return c
        except PermissionError as exc:
            refused.append(str(exc))
        except OSError:
            continue
    raise OSError(f"no writable cache directory for compiled kernels among {[str(c) for c in candidates]}"
                  f"{'; ' + '; '.join(refused) if refused else ''}; set KNIFEEDGE_CACHE_DIR")


def _private_folder(path: Path) -> None:
    """Create ``path`` with mode 0700, or check that the existing one is this user's and private."""
    try:
        path.mkdir(mode=0o700)
    except FileExistsError:
        pass
    if not hasattr(os, "getuid"):
        return
    st = os.lstat(path)
    if not stat.S_ISDIR(st.st_mode):
        raise PermissionError(f"refused {path}: not a folder (a link or a file)")
    if st.st_uid != os.getuid():
        raise PermissionError(f"refused {path}: owned by user id {st.st_uid}, not by this user ({os.getuid()})")
    if st.st_mode & 0o022:
        raise PermissionError(f"refused {path}: others may write to it (mode {stat.S_IMODE(st.st_mode):o})")


def kernel_source(template: str, variant, rhs_module: str, rhs_name: str, n_state: int, unroll: bool = True) -> str:
    """Text of the kernel module for a template specialized to ``rhs_module.rhs_name`` on ``n_state`` states.

    ``unroll=False`` keeps the template's generic loops over the tableau
    (same algorithm; the tests compare the two).
    """
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
            line = (f"TABLEAU = {str(variant)!r}  {VARIANT_MARK}" if template == "erk"
                    else f"VARIANT = {int(variant)}  {VARIANT_MARK}")
            seen.add(VARIANT_MARK)
        elif N_MARK in line and line.startswith("N ="):
            line = f"N = {n_state}  {N_MARK}"
            seen.add(N_MARK)
        out.append(line)
    if seen != {RHS_MARK, VARIANT_MARK, N_MARK}:
        raise RuntimeError(f"kernel template {template}.py lacks one of its {RHS_MARK!r}, {VARIANT_MARK!r}, "
                           f"{N_MARK!r} lines")
    if template == "erk" and unroll:
        tableau = _erk_tableau(variant)
        out = _replace_body(out, STAGES_MARK, _stage_body(tableau["A"], tableau["n_stages"]))
        out = _replace_body(out, ATTEMPT_MARK, _attempt_body(tableau["A"], tableau["C"], tableau["n_stages"]))
        out = _replace_body(out, ERROR_MARK, _error_body(tableau))
    header = (f"# Specialized kernel: template {template}.py, variant {variant}, rhs {rhs_module}.{rhs_name}, "
              f"{n_state} states{'' if unroll else ', generic loops'}.\n")
    return header + "\n".join(out) + "\n"


def _erk_tableau(name: str) -> dict:
    """The tables the ``erk`` template uses for the registered method ``name`` (row ``n_stages`` of ``A``
    holds the weights; later rows, DOP853's extra dense-output stages)."""
    import numpy as np

    from . import tableau

    t = tableau.get(name)
    s = t.stages
    n_ext = s + 1 + (t.hairer["c_ext"].size if t.hairer else 0)
    A = np.zeros((n_ext, n_ext))
    A[:s, :s] = t.A
    A[s, :s] = t.b
    C = np.ones(n_ext)
    C[:s] = t.c
    if t.hairer:
        A[s + 1:] = t.hairer["A_ext"]
        C[s + 1:] = t.hairer["c_ext"]
    return {"A": A, "C": C, "E5": t.e, "E3": t.hairer["e3"] if t.hairer else None, "n_stages": s}


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


def _error_body(tableau: dict) -> list:
    """Body of ``_error_norm(K, h, scale, work5, work3)`` with the estimators' coefficients as literals."""
    body = []
    if tableau["E3"] is not None:  # DOP853: the 5th- and 3rd-order estimates combined as in Hairer's code
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
    for dep in sorted(_HERE.glob("**/*.py")):  # every source of the integrators (templates, helpers, tableaus)
        h.update(dep.relative_to(_HERE).as_posix().encode())
        h.update(dep.read_bytes())
    h.update(Path(rhs_file).read_bytes())
    h.update(f"numba {numba.__version__} python {sys.version}".encode())
    return h.hexdigest()[:20]


def is_compiled(module: ModuleType) -> bool:
    """Whether numba's cache (beside the kernel module, or under ``NUMBA_CACHE_DIR``) holds its ``solve``."""
    try:
        return Path(module.solve._cache._cache_file._index_path).is_file()
    except AttributeError:  # another numba layout: look beside the module
        path = Path(module.__file__)
        return any((path.parent / "__pycache__").glob(f"{path.stem}.solve-*.nbi"))


#: errors numba's cache raises when one of its files is damaged (truncated, overwritten, unreadable)
_DAMAGE = (EOFError, pickle.UnpicklingError, zlib.error, ValueError, TypeError, AttributeError, IndexError,
           KeyError, OSError, ImportError)


def damaged_cache_files(exc: BaseException) -> list:
    """The numba cache files being read when ``exc`` was raised (empty if it did not come from the cache)."""
    files = []
    tb = exc.__traceback__
    while tb is not None:
        frame = tb.tb_frame
        if frame.f_code.co_filename.endswith(os.path.join("numba", "core", "caching.py")):
            owner = frame.f_locals.get("self")
            index = getattr(owner, "_index_path", None)
            if index:
                files.append(Path(index))
            path = frame.f_locals.get("path")
            if isinstance(path, (str, Path)) and str(path).endswith((".nbi", ".nbc")):
                files.append(Path(path))
        tb = tb.tb_next
    return list(dict.fromkeys(files))


def call_repairing(fn, *args):
    """``fn(*args)``, discarding damaged numba cache entries (and recompiling) instead of failing.

    A cache file that cannot be read (truncated by a full disk or a killed
    process, or overwritten) is removed with the entry it belongs to (its
    index and data files), the removal is said in one line on stderr, and
    the call is retried, which compiles the function again.
    """
    for _ in range(16):
        try:
            return fn(*args)
        except _DAMAGE as exc:
            files = damaged_cache_files(exc)
            if not files:
                raise
            for f in files:
                stem = f.name.split(".py")[0]  # "<module>.<function>-<line>"
                for entry in f.parent.glob(f"{glob.escape(stem)}.py*.nb[ic]"):
                    entry.unlink(missing_ok=True)
            print(f"knifeedge: discarded a damaged compiled-code cache entry {files[0]} "
                  f"({type(exc).__name__}: {exc}); compiling it again", file=sys.stderr, flush=True)
    return fn(*args)


def load_kernel(template: str, variant, rhs_module: ModuleType, rhs_name: str, n_state: int,
                unroll: bool = True) -> ModuleType:
    """Import (writing it first if needed) the kernel module for a model's right-hand side.

    Raises if the kernel cannot be written or imported: there is no slow fallback.
    """
    source = kernel_source(template, variant, rhs_module.__name__, rhs_name, n_state, unroll)
    key = _key(source, rhs_module.__file__)
    stem = f"{template}{variant}{'' if unroll else 'g'}_{rhs_module.__name__.rsplit('.', 1)[-1]}_{rhs_name}_{key}"
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
