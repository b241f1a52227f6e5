"""``knifeedge figures`` compiles what the scenes need once: the first integrator alone among the integrators with
the next models' parts beside it, the Lyapunov loop beside the first integrator, and no integrator for a scene that
integrates nothing (issue 25 item 4: ``knifeedge figures`` cold)."""
import concurrent.futures as cf
import threading
import time

from knifeedge import figures
from knifeedge.scenes import get_scene


def _scheduled(monkeypatch, tmp_path, order, seconds=None, scene_seconds=None):
    """Run ``figures._schedule`` on threads with every compilation and scene replaced by a logged stub
    (``seconds(key)``: how long the compilation ``key`` takes; default the first 0.5 s, the others 0.01 s;
    ``scene_seconds``: how long each scene and animation takes, its end logged too; default no time, no end)."""
    log, lock = [], threading.Lock()

    def record(*event):
        with lock:
            log.append((time.perf_counter(), *event))

    def warm(*key):
        record("warm start", key)
        if seconds is not None:
            time.sleep(seconds(key))
        else:
            time.sleep(0.5 if not any(e[1] == "warm end" for e in log) else 0.01)  # the first: long against the parts
        record("warm end", key)
        return "/".join(map(str, key))

    def warm_lyapunov(model, fidelity):
        return warm("lyapunov", model, fidelity)

    def scene(kind):
        def task(name, out):
            record(kind, name)
            if scene_seconds is not None:
                time.sleep(scene_seconds)
                record(f"{kind} end", name)
            return {"name": name, "ok": True, "seconds": 0.0}
        return task

    monkeypatch.setattr(figures, "warm", warm)
    monkeypatch.setattr(figures, "warm_lyapunov", warm_lyapunov)
    monkeypatch.setattr(figures, "warm_parts", lambda *key, drawing=False: record("parts", key, drawing) or True)
    monkeypatch.setattr(figures, "render_scene", scene("scene"))
    monkeypatch.setattr(figures, "render_animation", scene("animation"))
    with cf.ThreadPoolExecutor(max_workers=2) as pool:
        figures._schedule(pool, 2, order, tmp_path, lambda kind, rec: None, False, time.perf_counter())
    return log


def test_the_lyapunov_loop_compiles_once_beside_the_first_integrator(monkeypatch, tmp_path):
    log = _scheduled(monkeypatch, tmp_path, ["predictability", "celt_chaos", "numerical2"])
    warmed = [e[2] for e in log if e[1] == "warm start"]
    assert len(warmed) == len(set(warmed))  # each once
    loops = [k for k in warmed if k[0] == "lyapunov"]
    assert sorted(loops) == [("lyapunov", "celt", "full"), ("lyapunov", "two_mode", "reduced")]
    assert warmed[0][0] != "lyapunov"  # the first integrator compiles first ...
    first_end = min(e[0] for e in log if e[1] == "warm end")
    loop_starts = [e[0] for e in log if e[1] == "warm start" and e[2][0] == "lyapunov"]
    assert min(loop_starts) < first_end  # ... and a loop beside it, not after it
    for name in ("predictability", "celt_chaos"):
        start = min(e[0] for e in log if e[1] == "scene" and e[2] == name)
        for key in figures._scene_needs(name):
            assert max(e[0] for e in log if e[1] == "warm end" and e[2] == key) < start, (name, key)


def test_a_scene_that_integrates_nothing_compiles_no_integrator(monkeypatch, tmp_path):
    assert figures._scene_needs("bicycle_stability") == set()
    log = _scheduled(monkeypatch, tmp_path, ["bicycle_stability"])
    assert [e[1:] for e in log] == [("scene", "bicycle_stability")]
    # celt_stability integrates nothing either: it waits for the celt's Jacobian-vector product, which the
    # Lyapunov loop's warm-up compiles for celt_chaos too, and for no integrator
    assert figures._scene_needs("celt_stability") == {("lyapunov", "celt", "full")}
    log = _scheduled(monkeypatch, tmp_path, ["celt_stability", "celt_chaos"])
    warmed = [e[2] for e in log if e[1] == "warm start"]
    assert warmed.count(("lyapunov", "celt", "full")) == 1
    start = min(e[0] for e in log if e[1] == "scene" and e[2] == "celt_stability")
    assert max(e[0] for e in log if e[1] == "warm end" and e[2] == ("lyapunov", "celt", "full")) < start


def test_figures_compile_other_models_parts_while_the_first_integrator_compiles(monkeypatch, tmp_path):
    """The first integrator compiles alone among the integrators, the other worker compiles the next models' own
    parts meanwhile (never the first's; with the drawing functions of the animated ones), each integrator is
    compiled once, and a scene starts only when every integrator it uses is compiled."""
    order = ["numerical2", "knife_edge_rigid", "model_fidelity", "celt", "numerical"]
    log = _scheduled(monkeypatch, tmp_path, order)
    warmed = [e[2] for e in log if e[1] == "warm start"]
    assert len(warmed) == len(set(warmed)) >= 4
    first_end = min(e[0] for e in log if e[1] == "warm end")
    parts = [e for e in log if e[1] == "parts"]
    assert parts and all(e[0] < first_end and e[2] != warmed[0] for e in parts)
    # the bodies of the animated scenes' models are drawn: their drawing functions are compiled with the parts
    drawn = set().union(*(figures._animation_needs(n) for n in order))
    assert all(e[3] == (e[2] in drawn) for e in parts) and any(e[3] for e in parts)
    assert not [e for e in log if e[1] == "warm start" and e[0] < first_end and e[2] != warmed[0]]
    tasks = [("scene", n, figures._scene_needs(n)) for n in order]
    tasks += [("animation", n, figures._animation_needs(n)) for n in order if n in figures.ANIMATIONS]
    for kind, n, needs in tasks:
        start = min(e[0] for e in log if e[1] == kind and e[2] == n)
        for key in needs:
            assert max(e[0] for e in log if e[1] == "warm end" and e[2] == key) < start, (kind, n, key)


