"""Compiling a kernel in a background process while a first run goes on without it.

In the ``"background"`` compile mode a run whose kernel is not compiled starts a separate process that compiles it
into the cache (:func:`start`) and is stepped meanwhile by SciPy's solver of the same method
(``simulate._run_compiled``), moving into the kernel when it is ready; the mode ``"wait"`` compiles in the
calling process.  docs/integrators.md says more.
"""
from __future__ import annotations

import base64
import contextlib
import json
import os
import pickle
import subprocess
import sys
from pathlib import Path

from .._process import alive, start_time

MODES = ("wait", "background")
_MODE: list = [None]
#: what the compiling process runs (not ``-m``: the module is imported by its package first)
_CHILD = "import sys; from knifeedge.integrators.compiler import _main; sys.exit(_main())"
#: the compiling processes this process started, by kernel file name
_STARTED: dict = {}


def set_compile_mode(mode: str) -> None:
    """Set how a kernel that is not yet compiled is compiled (overrides ``$KNIFEEDGE_COMPILE``).

    ``"wait"``: the first run of a (model, method) pair compiles it, then runs.  ``"background"``: a separate
    process compiles it while SciPy's solver of the same method (``DOP853``, ``DP54``/``RK45``) answers; the run
    moves into the kernel when it is ready.  Methods without a SciPy twin, and ``error_control="mode"``, wait.
    """
    if mode not in MODES:
        raise ValueError(f"`mode` must be one of {MODES}, got {mode!r}")
    _MODE[0] = mode


@contextlib.contextmanager
def compile_mode_set(mode: str):
    """Context manager: :func:`set_compile_mode` ``mode`` inside the block, the previous setting after it."""
    previous = _MODE[0]
    set_compile_mode(mode)
    try:
        yield
    finally:
        _MODE[0] = previous


def compile_mode() -> str:
    """The compile mode in force: :func:`set_compile_mode`, else ``$KNIFEEDGE_COMPILE``, else ``"wait"``."""
    if _MODE[0] is not None:
        return _MODE[0]
    env = os.environ.get("KNIFEEDGE_COMPILE", "").strip()
    if env and env not in MODES:
        raise ValueError(f"environment variable KNIFEEDGE_COMPILE must be one of {MODES}, got {env!r}")
    return env or "wait"


class Pending:
    """A kernel being compiled by another process: ``module`` the kernel (made, not compiled), ``path`` its name in
    the cache folder (the lock: suffix ``.compiling``), ``started`` whether this process started the compiler."""

    def __init__(self, module, path: Path, proc, started: bool):
        self.module, self.path, self.proc, self.started = module, path, proc, started

    def ready(self) -> bool:
        """Whether the compiled code is in the cache (a cheap check: one file's existence)."""
        return self.module.is_compiled()

    def failed(self) -> bool:
        """Whether the compiling process ended (or its lock disappeared) without leaving compiled code."""
        if self.ready():
            return False
        if self.proc is not None:
            return self.proc.poll() is not None
        return _holder(_lock(self.path)) is None

    def log(self) -> str:
        """The compiling process's error output (empty if none)."""
        try:
            return _log(self.path).read_text()[-2000:]
        except OSError:
            return ""


def _lock(path: Path) -> Path:
    return path.with_suffix(".compiling")


def _log(path: Path) -> Path:
    return path.with_suffix(".log")


def _holder(lock: Path) -> int | None:
    """The process id of the live compiling process that holds ``lock``, or None (no lock, or a stale one).

    A lock holds ``"<pid> <start time>"`` (:mod:`knifeedge._process`): a reused pid does not hold it; a lock
    without the start time is stale where start times can be read."""
    try:
        fields = lock.read_text().split()
        pid = int(fields[0])
    except (OSError, ValueError, IndexError):
        return None
    started = fields[1] if len(fields) > 1 and fields[1] != "-" else None
    if started is None and start_time(os.getpid()) is not None:
        return None
    return pid if alive(pid, started) else None


def start(model, method: str, kernel_module, arg_types: tuple) -> Pending:
    """Compile the kernel of ``method`` for ``model`` (``kernel_module``) for the argument types ``arg_types``
    (numba's types of its ``solve(*args)``) in a separate process; a :class:`Pending`.  None is started while
    another live process compiles the same kernel (its lock file names it)."""
    path = Path(kernel_module.path)
    lock = _lock(path)
    if path.name in _STARTED:
        return _STARTED[path.name]
    if _holder(lock) is not None:
        return Pending(kernel_module, path, None, started=False)
    lock.unlink(missing_ok=True)
    job = {
        "kernel": str(path), "method": method,
        "model": model.module.MODEL, "fidelity": model.module.FIDELITY, "pose": bool(model.pose),
        "path": str(model.source_path.parent) if model.source_path is not None else None,
        "types": base64.b64encode(pickle.dumps(tuple(arg_types))).decode(),
    }
    env = dict(os.environ, KNIFEEDGE_COMPILE="wait")
    with open(_log(path), "w") as err:
        proc = subprocess.Popen([sys.executable, "-c", _CHILD], stdin=subprocess.PIPE,
                                stdout=subprocess.DEVNULL, stderr=err, env=env, start_new_session=True)
    lock.write_text(f"{proc.pid} {start_time(proc.pid) or '-'}")
    proc.stdin.write(json.dumps(job).encode())
    proc.stdin.close()
    pending = Pending(kernel_module, path, proc, started=True)
    _STARTED[path.name] = pending
    return pending


def _main() -> int:
    """The compiling process: read the job from stdin, import the model and the kernel, compile, cache."""
    job = json.loads(sys.stdin.read())
    path = Path(job["kernel"])
    try:
        from ..models import load
        from .kernels import kernel_module

        model = load(job["model"], fidelity=job["fidelity"], pose=job["pose"], path=job["path"])
        module = kernel_module(model, job["method"])
        if Path(module.path) != path:
            raise RuntimeError(f"the kernel of this process is {module.path}, not {path}")
        module.compile_types(pickle.loads(base64.b64decode(job["types"])))
        try:  # compiled: nothing to report, so no log is left beside the kernel (before the lock goes)
            if _log(path).stat().st_size == 0:
                _log(path).unlink()
        except OSError:
            pass
    finally:
        lock = _lock(path)
        try:
            if int(lock.read_text().split()[0]) == os.getpid():
                lock.unlink()
        except (OSError, ValueError, IndexError):
            pass
    return 0

