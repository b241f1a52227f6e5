"""CPU time per right-hand-side evaluation of ``ke.simulate``, per compiled method, and a hash of each result.

``python -m benchmarks.per_method [--repeats 41]`` prints one JSON object: for each scene and method the
nanoseconds of CPU per evaluation (the minimum over the repeats of one call's ``time.process_time``, which a
busy machine disturbs far less than wall-clock medians) and a SHA-256 prefix of the final state, the rows of
every step and the reversal times (equal hashes: bit-identical results).  To compare two versions of the code,
run it once per version with fresh ``KNIFEEDGE_CACHE_DIR`` and ``NUMBA_CACHE_DIR`` folders each, interleaved
(docs/performance.md, "Kernels").
"""
from __future__ import annotations

import argparse
import hashlib
import json
import math
import time

import numpy as np

import knifeedge as ke

#: method -> options (the fixed-step runs span a tenth of the scene)
METHODS = {"DOP853": dict(rtol=1e-10, atol=1e-16), "DP54": dict(rtol=1e-8, atol=1e-14),
           "Tsit5": dict(rtol=1e-8, atol=1e-14), "RK4": dict(h=0.01), "implicit_midpoint": dict(h=0.01),
           "gauss4": dict(h=0.02), "gauss6": dict(h=0.04)}
ADAPTIVE = ("DOP853", "DP54", "Tsit5")


def _scenes():
    single, two, celt = ke.load("single_mode"), ke.load("two_mode"), ke.load("celt")
    yield ("single", single, single.state(theta=1e-3, theta_dot=0.0, phi_dot=0.1),
           single.params(g=1.0, ell=1.0, L=1.0, D=1.0), 3000.0, tuple(METHODS))
    yield ("two", two, two.state(theta1=1e-3, theta2=1e-3, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1),
           two.params(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4), 3000.0, tuple(METHODS))
    yield ("celt", celt, celt.state(**celt.module.DEFAULT_STATE), celt.params(**celt.module.DEFAULT_PARAMS), 20.0,
           ("DOP853", "DP54", "Tsit5", "RK4", "gauss4"))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=41)
    ap.add_argument("--only", default="", help="comma-separated scene/method keys to run (default: all)")
    args = ap.parse_args(argv)
    only = set(filter(None, args.only.split(",")))
    out = {}
    for name, m, y0, p, t1, methods in _scenes():
        for method in methods:
            if only and f"{name}/{method}" not in only:
                continue
            t_end = t1 if method in ADAPTIVE else t1 / 10
            kw = METHODS[method]
            run = lambda: ke.simulate(m, y0, (0.0, t_end), p, method=method, t_eval=np.array([t_end]), **kw)  # noqa: E731
            final = run()  # compiles (or loads) the kernel
            every = ke.simulate(m, y0, (0.0, t_end), p, method=method, **kw)
            digest = hashlib.sha256(final.y.tobytes() + every.y.tobytes() + every.t.tobytes()
                                    + np.asarray(every.reversal_times, dtype=float).tobytes()).hexdigest()[:16]
            best = math.inf
            for _ in range(args.repeats):
                t = time.process_time()
                run()
                best = min(best, time.process_time() - t)
            out[f"{name}/{method}"] = {"ns": round(best / final.nfev * 1e9, 2), "nfev": int(final.nfev),
                                       "hash": digest}
    print(json.dumps(out))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
