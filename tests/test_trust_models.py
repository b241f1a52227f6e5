"""Issue 26, roots 3, 5 and 6: a model module is what its header says; a rigid body is physical, or refused;
everything a user names is the thing used.

Each test is named after its root; each fails on the code before the fix (the refusal did not exist, or the
wrong thing was used).
"""
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import knifeedge as ke
from knifeedge import cli, modulecheck
from knifeedge import models as kmodels

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
USER_MODEL = HERE / "models" / "damped_sleigh.py"


@pytest.fixture(scope="module")
def user_folder(tmp_path_factory):
    out = tmp_path_factory.mktemp("trusted_models")
    assert cli.main(["derive", str(USER_MODEL), "--out", str(out)]) == 0
    return out


def _copy(folder: Path, tmp_path: Path) -> Path:
    target = tmp_path / "copy"
    shutil.copytree(folder, target)
    return target


def _reseal(path: Path, edit) -> None:
    """Apply ``edit`` to the module's text (without its seal) and seal it again, as a forger would."""
    text = path.read_text()
    body = text[: text.rindex("#: SHA-256 of this file")]
    path.write_text(modulecheck.seal(edit(body)))


# -- root 3: a model module is what its header says -----------------------------------------------------------------
def test_root3_a_model_module_is_what_its_header_says_hand_edit_refused(user_folder, tmp_path):
    folder = _copy(user_folder, tmp_path)
    assert ke.load("damped_sleigh", path=folder).param_names  # the module as written loads
    module = folder / "damped_sleigh_full.py"
    text = module.read_text()
    edited = text.replace("DEFAULT_PARAMS = {'a': 0.5", "DEFAULT_PARAMS = {'a': 0.6")
    assert edited != text
    module.write_text(edited)
    with pytest.raises(ValueError, match=r"does not match its own content hash.*knifeedge derive"):
        ke.load("damped_sleigh", path=folder)


def test_root3_a_model_module_is_what_its_header_says_sizes_checked_before_it_runs(user_folder, tmp_path):
    """A shortened STATE_NAMES (even with its hash made to match) would make the kernels read and write past the
    state: refused before the module runs (a module that runs would set `ran`)."""
    folder = _copy(user_folder, tmp_path)
    module = folder / "damped_sleigh_full.py"
    names = kmodels.load("damped_sleigh", path=user_folder).closed_state_names
    short = repr(names[:-1])

    def shorten(body):
        return body.replace(f"STATE_NAMES = {names!r}", f"STATE_NAMES = {short}", 1).replace(
            "import math\n", "import math\nimport builtins\nbuiltins.ran = True\n", 1)

    _reseal(module, shorten)
    assert f"STATE_NAMES = {short}" in module.read_text()
    with pytest.raises(ValueError, match=r"inconsistent.*(rhs_into|STATE_UNITS)"):
        ke.load("damped_sleigh", path=folder)
    import builtins
    assert not hasattr(builtins, "ran")


def test_root3_a_model_module_is_what_its_header_says_renamed_file_refused_before_it_runs(user_folder, tmp_path):
    folder = tmp_path / "renamed"
    folder.mkdir()
    shutil.copy(user_folder / "damped_sleigh_full.py", folder / "other_full.py")
    with pytest.raises(ValueError, match="declares model 'damped_sleigh' at fidelity 'full', not 'other'"):
        ke.load("other", path=folder)
    assert not any(k.startswith("knifeedge_model_other_") for k in sys.modules)


def test_root3_a_model_module_is_what_its_header_says_every_builtin_sealed(monkeypatch):
    """Every built-in module verifies; load checks a built-in's file before importing it."""
    for (name, fidelity), stem in kmodels.MODULES.items():
        modulecheck.check((ROOT / "generated" / f"{stem}.py").read_bytes(), stem, "make derive")
    seen = []
    monkeypatch.setattr(kmodels.modulecheck, "check", lambda data, where, *args: seen.append(where))
    monkeypatch.setattr(kmodels, "_CACHE", {})
    kmodels.load("two_mode", fidelity="reduced")
    assert seen and seen[0].endswith("two_mode_reduced.py")


def test_root3_a_model_module_is_what_its_header_says_names_confined(user_folder, tmp_path):
    outside = tmp_path / "outside_full.py"
    shutil.copy(user_folder / "damped_sleigh_full.py", outside)
    inner = tmp_path / "inner"
    inner.mkdir()
    for name, fidelity in (("../outside", "full"), ("damped_sleigh", "../full"), (str(tmp_path / "x"), "full")):
        with pytest.raises(ValueError, match="plain name"):
            ke.load(name, fidelity=fidelity, path=inner)
    from knifeedge.derive import emit
    with pytest.raises(ValueError, match="plain names"):
        emit.module_path(inner, "../outside", "full")


