"""Inputs on the one-body rigid path (issue 22): ``RigidBody(torque=..., inputs=...)`` derived by ``rigid.derive``.

A uniform disk (unit mass, radius ``r``) rolling on its edge, driven by a motor torque ``tau`` about its axle
given at run time, written twice: with the rigid-body front end (state: the upward vertical ``n`` and the
angular velocity ``omega`` in body axes, Newton--Euler with the contact force eliminated, ``derivation/rigid.py``)
and through ``multibody.assemble`` with ``multibody.Torque`` (Euler angles, the Lagrangian with multipliers
eliminated by the engine: an independent derivation).  The same sampled torque must move both the same way (n and
omega of the Euler-angle run mapped by ``n = R^T e_z``, ``omega = B q_dot``), to 1e-10; along the run the rigid
model's ``energy(t) = energy(t0) + int torque . omega dt`` (its ``power_input``) to 1e-9 relative.
"""
import numpy as np
import pytest
import sympy as sp

import knifeedge as ke
from knifeedge.derive.rigid import Circle, RigidBody

g, r = sp.symbols("g r", positive=True)
tau = sp.Symbol("tau", real=True)
DISK = dict(mass=1, inertia=sp.diag(r**2 / 4, r**2 / 2, r**2 / 4), shape=Circle(r, axis=(0, 1, 0)), gravity=g,
            params=(g, r), param_units={"g": "m/s^2", "r": "m"}, heading_axis=(0, 1, 0))
SAMPLE_T = np.array([0.0, 0.8, 1.5, 2.4, 3.0])
SAMPLE_U = np.array([0.0, 0.004, -0.003, 0.002, 0.0])


def driven_body(**kw) -> RigidBody:
    return RigidBody(name="rigid_driven_disk", **{**DISK, "torque": (0, tau, 0), "inputs": (tau,), **kw})


def test_torques_and_inputs_that_cannot_be_built_are_refused():
    with pytest.raises(ValueError, match=r"`torque` holds symbols that are not parameters.*\['tau'\].*declare "
                                         r"run-time quantities in `inputs`"):
        driven_body(inputs=()).check()
    with pytest.raises(ValueError, match=r"`inputs` \['tau'\] must appear in `torque`"):
        driven_body(torque=None).check()
    with pytest.raises(ValueError, match=r"has fidelity 'full' only.*leave `small` empty"):
        driven_body(small=("n_x",)).check()
    clash = sp.Symbol("omega_x", real=True)
    with pytest.raises(ValueError, match=r"`inputs` names clash with parameter, state or slot names: \['omega_x'\]"):
        driven_body(torque=(0, clash, 0), inputs=(clash,)).check()
    driven_body().check()


@pytest.fixture(scope="module")
def models(tmp_path_factory):
    from knifeedge.derive import emit
    from knifeedge.derive.cli import derive_specs
    from knifeedge.derive.multibody import Torque, assemble

    out = tmp_path_factory.mktemp("rigid_inputs")
    base = RigidBody(name="disk", **{k: v for k, v in DISK.items() if k not in ("param_units", "heading_axis")})
    euler = assemble("euler_driven_disk", base, [], params=(g, r), gravity=g, units={g: "m/s^2", r: "m"},
                     loads=(Torque(base, (0, tau, 0)),), inputs=(tau,))
    emit.write_all(out, derive_specs([euler, driven_body()]), registry=False)
    return ke.load("euler_driven_disk", path=out), ke.load("rigid_driven_disk", path=out)


def _rigid_state(euler_model, y):
    """``(n, omega)`` in body axes of Euler-angle states ``y`` (columns): ``n = R^T e_z``, ``omega = B q_dot``
    (``derivation.rigid.euler_angle_maps``, the angles of ``multibody``)."""
    from knifeedge.derive.rigid import a1, a1_dot, a2, a2_dot, euler_angle_maps, psi_dot

    _, n, B = euler_angle_maps()
    f = sp.lambdify((a1, a2, psi_dot, a1_dot, a2_dot), [*n, *(B * sp.Matrix([psi_dot, a1_dot, a2_dot]))])
    s = dict(zip(euler_model.state_names, np.atleast_2d(np.asarray(y, dtype=float).T).T))
    return np.array([np.broadcast_to(np.asarray(v, dtype=float), s["a1"].shape)
                     for v in f(s["a1"], s["a2"], s["psi_dot"], s["a1_dot"], s["a2_dot"])])


@pytest.mark.slow  # derives two models and compiles their kernels
def test_a_driven_disk_moves_as_the_same_disk_through_multibody(models):
    euler, rigid = models
    y0 = euler.state(a1=0.15, a2=0.3, a1_dot=0.0, a2_dot=12.0, psi_dot=0.4)
    n_w = _rigid_state(euler, y0)[:, 0]
    y0_rigid = np.append(n_w, n_w[:3] @ n_w[3:])  # omega_n = omega . n
    grids = [np.linspace(a, b, 401) for a, b in zip(SAMPLE_T[:-1], SAMPLE_T[1:])]
    t_eval = np.unique(np.concatenate(grids))
    given = {"tau": (SAMPLE_T, SAMPLE_U)}
    one = ke.simulate(euler, y0, (0.0, 3.0), euler.params(g=9.81, r=0.1), t_eval=t_eval, rtol=1e-12, atol=1e-14,
                      inputs=given)
    two = ke.simulate(rigid, y0_rigid, (0.0, 3.0), rigid.params(g=9.81, r=0.1), t_eval=t_eval, rtol=1e-12,
                      atol=1e-14, inputs=given)
    assert one.success and two.success
    assert np.max(np.abs(_rigid_state(euler, one.y) - two.y[:6])) < 1e-10
    assert np.ptp(two["omega_y"]) > 0.1  # the motor changed the rolling rate
    # the energy balance of the rigid model: energy(t) - energy(0) = int power_input dt (Simpson, interval by interval)
    power = rigid.power_input(two.y, two.p, two.t, inputs=two.inputs)
    assert np.allclose(power, np.interp(two.t, SAMPLE_T, SAMPLE_U) * two["omega_y"],
                       rtol=1e-12, atol=1e-15)
    work, total = [0.0], 0.0
    for grid in grids:
        sel = np.isin(two.t, grid)
        h, f = grid[1] - grid[0], power[sel]
        total += h / 3 * (f[0] + f[-1] + 4 * f[1:-1:2].sum() + 2 * f[2:-1:2].sum())
        work.append(total)
    energy = two.energy
    at_samples = energy[np.isin(two.t, SAMPLE_T)]
    assert np.max(np.abs(at_samples - (energy[0] + np.array(work)))) < 1e-9 * np.max(np.abs(energy))
