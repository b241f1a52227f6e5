"""docs/your-own-model.md runs as written: the model file it builds, its knifeedge commands, its Python blocks.

The blocks marked ``python file=rolling_disk.py`` are written, in order, to
``rolling_disk.py`` in a fresh folder (and together they are
``examples/rolling_disk.py``); every ``knifeedge ...`` line of the ``sh``
blocks runs through the command line's ``main``; every other ``python`` block
runs in order in one namespace, and the numbers its comments state are checked.
"""
from __future__ import annotations

import re
import shlex
from pathlib import Path

import docs_blocks
import pytest

from knifeedge.cli import main

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "your-own-model.md"
EXAMPLE = ROOT / "examples" / "rolling_disk.py"


def _blocks(info: str) -> list:
    return re.findall(rf"```{re.escape(info)}\n(.*?)```", DOC.read_text(), flags=re.S)


def _squeeze(text: str) -> str:
    """Text with runs of blank lines collapsed to one (the doc separates its pieces by one)."""
    return re.sub(r"\n{3,}", "\n\n", text).strip() + "\n"


def test_the_doc_builds_the_example_file():
    pieces = _blocks("python file=rolling_disk.py")
    assert len(pieces) >= 4
    assert _squeeze("\n".join(pieces)) == _squeeze(EXAMPLE.read_text())


@pytest.mark.slow
def test_the_doc_runs_from_an_empty_folder(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "rolling_disk.py").write_text("\n".join(_blocks("python file=rolling_disk.py")))
    commands = [line for block in _blocks("sh") for line in block.splitlines() if line.startswith("knifeedge ")]
    assert commands[0].startswith("knifeedge derive rolling_disk.py --out my_models")
    for line in commands[:1]:
        assert main(shlex.split(line)[1:]) == 0, line
    assert sorted(p.name for p in (tmp_path / "my_models").glob("*_full.py")) == [
        "rolling_disk_damped_full.py", "rolling_disk_full.py"]
    for line in commands[1:]:
        assert main(shlex.split(line)[1:]) == 0, line
    assert (tmp_path / "rolling_disk_cli.png").exists()

    namespace: dict = {}
    for code in _blocks("python"):  # in order: later blocks use earlier names
        docs_blocks.run(code, str(DOC), namespace)
    assert (tmp_path / "rolling_disk.png").exists()
