"""``knifeedge figures`` compiles what the scenes need once: the Lyapunov loop beside the first integrator, and no
integrator for a scene that integrates nothing (issue 25 item 4: ``knifeedge figures`` cold)."""
import concurrent.futures as cf
import threading
import time

from knifeedge import figures


def _scheduled(monkeypatch, tmp_path, order):
    """Run ``figures._schedule`` on threads with every compilation and scene replaced by a logged stub."""
    log, lock = [], threading.Lock()

    def record(*event):
        with lock:
            log.append((time.perf_counter(), *event))

    def warm(*key):
        record("warm start", key)
        time.sleep(0.3 if not any(e[1] == "warm end" for e in log) else 0.01)  # the first: long
        record("warm end", key)
        return "/".join(map(str, key))

    def warm_lyapunov(model, fidelity):
        return warm("lyapunov", model, fidelity)

    def scene(kind):
        def task(name, out):
            record(kind, name)
            return {"name": name, "ok": True, "seconds": 0.0}
        return task

    monkeypatch.setattr(figures, "warm", warm)
    monkeypatch.setattr(figures, "warm_lyapunov", warm_lyapunov)
    monkeypatch.setattr(figures, "warm_parts", lambda *key, drawing=False: record("parts", key) or True)
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
    assert figures._scene_needs("celt_stability") == set()
    log = _scheduled(monkeypatch, tmp_path, ["celt_stability"])
    assert [e[1:] for e in log] == [("scene", "celt_stability")]
