"""ke.sweep: tidy table, physics of the rows, failures recorded, the results store (SQLite), resume after
interruption, infrastructure failures (killed workers, broken executors, a killed parent), concurrent sweeps on
one store, damaged rows, executors (incl. Dask)."""
from __future__ import annotations

import concurrent.futures as cf
import json
import math
import os
import signal
import sqlite3
import subprocess
import sys
import time
import warnings
from concurrent.futures.process import BrokenProcessPool

import numpy as np
import pytest

import knifeedge as ke
from knifeedge.scenes import amplitude_theory as th
from knifeedge.store import StoreError

GRID = {"phi_dot": [0.1, 0.2], "D": [0.5, 1.0]}
#: a cheap sweep for the failure tests: 24 short single-mode runs, inside the reduced fidelity's domain (the tilt
#: reaches about phi_dot0 L/sqrt(g ell) <= 0.19 < 0.21: no ValidityWarning)
QUICK = {"phi_dot": [0.1 + 0.004 * i for i in range(24)]}


def _spec():
    """The single-mode scene (Fig. numerical), with a span that holds every first reversal of GRID."""
    return ke.scene("numerical", t_end=260.0)


def _quick():
    return ke.scene("numerical", t_end=40.0)


def _same(a, b) -> None:
    assert a.columns == b.columns
    assert len(a) == len(b)
    for ra, rb in zip(a.rows, b.rows):
        for c in a.columns:
            if c == "seconds":  # the worker's time, not a result
                continue
            va, vb = ra[c], rb[c]
            if isinstance(va, float) and math.isnan(va):
                assert isinstance(vb, float) and math.isnan(vb), c
            else:
                assert va == vb, (c, va, vb)


def _rows(db) -> list:
    con = sqlite3.connect(db)
    try:
        return con.execute("SELECT run_id, status FROM runs").fetchall()
    except sqlite3.OperationalError:  # the sweep is creating the table
        return []
    finally:
        con.close()


def _cli(*args) -> list:
    return [sys.executable, "-m", "knifeedge", "sweep", *args]


@pytest.fixture(scope="module")
def serial_table():
    return ke.sweep(_spec(), GRID, executor="serial", progress=False)


@pytest.fixture(scope="module")
def quick_table():
    return ke.sweep(_quick(), QUICK, executor="serial", progress=False)


# -- the table -----------------------------------------------------------------------
def test_rows_in_grid_order_with_inputs_and_outcomes(serial_table):
    t = serial_table
    assert len(t) == 4
    assert [(r["phi_dot"], r["D"]) for r in t] == [(0.1, 0.5), (0.1, 1.0), (0.2, 0.5), (0.2, 1.0)]
    for col in ("run_id", "model", "fidelity", "method", "rtol", "atol", "g", "ell", "L", "theta", "status",
                "message", "nfev", "n_reversals", "first_reversal", "mean_interval", "reversal_times", "seconds"):
        assert col in t.columns
    assert set(t["status"]) == {"ok"}
    assert len(set(t["run_id"])) == 4
    assert (t.n_computed, t.n_reused, t.n_missing) == (4, 0, 0)


def test_first_reversals_follow_the_amplitude_solution(serial_table):
    """Single-mode first reversal against the closed form of Eqs. an (errata applied), t_R ~ 1/(phi_dot0 D)."""
    for row in serial_table:
        predicted = th.first_reversal_time(row["phi_dot"], row["theta"], row["g"], row["ell"], row["L"], row["D"])
        assert row["n_reversals"] == 1
        assert row["first_reversal"] == pytest.approx(predicted, rel=0.02)
        assert math.isnan(row["mean_interval"])  # one reversal: no interval


def test_table_columns_as_arrays(serial_table):
    first = serial_table["first_reversal"]
    assert first.dtype == float and first.shape == (4,)
    # t_R ~ 1/(phi_dot0 D) up to the logarithm: doubling D halves the time (Eq. tr)
    assert first[1] / first[0] == pytest.approx(0.5, rel=0.01)
    with pytest.raises(KeyError):
        serial_table["nope"]
    assert "first_reversal" in serial_table.to_csv().splitlines()[0]
    assert np.all(serial_table.ok)


def test_to_pandas_has_typed_columns(serial_table):
    pd = pytest.importorskip("pandas")
    df = serial_table.to_pandas()
    assert list(df.columns) == list(serial_table.columns) and len(df) == 4
    assert df["D"].dtype == np.float64 and df["first_reversal"].dtype == np.float64
    assert str(df["nfev"].dtype) == "Int64" and str(df["run_id"].dtype) == "string"
    assert isinstance(df["status"].dtype, pd.CategoricalDtype) and set(df["status"]) == {"ok"}
    assert df["first_reversal"].tolist() == serial_table["first_reversal"].tolist()
    assert isinstance(df["reversal_times"].iloc[0], np.ndarray)


