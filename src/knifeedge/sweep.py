"""``sweep``: many integrations over a grid of parameters or initial states.

One row per run (its inputs, its spin reversals, its status).  Runs execute
in local worker processes (default), on any :class:`concurrent.futures.Executor`
(a Dask cluster through ``distributed.Client(...).get_executor()``), or in
this process; their rows are committed to an SQLite results store
(:mod:`knifeedge.store`) as they finish (within half a second, together with
the next claim of runs).  So a sweep

* killed at any instant keeps every row it committed, and the same sweep run
  again computes only the rest (*resume*);
* run twice at once on one file shares the work: each run is claimed in the
  store before it is computed, nothing is computed twice, nothing is lost;
* tells a failed integration (a result: ``status`` ``"failed"``, the
  integrator gave up, or ``"error"``, the run raised) from a failure of the
  infrastructure (a worker killed, a broken pool, a cancelled future), which
  is not a result: those runs are retried, and the ones still without a
  result are reported (:attr:`SweepTable.n_missing`) and computed on resume.
"""
from __future__ import annotations

import concurrent.futures as cf
import contextlib
import hashlib
import itertools
import json
import math
import os
import re
import statistics
import sys
import time
import warnings
from collections import deque
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from operator import itemgetter
from pathlib import Path
from typing import Any

import numpy as np

from . import _validate
from ._process import heap_frozen
from .runspec import RUN_SETTINGS, RunSpec
from .simulate import METHODS, check_inputs
from .store import (INPUT_COLUMNS, INT_COLUMNS, RESULT_COLUMNS, STATUSES, STORE_SUFFIXES, TEXT_COLUMNS, TEXT_SUFFIXES,
                    ResultStore, RowChecksum, StoreGone, read_text, write_text)
from .workers import ExecutorPool, LocalPool, SerialPool, WorkerLost, _can_fork

__all__ = ["sweep", "SweepTable", "run_one", "run_batch", "RESULT_COLUMNS", "STATUSES"]

_RESULT_KEYS = frozenset(RESULT_COLUMNS)
#: status of a row that has no result (its run was lost to the infrastructure and is computed on resume)
MISSING = "missing"
#: attempts of a run whose worker keeps dying before it is left without a result
MAX_ATTEMPTS = 3
#: wall time a task of several runs aims at (a few per worker in flight; see ``chunksize``); an executor's tasks
#: (a Dask cluster's) aim at ``ExecutorPool.task_seconds``, longer: each costs its scheduler milliseconds
TASK_SECONDS = 0.25
#: most runs in one task (a task whose worker dies is retried run by run); ``ExecutorPool.max_chunk`` for an executor
MAX_CHUNK = 256
#: the longest a finished run's row waits to be written to the store (rows are written with the next claim, else
#: after this long: a sweep killed outright loses at most this much work; an interrupted one loses none)
WRITE_SECONDS = 0.5


# -- one run ------------------------------------------------------------------
def run_one(spec: Mapping) -> dict:
    """Integrate one :class:`~knifeedge.runspec.RunSpec` given as a dict; return its outcome columns.

    Runs in a worker.  Never raises for a failure of the run itself: an
    exception becomes ``status="error"`` with its message (a result).
    ``MemoryError`` is not caught: the infrastructure failed, not the run.
    """
    t = time.perf_counter()
    try:
        run = RunSpec.from_dict(dict(spec, n_eval=None))
        r = run.simulate()
        rev = [float(x) for x in r.reversal_times]
        out = {
            "status": "ok" if r.success else "failed",
            "message": "" if r.success else r.message,
            "nfev": int(r.nfev),
            **_reversal_columns(rev),
        }
    except MemoryError:
        raise
    except Exception as exc:  # noqa: BLE001 - recorded, not raised
        out = {"status": "error", "message": f"{type(exc).__name__}: {exc}", "nfev": 0, **_reversal_columns([])}
    out["seconds"] = time.perf_counter() - t
    return out


def run_batch(specs: Iterable[Mapping]) -> list:
    """:func:`run_one` on each of ``specs`` (one task of a sweep: a list, or the opaque task an executor gets)."""
    return [run_one(s) for s in specs]


def _reversal_columns(rev: list) -> dict:
    return {
        "n_reversals": len(rev),
        "first_reversal": rev[0] if rev else math.nan,
        "mean_interval": float(np.mean(np.diff(rev))) if len(rev) > 1 else math.nan,
        "reversal_times": rev,
    }


