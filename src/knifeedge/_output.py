"""Files a command or a function writes for the user: checked before any work, written whole or not at all.

:func:`writable` is called with the other argument checks: a folder that
cannot be created or written, or a path that is a folder, is a
``ValueError`` naming the argument before the run starts (not an
``OSError`` after it).  :func:`replacing` writes through a temporary file
beside the target and moves it into place only when the writer finished, so
that an error or a Ctrl-C leaves no half-written file (and an earlier file of
the same name untouched).
"""
from __future__ import annotations

import contextlib
import os
from pathlib import Path


def writable(path, what: str) -> Path:
    """``Path(path)``, its folder made if needed, once a file can be created there; else ``ValueError`` naming
    ``what`` (e.g. ``"`--out`"``)."""
    path = Path(path)
    if path.is_dir():
        raise ValueError(f"{what} {str(path)!r} is a folder: give the name of a file in it")
    above = next((d for d in path.parents if d.exists()), None)  # the nearest folder that exists, or a file
    if above is not None and not above.is_dir():
        raise ValueError(f"{what} {str(path)!r} cannot be written: {str(above)!r} is a file, not a folder")
    probe = _temporary(path)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        with open(probe, "x"):
            pass
    except OSError as exc:
        raise ValueError(f"{what} {str(path)!r} cannot be written ({exc.strerror or exc}); choose a writable "
                         f"location") from None
    probe.unlink()
    return path


@contextlib.contextmanager
def replacing(path: Path):
    """A temporary path beside ``path`` (same suffix, so writers pick the same format) to write in the block;
    moved onto ``path`` when the block ends, removed if it raises."""
    tmp = _temporary(path)
    try:
        yield tmp
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            tmp.unlink()
        raise


def _temporary(path: Path) -> Path:
    """A hidden file name beside ``path`` that no other process picks, ending in ``path``'s suffix."""
    return path.with_name(f".{path.stem}.{os.getpid()}-{os.urandom(4).hex()}.part{path.suffix}")
