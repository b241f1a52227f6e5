"""Who holds a claim or a lock: a process named by its id and its start time.

A process id alone is reused by the system; with the start time it names one
process.  The sweep's claims (:mod:`knifeedge.store`) and the background
compiler's locks (:mod:`knifeedge.integrators.compiler`) both write the two
and ask :func:`alive` before honouring what another process holds.
:func:`heap_frozen` keeps a process's long-lived objects out of the cyclic
garbage collector's passes (a sweep, the figures' forked workers).
"""
from __future__ import annotations

import contextlib
import gc
import os


def start_time(pid: int) -> str | None:
    """The start time of process ``pid`` (Linux ``/proc``, clock ticks since boot), to tell a reused pid from its
    first owner; None where it cannot be read (no such process, or no ``/proc``)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            return f.read().rsplit(b")", 1)[1].split()[19].decode()
    except (OSError, IndexError):
        return None


def alive(pid: int, started: str | None) -> bool:
    """Whether process ``pid`` started at ``started`` (:func:`start_time`; None: not known) still runs."""
    if pid <= 0:  # 0 and negative ids name process groups
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        pass  # exists, another user's
    except (OverflowError, ValueError):
        return False
    return started is None or start_time(pid) in (None, started)


@contextlib.contextmanager
def heap_frozen():
    """The objects alive on entry (the modules, the kernels) left out of the cyclic garbage collector's passes
    until the context ends (:func:`gc.freeze`); the context's value freezes those alive when called.

    A full pass over them cost a sweep's process 0.1 s of CPU each (numba and SciPy hold some 10^5 objects),
    once per few thousand rows; and workers forked inside the context would walk them too, copying the pages
    they share with this process.  Nothing is done if the collector is off or something else froze objects
    already.
    """
    if not gc.isenabled() or gc.get_freeze_count():
        yield lambda: None
        return
    gc.freeze()
    try:
        yield gc.freeze
    finally:
        gc.unfreeze()