def test_a_failed_run_is_a_row_with_its_message_not_an_exception():
    t = ke.sweep(ke.scene("numerical", max_steps=2000), {"t_end": [200.0, 20000.0]}, executor="serial",
                 progress=False)
    ok, failed = t.rows
    assert ok["status"] == "ok" and ok["n_reversals"] == 1
    assert failed["status"] == "failed"
    assert "max_steps" in failed["message"]
    assert t.failures() == [failed] and t.n_missing == 0


def test_bad_grid_is_rejected_before_any_work(tmp_path):
    out = tmp_path / "s.sqlite"
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
    with pytest.raises(ValueError, match="`chunksize`"):
        ke.sweep("numerical", {"D": [1.0]}, chunksize=0, progress=False)
    assert not out.exists()


def test_grid_values_are_checked_once_each_yet_every_bad_one_is_caught():
    """The grid is checked by value, not run by run: a bad value anywhere, of any kind, still stops the sweep."""
    for grid, exc, text in [({"phi_dot": [0.1, 0.2, math.nan]}, ValueError, "`phi_dot`"),
                            ({"t_end": [50.0, 60.0, -1.0]}, ValueError, "`t_end` must exceed"),
                            ({"D": [1.0, True]}, TypeError, "`D`"),  # equal to 1.0, still refused
                            ({"D": [1.0, 2.0], "phi_dot": [0.1, -0.0]}, None, None),
                            ({"rtol": [1e-8, 1e-8, 1.0], "phi_dot": [0.1, 0.2]}, ValueError, "`rtol`"),
                            ([{"phi_dot": 0.1}, {"phi_dot": 0.2, "L": 0.0}], ValueError, "`L`")]:
        if exc is None:
            assert len(ke.sweep("numerical", grid, executor="serial", progress=False, t_span=(0.0, 1.0))) == 4
            continue
        with pytest.raises(exc, match=text):
            ke.sweep("numerical", grid, progress=False)


def _definition_run_id(spec) -> str:
    """The run id (key version 2): sha1 of the run's sorted JSON, without its output sampling (and without
    max_steps or path when unset), with the SHA-256 of the model module's file (issue 26: every model's)."""
    import hashlib
    from pathlib import Path

    d = spec.to_dict()
    del d["n_eval"]
    for k in ("max_steps", "path"):
        if d[k] is None:
            del d[k]
    folder = Path(d["path"]) if "path" in d else Path(__file__).resolve().parents[1] / "generated"
    d["module_sha256"] = hashlib.sha256((folder / f"{d['model']}_{d['fidelity']}.py").read_bytes()).hexdigest()
    d["key_version"] = 2
    return hashlib.sha1(json.dumps(d, sort_keys=True).encode()).hexdigest()[:16]


@pytest.mark.parametrize("grid", [
    {"phi_dot": list(np.linspace(0.05, 0.4, 7)), "t_end": [100.0, 250.5]},
    {"D": [0.5, 1, np.float64(2.0)], "theta": [1e-3, -0.0, 0.0], "rtol": [1e-8, 1e-9]},
    [{"t_end": 100.0}, {"method": "DP54", "t_end": 50}, {}, {"max_steps": 4000.0, "phi_dot": 1 / 3}],
])
def test_run_ids_and_stored_specs_are_those_of_earlier_versions(grid):
    """Runs are made from the grid without a RunSpec each: their ids (the key of every store, so of resuming)
    and their JSON are still those that RunSpec gives."""
    from knifeedge.sweep import _expand, _grid_points

    base = ke.scene("numerical").run
    points = _grid_points(grid)
    runs = _expand(base, points)
    assert len(runs) == len(points)
    for run, point in zip(runs, points):
        spec = base.with_(**point)
        assert run.inputs["run_id"] == _definition_run_id(spec)
        assert run.spec == spec.to_dict() and run.text == json.dumps(spec.to_dict())
        assert ke.RunSpec.from_dict(json.loads(run.text)) == spec
        expected = {"model": spec.model, "fidelity": spec.fidelity, "method": spec.method, "rtol": spec.rtol,
                    "atol": spec.atol, "t0": spec.t_span[0], "t1": spec.t_span[1], **spec.params, **spec.y0}
        for k, v in expected.items():
            assert run.inputs[k] == v and type(run.inputs[k]) is type(v), k
        assert math.copysign(1.0, run.inputs["theta"]) == math.copysign(1.0, spec.y0["theta"])