# -- the table ----------------------------------------------------------------
class SweepTable:
    """The rows of a sweep, in grid order; ``to_pandas()`` gives a typed DataFrame.

    Attributes
    ----------
    columns : tuple of str
    rows : list of dict
    n_computed : int
        Runs integrated by this call.
    n_reused : int
        Runs read back from the store (an earlier sweep, or a concurrent one).
    n_retried : int
        Runs sent again because their worker died (or the executor lost them).
    n_missing : int
        Runs without a result: their worker died (or the executor broke)
        every time they were tried.  Their rows have ``status="missing"``;
        running the same sweep again computes them.
    store : Path or None
        The results store (SQLite) the rows are in.
    damaged : list of str
        Rows of the store that failed their checksum (recomputed).
    """

    def __init__(self, columns: Sequence[str], rows: list, n_computed: int = 0, n_reused: int = 0,
                 n_missing: int = 0, store: Path | None = None, damaged: Sequence[str] = (), n_retried: int = 0):
        self.columns = tuple(columns)
        self.rows = rows
        self.n_computed = n_computed
        self.n_reused = n_reused
        self.n_missing = n_missing
        self.n_retried = n_retried
        self.store = store
        self.damaged = list(damaged)

    def __len__(self) -> int:
        return len(self.rows)

    def __iter__(self):
        return iter(self.rows)

    def __getitem__(self, column: str) -> np.ndarray:
        """One column as an array (float for numbers, object otherwise)."""
        if column not in self.columns:
            raise KeyError(f"no column {column!r}; columns are {self.columns}")
        values = [row[column] for row in self.rows]
        if column in TEXT_COLUMNS or column == "reversal_times":
            return np.array(values, dtype=object)
        return np.array(values, dtype=float)

    @property
    def ok(self) -> np.ndarray:
        """Boolean mask of the runs that reached the end of their span."""
        return np.array([row["status"] == "ok" for row in self.rows], dtype=bool)

    def failures(self) -> list:
        """The rows whose integration did not succeed (``"failed"`` or ``"error"``)."""
        return [row for row in self.rows if row["status"] in ("failed", "error")]

    def missing(self) -> list:
        """The rows without a result (``status="missing"``): compute them by running the sweep again."""
        return [row for row in self.rows if row["status"] == MISSING]

    def summary(self) -> str:
        """One line: how many runs, computed, read back, failed, and without a result."""
        where = f" (store: {self.store})" if self.store is not None else ""
        text = (f"{len(self)} runs: {self.n_computed} computed, {self.n_reused} read back{where}, "
                f"{len(self.failures())} failed, {self.n_missing} without a result")
        if self.n_retried:
            text += f" ({self.n_retried} sent again after their worker died)"
        if self.n_missing:
            text += " -- run the same sweep again to compute them"
        return text

    def to_pandas(self):
        """A ``pandas.DataFrame``, one row per run, typed columns.

        Text columns are ``string``, ``status`` is categorical, counts are
        nullable integers (``Int64``), times and parameters are ``float64``,
        ``reversal_times`` holds one float array per run.
        """
        import pandas as pd

        data = {}
        for c in self.columns:
            values = [row[c] for row in self.rows]
            if c == "status":
                data[c] = pd.Categorical(values, categories=list(STATUSES) + [MISSING])
            elif c in TEXT_COLUMNS:
                data[c] = pd.array(values, dtype="string")
            elif c in INT_COLUMNS:
                data[c] = pd.array([None if v is None else int(v) for v in values], dtype="Int64")
            elif c == "reversal_times":
                data[c] = pd.Series([np.asarray(v, dtype=float) for v in values], dtype=object)
            else:
                data[c] = np.asarray(values, dtype=float)
        return pd.DataFrame(data, columns=list(self.columns))

    def to_csv(self, path: str | Path | None = None) -> str:
        """CSV text (reversal times space-separated, a ``checksum`` per row); written to ``path`` if given."""
        return self._text(path, ".csv")

    def to_jsonl(self, path: str | Path | None = None) -> str:
        """JSON lines (one object per run, a ``checksum`` per row); written to ``path`` if given."""
        return self._text(path, ".jsonl")

    def _text(self, path, suffix) -> str:
        import tempfile

        rows = [r for r in self.rows if r["status"] != MISSING]
        with tempfile.TemporaryDirectory() as d:
            text = write_text(Path(d) / f"t{suffix}", rows, self.columns).read_text()
        if path is not None:
            write_text(path, rows, self.columns)
        return text

    def __repr__(self) -> str:
        shown = [c for c in self.columns if c not in ("run_id", "message", "reversal_times", "seconds")]
        lines = ["  ".join(shown)]
        for row in self.rows[:20]:
            lines.append("  ".join(_cell(row[c]) for c in shown))
        if len(self.rows) > 20:
            lines.append(f"... {len(self.rows)} rows")
        return "\n".join(lines)


def _cell(v) -> str:
    if isinstance(v, float):
        return f"{v:.6g}"
    return str(v)


# -- the grid -----------------------------------------------------------------
#: most runs one sweep may hold (its grid is expanded into memory before any work)
MAX_RUNS = 1_000_000


def _grid_points(grid) -> list:
    """``{name: values}`` -> Cartesian product; a sequence of mappings -> as given."""
    if isinstance(grid, Mapping):
        if not grid:
            raise ValueError("`grid` is empty: give at least one name and its values")
        names = list(grid)
        values = []
        for n in names:
            v = grid[n]
            if isinstance(v, (str, bytes)) or not isinstance(v, Iterable):
                raise TypeError(f"`grid[{n!r}]` must be a sequence of values, got {v!r}")
            v = list(v)
            if not v:
                raise ValueError(f"`grid[{n!r}]` has no values")
            values.append(v)
        n_runs = math.prod(len(v) for v in values)
        if n_runs > MAX_RUNS:
            raise ValueError(f"`grid` makes {n_runs:.3g} runs, more than the {MAX_RUNS} one sweep may hold")
        return [dict(zip(names, combo)) for combo in itertools.product(*values)]
    if isinstance(grid, Iterable) and not isinstance(grid, (str, bytes)):
        points = [dict(pt) if isinstance(pt, Mapping) else None for pt in grid]
        if not points or any(pt is None for pt in points):
            raise TypeError("`grid` must be a mapping {name: values} or a non-empty sequence of mappings")
        return points
    raise TypeError(f"`grid` must be a mapping {{name: values}} or a sequence of mappings, got {type(grid).__name__}")