def test_root3_a_model_module_is_what_its_header_says_derive_refuses_the_package_folder():
    from knifeedge.derive import DeriveError, derive_files
    before = {p.name: p.read_bytes() for p in (ROOT / "generated").glob("*.py")}
    for folder in (ROOT / "generated", ROOT / "generated" / "sub", ROOT / "src" / "knifeedge"):
        with pytest.raises(DeriveError, match="inside the package's own folders"):
            derive_files([USER_MODEL], folder)
    assert before == {p.name: p.read_bytes() for p in (ROOT / "generated").glob("*.py")}
    assert not (ROOT / "generated" / "sub").exists()


@pytest.mark.slow  # the same refusal through `python -m knifeedge derive` (a process importing SymPy, ~4 s of CPU)
def test_root3_a_model_module_is_what_its_header_says_derive_command_refuses_the_package_folder():
    before = {p.name: p.read_bytes() for p in (ROOT / "generated").glob("*.py")}
    r = subprocess.run([sys.executable, "-m", "knifeedge", "derive", str(USER_MODEL), "--out",
                        str(ROOT / "generated")], capture_output=True, text=True)
    assert r.returncode != 0 and "inside the package's own folders" in r.stderr
    assert before == {p.name: p.read_bytes() for p in (ROOT / "generated").glob("*.py")}
    assert not (ROOT / "generated" / "sub").exists()


def test_root3_a_model_module_is_what_its_header_says_users_file_not_overwritten(user_folder, tmp_path):
    from knifeedge.derive import DeriveError
    from knifeedge.derive.cli import check_out
    out = _copy(user_folder, tmp_path)
    check_out(out, [("damped_sleigh", "full")])  # a module knifeedge wrote may be rewritten
    mine = out / "damped_sleigh_full.py"
    mine.write_text("# my own notes, not a generated module\n")
    with pytest.raises(DeriveError, match="not a module knifeedge wrote"):
        check_out(out, [("damped_sleigh", "full")])
    assert mine.read_text() == "# my own notes, not a generated module\n"


@pytest.mark.slow  # the same refusal through `python -m knifeedge derive` (a process deriving, ~5 s of CPU)
def test_root3_a_model_module_is_what_its_header_says_derive_command_keeps_the_users_file(user_folder, tmp_path):
    out = _copy(user_folder, tmp_path)
    mine = out / "damped_sleigh_full.py"
    mine.write_text("# my own notes, not a generated module\n")
    r = subprocess.run([sys.executable, "-m", "knifeedge", "derive", str(USER_MODEL), "--out", str(out)],
                       capture_output=True, text=True)
    assert r.returncode != 0 and "not overwritten" in r.stderr
    assert mine.read_text() == "# my own notes, not a generated module\n"


def test_root3_a_model_module_is_what_its_header_says_users_header_names_users_command(user_folder):
    from knifeedge.derive import emit, rigid_emit
    hint = (user_folder / "damped_sleigh_full.py").read_text().split("\n")[2]
    assert "Run ``knifeedge derive " in hint and "damped_sleigh.py --out DIR``" in hint
    body = type("Body", (), {"source": "knifeedge_user_spec_my_disk"})()
    assert emit.regenerate_hint(rigid_emit.source_label(body)) == \
        "Run ``knifeedge derive my_disk.py --out DIR`` to regenerate."
    assert "make derive" in (ROOT / "generated" / "celt_full.py").read_text()[:400]


# -- root 6: everything a user names is the thing used -----------------------------------------------------------
NAMED_LIKE_BUILTINS = '''
import dataclasses
import importlib.util

import sympy as sp

from knifeedge.derive.drawing import Drawing

_spec = importlib.util.spec_from_file_location("damped_sleigh_source", {source!r})
_mod = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_mod)
a, x, y, phi = _mod.a, _mod.x, _mod.y, _mod.phi
drawn = Drawing(points={{"C": (x, y, 0), "G": (x + a * sp.cos(phi), y + a * sp.sin(phi), 0)}},
                segments=(("C", "G"),), contact="C", masses=("G",), description="the user's own sleigh")
MODEL = [dataclasses.replace(_mod.MODEL, name="chaplygin_sleigh", drawing=drawn),
         dataclasses.replace(_mod.MODEL, name="single_mode")]
'''


