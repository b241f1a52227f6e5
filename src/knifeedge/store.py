"""The results store of sweeps: one SQLite file, one row per run.

A sweep's results are the user's data, so they live in a store made for it:
an SQLite database (Python's standard library; readable by the ``sqlite3``
shell, ``pandas.read_sql``, DB browsers).

* **One row per run**, keyed by ``run_id``, a hash of the run's inputs (its
  :class:`~knifeedge.runspec.RunSpec` without the output sampling).  The key
  is the table's primary key: two sweeps on one file cannot both write a run.
* **Typed columns**: the inputs (model, fidelity, method, tolerances, span,
  every parameter and initial state as a ``REAL`` column), the outcome
  (``status``, ``message``, ``nfev``, ``n_reversals``, ``first_reversal``,
  ``mean_interval``, ``reversal_times`` as a JSON list), the worker time of
  the run (``seconds``), when it finished, the full run as JSON (``spec``)
  and a ``checksum`` of the row: a row edited by hand or damaged is detected,
  reported (file and run) and recomputed, never trusted.
* **Transactions, WAL journal**: rows are committed as they arrive (a sweep
  gathers what arrives within half a second into one transaction, with its
  next claim); a sweep killed at any instant leaves every committed row intact
  and readable.
* **Claims with a lease**: before a run is computed, the sweep claims it in
  the ``claims`` table (one transaction), with its process (pid, start
  time, host), the time of the claim and a lease it renews while it works.
  A second sweep on the same file skips runs claimed by a live sweep and
  computes the others, then waits for the first sweep's rows; a claim whose
  owner died (same host: its process is gone) or whose lease expired without
  renewal (a sweep suspended with Ctrl-Z, hung, or on a host that went away)
  is taken over.  So concurrent sweeps share the work, nothing is lost, and
  no wait outlasts a lease.
* **A knifeedge file, and the same file throughout**: a store is marked with
  SQLite's ``application_id`` and ``user_version``; any other database is
  refused before anything in it is changed.  A store deleted or replaced
  while a sweep writes to it is noticed at the sweep's next transaction.

CSV and JSON-lines files are exports (:func:`write_text`) and, for results
written by earlier versions, imports (:func:`read_text`): an unreadable line
is an error naming the file, the line and what to do.
"""
from __future__ import annotations

import csv
import hashlib
import io
import json
import math
import os
import socket
import sqlite3
import time
import uuid
from collections.abc import Iterable, Mapping, Sequence
from operator import add, itemgetter
from pathlib import Path

from ._output import replacing
from ._process import alive as _alive, start_time as _start_time

#: outcome columns, after the input columns
RESULT_COLUMNS = ("status", "message", "nfev", "n_reversals", "first_reversal", "mean_interval", "reversal_times",
                  "seconds")
#: statuses of a run that has a result: reached the end / the integrator gave up / the run raised
STATUSES = ("ok", "failed", "error")
#: fixed input columns, before the parameters and initial states
INPUT_COLUMNS = ("run_id", "model", "fidelity", "method", "rtol", "atol", "t0", "t1")
TEXT_COLUMNS = frozenset({"run_id", "model", "fidelity", "method", "status", "message"})
INT_COLUMNS = frozenset({"nfev", "n_reversals"})
STORE_SUFFIXES = (".sqlite", ".sqlite3", ".db")
TEXT_SUFFIXES = (".csv", ".jsonl", ".ndjson", ".json")
SCHEMA_VERSION = 2
#: SQLite's ``application_id`` of a knifeedge results store (the bytes "knif"); ``user_version`` is SCHEMA_VERSION
APPLICATION_ID = 0x6B6E6966
#: the tables of a store written before stores were marked (schema 1), adopted and marked when opened
_LEGACY_TABLES = frozenset({"meta", "runs", "claims"})
_NONE: Mapping = {}
_RESERVED = frozenset(INPUT_COLUMNS + RESULT_COLUMNS + ("spec", "finished_at", "checksum"))