def _base_run(target, params, y0, t_span, method, rtol, atol) -> RunSpec:
    from .models import Model
    from .scenes import Scene, get_scene

    if isinstance(target, str):
        target = get_scene(target)
    if isinstance(target, Scene):
        run = target.main_run()
    elif isinstance(target, RunSpec):
        run = target
    elif isinstance(target, Model):
        if params is None or y0 is None or t_span is None:
            raise ValueError("sweeping a Model needs `params`, `y0` and `t_span` (a Scene brings its own)")
        m = target
        m.check_params(params)
        m.check_state(y0)
        run = RunSpec(model=m.name, fidelity=m.fidelity, pose=m.pose, params=dict(params) if isinstance(params, Mapping)
                      else dict(zip(m.param_names, params)),
                      y0=dict(y0) if isinstance(y0, Mapping) else dict(zip(m.state_names, y0)), t_span=t_span,
                      path=None if getattr(m, "source_path", None) is None else m.source_path.parent)
    else:
        raise TypeError(f"`scene_or_model` must be a Scene, a scene name, a RunSpec or a Model, got {type(target).__name__}")
    changes: dict[str, Any] = {}
    if not isinstance(target, Model):
        for name, given in (("params", params), ("y0", y0)):
            if given is not None and not isinstance(given, Mapping):
                raise TypeError(f"`{name}` of a scene or RunSpec must be a mapping {{name: value}} of the values to "
                                f"replace (an array is taken only with a Model), got {type(given).__name__}")
        changes.update({k: v for k, v in (params or {}).items()})
        changes.update({k: v for k, v in (y0 or {}).items()})
        if t_span is not None:
            run = RunSpec.from_dict({**run.to_dict(), "t_span": t_span})
    for k, v in (("method", method), ("rtol", rtol), ("atol", atol)):
        if v is not None:
            changes[k] = v
    return run.with_(**changes) if changes else run


def _expand(run: RunSpec, points: list) -> list:
    """The grid's runs, each checked as :func:`simulate` checks it, before any work.

    Returns one :class:`_Run` per grid point (its ``spec`` as a plain dict,
    its ``inputs`` columns with the ``run_id``, its JSON text).

    Each check of :func:`~knifeedge.simulate.check_inputs` concerns one
    argument (a parameter's sign, a state's finiteness, the order of the
    span, a tolerance's range), so the grid is checked by value rather than
    run by run: every distinct combination of run settings (``method``,
    ``rtol``, ``atol``, ``max_steps``) as a whole run, every distinct
    parameter vector by ``Model.check_params``, every initial value and
    ``t_end`` by the rule of ``RunSpec`` and ``Model.state`` (a finite real
    number; ``t_end`` after the start).
    """
    accepted = set(run.params) | set(run.y0) | set(RUN_SETTINGS)
    varying = set(run.params) | set(run.y0) | {"t_end"}  # per run; the other names are run settings
    kinds: dict = {}  # names of a point -> (its run settings, its values that vary run by run)
    grid_varying: list = []  # names of the grid that vary run by run, in order of first use
    for pt in points:
        names = tuple(pt)
        if names in kinds:
            continue
        bad = [k for k in pt if k not in accepted or k in ("fidelity", "pose", "n_eval", "path")]
        if bad:
            raise ValueError(
                f"`grid` name(s) {bad} are not parameters {tuple(run.params)}, initial states {tuple(run.y0)} "
                "or one of method, rtol, atol, t_end, max_steps"
            )
        kinds[names] = (tuple(k for k in pt if k not in varying), tuple(k for k in pt if k in varying))
        grid_varying.extend(k for k in pt if k in varying and k not in grid_varying)
    model = run.load()
    bases: dict = {}  # the run settings of a point (typed) -> its _Base
    params_ok: set = set()
    out = []
    for pt in points:
        settings, names = kinds[tuple(pt)]
        key = tuple((k, type(pt[k]), repr(pt[k])) for k in settings) if settings else ()
        base = bases.get(key)
        if base is None:
            base = bases[key] = _Base(run.with_(**{k: pt[k] for k in settings}), model, grid_varying)
        values = dict(base.values)
        for k in names:
            values[k] = _validate.finite(pt[k], f"`{k}`")  # the rule of RunSpec and Model.state
        if base.params_varying:
            p = tuple(values.get(k, v) for k, v in base.run.params.items())
            if p not in params_ok:
                model.check_params(dict(zip(base.run.params, p)))
                params_ok.add(p)
        if "t_end" in names and not values["t_end"] > base.run.t_span[0]:
            raise ValueError(f"`t_end` must exceed the start time {base.run.t_span[0]:g}, got {pt['t_end']!r}")
        out.append(base.make(values))
    return out


class _Run:
    """One run of a sweep: ``spec`` (``RunSpec.to_dict`` form), ``inputs`` (its input columns, ``run_id``
    first), ``text`` (``spec`` as JSON, for the store) and ``checksum`` (a :class:`~knifeedge.store.RowChecksum`
    of its row, shared with the runs of its base)."""

    __slots__ = ("spec", "inputs", "text", "checksum")

    def __init__(self, spec: dict, inputs: dict, text: str, checksum=None):
        self.spec, self.inputs, self.text, self.checksum = spec, inputs, text, checksum

    @property
    def run_id(self) -> str:
        return self.inputs["run_id"]


_HOLE_MARK = "@knifeedge-sweep-value-"
_HOLE = _HOLE_MARK + "{}@"


