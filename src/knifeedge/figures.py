"""Every figure of the paper from one call: :func:`make_figures` (``knifeedge figures --out DIR``).

Writes one PNG per scene and an ``index.html`` and ``index.md`` that put
each figure beside the paper's caption, the model the scene used and why,
and the numbers that support or contradict the caption; the scenes of
:data:`ANIMATIONS` also get a GIF of the body (:func:`knifeedge.animate`)
beside their figure.  Scenes and animations run in parallel processes;
progress goes to stderr.
"""
from __future__ import annotations

import concurrent.futures as cf
import html
import os
import sys
import time
from pathlib import Path

from ._process import heap_frozen
from .scenes import SCENE_NAMES, get_scene
from .scenes.base import format_number

#: the tasks, heaviest first (CPU seconds, cold: knife_edge_rigid 4.6-5.3, the GIFs of numerical2, celt and
#: numerical 3.1, 2.7, 1.7, the scenes tinversion 2.1, numerical2 1.7, ...), so that the parallel run does not
#: end on a long task started last; a scene's GIF is a task of its own, ("animation", name)
_ORDER = (("scene", "predictability"), ("scene", "knife_edge_rigid"), ("scene", "celt_stability"), ("scene", "celt_chaos"),
          ("animation", "numerical2"), ("animation", "celt"), ("scene", "tinversion"),
          ("scene", "numerical2"), ("animation", "numerical"), ("scene", "celt"), ("scene", "knife_edge_vs_celt"),
          ("scene", "model_fidelity"), ("scene", "table_path"), ("scene", "ellipses"), ("scene", "celt_schoemer"),
          ("scene", "amplitudes"), ("scene", "numerical"), ("scene", "rolling_disk"))
#: scenes whose run is also animated, with the animation's settings (modest size and frame count; a frame costs
#: ~10 ms of CPU: numerical's 80 frames still put ~7 in each rocking period at its reversal, numerical2's and the
#: celt's ~3.5 and ~3 with 150 and 100 frames, fewer would not show the rocking there)
ANIMATIONS = {
    "numerical": {"frames": 80, "fps": 12.5, "size": (8.0, 4.5), "dpi": 80},
    "numerical2": {"frames": 150, "fps": 12.5, "size": (8.0, 4.5), "dpi": 80},
    "celt": {"frames": 100, "fps": 12.5, "size": (8.0, 4.5), "dpi": 80},
}


def render_scene(name: str, out_dir: str) -> dict:
    """Compute one scene and write its PNG; returns plain data (runs in a worker)."""
    t0 = time.perf_counter()
    scene = get_scene(name)
    try:
        result = scene()
        png = result.savefig(Path(out_dir) / f"{name}.png")
        return {"name": name, "ok": True, "png": png.name, "numbers": result.numbers, "claims": result.claims,
                "seconds": time.perf_counter() - t0}
    except Exception as exc:  # noqa: BLE001 - reported in the index, the other scenes go on
        return {"name": name, "ok": False, "error": f"{type(exc).__name__}: {exc}", "numbers": {}, "claims": [],
                "seconds": time.perf_counter() - t0}


def render_animation(name: str, out_dir: str) -> dict:
    """Animate one scene's run into ``NAME.gif``; returns plain data (runs in a worker)."""
    from .animation import animate

    t0 = time.perf_counter()
    scene = get_scene(name)
    try:
        info = animate(scene, Path(out_dir) / f"{name}.gif", title=f"scene {name}: {scene.title}", **ANIMATIONS[name])
        return {"name": name, "ok": True, "gif": info.path.name, "summary": _animation_caption(info),
                "seconds": time.perf_counter() - t0}
    except Exception as exc:  # noqa: BLE001 - reported in the index
        return {"name": name, "ok": False, "error": f"{type(exc).__name__}: {exc}", "seconds": time.perf_counter() - t0}


def _animation_caption(info) -> str:
    tps = info.time_per_second
    mag = f"tilt angles drawn x{info.magnification:g}" if info.magnification != 1 else "tilt angles true"
    return (f"{info.n_frames} frames at {info.fps:g} frames/s; 1 s of video covers {tps.min():.3g} time units "
            f"around the reversals and up to {tps.max():.3g} elsewhere; {mag}. Drawn by {info.drawn_by}.")