def test_row_checksums_are_those_of_earlier_versions():
    """The checksum of a row (kept in every store and export) is unchanged for any value a row may hold."""
    import hashlib

    from knifeedge.store import checksum

    def definition(row, columns):
        parts = []
        for c in sorted(columns):
            v = row.get(c)
            if isinstance(v, float) and v != v:
                v = None
            elif isinstance(v, (list, tuple)):
                v = [float(x) for x in v]
            parts.append(f"{c}={v!r}")
        return hashlib.blake2b("\x1f".join(parts).encode(), digest_size=8).hexdigest()

    row = {"run_id": "49caebe209174298", "model": "two_mode", "method": "DOP853", "rtol": 1e-10, "t0": 0.0,
           "phi_dot": 0.2, "status": "ok", "message": "", "nfev": 90260, "first_reversal": 1340.3245325684602,
           "mean_interval": math.nan, "reversal_times": [1340.3245325684602, 2746.5327819182367], "seconds": 0.48}
    variants = [row, {**row, "phi_dot": 0.3}, {**row, "reversal_times": [], "message": "x'y\"=nan", "nfev": None},
                {**row, "reversal_times": (1, 2.5), "status": "failed", "t0": -0.0, "rtol": 1e300, "x": True},
                {**row, "reversal_times": [math.nan], "rtol": np.float64("nan"), "t0": np.float64(2.0)},
                {**row, "weird{0}": "a}{", "seconds": math.inf}]
    for _ in range(2):  # the second time, every value has been seen before
        for r in variants:
            for cols in (tuple(r), list(r), r, tuple(r)[:5], ("absent", "run_id"), ()):
                assert checksum(r, cols) == definition(r, cols), (r, cols)
    times = [1.0, 2.0]
    before = checksum({**row, "reversal_times": times}, tuple(row))
    times.append(3.0)  # a list changed in place is written anew
    assert checksum({**row, "reversal_times": times}, tuple(row)) != before
    for r in ({**row, "reversal_times": None}, {**row, "reversal_times": [4.0]}, {**row, "reversal_times": None}):
        assert checksum(r, tuple(r)) == definition(r, tuple(r))

    # a sweep's rows: the text of the inputs its runs share written once (RowChecksum), the same checksums
    from knifeedge.store import RowChecksum

    fixed_sets = [("model", "method", "rtol", "t0"), ("model", "zeta"), (), tuple(row)]
    for fixed_names in fixed_sets:
        base = {**row, "zeta": math.nan, "%d": "100%", "a{b}": -0.0}
        sums = RowChecksum(tuple(base), {k: base[k] for k in fixed_names if k in base})
        for change in ({}, {"mean_interval": 2.5}, {"zeta": math.nan} if "zeta" not in fixed_names else {},
                       {"message": "x=nan\x1f=nan", "status": "error", "nfev": 0}, {"reversal_times": []},
                       {"reversal_times": [math.nan, 1.0]}, {"first_reversal": math.nan, "seconds": math.inf},
                       {"seconds": np.float64(0.5)}, {"nfev": True}, {"reversal_times": (1.0, 2.0)},
                       {"reversal_times": [1, 2.0]}, {"nfev": None}, {"first_reversal": -math.inf}):
            r = {**base, **{k: v for k, v in change.items() if k not in fixed_names}}
            assert sums(r) == definition(r, tuple(r)), (fixed_names, change)
    last_nan = RowChecksum(("a", "z"), {"a": 1.0})  # the last column's NaN
    assert last_nan({"a": 1.0, "z": math.nan}) == definition({"a": 1.0, "z": None}, ("a", "z"))


def test_a_sweep_leaves_the_garbage_collector_as_it_found_it():
    """During a sweep the objects alive at its start are left out of the collector's passes (``gc.freeze``); after
    it, they are given back; objects frozen by someone else stay so, and are not given back by the sweep."""
    import gc

    seen = []
    grid = {"phi_dot": QUICK["phi_dot"][:2]}
    ke.sweep(_quick(), grid, executor="serial", progress=lambda done, total, row: seen.append(gc.get_freeze_count()))
    assert len(seen) == 2 and min(seen) > 0 and gc.get_freeze_count() == 0
    gc.freeze()
    try:
        mine, seen = gc.get_freeze_count(), []
        ke.sweep(_quick(), grid, executor="serial", progress=lambda done, total, row: seen.append(gc.get_freeze_count()))
        # (frozen objects that die leave the count: it may only fall)
        assert len(seen) == 2 and 0 < min(seen) and max(seen) <= mine and 0 < gc.get_freeze_count() <= mine
    finally:
        gc.unfreeze()


