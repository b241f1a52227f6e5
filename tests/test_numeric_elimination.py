"""Numeric elimination of the multipliers (issue 22 item 3): the generated right-hand side solves
``[[M, -A^T], [A, 0]] [q_ddot, lambda] = [f, -c]`` at every call instead of evaluating a closed form.

The independent check is the closed form itself: the same model (the rolling disk of examples/rolling_disk.py)
derived both ways must agree at random states, accelerations and multipliers to 1e-12, and the numeric module
must pass the derivation's own comparison with the unreduced equations at a general pose (``check_symmetry``).
"""
import dataclasses
import importlib.util
from pathlib import Path

import numpy as np
import pytest

import knifeedge as ke

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _spec(file, name):
    spec = importlib.util.spec_from_file_location(f"_example_{name}", EXAMPLES / file)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.MODEL


@pytest.fixture(scope="module")
def disks(tmp_path_factory):
    from knifeedge.derive import emit
    from knifeedge.derive.cli import derive_specs

    out = tmp_path_factory.mktemp("elimination")
    disk = _spec("rolling_disk.py", "disk")[0]
    specs = [dataclasses.replace(disk, name=f"disk_{mode}", elimination=mode) for mode in ("symbolic", "numeric")]
    emit.write_all(out, derive_specs(specs), registry=False)
    return ke.load("disk_symbolic", path=out), ke.load("disk_numeric", path=out), out


@pytest.mark.slow  # derives the disk twice (about 15 s of a worker): the slow tier
def test_header_says_which_elimination(disks):
    symbolic, numeric, out = disks
    assert symbolic.module.ELIMINATION == "symbolic" and numeric.module.ELIMINATION == "numeric"
    assert "Multipliers eliminated numerically" in (out / "disk_numeric_full.py").read_text()
    assert "_lu_solve" not in (out / "disk_symbolic_full.py").read_text()


@pytest.mark.slow  # derives the disk twice (about 15 s of a worker): the slow tier
def test_numeric_and_symbolic_agree_at_random_states(disks):
    symbolic, numeric, _ = disks
    rng = np.random.default_rng(7)
    p = symbolic.params(g=9.81, r=0.13)
    for _ in range(50):
        s = rng.uniform(-1.2, 1.2, 4) * np.array([1.0, 5.0, 5.0, 20.0])
        a, b = symbolic.module.rhs(0.0, s, p), numeric.module.rhs(0.0, s, p)
        assert np.allclose(b, a, rtol=1e-12, atol=1e-12 * np.max(np.abs(a)))
        la, lb = symbolic.module.multipliers(s, p), numeric.module.multipliers(s, p)
        assert np.allclose(lb, la, rtol=1e-12, atol=1e-12 * np.max(np.abs(la)))
        assert numeric.module.energy(s, p) == pytest.approx(symbolic.module.energy(s, p), rel=1e-13)


@pytest.mark.slow  # derives the disk twice (about 15 s of a worker): the slow tier
def test_numeric_jacobians_equal_the_closed_forms(disks):
    """The numeric model's Jacobians (implicit differentiation of the multipliers' system, kkt_emit) equal those
    derived from the closed form of the same disk (derivation/jacobian.py), at random states."""
    symbolic, numeric, _ = disks
    rng = np.random.default_rng(11)
    p = symbolic.params(g=9.81, r=0.13)
    for _ in range(20):
        s = rng.uniform(-1.2, 1.2, 4) * np.array([1.0, 5.0, 5.0, 20.0])
        for f in ("jacobian", "jacobian_p"):
            a, b = getattr(symbolic, f)(s, p), getattr(numeric, f)(s, p)
            assert np.allclose(b, a, rtol=1e-11, atol=1e-11 * np.max(np.abs(a)))