def test_a_scene_that_needs_nothing_compiled_leaves_the_first_processes_to_the_compilations(monkeypatch, tmp_path):
    """Started first, ``celt_stability`` and ``bicycle_stability`` held both processes while the first integrator
    and the Lyapunov loop, which every other scene waits for, had to wait for them."""
    log = _scheduled(monkeypatch, tmp_path, ["predictability", "celt_stability", "bicycle_stability", "numerical2"])
    starts = [e for e in log if e[1] in ("warm start", "scene", "parts")]
    assert [e[1] for e in starts[:2]] == ["warm start", "warm start"]  # the first integrator and the loop
    assert {e[2][0] == "lyapunov" for e in starts[:2]} == {True, False}
    first_end = min(e[0] for e in log if e[1] == "warm end")
    for name in ("celt_stability", "bicycle_stability"):
        assert min(e[0] for e in log if e[1] == "scene" and e[2] == name) > first_end


def test_the_workers_inherit_pyplot_and_numbas_registries_and_the_callers_backend_is_left_alone(monkeypatch):
    """Each forked worker imported matplotlib's pyplot and loaded numba's CPU registries on its own (~0.9 s of CPU
    each); ``_preload`` does it once in the parent, without choosing the caller's matplotlib backend, and not at
    all where the workers are not forked (they would do it again)."""
    import multiprocessing
    import sys

    import matplotlib
    from numba.core.registry import cpu_target

    calls = []
    monkeypatch.setattr(cpu_target.target_context, "refresh", lambda: calls.append("refresh"))
    monkeypatch.setattr(matplotlib, "use", lambda *a, **k: calls.append("use"))
    monkeypatch.setattr(multiprocessing, "get_start_method", lambda allow_none=False: "spawn")
    figures._preload()
    assert calls == []
    monkeypatch.setattr(multiprocessing, "get_start_method", lambda allow_none=False: "fork")
    figures._preload()
    assert calls == ["refresh"] and "matplotlib.pyplot" in sys.modules


def test_no_integrator_compiles_beside_the_first_one_when_a_lyapunov_loop_ends_first(monkeypatch, tmp_path):
    """The integrators share one driver, which the first one compiles: an integrator started before it is
    cached compiles it again (7-8 s of CPU).  With the Lyapunov loops ending before the first integrator,
    the other worker compiles the next loop and the models' parts, and no integrator."""
    log = _scheduled(monkeypatch, tmp_path, ["predictability", "knife_edge_rigid", "celt_stability", "celt_chaos"],
                     seconds=lambda key: 0.05 if key[0] == "lyapunov" else (0.6 if key[0] == "two_mode" and
                                                                              key[1] == "reduced" else 0.01))
    warmed = [e for e in log if e[1] == "warm start"]
    first = next(e for e in warmed if e[2][0] != "lyapunov")
    first_end = next(e[0] for e in log if e[1] == "warm end" and e[2] == first[2])
    assert [e[2] for e in warmed if e[0] < first_end and e[2][0] != "lyapunov"] == [first[2]]
    loops = [e for e in warmed if e[2][0] == "lyapunov"]
    assert len(loops) == 2 and all(e[0] < first_end for e in loops)  # both loops beside the first integrator
    assert any(e[1] == "parts" and e[0] < first_end for e in log)  # then the next models' parts


def test_two_scenes_that_compile_one_function_do_not_run_at_once(monkeypatch, tmp_path):
    """``celt`` and ``celt_schoemer`` both call the celt's ``energy`` and ``power_dissipated`` compiled (their
    energy balance over thousands of samples): run at once, both processes compiled them (0.3-0.5 s of CPU);
    one after the other, the second loads them from numba's cache.  The other worker runs other tasks meanwhile."""
    assert set(get_scene("celt").compiles) & set(get_scene("celt_schoemer").compiles)
    log = _scheduled(monkeypatch, tmp_path, ["celt", "celt_schoemer", "knife_edge_vs_celt", "ellipses"],
                     scene_seconds=0.1)
    span = {n: (next(e[0] for e in log if e[1] == "scene" and e[2] == n),
                next(e[0] for e in log if e[1] == "scene end" and e[2] == n)) for n in ("celt", "celt_schoemer")}
    first, second = sorted(span.values())
    assert second[0] >= first[1]
    assert any(first[0] < e[0] < first[1] for e in log if e[1] in ("scene", "warm start"))  # the other worker works
