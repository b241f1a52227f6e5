"""Where a cold compile of one of the two long loops goes: CPU seconds by numba pass, LLVM and compiled function.

``python -m benchmarks.compile_profile [driver|benettin|adaptive|warmups ...] [--repeats 3]``

Each repeat is a fresh process with empty caches (``NUMBA_CACHE_DIR``, ``KNIFEEDGE_CACHE_DIR``):

* ``driver``: the DOP853 driver (``integrators.erk``, once per machine for every model), compiled by a first run
  of the single mode after its model parts (``figures.warm_parts``, not counted);
* ``benettin``: the fixed-step Lyapunov loop (``lyapunov._benettin``, what ``celt_chaos`` and ``predictability``
  run) for its first-class function types, then ``figures.warm_lyapunov`` of the two-mode model (its
  ``jvp_into`` and ``invariant_gradients``: the task ``knifeedge figures`` runs);
* ``adaptive``: the largest exponent's DOP853 loop (``lyapunov._benettin_adaptive``) alone;
* ``warmups``: ``benettin``, then ``figures.warm_lyapunov`` of the celt (its ``jvp_into`` and
  ``invariant_gradients``): all that ``knifeedge figures`` compiles for its Lyapunov scenes.

Printed per repeat: the process's CPU for the imports, for numba's first compile in the process (a one-line
function), for the model's parts (``driver``), for the target; then, from numba's events (``numba:compile``, ``numba:run_pass``,
``numba:llvm_lock``), the CPU exclusive of nested compiles by pass, in LLVM, and by function.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from collections import defaultdict


def _profiler():
    from numba.core import event

    class Profile(event.Listener):
        """CPU (``time.process_time``) of each event less the events nested in it, summed by pass and function."""

        def __init__(self):
            self.stack, self.passes, self.functions, self.llvm = [], defaultdict(float), defaultdict(float), 0.0

        def on_start(self, ev):
            if ev.kind == "numba:compile":
                f = ev.data["dispatcher"].py_func
                name = ("function", f"{f.__module__.rsplit('.', 1)[-1]}:{f.__qualname__.replace('<locals>.', '')}")
            else:
                name = ("pass", ev.data["name"].split(" [")[0]) if ev.kind == "numba:run_pass" else ("llvm", "")
            self.stack.append([name, time.process_time(), 0.0])

        def on_end(self, ev):
            (kind, name), start, nested = self.stack.pop()
            spent = time.process_time() - start
            if self.stack:
                self.stack[-1][2] += spent
            function = next((n for (k, n), *_ in reversed(self.stack) if k == "function"), name)
            self.functions[function] += spent - nested
            if kind == "pass":
                self.passes[name] += spent - nested
            elif kind == "llvm":
                self.llvm += spent - nested

    profile = Profile()
    for kind in ("numba:compile", "numba:run_pass", "numba:llvm_lock"):
        event.register(kind, profile)
    return profile


def _child(target: str) -> dict:
    """Run in a fresh process (the caches empty): compile ``target`` and return the CPU seconds."""
    cpu = time.process_time
    c0 = cpu()
    import importlib

    import numba

    import knifeedge  # noqa: F401
    from knifeedge import figures

    c_imports = cpu()
    numba.njit(lambda x: x + 1.0)(1.0)
    c_first = cpu()
    profile, c_parts = _profiler(), c_first
    if target == "driver":
        figures.warm_parts("single_mode", "reduced", True, "DOP853")
        c_parts = cpu()  # the model's parts are not the driver's
        figures.warm("single_mode", "reduced", True, "DOP853")
    elif target in ("benettin", "warmups"):
        importlib.import_module("knifeedge.lyapunov")._kernel()
        figures.warm_lyapunov("two_mode", "reduced")
        if target == "warmups":
            figures.warm_lyapunov("celt", "full")
    elif target == "adaptive":
        importlib.import_module("knifeedge.lyapunov")._adaptive_kernel()
    else:
        raise ValueError(f"`target` must be driver, benettin, adaptive or warmups, got {target!r}")
    top = lambda d, n: sorted(((round(v, 2), k) for k, v in d.items() if v >= 0.05), reverse=True)[:n]  # noqa: E731
    return {"imports": round(c_imports - c0, 2), "first_compile": round(c_first - c_imports, 2),
            "parts": round(c_parts - c_first, 2), "target": round(cpu() - c_parts, 2), "llvm": round(profile.llvm, 2), "passes": top(profile.passes, 6),
            "functions": top(profile.functions, 14)}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("targets", nargs="*", default=["driver", "benettin", "adaptive"])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--child", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child:
        print(json.dumps(_child(args.child)))
        return 0
    for target in args.targets:
        for k in range(args.repeats):
            caches = tempfile.mkdtemp(prefix="compile-profile-")
            env = dict(os.environ, NUMBA_CACHE_DIR=f"{caches}/numba", KNIFEEDGE_CACHE_DIR=f"{caches}/kernels")
            out = subprocess.run([sys.executable, "-m", "benchmarks.compile_profile", "--child", target], env=env,
                                 capture_output=True, text=True, check=True)
            shutil.rmtree(caches, ignore_errors=True)
            print(target, k + 1, out.stdout.strip().splitlines()[-1], flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