def _scene_needs(name: str) -> set:
    """What scene ``name`` needs compiled: ``(model, fidelity, pose, method)`` of each of its runs' models, and
    ``("lyapunov", model, fidelity)`` of each model whose Lyapunov exponents it computes."""
    scene = get_scene(name)
    return {(*u, scene.run.method) for u in scene.uses} | {("lyapunov", *u) for u in scene.lyapunov}


def _animation_needs(name: str) -> set:
    """The integrators an animation of scene ``name`` uses: its run's model with the pose."""
    if name not in ANIMATIONS:
        return set()
    run = get_scene(name).run
    return {(run.model, run.fidelity, True, run.method)}


def warm(model: str, fidelity: str, pose: bool, method: str) -> str:
    """Compile (or load from the cache) one model's integrator by a tiny run; returns a label."""
    from .models import load
    from .simulate import simulate

    try:
        m = load(model, fidelity=fidelity, pose=pose)
    except ValueError:
        return f"{model}/{fidelity}: not available"
    y0 = {n: 1e-3 for n in m.state_names}
    if m.spin_name is not None:
        y0[m.spin_name] = 0.1
    y0.update({n: v for n, v in m.default_state.items() if n in y0})
    # the model's own defaults: parameters of 1 describe no rigid body (the celt's inertia, say)
    simulate(m, y0, (0.0, 0.01), m.params(**m.default_params), method=method)
    return f"{model}/{fidelity}{'+pose' if pose else ''}/{method}"


def warm_lyapunov(model: str, fidelity: str) -> str:
    """Compile (or load from numba's cache) the Lyapunov loop and the model's Jacobian by a few steps; returns a
    label."""
    from .lyapunov import lyapunov
    from .models import load

    m = load(model, fidelity=fidelity)
    lyapunov(m, m.state(**m.default_state), m.params(**m.default_params), 0.02, k=1, h=0.01, tau=0.01)
    return f"Lyapunov loop for {model}/{fidelity}"


def warm_parts(model: str, fidelity: str, pose: bool, method: str, drawing: bool = False) -> bool:
    """Compile (or load from the cache) only the model's parts of an adaptive method's integrator, not the
    integrator they plug into, and with ``drawing`` the function that places its body (``body_points``, for
    the arrays an animation passes it: compiled for long runs, :data:`knifeedge.animation.DRAW_AS_PYTHON_UP_TO`;
    ``body_outlines`` is always called as Python); False if the method has no such parts (fixed step) or the
    model no such form."""
    from .integrators import kernel_module
    from .models import load

    try:
        m = load(model, fidelity=fidelity, pose=pose)
        module = kernel_module(m, method)
    except ValueError:
        return False
    if not hasattr(module, "parts"):
        return False
    module.parts()
    if drawing:
        from numba import types

        vector = types.float64[::1]
        f = getattr(m.module, "body_points", None)
        if hasattr(f, "compile"):
            f.compile((vector, vector))
    return True


def _warm_call(key: tuple) -> tuple:
    """The function and arguments that compile ``key`` (an integrator, or ``("lyapunov", model, fidelity)``)."""
    return (warm_lyapunov, *key[1:]) if key[0] == "lyapunov" else (warm, *key)


def _next_warm(warms: list, compiled: set, running: dict) -> tuple | None:
    """The next compilation to start, or None: the first integrator alone among the integrators (it compiles the
    driver they share, which the others then load from the cache: started before it is cached, each would
    compile it again); beside it the Lyapunov loops (they share nothing with the integrators); after it, the
    next in the order the tasks want them (one whose model parts are not being compiled, if any)."""
    if not warms:
        return None
    integrators = [w for w in warms if w[0] != "lyapunov"]
    first_running = any(kind == "warm" and what[0] != "lyapunov" for kind, what in running.values())
    if _integrator_compiled(compiled) or (not integrators and not first_running):
        busy = {what for kind, what in running.values() if kind == "parts"}  # not compiled twice at once
        return next((w for w in warms if w not in busy), warms[0])
    if not first_running:
        return integrators[0]
    return next((w for w in warms if w[0] == "lyapunov"), None)


