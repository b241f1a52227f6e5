"""Where a sweep's runs execute: local worker processes, any ``Executor``, or this process.

Each backend takes *tasks* (a task id and a list of runs as plain dicts) and
reports, for each finished task, either its outcomes or an infrastructure
failure -- a worker that died, a broken pool, a cancelled future.  Such a
failure is not a result: the sweep retries those runs or leaves them
without a result, to be computed on resume.

:class:`LocalPool` is the default.  Its workers are plain child processes
(``python -c ...``) fed through their stdin and answering on their stdout,
so that

* a worker that dies (``SIGKILL`` from the out-of-memory killer, a crash)
  costs only the task it was running: the parent sees the end of its pipe,
  knows exactly which runs were lost, and starts a new worker;
* a worker never outlives the sweep: it ends when its parent dies (Linux
  ``PR_SET_PDEATHSIG``, and a thread that watches the parent process id
  elsewhere), when its stdin closes, or when the sweep shuts the pool down;
* a worker ignores Ctrl-C (the terminal sends it to the whole process
  group); the sweep decides what to do and ends its workers.

On Linux, when no other thread is running, a worker is forked from the
sweep's process (it starts with the package imported and the kernels
compiled, in milliseconds); otherwise it is a new interpreter
(``python -c ...``), which imports the package and loads the kernels from the
cache first.
"""
from __future__ import annotations

import concurrent.futures as cf
import importlib
import os
import pickle
import selectors
import signal
import struct
import subprocess
import sys
import threading
import time
import uuid
from collections.abc import Callable

_HEADER = struct.Struct("<Q")


class WorkerLost(Exception):
    """A task ended without outcomes because of the infrastructure (not the integration)."""


def _frame(obj) -> bytes:
    data = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
    return _HEADER.pack(len(data)) + data


# -- the worker side --------------------------------------------------------------------
def _die_with_parent(parent: int) -> None:
    if sys.platform.startswith("linux"):
        try:
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(1, signal.SIGKILL, 0, 0, 0)  # PR_SET_PDEATHSIG
        except (OSError, AttributeError):
            pass
    if os.getppid() != parent:  # the parent died before the line above took effect
        os._exit(70)

    def watch():
        while True:
            time.sleep(1.0)
            if os.getppid() != parent:
                os._exit(70)

    threading.Thread(target=watch, name="knifeedge-parent-watch", daemon=True).start()


def worker_main(parent: int, fn: str) -> None:
    """Entry of a worker started as a new interpreter: the protocol runs on its stdin and stdout.

    ``fn``: ``"module:name"`` of the function that runs a task's list of runs (the pool's, :func:`_reference`).
    """
    module, _, name = fn.partition(":")
    run = getattr(importlib.import_module(module), name)
    proto_out = os.fdopen(os.dup(1), "wb", buffering=0)
    os.dup2(2, 1)  # anything printed goes to stderr, not into the protocol
    sys.stdout = sys.stderr
    proto_in = os.fdopen(os.dup(0), "rb", buffering=0)
    _serve(proto_in, proto_out, parent, run)


def _serve(proto_in, proto_out, parent: int, run_batch: Callable) -> None:
    """Loop of a worker: read a task, run it (``run_batch(runs)``), write the outcomes; leave with ``os._exit``."""
    try:
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        _die_with_parent(parent)

        def read_exact(n: int) -> bytes | None:
            buf = b""
            while len(buf) < n:
                chunk = proto_in.read(n - len(buf))
                if not chunk:
                    return None
                buf += chunk
            return buf

        proto_out.write(_frame(("ready", os.getpid())))
        while True:
            head = read_exact(_HEADER.size)
            body = None if head is None else read_exact(_HEADER.unpack(head)[0])
            msg = None if body is None else pickle.loads(body)
            if msg is None:  # the sweep is done (or closed our stdin, or died): nothing to tidy up
                break
            task_id, runs = msg
            out = run_batch(runs)
            proto_out.write(_frame((task_id, out)))
    except BaseException:  # noqa: BLE001 - a broken pipe, a crash: the parent sees the end of the pipe
        import traceback

        traceback.print_exc()
    finally:
        os._exit(0)


