"""Energy right or absent (issue 22, item 4).

The skate on an inclined plane (Neimark & Fufaev, *Dynamics of Nonholonomic
Systems*, chapter III; Bloch, *Nonholonomic Mechanics and Control*, section
1.6): a knife edge of radius of gyration ``k`` on a plane tilted by
``alpha``, ``x`` down the slope, ``L = (x_dot^2 + y_dot^2 + k^2 phi_dot^2)/2 +
g sin(alpha) x``.  The equations do not depend on ``x`` or ``y`` (the slope's
force is constant), so both are cyclic, but the energy
``v^2/2 + k^2 phi_dot^2/2 - g sin(alpha) x`` does: it must hold the potential
of ``x`` (read from the pose), and is then conserved (the closed forms:
``phi_dot`` constant, ``dv/dt = g sin(alpha) cos(phi)``).
"""
import math

import numpy as np
import pytest
import sympy as sp

import knifeedge as ke
from knifeedge.derive import ModelSpec, emit
from knifeedge.derive.cli import DeriveError, derive_specs

g, alpha, k = sp.symbols("g alpha k", positive=True)
x, y, phi, x_dot, y_dot, phi_dot, v = sp.symbols("x y phi x_dot y_dot phi_dot v", real=True)


def skate(**overrides) -> ModelSpec:
    kw = dict(name="incline_skate", coordinates=(x, y, phi), velocities=(x_dot, y_dot, phi_dot),
              lagrangian=(x_dot**2 + y_dot**2 + k**2 * phi_dot**2) / 2 + g * sp.sin(alpha) * x,
              constraints=(x_dot * sp.sin(phi) - y_dot * sp.cos(phi),), dependent=(y,), params=(g, alpha, k),
              cyclic={x: 0, y: 0}, pose=(x, y),
              quasi_velocities=((v, x_dot, x_dot * sp.cos(phi) + y_dot * sp.sin(phi)),))
    kw.update(overrides)
    return ModelSpec(**kw)


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    out = tmp_path_factory.mktemp("energy")
    emit.write_all(out, derive_specs([skate()]), registry=False)
    return out


def test_energy_holds_the_potential_of_a_cyclic_coordinate(folder):
    m = ke.load("incline_skate", path=folder, pose=True)
    assert m.state_names == ("phi", "phi_dot", "v", "x", "y")
    p = m.params(g=9.81, alpha=0.3, k=0.4)
    y0 = np.array([0.2, 0.7, 0.5, 0.0, 0.0])
    r = ke.simulate(m, y0, (0.0, 10.0), p, rtol=1e-11, atol=1e-13, t_eval=np.linspace(0, 10, 101))
    assert np.allclose(r["phi_dot"], 0.7, rtol=1e-12)
    gs = 9.81 * math.sin(0.3)
    v_exact = 0.5 + gs / 0.7 * (np.sin(0.2 + 0.7 * r.t) - math.sin(0.2))
    assert np.max(np.abs(r["v"] - v_exact)) < 1e-8
    e = r.energy
    assert e[0] == pytest.approx(0.5 * 0.25 + 0.5 * 0.16 * 0.49, rel=1e-14)
    assert np.ptp(r["x"]) > 1.0 and np.ptp(e) < 1e-9 * abs(e[0])
    with pytest.raises(ValueError, match="load the model with `pose=True`"):
        ke.load("incline_skate", path=folder).energy(y0[:3], p)


def test_a_potential_the_state_cannot_read_is_refused():
    with pytest.raises(DeriveError, match=r"cyclic coordinates \['x'\].*add them to `pose`"):
        derive_specs([skate(pose=(y,))])