@pytest.mark.slow  # derives the disk twice (about 15 s of a worker): the slow tier
def test_numeric_jvp_is_the_closed_forms_jacobian_times_the_columns(disks):
    """``jvp_into`` of the numeric model (forward mode through the solve's program) writes the closed form's rates
    and its Jacobian times the columns of ``V``."""
    symbolic, numeric, _ = disks
    rng = np.random.default_rng(5)
    p = symbolic.params(g=9.81, r=0.13)
    for _ in range(10):
        s = rng.uniform(-1.2, 1.2, 4) * np.array([1.0, 5.0, 5.0, 20.0])
        V, ds, out = rng.standard_normal((4, 3)), np.empty(4), np.empty((4, 3))
        numeric.module.jvp_into.py_func(s, p, V, ds, out)
        want = symbolic.jacobian(s, p) @ V
        assert np.allclose(out, want, rtol=1e-11, atol=1e-11 * np.max(np.abs(want)))
        assert np.allclose(ds, symbolic.module.rhs(0.0, s, p), rtol=1e-12, atol=1e-12 * np.max(np.abs(ds)))


@pytest.mark.slow  # derives the two-body model (6-12 s) and compiles it: the slow tier
def test_disk_pendulum_jacobian_against_central_differences(disk_pendulum):
    """The pendulum on the disk (numeric elimination): the exact Jacobian against 8th-order central differences."""
    m = disk_pendulum
    p = m.params(m.default_params) if m.default_params else None
    rng = np.random.default_rng(3)
    c = np.array([1 / 280, -4 / 105, 1 / 5, -4 / 5, 0, 4 / 5, -1 / 5, 4 / 105, -1 / 280])
    for _ in range(3):
        s = rng.uniform(-0.8, 0.8, m.n_state)
        J = m.jacobian(s, p)
        fd = np.empty_like(J)
        for j in range(m.n_state):
            h = 1e-3 * max(1.0, abs(s[j]))
            cols = [m.rhs(0.0, s + (k - 4) * h * np.eye(m.n_state)[j], p) for k in range(9)]
            fd[:, j] = sum(ck * col for ck, col in zip(c, cols)) / h
        assert np.allclose(J, fd, rtol=1e-8, atol=1e-8 * np.max(np.abs(J)))


@pytest.mark.slow  # derives the disk twice (about 15 s of a worker): the slow tier
def test_numeric_run_conserves_energy(disks):
    """The rolling disk conserves its energy (Jacobi integral): a run through the numeric right-hand side holds it."""
    _, numeric, _ = disks
    p = numeric.params(g=9.81, r=0.1)
    r = ke.simulate(numeric, [0.3, 0.5, 0.0, 9.0], (0.0, 3.0), p, rtol=1e-11, atol=1e-13)
    e = r.energy
    assert np.max(np.abs(e - e[0])) < 1e-9 * abs(e[0])


def test_numeric_is_refused_with_affine_constraints():
    import sympy as sp

    from knifeedge.derive import ModelSpec, ModelSpecError, derive, t

    x, phi, x_dot, phi_dot = sp.symbols("x phi x_dot phi_dot", real=True)
    spec = ModelSpec(name="turned", coordinates=(x, phi), velocities=(x_dot, phi_dot),
                     lagrangian=(x_dot**2 + phi_dot**2) / 2, constraints=(phi_dot - sp.sin(t),), dependent=(phi,),
                     params=(), cyclic={phi: 0}, elimination="numeric")
    with pytest.raises(ModelSpecError, match="elimination='symbolic'"):
        derive(spec)
    with pytest.raises(ModelSpecError, match="`elimination` must be"):
        dataclasses.replace(spec, elimination="lu")


@pytest.fixture(scope="module")
def disk_pendulum(tmp_path_factory):
    from knifeedge import cli

    out = tmp_path_factory.mktemp("disk_pendulum")
    assert cli.main(["derive", str(EXAMPLES / "disk_pendulum.py"), "--out", str(out)]) == 0
    return ke.load("disk_pendulum", path=out)


