import pytest


@pytest.fixture(scope="session")
def systems():
    """Every model at every fidelity, derived afresh: {(model, fidelity): ReducedSystem}."""
    from derivation.emit import build_all

    return build_all()