def _integrator_compiled(compiled: set) -> bool:
    """Whether an integrator (and with it the driver they share) is compiled, among the keys ``compiled``."""
    return any(w[0] != "lyapunov" for w in compiled)


def _schedule(pool, workers: int, order: list, out: Path, report, progress, t0: float) -> None:
    """Run the scenes on ``pool``, compiling each integrator once and first.

    The first integrator compiles alone among the integrators (it also
    compiles the driver every kernel shares, which later processes then load
    from the cache: :func:`_next_warm`), while the other processes compile the
    Lyapunov loops with the models' ``jvp_into`` (they share nothing with the
    integrators), then the next models' parts of it (each model's own code,
    which does not need the shared integrator) and the functions that draw
    the animated bodies; after that at most
    ``workers`` tasks run at once, a scene as soon as all its integrators are
    compiled, otherwise the next compilation, in the order of the first task
    that needs it.  A scene that needs nothing compiled waits for the first
    compilation to end: started first, it would hold a process while the
    compilations that every other scene waits for could run.  Two scenes that
    call one generated function compiled (their ``compiles``) do not run at
    once: the second loads what the first compiled, instead of compiling it
    too in the other process.
    """
    tasks = [("scene", n) for n in order] + [("animation", n) for n in order if n in ANIMATIONS]
    tasks.sort(key=lambda t: _ORDER.index(t) if t in _ORDER else len(_ORDER))  # heaviest first
    needs = {t: (_scene_needs if t[0] == "scene" else _animation_needs)(t[1]) for t in tasks}
    # integrators in the order the tasks want them (the tasks' order puts the longest first, so that they
    # do not start last), then those more tasks need
    warms = sorted(set().union(*needs.values()),
                   key=lambda k: (min(i for i, t in enumerate(tasks) if k in needs[t]),
                                  -sum(k in v for v in needs.values())))
    drawn = set().union(*(needs[t] for t in tasks if t[0] == "animation"))  # their bodies are drawn too
    compiled: set = set()
    parted: set = set()  # integrators whose model parts were compiled, or are, while the first one compiles
    scenes = list(needs)
    calls = {t: set(get_scene(t[1]).compiles) if t[0] == "scene" else set() for t in tasks}
    running: dict = {}
    n_warm = len(warms)
    while scenes or running:
        while len(running) < workers:
            compiling = set().union(*(calls.get(t, set()) for t in running.values()))
            ready = [n for n in scenes if needs[n] <= compiled and (needs[n] or compiled or not n_warm)
                     and not calls[n] & compiling]
            if ready:
                scenes.remove(ready[0])
                task = render_scene if ready[0][0] == "scene" else render_animation
                running[pool.submit(task, ready[0][1], str(out))] = ready[0]
            elif k := _next_warm(warms, compiled, running):
                warms.remove(k)
                running[pool.submit(*_warm_call(k))] = ("warm", k)
            elif not _integrator_compiled(compiled) and any(w not in parted and w[0] != "lyapunov" for w in warms):
                k = next(w for w in warms if w not in parted and w[0] != "lyapunov")
                parted.add(k)
                running[pool.submit(warm_parts, *k, drawing=k in drawn)] = ("parts", k)
            else:
                break
        done, _ = cf.wait(list(running), return_when=cf.FIRST_COMPLETED)
        for fut in done:
            kind, what = running.pop(fut)
            if kind in ("scene", "animation"):
                report(kind, fut.result())
                continue
            if kind == "parts":  # errors show when the integrator itself is compiled
                fut.exception()
                continue
            try:
                label = fut.result()
            except Exception as exc:  # noqa: BLE001 - the scenes that need it will report the error
                label = f"{what}: {type(exc).__name__}: {exc}"
            compiled.add(what)
            if progress:
                print(f"figures: compiled [{len(compiled)}/{n_warm}] {label}; {time.perf_counter() - t0:.1f} s elapsed",
                      file=sys.stderr, flush=True)


