"""Issue 26, root 2: cached compiled code is checked before it runs.

The compiled parts of a kernel (``.nbo``) are kept in the checked format of
numba's own cache files of the kernels, whose owner, checksum and compiler
key are verified before anything in it is unpickled or loaded; a damaged or altered file is removed, said in one line and
compiled again.  The cache folder, wherever it is, is refused when another
user could write to it; the background compiler's locks name their process by
pid and start time; a full disk is said as such.
"""
import errno
import inspect
import os
import pickle
import struct
import subprocess
import sys
import types

import numpy as np
import pytest

from knifeedge import _process
from knifeedge.integrators import cache, compiler, irparts
from knifeedge.integrators.methods import DOP853


def _blobs():
    return ("knifeedge_parts_test", "object", (b"\x7fELF" + bytes(range(256)) * 4, b"BC\xc0\xde" + b"\x01" * 300))


def test_cached_compiled_code_is_checked_before_it_runs_parts_file(tmp_path, monkeypatch, capsys):
    """A parts file written by write_parts reads back as numba serialized it; a flipped byte, a cut file, a
    pickle planted in its place, parts of another numba or machine, and a file others may write are each
    refused with the check that failed, before anything in it is unpickled or used."""
    path = tmp_path / "k.parts-x.nbo"
    irparts.write_parts(path, _blobs())
    with monkeypatch.context() as patch:  # no pickle in our own files (issue 26): reading one unpickles nothing
        patch.setattr(pickle, "loads", lambda *a, **k: pytest.fail("the parts file was unpickled"))
        assert irparts.read_parts(path) == _blobs()
    good = path.read_bytes()
    assert good.startswith(cache.CHECKED_MAGIC)  # the kernels' own checked format, not a bare pickle
    body = good.index(b"\x7fELF")

    def refused(data: bytes, match: str):
        path.write_bytes(data)
        with pytest.raises(ValueError, match=match):
            irparts.read_parts(path)

    refused(good[:body + 10] + bytes([good[body + 10] ^ 1]) + good[body + 11:], "checksum")
    refused(good[:-4], "checksum")
    refused(pickle.dumps(_blobs()), "not a checked cache file")
    key = irparts._key()
    for other in ((1,) + key[1:], key[:1] + ("0.1",) + key[2:], key[:3] + (("x86_64-unknown", "other-cpu", ""),)):
        monkeypatch.setattr(irparts, "_key", lambda other=other: other)
        irparts.write_parts(path, _blobs())
        monkeypatch.setattr(irparts, "_key", lambda: key)
        refused(path.read_bytes(), "another compiler or for another machine")
    irparts.write_parts(path, _blobs())
    path.chmod(0o666)
    if hasattr(os, "getuid"):
        with pytest.raises(ValueError, match="no one else may write"):
            irparts.read_parts(path)
    assert capsys.readouterr().err == ""


