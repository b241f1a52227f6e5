"""``sweep``: many integrations over a grid of parameters or initial states.

One row per run (its inputs, its spin reversals, its status), computed on
any :class:`concurrent.futures.Executor` -- local processes by default, or a
Dask cluster through ``distributed.Client(...).get_executor()`` -- and
appended to a file as each run finishes, so that an interrupted sweep
resumes without recomputing or losing the runs already done.  A run that
fails is a row with ``status`` ``"failed"`` (the integrator gave up) or
``"error"`` (the run raised), and its message; it never aborts the sweep.
"""
from __future__ import annotations

import concurrent.futures as cf
import csv
import hashlib
import io
import itertools
import json
import math
import os
import sys
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from .scenes.base import RUN_SETTINGS, RunSpec
from .simulate import METHODS

#: outcome columns, after the input columns
RESULT_COLUMNS = ("status", "message", "nfev", "n_reversals", "first_reversal", "mean_interval", "reversal_times")
STATUSES = ("ok", "failed", "error")
_TEXT_COLUMNS = frozenset({"run_id", "model", "fidelity", "method", "status", "message"})


# -- one run ------------------------------------------------------------------
def run_one(spec: Mapping) -> dict:
    """Integrate one :class:`RunSpec` given as a dict; return its outcome columns.

    Runs in a worker process.  Never raises: an exception becomes
    ``status="error"`` with the exception's message.
    """
    try:
        run = RunSpec.from_dict(dict(spec, n_eval=None))
        r = run.simulate()
        rev = [float(t) for t in r.reversal_times]
        return {
            "status": "ok" if r.success else "failed",
            "message": "" if r.success else r.message,
            "nfev": int(r.nfev),
            **_reversal_columns(rev),
        }
    except Exception as exc:  # noqa: BLE001 - recorded, not raised
        return {"status": "error", "message": f"{type(exc).__name__}: {exc}", "nfev": 0, **_reversal_columns([])}


def _reversal_columns(rev: list) -> dict:
    return {
        "n_reversals": len(rev),
        "first_reversal": rev[0] if rev else math.nan,
        "mean_interval": float(np.mean(np.diff(rev))) if len(rev) > 1 else math.nan,
        "reversal_times": rev,
    }


# -- the table ----------------------------------------------------------------
class SweepTable:
    """A tidy table: one row (a dict) per run, columns in a fixed order.

    Attributes
    ----------
    columns : tuple of str
    rows : list of dict
    n_computed, n_reused : int
        Runs integrated by this call, and runs read back from the ``out`` file.
    """

    def __init__(self, columns: Sequence[str], rows: list, n_computed: int = 0, n_reused: int = 0):
        self.columns = tuple(columns)
        self.rows = rows
        self.n_computed = n_computed
        self.n_reused = n_reused

    def __len__(self) -> int:
        return len(self.rows)

    def __iter__(self):
        return iter(self.rows)

    def __getitem__(self, column: str) -> np.ndarray:
        """One column as an array (float for numbers, object otherwise)."""
        if column not in self.columns:
            raise KeyError(f"no column {column!r}; columns are {self.columns}")
        values = [row[column] for row in self.rows]
        if column in _TEXT_COLUMNS or column == "reversal_times":
            return np.array(values, dtype=object)
        return np.array(values, dtype=float)

    @property
    def ok(self) -> np.ndarray:
        """Boolean mask of the runs that reached the end of their span."""
        return np.array([row["status"] == "ok" for row in self.rows], dtype=bool)

    def failures(self) -> list:
        """The rows whose status is not ``"ok"``."""
        return [row for row in self.rows if row["status"] != "ok"]

    def to_csv(self, path: str | Path | None = None) -> str:
        """CSV text (reversal times space-separated); written to ``path`` if given."""
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(self.columns)
        for row in self.rows:
            w.writerow(_csv_cells(row, self.columns))
        if path is not None:
            Path(path).write_text(buf.getvalue())
        return buf.getvalue()

    def to_pandas(self):
        """A ``pandas.DataFrame`` (needs pandas)."""
        import pandas as pd

        return pd.DataFrame(self.rows, columns=list(self.columns))

    def __repr__(self) -> str:
        shown = [c for c in self.columns if c not in ("run_id", "message", "reversal_times")]
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


