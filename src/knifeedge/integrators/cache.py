"""The cache of compiled kernels: one private folder, numba's files checked by SHA-256 before they are unpickled.

:func:`compiled` gives a kernel (a numba closure made by :mod:`.fixed` or :mod:`.erk`) numba's cache in
``<cache>/kernels`` under a name that stands for everything its machine code depends on (its stamp).  Every
file kept there carries a magic line and the SHA-256 of the rest, verified before anything in it is read
(:class:`CheckedCacheFile`, :func:`read_checked`); a damaged one is discarded and compiled again
(:func:`discard`), one that cannot be written is said (:func:`not_kept`).  docs/integrators.md says more.
"""
from __future__ import annotations

import errno
import glob
import hashlib
import marshal
import os
import pickle
import stat
import sys
import tempfile
import zlib
from pathlib import Path

import llvmlite
import numba
import numpy as np
from numba.core import caching
from numba.core.caching import CompileResultCacheImpl, FunctionCache, IndexDataCacheFile, _CacheLocator
from numba.core.registry import CPUDispatcher

_HERE = Path(__file__).resolve().parent
#: refusals of cache folders said on stderr already
_SAID: set = set()


def cache_dir() -> Path:
    """The writable folder of compiled kernels: $KNIFEEDGE_CACHE_DIR, else $XDG_CACHE_HOME/knifeedge (default
    ~/.cache/knifeedge), else a per-user folder in the system temporary directory.

    It and its ``kernels`` folder are created private (mode 0700) and refused, said once on stderr, when another
    user could write to them (files planted there would be loaded as machine code).
    """
    env, xdg = os.environ.get("KNIFEEDGE_CACHE_DIR"), os.environ.get("XDG_CACHE_HOME")
    uid = os.getuid() if hasattr(os, "getuid") else "user"
    fallback = Path(tempfile.gettempdir()) / f"knifeedge-cache-{uid}"
    candidates = [Path(env) if env else (Path(xdg) if xdg else Path.home() / ".cache") / "knifeedge", fallback]
    refused = []
    for c in candidates:
        try:
            if c != fallback:
                c.parent.mkdir(parents=True, exist_ok=True)
            _private_folder(c, follow=c != fallback)  # a folder the user named may be a link to one
            _private_folder(c / "kernels")
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


def _named(value):
    """What a closure cell stands for in a kernel's cache name: a compiled function by its module's file (a
    generated model's bytes) or, for a closure, its code and cells; an array by its bytes; else the value."""
    if isinstance(value, CPUDispatcher) or hasattr(value, "py_func"):
        f = value.py_func
        if f.__closure__:
            return _closure_named(f)
        path = getattr(sys.modules.get(f.__module__), "__file__", None)
        if path is None or not Path(path).is_file():  # typed in a session or run by exec: by its code
            return ("function", f.__module__, f.__qualname__, _code_named(f))
        return ("function", f.__module__, f.__qualname__, hashlib.sha256(Path(path).read_bytes()).hexdigest())
    if isinstance(value, np.ndarray):
        return ("array", value.dtype.str, value.shape, value.tobytes())
    if isinstance(value, tuple):
        return tuple(_named(v) for v in value)
    return value


def _closure_named(f) -> tuple:
    return ("closure", f.__qualname__, hashlib.sha256(f.__code__.co_code).hexdigest(),
            tuple(_named(c.cell_contents) for c in f.__closure__ or ()))


def _code_named(f) -> tuple:
    """A function without a module file (a user's input typed in a session): its code and the numbers, arrays and
    compiled functions among the globals it reads (numba freezes them into the machine code)."""
    code, glob_ = f.__code__, f.__globals__
    read = tuple((n, _named(glob_[n])) for n in code.co_names if isinstance(glob_.get(n), (int, float, complex,
                                                                                            np.ndarray, CPUDispatcher)))
    return ("code", hashlib.sha256(marshal.dumps(code)).hexdigest(), read)


def digest(*items) -> str:
    """A hash of ``items`` (:func:`_named`), the sources of the integrators and the compiler versions."""
    h = hashlib.sha256(pickle.dumps(_named(items), protocol=4))
    for dep in sorted(_HERE.glob("*.py")):
        h.update(dep.name.encode())
        h.update(dep.read_bytes())
    h.update(f"numba {numba.__version__} llvmlite {llvmlite.__version__} python {sys.version}".encode())
    return h.hexdigest()[:20]


class _Locator(_CacheLocator):
    """numba's cache of a kernel: in ``<cache>/kernels``, named by the label and stamp the function carries."""

    def __init__(self, py_func, py_file):
        self._py_file = py_file
        self._folder, self._name = py_func.__knifeedge_cache__

    def ensure_cache_path(self):
        _private_folder(Path(self._folder))

    def get_cache_path(self):
        return self._folder

    def get_source_stamp(self):
        return self._name

    def get_disambiguator(self):
        return self._name

    @classmethod
    def from_function(cls, py_func, py_file):
        return cls(py_func, py_file)


