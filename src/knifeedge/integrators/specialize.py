"""Specialize a kernel template to one generated model and cache the compiled result.

A kernel module is a template's text with its ``# knifeedge:rhs`` line
replaced by an import of the model's right-hand side, its
``# knifeedge:variant`` line by the chosen variant and its ``# knifeedge:n``
line by the state size (a compile-time constant, so LLVM unrolls the loops
over the state).  For the adaptive methods the kernel module is the model's
parts (``templates/erk_parts.py``: ``# knifeedge:nv`` and ``# knifeedge:nq``
become its number of event functions and the size of its ``constants(p)``,
``# knifeedge:driver`` the import of the integrator; its stages and
interpolant are LLVM IR, :mod:`.irparts`).  The integrator they serve
(``templates/erk.py``, one per method for every model, its ``power`` block
the step-size controller's power) is written by :func:`driver_source`.
Each module is written once to ``<cache>/kernels/`` under a name carrying a
hash of everything it depends on (template and helper sources, the
generated module's source, numba and Python versions), imported from there,
and its ``cache=True`` functions keep their machine code in the
``__pycache__`` beside it (the IR parts in a file beside it), so a second
process loads instead of compiling.

The cache directory is ``$KNIFEEDGE_CACHE_DIR`` if set, else
``$XDG_CACHE_HOME/knifeedge`` (default ``~/.cache/knifeedge``); when that is
not writable, a per-user folder in the system temporary directory.
"""
from __future__ import annotations

import errno
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

import llvmlite
import numba

_HERE = Path(__file__).resolve().parent
TEMPLATES = ("erk", "fixed")
#: the file of each template's per-model module (``erk``: the model's parts of the shared integrator ``erk.py``)
MODEL_FILES = {"erk": "erk_parts", "fixed": "fixed"}
RHS_MARK = "# knifeedge:rhs"
DRIVER_MARK = "# knifeedge:driver"
NV_MARK = "# knifeedge:nv"
NQ_MARK = "# knifeedge:nq"
VARIANT_MARK = "# knifeedge:variant"
N_MARK = "# knifeedge:n"
EVENTS_MARK = "# knifeedge:event_values"
BLOCK_MARK = "# knifeedge:"
#: blocks every template takes from ``templates/_blocks.py`` (the bodies of its functions of these names)
EVENT_BLOCKS = ("alloc", "ends", "suspect", "output")
#: functions of ``templates/_blocks.py`` compiled into the kernels of models with event functions
FUNCTION_DEFS = ("_event_at", "_function_ends", "_locate_functions")
_LOADED: dict = {}