@pytest.mark.slow
def test_cached_compiled_code_is_checked_before_it_runs_scaled_constant(tmp_path):
    """The probe's case: one coefficient of DOP853 scaled in the cached object code.  The next process must not
    run it (its reversal time would change): it says one line, compiles again and gets the first answer."""
    code = (
        "import numpy as np, knifeedge as ke\n"
        "m = ke.load('single_mode', 'reduced')\n"
        "r = ke.simulate(m, {'theta': 1e-3, 'theta_dot': 0.0, 'phi_dot': 0.1}, (0.0, 150.0),"
        " m.params(g=1.0, ell=1.0, L=1.0, D=1.0), rtol=1e-10)\n"
        "print(r.success, repr(float(r.reversal_times[0])), r.nfev)\n"
    )
    env = dict(os.environ, KNIFEEDGE_CACHE_DIR=str(tmp_path / "k"), NUMBA_CACHE_DIR=str(tmp_path / "n"))
    first = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    parts = next((tmp_path / "k" / "kernels").glob("erk-DOP853-single_mode_reduced-*.parts-*.nbo"))
    data = parts.read_bytes()
    constant = struct.pack("<d", float(DOP853.A[1, 0]))  # the first stage's coefficient, a literal of the IR
    assert data.count(constant) >= 1
    parts.write_bytes(data.replace(constant, struct.pack("<d", float(DOP853.A[1, 0]) * 1.5)))
    again = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert again.stdout == first.stdout
    lines = [ln for ln in again.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and "discarded a damaged compiled-parts cache file" in lines[0], again.stderr
    assert parts.read_bytes().count(constant) >= 1  # compiled again


def test_cached_compiled_code_is_checked_before_it_runs_cache_folder(tmp_path, monkeypatch, capsys):
    """KNIFEEDGE_CACHE_DIR and XDG_CACHE_HOME get the checks of the temporary fallback: a folder others may
    write to (or its kernels folder) is refused, said once, and the private fallback used."""
    if not hasattr(os, "getuid"):
        pytest.skip("no user ids")
    monkeypatch.setattr(cache.tempfile, "gettempdir", lambda: str(tmp_path / "tmp"))
    (tmp_path / "tmp").mkdir()
    fallback = tmp_path / "tmp" / f"knifeedge-cache-{os.getuid()}"
    shared = tmp_path / "shared"
    shared.mkdir()
    shared.chmod(0o777)
    monkeypatch.setenv("KNIFEEDGE_CACHE_DIR", str(shared))
    assert cache.cache_dir() == fallback
    assert "others may write to it" in capsys.readouterr().err
    monkeypatch.delenv("KNIFEEDGE_CACHE_DIR")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert cache.cache_dir() == tmp_path / "xdg" / "knifeedge"  # created private
    assert (tmp_path / "xdg" / "knifeedge" / "kernels").stat().st_mode & 0o777 == 0o700
    (tmp_path / "xdg" / "knifeedge" / "kernels").chmod(0o777)
    assert cache.cache_dir() == fallback
    assert "kernels: others may write to it" in capsys.readouterr().err


def test_cached_compiled_code_is_checked_before_it_runs_lock(tmp_path, monkeypatch):
    """A ``.compiling`` lock naming a live process that is not the compiler that wrote it (a pid reused, or a
    lock of an earlier version holding only a pid) does not stop background compiling; the lock of a live
    compiler does."""
    started = []

    class _Proc:
        pid = os.getpid()
        stdin = types.SimpleNamespace(write=lambda b: None, close=lambda: None)

        def poll(self):
            return None

    def popen(*args, **kwargs):
        started.append(args)
        return _Proc()

    monkeypatch.setattr(compiler.subprocess, "Popen", popen)
    kernel = types.SimpleNamespace(path=tmp_path / "erk-DOP853-m-0123", TABLEAU="DOP853", is_compiled=lambda: False,
                                   RHS_NAME="rhs_q_into")
    model = types.SimpleNamespace(module=types.SimpleNamespace(MODEL="m", FIDELITY="full"), pose=False,
                                  source_path=None)
    lock = tmp_path / "erk-DOP853-m-0123.compiling"
    if _process.start_time(os.getpid()) is None:
        pytest.skip("process start times cannot be read here")
    unrelated = os.getppid()  # alive, and not a compiler
    for text in (str(unrelated), f"{unrelated} 1"):
        lock.write_text(text)
        compiler._STARTED.clear()
        pending = compiler.start(model, "DOP853", kernel, ())
        assert pending.started and len(started) == 1, text
        started.clear()
    assert lock.read_text() == f"{os.getpid()} {_process.start_time(os.getpid())}"  # the new lock: pid and start
    compiler._STARTED.clear()
    pending = compiler.start(model, "DOP853", kernel, ())  # a live compiler holds it: none started
    assert not pending.started and not started and not pending.failed()
    compiler._STARTED.clear()


def test_cached_compiled_code_is_checked_before_it_runs_disk_full(tmp_path, monkeypatch, capsys):
    """A full disk while the cache is written (a kernel's entry or its parts) is said as such, never as a
    damaged entry, and the run goes on with what it compiled."""
    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device", str(tmp_path / "x"))

    monkeypatch.setenv("KNIFEEDGE_CACHE_DIR", str(tmp_path / "k"))
    monkeypatch.setattr(cache.CheckedCacheFile, "_open_for_write", full)
    assert _scaled(1.5, "test-full")(2.0) == 3.0
    err = capsys.readouterr().err
    assert "the disk is full" in err and "damaged" not in err
    monkeypatch.setattr("builtins.open", full)
    irparts.write_parts(tmp_path / "k.parts-x.nbo", _blobs())
    err = capsys.readouterr().err
    assert "the disk is full" in err and "damaged" not in err
    monkeypatch.undo()
    assert not list(tmp_path.glob(".*tmp"))


def _scaled(factor: float, label: str):
    """A kernel as the factories make them: a closure over a constant, compiled and cached (made anew, as a
    second process would: a new dispatcher reading the cache's files)."""
    def scaled(x):
        return factor * x

    return cache.compiled(scaled, label)


def test_cached_compiled_code_is_checked_before_it_runs_numba_cache(tmp_path, monkeypatch, capsys):
    """numba's cache files of a kernel carry a SHA-256 checked before they are unpickled: a constant scaled in
    the cached machine code is discarded (one line) and compiled again, never run."""
    monkeypatch.setenv("KNIFEEDGE_CACHE_DIR", str(tmp_path / "k"))
    first = _scaled(2.5, "test-scaled")
    assert first(2.0) == 5.0
    assert cache.is_cached(first)
    data = next((tmp_path / "k" / "kernels").glob("test-scaled-*.nbc"))
    raw = data.read_bytes()
    assert raw.startswith(cache.CHECKED_MAGIC)
    constant = struct.pack("<d", 2.5)
    assert constant in raw
    data.write_bytes(raw.replace(constant, struct.pack("<d", 3.0)))
    capsys.readouterr()
    second = _scaled(2.5, "test-scaled")
    assert second(2.0) == 5.0
    err = [ln for ln in capsys.readouterr().err.splitlines() if ln.strip()]
    assert len(err) == 1 and "discarded a damaged compiled-code cache entry" in err[0] and "checksum" in err[0]
    third = _scaled(2.5, "test-scaled")  # compiled again and kept: loads quietly
    assert third(2.0) == 5.0 and capsys.readouterr().err == ""
    assert sum(third.stats.cache_hits.values()) == 1  # loaded, not compiled
    other = _scaled(4.0, "test-scaled")  # another constant in the closure: another entry, its own answer
    assert other(2.0) == 8.0 and len(list(data.parent.glob("test-scaled-*.nbi"))) == 2


def test_cached_compiled_code_is_checked_before_it_runs_numba_cache_dir(tmp_path, monkeypatch, capsys):
    """Where NUMBA_CACHE_DIR names a folder others may write to, the kernels' machine code is neither kept
    nor read there: it stays in the private cache folder."""
    import numba

    if not hasattr(os, "getuid"):
        pytest.skip("no user ids")
    shared = tmp_path / "numba-shared"
    shared.mkdir()
    shared.chmod(0o777)
    monkeypatch.setenv("KNIFEEDGE_CACHE_DIR", str(tmp_path / "k"))
    monkeypatch.setattr(numba.config, "CACHE_DIR", str(shared))
    assert _scaled(2.5, "test-shared")(2.0) == 5.0
    assert not list(shared.rglob("*.nb[ic]"))
    assert list((tmp_path / "k" / "kernels").glob("test-shared-*.nbi"))


def test_cached_compiled_code_is_checked_before_it_runs_under_a_group_umask(tmp_path, monkeypatch):
    """With umask 002 (user private groups), the folders and parts files the cache makes still pass its own
    checks: folders 0700, parts files 0644."""
    if not hasattr(os, "getuid"):
        pytest.skip("no user ids")
    monkeypatch.delenv("KNIFEEDGE_CACHE_DIR", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    old = os.umask(0o002)
    try:
        folder = cache.cache_dir()
        assert folder == tmp_path / "xdg" / "knifeedge"
        for f in (folder, folder / "kernels"):
            assert f.stat().st_mode & 0o777 == 0o700, f
        path = folder / "kernels" / "k.parts-x.nbo"
        irparts.write_parts(path, _blobs())
        assert path.stat().st_mode & 0o777 == 0o644
        assert irparts.read_parts(path) == _blobs()
    finally:
        os.umask(old)


@pytest.mark.slow
def test_a_kernel_loaded_from_the_cache_keeps_its_own_closures(tmp_path):
    """The DP54 and DOP853 integrators are closures of one factory; each holds a compiled initial-step closure
    of its own error order.  A DP54 integrator compiled in one process and loaded from the cache in another
    that compiled DOP853's first must still take DP54's first step: the step of SciPy's select_initial_step
    at order 4 (DOP853's at order 7), the rule the kernels follow (Hairer, Norsett & Wanner I, Sect. II.4)."""
    from scipy.integrate._ivp.common import select_initial_step

    code = ("import sys, json; sys.path.insert(0, {tests!r}); import numpy as np; import test_events as te\n"
            "print(json.dumps({{m: te._run(m, np.array([1.0, 0.0, 0.4999]), np.array([te.W, 0.0]), 10.0, [2],"
            " atol=1e-9)[0][1] for m in sys.argv[1:]}}))").format(tests=os.path.dirname(__file__))
    env = dict(os.environ, KNIFEEDGE_CACHE_DIR=str(tmp_path / "cache"))

    def first_steps(*methods):
        out = subprocess.run([sys.executable, "-c", code, *methods], env=env, capture_output=True, text=True,
                             check=True)
        return __import__("json").loads(out.stdout.splitlines()[-1])

    first_steps("DP54")  # compiled and cached in this process
    got = first_steps("DOP853", "DP54")  # DOP853 compiled here, DP54 loaded from the cache after it

    def f(t, y):
        return np.array([y[1], -4.0 * y[0], -y[0]])

    y0 = np.array([1.0, 0.0, 0.4999])
    for method, order in (("DP54", 4), ("DOP853", 7)):
        args = (f, 0.0, y0, 10.0, np.inf, f(0.0, y0), 1, order, 1e-10, np.full(3, 1e-9))
        if "t_bound" not in inspect.signature(select_initial_step).parameters:  # SciPy before 1.12
            args = args[:3] + args[5:]
        want = select_initial_step(*args)
        assert got[method] == pytest.approx(want, rel=1e-12), method


@pytest.mark.slow
def test_a_damaged_file_of_numbas_own_cache_is_discarded_and_compiled_again(tmp_path):
    """The kernels' helpers and the generated functions keep numba's plain cache files (``cache=True``, here in
    NUMBA_CACHE_DIR): one truncated is discarded with its entry, said in one line, compiled again, and the run
    gives the same answer (without the repair numba raises UnpicklingError)."""
    code = (
        "import knifeedge as ke\n"
        "m = ke.load('single_mode', 'reduced')\n"
        "r = ke.simulate(m, {'theta': 1e-3, 'theta_dot': 0.0, 'phi_dot': 0.1}, (0.0, 15.0),"
        " m.params(g=1.0, ell=1.0, L=1.0, D=1.0))\n"
        "print(r.success, repr(r.y[:, -1].tolist()))\n"
    )
    env = dict(os.environ, KNIFEEDGE_CACHE_DIR=str(tmp_path / "k"), NUMBA_CACHE_DIR=str(tmp_path / "n"))
    first = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    plain = sorted((tmp_path / "n").rglob("*.nbi"))
    assert plain, "no plain numba cache files were written"
    for index in plain:
        with open(index, "r+b") as f:
            f.truncate(20)
    again = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    assert again.returncode == 0, again.stderr
    assert again.stdout == first.stdout
    assert "discarded a damaged compiled-code cache entry" in again.stderr
    quiet = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert quiet.stdout == first.stdout and "discarded" not in quiet.stderr


def test_kernels_of_one_factory_have_machine_code_names_of_their_own():
    """The RK4 kernels of two models are closures of one factory with the same argument types: their machine code
    is named after their code and cells (``cache._distinct_names``), not only after the factory's function."""
    from knifeedge import load
    from knifeedge.integrators import kernel_module

    single, two = (kernel_module(load(name), "RK4").solve.py_func for name in ("single_mode", "two_mode"))
    assert single.__qualname__ != two.__qualname__
    assert single.__qualname__.startswith("_solve_closure.<locals>.solve_")


@pytest.mark.slow
def test_kernels_of_two_models_loaded_from_the_cache_run_their_own_code(tmp_path):
    """Two RK4 kernels (single- and two-mode models), the second compiled in a process that had loaded the first
    from the cache, both loaded by a third process: each runs and gives the state its own process computed
    (before the kernels were named after their cells, the third process failed with ``NRT_adapt_ndarray_to_python:
    'descr' is NULL``)."""
    code = ("import sys, json, numpy as np, knifeedge as ke\n"
            "out = {}\n"
            "for name in sys.argv[1:]:\n"
            "    m = ke.load(name)\n"
            "    p = m.params(g=1.0, ell=1.0, L=2.0, D=0.5, **({'alpha': 0.7} if name == 'two_mode' else {}))\n"
            "    y0 = np.full(m.n_state, 1e-3)\n"
            "    y0[-1] = 0.1\n"
            "    r = ke.simulate(m, y0, (0.0, 2.0), p, method='RK4', h=0.01)\n"
            "    out[name] = [r.message, r.y[:, -1].tolist()]\n"
            "print(json.dumps(out))\n")
    env = dict(os.environ, KNIFEEDGE_CACHE_DIR=str(tmp_path / "k"), NUMBA_CACHE_DIR=str(tmp_path / "n"))

    def run(*names):
        out = subprocess.run([sys.executable, "-c", code, *names], env=env, capture_output=True, text=True)
        assert out.returncode == 0, out.stderr[-2000:]
        return __import__("json").loads(out.stdout.splitlines()[-1])

    first = run("single_mode")  # compiled and cached
    second = run("single_mode", "two_mode")  # the first loaded, the second compiled and cached
    assert second["single_mode"] == first["single_mode"]
    assert run("single_mode", "two_mode") == second  # both loaded