class _Base:
    """A run checked whole, and the runs that differ from it only in the values of parameters, initial states
    and ``t_end``: their spec, input columns, run id and JSON text, written as :func:`_inputs` and
    ``json.dumps`` write them, by filling the text of the values into the base run's JSON (a float is written
    by its ``repr`` either way)."""

    def __init__(self, run: RunSpec, model, names: Sequence[str]):
        if not isinstance(run.method, str) or run.method not in METHODS:
            raise ValueError(f"unknown `method` {run.method!r} (the argument, the scene's or a `grid` value); "
                             f"accepted: {', '.join(sorted(METHODS))}")
        if not run.t_span[1] > run.t_span[0]:
            raise ValueError(f"`t_end` must exceed the start time {run.t_span[0]:g}, got {run.t_span[1]!r}")
        extra = {} if run.max_steps is None else {"max_steps": run.max_steps}
        check_inputs(model, dict(run.y0), run.t_span, dict(run.params), run.method, run.rtol, run.atol, **extra)
        self.run = run
        self.names = [n for n in names if n in run.params or n in run.y0 or n == "t_end"]
        self.params_varying = any(n in run.params for n in self.names)
        self.values = {n: (run.t_span[1] if n == "t_end" else run.params[n] if n in run.params else run.y0[n])
                       for n in self.names}
        self.spec = run.to_dict()
        self.inputs = _inputs(run)
        self.y0_varying = any(n in run.y0 for n in self.names)
        varying = {"run_id", *("t1" if n == "t_end" else n for n in self.names)}
        self.checksum = RowChecksum(tuple(self.inputs) + RESULT_COLUMNS,
                                    {k: v for k, v in self.inputs.items() if k not in varying})
        self.key_format = self.text_format = None
        if not self.names:
            self.text = json.dumps(self.spec)
            return
        marked = _with_values(self.spec, {n: _HOLE.format(i) for i, n in enumerate(self.names)})
        self.key_format = _template(json.dumps(_key(marked), sort_keys=True), len(self.names))
        self.text_format = _template(json.dumps(marked), len(self.names))
        if self.key_format is None or self.text_format is None or _HOLE_MARK in json.dumps(self.spec):
            self.key_format = self.text_format = None
        else:
            made = self.make(dict(self.values))
            if made.inputs != self.inputs or made.text != json.dumps(self.spec):  # as _inputs and json write them
                self.key_format = self.text_format = None

    def make(self, values: dict) -> _Run:
        """The run whose parameters, initial values and ``t_end`` are ``values`` (one for each of ``names``)."""
        spec = dict(self.spec)
        if self.params_varying:
            spec["params"] = {**self.spec["params"], **{n: values[n] for n in self.names if n in self.spec["params"]}}
        if self.y0_varying:
            spec["y0"] = {**self.spec["y0"], **{n: values[n] for n in self.names if n in self.spec["y0"]}}
        inputs = dict(self.inputs)
        if "t_end" in values:
            spec["t_span"] = [self.spec["t_span"][0], values["t_end"]]
            inputs["t1"] = values["t_end"]
        inputs.update((n, v) for n, v in values.items() if n != "t_end")
        if not self.names:
            return _Run(spec, inputs, self.text, self.checksum)
        if self.key_format is None:  # the slow way, for a base whose JSON the template cannot hold
            inputs["run_id"] = _inputs(RunSpec.from_dict(spec))["run_id"]
            return _Run(spec, inputs, json.dumps(spec), self.checksum)
        texts = tuple([repr(values[n]) for n in self.names])  # each value written once, for both texts
        key, pick = self.key_format
        inputs["run_id"] = hashlib.sha1((key % pick(texts)).encode()).hexdigest()[:16]
        text, pick = self.text_format
        return _Run(spec, inputs, text % pick(texts), self.checksum)


def _with_values(spec: dict, values: Mapping) -> dict:
    """``spec`` (a plain-dict run) with some parameters, initial values and ``t_end`` replaced."""
    d = dict(spec)
    params = {k: v for k, v in values.items() if k in spec["params"]}
    y0 = {k: v for k, v in values.items() if k in spec["y0"]}
    if params:
        d["params"] = {**spec["params"], **params}
    if y0:
        d["y0"] = {**spec["y0"], **y0}
    if "t_end" in values:
        d["t_span"] = [spec["t_span"][0], values["t_end"]]
    return d


def _template(text: str, n: int) -> tuple | None:
    """``text`` (JSON with the strings of ``_HOLE`` in the places of ``n`` floats) as a ``%`` format of the
    floats' texts (a float's ``repr`` is what ``json.dumps`` writes), and the getter that puts a tuple of the
    ``n`` texts in the order of the holes; None unless each hole is there once."""
    pieces = re.split(r'"@knifeedge-sweep-value-(\d+)@"', text)
    order = [int(i) for i in pieces[1::2]]
    if sorted(order) != list(range(n)):
        return None
    fmt = "%s".join(p.replace("%", "%%") for p in pieces[0::2])
    return fmt, (itemgetter(*order) if n > 1 else lambda texts: texts)


def _columns(run: RunSpec) -> tuple:
    return INPUT_COLUMNS + (*run.params, *run.y0) + RESULT_COLUMNS


def _key(spec: RunSpec | Mapping) -> dict:
    """The inputs that identify a run (its output sampling does not).

    The hash of the model module's text is part of the key, for the built-in
    models as for a model from a user's folder: after ``make derive`` or
    ``knifeedge derive`` rewrites a model, its runs are new runs.  (Run ids
    of stores written before this rule, ``KEY_VERSION``, are never matched.)
    """
    d = dict(spec.to_dict() if isinstance(spec, RunSpec) else spec)
    d.pop("n_eval", None)
    for k in ("max_steps", "path"):  # absent when unset
        if d.get(k) is None:
            d.pop(k, None)
    d["module_sha256"] = _module_hash(d.get("path"), d["model"], d["fidelity"])
    d["key_version"] = KEY_VERSION
    return d


#: the version of the rule of :func:`_key` (2: every model's module hashed)
KEY_VERSION = 2
_MODULE_HASHES: dict = {}


def _module_file(folder: str | None, model: str, fidelity: str) -> Path:
    """The file of the model module a run loads: in the user's ``folder``, or the built-in one."""
    if folder is not None:
        return Path(folder) / f"{model}_{fidelity}.py"
    from . import generated

    name = generated.MODULES.get((model, fidelity))
    if name is None:
        raise ValueError(f"unknown model {model!r} at fidelity {fidelity!r}; built-in: "
                         f"{sorted(set(m for m, _ in generated.MODULES))}")
    return Path(generated.__file__).parent / f"{name}.py"


