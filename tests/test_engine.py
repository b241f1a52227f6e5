"""The generic derivation engine, the truncation and the emitter's refusals."""
from dataclasses import replace

import pytest
import sympy as sp

from knifeedge.derive import codegen, engine, models
from knifeedge.derive.rigid import RollingSystem
from knifeedge.generated import MODULES
from knifeedge.derive.truncation import ORDER
from knifeedge.derive.verify import is_zero, tilt_order

# the session's symbolic derivation of every model (`systems`) is built once, in one test worker
pytestmark = pytest.mark.xdist_group("symbolic")


@pytest.mark.parametrize("name", [n if n in ("single_mode", "two_mode") else pytest.param(n, marks=pytest.mark.slow)
                                  for n in sorted({m for m, _ in MODULES})])
def test_reduced_equations_hold_at_a_general_pose(name, systems):
    """Evaluating at phi = x = y = 0 after differentiating is exact: at a random pose, the
    unreduced Lagrange equations with multipliers (solved as a DAE at 30 digits) give the same
    accelerations and multipliers."""
    if isinstance(systems[(name, "full")], RollingSystem):
        pytest.skip("a rigid body has no cyclic coordinates to reduce (tests/test_rigid.py checks it independently)")
    for seed in range(3):
        assert engine.check_symmetry(systems[(name, "full")], seed=seed) < 1e-20


@pytest.mark.parametrize("name", ["single_mode", "two_mode"])
def test_reduced_fidelity_is_the_degree_2_truncation(name, systems):
    """Tilt equations agree with the full ones to O(theta) (residual O(theta^3)); the spin
    equation to O(theta^2) (residual O(theta^4)) -- the order of FINAL1/FINAL2, eqs_2modes."""
    full, red = systems[(name, "full")], systems[(name, "reduced")]
    n_tilt = len(full.spec.small)
    for k, (a, b) in enumerate(zip(full.explicit, red.explicit)):
        spin = k >= n_tilt
        assert tilt_order(b, full) == (2 if spin else 1)
        # (the single-mode spin equation is exactly quadratic: L^2 phi_ddot = -g D theta^2)
        assert tilt_order(a - b, full) in ((4, None) if spin else (3,))
    assert ORDER == 2


@pytest.mark.slow
def test_mass_matrix_and_explicit_forms_agree(systems):
    for (name, fid), s in systems.items():
        if fid != "full" or isinstance(s, RollingSystem):  # rigid bodies (square roots): test_rigid.py, numerically
            continue
        residual = s.mass_matrix * s.explicit - s.forcing
        assert all(is_zero(e) for e in residual), name


def test_two_mode_mass_matrix_determinant(systems):
    """det = ell^2 L^2 (L^2 + ell^2 + D^2 theta_alpha^2 sin^2 alpha): positive, never singular."""
    s = systems[("two_mode", "full")]
    th_a = models.theta_alpha
    expected = models.ell**2 * models.L**2 * (models.L**2 + models.ell**2 + models.D**2 * th_a**2 * sp.sin(models.alpha)**2)
    assert is_zero(s.mass_matrix.det() - expected)


def test_engine_rejects_nonlinear_constraints():
    spec = models.MODELS["single_mode"]
    with pytest.raises(ValueError, match="affine in the velocities") as err:
        replace(spec, constraints=(spec.constraints[0] ** 2, spec.constraints[1]))
    assert "test_engine.py:" in str(err.value)  # where the faulty spec was built


def test_engine_rejects_a_state_that_does_not_close():
    """If phi is declared non-cyclic-free but x is not substituted, the dependent velocity stays."""
    spec = models.MODELS["single_mode"]
    # declare only y as dependent: x_dot is then an independent velocity the state does not hold
    with pytest.raises(ValueError):  # refused when built (x in the pose is not cyclic) or when derived
        engine.derive(replace(spec, dependent=(models.y,), cyclic={models.y: 0, models.phi: 0},
                              constraints=(spec.constraints[0],), constraint_labels=("vinculo1",)))
    with pytest.raises(ValueError, match="do not determine the velocities of `dependent`"):
        engine.derive(replace(spec, dependent=(models.y,), cyclic={models.y: 0, models.phi: 0}, pose=(models.phi,),
                              constraints=(spec.constraints[0],), constraint_labels=("vinculo1",)))


def test_emitter_refuses_undeclared_symbols():
    stray = sp.Symbol("stray")
    with pytest.raises(ValueError, match="undeclared symbols"):
        codegen.cse_block([models.theta + stray], ["ds[0]"], {models.theta})