@pytest.fixture(scope="module")
def named_like_builtins(tmp_path_factory):
    """A user's sleighs named like two built-in models, one with its own drawing, one without."""
    folder = tmp_path_factory.mktemp("named_like_builtins")
    model_file = folder / "sleighs.py"
    model_file.write_text(NAMED_LIKE_BUILTINS.format(source=str(USER_MODEL)))
    out = folder / "out"
    assert cli.main(["derive", str(model_file), "--out", str(out)]) == 0
    return out


def test_root6_everything_a_user_names_is_the_thing_used_no_builtin_drawing_by_name(named_like_builtins):
    module = ke.load("single_mode", path=named_like_builtins).module
    assert module.DRAWING is None  # the built-in single_mode's drawing (theta, D, L, ell) is not attached
    assert ke.load("chaplygin_sleigh", path=named_like_builtins).module.DRAWING["description"] == \
        "the user's own sleigh"


def test_root6_everything_a_user_names_is_the_thing_used_animate_a_model_loaded_by_path(named_like_builtins,
                                                                                       tmp_path):
    from knifeedge import animation
    m = ke.load("chaplygin_sleigh", path=named_like_builtins)
    r = ke.simulate(m, m.default_state, (0.0, 2.0), m.default_params)
    mo = animation.motion(r, frames=5)
    assert mo.model.source_path == m.source_path and mo.model.pose  # the user's module, not the built-in one
    info = ke.animate(r, tmp_path / "sleigh.gif", frames=3)
    assert info.n_frames == 3 and (tmp_path / "sleigh.gif").stat().st_size > 0


@pytest.mark.parametrize("code", [0, 3])
def test_root6_everything_a_user_names_is_the_thing_used_sys_exit_is_an_error(tmp_path, capsys, code):
    model_file = tmp_path / "exits.py"
    model_file.write_text(f"import sys\nsys.exit({code})\n")
    assert cli.main(["derive", str(model_file), "--out", str(tmp_path / "out")]) != 0
    err = capsys.readouterr().err
    assert f"exits.py:2: the model file called sys.exit({code})" in err and "nothing was derived" in err
    assert not (tmp_path / "out").exists()


def _sleigh_kwargs():
    import sympy as sp
    x, phi, x_dot, phi_dot = sp.symbols("x phi x_dot phi_dot", real=True)
    a = sp.Symbol("a", positive=True)
    return dict(name="sled", coordinates=(x, phi), velocities=(x_dot, phi_dot),
                lagrangian=(x_dot**2 + a * phi_dot**2) / 2, constraints=(x_dot - a * phi_dot,),
                dependent=(x,), params=(a,), cyclic={x: 0, phi: 0})


def test_root6_everything_a_user_names_is_the_thing_used_spec_fields_named():
    from knifeedge.derive import ModelSpec, ModelSpecError
    kw = _sleigh_kwargs()
    ModelSpec(**kw)  # the spec as given is accepted
    with pytest.raises(ModelSpecError, match=r"`constraints` must be a tuple or a list.*constraints=\("):
        ModelSpec(**{**kw, "constraints": kw["constraints"][0]})
    with pytest.raises(ModelSpecError, match="`params` must be a tuple or a list"):
        ModelSpec(**{**kw, "params": kw["params"][0]})
    with pytest.raises(ModelSpecError, match="`cyclic` must be a dict"):
        ModelSpec(**{**kw, "cyclic": [kw["coordinates"][0]]})


def test_root6_everything_a_user_names_is_the_thing_used_every_velocity_constrained_refused():
    from knifeedge.derive import ModelSpec, ModelSpecError
    kw = _sleigh_kwargs()
    x, phi = kw["coordinates"]
    x_dot, phi_dot = kw["velocities"]
    with pytest.raises(ModelSpecError, match="every velocity is constrained"):
        ModelSpec(**{**kw, "constraints": (x_dot - kw["params"][0] * phi_dot, phi_dot), "dependent": (x, phi),
                     "constraint_labels": ("roll", "stop")})


# -- root 5: a rigid body is physical, or refused ------------------------------------------------------------------
def _body(preset=None, **changes):
    """An ellipsoidal body with numbers in one preset: a, b, c, h [m], mass, g, principal moments."""
    import sympy as sp
    from knifeedge.derive import rigid
    a, b, c, h, m, g, I1, I2, I3 = sp.symbols("a b c h m g I1 I2 I3", real=True)
    values = {"a": 0.2, "b": 0.03, "c": 0.02, "h": 0.01, "m": 1.0, "g": 9.81, "I1": 2e-4, "I2": 1.6e-3,
              "I3": 1.7e-3, **(preset or {})}
    kw = dict(name="body", mass=m, inertia=sp.diag(I1, I2, I3), shape=rigid.Ellipsoid(a, b, c, centre=(0, 0, h)),
              gravity=g, params=(a, b, c, h, m, g, I1, I2, I3),
              param_units={"a": "m", "b": "m", "c": "m", "h": "m", "m": "kg", "g": "m/s^2",
                           "I1": "kg m^2", "I2": "kg m^2", "I3": "kg m^2"},
              presets={"numbers": values})
    return rigid.RigidBody(**{**kw, **changes})


