"""Several rigid bodies joined by pins and sliders (issue 22 item 3): ``knifeedge.derive.multibody.assemble``.

Written as a user would (examples/disk_pendulum_bodies.py): the disk with a pendulum on its axle, two
``RigidBody`` and a ``Pin``, against examples/disk_pendulum.py whose kinetic energies are written by hand: the same
accelerations, contact forces and energy at random states to 1e-12, after the change of coordinates
``q1 = psi, q2 = a1, q3 = a2, q4 = a2 + phi`` (the pin's angle is relative to the disk; the hand-written ``q4`` is
measured from the lean frame).
"""
import importlib.util
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import knifeedge as ke
from knifeedge.derive.multibody import Pin, Slider, assemble
from knifeedge.derive.rigid import Circle, RigidBody

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _spec(file):
    spec = importlib.util.spec_from_file_location(f"_example_{Path(file).stem}", EXAMPLES / file)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.MODEL


@pytest.fixture(scope="module")
def derived(tmp_path_factory):
    from knifeedge.derive import emit
    from knifeedge.derive.cli import derive_specs

    out = tmp_path_factory.mktemp("multibody")
    specs = [_spec("disk_pendulum_bodies.py"), _spec("disk_pendulum.py")]
    emit.write_all(out, derive_specs(specs), registry=False)
    return {s.name: ke.load(s.name, path=out) for s in specs}


@pytest.mark.slow  # derives two models (about 20 s of a worker): the slow tier
def test_two_bodies_and_a_pin_give_the_hand_written_disk_with_a_pendulum(derived):
    bodies, hand = derived["disk_pendulum_bodies"], derived["disk_pendulum"]
    assert bodies.state_names == ("a1", "a2", "phi", "a1_dot", "a2_dot", "phi_dot", "psi_dot")
    assert hand.state_names == ("q2", "q4", "q2_dot", "q4_dot", "q1_dot", "q3_dot")
    rng = np.random.default_rng(3)
    for _ in range(50):
        q2, q3, q4 = rng.uniform(-1.3, 1.3), rng.uniform(-4, 4), rng.uniform(-4, 4)
        q1d, q2d, q3d, q4d = rng.normal(size=4) * 4
        values = dict(g=9.81, r=rng.uniform(0.05, 0.3), l=rng.uniform(0.02, 0.2), mu=rng.uniform(0.1, 2.0))
        s_hand = np.array([q2, q4, q2d, q4d, q1d, q3d])
        s_bodies = np.array([q2, q3, q4 - q3, q2d, q3d, q4d - q3d, q1d])
        d = hand.module.rhs(0.0, s_hand, hand.params(**values))
        q2dd, q4dd, q1dd, q3dd = d[2:]
        expected = np.array([q2d, q3d, q4d - q3d, q2dd, q3dd, q4dd - q3dd, q1dd])
        got = bodies.module.rhs(0.0, s_bodies, bodies.params(**values))
        np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-12 * np.max(np.abs(expected)))
        # contact forces along and across the heading: the same multipliers
        np.testing.assert_allclose(bodies.module.multipliers(s_bodies, bodies.params(**values)),
                                   hand.module.multipliers(s_hand, hand.params(**values)), rtol=1e-12, atol=1e-12)
        assert bodies.module.energy(s_bodies, bodies.params(**values)) == pytest.approx(
            hand.module.energy(s_hand, hand.params(**values)), rel=1e-12)


g, r, l, mu = sp.symbols("g r l mu", positive=True)
phi, s = sp.symbols("phi s", real=True)
DISK = RigidBody(name="disk", mass=1, inertia=sp.diag(r**2 / 4, r**2 / 2, r**2 / 4), shape=Circle(r, axis=(0, 1, 0)),
                 gravity=g, params=(g, r))
BOB = RigidBody(name="bob", mass=mu, inertia=sp.zeros(3), shape=None, gravity=g, params=(mu,))


def _assemble(joints, **kw):
    return assemble("two", kw.pop("base", DISK), joints, params=(g, r, l, mu), gravity=g, **kw)