# -- the parent side ----------------------------------------------------------------------
class _Forked:
    """A worker forked from this process (Linux, when no other thread runs): it starts with the package and the
    compiled kernels already loaded.  Offers the part of ``subprocess.Popen`` the pool uses."""

    def __init__(self, fn: Callable):
        parent = os.getpid()
        r_task, w_task = os.pipe()
        r_out, w_out = os.pipe()
        pid = os.fork()
        if pid == 0:  # the worker
            os.close(w_task)
            os.close(r_out)
            _serve(os.fdopen(r_task, "rb", buffering=0), os.fdopen(w_out, "wb", buffering=0), parent, fn)
        os.close(r_task)
        os.close(w_out)
        self.pid = pid
        self.stdin = os.fdopen(w_task, "wb", buffering=0)
        self.stdout = os.fdopen(r_out, "rb", buffering=0)
        self.returncode = None

    def poll(self):
        if self.returncode is None:
            pid, status = os.waitpid(self.pid, os.WNOHANG)
            if pid:
                self.returncode = os.waitstatus_to_exitcode(status)
        return self.returncode

    def wait(self, timeout=None):
        deadline = None if timeout is None else time.monotonic() + timeout
        while self.poll() is None:
            if deadline is not None and time.monotonic() > deadline:
                raise subprocess.TimeoutExpired(f"worker {self.pid}", timeout)
            time.sleep(0.01)
        return self.returncode

    def kill(self):
        os.kill(self.pid, signal.SIGKILL)


def _can_fork() -> bool:
    return sys.platform.startswith("linux") and threading.active_count() == 1 and hasattr(os, "fork")


def _reference(fn: Callable) -> str:
    """``"module:name"`` of a module-level function, which a new interpreter imports (:func:`worker_main`)."""
    if getattr(importlib.import_module(fn.__module__), fn.__qualname__, None) is not fn:
        raise ValueError(f"`fn` must be a module-level function (a worker imports it by name), got {fn!r}")
    return f"{fn.__module__}:{fn.__qualname__}"


class _Worker:
    def __init__(self, env: dict, fn: Callable):
        if _can_fork():
            self.proc = _Forked(fn)
        else:
            code = ("import sys; sys.path[:0] = %r; from knifeedge.workers import worker_main; worker_main(%d, %r)"
                    % ([p for p in sys.path if p], os.getpid(), _reference(fn)))
            self.proc = subprocess.Popen([sys.executable, "-c", code], stdin=subprocess.PIPE,
                                         stdout=subprocess.PIPE, env=env, close_fds=True)
        os.set_blocking(self.proc.stdout.fileno(), False)
        self.buf = b""
        self.ready = False
        self.tasks: list = []  # task ids sent, oldest first

    def send(self, obj) -> bool:
        try:
            self.proc.stdin.write(_frame(obj))
            self.proc.stdin.flush()
            return True
        except (BrokenPipeError, OSError):
            return False

    def frames(self) -> tuple[list, bool]:
        """Complete messages available now, and whether the pipe reached its end (the worker exited)."""
        eof = False
        while True:
            try:
                chunk = os.read(self.proc.stdout.fileno(), 1 << 16)
            except BlockingIOError:
                break
            except OSError:
                eof = True
                break
            if not chunk:
                eof = True
                break
            self.buf += chunk
        out = []
        while len(self.buf) >= _HEADER.size:
            n = _HEADER.unpack_from(self.buf)[0]
            if len(self.buf) < _HEADER.size + n:
                break
            out.append(pickle.loads(self.buf[_HEADER.size:_HEADER.size + n]))
            self.buf = self.buf[_HEADER.size + n:]
        return out, eof

    def exit_reason(self) -> str:
        try:
            code = self.proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            self.kill()
            code = self.proc.wait()
        if code is not None and code < 0:
            try:
                name = signal.Signals(-code).name
            except ValueError:
                name = f"signal {-code}"
            return f"the worker process (pid {self.proc.pid}) was killed by {name}"
        return f"the worker process (pid {self.proc.pid}) exited with status {code}"

    def kill(self) -> None:
        if self.proc.poll() is None:
            try:
                self.proc.kill()
            except ProcessLookupError:
                pass

    def close(self) -> None:
        for f in (self.proc.stdin, self.proc.stdout):
            try:
                f.close()
            except OSError:
                pass


