"""The first run of a kernel not yet compiled, in the ``"background"`` compile mode.

SciPy's solver of the same method steps the run while another process
compiles the kernel; the run moves into the compiled kernel when it is ready.
SciPy's ``DOP853`` and ``RK45`` have the tableaus, initial step, error norm
and step-size control of the compiled ``DOP853`` and ``DP54``
(``templates/erk.py``), so the run takes the steps of a compiled run, up to
round-off.  The reference is the compiled run itself, whole.
"""
import json
import math
import os
import subprocess
import sys
import time

import numpy as np
import pytest

import knifeedge as ke
from knifeedge.integrators import compiler, set_compile_mode

SIM = sys.modules["knifeedge.simulate"]


class _Ready:
    """A compiling process that reports its kernel ready at the ``after``-th question."""

    def __init__(self, after):
        self.after, self.asked = after, 0

    def ready(self):
        self.asked += 1
        return self.asked >= self.after

    def failed(self):
        return False


@pytest.fixture
def background(monkeypatch):
    """Background mode, with the kernel taken as not compiled and a stand-in compiling process."""
    pending = _Ready(after=3)
    monkeypatch.setattr(SIM, "kernel_compiled", lambda model, method: False)
    monkeypatch.setattr(compiler, "start", lambda model, method, module, types: pending)
    with compiler.compile_mode_set("background"):
        yield pending


def _two_mode():
    m = ke.load("two_mode", fidelity="full")
    p = m.params(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4)
    y0 = {"theta1": 1e-3, "theta2": 1e-3, "theta1_dot": 0.0, "theta2_dot": 0.0, "phi_dot": 0.1}
    return m, p, y0


@pytest.mark.xdist_group("dp54_tsit5")  # one worker compiles the DP54 and Tsit5 integrators for all such tests
@pytest.mark.parametrize("method,output", [("DOP853", "every step"), ("DOP853", "t_eval"),
                                           *(pytest.param("RK45", out, marks=pytest.mark.slow)
                                             for out in ("every step", "t_eval"))])
def test_handover_takes_the_steps_of_the_compiled_run(background, method, output, capsys):
    """Two-mode knife edge (paper eqs_2modes, Fig. Numerical2), first reversal near t = 2396.7: the run
    begun by SciPy and finished by the kernel has the compiled run's steps, states and reversal."""
    m, p, y0 = _two_mode()
    t_eval = None if output == "every step" else np.linspace(0.0, 3000.0, 777)
    kw = dict(rtol=1e-10, atol=1e-12, t_eval=t_eval, method=method, events=("theta1",))
    with compiler.compile_mode_set("wait"):
        ref = ke.simulate(m, y0, (0.0, 3000.0), p, **kw)
    r = ke.simulate(m, y0, (0.0, 3000.0), p, **kw)
    err = capsys.readouterr().err
    assert "background process" in err and "continues in it at t =" in err
    t_switch = float(err.split("continues in it at t =")[1].split()[0])
    assert 0.0 < t_switch < 3000.0  # both parts ran
    # the same controller: the step counts agree; the step sizes only up to round-off, which the error
    # estimate (a difference of nearly equal stage sums) amplifies to ~2e-6 of an early step for RK45
    assert r.success and r.nsteps == ref.nsteps and r.nrejected == ref.nrejected
    assert r.t.shape == ref.t.shape
    np.testing.assert_allclose(r.t, ref.t, rtol=1e-5, atol=0)
    assert (np.abs(r.y - ref.y).max(axis=1) <= 1e-6 * np.abs(ref.y).max(axis=1)).all()
    assert r.reversal_times.size == ref.reversal_times.size == 1
    assert abs(r.reversal_times[0] - 2396.685) < 0.01
    np.testing.assert_allclose(r.reversal_times, ref.reversal_times, rtol=1e-9)
    assert r.events["theta1"].size == ref.events["theta1"].size
    np.testing.assert_allclose(r.events["theta1"], ref.events["theta1"], rtol=1e-8)
    assert r.events["theta1"].size > 100