def test_sweeping_a_model_needs_params_state_and_span():
    m = ke.load("single_mode", "reduced")
    with pytest.raises(ValueError, match="`params`"):
        ke.sweep(m, {"D": [1.0]}, progress=False)
    t = ke.sweep(m, {"D": [1.0]}, params=dict(g=1.0, ell=1.0, L=1.0, D=1.0),
                 y0={"theta": 1e-3, "theta_dot": 0.0, "phi_dot": 0.1}, t_span=(0.0, 150.0),
                 executor="serial", progress=False)
    assert t.rows[0]["n_reversals"] == 1


def test_a_model_from_a_users_folder_sweeps_on_local_workers(tmp_path):
    """A model written by `knifeedge derive` into a folder: every worker loads it from there (issue 9 item 2)."""
    pytest.importorskip("sympy")
    from pathlib import Path

    from knifeedge import cli

    folder = tmp_path / "my_models"
    model_file = Path(__file__).resolve().parent / "models" / "damped_sleigh.py"
    assert cli.main(["derive", str(model_file), "--out", str(folder)]) == 0
    m = ke.load("damped_sleigh", path=folder)
    grid = {k: [v, 1.5 * v] for k, v in list(m.default_params.items())[:1]}
    serial = ke.sweep(m, grid, params=m.default_params, y0=m.default_state, t_span=(0.0, 5.0), executor="serial",
                      progress=False)
    pooled = ke.sweep(m, grid, params=m.default_params, y0=m.default_state, t_span=(0.0, 5.0), max_workers=2,
                      out=tmp_path / "runs.sqlite", progress=False)
    assert set(serial["status"]) == {"ok"}, serial.rows[0]["message"]
    _same(pooled, serial)
    ref = ke.simulate(m, m.default_state, (0.0, 5.0), m.default_params)
    assert serial.rows[0]["nfev"] == ref.nfev  # the row is the model's own run


def test_runspec_is_a_core_notion():
    """Imports flow runspec <- scenes <- sweep: the scenes re-export it, no scene imports the sweep module."""
    import ast
    from pathlib import Path

    import knifeedge.runspec
    import knifeedge.scenes

    assert ke.RunSpec is knifeedge.runspec.RunSpec is knifeedge.scenes.RunSpec
    for f in Path(knifeedge.scenes.__file__).parent.glob("*.py"):
        for node in ast.walk(ast.parse(f.read_text())):
            if isinstance(node, ast.ImportFrom):
                assert node.module not in ("..sweep", "knifeedge.sweep", "sweep") and not (
                    node.level == 2 and node.module in ("sweep", "cli", "figures")), f
    spec = _spec().run.with_(phi_dot=0.3)
    assert ke.RunSpec.from_dict(json.loads(json.dumps(spec.to_dict()))) == spec


# -- the store: resume, export, damaged rows, old files ------------------------------------
@pytest.mark.parametrize("name", ["runs.sqlite", "runs.csv", "runs.jsonl"])
def test_interrupted_sweep_resumes_without_recomputing_or_losing_runs(tmp_path, name, serial_table):
    out = tmp_path / name
    db = out.with_suffix(".sqlite")
    seen = []

    def stop_after_two(done, total, row):
        seen.append(row["run_id"])
        if done == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        ke.sweep(_spec(), GRID, executor="serial", out=out, progress=stop_after_two, chunksize=1)
    assert len(_rows(db)) == 2  # both finished runs committed
    computed = []
    t = ke.sweep(_spec(), GRID, executor="serial", out=out, progress=lambda d, n, row: computed.append(row["run_id"]))
    assert (t.n_reused, t.n_computed) == (2, 2)
    assert len(computed) == 2 and not set(computed) & set(seen)  # nothing recomputed
    _same(t, serial_table)  # nothing lost, same numbers as an uninterrupted sweep
    again = ke.sweep(_spec(), GRID, executor="serial", out=out, progress=False)
    assert (again.n_reused, again.n_computed) == (4, 0)
    _same(again, serial_table)
    assert sorted(r for r, _ in _rows(db)) == sorted(serial_table["run_id"])  # one row per run
    if name.endswith(".csv"):
        assert len(out.read_text().splitlines()) == 5  # header + 4 rows, exported
    if name.endswith(".jsonl"):
        assert [json.loads(line)["status"] for line in out.read_text().splitlines()] == ["ok"] * 4
    fresh = ke.sweep(_spec(), GRID, executor="serial", out=out, progress=False, resume=False)
    assert (fresh.n_reused, fresh.n_computed) == (0, 4) and len(_rows(db)) == 4


