"""generated/ is exactly what the derivation writes now, and the runtime needs no SymPy."""
import difflib
import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _derive(out: Path, seed: str = "0") -> None:
    env = dict(os.environ, PYTHONHASHSEED=seed)
    subprocess.run([sys.executable, "-m", "knifeedge.derive", "--out", str(out)], cwd=ROOT, env=env,
                   check=True, capture_output=True, text=True)


@pytest.fixture(scope="module")
def fresh(tmp_path_factory):
    out = tmp_path_factory.mktemp("generated")
    _derive(out)
    return out


def test_generated_matches_its_manifest():
    """Nothing changed since make derive: every derivation source and generated module has the SHA-256 that
    make derive recorded in generated/MANIFEST.sha256 (reads files only; the slow test below derives again)."""
    from knifeedge.derive.cli import manifest_mismatches

    problems = manifest_mismatches(ROOT / "generated")
    assert not problems, "generated/ is stale or edited by hand: run make derive\n" + "\n".join(problems)


def test_manifest_reports_an_edited_module_and_a_changed_source(tmp_path):
    """The manifest check fails when a generated module or a derivation source differs by one byte."""
    import shutil

    from knifeedge.derive.cli import EXAMPLE_MODELS, MANIFEST, manifest_mismatches

    for sub in ("derivation", "generated"):
        shutil.copytree(ROOT / sub, tmp_path / sub, ignore=shutil.ignore_patterns("__pycache__"))
    for f in EXAMPLE_MODELS:
        (tmp_path / f).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(ROOT / f, tmp_path / f)
    assert manifest_mismatches(tmp_path / "generated", tmp_path) == []
    module = tmp_path / "generated" / "two_mode_full.py"
    module.write_text(module.read_text().replace("cos(", "sin(", 1))
    source = tmp_path / "derivation" / "averaging.py"
    source.write_text(source.read_text() + "\n")
    assert manifest_mismatches(tmp_path / "generated", tmp_path) == [
        "derivation/averaging.py: changed since the manifest was written",
        "generated/two_mode_full.py: changed since the manifest was written"]
    (tmp_path / "generated" / MANIFEST).unlink()
    assert "is missing" in manifest_mismatches(tmp_path / "generated", tmp_path)[0]


@pytest.mark.slow
@pytest.mark.xdist_group("derive")  # one worker derives `fresh` once for both tests that use it
def test_generated_is_not_stale(fresh):
    """A fresh derivation reproduces the checked-in generated/ (and its manifest) byte for byte."""
    from knifeedge.derive.cli import MANIFEST

    assert (fresh / MANIFEST).read_text() == (ROOT / "generated" / MANIFEST).read_text(), "run make derive"
    checked_in = sorted(p.name for p in (ROOT / "generated").glob("*.py"))
    regenerated = sorted(p.name for p in fresh.glob("*.py"))
    assert checked_in == regenerated, f"generated/ holds {checked_in}, derivation writes {regenerated}: run make derive"
    problems = []
    for name in regenerated:
        old = (ROOT / "generated" / name).read_text().splitlines(keepends=True)
        new = (fresh / name).read_text().splitlines(keepends=True)
        if old != new:
            diff = "".join(difflib.unified_diff(old, new, f"generated/{name}", f"fresh/{name}", n=1))
            problems.append(diff[:3000])
    assert not problems, "generated/ is stale: run make derive\n" + "\n".join(problems)


@pytest.mark.slow
@pytest.mark.xdist_group("derive")
def test_derivation_is_deterministic_under_any_hash_seed(fresh, tmp_path):
    """make derive pins PYTHONHASHSEED=0; the output does not depend on it anyway."""
    _derive(tmp_path, seed="12345")
    for p in fresh.glob("*.py"):
        assert (tmp_path / p.name).read_bytes() == p.read_bytes(), p.name


def test_generated_headers():
    # (stages.py is no model: the adaptive methods' stages as IR, checked by tests/test_irparts.py)
    for p in sorted(q for q in (ROOT / "generated").glob("*.py") if q.name not in ("__init__.py", "stages.py")):
        text = p.read_text()
        head = text[:3000]
        assert "DO NOT EDIT BY HAND" in head and "make derive" in head, p.name
        assert "SymPy" in head and "input hash sha256:" in head, p.name
        assert "State vector" in head and "Parameter vector" in head, p.name
        assert "import sympy" not in text and "from sympy" not in text, p.name


def test_runtime_does_not_import_sympy():
    code = (
        "import sys, math, knifeedge as ke\n"
        "m = ke.load('two_mode', fidelity='reduced', pose=True)\n"
        "p = m.params(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi/4)\n"
        "r = ke.simulate(m, m.state(theta1=1e-3, theta2=0.0, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1), (0, 5), p)\n"
        "assert r.success\n"
        "bad = [k for k in sys.modules if k == 'sympy' or k.startswith('sympy.')]\n"
        "assert not bad, bad\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, cwd=ROOT / "tests")


@pytest.mark.slow  # builds the wheel in a subprocess (~5 s of CPU): the packaging, not the physics
def test_wheel_ships_the_generated_modules(tmp_path):
    """A non-editable install gets knifeedge.generated from the wheel."""
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q",
                    "-w", str(tmp_path), str(ROOT)], check=True, capture_output=True)
    wheel = next(tmp_path.glob("knifeedge-*.whl"))
    names = set(zipfile.ZipFile(wheel).namelist())
    for p in (ROOT / "generated").rglob("*.py"):  # with generated/linear (make bicycle-linear)
        name = p.relative_to(ROOT / "generated").as_posix()
        assert f"knifeedge/generated/{name}" in names, name
    assert any(n.startswith("knifeedge/derive/") for n in names)  # the engine, with the derive extra
    assert not any(n.startswith("derivation/") for n in names)
