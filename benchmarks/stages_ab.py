"""The adaptive methods per evaluation on two source trees, interleaved: ``python -m benchmarks.stages_ab --base DIR``.

``DIR`` is another checkout of knifeedge with its own ``.venv`` (e.g. ``git clone . /tmp/base && cd /tmp/base
&& git checkout main && python3 -m venv .venv && .venv/bin/pip install -e .``).  Each round starts one child
process per tree (its own interpreter, its own cache folders, made fresh once per tree and kept over the
rounds), the order alternating; each child runs DOP853, DP54 and Tsit5 on every scene ``--repeats`` times and
prints the CPU nanoseconds per right-hand-side evaluation (the minimum over the repeats of ``time.process_time``)
and a SHA-256 prefix of the result.  Printed per scene and method: the minimum over the rounds for each tree,
their ratio (this tree / base) and whether the results are bit for bit equal; then each tree's compile time of
the parts (the first run of each method in a fresh cache, CPU seconds, minus the integrator's own compile).

Scenes: ``single`` (the single mode, 3 states), ``celt`` (the full celt, 7 states) and ``bicycle`` (the Whipple
bicycle derived from ``tests/models/whipple_bicycle.py`` by ``knifeedge derive`` into ``--bicycle`` once: the
largest model; its right-hand side, selects included, is IR since derivation/ir_emit.py writes selects).
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
METHODS = ("DOP853", "DP54", "Tsit5")

#: the child: one JSON line {scene/method: [ns per evaluation, hash, seconds of the first run]}
CHILD = r"""
import hashlib, json, sys, time
import numpy as np
import knifeedge as ke

repeats, bicycle = int(sys.argv[1]), sys.argv[2]
single, celt, bike = ke.load("single_mode"), ke.load("celt"), ke.load("whipple_bicycle", path=bicycle)
from knifeedge.stability import steady_state
yb = steady_state(bike, bike.params(bike.default_params), "straight_running", 5.0)
yb[bike.state_names.index("q2_dot")] = 0.5
scenes = [("single", single, single.state(theta=1e-3, theta_dot=0.0, phi_dot=0.1),
           single.params(g=1.0, ell=1.0, L=1.0, D=1.0), 3000.0, 1e-10),
          ("celt", celt, celt.state(**celt.module.DEFAULT_STATE), celt.params(**celt.module.DEFAULT_PARAMS),
           20.0, 1e-10),
          ("bicycle", bike, yb, bike.params(bike.default_params), 10.0, 1e-10)]
out = {}
for method in ("DOP853", "DP54", "Tsit5"):
    for name, m, y0, p, t1, rtol in scenes:
        run = lambda: ke.simulate(m, y0, (0.0, t1), p, method=method, rtol=rtol, atol=rtol * 1e-6,
                                  t_eval=np.array([t1]))
        c = time.process_time()
        r = run()
        first = time.process_time() - c
        every = ke.simulate(m, y0, (0.0, t1), p, method=method, rtol=rtol, atol=rtol * 1e-6)
        digest = hashlib.sha256(r.y.tobytes() + every.y.tobytes() + every.t.tobytes()).hexdigest()[:16]
        best = float("inf")
        for _ in range(repeats):
            c = time.process_time()
            run()
            best = min(best, time.process_time() - c)
        out[f"{name}/{method}"] = [best / r.nfev * 1e9, digest, first]
print(json.dumps(out))
"""


def child(tree: Path, cache: Path, repeats: int, bicycle: Path) -> dict:
    env = dict(os.environ, KNIFEEDGE_CACHE_DIR=str(cache / "k"), NUMBA_CACHE_DIR=str(cache / "n"))
    done = subprocess.run([str(tree / ".venv" / "bin" / "python"), "-c", CHILD, str(repeats), str(bicycle)],
                          cwd=tree, env=env, capture_output=True, text=True, check=True)
    return json.loads(done.stdout.splitlines()[-1])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", type=Path, required=True, help="the other tree (with its .venv)")
    ap.add_argument("--bicycle", type=Path, default=None, help="folder of the derived bicycle (derived if absent)")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--repeats", type=int, default=11)
    args = ap.parse_args(argv)
    work = Path(tempfile.mkdtemp(prefix="stages_ab-"))
    bicycle = args.bicycle or work / "bicycle"
    if not (bicycle / "whipple_bicycle_full.py").is_file():
        subprocess.run([sys.executable, "-m", "knifeedge", "derive", str(ROOT / "tests/models/whipple_bicycle.py"),
                        "--out", str(bicycle)], check=True, stdout=subprocess.DEVNULL)
    trees = {"this": ROOT, "base": args.base.resolve()}
    runs: dict = {name: [] for name in trees}
    for r in range(args.rounds):
        for name in (("this", "base") if r % 2 == 0 else ("base", "this")):
            runs[name].append(child(trees[name], work / name, args.repeats, bicycle))
    print(f"{'scene/method':<18} {'base ns':>9} {'this ns':>9} {'ratio':>6}  bit for bit")
    for key in runs["this"][0]:
        base, this = (min(x[key][0] for x in runs[n]) for n in ("base", "this"))
        same = runs["this"][0][key][1] == runs["base"][0][key][1]
        print(f"{key:<18} {base:9.2f} {this:9.2f} {this / base:6.3f}  {'yes' if same else 'NO'}")
    print("first run in a fresh cache (CPU s, the integrator's compile included where it is the method's first use):")
    for name in trees:
        print(f"  {name}: " + ", ".join(f"{k} {v[2]:.2f}" for k, v in runs[name][0].items()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