class _Impl(CompileResultCacheImpl):
    _locator_classes = [_Locator]

    def get_filename_base(self, fullname, abiflags):
        return f"{self.locator.get_disambiguator()}.py{sys.version_info[0]}{sys.version_info[1]}{abiflags}"


class KernelCache(FunctionCache):
    """numba's function cache for a closure: its index key is the kernel's stamp (numba's own key pickles a
    compiled function in a cell with a per-process id, so it would never match in another process); its files
    carry a SHA-256 checked before anything in them is unpickled (:class:`CheckedCacheFile`)."""

    _impl_class = _Impl

    def __init__(self, py_func):
        super().__init__(py_func)
        self._cache_file.__class__ = CheckedCacheFile

    def _index_key(self, sig, codegen):
        return (sig, codegen.magic_tuple(), self._py_func.__knifeedge_cache__[1])


def _distinct_names(py_func) -> str:
    """Give the closure ``py_func`` and every compiled closure in its cells (and in theirs) a name that stands for
    its code and cells: numba links machine code of one name once per process, so a kernel loaded from the cache
    would call another closure of the same factory (or be another kernel, of another model) compiled or loaded
    here under the same name (NOTES, fourth stop).  Returns its stamp, the :func:`digest` of its code and cells."""
    stamp = getattr(py_func, "__knifeedge_stamp__", None)
    if stamp is None:
        for cell in py_func.__closure__ or ():
            contents = cell.cell_contents
            for value in contents if isinstance(contents, tuple) else (contents,):
                f = getattr(value, "py_func", None)
                if f is not None and f.__closure__:
                    _distinct_names(f)
        stamp = digest(_closure_named(py_func))
        py_func.__qualname__ = f"{py_func.__qualname__}_{stamp[:12]}"
        py_func.__knifeedge_stamp__ = stamp
    return stamp


def _named_in_cache(py_func, label: str) -> None:
    """Name ``py_func``'s entry in ``<cache>/kernels`` (read by :class:`_Locator`): ``<label>-<stamp>``, after its
    compiled closures are given names of their own (:func:`_distinct_names`, which gives the stamp)."""
    py_func.__knifeedge_cache__ = (str(cache_dir() / "kernels"), f"{label}-{_distinct_names(py_func)}")


def compiled(py_func, label: str):
    """``numba.njit(py_func)`` (error model numpy) cached in ``<cache>/kernels`` as ``<label>-<stamp>``."""
    _named_in_cache(py_func, label)
    dispatcher = numba.njit(error_model="numpy")(py_func)
    dispatcher._cache = KernelCache(py_func)
    return dispatcher


def compiled_cfunc(py_func, signature, label: str):
    """``numba.cfunc(signature)(py_func)`` (error model numpy), cached as :func:`compiled`; it compiles, or loads
    from the cache, at its ``compile()``."""
    from numba.core import sigutils
    from numba.core.ccallback import CFunc

    _named_in_cache(py_func, label)
    function = CFunc(py_func, sigutils.normalize_signature(signature), locals={}, options={"error_model": "numpy"})
    function._cache = KernelCache(py_func)
    return function


def is_cached(function) -> bool:
    """Whether the cache holds machine code of ``function`` (made by :func:`compiled` or :func:`compiled_cfunc`)."""
    return Path(function._cache._cache_file._index_path).is_file()


#: the first bytes of every checked cache file (numba's files of the kernels, the parts of :mod:`.irparts`)
CHECKED_MAGIC = b"knifeedge checked numba cache\n"


def _checked(data: bytes) -> bytes:
    return CHECKED_MAGIC + hashlib.sha256(data).digest() + data


def _verified(data: bytes, path) -> bytes:
    """``data`` without its :func:`_checked` prefix; ValueError if the prefix or the checksum is wrong."""
    head = len(CHECKED_MAGIC) + 32
    if not data.startswith(CHECKED_MAGIC):
        raise ValueError(f"{path}: not a checked cache file of this version")
    if hashlib.sha256(data[head:]).digest() != data[len(CHECKED_MAGIC):head]:
        raise ValueError(f"{path}: its checksum does not match its content")
    return data[head:]


