"""Issue 26, root 4: the sweep store holds exactly what it says.

Runs are keyed by the content of their model's module, built-in ones too; a
store is marked as knifeedge's (SQLite ``application_id``/``user_version``)
and any other database is refused untouched; read-only media are said as
such; a store deleted or replaced during a sweep ends it with an error, not
with "computed"; the ``spec`` column is inside the row checksum; the wait on
another sweep's claims ends with their lease and says whose they are.
"""
from __future__ import annotations

import hashlib
import shutil
import sqlite3
import time
import warnings

import pytest

import knifeedge as ke
from knifeedge import store as store_module
from knifeedge.store import ResultStore, StoreError

#: a cheap sweep: 6 short single-mode runs, inside the reduced fidelity's domain (tilts stay below 0.21)
GRID = {"phi_dot": [0.1, 0.11, 0.12, 0.13, 0.14, 0.15]}


def _scene():
    return ke.scene("numerical", t_end=20.0)


def _sweep(out, **kw):
    return ke.sweep(_scene(), GRID, executor="serial", out=out, progress=False, **kw)


def test_the_sweep_store_holds_exactly_what_it_says_built_in_modules_key_runs(tmp_path, monkeypatch):
    """After a built-in model's generated module changes, its runs are new runs (not read back as current)."""
    from knifeedge import generated
    from knifeedge.sweep import _expand, _grid_points

    copy = tmp_path / "generated"
    shutil.copytree(generated.__file__.rsplit("/", 1)[0], copy, ignore=shutil.ignore_patterns("__pycache__"))
    monkeypatch.setattr(generated, "__file__", str(copy / "__init__.py"))
    base = _scene().run
    before = [r.run_id for r in _expand(base, _grid_points(GRID))]
    module = copy / f"{generated.MODULES[(base.model, base.fidelity)]}.py"
    module.write_text(module.read_text().replace("VALIDITY = {'theta': 0.21}", "VALIDITY = {'theta': 0.2}"))
    after = [r.run_id for r in _expand(base, _grid_points(GRID))]
    assert len(set(before)) == len(GRID["phi_dot"]) and not set(before) & set(after)


def _digest(path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def test_the_sweep_store_holds_exactly_what_it_says_foreign_database_untouched(tmp_path):
    """Another program's SQLite file, even one with a `runs` table, is refused and left as it was: no table
    added, its journal mode not switched to WAL, no byte changed."""
    other = tmp_path / "other.sqlite"
    con = sqlite3.connect(other)
    con.execute("CREATE TABLE runs (run_id TEXT PRIMARY KEY, x REAL)")
    con.execute("INSERT INTO runs VALUES ('a', 1.0)")
    con.commit()
    con.close()
    before = _digest(other)
    with pytest.raises(StoreError, match="knifeedge did not write.*left untouched"):
        _sweep(other)
    assert _digest(other) == before
    con = sqlite3.connect(other)
    assert con.execute("PRAGMA journal_mode").fetchone()[0] == "delete"
    assert {r[0] for r in con.execute("SELECT name FROM sqlite_master WHERE type = 'table'")} == {"runs"}
    con.close()
    # a knifeedge store is marked as such
    mine = tmp_path / "mine.sqlite"
    _sweep(mine)
    con = sqlite3.connect(mine)
    assert con.execute("PRAGMA application_id").fetchone()[0] == store_module.APPLICATION_ID
    assert con.execute("PRAGMA user_version").fetchone()[0] == store_module.SCHEMA_VERSION
    con.close()


def test_the_sweep_store_holds_exactly_what_it_says_read_only_media(tmp_path, monkeypatch):
    """A store that cannot be written (read-only media) is said to be read-only, not "not a knifeedge
    results database"."""
    path = tmp_path / "runs.sqlite"
    ResultStore(path).close()
    connect = sqlite3.connect

    def read_only(name, *args, **kwargs):  # what SQLite meets on a read-only mount
        return connect(f"file:{name}?mode=ro", *args, uri=True, **kwargs)

    monkeypatch.setattr(store_module.sqlite3, "connect", read_only)
    with pytest.raises(StoreError, match="read-only") as info:
        ResultStore(path)
    assert "not a knifeedge results database" not in str(info.value)


def test_the_sweep_store_holds_exactly_what_it_says_store_deleted_during_a_sweep(tmp_path):
    """A store deleted (or replaced) while the sweep writes to it ends the sweep with an error naming it: the
    rows would otherwise go to a file no one can read, under a summary saying they were computed."""
    for how in ("deleted", "replaced"):
        path = tmp_path / f"{how}.sqlite"

        def progress(done, total, row, path=path, how=how):
            if done == 2:
                for f in path.parent.glob(path.name + "*"):
                    f.unlink()
                if how == "replaced":
                    sqlite3.connect(path).close()

        with pytest.raises(StoreError, match=f"results store .* was {how}"):
            ke.sweep(_scene(), GRID, executor="serial", out=path, progress=progress, chunksize=1)


def test_the_sweep_store_holds_exactly_what_it_says_spec_in_checksum(tmp_path):
    """The `spec` column (the run as JSON) is inside the row checksum: a row whose spec was edited is reported
    and recomputed."""
    path = tmp_path / "runs.sqlite"
    first = _sweep(path)
    victim = first.rows[2]["run_id"]
    with sqlite3.connect(path) as con:
        con.execute("UPDATE runs SET spec = replace(spec, '\"DOP853\"', '\"RK4\"') WHERE run_id = ?", (victim,))
        assert con.total_changes == 1
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        again = _sweep(path)
    messages = [str(w.message) for w in rec]
    assert any(f"(run {victim}): its checksum does not match" in m for m in messages), messages
    assert (again.n_reused, again.n_computed) == (len(GRID["phi_dot"]) - 1, 1)


def test_the_sweep_store_holds_exactly_what_it_says_claims_have_a_lease(tmp_path):
    """Claims of a sweep that stopped renewing them (suspended with Ctrl-Z: its process alive) are taken over
    once their lease ends; until then the waiting sweep is told whose they are (pid, host, since when)."""
    path = tmp_path / "runs.sqlite"
    ids = [f"run{i}" for i in range(3)]
    suspended = ResultStore(path, lease=1.0)
    claimed, _, _, _ = suspended.claim(ids)
    assert claimed == ids
    other = ResultStore(path)
    claimed, done, busy, _ = other.claim(ids)
    assert not claimed and not done and set(busy) == set(ids)
    assert all(text.startswith(f"pid {suspended.pid} on {suspended.host} since ") for text in busy.values())
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:  # the lease is 1 s
        claimed, _, busy, _ = other.claim(ids)
        if claimed:
            break
        time.sleep(0.2)
    assert claimed == ids and not busy
    other.close()
    suspended.db.close()
