"""Two bodies from the multibody front end against the hand-written model (issue 22 item 3).

``python -m benchmarks.multibody`` derives examples/rolling_disk.py (the disk), examples/disk_pendulum.py (both
kinetic energies by hand) and examples/disk_pendulum_bodies.py (two ``RigidBody`` and a ``Pin``) with
``knifeedge derive`` into a temporary folder, each in a fresh process (wall and CPU time of the process, one run,
in this order), then times ``rhs_into`` as benchmarks/elimination.py does (median of 9 repeats of 200,000 calls), the
three models in turn for 5 rounds, and prints the medians and their ratios to the disk's, all from this one run.
"""
from __future__ import annotations

import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import knifeedge as ke

from .elimination import EXAMPLES, per_call_ns

MODELS = ("rolling_disk", "disk_pendulum", "disk_pendulum_bodies")
ROUNDS = 5


def derive(name: str, out: Path) -> tuple:
    """Wall and CPU seconds of ``knifeedge derive examples/<name>.py --out out`` in a child process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "knifeedge.derive", str(EXAMPLES / f"{name}.py"), "--out", str(out)],
                   check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main(argv=None) -> int:
    out = Path(tempfile.mkdtemp(prefix="multibody"))
    for name in MODELS:
        wall, cpu = derive(name, out)
        print(f"knifeedge derive examples/{name}.py: {wall:.1f} s wall, {cpu:.1f} s CPU")
    models = {name: ke.load(name, path=out) for name in MODELS}
    states = {n: np.array([m.default_state.get(k, 0.3) for k in m.state_names]) + 0.1 for n, m in models.items()}
    rounds = {n: [] for n in MODELS}
    for _ in range(ROUNDS):  # interleaved: the machine's load changes within a run
        for n, m in models.items():
            rounds[n].append(per_call_ns(m, states[n], m.params(m.default_params)))
    ns = {n: statistics.median(v) for n, v in rounds.items()}
    for name, m in models.items():
        print(f"{name:22s} rhs_into {ns[name]:6.0f} ns/call, {m.module.OP_COUNTS['rhs']:5d} operations, "
              f"{m.module.ELIMINATION}; ratio to the disk {ns[name] / ns['rolling_disk']:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
