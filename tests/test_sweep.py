"""ke.sweep: tidy table, physics of the rows, failures recorded, resume after interruption, executors (incl. Dask)."""
from __future__ import annotations

import concurrent.futures as cf
import json
import math

import numpy as np
import pytest

import knifeedge as ke
from knifeedge.scenes import amplitude_theory as th

GRID = {"phi_dot": [0.1, 0.2], "D": [0.5, 1.0]}


def _spec():
    """The single-mode scene (Fig. numerical), with a span that holds every first reversal of GRID."""
    return ke.scene("numerical", t_end=260.0)


def _same(a, b) -> None:
    assert a.columns == b.columns
    assert len(a) == len(b)
    for ra, rb in zip(a.rows, b.rows):
        for c in a.columns:
            va, vb = ra[c], rb[c]
            if isinstance(va, float) and math.isnan(va):
                assert isinstance(vb, float) and math.isnan(vb), c
            else:
                assert va == vb, (c, va, vb)


@pytest.fixture(scope="module")
def serial_table():
    return ke.sweep(_spec(), GRID, executor="serial", progress=False)


def test_rows_in_grid_order_with_inputs_and_outcomes(serial_table):
    t = serial_table
    assert len(t) == 4
    assert [(r["phi_dot"], r["D"]) for r in t] == [(0.1, 0.5), (0.1, 1.0), (0.2, 0.5), (0.2, 1.0)]
    for col in ("run_id", "model", "fidelity", "method", "rtol", "atol", "g", "ell", "L", "theta", "status",
                "message", "nfev", "n_reversals", "first_reversal", "mean_interval", "reversal_times"):
        assert col in t.columns
    assert set(t["status"]) == {"ok"}
    assert len(set(t["run_id"])) == 4


def test_first_reversals_follow_the_amplitude_solution(serial_table):
    """Single-mode first reversal against the closed form of Eqs. an (errata applied), t_R ~ 1/(phi_dot0 D)."""
    for row in serial_table:
        predicted = th.first_reversal_time(row["phi_dot"], row["theta"], row["g"], row["ell"], row["L"], row["D"])
        assert row["n_reversals"] == 1
        assert row["first_reversal"] == pytest.approx(predicted, rel=0.02)
        assert math.isnan(row["mean_interval"])  # one reversal: no interval


def test_a_failed_run_is_a_row_with_its_message_not_an_exception():
    t = ke.sweep(ke.scene("numerical", max_steps=2000), {"t_end": [200.0, 20000.0]}, executor="serial",
                 progress=False)
    ok, failed = t.rows
    assert ok["status"] == "ok" and ok["n_reversals"] == 1
    assert failed["status"] == "failed"
    assert "max_steps" in failed["message"]
    assert t.failures() == [failed]


def test_bad_grid_is_rejected_before_any_work(tmp_path):
    out = tmp_path / "s.csv"
    with pytest.raises(ValueError, match="`grid`"):
        ke.sweep("numerical", {"nonsense": [1.0]}, out=out, progress=False)
    with pytest.raises(ValueError, match="`D`"):
        ke.sweep("numerical", {"D": [1.0, -1.0]}, out=out, progress=False)
    with pytest.raises(ValueError, match="`method`"):
        ke.sweep("numerical", {"method": ["DOP853", "Euler?"]}, out=out, progress=False)
    with pytest.raises(ValueError, match="`grid`"):
        ke.sweep("numerical", {}, progress=False)
    with pytest.raises(TypeError, match="`executor`"):
        ke.sweep("numerical", {"D": [1.0]}, executor=4, progress=False)
    with pytest.raises(ValueError, match="`out`"):
        ke.sweep("numerical", {"D": [1.0]}, out=tmp_path / "s.txt", progress=False)
    assert not out.exists()


def test_sweeping_a_model_needs_params_state_and_span():
    m = ke.load("single_mode", "reduced")
    with pytest.raises(ValueError, match="`params`"):
        ke.sweep(m, {"D": [1.0]}, progress=False)
    t = ke.sweep(m, {"D": [1.0]}, params=dict(g=1.0, ell=1.0, L=1.0, D=1.0),
                 y0={"theta": 1e-3, "theta_dot": 0.0, "phi_dot": 0.1}, t_span=(0.0, 150.0),
                 executor="serial", progress=False)
    assert t.rows[0]["n_reversals"] == 1