def cache_dir() -> Path:
    """The writable folder holding specialized kernels (created if needed).

    Whichever folder is used ($KNIFEEDGE_CACHE_DIR, $XDG_CACHE_HOME/knifeedge,
    ~/.cache/knifeedge, or the fallback in the system temporary directory),
    it and its ``kernels`` folder are created private (mode 0700) and refused
    when they are not plain folders of this user that only this user can
    write to: a folder another user can write to could hold files planted for
    this process to import or load as machine code.  A refused folder is said
    in one line on stderr (once) and the next candidate is tried.
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
            if c != fallback:
                c.parent.mkdir(parents=True, exist_ok=True)
            _private_folder(c, follow=c != fallback)  # a folder the user named may be a link to one
            _private_folder(c / "kernels")
            _private_folder(c / "kernels" / "__pycache__")  # numba's cache of the kernels' functions (made 0700)
            probe = c / "kernels" / f".probe-{os.getpid()}"
            probe.write_text("")
            probe.unlink()
            return c
        except PermissionError as exc:
            refused.append(str(exc))
            if c != fallback and str(exc) not in _SAID and "refused" in str(exc):
                _SAID.add(str(exc))
                print(f"knifeedge: compiled-code cache {exc}; using {fallback} instead (make the folder private "
                      "with chmod 700, or set KNIFEEDGE_CACHE_DIR)", file=sys.stderr, flush=True)
        except OSError:
            continue
    raise OSError(f"no writable cache directory for compiled kernels among {[str(c) for c in candidates]}"
                  f"{'; ' + '; '.join(refused) if refused else ''}; set KNIFEEDGE_CACHE_DIR")


#: refusals of cache folders said on stderr already
_SAID: set = set()


def _private_folder(path: Path, follow: bool = False) -> None:
    """Create ``path`` with mode 0700, or check that the existing one is this user's and private (``follow``:
    a link to such a folder is accepted)."""
    try:
        path.mkdir(mode=0o700)
    except FileExistsError:
        pass
    if not hasattr(os, "getuid"):
        return
    st = os.stat(path) if follow else os.lstat(path)
    if not stat.S_ISDIR(st.st_mode):
        raise PermissionError(f"refused {path}: not a folder (a link or a file)")
    if st.st_uid != os.getuid():
        raise PermissionError(f"refused {path}: owned by user id {st.st_uid}, not by this user ({os.getuid()})")
    if st.st_mode & 0o022:
        raise PermissionError(f"refused {path}: others may write to it (mode {stat.S_IMODE(st.st_mode):o})")


def kernel_source(template: str, variant, rhs_module: str, rhs_name: str, n_state: int, has_events: bool = False,
                  driver: str = "knifeedge.integrators.templates.erk", n_events: int = 0, n_constants: int = 1) -> str:
    """Text of the kernel module for a template specialized to ``rhs_module.rhs_name`` on ``n_state`` states.

    ``has_events``: the module defines ``n_events`` event functions (``EVENT_NAMES``, ``event_values(s,
    p)``), which the kernel then locates besides state components.  For
    ``erk`` the module holds the model's parts of the integrator, the module
    ``driver`` (see :func:`driver_source`); ``n_constants`` is the size of the model's ``constants(p)``.
    """
    if template not in TEMPLATES:
        raise ValueError(f"unknown kernel template {template!r}; known: {TEMPLATES}")
    if isinstance(n_state, bool) or not isinstance(n_state, int) or n_state < 1:
        raise ValueError(f"`n_state` must be a positive integer, got {n_state!r}")
    lines = (_HERE / "templates" / f"{MODEL_FILES[template]}.py").read_text().splitlines()
    out, seen = [], set()
    for line in lines:
        if template == "erk" and line.rstrip().endswith(DRIVER_MARK):
            line = f"import {driver} as _driver  {DRIVER_MARK}"
            seen.add(DRIVER_MARK)
        elif template == "erk" and line.startswith("NV =") and NV_MARK in line:
            line = f"NV = {int(n_events) if has_events else 0}  {NV_MARK}"
            seen.add(NV_MARK)
        elif template == "erk" and line.startswith("NQ =") and NQ_MARK in line:
            line = f"NQ = {int(n_constants)}  {NQ_MARK}"
            seen.add(NQ_MARK)
        elif line.rstrip().endswith(RHS_MARK):
            line = f"from {rhs_module} import constants as _constants, {rhs_name} as _rhs  {RHS_MARK}"
            seen.add(RHS_MARK)
        elif line.rstrip().endswith(EVENTS_MARK):
            line = (f"from {rhs_module} import event_values as _event_values  {EVENTS_MARK}" if has_events else
                    f"from knifeedge.integrators.common import no_event_values as _event_values  {EVENTS_MARK}")
            seen.add(EVENTS_MARK)
        elif VARIANT_MARK in line:
            line = (f"TABLEAU = {str(variant)!r}  {VARIANT_MARK}" if template == "erk"
                    else f"METHOD = {str(variant)!r}  {VARIANT_MARK}")
            seen.add(VARIANT_MARK)
        elif N_MARK in line and line.startswith("N ="):
            line = f"N = {n_state}  {N_MARK}"
            seen.add(N_MARK)
        out.append(line)
    if seen != {RHS_MARK, VARIANT_MARK, N_MARK, EVENTS_MARK} | ({DRIVER_MARK, NV_MARK, NQ_MARK} if template == "erk" else set()):
        raise RuntimeError(f"kernel template {template}.py lacks one of its {RHS_MARK!r}, {VARIANT_MARK!r}, "
                           f"{N_MARK!r}, {EVENTS_MARK!r} lines")
    if template == "fixed":
        out = _event_blocks(out, has_events)
    header = (f"# Specialized kernel: template {template}.py, variant {variant}, rhs {rhs_module}.{rhs_name}, "
              f"{n_state} states.\n")
    return header + "\n".join(out) + "\n"


def _event_blocks(out: list, has_events: bool) -> list:
    """The template's event blocks and functions filled in (``has_events``: with the event functions')."""
    if has_events:
        out = _replace_block(out, "function_defs", sum((_event_function(f) for f in FUNCTION_DEFS), []))
        out = _replace_block(out, "functions", lambda block: block)
    else:
        out = _replace_block(out, "function_defs", [])
        out = _replace_block(out, "functions", [])
    for name in EVENT_BLOCKS:
        out = _replace_block(out, name, _event_block(name))
    return out


def driver_source(variant: str) -> str:
    """Text of the adaptive integrator ``templates/erk.py`` for the registered method ``variant``: the part
    that serves every model (its step-size control, output and event location; it finds the event
    functions' code through the model's parts)."""
    lines = (_HERE / "templates" / "erk.py").read_text().splitlines()
    out, seen = [], False
    for line in lines:
        if VARIANT_MARK in line:
            line = f"TABLEAU = {str(variant)!r}  {VARIANT_MARK}"
            seen = True
        out.append(line)
    if not seen:
        raise RuntimeError(f"kernel template erk.py lacks its {VARIANT_MARK!r} line")
    out = _event_blocks(out, True)
    from .tableau import erk_arrays

    out = _replace_block(out, "power", _power_block(erk_arrays(variant)[-1]))
    return f"# The adaptive integrator: template erk.py, variant {variant}, every model.\n" + "\n".join(out) + "\n"


def _power_block(error_order: int):
    """The controller's ``err ** ERROR_EXPONENT``; for DOP853 (-1/8) three square roots, cheaper than pow."""
    def edit(lines):
        if error_order != 7:
            return [line.strip() for line in lines]
        return [line.strip().replace("err ** ERROR_EXPONENT", "(1.0 / np.sqrt(np.sqrt(np.sqrt(err))))")
                for line in lines]
    return edit