def _module_hash(folder: str | None, model: str, fidelity: str) -> str:
    f = _module_file(folder, model, fidelity)
    stat = f.stat()
    key = (str(f), stat.st_mtime_ns, stat.st_size)
    if key not in _MODULE_HASHES:
        _MODULE_HASHES[key] = hashlib.sha256(f.read_bytes()).hexdigest()
    return _MODULE_HASHES[key]


def _inputs(spec: RunSpec) -> dict:
    """The input columns of a run, ``run_id`` first: the definition that :class:`_Base` follows faster."""
    key = json.dumps(_key(spec), sort_keys=True)
    run_id = hashlib.sha1(key.encode()).hexdigest()[:16]
    return {"run_id": run_id, "model": spec.model, "fidelity": spec.fidelity, "method": spec.method,
            "rtol": float(spec.rtol), "atol": float(spec.atol), "t0": spec.t_span[0], "t1": spec.t_span[1],
            **dict(spec.params), **dict(spec.y0)}


def _missing_row(inputs: dict, reason: str) -> dict:
    return {**inputs, "status": MISSING, "message": reason, "nfev": None, **_reversal_columns([]),
            "seconds": math.nan}


# -- where the results go -----------------------------------------------------
def _open_store(out, names: Sequence[str]) -> tuple[ResultStore | None, Path | None]:
    """The SQLite store for ``out``, and the text file to export to (``out`` itself if it is .csv/.jsonl)."""
    if out is None:
        return None, None
    if not isinstance(out, (str, os.PathLike)):
        raise TypeError(f"`out` must be a file path, got {type(out).__name__}")
    path = Path(out)
    suffix = path.suffix.lower()
    if suffix in STORE_SUFFIXES:
        return ResultStore(path, names), None
    if suffix not in TEXT_SUFFIXES:
        raise ValueError(f"`out` must end in .sqlite (the results store; also .sqlite3, .db), or .csv / .jsonl "
                         f"(a text export beside a store of the same name ending in .sqlite), got {path.name!r}")
    db = path.with_suffix(".sqlite")
    if path.exists() and path.is_dir():
        raise ValueError(f"`out` {str(path)!r} is a folder")
    new = not db.exists()
    legacy = read_text(path) if new and path.exists() else []  # results of an earlier version: keep them
    store = ResultStore(db, names)
    if legacy:
        store.import_rows(legacy)
    return store, path


# -- progress -----------------------------------------------------------------
class _Progress:
    """A tqdm bar on stderr (``progress=True``), and/or the user's ``callback(done, total, row)``."""

    def __init__(self, total: int, done: int, progress):
        self.total, self.done, self.failed, self.missing = total, done, 0, 0
        self.callback = progress if callable(progress) else None
        self.bar = None
        if progress is True:
            from tqdm.auto import tqdm

            self.bar = tqdm(total=total, initial=done, desc="sweep", unit="run", file=sys.stderr,
                            dynamic_ncols=True, mininterval=0.5, smoothing=0.05)

    def update(self, row: dict) -> None:
        self.done += 1
        self.failed += row["status"] in ("failed", "error")
        if self.callback:
            self.callback(self.done, self.total, row)
        if self.bar is not None:
            self.bar.update(1)
            if row["status"] != "ok":
                self.postfix()

    def postfix(self, waiting: Mapping | None = None) -> None:
        """Show the failures, runs without result and ``waiting`` (run id -> whose claim holds it) on the bar."""
        if self.bar is not None:
            info = {"failed": self.failed}
            if self.missing:
                info["no result"] = self.missing
            if waiting:
                info["waiting for"] = f"{len(waiting)} run(s) claimed by another sweep, {next(iter(waiting.values()))}"
            self.bar.set_postfix(info, refresh=False)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


