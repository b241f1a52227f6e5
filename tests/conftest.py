import pytest


@pytest.fixture(scope="session")
def systems():
    """Every model at every fidelity, derived afresh: {(model, fidelity): ReducedSystem}."""
    from knifeedge.derive.cli import project_specs
    from knifeedge.derive.emit import build_all

    return build_all(project_specs())
