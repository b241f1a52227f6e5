import os

import pytest

# kernels compile in the process that needs them (the command line's default for single runs is to compile in
# the background while SciPy answers: tests/test_compile_background.py tests that mode on purpose)
os.environ.setdefault("KNIFEEDGE_COMPILE", "wait")


@pytest.fixture(scope="session")
def systems():
    """Every model at every fidelity, derived afresh: {(model, fidelity): ReducedSystem}."""
    from knifeedge.derive.cli import project_specs
    from knifeedge.derive.emit import build_all

    return build_all(project_specs())