# -- the sweep ----------------------------------------------------------------
def sweep(
    scene_or_model,
    grid,
    *,
    params: Mapping | None = None,
    y0: Mapping | None = None,
    t_span=None,
    method: str | None = None,
    rtol: float | None = None,
    atol: float | None = None,
    executor: cf.Executor | str | None = None,
    max_workers: int | None = None,
    out: str | Path | None = None,
    resume: bool = True,
    progress: bool | Callable[[int, int, dict], None] = True,
    chunksize: int | None = None,
) -> SweepTable:
    """Integrate one model over a grid of parameters and initial states.

    Parameters
    ----------
    scene_or_model : Scene, scene name, RunSpec or Model
        The base run.  A scene or run brings its parameters, initial state,
        span, method and tolerances; a Model needs ``params``, ``y0`` and
        ``t_span`` (a model loaded with ``path=`` is loaded from that folder
        by every worker).
    grid : mapping ``{name: values}`` (Cartesian product, first name slowest)
        or sequence of mappings (explicit points).  Names are parameter names
        (``"D"``), initial-state names (``"phi_dot"``) or ``"method"``,
        ``"rtol"``, ``"atol"``, ``"t_end"``, ``"max_steps"``.
    params, y0 : mappings; for a scene, values that replace the scene's.
    t_span, method, rtol, atol : replace the base run's settings.
    executor : ``concurrent.futures.Executor``, ``"processes"``, ``"serial"`` or None
        Where runs execute.  None or ``"processes"``: ``max_workers`` local
        worker processes (default: all cores; a single run or one worker
        runs in this process) that are replaced if they die and never
        outlive the sweep.  An Executor: e.g. a Dask cluster,
        ``distributed.Client(...).get_executor()``.  ``"serial"``: in this
        process.
    max_workers : number of local worker processes.
    out : path, optional
        The results store.  ``.sqlite`` (or ``.sqlite3``, ``.db``): an SQLite
        file, one row per run, each committed within half a second of finishing.  ``.csv`` or
        ``.jsonl``: the store is the file of the same name ending in
        ``.sqlite`` and this file is a text export of the sweep's rows,
        rewritten when the sweep ends (a text file written by an earlier
        version is read in first).  Runs already in the store are read back,
        not recomputed; runs claimed by a concurrent sweep on the same store
        are left to it and their rows awaited.
    resume : if False, runs stored before this call are recomputed (and replaced).
    progress : True (a tqdm bar on stderr), False, or ``callback(done, total, row)``.
    chunksize : runs per task sent to a worker; default: sized from the
        runs' duration so that a task takes about 0.25 s (up to 256 runs; on an Executor 1 s, up to 1024 runs).

    Returns
    -------
    SweepTable
        Rows in grid order (``.to_pandas()`` for a DataFrame).  Columns:
        ``run_id`` (a hash of the run's inputs), ``model``, ``fidelity``,
        ``method``, ``rtol``, ``atol``, ``t0``, ``t1``, every parameter,
        every initial state, then ``status`` (``"ok"``/``"failed"``/
        ``"error"``, or ``"missing"`` for a run without a result),
        ``message``, ``nfev``, ``n_reversals``, ``first_reversal`` (time of
        the first spin reversal, NaN if none), ``mean_interval`` (mean time
        between consecutive reversals, NaN if fewer than two),
        ``reversal_times`` (list) and ``seconds`` (the run's time in its worker).

    Warns
    -----
    RuntimeWarning
        If some runs have no result (their worker died every time), or rows
        of the store were damaged (they are recomputed).
    """
    if not (executor is None or executor in ("serial", "processes") or isinstance(executor, cf.Executor)):
        raise TypeError(f"`executor` must be a concurrent.futures.Executor, 'processes', 'serial' or None, "
                        f"got {executor!r}")
    if max_workers is not None and (isinstance(max_workers, bool) or not isinstance(max_workers, int)
                                    or max_workers < 1):
        raise ValueError(f"`max_workers` must be a positive integer, got {max_workers!r}")
    if chunksize is not None and (isinstance(chunksize, bool) or not isinstance(chunksize, int) or chunksize < 1):
        raise ValueError(f"`chunksize` must be a positive integer, got {chunksize!r}")
    if not (isinstance(progress, bool) or callable(progress)):
        raise TypeError("`progress` must be True, False or a callable(done, total, row)")
    if not isinstance(resume, bool):
        raise TypeError(f"`resume` must be True or False, got {resume!r}")
    with heap_frozen() as freeze:
        run = _base_run(scene_or_model, params, y0, t_span, method, rtol, atol)
        runs = _expand(run, _grid_points(grid))
        freeze()  # the grid's runs too: they live as long as the sweep
        columns = _columns(run)
        store, export = _open_store(out, (*run.params, *run.y0))
        try:
            return _Sweep(runs, columns, store, export, executor, max_workers, resume, progress, chunksize).run()
        finally:
            if store is not None:
                store.close()


@dataclass
class _Queues:
    """Where the runs of a sweep without a result are: to claim (``todo``), claimed and not handed out
    (``ready``), in a task (``inflight``: task id -> run ids), held by another sweep (``others``: run_id -> who)."""

    todo: deque
    ready: deque = field(default_factory=deque)
    inflight: dict = field(default_factory=dict)
    others: dict = field(default_factory=dict)
    attempts: dict = field(default_factory=dict)  # run_id -> how many times its worker was lost
    task_ids: Iterator = field(default_factory=itertools.count)
    last_poll: float = 0.0  # when the runs of ``others`` were last asked for