def _preload() -> None:
    """Set up once, before the worker processes are forked (they inherit it), what each of them would set up
    on its own: matplotlib's pyplot and Agg modules (imported, this process's backend left as it is), and
    numba's registries of the CPU target (about 0.9 s of CPU per process).  Nothing where the workers are not
    forked (they would import it again)."""
    import multiprocessing

    if multiprocessing.get_start_method(allow_none=False) != "fork":
        return
    import matplotlib.backends.backend_agg  # noqa: F401
    import matplotlib.pyplot  # noqa: F401
    from numba.core.registry import cpu_target

    cpu_target.target_context.refresh()


def make_figures(out: str | Path, names=None, max_workers: int | None = None, progress: bool = True) -> list:
    """Compute the scenes ``names`` (default: all) and write PNGs and the index into ``out``.

    Returns the list of per-scene records (``name``, ``ok``, ``png``,
    ``numbers``, ``claims``, ``seconds`` or ``error``).
    """
    names = list(SCENE_NAMES if names is None else names)
    for n in names:
        get_scene(n)  # unknown names fail here, before any work
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    order = sorted(names, key=lambda n: _ORDER.index(("scene", n)) if ("scene", n) in _ORDER else len(_ORDER))
    t0 = time.perf_counter()
    records: dict = {}
    workers = max_workers or min(len(order), os.cpu_count() or 1)

    animations: dict = {}
    n_tasks = len(order) + sum(n in ANIMATIONS for n in order)

    def report(kind: str, rec: dict) -> None:
        (records if kind == "scene" else animations)[rec["name"]] = rec
        if progress:
            state = f"{rec['seconds']:.1f} s" if rec["ok"] else f"FAILED: {rec['error']}"
            what = rec["name"] if kind == "scene" else f"{rec['name']} (animation)"
            print(f"figures: [{len(records) + len(animations)}/{n_tasks}] {what} ({state}); "
                  f"{time.perf_counter() - t0:.1f} s elapsed", file=sys.stderr, flush=True)

    if progress:
        print(f"figures: {len(order)} scenes on {workers} process(es) -> {out}/", file=sys.stderr, flush=True)
    if workers <= 1:
        for n in order:
            report("scene", render_scene(n, str(out)))
            if n in ANIMATIONS:
                report("animation", render_animation(n, str(out)))
    else:
        _preload()
        # the forked workers' collector passes leave out what they inherit (numba, SciPy, matplotlib: ~10^5 objects)
        with heap_frozen(), cf.ProcessPoolExecutor(max_workers=workers) as pool:
            _schedule(pool, workers, order, out, report, progress, t0)
    recs = [records[n] for n in names]
    for rec in recs:
        if rec["name"] in animations:
            rec["animation"] = animations[rec["name"]]
    (out / "index.md").write_text(index_markdown(recs))
    (out / "index.html").write_text(index_html(recs))
    if progress:
        print(f"figures: done in {time.perf_counter() - t0:.1f} s; open {out / 'index.html'}", file=sys.stderr)
    return recs


def _verdict_mark(verdict: str) -> str:
    return {"supports": "supports", "contradicts": "CONTRADICTS", "n/a": "finding"}[verdict]


def _md(text) -> str:
    return str(text).replace("|", "\\|")