def test_one_store_holds_several_sweeps(tmp_path):
    out = tmp_path / "runs.sqlite"
    a = ke.sweep(_spec(), {"D": [1.0]}, executor="serial", out=out, progress=False)
    b = ke.sweep("numerical2", {"D": [0.5]}, executor="serial", out=out, progress=False, chunksize=1)
    assert a.rows[0]["model"] == "single_mode" and b.rows[0]["model"] == "two_mode"
    assert len(_rows(out)) == 2
    again = ke.sweep(_spec(), {"D": [1.0]}, executor="serial", out=out, progress=False)
    assert again.n_reused == 1
    _same(again, a)
    # other tools read the store: typed columns, NaN stored as NULL
    with sqlite3.connect(out) as con:
        (first, d, status), = con.execute("SELECT first_reversal, D, status FROM runs WHERE model='single_mode'")
    assert (first, d, status) == (a.rows[0]["first_reversal"], 1.0, "ok")


def test_a_damaged_row_is_detected_and_recomputed(tmp_path, quick_table):
    out = tmp_path / "runs.sqlite"
    ke.sweep(_quick(), QUICK, executor="serial", out=out, progress=False)
    victim = quick_table.rows[5]["run_id"]
    with sqlite3.connect(out) as con:  # a hand edit of one result
        con.execute("UPDATE runs SET first_reversal = 1.0 WHERE run_id = ?", (victim,))
        con.execute("UPDATE runs SET nfev = 'abc' WHERE run_id = ?", (quick_table.rows[7]["run_id"],))
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        t = ke.sweep(_quick(), QUICK, executor="serial", out=out, progress=False)
    messages = sorted(str(w.message) for w in rec)
    assert len(messages) == 2 and all(m.startswith(f"{out}: row ") for m in messages)
    assert any(f"(run {victim}): its checksum does not match its values" in m for m in messages)
    assert any("column `nfev` must be a whole number, got 'abc'; the run will be recomputed" in m for m in messages)
    assert (t.n_reused, t.n_computed) == (22, 2) and len(t.damaged) == 2
    _same(t, quick_table)  # the edited values were not trusted
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert ke.sweep(_quick(), QUICK, executor="serial", out=out, progress=False).n_reused == 24


def test_an_unreadable_text_file_names_file_line_and_remedy(tmp_path, quick_table):
    csv_path = tmp_path / "old.csv"
    quick_table.to_csv(csv_path)
    lines = csv_path.read_text().splitlines()
    cells = lines[3].split(",")
    cells[lines[0].split(",").index("first_reversal")] = "abc"
    lines[3] = ",".join(cells)
    csv_path.write_text("\n".join(lines) + "\n")
    with pytest.raises(StoreError, match=r"old\.csv, line 4: column `first_reversal` must be a number, got 'abc'; "
                                         r"correct or delete that line"):
        ke.sweep(_quick(), QUICK, executor="serial", out=csv_path, progress=False)
    jl = tmp_path / "old.jsonl"
    quick_table.to_jsonl(jl)
    rows = [json.loads(x) for x in jl.read_text().splitlines()]
    del rows[2]["status"]
    rows[5]["first_reversal"] = 3.0  # an edit the checksum catches
    jl.write_text("".join(json.dumps(r) + "\n" for r in rows))
    with pytest.raises(StoreError, match=r"old\.jsonl, line 3: no value for column\(s\) \['status'\]"):
        ke.sweep(_quick(), QUICK, executor="serial", out=jl, progress=False)
    del rows[2]
    jl.write_text("".join(json.dumps(r) + "\n" for r in rows))
    with pytest.raises(StoreError, match=r"old\.jsonl, line 5: the row's values do not match its checksum"):
        ke.sweep(_quick(), QUICK, executor="serial", out=jl, progress=False)


def test_a_text_export_is_readable_as_any_file_the_user_writes(tmp_path, quick_table):
    """The CSV/JSONL export takes its mode from the umask, as the store and any file the user writes (it was
    0600 whatever the umask: a temporary file's mode, moved into place), and leaves no temporary file."""
    old = os.umask(0o022)
    try:
        quick_table.to_csv(tmp_path / "tr.csv")
        quick_table.to_jsonl(tmp_path / "tr.jsonl")
    finally:
        os.umask(old)
    assert {p.name: p.stat().st_mode & 0o777 for p in tmp_path.iterdir()} == {"tr.csv": 0o644, "tr.jsonl": 0o644}