class _Sweep:
    def __init__(self, runs, columns, store, export, executor, max_workers, resume, progress, chunksize):
        self.inputs = [r.inputs for r in runs]
        self.columns, self.store, self.export = columns, store, export
        self.executor, self.max_workers, self.chunksize = executor, max_workers, chunksize
        self.since = None if resume else time.time()
        self.progress = progress
        self.by_id: dict = {}  # run_id -> index of its first grid point
        self.spec_of: dict = {}  # run_id -> its _Run
        for i, r in enumerate(runs):
            if r.run_id not in self.by_id:
                self.by_id[r.run_id] = i
                self.spec_of[r.run_id] = r
        self.results: dict = {}  # run_id -> row
        self.missing: dict = {}  # run_id -> reason
        self.damaged: list = []
        self.n_computed = 0
        self.n_retried = 0
        self.times: deque = deque(maxlen=64)
        self.pending: list = []  # (rows, run ids, outcomes) of the tasks received and not written yet
        self.written_at = time.monotonic()

    # -- helpers ------------------------------------------------------------------
    def _row(self, rid: str, outcome: Mapping) -> dict:
        return {**self.inputs[self.by_id[rid]], **outcome}

    def _checksums(self, ids: list, out: list, rows: list) -> dict:
        """The checksum of each row (by its base's template) whose outcome has exactly the result columns."""
        spec_of = self.spec_of
        return {rid: spec_of[rid].checksum(row) for rid, o, row in zip(ids, out, rows) if o.keys() == _RESULT_KEYS}

    def _record(self, rows: list, computed: bool) -> None:
        for row in rows:
            self.results[row["run_id"]] = row
            self.bar.update(row)
        if computed:
            self.n_computed += len(rows)

    def _pool(self, n_todo: int):
        ex = self.executor
        if ex == "serial" or (ex is None and (n_todo <= 1 or self.max_workers == 1)):
            return SerialPool(run_batch), 1
        if ex in (None, "processes"):
            n = self.max_workers or os.cpu_count() or 1
            n = max(1, min(n, n_todo))
            if _can_fork():
                self._warm()
            return LocalPool(n, run_batch), n
        n = self.max_workers
        client = getattr(ex, "_client", None)  # distributed.Client.get_executor()
        if n is None and client is not None:
            try:
                n = sum(client.nthreads().values())
            except Exception:  # noqa: BLE001
                n = None
        n = n or getattr(ex, "_max_workers", None) or os.cpu_count() or 1
        return ExecutorPool(ex, run_batch, 2 * n), n

    def _warm(self) -> None:
        """Load (or compile) the kernels of the runs to do in this process, before workers are forked from it:
        each worker would otherwise load them itself (0.4 s of CPU for the two-mode model; on a first use, all
        would run SciPy's solver while a background process compiles, or all compile at once)."""
        from .integrators.compiler import compile_mode_set

        done = set()
        for r in self.spec_of.values():
            method = r.spec["method"]
            if method in done:
                continue
            done.add(method)
            t0, t1 = r.spec["t_span"]
            tiny = {**r.spec, "t_span": [t0, t0 + 1e-9 * (t1 - t0)], "n_eval": None, "max_steps": None}
            try:
                with warnings.catch_warnings(), compile_mode_set("wait"):
                    warnings.simplefilter("ignore")
                    RunSpec.from_dict(tiny).simulate()
            except Exception:  # noqa: BLE001 - the runs themselves will say what is wrong
                pass

    def _chunk(self, remaining: int, n_workers: int, pool) -> int:
        if self.chunksize is not None:
            return self.chunksize
        if len(self.times) < 2:
            return 1
        per_run = max(statistics.median(self.times), 1e-5)
        k = int(getattr(pool, "task_seconds", TASK_SECONDS) / per_run)
        k = min(k, getattr(pool, "max_chunk", MAX_CHUNK), max(1, remaining // (4 * n_workers)))  # a balanced tail
        k = max(k, int(getattr(pool, "min_task_seconds", 0.0) / per_run))  # ... of tasks worth their own cost
        return max(1, k)

    # -- the loop -----------------------------------------------------------------
    def run(self) -> SweepTable:
        order = list(self.by_id)
        self._read_store(order)
        for msg in self.damaged:
            warnings.warn(msg, RuntimeWarning, stacklevel=3)
        n_reused = len(self.results)
        queues = _Queues(deque(r for r in order if r not in self.results))
        pool, n_workers = self._start(queues.todo, len(order), n_reused)
        interrupted = gone = False
        try:
            self._loop(pool, n_workers, queues)
            if self.store is not None:
                self._write_now()
                self.store.check_file()
        except BaseException as exc:
            interrupted = True
            gone = isinstance(exc, StoreGone)  # said by the error itself: no store to resume from
            raise
        finally:
            rows = self._finish(pool, interrupted, gone, len(order))
        table = SweepTable(self.columns, rows, n_computed=self.n_computed, n_reused=len(self.results) - self.n_computed,
                           n_missing=len(self.inputs) - sum(r["status"] != MISSING for r in rows),
                           store=self.store.path if self.store is not None else None, damaged=self.damaged,
                           n_retried=self.n_retried)
        if table.n_missing:
            warnings.warn(f"sweep: {table.n_missing} run(s) have no result ({next(iter(self.missing.values()))}); "
                          "run the same sweep again to compute them", RuntimeWarning, stacklevel=3)
        return table

    def _read_store(self, order: list) -> None:
        """The rows of ``order`` the store holds already (written since ``self.since``), as results."""
        if self.store is None:
            return
        found, damaged = self.store.read(order, self.since)
        self.damaged.extend(damaged)
        self.results.update({rid: {**self._row(rid, {}), **{c: row[c] for c in RESULT_COLUMNS if c in row}}
                             for rid, row in found.items()})

    def _start(self, todo, n_total: int, n_reused: int) -> tuple:
        """``(pool, n_workers)`` (``(None, 0)`` with nothing to do), then the progress bar."""
        pool, n_workers = (None, 0)
        if todo:  # before the progress bar's thread: workers are forked while this process has one thread
            pool, n_workers = self._pool(len(todo))
        try:
            self.bar = _Progress(n_total, n_reused, self.progress)
        except BaseException:
            if pool is not None:
                pool.shutdown()
            raise
        return pool, n_workers

    def _loop(self, pool, n_workers: int, q: _Queues) -> None:
        """Until every run has a result or none can get one: hand out work, collect it, keep the store."""
        while q.todo or q.ready or q.inflight or q.others:
            self._hand_out(pool, n_workers, q)
            for t, out in pool.wait(0.5 if (q.inflight or not q.others) else 1.0):
                self._received(q.inflight.pop(t), out, q)
            self._drop_if_broken(pool, q)
            if self.store is not None:
                self._keep_store(q)

    def _hand_out(self, pool, n_workers: int, q: _Queues) -> None:
        """Hand out work while the pool has room."""
        while (q.ready or q.todo) and pool.free():
            head = q.ready[0] if q.ready else q.todo[0]
            k = 1 if head in q.attempts else self._chunk(len(q.ready) + len(q.todo), n_workers, pool)
            if len(q.ready) < k and q.todo:  # claim this task's runs and the next task's at once
                ids = [q.todo.popleft() for _ in range(min(2 * k - len(q.ready), len(q.todo)))]
                q.ready.extend(self._claim(ids, q.others))
                continue
            ids = [q.ready.popleft() for _ in range(min(k, len(q.ready)))]
            t = next(q.task_ids)
            q.inflight[t] = ids
            pool.submit(t, [self.spec_of[r].spec for r in ids])

    def _received(self, ids: list, out, q: _Queues) -> None:
        """The outcomes of a finished task (or the news that its worker was lost)."""
        if isinstance(out, WorkerLost):
            self._lost(ids, str(out), q.attempts, q.ready)
            return
        rows = [self._row(rid, o) for rid, o in zip(ids, out)]
        self.times.extend(o["seconds"] for o in out)
        if self.store is not None:
            self.pending.append((rows, ids, out))
        self._record(rows, computed=True)

    def _drop_if_broken(self, pool, q: _Queues) -> None:
        """An executor that takes no more work: the runs not handed out stay without a result."""
        broken = getattr(pool, "broken", None)
        if broken and not q.inflight and (q.todo or q.ready):
            for rid in itertools.chain(q.ready, q.todo):
                self.missing[rid] = f"not computed: the executor is broken ({broken})"
            self.bar.missing += len(q.todo) + len(q.ready)
            if self.store is not None:
                self.store.release(list(q.ready))
            q.todo.clear()
            q.ready.clear()

    def _keep_store(self, q: _Queues) -> None:
        """Write the rows waiting (every WRITE_SECONDS), renew the claims, take over the runs another sweep left."""
        now = time.monotonic()
        if self.pending and now - self.written_at >= WRITE_SECONDS:
            self._write_now()
        self.store.renew()
        if q.others and not q.todo and not q.ready and now - q.last_poll > 0.5:  # another sweep's runs: done?
            q.last_poll = now
            waiting = list(q.others)
            q.others.clear()
            q.ready.extend(self._claim(waiting, q.others))
        self.bar.postfix(waiting=q.others)

    def _finish(self, pool, interrupted: bool, gone: bool, n_total: int) -> list:
        """Shut the pool down, write the last rows and the export, close the bar; returns the rows in grid order."""
        if pool is not None:
            pool.shutdown()
        if self.store is not None:
            self._write_last(interrupted)
        self.bar.close()
        rows = [self.results.get(inp["run_id"]) or _missing_row(inp, self.missing.get(
            inp["run_id"], "not computed: the sweep was interrupted")) for inp in self.inputs]
        if self.export is not None:
            write_text(self.export, [r for r in rows if r["status"] != MISSING], self.columns)
        if interrupted and self.progress is True and not gone:
            where = self.store.path if self.store is not None else None
            saved = (f"; the finished runs are in {where}: run the same sweep again to resume"
                     if where is not None else "")
            print(f"sweep: interrupted after {len(self.results)}/{n_total} runs{saved}", file=sys.stderr,
                  flush=True)
        return rows

    def _write(self) -> int:
        """Write the rows received since the last write, inside the store's transaction the caller opened; returns
        how many tasks' rows it wrote, to pass to :meth:`_written` once that transaction has committed (until
        then they stay waiting: a transaction that fails takes them with it, and they are written again)."""
        if not self.pending:
            return 0
        rows, specs, sums = [], {}, {}
        spec_of = self.spec_of
        for task_rows, ids, out in self.pending:
            rows += task_rows
            specs.update((r, spec_of[r].text) for r in ids)
            sums.update(self._checksums(ids, out, task_rows))
        self.store.write(rows, specs, sums)
        return len(self.pending)

    def _written(self, n: int) -> None:
        del self.pending[:n]
        self.written_at = time.monotonic()

    def _write_now(self) -> None:
        with self.store.transaction():
            n = self._write()
        self._written(n)

    def _write_last(self, interrupted: bool) -> None:
        """At the end (or on the way out of an exception): write the rows received and not written yet, then free
        the runs handed out but unfinished, or claimed and not handed out (not results).  A failure to write is
        raised, unless the sweep is already on its way out of another exception (then it is a warning)."""
        gone = False
        try:
            self._write_now()
        except StoreGone:  # the file that held the claims is gone: nothing to release
            gone = True
            if not interrupted:
                raise
        except Exception as exc:  # noqa: BLE001
            if not interrupted:
                raise
            lost = sum(len(rows) for rows, _, _ in self.pending)
            warnings.warn(f"sweep: {lost} finished run(s) could not be written to {self.store.path} "
                          f"({type(exc).__name__}: {exc}); they are computed again on resume", RuntimeWarning,
                          stacklevel=4)
        finally:
            if not gone:
                self.store.release()

    def _claim(self, ids: list, others: dict) -> list:
        """Claim ``ids`` in the store, and write the rows waiting, in one transaction; record rows found written,
        note runs held by another sweep."""
        if self.store is None:
            return ids
        with self.store.transaction():
            n = self._write()
            claimed, done, busy, damaged = self.store.claim(ids, self.since)
        self._written(n)
        for msg in damaged:
            if msg not in self.damaged:
                self.damaged.append(msg)
                warnings.warn(msg, RuntimeWarning, stacklevel=4)
        if done:
            self._record([{**self._row(rid, {}), **{c: row[c] for c in RESULT_COLUMNS if c in row}}
                          for rid, row in done.items()], computed=False)
        others.update(busy)
        return claimed

    def _lost(self, ids: list, reason: str, attempts: dict, ready: deque) -> None:
        """Runs of a task lost to the infrastructure: retry each alone, up to MAX_ATTEMPTS."""
        retry = []
        for rid in ids:
            attempts[rid] = attempts.get(rid, 0) + 1
            if attempts[rid] < MAX_ATTEMPTS:
                retry.append(rid)
            else:
                self.missing[rid] = f"no result after {MAX_ATTEMPTS} attempts: {reason}"
                self.bar.missing += 1
        if self.store is not None:
            self.store.release([r for r in ids if r not in retry])
        # retried first, one run per task, so that a run that kills its worker is isolated
        self.n_retried += len(retry)
        for rid in reversed(retry):  # still claimed by this sweep
            ready.appendleft(rid)
        self.bar.postfix()
