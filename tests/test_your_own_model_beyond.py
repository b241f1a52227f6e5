"""docs/your-own-model.md, sections 7 and 8, run as written.

The blocks marked ``python file=NAME.py`` (other than the rolling disk's, which
``tests/test_your_own_model.py`` checks) are written, in order, to ``NAME.py``
in a fresh folder; every ``knifeedge ...`` line of the ``sh example`` blocks
runs through the command line's ``main``; then every ``python example`` block
runs in order in one namespace, and the values its ``print(...)  # value``
comments state are checked (the checks themselves are against closed forms:
a hand-written ODE, the exact pendulum period).
"""
from __future__ import annotations

import re
import shlex

import pytest

from knifeedge.cli import main

import docs_blocks
from test_your_own_model import DOC, _blocks


@pytest.mark.slow  # the docs' runs are the slow tier's (as test_your_own_model's)
def test_sections_on_time_constraints_and_rigid_bodies_run(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    files = re.findall(r"```python file=(\w+\.py)\n(.*?)```", DOC.read_text(), flags=re.S)
    written: dict = {}
    for name, code in files:
        if name != "rolling_disk.py":
            written[name] = written.get(name, "") + code + "\n"
    assert sorted(written) == ["pendulum.py", "rigid_disk.py", "sleighs.py"]
    for name, code in written.items():
        (tmp_path / name).write_text(code)
    commands = [line for block in _blocks("sh example") for line in block.splitlines() if line.startswith("knifeedge ")]
    assert len(commands) == 3
    for line in commands:
        assert main(shlex.split(line)[1:]) == 0, line
    for name in ("rigid_disk", "driven_sleigh"):  # a user's module names the user's command, not make derive
        header = (tmp_path / "my_models" / f"{name}_full.py").read_text().split("\n")[2]
        assert "knifeedge derive" in header and "make derive" not in header, header
    namespace: dict = {}
    for code in _blocks("python example"):
        docs_blocks.run(code, str(DOC), namespace)