# -- rows -----------------------------------------------------------------------
def checksum(row: Mapping, columns: Iterable[str]) -> str:
    """Hash of a row's values in ``columns`` (floats by their exact ``repr``; NaN and a missing value alike)."""
    names = columns if type(columns) is tuple else tuple(columns)
    prepared = _PREPARED.get(names)
    if prepared is None:
        if len(_PREPARED) > 256:
            _PREPARED.clear()
        order = sorted(names)
        get = itemgetter(*order) if len(order) > 1 else (lambda r: (r[order[0]],)) if order else (lambda r: ())
        prepared = _PREPARED[names] = (order, tuple(f"{c}=" for c in order), get, [(None, "None")] * len(order))
    order, heads, get, last = prepared
    try:
        values = get(row)
    except KeyError:  # a missing value: the general rule
        return _checksum(row, order)
    texts = []
    for i, v in enumerate(values):
        seen = last[i]
        if seen[0] is v:  # the same object as in the previous row (an input column of a sweep): the same text
            texts.append(seen[1])
            continue
        kind = type(v)
        if kind is float:
            text = "None" if v != v else float.__repr__(v)
        elif kind is str or kind is int:
            text = repr(v)
        elif kind is list and all(type(x) is float for x in v):
            texts.append(repr(v))  # a list may change in place: not remembered
            continue
        else:
            return _checksum(row, order)
        last[i] = (v, text)
        texts.append(text)
    return hashlib.blake2b("\x1f".join(map(add, heads, texts)).encode(), digest_size=8).hexdigest()


#: column names -> (sorted names, "name=" of each, getter of the values in that order, last value and text of each)
_PREPARED: dict = {}


def _checksum(row: Mapping, order: Sequence[str]) -> str:
    """The definition of :func:`checksum` (``order``: the column names, sorted), for any value.

    ``None`` and a missing value are written ``None``, a NaN float too; a list or tuple as a list of floats;
    anything else by its ``repr``.
    """
    return hashlib.blake2b("\x1f".join(_segment(c, row.get(c)) for c in order).encode(), digest_size=8).hexdigest()


def with_spec(row_checksum: str, spec: str | None) -> str:
    """The checksum kept in a store's row: its values' :func:`checksum` and the JSON text of its run (``spec``)."""
    return hashlib.blake2b(f"{row_checksum}\x1fspec={spec!r}".encode(), digest_size=8).hexdigest()


class RowChecksum:
    """:func:`checksum` over ``columns`` of rows whose values in ``fixed`` are those given (the inputs a sweep's
    runs share): the text of the fixed values is written once, the others by one ``%`` format.

    The caller vouches that a row's ``fixed`` columns hold those values and that it has exactly ``columns``; a
    value of another type than a float, str, int, ``None`` or a list of floats takes the general rule.
    """

    __slots__ = ("columns", "format", "get", "ends")

    def __init__(self, columns: Sequence[str], fixed: Mapping):
        self.columns = tuple(columns)
        order = sorted(self.columns)
        holes = [c for c in order if c not in fixed]
        self.format = "\x1f".join(c.replace("%", "%%") + "=%r" if c not in fixed
                                   else _segment(c, fixed[c]).replace("%", "%%") for c in order)
        self.get = itemgetter(*holes) if len(holes) > 1 else (lambda r: (r[holes[0]],)) if holes else (lambda r: ())
        self.ends = order[-1] not in fixed if order else False  # the last segment may be a NaN

    def __call__(self, row: Mapping) -> str:
        values = self.get(row)
        kinds = set(map(type, values))
        if not kinds <= _PLAIN or (list in kinds and not all(all(type(x) is float for x in v) for v in values
                                                              if type(v) is list)):
            return checksum(row, self.columns)
        text = self.format % values  # %r writes a float, str, int, None or list of floats as the definition does
        if "=nan" in text:  # NaN is written None (a str's repr is quoted, a list's NaN follows "[" or ", ")
            text = text.replace("=nan\x1f", "=None\x1f")
            if self.ends and text.endswith("=nan"):
                text = text[:-3] + "None"
        return hashlib.blake2b(text.encode(), digest_size=8).hexdigest()


