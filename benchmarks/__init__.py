"""Speed and accuracy benchmarks of knifeedge's integrators (``python -m benchmarks``, ``make bench``).

Not part of the tests: timings depend on the machine; every ratio reported is
measured in one run, as the median of repeats.
"""