def test_run_that_ends_first_does_not_wait(monkeypatch, capsys):
    """A run shorter than the compile is SciPy's whole; its result is the compiled run's to round-off."""
    monkeypatch.setattr(SIM, "kernel_compiled", lambda model, method: False)
    monkeypatch.setattr(compiler, "start", lambda model, method, module, types: _Ready(after=10**9))
    m, p, y0 = _two_mode()
    ref = ke.simulate(m, y0, (0.0, 50.0), p, rtol=1e-10, atol=1e-12)
    with compiler.compile_mode_set("background"):
        r = ke.simulate(m, y0, (0.0, 50.0), p, rtol=1e-10, atol=1e-12)
    assert "run done in" in capsys.readouterr().err
    assert r.nsteps == ref.nsteps and r.t.shape == ref.t.shape
    assert (np.abs(r.y - ref.y).max(axis=1) <= 1e-7 * np.abs(ref.y).max(axis=1)).all()


@pytest.mark.slow
def test_methods_without_a_scipy_twin_and_mode_control_wait(background, capsys):
    """Tsit5, fixed-step methods and ``error_control="mode"`` compile in the calling process (as "wait")."""
    m, p, y0 = _two_mode()
    ke.simulate(m, y0, (0.0, 10.0), p, method="Tsit5")
    ke.simulate(m, y0, (0.0, 10.0), p, method="RK4", h=0.01)
    ke.simulate(m, y0, (0.0, 10.0), p, error_control="mode")
    assert "background" not in capsys.readouterr().err
    assert background.asked == 0


def test_compile_mode_is_checked(monkeypatch):
    with pytest.raises(ValueError, match="mode"):
        set_compile_mode("later")
    monkeypatch.setenv("KNIFEEDGE_COMPILE", "sometimes")
    with pytest.raises(ValueError, match="KNIFEEDGE_COMPILE"):
        compiler.compile_mode()
    monkeypatch.setenv("KNIFEEDGE_COMPILE", "background")
    assert compiler.compile_mode() == "background"
    with compiler.compile_mode_set("wait"):
        assert compiler.compile_mode() == "wait"
    assert compiler.compile_mode() == "background"


_CHILD_RUN = """
import json, math, sys
import numpy as np
import knifeedge as ke
from knifeedge.integrators import set_compile_mode, kernel_compiled
set_compile_mode("background")
m = ke.load("chaplygin_sleigh", fidelity="full")
p = m.params(**m.module.DEFAULT_PARAMS)
y0 = m.module.DEFAULT_STATE
before = kernel_compiled(m, "RK45")
r = ke.simulate(m, y0, (0.0, 5.0), p, method="RK45", rtol=1e-8, atol=1e-10)
print(json.dumps({"before": before, "y": r.y[:, -1].tolist(), "nsteps": r.nsteps}))
"""


@pytest.mark.slow
def test_a_cold_machine_compiles_in_a_separate_process(tmp_path):
    """Empty caches: the run answers without the kernel, a separate process leaves it compiled in the cache,
    and the answer equals the compiled kernel's (Chaplygin sleigh, paper section II.C)."""
    env = dict(os.environ, KNIFEEDGE_CACHE_DIR=str(tmp_path / "kernels"), NUMBA_CACHE_DIR=str(tmp_path / "numba"))
    env.pop("KNIFEEDGE_COMPILE")
    out = subprocess.run([sys.executable, "-c", _CHILD_RUN], env=env, capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    assert "in a background process" in out.stderr
    first = json.loads(out.stdout)
    assert first["before"] is False
    locks = list((tmp_path / "kernels" / "kernels").glob("*.compiling"))
    deadline = time.monotonic() + 600
    while locks and any(p.exists() for p in locks) and time.monotonic() < deadline:
        time.sleep(0.5)
    check = _CHILD_RUN.replace('set_compile_mode("background")', 'set_compile_mode("wait")')
    out2 = subprocess.run([sys.executable, "-c", check], env=env, capture_output=True, text=True, timeout=600)
    assert out2.returncode == 0, out2.stderr
    second = json.loads(out2.stdout)
    assert second["before"] is True, out2.stderr  # compiled by the background process
    assert not list((tmp_path / "kernels" / "kernels").glob("*.log"))  # a compile that succeeded leaves no log
    assert "compiling" not in out2.stderr
    assert second["nsteps"] == first["nsteps"]
    np.testing.assert_allclose(second["y"], first["y"], rtol=1e-12, atol=1e-14)
