"""A newcomer's first run: ``knifeedge demo`` and ``knifeedge figures`` with every cache empty, then warm.

``python -m benchmarks.first_run [--repeats 3] [--skip-figures] [--test-command] [--out benchmarks/results]``

Each cold run gets fresh, empty folders for the compiled kernels
(``KNIFEEDGE_CACHE_DIR``) and for numba's cache of the generated modules
(``NUMBA_CACHE_DIR``), as after a fresh install; a cold ``demo`` is followed by
a pause for the kernel it left compiling in the background (the command
line's default for single runs), so that the next cold run is not slowed by
it.  The warm runs reuse the caches of the last cold run.  Wall and CPU time
(of the command and its children) are medians of the repeats; the load
average before each run is recorded, as the machine may be shared.  Writes
``first_run.json``.

``--per-scene`` also times each scene alone (``knifeedge figures --only NAME
--workers 1``, its animation included), cold but for the DOP853 integrator
that every scene shares (compiled once per machine, by ``knifeedge demo``
into a cache that is restored at the same path before each scene: numba's
cache is keyed by the kernel file's path), then warm.

``--compiles`` runs ``knifeedge figures`` once in one process with every
cache empty and numba's compile events recorded: the CPU seconds of each
scene and animation, how much of it was numba compiling, and the functions
that took longest to compile (the kernels' own LLVM parts are not numba
compiles: they count in the scene's time only).

``--timeline`` runs ``knifeedge figures`` cold as the command does (two worker
processes) with each task's process, start, end and CPU recorded, and every
numba compile with the process and task it ran in: which core waits for what,
and what is compiled twice.

``--as-user COMMIT [COMMIT ...]`` times ``knifeedge figures`` as a user's first
run of each commit: a ``git archive`` of it, ``pip install --no-compile`` into
a fresh virtual environment (as the README's demo command), copied afresh for
every run with no bytecode and ``PYTHONDONTWRITEBYTECODE`` unset (the run
writes it, as on a new machine), every cache empty; the commits interleaved,
``--repeats`` times; each cold run is followed by a warm one with its caches.
With ``--byte-compiled`` the install is pip's default (bytecode written at
install, as the README's test command), kept in the copies.  With
``--shared-precompiled`` the cold run's caches start with the package's own
compiled code that serves every model (the adaptive integrators, the event
helpers, the Lyapunov loops: what is not named after a model), taken from a
cold run made first: what shipping that code with the package would give.

``--test-command`` also times the README's test command (the set-up line that
ends in ``pytest``: a virtual environment, the install, the tests) from a fresh
clone of this repository's committed ``HEAD``, with empty caches, ``--repeats``
times (a few minutes each).
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def _run(args: list, env: dict, cwd: Path) -> dict:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    load = os.getloadavg()[0]
    t = time.perf_counter()
    out = subprocess.run(args, env=env, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if out.returncode != 0:
        raise RuntimeError(f"{' '.join(args)} failed: {out.stderr[-2000:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"wall_s": round(wall, 2), "cpu_s": round(cpu, 2), "load_before": round(load, 2)}


def _wait_for_compiles(cache: Path, limit: float = 300.0) -> None:
    """Wait until no background compile of this cache folder is running (its lock files are gone)."""
    end = time.monotonic() + limit
    while any((cache / "kernels").glob("*.compiling")) and time.monotonic() < end:
        time.sleep(0.5)


def _cold_env(caches: Path) -> dict:
    """This environment with empty cache folders under ``caches`` (kernels, numba) and the default compile mode."""
    env = dict(os.environ, KNIFEEDGE_CACHE_DIR=str(caches / "kernels-cache"), NUMBA_CACHE_DIR=str(caches / "numba-cache"))
    env.pop("KNIFEEDGE_COMPILE", None)
    return env


def measure(command: list, repeats: int, work: Path) -> dict:
    exe = str(Path(sys.executable).parent / "knifeedge")
    cold, warm = [], []
    env = None
    for k in range(repeats):
        caches = Path(tempfile.mkdtemp(prefix="first-run-", dir=work))
        env = _cold_env(caches)
        cold.append(_run([exe, *command], env, work))
        _wait_for_compiles(caches / "kernels-cache")
        print(f"  cold {k + 1}/{repeats}: {cold[-1]}", flush=True)
    for k in range(repeats):
        warm.append(_run([exe, *command], env, work))
        print(f"  warm {k + 1}/{repeats}: {warm[-1]}", flush=True)
    med = lambda rows, key: round(statistics.median(r[key] for r in rows), 2)  # noqa: E731
    return {"command": "knifeedge " + " ".join(command), "cold": cold, "warm": warm,
            "cold_wall_median_s": med(cold, "wall_s"), "cold_cpu_median_s": med(cold, "cpu_s"),
            "warm_wall_median_s": med(warm, "wall_s"), "warm_cpu_median_s": med(warm, "cpu_s"),
            "cold_over_warm_wall": round(med(cold, "wall_s") / med(warm, "wall_s"), 2)}


def measure_per_scene(work: Path) -> dict:
    """Each scene alone, cold but for the shared DOP853 integrator, then warm (one run each)."""
    import shutil

    from knifeedge.scenes import SCENE_NAMES

    exe = str(Path(sys.executable).parent / "knifeedge")
    base, saved = work / "scene-cache", work / "scene-cache-with-driver"
    env = dict(_cold_env(base), KNIFEEDGE_COMPILE="wait")
    _run([exe, "demo", "--out", str(work / "demo.png")], env, work)
    shutil.copytree(base, saved, symlinks=True)
    rows = {}
    for name in SCENE_NAMES:
        shutil.rmtree(base)
        shutil.copytree(saved, base, symlinks=True)  # copytree keeps the files' times: numba's cache holds
        command = [exe, "figures", "--only", name, "--workers", "1", "--out", str(work / "scene-out")]
        rows[name] = {"cold": _run(command, env, work), "warm": _run(command, env, work)}
        print(f"  {name}: {rows[name]}", flush=True)
    return rows


def compile_profile() -> dict:
    """``make_figures`` in this process, one task after the other, with numba's top-level compile events recorded
    per task (run it with empty caches: :func:`measure_compiles`)."""
    import collections

    from numba.core import event

    from knifeedge import figures

    task, depth, compiles, cpu = ["import"], [0], collections.Counter(), collections.Counter()
    per_task = collections.Counter()

    class Listener(event.Listener):
        def on_start(self, ev):
            depth[0] += 1
            if depth[0] == 1:
                self.t0 = time.process_time()

        def on_end(self, ev):
            if depth[0] == 1:
                f = getattr(ev.data.get("dispatcher"), "py_func", None)
                name = f"{f.__module__}.{f.__qualname__}" if f else "?"
                compiles[name] += time.process_time() - self.t0
                per_task[task[0]] += time.process_time() - self.t0
            depth[0] -= 1

    def timed(kind, render):
        def run(name, out):
            task[0], t = f"{kind} {name}", time.process_time()
            try:
                return render(name, out)
            finally:
                cpu[task[0]] += time.process_time() - t
        return run

    event.register("numba:compile", Listener())
    figures.render_scene = timed("scene", figures.render_scene)
    figures.render_animation = timed("animation", figures.render_animation)
    with tempfile.TemporaryDirectory() as out:
        figures.make_figures(out, max_workers=1, progress=False)
    return {"tasks": {k: {"cpu_s": round(v, 2), "numba_compile_s": round(per_task[k], 2)} for k, v in cpu.most_common()},
            "compiles": {k: round(v, 2) for k, v in compiles.most_common(25)}}


def measure_compiles(work: Path) -> dict:
    env = _cold_env(Path(tempfile.mkdtemp(prefix="compiles-", dir=work)))
    code = "import json; from benchmarks.first_run import compile_profile; print(json.dumps(compile_profile()))"
    out = subprocess.run([sys.executable, "-c", code], env=dict(env, KNIFEEDGE_COMPILE="wait"), cwd=ROOT,
                         capture_output=True, text=True, check=True)
    result = json.loads(out.stdout.strip().splitlines()[-1])
    for k, v in result["tasks"].items():
        print(f"  {v['cpu_s']:6.2f} s CPU, {v['numba_compile_s']:5.2f} s of it numba compiling: {k}", flush=True)
    return result


def timeline_profile() -> dict:
    """``make_figures`` as ``knifeedge figures`` runs it, each task (scene, animation, warm-up) and each numba
    compile recorded with its process (run it with empty caches: :func:`measure_timeline`)."""
    import functools

    from numba.core import event

    from knifeedge import figures

    t0, log = time.perf_counter(), tempfile.mkstemp(suffix=".jsonl")[1]
    task = ["parent"]

    def write(row: dict) -> None:
        with open(log, "a") as fh:
            fh.write(json.dumps({"pid": os.getpid(), **row}) + "\n")

    class Listener(event.Listener):
        depth = 0

        def on_start(self, ev):
            Listener.depth += 1
            if Listener.depth == 1:
                self.t = time.process_time()

        def on_end(self, ev):
            if Listener.depth == 1:
                f = getattr(ev.data.get("dispatcher"), "py_func", None)
                write({"compile": f"{f.__module__}.{f.__qualname__}" if f else "?", "task": task[0],
                       "cpu": time.process_time() - self.t})
            Listener.depth -= 1

    def timed(f, kind):
        @functools.wraps(f)
        def run(*args, **kwargs):
            task[0] = " ".join([kind, *(str(a) for a in args if not str(a).startswith("/"))])
            start, cpu = time.perf_counter() - t0, time.process_time()
            try:
                return f(*args, **kwargs)
            finally:
                write({"task": task[0], "start": start, "end": time.perf_counter() - t0,
                       "cpu": time.process_time() - cpu})
        return run

    event.register("numba:compile", Listener())
    for name in ("render_scene", "render_animation", "warm", "warm_lyapunov", "warm_parts"):
        setattr(figures, name, timed(getattr(figures, name), name))  # the workers are forked: they inherit these
    with tempfile.TemporaryDirectory() as out:
        figures.make_figures(out, progress=False)
    rows = [json.loads(line) for line in Path(log).read_text().splitlines()]
    Path(log).unlink()
    pids = sorted({r["pid"] for r in rows if "start" in r})
    tasks = [dict(r, process=pids.index(r["pid"])) for r in rows if "start" in r]
    compiles = [dict(r, process=pids.index(r["pid"]) if r["pid"] in pids else "parent") for r in rows
                if "compile" in r]
    return {"wall_s": time.perf_counter() - t0, "tasks": sorted(tasks, key=lambda r: r["start"]),
            "compiles": compiles}


def measure_timeline(work: Path) -> dict:
    env = _cold_env(Path(tempfile.mkdtemp(prefix="timeline-", dir=work)))
    code = "import json; from benchmarks.first_run import timeline_profile; print(json.dumps(timeline_profile()))"
    out = subprocess.run([sys.executable, "-c", code], env=env, cwd=ROOT, capture_output=True, text=True, check=True)
    result = json.loads(out.stdout.strip().splitlines()[-1])
    for r in result["tasks"]:
        print(f"  process {r['process']} {r['start']:6.1f}-{r['end']:6.1f} s, {r['cpu']:5.2f} s CPU: {r['task']}")
    for r in sorted(result["compiles"], key=lambda r: -r["cpu"]):
        print(f"  compile {r['cpu']:5.2f} s CPU in process {r['process']} ({r['task']}): {r['compile']}")
    return result


ROOT = Path(__file__).resolve().parents[1]


def _user_venv(commit: str, work: Path, byte_compiled: bool) -> Path:
    """A virtual environment with ``commit`` installed as the README's demo command says (``pip install
    --no-compile``), or with pip's default (``byte_compiled``: bytecode written at install)."""
    import shutil

    src, venv = work / f"src-{commit}", work / f"venv-{commit}"
    src.mkdir()
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", commit], check=True, capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", str(src)], input=archive, check=True)
    subprocess.run([getattr(sys, "_base_executable", sys.executable), "-m", "venv", str(venv)], check=True)
    flags = [] if byte_compiled else ["--no-compile"]
    subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "-q", *flags, str(src)], check=True)
    shutil.rmtree(src)
    return venv


