"""The fixed-step Lyapunov runs of the scenes ``celt_chaos`` and ``predictability``, warm: CPU and a hash of the results.

``python -m benchmarks.lyapunov_scenes [--repeats 5]``

Each run as its scene calls it (the celt's spectrum over 1000 time units; the two-mode model's largest exponent
over 9x10^4), once to compile or load it, then ``--repeats`` times: the minimum and median CPU, and the first 12
hex digits of a SHA-256 of the exponents, the history and the final state (equal hashes: the same bits).  Run it in
one process per tree, interleaved (``PYTHONPATH=<tree>/src`` for another tree), to compare the loop's speed.
"""
from __future__ import annotations

import argparse
import hashlib
import time

import numpy as np


def runs() -> dict:
    """The two scenes' calls of ``lyapunov``, by scene name."""
    from knifeedge.lyapunov import lyapunov
    from knifeedge.scenes import get_scene

    calls = {}
    for name in ("celt_chaos", "predictability"):
        scene = get_scene(name)
        s, run = scene.settings, scene.run
        m = run.load()
        p, y0 = m.params(**dict(run.params)), m.state(**dict(run.y0))
        if name == "celt_chaos":
            calls[name] = lambda m=m, p=p, y0=y0, s=s, run=run: lyapunov(m, y0, p, run.t_span[1], h=s["h"],
                                                                           tau=s["tau"])
        else:
            t0 = run.t_span[0]
            calls[name] = lambda m=m, p=p, y0=y0, s=s, t0=t0: lyapunov(m, y0, p, t0 + s["lyapunov_span"], k=1,
                                                                         h=s["h"], tau=s["tau"], t0=t0)
    return calls


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5)
    args = ap.parse_args(argv)
    for name, call in runs().items():
        r, times = call(), []
        for _ in range(args.repeats):
            t = time.process_time()
            r = call()
            times.append(time.process_time() - t)
        digest = hashlib.sha256(np.concatenate([r.exponents, r.history.ravel(), r.y]).tobytes()).hexdigest()[:12]
        print(f"{name}: min {min(times) * 1e3:.1f} ms, median {float(np.median(times)) * 1e3:.1f} ms, "
              f"results {digest}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