def _replace_block(lines: list, name: str, body) -> list:
    """Replace every block between ``# knifeedge:begin name`` and ``# knifeedge:end name`` by ``body``.

    ``body`` is a list of lines (indented relative to the block) or a function of the block's lines
    (stripped of their indentation) returning them; the markers are dropped.
    """
    begin, end = f"{BLOCK_MARK}begin {name}", f"{BLOCK_MARK}end {name}"
    out, found = [], False
    k = 0
    while k < len(lines):
        line = lines[k]
        if line.strip() != begin:
            out.append(line)
            k += 1
            continue
        found = True
        indent = line[: len(line) - len(line.lstrip())]
        stop = next((j for j in range(k + 1, len(lines)) if lines[j].strip() == end), None)
        if stop is None:
            raise RuntimeError(f"kernel template: {begin!r} without {end!r}")
        block = [x[len(indent):] for x in lines[k + 1:stop] if not x.strip().startswith("#")]
        new = body(block) if callable(body) else body
        out += [indent + x for x in new]
        k = stop + 1
    if not found:
        raise RuntimeError(f"kernel template lacks a block {begin!r}")
    return out


def _event_block(name: str) -> list:
    """The body of function ``name`` of ``templates/_blocks.py`` (dedented, without its ``return`` line)."""
    lines = (_HERE / "templates" / "_blocks.py").read_text().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith(f"def {name}("))
    body = []
    for line in lines[start + 1:]:
        if line and not line.startswith(" "):
            break
        body.append(line[4:])
    while body and not body[-1].strip():
        body.pop()
    if body and body[-1].startswith("return "):
        body.pop()
    return body


def _event_function(name: str) -> list:
    """Function ``name`` of ``templates/_blocks.py``, whole, compiled (decorated) and followed by two blank lines."""
    lines = (_HERE / "templates" / "_blocks.py").read_text().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith(f"def {name}("))
    end = start + 1
    while end < len(lines) and (not lines[end] or lines[end].startswith(" ")):
        end += 1
    body = lines[start:end]
    while body and not body[-1].strip():
        body.pop()
    return ['@njit(cache=True, error_model="numpy")'] + body + ["", ""]


def _key(source: str, rhs_file: str | None) -> str:
    h = hashlib.sha256(source.encode())
    for dep in sorted(_HERE.glob("**/*.py")):  # every source of the integrators (templates, helpers, tableaus)
        h.update(dep.relative_to(_HERE).as_posix().encode())
        h.update(dep.read_bytes())
    if rhs_file is not None:
        h.update(Path(rhs_file).read_bytes())
    h.update(f"numba {numba.__version__} llvmlite {llvmlite.__version__} python {sys.version}".encode())
    return h.hexdigest()[:20]