@pytest.mark.parametrize("preset, match", [
    ({"I1": 1e-4, "I2": 1e-4, "I3": 1.7e-3}, "triangle inequality"),      # 1e-4 + 1e-4 < 1.7e-3
    ({"I1": -2e-4}, "positive definite"),
    ({"m": -1.0}, "`mass` must be positive"),
    ({"h": 0.05}, "above the table at rest"),                               # centre of mass 3 cm under the bottom
    ({"g": -9.81}, "`gravity` must be positive"),
])
def test_root5_a_rigid_body_is_physical_or_refused(preset, match):
    _body().check()  # the same body with the Kane-Levinson numbers (docs/rigid-bodies.md) is accepted
    with pytest.raises(ValueError, match=match):
        _body(preset).check()


def test_root5_a_rigid_body_is_physical_or_refused_units_and_n0_at_build():
    from knifeedge.derive import rigid
    import time
    start = time.perf_counter()
    with pytest.raises(ValueError, match=r"without a unit in `param_units`: \['h'\]"):
        rigid.derive(_body(param_units={"a": "m", "b": "m", "c": "m", "m": "kg", "g": "m/s^2",
                                        "I1": "kg m^2", "I2": "kg m^2", "I3": "kg m^2"}))
    assert time.perf_counter() - start < 5  # reported when the body is checked, before the derivation
    for n0 in ((1j, 0, 1), "up", (0, 0, 0)):
        with pytest.raises(ValueError, match=r"`default_state\['n0'\]`"):
            _body(default_state={"n0": n0}).check()


def test_root5_a_rigid_body_is_physical_or_refused_circle_axis():
    import sympy as sp
    from knifeedge.derive import rigid
    r = sp.Symbol("r", positive=True)
    with pytest.raises(ValueError, match="`axis` of a Circle must be a non-zero vector"):
        rigid.Circle(r, axis=(0, 0, 0))
    n = sp.Matrix([sp.Rational(3, 5), 0, sp.Rational(4, 5)])
    long_axis, unit = rigid.Circle(r, axis=(0, 2, 0)), rigid.Circle(r, axis=(0, 1, 0))
    assert long_axis.axis == (0, 1, 0)
    # the lowest point of the rim is at distance r from the centre whatever length the axis was given with
    assert sp.simplify(long_axis.lowest_point(n) - unit.lowest_point(n)) == sp.zeros(3, 1)


@pytest.mark.parametrize("n0, error", [((1j, 0.0, 1.0), TypeError), ("001", TypeError), ((True, 0, 1), TypeError),
                                       ((0.0, 0.0), ValueError)])
def test_root5_a_rigid_body_is_physical_or_refused_n0_named(n0, error):
    m = ke.load("celt")
    with pytest.raises(error, match="`n0`"):
        m.initial_state(n0=n0, omega0=(0.0, 0.0, 1.0))


@pytest.mark.parametrize("fidelity", ["full", "reduced"])
@pytest.mark.parametrize("change, match", [
    ({"I_xx": 1e-4, "I_yy": 1e-4}, "triangle inequality"),   # 1e-4 + 1e-4 < 1.7e-3 (I_zz)
    ({"I_xy": 5e-3}, "positive definite"),                   # |I_xy| > sqrt(I_xx I_yy)
    ({"h": 0.05}, "above the table at rest"),                # c = 0.02: centre of mass 3 cm under the bottom
])
def test_root5_a_rigid_body_is_physical_or_refused_at_every_parameter_set(fidelity, change, match):
    """The built-in celt (docs/rigid-bodies.md: Kane & Levinson's numbers) given an impossible body at run time."""
    import numpy as np
    m = ke.load("celt", fidelity=fidelity)
    good = m.preset("kane_levinson_1982")
    assert np.array_equal(m.check_params(good), good)
    bad = dict(zip(m.param_names, good), **change)
    with pytest.raises(ValueError, match=match):
        m.params(bad)
    with pytest.raises(ValueError, match=match):
        m.check_params(np.array([bad[k] for k in m.param_names]))