_PLAIN = frozenset({float, str, int, list, type(None)})


def _segment(column: str, v) -> str:
    """One ``name=text`` piece of :func:`_checksum`."""
    if isinstance(v, float) and v != v:
        v = None
    elif isinstance(v, (list, tuple)):
        v = [float(x) for x in v]
    return f"{column}={v!r}"


def _coerce(column: str, value, where: str):
    """A cell read from a file or the database, as the column's Python type; ValueError saying what is wrong."""
    if column in TEXT_COLUMNS:
        if not isinstance(value, str):
            if column == "message" and value is None:
                return ""
            raise ValueError(f"{where}: column `{column}` must be text, got {value!r}")
        if column == "status" and value not in STATUSES:
            raise ValueError(f"{where}: column `status` must be one of {', '.join(STATUSES)}, got {value!r}")
        return value
    if column == "reversal_times":
        if isinstance(value, str):
            text = value.strip()
            try:
                value = json.loads(text) if text.startswith("[") else [float(t) for t in text.split()]
            except ValueError:
                raise ValueError(f"{where}: column `reversal_times` must be numbers separated by spaces, "
                                 f"got {value!r}") from None
        if not isinstance(value, list) or not all(isinstance(t, (int, float)) and not isinstance(t, bool)
                                                  for t in value):
            raise ValueError(f"{where}: column `reversal_times` must be a list of numbers, got {value!r}")
        return [float(t) for t in value]
    if column in INT_COLUMNS:
        try:
            if isinstance(value, bool) or (isinstance(value, float) and not value.is_integer()):
                raise ValueError
            return int(value)
        except (TypeError, ValueError):
            raise ValueError(f"{where}: column `{column}` must be a whole number, got {value!r}") from None
    # a number (NaN stored as NULL / empty)
    if value is None or value == "":
        return math.nan
    if isinstance(value, bool):
        raise ValueError(f"{where}: column `{column}` must be a number, got {value!r}")
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{where}: column `{column}` must be a number, got {value!r}") from None


class StoreError(ValueError):
    """A results file that cannot be used as it is (the message says which file and what to do)."""


class StoreGone(StoreError):
    """The store's file was deleted or replaced during a sweep."""


def _file_id(path: Path) -> tuple:
    st = os.stat(path)
    return st.st_dev, st.st_ino