def _shared_caches(caches: Path, into: Path) -> None:
    """Copy from the cache folders of a cold run (``_cold_env(caches)``) what serves every model into ``into``:
    the kernels named after a method alone (the adaptive integrators, ``erk-<method>-<stamp>``, not
    ``erk-<method>-<model>-...``) and numba's cache of the package's own functions (not ``generated_*``)."""
    import re
    import shutil

    kernels = into / "kernels-cache" / "kernels"
    kernels.mkdir(parents=True, mode=0o700)
    (into / "kernels-cache").chmod(0o700)
    for f in (caches / "kernels-cache" / "kernels").iterdir():
        if re.fullmatch(r"erk-[A-Za-z0-9_]+-[0-9a-f]{20}\.py\d+(\.\d+\.nbc|\.nbi)", f.name):
            shutil.copy2(f, kernels / f.name)
    for folder in (caches / "numba-cache").iterdir():
        if not folder.name.startswith("generated_"):
            shutil.copytree(folder, into / "numba-cache" / folder.name)


def measure_as_user(commits: list, repeats: int, work: Path, byte_compiled: bool = False,
                    shared_precompiled: bool = False) -> dict:
    """``knifeedge figures`` as a user's first run of each of ``commits`` (interleaved), then warm."""
    import shutil

    templates = {c: _user_venv(c, work, byte_compiled) for c in commits}

    def figures(c: str, run: Path, seed: Path | None = None) -> dict:
        venv = run / "venv"
        shutil.copytree(templates[c], venv, symlinks=True)
        if not byte_compiled:
            for cache in list(venv.rglob("__pycache__")):
                shutil.rmtree(cache)
        if seed is not None:
            _shared_caches(seed, run)
        env = {**_cold_env(run), "XDG_CACHE_HOME": str(run / "xdg")}
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        command = [str(venv / "bin" / "python"), "-m", "knifeedge", "figures", "--out", str(run / "figs")]
        return {"cold": _run(command, env, run), "warm": _run(command, env, run)}

    seeds = {}
    if shared_precompiled:
        for c in commits:
            seeds[c] = Path(tempfile.mkdtemp(prefix=f"seed-{c}-", dir=work))
            figures(c, seeds[c])
    rows = {c: [] for c in commits}
    for k in range(repeats):
        for c in commits:
            run = Path(tempfile.mkdtemp(prefix=f"user-{c}-", dir=work))
            rows[c].append(figures(c, run, seeds.get(c)))
            print(f"  {c} {k + 1}/{repeats}: {rows[c][-1]}", flush=True)
            shutil.rmtree(run)
    return rows