def test_results_of_an_earlier_version_are_read_not_recomputed(tmp_path, quick_table):
    """A CSV appended by the earlier sweep (no checksum, no `seconds`, the last line cut short) is imported."""
    cols = [c for c in quick_table.columns if c != "seconds"]
    lines = [",".join(cols)]
    for row in quick_table.rows[:10]:
        lines.append(",".join(" ".join(repr(x) for x in row[c]) if c == "reversal_times" else
                              (repr(row[c]) if isinstance(row[c], float) else str(row[c])) for c in cols))
    out = tmp_path / "runs.csv"
    out.write_text("\n".join(lines) + "\n" + lines[1][:30])
    t = ke.sweep(_quick(), QUICK, executor="serial", out=out, progress=False)
    assert (t.n_reused, t.n_computed) == (10, 14)
    _same(t, quick_table)
    assert len(out.read_text().splitlines()) == 25 and (tmp_path / "runs.sqlite").exists()


# -- infrastructure failures are not results -------------------------------------------------
def _workers_of(pid: int) -> list:
    """The sweep's worker processes: forked from ``pid`` (same command line) or started as ``knifeedge.workers``."""
    psutil = pytest.importorskip("psutil")
    parent = psutil.Process(pid)
    return [c for c in parent.children() if c.cmdline() == parent.cmdline()
            or "knifeedge.workers" in " ".join(c.cmdline())]


def test_rows_received_before_an_interruption_are_written(tmp_path, monkeypatch):
    """Rows wait up to half a second to be written with the next claim; an exception (here Ctrl-C in a progress
    callback, then a claim that fails and rolls back the rows written in its transaction) writes the ones received
    before claims are freed.  If writing them fails too, the interruption is still what the caller gets, with a
    warning counting the rows lost."""
    from knifeedge.store import ResultStore

    def stop_at(n):
        seen = []

        def progress(done, total, row):
            seen.append(row["run_id"])
            if len(seen) == n:
                raise KeyboardInterrupt

        return progress

    out = tmp_path / "runs.sqlite"
    with pytest.raises(KeyboardInterrupt):
        ke.sweep(_quick(), QUICK, executor="serial", out=out, progress=stop_at(3), chunksize=2)
    assert len(_rows(out)) == 4  # both tasks received: the one whose third row was being reported, and the first
    with sqlite3.connect(out) as con:
        assert con.execute("SELECT count(*) FROM claims").fetchone()[0] == 0

    # rows are written in the transaction of the next claim: if the claim fails, they are rolled back with it,
    # and written on the way out
    out = tmp_path / "claims-fail.sqlite"
    claim = ResultStore.claim
    calls = []

    def claim_fails_the_second_time(self, *args):
        calls.append(1)
        if len(calls) == 2:
            raise sqlite3.OperationalError("database is locked")
        return claim(self, *args)

    monkeypatch.setattr(ResultStore, "claim", claim_fails_the_second_time)
    with pytest.raises(sqlite3.OperationalError, match="locked"):
        ke.sweep(_quick(), QUICK, executor="serial", out=out, progress=False, chunksize=2)
    assert len(calls) == 2 and len(_rows(out)) == 4  # the two tasks claimed by the first call
    monkeypatch.setattr(ResultStore, "claim", claim)
    out = tmp_path / "runs.sqlite"

    def broken_disk(self, rows, *args):
        raise sqlite3.OperationalError("disk I/O error")

    monkeypatch.setattr(ResultStore, "write", broken_disk)
    with pytest.warns(RuntimeWarning, match=r"2 finished run\(s\) could not be written .*disk I/O error"):
        with pytest.raises(KeyboardInterrupt):
            ke.sweep(_quick(), QUICK, executor="serial", out=out, progress=stop_at(1), chunksize=2)
    with sqlite3.connect(out) as con:
        assert con.execute("SELECT count(*) FROM claims").fetchone()[0] == 0