# -- the store ------------------------------------------------------------------------
class ResultStore:
    """An SQLite file of run results (see the module docstring).

    Parameters
    ----------
    path : the database file (created if missing).
    input_columns : the parameter and initial-state names of the sweep; a
        column is added for each name the table does not have yet.
    lease : seconds a claim stays valid without renewal (matters only for
        sweeps on other hosts; on one host a claim lives as long as its process).
    """

    def __init__(self, path: str | Path, input_columns: Sequence[str] = (), lease: float = 120.0):
        self.path = Path(path)
        self.lease = float(lease)
        self.owner = uuid.uuid4().hex
        self.host = socket.gethostname()
        self.pid = os.getpid()
        self.started = _start_time(self.pid)
        self._mine: set = set()
        self._sql: dict = {}
        self._last_renew = 0.0
        self._depth = 0  # transactions open (see transaction)
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise StoreError(f"`out` file {str(self.path)!r}: its folder cannot be created ({exc}); "
                             "choose a writable location") from None
        self.db = None
        try:
            self.db = sqlite3.connect(str(self.path), timeout=60.0, isolation_level=None, check_same_thread=False)
            self._file = _file_id(self.path)
            legacy = self._identify()  # before anything is written: another database is left untouched
            self.db.execute("PRAGMA journal_mode=WAL")
            self.db.execute("PRAGMA synchronous=NORMAL")
            self._create(tuple(input_columns), legacy)
        except BaseException as exc:
            if self.db is not None:
                self.db.close()
            if isinstance(exc, sqlite3.DatabaseError):
                raise StoreError(self._cannot_use(exc)) from None
            raise

    def _cannot_use(self, exc: sqlite3.DatabaseError) -> str:
        """What to say when SQLite refused the file: read-only, or not a database at all."""
        text = str(exc)
        no_access = not os.access(self.path.parent, os.W_OK) or (self.path.exists()
                                                                 and not os.access(self.path, os.W_OK))
        if "readonly" in text or "read-only" in text or ("unable to open" in text and no_access):
            return (f"`out` file {str(self.path)!r} cannot be written ({text}): it or its folder is read-only "
                    f"(read-only media, or no write permission); choose a writable location")
        return (f"`out` file {str(self.path)!r} is not a knifeedge results database ({text}); "
                "choose another file name")

    def _identify(self) -> bool:
        """Check that the file is a knifeedge store, an empty (new) database, or a store of schema 1 (returns
        True: to be marked); raise :class:`StoreError` for any other database, having changed nothing."""
        app = self.db.execute("PRAGMA application_id").fetchone()[0]
        version = self.db.execute("PRAGMA user_version").fetchone()[0]
        tables = {r[0] for r in self.db.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
        if app == APPLICATION_ID:
            if version != SCHEMA_VERSION:
                raise StoreError(f"`out` file {str(self.path)!r} has results schema {version}, this knifeedge "
                                 f"reads schema {SCHEMA_VERSION}: choose another file")
            return False
        if app == 0 and not tables:
            return False
        if app == 0 and tables == _LEGACY_TABLES and self.db.execute(
                "SELECT value FROM meta WHERE key = 'written_by'").fetchone() == ("knifeedge",):
            return True
        raise StoreError(f"`out` file {str(self.path)!r} is an SQLite database that knifeedge did not write "
                         f"(application_id {app:#x}, tables {sorted(tables)}); it was left untouched: choose "
                         "another file name")

    def check_file(self) -> None:
        """Raise :class:`StoreGone` if the store's file was deleted or replaced since it was opened (SQLite would
        go on writing to the file it has open, which no one can read any more)."""
        try:
            now = _file_id(self.path)
        except FileNotFoundError:
            raise StoreGone(f"the results store {self.path} was deleted while the sweep wrote to it: the rows "
                            "written to it are lost; run the sweep again") from None
        if now != self._file:
            raise StoreGone(f"the results store {self.path} was replaced by another file while the sweep wrote "
                            "to it: the rows written since are not in that file; run the sweep again") from None

    # -- schema -------------------------------------------------------------------
    def _create(self, names: tuple, legacy: bool = False) -> None:
        bad = sorted(set(names) & _RESERVED)
        if bad:
            raise StoreError(f"parameter or state name(s) {bad} clash with the columns of the results table")
        with self._transaction():
            self.db.execute("CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT NOT NULL)")
            row = self.db.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone()
            if row is None:
                self.db.execute("INSERT INTO meta VALUES ('schema_version', ?), ('written_by', 'knifeedge')",
                                (str(SCHEMA_VERSION),))
            elif legacy and row[0] == "1":  # rows of schema 1 stay; their run ids (key version 1) are never matched
                self.db.execute("UPDATE meta SET value = ? WHERE key = 'schema_version'", (str(SCHEMA_VERSION),))
            elif row[0] != str(SCHEMA_VERSION):
                raise StoreError(f"`out` file {str(self.path)!r} has results schema {row[0]}, this knifeedge "
                                 f"reads schema {SCHEMA_VERSION}: choose another file")
            self.db.execute(
                "CREATE TABLE IF NOT EXISTS runs (run_id TEXT PRIMARY KEY, model TEXT NOT NULL, "
                "fidelity TEXT NOT NULL, method TEXT NOT NULL, rtol REAL, atol REAL, t0 REAL, t1 REAL, "
                "status TEXT NOT NULL, message TEXT, nfev INTEGER, n_reversals INTEGER, first_reversal REAL, "
                "mean_interval REAL, reversal_times TEXT, seconds REAL, finished_at REAL, spec TEXT, "
                "checksum TEXT NOT NULL)")
            self.db.execute("CREATE TABLE IF NOT EXISTS claims (run_id TEXT PRIMARY KEY, owner TEXT NOT NULL, "
                            "host TEXT NOT NULL, pid INTEGER NOT NULL, started TEXT, expires REAL NOT NULL, "
                            "claimed_at REAL)")
            if "claimed_at" not in {r[1] for r in self.db.execute("PRAGMA table_info(claims)")}:
                self.db.execute("ALTER TABLE claims ADD COLUMN claimed_at REAL")
            self.db.execute(f"PRAGMA application_id = {APPLICATION_ID}")
            self.db.execute(f"PRAGMA user_version = {SCHEMA_VERSION}")
            have = {r[1] for r in self.db.execute("PRAGMA table_info(runs)")}
            for n in names:
                if n not in have:
                    self.db.execute(f"ALTER TABLE runs ADD COLUMN {_q(n)} REAL")
        self.columns = tuple(r[1] for r in self.db.execute("PRAGMA table_info(runs)"))

    class _Tx:
        """``BEGIN IMMEDIATE`` ... ``COMMIT`` (``ROLLBACK`` on an exception); one opened inside another is part
        of it."""

        def __init__(self, store):
            self.store = store

        def __enter__(self):
            st = self.store
            if st._depth == 0:
                st.check_file()
                st.db.execute("BEGIN IMMEDIATE")
            st._depth += 1
            return st.db

        def __exit__(self, kind, exc, tb):
            st = self.store
            st._depth -= 1
            if st._depth == 0:
                if kind is not None:
                    if st.db.in_transaction:  # (SQLite ends it itself after some errors)
                        st.db.execute("ROLLBACK")
                    return
                try:
                    st.db.execute("COMMIT")
                except BaseException:  # a failed commit (a full disk) leaves the transaction open
                    if st.db.in_transaction:
                        st.db.execute("ROLLBACK")
                    raise
                st.check_file()  # (deleted meanwhile: what was committed is in a file no one can read)

    def transaction(self):
        """A context in which every write of this store is one transaction (committed at its end)."""
        return self._Tx(self)

    _transaction = transaction

    # -- reading ------------------------------------------------------------------
    def read(self, run_ids: Sequence[str], since: float | None = None) -> tuple[dict, list]:
        """Rows of ``run_ids`` that hold a result: ``({run_id: row}, damaged)``.

        ``damaged`` lists one message per row that fails its checksum or
        cannot be read; those runs count as having no result.  With ``since``,
        rows finished before that time are left out (a fresh sweep recomputes them).
        """
        found, damaged = {}, []
        ids = list(dict.fromkeys(run_ids))
        for i in range(0, len(ids), 500):
            chunk = ids[i:i + 500]
            cur = self.db.execute(f"SELECT rowid, * FROM runs WHERE run_id IN ({','.join('?' * len(chunk))})", chunk)
            names = [d[0] for d in cur.description]
            for values in cur.fetchall():
                raw = dict(zip(names, values))
                rid = raw["run_id"]
                if since is not None and (raw["finished_at"] or 0.0) < since:
                    continue
                try:
                    row = self._decode(raw)
                except ValueError as exc:
                    damaged.append(f"{exc}; the run will be recomputed and its row replaced")
                    continue
                found[rid] = row
        return found, damaged

    def _decode(self, raw: dict) -> dict:
        where = f"{self.path}: row {raw['rowid']} (run {raw['run_id']})"
        row = {}
        for c, v in raw.items():
            if c in ("rowid", "spec", "checksum", "finished_at"):
                continue
            if v is None and c not in INPUT_COLUMNS and c not in RESULT_COLUMNS:
                continue  # a parameter or state of another model's runs
            if v is None and c == "reversal_times":
                raise ValueError(f"{where}: column `reversal_times` is empty")
            row[c] = _coerce(c, v, where)
        if raw["checksum"] != with_spec(checksum(row, row), raw["spec"]):
            raise ValueError(f"{where}: its checksum does not match its values (edited by hand or damaged)")
        return row

    def count(self) -> int:
        return self.db.execute("SELECT count(*) FROM runs").fetchone()[0]

    # -- claims -------------------------------------------------------------------
    def claim(self, run_ids: Sequence[str], since: float | None = None) -> tuple[list, dict, dict, list]:
        """Claim the runs of ``run_ids`` that have no result and no live claim.

        Returns ``(claimed, done, busy, damaged)``: the ids now ours; rows found
        already written (``{run_id: row}``); ids claimed by a live sweep
        (``{run_id: "pid 123 on host"}``); messages about damaged rows.
        """
        now = time.time()
        claimed, busy, done, damaged = [], {}, {}, []
        ids = list(dict.fromkeys(run_ids))
        with self._transaction():  # no other sweep writes meanwhile: what is found written stays so
            for i in range(0, len(ids), 500):
                chunk = ids[i:i + 500]
                marks = ",".join("?" * len(chunk))
                written = [r[0] for r in self.db.execute(
                    f"SELECT run_id FROM runs WHERE run_id IN ({marks})" + ("" if since is None else
                                                                            " AND finished_at >= ?"),
                    chunk + ([] if since is None else [since]))]
                if written:  # read back (a damaged row is reported, and its run claimed to be computed again)
                    found, bad = self.read(written, since)
                    done.update(found)
                    damaged.extend(bad)
                held = {r[0]: r[1:] for r in self.db.execute(
                    "SELECT run_id, owner, host, pid, started, expires, claimed_at FROM claims "
                    f"WHERE run_id IN ({marks})", chunk)}
                for rid in chunk:
                    if rid in done:
                        continue
                    h = held.get(rid)
                    if h is not None and h[0] != self.owner and self._live(h[:5], now):
                        busy[rid] = _holder_text(h)
                        continue
                    claimed.append(rid)
            self.db.executemany("INSERT OR REPLACE INTO claims (run_id, owner, host, pid, started, expires, "
                                "claimed_at) VALUES (?, ?, ?, ?, ?, ?, ?)",
                                [(rid, self.owner, self.host, self.pid, self.started, now + self.lease, now)
                                 for rid in claimed])
        self._mine.update(claimed)
        return claimed, done, busy, damaged

    def _live(self, held: tuple, now: float) -> bool:
        """Whether a claim still holds: its lease runs (a sweep renews it every ``lease/4`` s while it works; one
        suspended or hung stops renewing), and on this host its process is alive."""
        owner, host, pid, started, expires = held
        if host == self.host and not _alive(pid, started):
            return False
        return expires > now

    def renew(self, every: float | None = None) -> None:
        """Extend the lease of this sweep's claims (at most once per ``every`` seconds)."""
        now = time.time()
        if not self._mine or now - self._last_renew < (self.lease / 4 if every is None else every):
            return
        with self._transaction():
            self.db.execute("UPDATE claims SET expires = ? WHERE owner = ?", (now + self.lease, self.owner))
        self._last_renew = now

    def release(self, run_ids: Iterable[str] | None = None) -> None:
        """Drop this sweep's claims on ``run_ids`` (all of them if None)."""
        with self._transaction():
            if run_ids is None:
                self.db.execute("DELETE FROM claims WHERE owner = ?", (self.owner,))
                self._mine.clear()
                return
            ids = list(run_ids)
            self.db.executemany("DELETE FROM claims WHERE run_id = ? AND owner = ?", [(r, self.owner) for r in ids])
            self._mine.difference_update(ids)

    # -- writing ------------------------------------------------------------------
    def write(self, rows: Sequence[Mapping], specs: Mapping[str, str] | None = None,
              checksums: Mapping[str, str] | None = None) -> None:
        """Insert (or replace) finished rows and drop their claims, in one transaction.

        ``specs``: the JSON text of each run's spec, by run id; ``checksums``: the :func:`checksum` of rows
        the caller has computed (by a :class:`RowChecksum`), by run id.
        """
        if not rows:
            return
        now = time.time()
        with self._transaction():
            self._insert(rows, now, specs or {}, checksums or {})
            self.db.executemany("DELETE FROM claims WHERE run_id = ? AND owner = ?",
                                [(r["run_id"], self.owner) for r in rows])
        self._mine.difference_update(r["run_id"] for r in rows)

    def _insert(self, rows: Sequence[Mapping], finished_at: float | None, specs: Mapping[str, str],
                sums: Mapping[str, str] = _NONE) -> None:
        groups: dict = {}
        for row in rows:
            groups.setdefault(tuple(row), []).append(row)
        for names, group in groups.items():
            missing = sorted(set(names) - set(self.columns))
            if missing:
                raise StoreError(f"{self.path}: the results table has no column(s) {missing}")
            prepared = self._sql.get(names)
            if prepared is None:
                cols = names + ("finished_at", "spec", "checksum")
                prepared = self._sql[names] = (
                    f"INSERT OR REPLACE INTO runs ({','.join(_q(n) for n in cols)}) "
                    f"VALUES ({','.join('?' * len(cols))})", itemgetter(*names), names.index("reversal_times"))
            sql, get, rt = prepared
            values = []
            for row in group:
                v = list(get(row))
                v[rt] = _times_json(v[rt])
                rid = row["run_id"]
                spec = specs.get(rid)
                v += (finished_at, spec, with_spec(sums.get(rid) or checksum(row, names), spec))
                values.append(v)
            self.db.executemany(sql, values)

    def import_rows(self, rows: Sequence[Mapping]) -> int:
        """Add rows read from an older text file (those whose run is not stored yet)."""
        have = set()
        ids = [r["run_id"] for r in rows]
        for i in range(0, len(ids), 500):
            chunk = ids[i:i + 500]
            have |= {r[0] for r in self.db.execute(
                f"SELECT run_id FROM runs WHERE run_id IN ({','.join('?' * len(chunk))})", chunk)}
        new = [r for r in rows if r["run_id"] not in have]
        with self._transaction():
            names = {c for r in new for c in r} - set(self.columns)
            for n in sorted(names):
                self.db.execute(f"ALTER TABLE runs ADD COLUMN {_q(n)} REAL")
            self.columns = tuple(r[1] for r in self.db.execute("PRAGMA table_info(runs)"))
            self._insert(new, None, {})
        return len(new)

    def close(self) -> None:
        try:
            if self._mine:
                self.release()
        except StoreGone:
            pass  # the claims went with the file
        finally:
            self.db.close()


def _holder_text(held: tuple) -> str:
    """Whose claim it is: ``pid P on HOST since HH:MM:SS, lease to HH:MM:SS``."""
    owner, host, pid, started, expires, claimed_at = held
    since = f" since {time.strftime('%H:%M:%S', time.localtime(claimed_at))}" if claimed_at else ""
    return f"pid {pid} on {host}{since}, lease to {time.strftime('%H:%M:%S', time.localtime(expires))}"


def _times_json(times) -> str:
    """``json.dumps`` of a list of times as floats (written directly when they are finite floats)."""
    if all(type(t) is float and t - t == 0.0 for t in times):
        return "[" + ", ".join(map(float.__repr__, times)) + "]"
    return json.dumps([float(t) for t in times])


def _q(name: str) -> str:
    return '"' + name.replace('"', '""') + '"'


# -- text files: export and import --------------------------------------------------------
def _csv_cell(column: str, v):
    if column == "reversal_times":
        return " ".join(repr(float(t)) for t in v)
    if isinstance(v, float):
        return "" if math.isnan(v) else repr(v)
    return v


def write_text(path: str | Path, rows: Sequence[Mapping], columns: Sequence[str]) -> Path:
    """Write ``rows`` as CSV (``.csv``) or JSON lines (otherwise), atomically, with a ``checksum`` column."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    cols = list(columns)
    # a temporary file moved into place; created as open() creates files (its mode from the umask, as the store's)
    with replacing(path) as tmp, open(tmp, "w", newline="") as f:
        if path.suffix.lower() == ".csv":
            w = csv.writer(f, lineterminator="\n")
            w.writerow(cols + ["checksum"])
            for row in rows:
                w.writerow([_csv_cell(c, row[c]) for c in cols] + [checksum(row, cols)])
        else:
            for row in rows:
                d = {c: (None if isinstance(row[c], float) and math.isnan(row[c]) else row[c]) for c in cols}
                d["checksum"] = checksum(row, cols)
                f.write(json.dumps(d, allow_nan=False) + "\n")
        f.flush()
        os.fsync(f.fileno())
    return path


_ADVICE = ("correct or delete that line (a deleted run is recomputed), or start afresh with resume=False "
           "(command line: --fresh)")


def read_text(path: str | Path) -> list:
    """Rows of a CSV or JSON-lines results file written by ``sweep`` (this version or an earlier one).

    A line cut short at the end of the file (a write interrupted by a kill)
    is ignored.  Any other unreadable line raises :class:`StoreError` naming
    the file and the line, and saying what to do.  A row with a ``checksum``
    must match it.
    """
    path = Path(path)
    try:
        text = path.read_text()
    except UnicodeDecodeError:
        raise StoreError(f"{path}: not a text file; choose another `out` file") from None
    lines = text.splitlines(keepends=True)
    if lines and not lines[-1].endswith("\n"):
        lines = lines[:-1]  # cut short by an interruption
    rows = []
    if path.suffix.lower() == ".csv":
        reader = csv.reader(lines)
        header = next(reader, None)
        if header is None:
            return []
        required = {"run_id", "status"} | {c for c in RESULT_COLUMNS if c != "seconds"}
        absent = sorted(required - set(header))
        if absent:
            raise StoreError(f"{path}, line 1: the header lacks column(s) {absent}: this is not a results file "
                             "of knifeedge.sweep; choose another `out` file")
        for cells in reader:
            n = reader.line_num
            if not cells:
                continue
            if len(cells) != len(header):
                raise StoreError(f"{path}, line {n}: {len(cells)} cells for {len(header)} columns; {_ADVICE}")
            rows.append(_text_row(dict(zip(header, cells)), f"{path}, line {n}"))
        return rows
    for n, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            d = json.loads(line)
        except json.JSONDecodeError as exc:
            raise StoreError(f"{path}, line {n}: not valid JSON ({exc.msg}); {_ADVICE}") from None
        if not isinstance(d, dict):
            raise StoreError(f"{path}, line {n}: not a JSON object; {_ADVICE}")
        rows.append(_text_row(d, f"{path}, line {n}"))
    return rows


def _text_row(d: dict, where: str) -> dict:
    absent = [c for c in ("run_id", "model", "fidelity", "method", "status", "reversal_times") if c not in d]
    if absent:
        raise StoreError(f"{where}: no value for column(s) {absent}; {_ADVICE}")
    row = {}
    try:
        for c, v in d.items():
            if c != "checksum":
                row[c] = _coerce(c, v, where)
    except ValueError as exc:
        raise StoreError(f"{exc}; {_ADVICE}") from None
    for c in ("nfev", "n_reversals"):
        row.setdefault(c, 0)
    for c in ("first_reversal", "mean_interval", "seconds"):
        row.setdefault(c, math.nan)
    row.setdefault("message", "")
    if "checksum" in d and d["checksum"] != checksum(row, [c for c in d if c != "checksum"]):
        raise StoreError(f"{where}: the row's values do not match its checksum (edited by hand?); {_ADVICE}")
    return row