def write_checked(path: Path, data: bytes, what: str) -> None:
    """Keep the bytes ``data`` in ``path`` as a checked file (:func:`_checked`), mode 0644, written to a temporary
    file and renamed (a folder that cannot be written: :func:`not_kept`)."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        with open(os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644), "wb") as f:
            f.write(_checked(data))
        os.replace(tmp, path)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        not_kept(exc, path, what)


def read_checked(path: Path) -> bytes:
    """The bytes :func:`write_checked` kept in ``path``, after checking that the file is this user's and no one
    else may write it, and its checksum; ValueError saying which check failed."""
    st = os.lstat(path)
    if not stat.S_ISREG(st.st_mode):
        raise ValueError(f"{path}: not a plain file")
    if hasattr(os, "getuid") and (st.st_uid != os.getuid() or st.st_mode & 0o022):
        raise ValueError(f"{path}: owned by user id {st.st_uid} with mode {stat.S_IMODE(st.st_mode):o}: only this "
                         "user's files that no one else may write are loaded")
    return _verified(path.read_bytes(), path)


def not_kept(exc: OSError, path, what: str) -> None:
    """Say in one line that ``what`` could not be written to ``path`` (a full disk said as such): it stays
    compiled for this process only."""
    why = "the disk is full" if exc.errno in (errno.ENOSPC, errno.EDQUOT) else f"{type(exc).__name__}: {exc}"
    print(f"knifeedge: could not keep {what} in {path} ({why}); it stays compiled for this process only (free "
          "some space, or set KNIFEEDGE_CACHE_DIR to a folder on another disk)", file=sys.stderr, flush=True)


def discard(paths, problem, what: str) -> None:
    """Remove the damaged cache files ``paths`` (``what`` says of which kind) and say so in one line: what
    they held is compiled again."""
    for f in paths:
        Path(f).unlink(missing_ok=True)
    print(f"knifeedge: discarded a damaged {what} {paths[0]} ({type(problem).__name__}: {problem}); compiling it "
          "again", file=sys.stderr, flush=True)


def _entry(index_path) -> list:
    """The files of one entry of numba's cache: its index ``<name>.nbi`` and its data files ``<name>.<k>.nbc``."""
    return [index_path, *glob.glob(f"{glob.escape(str(index_path)[:-len('.nbi')])}.*.nbc")]


#: what numba raises when a file of its own cache is damaged (truncated, overwritten, unreadable)
_DAMAGE = (EOFError, pickle.UnpicklingError, zlib.error, ValueError, TypeError, AttributeError, IndexError,
           KeyError, OSError, ImportError)


def call_repairing(fn, *args):
    """``fn(*args)``; a damaged file of numba's own cache (a plain ``cache=True`` function's: the kernels' files
    are checked where they are read) read on the way is discarded with its entry and the call made again, which
    compiles it again.  A full disk is not damage: raised as it is."""
    for _ in range(16):
        try:
            return fn(*args)
        except _DAMAGE as exc:
            if isinstance(exc, OSError) and exc.errno in (errno.ENOSPC, errno.EDQUOT):
                raise
            tb, index = exc.__traceback__, None
            while tb is not None:  # the innermost cache file numba was reading
                if tb.tb_frame.f_code.co_filename == caching.__file__:
                    index = getattr(tb.tb_frame.f_locals.get("self"), "_index_path", None) or index
                tb = tb.tb_next
            if index is None:
                raise
            discard(_entry(index), exc, "compiled-code cache entry")
    return fn(*args)


class CheckedCacheFile(IndexDataCacheFile):
    """numba's index-and-data cache file with a SHA-256 written with each file and verified before anything in
    it is unpickled; a damaged file is discarded with its entry (numba compiles it again), an entry that
    cannot be saved is said.  Private numba API: ``_dump``, ``_save_index``, ``_load_index``, ``_load_data``,
    ``_data_path``, ``_open_for_write``, ``_index_path``, ``_version``, ``_source_stamp``."""

    def _dump(self, obj):
        return _checked(super()._dump(obj))

    def _save_index(self, overloads):
        data = self._version.encode() + b"\n" + IndexDataCacheFile._dump(self, (self._source_stamp, overloads))
        with self._open_for_write(self._index_path) as f:
            f.write(_checked(data))

    def save(self, key, data):
        try:
            super().save(key, data)
        except OSError as exc:
            not_kept(exc, self._index_path, "the compiled code")

    def _read(self, path):
        """The content of ``path`` without its checksum, or None: missing, or damaged (then discarded)."""
        try:
            with open(path, "rb") as f:
                return _verified(f.read(), path)
        except FileNotFoundError:
            return None
        except (OSError, ValueError) as exc:
            discard(_entry(self._index_path), exc, "compiled-code cache entry")
            return None

    def _load_index(self):
        data = self._read(self._index_path)
        if data is None:
            return {}
        version, _, data = data.partition(b"\n")
        if version != self._version.encode():
            return {}
        stamp_, overloads = pickle.loads(data)
        return overloads if stamp_ == self._source_stamp else {}

    def _load_data(self, name):
        data = self._read(self._data_path(name))
        return None if data is None else pickle.loads(data)