def cached(fn) -> bool:
    """Whether numba's cache holds compiled code of ``fn`` (a Python function or an ``njit`` dispatcher; an
    ``njit`` and a ``cfunc`` of one function are cached alike, under its name and first line)."""
    from numba.core.caching import FunctionCache

    fn = getattr(fn, "py_func", fn)
    try:
        return Path(FunctionCache(fn)._cache_file._index_path).is_file()
    except Exception:  # noqa: BLE001 - another numba layout: not known to be cached
        return False


def is_compiled(module: ModuleType) -> bool:
    """Whether numba's cache (beside the kernel module, or under ``NUMBA_CACHE_DIR``) holds its ``solve``
    (for the adaptive methods: the model's parts and the shared integrator)."""
    if hasattr(module, "is_compiled"):
        return module.is_compiled()
    try:
        return Path(module.solve._cache._cache_file._index_path).is_file()
    except AttributeError:  # another numba layout: look beside the module
        path = Path(module.__file__)
        return any((path.parent / "__pycache__").glob(f"{path.stem}.solve-*.nbi"))


#: the first bytes of numba's cache files of the kernels' functions, written by :class:`_CheckedCacheFile`
CHECKED_MAGIC = b"knifeedge checked numba cache\n"


def _checked(data: bytes) -> bytes:
    return CHECKED_MAGIC + hashlib.sha256(data).digest() + data


def _verified(data: bytes, path) -> bytes:
    """``data`` without its :func:`_checked` prefix; ValueError if the prefix or the checksum is wrong."""
    head = len(CHECKED_MAGIC) + 32
    if not data.startswith(CHECKED_MAGIC) or hashlib.sha256(data[head:]).digest() != data[len(CHECKED_MAGIC):head]:
        raise ValueError(f"{path}: its checksum does not match its content")
    return data[head:]


def _checked_cache_file_class():
    """numba's index-and-data cache file with a SHA-256 written with each file and verified before anything in
    it is unpickled (the index's numba version too)."""
    from numba.core.caching import IndexDataCacheFile

    class _CheckedCacheFile(IndexDataCacheFile):
        def _dump(self, obj):
            return _checked(super()._dump(obj))

        def _save_index(self, overloads):
            data = self._version.encode() + b"\n" + IndexDataCacheFile._dump(self, (self._source_stamp, overloads))
            with self._open_for_write(self._index_path) as f:
                f.write(_checked(data))

        def _load_index(self):
            try:
                with open(self._index_path, "rb") as f:
                    raw = f.read()
            except FileNotFoundError:
                return {}
            version, _, data = _verified(raw, self._index_path).partition(b"\n")
            if version != self._version.encode():
                return {}
            stamp, overloads = pickle.loads(data)
            return overloads if stamp == self._source_stamp else {}

        def _load_data(self, name):
            path = self._data_path(name)
            with open(path, "rb") as f:
                return pickle.loads(_verified(f.read(), path))

    return _CheckedCacheFile


_CHECKED: list = []


def check_cached_code(module: ModuleType) -> None:
    """Have numba keep the machine code of ``module``'s own ``cache=True`` functions in files with a checksum,
    verified before they are loaded (a damaged or altered file is then discarded by :func:`call_repairing`).

    Where numba keeps them outside the checked cache folder (``NUMBA_CACHE_DIR``), that folder and its parent
    get :func:`cache_dir`'s checks; if refused, the functions compile in each process without a cache (said
    once)."""
    from numba.core.caching import IndexDataCacheFile, NullCache

    if not _CHECKED:
        _CHECKED.append(_checked_cache_file_class())
    for obj in vars(module).values():
        cache_file = getattr(getattr(obj, "_cache", None), "_cache_file", None)
        if type(cache_file) is IndexDataCacheFile and getattr(obj.py_func, "__module__", None) == module.__name__:
            if _private_numba_folder(Path(cache_file._cache_path), Path(module.__file__).parent):
                cache_file.__class__ = _CHECKED[0]
            else:
                obj._cache = NullCache()


