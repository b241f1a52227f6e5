"""The Whipple bicycle with and without its right-hand side as IR, interleaved: ``python -m benchmarks.bicycle_ir_ab``.

The bicycle's right-hand side solves its dependent velocities by an LU with partial pivoting whose pivot choices
are selects (``derivation/kkt_emit.py``).  ``derivation/ir_emit.py`` writes them as IR (``fcmp`` + ``select``), so
the module carries ``LLVM_IR["rhs_q_into"]`` and the adaptive kernels inline it into their stages; before, the
writer refused a select and the kernels called numba's compiled C callback of ``rhs_q_into``.

The bicycle is derived once from ``tests/models/whipple_bicycle.py`` (``knifeedge derive``, or ``--bicycle DIR``
holding it).  The variant *without* is the same module with ``LLVM_IR`` written as the writer wrote it before
(only ``constants``: the rhs functions left out), sealed again: byte for byte the module the writer of commit
154029c derived, apart from the model file's path in the header (checked 2026-11-26, before the half-integer
powers of ``kkt_emit`` changed the program of both variants).  Each round starts, per variant (order alternating), one child in a
FRESH cache folder (``KNIFEEDGE_CACHE_DIR``, ``NUMBA_CACHE_DIR``) that first runs the single mode (its first DOP853
run compiles the driver every model shares: "driver"), then the bicycle, whose first run compiles its parts ("first
run": ``time.process_time`` around it; "child": the child's whole CPU, imports and both compiles included), then
one child on that cache
that runs 10 s of motion at rtol 1e-10 ``--repeats`` times (CPU nanoseconds per evaluation: the minimum).  Printed:
the minimum and median over the rounds, the ratios, and whether the runs of both variants are bit for bit equal.
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
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MODULE = "whipple_bicycle_full.py"

#: the child: one JSON line {"driver": CPU s of a first run of the single mode (the shared DOP853 driver compiles),
#: "first": CPU s of the bicycle's first run after it (its parts compile), "ns": ns per evaluation, "nfev", "hash"}
CHILD = r"""
import hashlib, json, sys, time
import numpy as np
import knifeedge as ke
from knifeedge.stability import steady_state

folder, repeats = sys.argv[1], int(sys.argv[2])
single = ke.load("single_mode")  # its first run compiles the DOP853 driver, which every model shares
c = time.process_time()
ke.simulate(single, single.state(theta=1e-3, theta_dot=0.0, phi_dot=0.1), (0.0, 1.0), single.params(g=1.0, ell=1.0, L=1.0, D=1.0), method="DOP853")
driver = time.process_time() - c
m = ke.load("whipple_bicycle", path=folder)
p = m.params(m.default_params)
y0 = steady_state(m, p, "straight_running", 5.0)
y0[m.state_names.index("q2_dot")] = 0.5
run = lambda: ke.simulate(m, y0, (0.0, 10.0), p, method="DOP853", rtol=1e-10, atol=1e-12)
c = time.process_time()
r = run()
first = time.process_time() - c
best = float("inf")
for _ in range(repeats):
    c = time.process_time()
    run()
    best = min(best, time.process_time() - c)
digest = hashlib.sha256(r.y.tobytes() + r.t.tobytes()).hexdigest()[:16]
print(json.dumps({"driver": driver, "first": first, "ns": best / r.nfev * 1e9, "nfev": int(r.nfev), "hash": digest}))
"""


def without_rhs_ir(text: str) -> str:
    """The sealed module text ``text`` with its ``LLVM_IR`` written without the right-hand sides (what
    ``ir_emit`` wrote for a module with selects before it wrote them), sealed again."""
    from knifeedge.derive import ir_emit
    from knifeedge.modulecheck import seal

    source = text[:text.index("\n\n\n#: LLVM IR of the functions above")]
    kept = ir_emit.FUNCTIONS
    ir_emit.FUNCTIONS = ("constants",)
    try:
        return seal(ir_emit.with_ir(source))
    finally:
        ir_emit.FUNCTIONS = kept


def _child(folder: Path, cache: Path, repeats: int) -> tuple:
    """``(result, CPU seconds of the child)``."""
    env = dict(os.environ, KNIFEEDGE_CACHE_DIR=str(cache), NUMBA_CACHE_DIR=str(cache / "numba"),
               KNIFEEDGE_COMPILE="wait")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run([sys.executable, "-c", CHILD, str(folder), str(repeats)], env=env, check=True,
                         capture_output=True, text=True, cwd=ROOT).stdout
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return json.loads(out.strip().splitlines()[-1]), cpu


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.bicycle_ir_ab", description=__doc__.split("\n")[0])
    ap.add_argument("--bicycle", type=Path, help="a folder holding the derived bicycle (else derived here)")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--repeats", type=int, default=41)
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        with_ir = args.bicycle or tmp / "with"
        if args.bicycle is None:
            subprocess.run([sys.executable, "-m", "knifeedge", "derive", str(ROOT / "tests/models/whipple_bicycle.py"),
                            "--out", str(with_ir)], check=True, stdout=subprocess.DEVNULL)
        without = tmp / "without"
        without.mkdir()
        (without / MODULE).write_text(without_rhs_ir((with_ir / MODULE).read_text()))
        variants = {"without IR": without, "with IR": with_ir}
        cold, cold_child, warm, hashes, driver = ({k: [] for k in variants} for _ in range(5))
        for r in range(args.rounds):
            for name in (list(variants) if r % 2 == 0 else list(variants)[::-1]):
                cache = tmp / f"cache-{r}-{name.replace(' ', '-')}"
                first, cpu = _child(variants[name], cache, 0)
                again, _ = _child(variants[name], cache, args.repeats)
                cold[name].append(first["first"])
                driver[name].append(first["driver"])
                cold_child[name].append(cpu)
                warm[name].append(again["ns"])
                hashes[name] += [first["hash"], again["hash"]]
                print(f"round {r} {name:<10}: driver {first['driver']:5.2f} s, first run {first['first']:6.2f} s CPU "
                      f"(child {cpu:6.2f} s), "
                      f"{again['ns']:7.1f} ns per evaluation ({again['nfev']} evaluations), {again['hash']}",
                      flush=True)
    print(f"{'':<10} {'driver CPU s':>12} {'first run CPU s (min, median)':>30} {'child CPU s':>12} "
          f"{'ns/evaluation (min, median)':>28}")
    for name in variants:
        print(f"{name:<10} {statistics.median(driver[name]):>12.2f} {min(cold[name]):>14.2f} "
              f"{statistics.median(cold[name]):>14.2f} "
              f"{statistics.median(cold_child[name]):>12.2f} {min(warm[name]):>14.1f} "
              f"{statistics.median(warm[name]):>13.1f}")
    a, b = variants
    print(f"with / without: first run {min(cold[b]) / min(cold[a]):.3f}, per evaluation "
          f"{min(warm[b]) / min(warm[a]):.3f}; bit for bit equal: {len(set(hashes[a] + hashes[b])) == 1}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