def _csv_cells(row: Mapping, columns: Sequence[str]) -> list:
    out = []
    for c in columns:
        v = row[c]
        if c == "reversal_times":
            out.append(" ".join(repr(float(t)) for t in v))
        elif isinstance(v, float):
            out.append(repr(v))
        else:
            out.append(v)
    return out


def _csv_row(cells: Sequence[str], columns: Sequence[str]) -> dict:
    row: dict = {}
    for c, v in zip(columns, cells):
        if c in _TEXT_COLUMNS:
            row[c] = v
        elif c == "reversal_times":
            row[c] = [float(t) for t in v.split()]
        elif c in ("nfev", "n_reversals"):
            row[c] = int(v)
        elif c == "pose":
            row[c] = v == "True"
        else:
            row[c] = float(v)
    return row


# -- the grid -----------------------------------------------------------------
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
        run = target.run
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
                      y0=dict(y0) if isinstance(y0, Mapping) else dict(zip(m.state_names, y0)), t_span=t_span)
    else:
        raise TypeError(f"`scene_or_model` must be a Scene, a scene name, a RunSpec or a Model, got {type(target).__name__}")
    changes: dict[str, Any] = {}
    if not isinstance(target, Model):
        changes.update({k: v for k, v in (params or {}).items()})
        changes.update({k: v for k, v in (y0 or {}).items()})
        if t_span is not None:
            run = RunSpec.from_dict({**run.to_dict(), "t_span": tuple(t_span)})
    for k, v in (("method", method), ("rtol", rtol), ("atol", atol)):
        if v is not None:
            changes[k] = v
    return run.with_(**changes) if changes else run