def test_joints_that_cannot_be_built_are_refused_with_the_fix():
    pin = dict(point=(0, 0, 0), axis=(0, 1, 0), angle=phi, child_point=(0, 0, l))
    other = RigidBody(name="other", mass=mu, inertia=sp.zeros(3), shape=None, gravity=g, params=(mu,))
    with pytest.raises(ValueError, match="its parent 'other' is neither the base nor the child of an earlier joint; "
                                         "list the joints from the base outwards"):
        _assemble([Pin(other, BOB, **pin)])
    with pytest.raises(ValueError, match="its child 'bob' is already joined .* write the ModelSpec with `holonomic`"):
        _assemble([Pin(DISK, BOB, **pin), Slider(DISK, BOB, point=(0, 0, 0), axis=(0, 0, 1), coordinate=s)])
    with pytest.raises(ValueError, match=r"`joints\[0\].axis` must be a non-zero vector"):
        _assemble([Pin(DISK, BOB, **{**pin, "axis": (0, 0, 0)})])
    with pytest.raises(ValueError, match=r"`joints\[0\]` must be a Pin or a Slider"):
        _assemble([(DISK, BOB)])
    with pytest.raises(ValueError, match="`base` must be a RigidBody with a `shape`"):
        _assemble([], base=BOB)
    with pytest.raises(ValueError, match=r"\['cyclic'\] are set by assemble from the bodies and joints; remove them"):
        _assemble([Pin(DISK, BOB, **pin)], cyclic={})
    with pytest.raises(ValueError, match="`symmetric` may name the base's tilts a1, a2 only"):
        _assemble([Pin(DISK, BOB, **pin)], symmetric=(phi,))


def test_the_disk_alone_rolls_with_the_textbook_constraints():
    """Rolling of a disk of radius r, by hand: the contact is ``C - r e_z`` (lean frame ``Rz(psi) Rx(a1)``, axes
    ``e_x`` the heading, ``e_y`` the axle), ``omega = psi_dot Z + a1_dot e_x + a2_dot e_y``; the contact at rest gives
    ``v_C = r omega x e_z``: along the heading ``r omega.e_y = r (a2_dot + psi_dot sin a1)``, across it
    (``h = Z x e_x``) ``r omega.(e_z x h) = -r a1_dot cos a1``."""
    from knifeedge.derive.rigid import a1, a1_dot, a2_dot, psi, psi_dot, x_dot, y_dot

    spec = _assemble([Pin(DISK, BOB, point=(0, 0, 0), axis=(0, 1, 0), angle=phi, child_point=(0, 0, l))])
    along, across = spec.constraints
    assert sp.simplify(along - (x_dot * sp.cos(psi) + y_dot * sp.sin(psi) - r * a2_dot - r * psi_dot * sp.sin(a1))) == 0
    assert sp.simplify(across - (-x_dot * sp.sin(psi) + y_dot * sp.cos(psi) + r * a1_dot * sp.cos(a1))) == 0
    assert spec.dependent == (sp.Symbol("x", real=True), sp.Symbol("y", real=True))
    assert spec.defined_at.startswith(__file__)  # errors name the user's line, not the front end's


def _run_doc_section(tmp_path, monkeypatch, tag: str, files: list) -> None:
    """docs/your-own-model.md's blocks ``python {tag}-file=NAME.py``, ``sh {tag}-example`` and
    ``python {tag}-example`` as written: the files, the commands, then the examples with their printed values."""
    import re
    import shlex

    from knifeedge.cli import main
    import docs_blocks
    from test_your_own_model import DOC, _blocks

    monkeypatch.chdir(tmp_path)
    found = re.findall(rf"```python {tag}-file=(\w+\.py)\n(.*?)```", DOC.read_text(), flags=re.S)
    assert [name for name, _ in found] == files
    for name, code in found:
        (tmp_path / name).write_text(code)
    for line in (ln for block in _blocks(f"sh {tag}-example") for ln in block.splitlines()):
        assert main(shlex.split(line)[1:]) == 0, line
    namespace: dict = {}
    for code in _blocks(f"python {tag}-example"):
        docs_blocks.run(code, "docs/your-own-model.md", namespace)


def test_the_docs_show_the_example_file_as_it_is():
    import re

    from test_your_own_model import DOC

    shown = re.findall(r"```python multibody-file=disk_pendulum_bodies.py\n(.*?)```", DOC.read_text(), flags=re.S)
    assert shown == [(EXAMPLES / "disk_pendulum_bodies.py").read_text()]


@pytest.mark.slow  # derives the two-body model and compiles it: the slow tier
def test_doc_section_on_bodies_joined_by_pins_runs(tmp_path, monkeypatch):
    _run_doc_section(tmp_path, monkeypatch, "multibody", ["disk_pendulum_bodies.py"])


@pytest.mark.slow  # derives the snakeboard (about 20 s of a worker) and compiles it: the slow tier
def test_doc_section_on_the_snakeboard_gait_runs(tmp_path, monkeypatch):
    """Section 12: the snakeboard's speed against its equation derived by hand (d'Alembert along the free
    direction, written in the section), and its forward drift under the gait."""
    _run_doc_section(tmp_path, monkeypatch, "gait", ["snakeboard.py"])