class _Interrupt(Exception):
    pass


@pytest.mark.parametrize("suffix", [".csv", ".jsonl"])
def test_interrupted_sweep_resumes_without_recomputing_or_losing_runs(tmp_path, suffix, serial_table):
    out = tmp_path / f"runs{suffix}"
    seen = []

    def stop_after_two(done, total, row):
        seen.append(row["run_id"])
        if done == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        ke.sweep(_spec(), GRID, executor="serial", out=out, progress=stop_after_two)
    lines = out.read_text().splitlines()
    assert len(lines) == 2 + (suffix == ".csv")  # header + two finished runs
    # a run cut short while being written: half a line at the end of the file
    with open(out, "a") as f:
        f.write(lines[-1][:25])
    computed = []
    t = ke.sweep(_spec(), GRID, executor="serial", out=out, progress=lambda d, n, row: computed.append(row["run_id"]))
    assert (t.n_reused, t.n_computed) == (2, 2)
    assert not set(computed) & set(seen)  # nothing recomputed
    _same(t, serial_table)  # nothing lost, same numbers as an uninterrupted sweep
    again = ke.sweep(_spec(), GRID, executor="serial", out=out, progress=False)
    assert (again.n_reused, again.n_computed) == (4, 0)
    _same(again, serial_table)
    if suffix == ".jsonl":
        assert all(json.loads(line)["status"] == "ok" for line in out.read_text().splitlines())


def test_resume_refuses_a_file_of_another_sweep(tmp_path):
    out = tmp_path / "runs.csv"
    ke.sweep(_spec(), {"D": [1.0]}, executor="serial", out=out, progress=False)
    with pytest.raises(ValueError, match="`out`"):
        ke.sweep("numerical2", {"D": [0.5]}, executor="serial", out=out, progress=False)


def test_process_pool_gives_the_serial_table(serial_table):
    with cf.ProcessPoolExecutor(max_workers=2) as pool:
        t = ke.sweep(_spec(), GRID, executor=pool, progress=False)
    _same(t, serial_table)


def test_dask_local_cluster_gives_the_serial_table(serial_table):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        t = ke.sweep(_spec(), GRID, executor=client.get_executor(), progress=False)
    _same(t, serial_table)


def test_table_columns_as_arrays(serial_table):
    first = serial_table["first_reversal"]
    assert first.dtype == float and first.shape == (4,)
    # t_R ~ 1/(phi_dot0 D) up to the logarithm: doubling D halves the time (Eq. tr)
    assert first[1] / first[0] == pytest.approx(0.5, rel=0.01)
    with pytest.raises(KeyError):
        serial_table["nope"]
    assert "first_reversal" in serial_table.to_csv().splitlines()[0]
    assert np.all(serial_table.ok)


def test_ctrl_c_on_the_command_line_keeps_finished_runs(tmp_path):
    """A real SIGINT to `knifeedge sweep` on a process pool: finished rows stay, the rerun computes only the rest."""
    import signal
    import subprocess
    import sys
    import time

    out = tmp_path / "runs.csv"
    cmd = [sys.executable, "-m", "knifeedge", "sweep", "tinversion", "--grid", "phi_dot=0.02:0.4:10",
           "--set", "t_end=30000", "--workers", "2", "--out", str(out)]
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and p.poll() is None:
        if out.exists() and len(out.read_text().splitlines()) >= 3:  # header + 2 finished runs
            break
        time.sleep(0.05)
    p.send_signal(signal.SIGINT)
    _, err = p.communicate(timeout=120)
    finished = len(out.read_text().splitlines()) - 1
    if p.returncode == 0:  # the machine was fast enough to finish first: nothing to resume
        pytest.skip("the sweep finished before the interrupt")
    assert p.returncode == 130 and "run the same sweep again to resume" in err
    assert 2 <= finished < 10
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert f"10 runs ({10 - finished} computed, {finished} read back" in r.stdout
    assert len(out.read_text().splitlines()) == 11
