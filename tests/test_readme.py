"""The README's tour runs as written: every python block, every knifeedge command of its sh blocks."""
from __future__ import annotations

import re
import shlex
from pathlib import Path

import docs_blocks
import pytest

import knifeedge as ke
from knifeedge.cli import main

README = Path(__file__).resolve().parents[1] / "README.md"


def _blocks(lang: str) -> list:
    return re.findall(rf"```{lang}\n(.*?)```", README.read_text(), flags=re.S)


def test_readme_has_a_tour():
    text = README.read_text()
    assert "## Tour" in text and len(_blocks("python")) >= 4 and _blocks("sh")


def test_readme_python_blocks_run(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    for code in _blocks("python"):  # in order: later blocks use earlier names
        docs_blocks.run(code, str(README), namespace, notes=True)
    assert (tmp_path / "reversal.png").exists() and (tmp_path / "numerical-D05.png").exists()
    assert len((tmp_path / "tr.csv").read_text().splitlines()) == 4  # header + 3 runs


@pytest.mark.slow
def test_readme_shell_commands_run(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    commands = [line for block in _blocks("sh") for line in block.splitlines() if line.startswith("knifeedge ")]
    assert commands
    for line in commands:
        assert main(shlex.split(line)[1:]) == 0, line
    assert (tmp_path / "figures" / "index.html").exists()
    assert len(list((tmp_path / "figures").glob("*.png"))) == len(ke.scene_names())
