"""Wall-clock timing: median over repeats, each repeat long enough to be measurable."""
from __future__ import annotations

import statistics
import time


def median_time(fn, repeats: int = 5, min_seconds: float = 0.02) -> float:
    """Median over ``repeats`` of the mean time of one ``fn()`` call, in seconds.

    Each repeat calls ``fn`` as many times as needed to last ``min_seconds``.
    """
    t = time.perf_counter()
    fn()  # warm-up (caches), also the calibration
    single = time.perf_counter() - t
    inner = max(1, int(min_seconds / max(single, 1e-9)))
    samples = []
    for _ in range(repeats):
        t = time.perf_counter()
        for _ in range(inner):
            fn()
        samples.append((time.perf_counter() - t) / inner)
    return statistics.median(samples)