def index_markdown(records: list) -> str:
    """The index as Markdown."""
    lines = ["# knifeedge: the figures of the paper", "",
             "Jagla & Rojo, *The chiral knife edge* (arXiv:2309.06154). Each figure is recomputed by a scene "
             "(`knifeedge scene NAME`); the errata are in docs/errata.md, the models in docs/models.md.", ""]
    for rec in records:
        scene = get_scene(rec["name"])
        lines += [f"## {rec['name']}: {scene.title}", ""]
        if rec["ok"]:
            lines += [f"![{rec['name']}]({rec['png']})", ""]
        else:
            lines += [f"**This scene failed:** {rec['error']}", ""]
        anim = rec.get("animation")
        if anim:
            lines += ([f"![{rec['name']}, animated]({anim['gif']})", "", f"*Animation.* {anim['summary']} "
                       f"(made in {anim['seconds']:.1f} s)", ""] if anim["ok"]
                      else [f"**The animation failed:** {anim['error']}", ""])
        lines += [f"**Paper's caption.** {scene.caption}", "",
                  f"**Model.** {scene.describe_model()}  ", f"**Why this model.** {scene.why}", ""]
        if rec["claims"]:
            lines += ["| the paper says | verdict | evidence |", "|---|---|---|"]
            lines += [f"| {_md(c)} | {_verdict_mark(v)} | {_md(e)} |" for c, v, e in rec["claims"]]
            lines.append("")
        if rec["numbers"]:
            lines += ["| number | value |", "|---|---|"]
            lines += [f"| {_md(k)} | {_md(format_number(v))} |" for k, v in rec["numbers"].items()]
            lines.append("")
        lines += [f"*computed in {rec['seconds']:.1f} s*", ""]
    return "\n".join(lines)


def index_html(records: list) -> str:
    """The index as a self-contained HTML page (figures beside captions)."""
    e = html.escape
    parts = ["<!doctype html><html><head><meta charset='utf-8'><title>knifeedge figures</title><style>",
             "body{font-family:sans-serif;max-width:1500px;margin:auto;padding:1em}"
             ".scene{display:flex;gap:1.5em;border-top:1px solid #ccc;padding:1em 0}"
             ".fig{flex:0 0 55%}.fig img{max-width:100%}.text{flex:1;font-size:14px}"
             "table{border-collapse:collapse;font-size:12px}td,th{border:1px solid #ddd;padding:2px 6px;vertical-align:top}"
             ".anim{font-size:12px;color:#444}.supports{color:#060}.contradicts{color:#b00;font-weight:bold}.na{color:#555}",
             "</style></head><body><h1>knifeedge: the figures of the paper</h1>",
             "<p>Jagla &amp; Rojo, <i>The chiral knife edge</i> (arXiv:2309.06154). Each figure is recomputed by a scene "
             "(<code>knifeedge scene NAME</code>); errata in docs/errata.md, models in docs/models.md.</p>"]
    for rec in records:
        scene = get_scene(rec["name"])
        fig = (f"<img src='{e(rec['png'])}' alt='{e(rec['name'])}'>" if rec["ok"]
               else f"<p class='contradicts'>This scene failed: {e(rec['error'])}</p>")
        anim = rec.get("animation")
        if anim:
            fig += (f"<img src='{e(anim['gif'])}' alt='{e(rec['name'])}, animated'>"
                    f"<p class='anim'>{e(anim['summary'])} <i>(made in {anim['seconds']:.1f} s)</i></p>"
                    if anim["ok"] else f"<p class='contradicts'>The animation failed: {e(anim['error'])}</p>")
        claims = "".join(
            f"<tr><td>{e(c)}</td><td class='{'na' if v == 'n/a' else v}'>{e(_verdict_mark(v))}</td><td>{e(ev)}</td></tr>"
            for c, v, ev in rec["claims"])
        numbers = "".join(f"<tr><td>{e(k)}</td><td>{e(format_number(v))}</td></tr>" for k, v in rec["numbers"].items())
        parts.append(
            f"<div class='scene' id='{e(rec['name'])}'><div class='fig'>{fig}</div><div class='text'>"
            f"<h2>{e(rec['name'])}: {e(scene.title)}</h2>"
            f"<p><b>Paper's caption.</b> {e(scene.caption)}</p>"
            f"<p><b>Model.</b> {e(scene.describe_model())}<br><b>Why this model.</b> {e(scene.why)}</p>"
            + (f"<table><tr><th>the paper says</th><th>verdict</th><th>evidence</th></tr>{claims}</table>" if claims else "")
            + (f"<p></p><table><tr><th>number</th><th>value</th></tr>{numbers}</table>" if numbers else "")
            + f"<p><i>computed in {rec['seconds']:.1f} s</i></p></div></div>")
    parts.append("</body></html>")
    return "\n".join(parts)
