"""docs/from-sympy.md runs as written: the model file it builds, its ``knifeedge`` command, its Python blocks.

The blocks marked ``python file=disc.py`` are, in order, ``tests/models/sympy_rolling_disc.py``
(the model the peer checks of ``tests/test_mechanics_peers.py`` compare with SymPy's own
equations); the other blocks run in order in a fresh folder, and the numbers their
comments state are checked.
"""
import re
import shlex
from pathlib import Path

import pytest

from knifeedge.cli import main
import docs_blocks
from test_your_own_model import _squeeze

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "from-sympy.md"
MODEL = ROOT / "tests" / "models" / "sympy_rolling_disc.py"


def _blocks(info: str) -> list:
    return re.findall(rf"```{re.escape(info)}\n(.*?)```", DOC.read_text(), flags=re.S)


def test_the_doc_builds_the_peer_model_file():
    pieces = _blocks("python file=disc.py")
    assert len(pieces) == 3
    assert _squeeze("\n".join(pieces)) == _squeeze(MODEL.read_text())


@pytest.mark.slow
def test_the_doc_runs_from_an_empty_folder(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "disc.py").write_text("\n".join(_blocks("python file=disc.py")))
    commands = [line for block in _blocks("sh") for line in block.splitlines() if line.startswith("knifeedge ")]
    assert commands == ["knifeedge derive disc.py --out my_models"]
    assert main(shlex.split(commands[0])[1:]) == 0
    namespace: dict = {}
    for code in _blocks("python"):
        docs_blocks.run(code, str(DOC), namespace)
    assert (tmp_path / "disc.png").exists()


def test_the_docs_stability_chart_runs(tmp_path, monkeypatch):
    """Section 7's ``python chart`` block (the scene ``bicycle_stability``) as written, in an empty folder."""
    monkeypatch.chdir(tmp_path)
    (code,) = _blocks("python chart")
    docs_blocks.run(code, str(DOC), {})
    assert (tmp_path / "bicycle_stability.png").exists()