# a pool of two workers and the one that replaces the killed worker (~10 s of CPU); the retries themselves:
# test_runs_lost_by_the_executor_are_retried_then_left_without_result below, in the default tier
@pytest.mark.slow
def test_a_worker_killed_mid_sweep_costs_no_result(tmp_path, quick_table):
    """SIGKILL one worker (as the out-of-memory killer does): its runs are sent again, none becomes an error."""
    out = tmp_path / "runs.sqlite"
    killed = []

    def kill_a_worker(done, total, row):
        if not killed:
            victim = _workers_of(os.getpid())[0]
            killed.append(victim.pid)
            victim.send_signal(signal.SIGKILL)

    t = ke.sweep(_quick(), QUICK, max_workers=2, out=out, progress=kill_a_worker, chunksize=1)
    assert killed
    assert t.n_missing == 0 and t.n_retried >= 1 and set(t["status"]) == {"ok"}
    _same(t, quick_table)
    assert len(_rows(out)) == 24
    assert not _workers_of(os.getpid())  # the pool is gone


class _FlakyExecutor(cf.Executor):
    """Threads, except that tasks holding ``poison`` runs fail as a dead process pool would, and one is cancelled."""

    def __init__(self, poison):
        self.pool = cf.ThreadPoolExecutor(2)
        self.poison, self.cancelled = poison, False

    def submit(self, fn, *args):
        runs = args[-1]  # the task
        if any(r["y0"]["phi_dot"] in self.poison for r in runs):
            fut = cf.Future()
            fut.set_exception(BrokenProcessPool("A process in the process pool was terminated abruptly"))
            return fut
        if not self.cancelled:
            self.cancelled = True
            fut = cf.Future()
            fut.cancel()
            return fut
        return self.pool.submit(fn, *args)

    def shutdown(self, wait=True, **kw):
        self.pool.shutdown(wait)


def test_runs_lost_by_the_executor_are_retried_then_left_without_result(tmp_path, quick_table):
    out = tmp_path / "runs.sqlite"
    poison = {QUICK["phi_dot"][3]}
    with pytest.warns(RuntimeWarning, match="1 run\\(s\\) have no result.*BrokenProcessPool"):
        t = ke.sweep(_quick(), QUICK, executor=_FlakyExecutor(poison), out=out, progress=False)
    assert t.n_missing == 1 and [r["phi_dot"] for r in t.missing()] == list(poison)
    assert "no result after 3 attempts" in t.missing()[0]["message"]
    assert t.failures() == [] and "1 without a result" in t.summary()
    assert len(_rows(out)) == 23  # the cancelled task was sent again; the lost run has no row
    resumed = ke.sweep(_quick(), QUICK, executor="serial", out=out, progress=False)
    assert (resumed.n_reused, resumed.n_computed, resumed.n_missing) == (23, 1, 0)
    _same(resumed, quick_table)


# a `knifeedge sweep` process with two workers, killed, then run again (~4 s of CPU): slow tier
@pytest.mark.slow
def test_killing_the_parent_ends_its_workers_and_loses_no_committed_run(tmp_path):
    psutil = pytest.importorskip("psutil")
    out = tmp_path / "runs.sqlite"
    cmd = _cli("tinversion", "--grid", "phi_dot=0.02:0.4:40", "--set", "t_end=30000", "--workers", "2",
               "--out", str(out))
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    workers = []
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline and p.poll() is None:
        if len(workers) < 2:  # started one after the other
            workers = _workers_of(p.pid)
        if len(workers) == 2 and out.exists() and len(_rows(out)) >= 2:
            break
        time.sleep(0.05)
    if p.poll() is not None:
        pytest.skip("the sweep finished before the kill")
    assert len(workers) == 2
    p.kill()
    p.communicate()
    _, alive = psutil.wait_procs(workers, timeout=60)
    assert not alive, "workers outlived their parent"
    before = {r for r, _ in _rows(out)}
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert f"40 runs: {40 - len(before)} computed, {len(before)} read back" in r.stdout
    assert len(_rows(out)) == 40


def test_two_sweeps_on_one_store_share_the_work(tmp_path):
    """Both finish with every row; each run is computed by exactly one of them; no row twice."""
    out = tmp_path / "runs.sqlite"
    cmd = _cli("numerical", "--grid", "phi_dot=0.05:0.4:30", "--set", "t_end=300", "--workers", "1",
               "--out", str(out))
    procs = [subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for _ in range(2)]
    outs = [p.communicate() for p in procs]
    assert [p.returncode for p in procs] == [0, 0], [e for _, e in outs]
    computed = []
    for stdout, _ in outs:
        line = next(x for x in stdout.splitlines() if x.startswith("30 runs:"))
        computed.append(int(line.split(":")[1].split()[0]))
    assert sum(computed) == 30
    rows = _rows(out)
    assert len(rows) == 30 and len({r for r, _ in rows}) == 30 and {s for _, s in rows} == {"ok"}
    with sqlite3.connect(out) as con:
        assert con.execute("SELECT count(*) FROM claims").fetchone()[0] == 0