class LocalPool:
    """``n`` worker processes running ``fn`` (a module-level function of a task's list of runs, which returns
    their outcomes); a dead worker is replaced and its task reported lost.

    Use :meth:`submit` (returns False if no worker is free for more work) and
    :meth:`wait`, which returns ``[(task_id, outcomes or WorkerLost)]``.
    """

    depth = 2  # tasks queued per worker, so that it never waits for the parent

    def __init__(self, n: int, fn: Callable):
        self.n, self.fn = int(n), fn
        self.env = dict(os.environ)
        self.sel = selectors.DefaultSelector()
        self.workers: list = []
        self.startup_failures = 0
        self._last_error = ""
        for _ in range(self.n):
            self._start()

    @property
    def slots(self) -> int:
        return self.n * self.depth

    def _start(self) -> None:
        w = _Worker(self.env, self.fn)
        self.workers.append(w)
        self.sel.register(w.proc.stdout, selectors.EVENT_READ, w)

    def free(self) -> bool:
        return any(len(w.tasks) < self.depth for w in self.workers)

    def submit(self, task_id, runs: list) -> None:
        w = min(self.workers, key=lambda w: len(w.tasks))
        w.tasks.append(task_id)
        w.send((task_id, runs))  # a failed send shows up as the worker's end of pipe

    def pids(self) -> list:
        return [w.proc.pid for w in self.workers]

    def wait(self, timeout: float) -> list:
        done: list = []
        for key, _ in self.sel.select(timeout):
            w = key.data
            msgs, eof = w.frames()
            for msg in msgs:
                if msg[0] == "ready":
                    w.ready = True
                    self.startup_failures = 0
                    continue
                task_id, out = msg
                if task_id in w.tasks:
                    w.tasks.remove(task_id)
                done.append((task_id, out))
            if eof:
                reason = w.exit_reason()
                self.sel.unregister(w.proc.stdout)
                w.close()
                self.workers.remove(w)
                if not w.ready:
                    self.startup_failures += 1
                    self._last_error = reason
                    if self.startup_failures >= 3:
                        self.shutdown()
                        raise RuntimeError(f"sweep: worker processes cannot start ({reason}); see the messages "
                                           "above, or run with executor='serial'")
                done.extend((t, WorkerLost(reason)) for t in w.tasks)
                self._start()
        return done

    def shutdown(self) -> None:
        """End every worker: ask politely, then kill what is still running."""
        workers, self.workers = self.workers, []
        for w in workers:
            if not w.tasks:
                w.send(None)
        for w in workers:
            if w.tasks:
                w.kill()
        deadline = time.monotonic() + 5.0
        for w in workers:
            try:
                w.proc.wait(timeout=max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                w.kill()
                w.proc.wait()
            try:
                self.sel.unregister(w.proc.stdout)
            except (KeyError, ValueError):
                pass
            w.close()
        self.sel.close()


class ExecutorPool:
    """Tasks on a ``concurrent.futures.Executor`` (a process pool, ``distributed.Client.get_executor()``, ...)."""

    #: wall time a task aims at, and most runs in one: a task costs a Dask scheduler, client and worker a few
    #: milliseconds of CPU between them, so tasks are longer than on local workers
    task_seconds = 1.0
    max_chunk = 1024
    #: the shortest task the sweep's balanced tail makes (on local workers it goes down to one run): 5 ms of a
    #: Dask client's and scheduler's CPU per task is 2.5 % of a task this long
    min_task_seconds = 0.2

    def __init__(self, executor: cf.Executor, fn: Callable, slots: int):
        self.executor, self.fn, self.slots_ = executor, fn, max(1, int(slots))
        self.futures: dict = {}
        self.broken: str | None = None

    @property
    def slots(self) -> int:
        return self.slots_

    def free(self) -> bool:
        return self.broken is None and len(self.futures) < self.slots_

    def submit(self, task_id, runs: list) -> None:
        try:
            self.futures[self.executor.submit(_run_task, self.fn, _Task(runs))] = task_id
        except Exception as exc:  # a broken or shut-down executor takes no more work  # noqa: BLE001
            self.broken = f"{type(exc).__name__}: {exc}"
            self.futures[_failed(exc)] = task_id

    def wait(self, timeout: float) -> list:
        if not self.futures:
            time.sleep(min(timeout, 0.05))
            return []
        # a future cancelled before it ran is never "done" for cf.wait: look for those first
        finished = [f for f in self.futures if f.cancelled()]
        if not finished:
            finished, _ = cf.wait(list(self.futures), timeout=timeout, return_when=cf.FIRST_COMPLETED)
        done = []
        for fut in finished:
            task_id = self.futures.pop(fut)
            try:
                done.append((task_id, fut.result().outcomes))
            except BaseException as exc:  # noqa: BLE001 - a dead worker, a broken pool, a cancelled future
                if isinstance(exc, KeyboardInterrupt):
                    raise
                done.append((task_id, WorkerLost(f"{type(exc).__name__}: {exc}".rstrip(": "))))
        return done

    def shutdown(self) -> None:
        for fut in self.futures:
            fut.cancel()
        self.futures.clear()


class _Task:
    """The runs of one task (iterable, sized), opaque to an executor: a Dask client hashes the arguments of each
    task (``tokenize``) and walks them for futures, which cost more than the sweep's own bookkeeping when they
    were a list of dicts.  A task has a token of its own, so that two tasks never share a key."""

    __slots__ = ("runs", "token")

    def __init__(self, runs: list):
        self.runs = runs
        self.token = uuid.uuid4().hex

    def __iter__(self):
        return iter(self.runs)

    def __len__(self) -> int:
        return len(self.runs)

    def __dask_tokenize__(self):
        return self.token

    def __getstate__(self):
        return self.runs, self.token

    def __setstate__(self, state):
        self.runs, self.token = state


def _run_task(fn: Callable, task: _Task) -> _Outcomes:
    """``fn`` on a task's runs (in an executor's worker), its list of outcomes wrapped as one object."""
    return _Outcomes(fn(task))


class _Outcomes:
    """The outcomes of a task's runs, one object to an executor.  A Dask worker serializes a list of dicts element
    by element, with a header each (13 ms for a task of 666 runs, against 0.5 ms for this object), and its
    client reads them back the same way."""

    __slots__ = ("outcomes",)

    def __init__(self, outcomes: list):
        self.outcomes = outcomes

    def __sizeof__(self) -> int:  # what Dask counts in a worker's memory: the list and its rows (shallow)
        return object.__sizeof__(self) + sys.getsizeof(self.outcomes) + sum(map(sys.getsizeof, self.outcomes))

    def __getstate__(self):
        return self.outcomes

    def __setstate__(self, state):
        self.outcomes = state


def _failed(exc: BaseException) -> cf.Future:
    fut: cf.Future = cf.Future()
    fut.set_exception(exc)
    return fut


class SerialPool:
    """Tasks run in this process, one at a time, when :meth:`wait` is called."""

    slots = 1

    def __init__(self, fn: Callable):
        self.fn = fn
        self.queue: list = []

    def free(self) -> bool:
        return not self.queue

    def submit(self, task_id, runs: list) -> None:
        self.queue.append((task_id, runs))

    def wait(self, timeout: float) -> list:
        if not self.queue:
            time.sleep(min(timeout, 0.05))
            return []
        task_id, runs = self.queue.pop(0)
        return [(task_id, self.fn(runs))]

    def shutdown(self) -> None:
        self.queue.clear()