def readme_test_command() -> str:
    """The README's set-up command that installs the package and runs the tests."""
    for line in (ROOT / "README.md").read_text().splitlines():
        if line.startswith("    python3 -m venv") and line.rstrip().endswith("pytest"):
            return line.strip()
    raise RuntimeError("README.md has no set-up command ending in pytest")


def measure_test_command(repeats: int, work: Path) -> dict:
    command = readme_test_command()
    rows = []
    for k in range(repeats):
        clone = Path(tempfile.mkdtemp(prefix="clone-", dir=work))
        subprocess.run(["git", "clone", "-q", str(ROOT), str(clone / "knifeedge")], check=True)
        if (ROOT.parent / "shared").exists():
            (clone / "shared").symlink_to(ROOT.parent / "shared")
        env = _cold_env(clone)
        env.pop("VIRTUAL_ENV", None)
        rows.append(_run(["bash", "-c", command], env, clone / "knifeedge"))
        print(f"  cold {k + 1}/{repeats}: {rows[-1]}", flush=True)
    return {"command": command, "cold": rows,
            "cold_wall_median_s": round(statistics.median(r["wall_s"] for r in rows), 2),
            "cold_cpu_median_s": round(statistics.median(r["cpu_s"] for r in rows), 2)}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.first_run", description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=Path(__file__).resolve().parent / "results")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--skip-figures", action="store_true")
    ap.add_argument("--per-scene", action="store_true",
                    help="also time each scene alone, cold but for the shared DOP853 integrator")
    ap.add_argument("--compiles", action="store_true",
                    help="also profile a cold `knifeedge figures` in one process: CPU and numba compiles per scene")
    ap.add_argument("--timeline", action="store_true",
                    help="also run a cold `knifeedge figures` with each task's process, times and CPU recorded")
    ap.add_argument("--as-user", nargs="+", metavar="COMMIT",
                    help="only time `knifeedge figures` as a user's first run of each commit (interleaved), then warm")
    ap.add_argument("--byte-compiled", action="store_true",
                    help="with --as-user: install with pip's default (bytecode written at install)")
    ap.add_argument("--shared-precompiled", action="store_true",
                    help="with --as-user: start each cold run with the compiled code that serves every model")
    ap.add_argument("--test-command", action="store_true",
                    help="also time the README's test command from a fresh clone (minutes per repeat)")
    args = ap.parse_args(argv)
    results = {"cpus": os.cpu_count()}
    with tempfile.TemporaryDirectory(prefix="knifeedge-first-run-") as tmp:
        work = Path(tmp)
        if args.as_user:
            print("knifeedge figures as a user's first run", flush=True)
            results = {"cpus": os.cpu_count(), "as_user": measure_as_user(args.as_user, args.repeats, work,
                                                                          args.byte_compiled, args.shared_precompiled)}
            print(json.dumps(results))
            return 0
        print("knifeedge demo", flush=True)
        results["demo"] = measure(["demo", "--out", str(work / "demo.png")], args.repeats, work)
        if not args.skip_figures:
            print("knifeedge figures", flush=True)
            results["figures"] = measure(["figures", "--out", str(work / "figures")], args.repeats, work)
        if args.per_scene:
            print("each scene alone", flush=True)
            results["per_scene"] = measure_per_scene(work)
        if args.compiles:
            print("knifeedge figures in one process, compiles recorded", flush=True)
            results["compiles"] = measure_compiles(work)
        if args.timeline:
            print("knifeedge figures cold, task by task", flush=True)
            results["timeline"] = measure_timeline(work)
        if args.test_command:
            print("the README's test command", flush=True)
            results["test_command"] = measure_test_command(args.repeats, work)
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "first_run.json"
    earlier = json.loads(path.read_text()) if path.is_file() else {}
    # a partial run (--skip-figures) keeps the earlier figures of what it did not measure
    path.write_text(json.dumps({**earlier, **results}, indent=1) + "\n")
    for key in ("demo", "figures"):
        if key in results:
            r = results[key]
            print(f"{r['command'].split(' --out')[0]}: cold {r['cold_wall_median_s']} s wall "
                  f"({r['cold_cpu_median_s']} s CPU), warm {r['warm_wall_median_s']} s wall "
                  f"({r['warm_cpu_median_s']} s CPU): {r['cold_over_warm_wall']}x")
    if "test_command" in results:
        r = results["test_command"]
        print(f"README test command: cold {r['cold_wall_median_s']} s wall ({r['cold_cpu_median_s']} s CPU)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
