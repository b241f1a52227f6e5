import os
from collections.abc import Mapping

import pytest

# kernels compile in the process that needs them (the command line's default for single runs is to compile in
# the background while SciPy answers: tests/test_compile_background.py tests that mode on purpose)
os.environ.setdefault("KNIFEEDGE_COMPILE", "wait")


class _Systems(Mapping):
    """Every model at every fidelity, derived afresh on first use: {(model, fidelity): ReducedSystem}.

    A model is derived (at all its fidelities) when a test first asks for one of them, so a run that checks only
    the paper's two models does not derive the rigid bodies (the two-mode model takes about 7 s, all of them 14 s).
    """

    def __init__(self):
        from knifeedge.derive.cli import project_specs
        from knifeedge.generated import MODULES

        self._specs = {s.name: s for s in project_specs()}
        self._keys = tuple(sorted(k for k in MODULES if k[0] in self._specs))
        self._built: dict = {}

    def __getitem__(self, key):
        name = key[0] if isinstance(key, tuple) and key else None
        if name in self._specs and name not in self._built:
            from knifeedge.derive.emit import build

            self._built[name] = build(self._specs[name])
        if name not in self._built or key not in self._built[name]:
            raise KeyError(key)
        return self._built[name][key]

    def __iter__(self):
        return iter(self._keys)

    def __len__(self):
        return len(self._keys)


@pytest.fixture(scope="session")
def systems():
    """Every model at every fidelity, derived afresh (each model when first asked for): {(model, fidelity): system}."""
    return _Systems()


def pytest_collection_modifyitems(config, items):
    """The default tier prints no ValidityWarning (issue 26, root 7): the package's own scenes stay inside their
    fidelities' domains or show the boundary, and a test that provokes the warning on purpose asserts it
    (``pytest.warns``); any other one is an error there."""
    for item in items:
        if item.get_closest_marker("slow") is None:
            item.add_marker(pytest.mark.filterwarnings("error::knifeedge.models.ValidityWarning"))