def _private_numba_folder(folder: Path, kernels: Path) -> bool:
    """Whether numba's cache ``folder`` of a kernel module in ``kernels`` may be read: its ``__pycache__`` (checked
    by :func:`cache_dir`), or a folder that passes the same checks, with its parent."""
    if folder == kernels / "__pycache__":
        return True
    try:
        for f in (folder, folder.parent):
            if f.exists():
                _private_folder(f, follow=f == folder.parent)
        return True
    except PermissionError as exc:
        if str(exc) not in _SAID:
            _SAID.add(str(exc))
            print(f"knifeedge: numba's cache {exc}; the kernels compile in each process without it (make the "
                  "folder private with chmod 700)", file=sys.stderr, flush=True)
        return False


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


#: errno values of a write that found no room
_FULL = (errno.ENOSPC, errno.EDQUOT)


def disk_full(exc: OSError, what: str) -> OSError:
    """The error to raise when writing ``what`` to the cache found the disk (or the quota) full."""
    where = exc.filename or cache_dir()
    return OSError(exc.errno, f"the disk holding the compiled-code cache is full: could not write {what} to "
                              f"{where}; free some space, or set KNIFEEDGE_CACHE_DIR to a folder on another disk")


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
            if isinstance(exc, OSError) and exc.errno in _FULL:
                raise disk_full(exc, "the compiled code") from exc
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


def load_kernel(template: str, variant, rhs_module: ModuleType, rhs_name: str, n_state: int) -> ModuleType:
    """Import (writing it first if needed) the kernel module for a model's right-hand side.

    For ``erk`` the adaptive integrator shared by every model (one module per
    method) is imported first; the kernel module holds the model's parts and
    a ``solve`` that runs the integrator with them.  Raises if a module
    cannot be written or imported: there is no slow fallback.
    """
    names = tuple(getattr(rhs_module, "EVENT_NAMES", ()))
    driver = "knifeedge.integrators.templates.erk"
    if template == "erk":
        dsource = driver_source(variant)
        dstem = f"erk{variant}_driver_{_key(dsource, None)}"
        driver = f"knifeedge_driver_{dstem}"
        _import(dstem, dsource, driver)
    source = kernel_source(template, variant, rhs_module.__name__, rhs_name, n_state, has_events=bool(names),
                           driver=driver, n_events=len(names), n_constants=_n_constants(rhs_module))
    key = _key(source, rhs_module.__file__)
    stem = f"{template}{variant}_{rhs_module.__name__.rsplit('.', 1)[-1]}_{rhs_name}_{key}"
    return _import(stem, source, f"knifeedge_kernels.{stem}")


def _n_constants(rhs_module: ModuleType) -> int:
    """The size of ``rhs_module.constants(p)`` (run as plain Python on parameters all one)."""
    import numpy as np

    n_inputs = len(getattr(rhs_module, "INPUT_NAMES", ()))  # their slots follow the parameters (input_slots.py)
    n_params = len(getattr(rhs_module, "PARAM_NAMES", ())) + (1 + 2 * n_inputs if n_inputs else 0) or 1
    with np.errstate(all="ignore"):
        return int(np.size(rhs_module.constants.py_func(np.ones(n_params))))


def _import(stem: str, source: str, name: str) -> ModuleType:
    """The module ``name`` of ``source``, written to ``<cache>/kernels/<stem>.py`` (once) and imported."""
    if stem in _LOADED:
        return _LOADED[stem]
    folder = cache_dir() / "kernels"
    path = folder / f"{stem}.py"
    try:
        same = path.read_bytes() == source.encode()
    except FileNotFoundError:
        same = None
    if not same:
        if same is False:  # its name is a hash of this text: the file was altered (or damaged)
            print(f"knifeedge: replaced a kernel module whose text was not the one its name stands for: {path}",
                  file=sys.stderr, flush=True)
        tmp = folder / f".{stem}.{os.getpid()}.tmp"
        try:
            tmp.write_bytes(source.encode())
            os.replace(tmp, path)
        except OSError as exc:
            tmp.unlink(missing_ok=True)
            if exc.errno in _FULL:
                raise disk_full(exc, f"the kernel module {path.name}") from exc
            raise
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except BaseException:
        del sys.modules[name]
        raise
    check_cached_code(module)
    _LOADED[stem] = module
    return module