@pytest.mark.slow  # derives the two-body model (6-12 s) and compiles it: the slow tier
def test_disk_pendulum_is_numeric_and_straight_line(disk_pendulum):
    """Four independent accelerations: ``elimination="auto"`` solves numerically, in code the derivation writes
    as IR too (the module carries it), the pose's velocity solve with its pivot choices (selects) included: numba's
    bits (tests/test_ir_emit.py)."""
    from test_ir_emit import check_module_ir

    assert disk_pendulum.module.ELIMINATION == "numeric"
    assert "define" in disk_pendulum.module.LLVM_IR["rhs_q_into"]
    assert "select i1" in disk_pendulum.module.LLVM_IR["rhs_pose_q_into"]
    check_module_ir(disk_pendulum.module, "disk_pendulum")


@pytest.mark.slow  # derives the two-body model (6-12 s) and compiles it: the slow tier
def test_disk_pendulum_matches_the_unreduced_equations(disk_pendulum):
    """Two bodies: the compiled right-hand side and multipliers against the full DAE
    ``[[M, -A^T], [A, 0]] [q_ddot, lambda] = [-h, -c]`` solved in 30-digit arithmetic from the Lagrangian
    (``engine.unreduced_accelerations``, independent of the null-space reduction and of the emitted code)."""
    import sympy as sp

    from knifeedge.derive import engine

    spec = _spec("disk_pendulum.py", "pendulum")
    m = disk_pendulum
    rng = np.random.default_rng(3)
    p = m.params(g=9.81, r=0.1, l=0.07, mu=0.4)
    for _ in range(2):
        s = rng.uniform(-1, 1, 6) * np.array([1.0, 3.0, 5.0, 5.0, 5.0, 20.0])
        values = dict(zip(map(str, m.state_names), s)) | dict(zip(m.param_names, p))
        values |= {"x": 0.3, "y": -0.2, "q1": 0.7, "q3": 1.1}  # a general pose: the symmetry is checked too
        symbols = {str(x): x for x in spec.coordinates + spec.velocities + spec.params}
        acc, lam = engine.unreduced_accelerations(spec, {symbols[k]: sp.Float(v, 30) for k, v in values.items()})
        ds = m.module.rhs(0.0, s, p)
        rates = dict(zip(m.state_names, ds))
        expected = dict(zip([str(spec.velocity_of(q)) for q in spec.independent], map(float, acc)))
        for name, rate in rates.items():
            if name.endswith("_dot"):
                assert rate == pytest.approx(expected[name], rel=1e-12, abs=1e-12 * max(map(abs, expected.values())))
        assert np.allclose(m.module.multipliers(s, p), np.array(lam, dtype=float), rtol=1e-12, atol=1e-12)


@pytest.mark.slow  # derives the two-body model (6-12 s) and compiles it: the slow tier
def test_disk_pendulum_conserves_energy(disk_pendulum):
    """Rolling without slipping and a frictionless axle do no work: the energy holds along a run."""
    m = disk_pendulum
    p = m.params(g=9.81, r=0.1, l=0.07, mu=0.4)
    r = ke.simulate(m, m.state(q2=0.1, q4=0.5, q1_dot=0.2, q2_dot=0.0, q4_dot=1.0, q3_dot=9.0), (0.0, 3.0), p,
                    rtol=1e-11, atol=1e-13)
    e = r.energy
    assert np.max(np.abs(e - e[0])) < 1e-9 * abs(e[0])


@pytest.mark.slow  # derives the two-body model (6-12 s) and compiles it: the slow tier
def test_doc_section_on_two_bodies_runs(tmp_path, monkeypatch):
    """docs/your-own-model.md section 9 as written (tags ``bodies-file=``, ``bodies-example``)."""
    import re
    import shlex

    from knifeedge.cli import main
    import docs_blocks
    from test_your_own_model import DOC, _blocks

    monkeypatch.chdir(tmp_path)
    files = re.findall(r"```python bodies-file=(\w+\.py)\n(.*?)```", DOC.read_text(), flags=re.S)
    assert [name for name, _ in files] == ["disk_pendulum.py"]
    (tmp_path / "disk_pendulum.py").write_text(files[0][1])
    for line in (ln for block in _blocks("sh bodies-example") for ln in block.splitlines()):
        assert main(shlex.split(line)[1:]) == 0, line
    namespace: dict = {}
    for code in _blocks("python bodies-example"):
        docs_blocks.run(code, str(DOC), namespace)