# -- executors --------------------------------------------------------------------------
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


def test_a_task_is_opaque_to_dask_and_has_a_key_of_its_own():
    """Dask hashes a task's arguments for its key: a task's runs are not walked, and a task sent again (a retry)
    never shares the key, so the future, of the task it replaces."""
    tokenize = pytest.importorskip("dask.base").tokenize
    from knifeedge.workers import _Task

    class Unhashable(dict):
        def __dask_tokenize__(self):
            raise AssertionError("a run was walked")

    runs = [Unhashable(phi_dot=0.1)]
    assert tokenize(_Task(runs)) != tokenize(_Task(runs))
    task = _Task(runs)
    assert list(task) == runs and len(task) == 1
    import pickle

    plain = _Task([{"phi_dot": 0.1}])
    again = pickle.loads(pickle.dumps(plain))
    assert list(again) == [{"phi_dot": 0.1}] and tokenize(again) == tokenize(plain)


def test_a_tasks_outcomes_cross_dask_as_one_object():
    """Dask's wire format writes a list of dicts as one frame per dict (a task's outcomes: hundreds); the task's
    outcomes go back wrapped as one object, whole after the trip."""
    core = pytest.importorskip("distributed.protocol.core")
    to_serialize = pytest.importorskip("distributed.protocol").to_serialize
    from knifeedge.workers import _run_task

    outcomes = [{"status": "ok", "nfev": i, "first_reversal": math.nan if i == 7 else 0.5 * i,
                 "reversal_times": [1.0, 2.0 * i]} for i in range(200)]
    wrapped = _run_task(lambda task: list(task), outcomes)
    assert wrapped.outcomes == outcomes
    frames = core.dumps({"op": "get_data", "data": {"k": to_serialize(wrapped)}})
    assert len(frames) <= 4 < 200 < len(core.dumps({"op": "get_data", "data": {"k": to_serialize(outcomes)}}))
    back = core.loads(frames)["data"]["k"].outcomes
    assert back[:7] == outcomes[:7] and back[8:] == outcomes[8:] and math.isnan(back[7]["first_reversal"])


def test_local_workers_are_forked_with_the_kernel_loaded():
    """The sweep's process runs the kernel once (loading it, or on a first use compiling it) before it forks its
    workers, rather than each worker loading or compiling it."""
    code = """if True:
        import os
        import knifeedge as ke
        from knifeedge import runspec, workers
        events, parent = [], os.getpid()
        simulate, start = runspec.RunSpec.simulate, workers.LocalPool.__init__

        def logged_simulate(self):
            if os.getpid() == parent:
                events.append("simulate")
            return simulate(self)

        def logged_start(self, n, fn):
            events.append("workers")
            start(self, n, fn)

        runspec.RunSpec.simulate, workers.LocalPool.__init__ = logged_simulate, logged_start
        t = ke.sweep(ke.scene("numerical", t_end=40.0), {"phi_dot": [0.1, 0.2, 0.3]}, max_workers=2, progress=False)
        assert set(t["status"]) == {"ok"}, t.rows
        assert events == ["simulate", "workers"], events
    """
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


# a `knifeedge sweep` process with two workers, interrupted, then run again (~4 s of CPU): slow tier
@pytest.mark.slow
def test_ctrl_c_on_the_command_line_keeps_finished_runs(tmp_path):
    """A real SIGINT to `knifeedge sweep` on local workers: finished rows stay, the rerun computes only the rest."""
    out = tmp_path / "runs.csv"
    db = tmp_path / "runs.sqlite"
    cmd = _cli("tinversion", "--grid", "phi_dot=0.02:0.4:10", "--set", "t_end=30000", "--workers", "2",
               "--out", str(out))
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline and p.poll() is None:
        if db.exists() and len(_rows(db)) >= 2:
            break
        time.sleep(0.05)
    p.send_signal(signal.SIGINT)
    _, err = p.communicate()
    if p.returncode == 0:  # the machine was fast enough to finish first: nothing to resume
        pytest.skip("the sweep finished before the interrupt")
    finished = len(_rows(db))
    assert p.returncode == 130 and "run the same sweep again to resume" in err
    assert 2 <= finished < 10
    assert len(out.read_text().splitlines()) == finished + 1  # the export holds what finished
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert f"10 runs: {10 - finished} computed, {finished} read back" in r.stdout
    assert len(out.read_text().splitlines()) == 11