def _expand(run: RunSpec, points: list) -> list:
    """Validated RunSpecs, one per grid point, before any work."""
    accepted = set(run.params) | set(run.y0) | set(RUN_SETTINGS)
    specs = []
    for pt in points:
        bad = [k for k in pt if k not in accepted or k in ("fidelity", "pose", "n_eval")]
        if bad:
            raise ValueError(
                f"`grid` name(s) {bad} are not parameters {tuple(run.params)}, initial states {tuple(run.y0)} "
                "or one of method, rtol, atol, t_end, max_steps"
            )
        spec = run.with_(**pt)
        if not isinstance(spec.method, str) or spec.method not in METHODS:
            raise ValueError(f"unknown `method` {spec.method!r} in `grid`; accepted: {', '.join(sorted(METHODS))}")
        for name in ("rtol", "atol"):
            v = getattr(spec, name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not (math.isfinite(v) and v > 0):
                raise ValueError(f"`{name}` must be positive and finite, got {v!r}")
        if not spec.t_span[1] > spec.t_span[0]:
            raise ValueError(f"`t_end` must exceed the start time {spec.t_span[0]:g}, got {spec.t_span[1]!r}")
        model = spec.load()
        model.check_params(dict(spec.params))  # bad values fail here, before any work
        model.check_state(dict(spec.y0))
        specs.append(spec)
    return specs


def _columns(run: RunSpec) -> tuple:
    return ("run_id", "model", "fidelity", "method", "rtol", "atol", "t0", "t1",
            *run.params, *run.y0) + RESULT_COLUMNS


def _inputs(spec: RunSpec) -> dict:
    d = spec.to_dict()
    d.pop("n_eval")
    if d["max_steps"] is None:
        d.pop("max_steps")
    key = json.dumps(d, sort_keys=True)
    run_id = hashlib.sha1(key.encode()).hexdigest()[:16]
    return {"run_id": run_id, "model": spec.model, "fidelity": spec.fidelity, "method": spec.method,
            "rtol": float(spec.rtol), "atol": float(spec.atol), "t0": spec.t_span[0], "t1": spec.t_span[1],
            **dict(spec.params), **dict(spec.y0)}


# -- the output file ----------------------------------------------------------
class _Store:
    """Rows already on disk, and appending new ones (CSV or JSON lines)."""

    def __init__(self, path: Path | None, columns: tuple, resume: bool):
        self.path, self.columns = path, columns
        self.done: dict = {}
        if path is None:
            return
        suffix = path.suffix.lower()
        if suffix not in (".csv", ".jsonl", ".ndjson", ".json"):
            raise ValueError(f"`out` must end in .csv or .jsonl (JSON lines), got {path.name!r}")
        self.jsonl = suffix != ".csv"
        if path.exists() and resume:
            self._read()
        else:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text("" if self.jsonl else ",".join(columns) + "\n")

    def _read(self) -> None:
        text = self.path.read_text()
        if text and not text.endswith("\n"):  # a row cut short by an interruption: drop it
            text = text[: text.rfind("\n") + 1]
            self.path.write_text(text)
        if self.jsonl:
            for line in text.splitlines():
                try:
                    row = json.loads(line)
                except json.JSONDecodeError:
                    continue
                if isinstance(row, dict) and "run_id" in row:
                    self.done[row["run_id"]] = row
            return
        reader = csv.reader(io.StringIO(text))
        header = next(reader, None)
        if header is None:
            self.path.write_text(",".join(self.columns) + "\n")
            return
        if tuple(header) != self.columns:
            raise ValueError(
                f"`out` file {str(self.path)!r} holds a sweep with other columns; "
                "choose another file or pass resume=False to overwrite it"
            )
        for cells in reader:
            if len(cells) == len(self.columns):
                row = _csv_row(cells, self.columns)
                self.done[row["run_id"]] = row

    def append(self, row: dict) -> None:
        if self.path is None:
            return
        with open(self.path, "a", newline="") as f:
            if self.jsonl:
                f.write(json.dumps({c: row[c] for c in self.columns}, allow_nan=True) + "\n")
            else:
                csv.writer(f, lineterminator="\n").writerow(_csv_cells(row, self.columns))
            f.flush()
            os.fsync(f.fileno())


# -- progress -----------------------------------------------------------------
class _Progress:
    def __init__(self, total: int, reused: int, progress):
        self.total, self.reused, self.done, self.failed = total, reused, reused, 0
        self.callback = progress if callable(progress) else None
        self.show = progress is True
        self.t0 = time.perf_counter()
        self._line()

    def _line(self, end: str = "") -> None:
        if self.show:
            tty = sys.stderr.isatty()
            msg = (f"sweep: {self.done}/{self.total} runs ({self.reused} from file, {self.failed} failed), "
                   f"{time.perf_counter() - self.t0:.1f} s")
            if tty:
                print("\r" + msg, end=end, file=sys.stderr, flush=True)
            elif end or self.done in (self.reused, self.total) or self.done % max(1, self.total // 10) == 0:
                print(msg, file=sys.stderr, flush=True)

    def update(self, row: dict) -> None:
        self.done += 1
        self.failed += row["status"] != "ok"
        if self.callback:
            self.callback(self.done, self.total, row)
        self._line()

    def close(self) -> None:
        if self.show and sys.stderr.isatty():
            print(file=sys.stderr, flush=True)


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
) -> SweepTable:
    """Integrate one model over a grid of parameters and initial states.

    Parameters
    ----------
    scene_or_model : Scene, scene name, RunSpec or Model
        The base run.  A scene or run brings its parameters, initial state,
        span, method and tolerances; a Model needs ``params``, ``y0`` and
        ``t_span``.
    grid : mapping ``{name: values}`` (Cartesian product, first name slowest)
        or sequence of mappings (explicit points).  Names are parameter names
        (``"D"``), initial-state names (``"phi_dot"``) or ``"method"``,
        ``"rtol"``, ``"atol"``, ``"t_end"``, ``"max_steps"``.
    params, y0 : mappings; for a scene, values that replace the scene's.
    t_span, method, rtol, atol : replace the base run's settings.
    executor : ``concurrent.futures.Executor``, ``"serial"`` or None
        Where runs execute.  None: a ``ProcessPoolExecutor`` with
        ``max_workers`` (default: all cores), shut down at the end.  A Dask
        cluster: ``distributed.Client(...).get_executor()``.  ``"serial"``:
        in this process.
    out : path ending in ``.csv`` or ``.jsonl``, optional
        Each finished run is appended (and flushed) at once.  If the file
        exists and ``resume`` is true, runs already in it are read back, not
        recomputed; otherwise it is overwritten.
    progress : True (a counter on stderr), False, or ``callback(done, total, row)``.

    Returns
    -------
    SweepTable
        Rows in grid order.  Columns: ``run_id``, ``model``, ``fidelity``,
        ``method``, ``rtol``, ``atol``, ``t0``, ``t1``, every parameter, every
        initial state, then ``status`` (``"ok"``/``"failed"``/``"error"``),
        ``message``, ``nfev``, ``n_reversals``, ``first_reversal`` (time of
        the first spin reversal, NaN if none), ``mean_interval`` (mean time
        between consecutive reversals, NaN if fewer than two) and
        ``reversal_times`` (list).
    """
    if not (executor is None or executor == "serial" or isinstance(executor, cf.Executor)):
        raise TypeError(f"`executor` must be a concurrent.futures.Executor, 'serial' or None, got {executor!r}")
    if max_workers is not None and (not isinstance(max_workers, int) or max_workers < 1):
        raise ValueError(f"`max_workers` must be a positive integer, got {max_workers!r}")
    if not (isinstance(progress, bool) or callable(progress)):
        raise TypeError("`progress` must be True, False or a callable(done, total, row)")
    run = _base_run(scene_or_model, params, y0, t_span, method, rtol, atol)
    specs = _expand(run, _grid_points(grid))
    columns = _columns(run)
    inputs = [_inputs(s) for s in specs]
    store = _Store(Path(out) if out is not None else None, columns, resume)

    rows: list = [None] * len(specs)
    todo = []
    for i, inp in enumerate(inputs):
        if inp["run_id"] in store.done:
            rows[i] = {**store.done[inp["run_id"]], **inp}
        else:
            todo.append(i)
    n_reused = len(specs) - len(todo)
    bar = _Progress(len(specs), n_reused, progress)

    def finish(i: int, outcome: dict) -> None:
        row = {**inputs[i], **outcome}
        rows[i] = row
        store.append(row)
        bar.update(row)

    try:
        if todo and (executor == "serial" or (executor is None and (len(todo) == 1 or max_workers == 1))):
            for i in todo:
                finish(i, run_one(specs[i].to_dict()))
        elif todo:
            own = executor is None
            pool = cf.ProcessPoolExecutor(max_workers=max_workers or os.cpu_count()) if own else executor
            futures = {}
            try:
                futures = {pool.submit(run_one, specs[i].to_dict()): i for i in todo}
                for fut in cf.as_completed(futures):
                    try:
                        outcome = fut.result()
                    except Exception as exc:  # the worker itself died
                        outcome = {"status": "error", "message": f"{type(exc).__name__}: {exc}", "nfev": 0,
                                   **_reversal_columns([])}
                    finish(futures[fut], outcome)
            finally:
                for fut in futures:
                    fut.cancel()
                if own:
                    pool.shutdown(wait=False, cancel_futures=True)
    except KeyboardInterrupt:
        bar.close()
        if progress is True:
            saved = f"; the {bar.done} finished runs are in {store.path}: run the same sweep again to resume" \
                if store.path is not None else ""
            print(f"sweep: interrupted after {bar.done}/{bar.total} runs{saved}", file=sys.stderr, flush=True)
        raise
    bar.close()
    return SweepTable(columns, rows, n_computed=len(todo), n_reused=n_reused)
