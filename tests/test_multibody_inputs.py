"""Inputs in models built from ``RigidBody`` bodies (issue 22 item 3 with item 1): a motor torque about a rolling
disk's axle, given at run time, through ``knifeedge.derive.multibody.Torque``.

Checked against two independent facts: (1) upright and rolling straight, the disk (unit mass, radius ``r``, axle
moment ``r^2/2``) obeys ``(r^2/2 + r^2) a2_ddot = tau`` (the torque about the axle against the rolling contact's
moment arm: Lamb, *Dynamics*, or any text's rolling cylinder under a couple); (2) along a general run,
``energy(t) = energy(t0) + int tau omega_y dt`` (the torque's work; no dissipation), integrated by Simpson's rule
between the sample times of the input, to 1e-9 relative at rtol 1e-11 (issue 22, "How it will be checked").
"""
import numpy as np
import pytest
import sympy as sp

import knifeedge as ke
from knifeedge.derive.multibody import Torque, assemble
from knifeedge.derive.rigid import Circle, RigidBody

g, r = sp.symbols("g r", positive=True)
tau = sp.Symbol("tau", real=True)
DISK = RigidBody(name="disk", mass=1, inertia=sp.diag(r**2 / 4, r**2 / 2, r**2 / 4), shape=Circle(r, axis=(0, 1, 0)),
                 gravity=g, params=(g, r))
SAMPLE_T = np.array([0.0, 0.8, 1.5, 2.4, 3.0])
SAMPLE_U = np.array([0.0, 0.004, -0.003, 0.002, 0.0])


def driven_disk():
    return assemble("driven_disk", DISK, [], params=(g, r), gravity=g, units={g: "m/s^2", r: "m"},
                    loads=(Torque(DISK, (0, tau, 0)),), inputs=(tau,))


@pytest.fixture(scope="module")
def model(tmp_path_factory):
    from knifeedge.derive import emit
    from knifeedge.derive.cli import derive_specs

    out = tmp_path_factory.mktemp("driven_disk")
    emit.write_all(out, derive_specs([driven_disk()]), registry=False)
    return ke.load("driven_disk", path=out)


def test_the_torque_is_a_generalized_force_on_the_axle_and_the_heading():
    """omega_y = a2_dot + psi_dot sin(a1) in the disk's axes (R = Rz(psi) Rx(a1) Ry(a2)): Q = tau d omega_y / d q_dot."""
    from knifeedge.derive.rigid import a1

    spec = driven_disk()
    assert [sp.simplify(q) for q in spec.forces] == [0, 0, tau * sp.sin(a1), 0, tau]
    assert spec.inputs == (tau,)


def test_loads_that_cannot_be_built_are_refused():
    other = RigidBody(name="bob", mass=1, inertia=sp.zeros(3), shape=None, gravity=g, params=(g,))
    with pytest.raises(ValueError, match=r"`loads\[0\]` must be a Torque on the base or on a body of `joints`"):
        assemble("d", DISK, [], params=(g, r), gravity=g, loads=(Torque(other, (0, tau, 0)),), inputs=(tau,))
    with pytest.raises(ValueError, match="give either `loads`"):
        assemble("d", DISK, [], params=(g, r), gravity=g, loads=(Torque(DISK, (0, tau, 0)),), inputs=(tau,),
                 forces=(0, 0, 0, 0, tau))


@pytest.mark.slow  # derives a model and compiles its kernel: the slow tier
def test_upright_rolling_accelerates_as_the_closed_form(model):
    rv, tv = 0.1, 0.02
    p = model.params(g=9.81, r=rv)
    s = model.state(a1=0.0, a2=0.0, a1_dot=0.0, a2_dot=5.0, psi_dot=0.0)
    d = model.module.rhs(0.0, s, np.append(p, [0.0, tv, 0.0]))  # slots: time origin, tau, its rate
    rates = dict(zip(model.state_names, d))
    assert rates["a2_dot"] == pytest.approx(tv / (1.5 * rv**2), rel=1e-13)
    assert rates["a1_dot"] == pytest.approx(0.0, abs=1e-13) and rates["psi_dot"] == pytest.approx(0.0, abs=1e-13)


@pytest.mark.slow
def test_energy_balance_with_a_torque_input(model):
    p = model.params(g=9.81, r=0.1)
    t0, t1 = 0.0, 3.0
    cuts = SAMPLE_T
    grids = [np.linspace(a, b, 401) for a, b in zip(cuts[:-1], cuts[1:])]
    t_eval = np.unique(np.concatenate(grids))
    y0 = model.state(a1=0.15, a2=0.0, a1_dot=0.0, a2_dot=12.0, psi_dot=0.4)
    run = ke.simulate(model, y0, (t0, t1), p, t_eval=t_eval, rtol=1e-11, atol=1e-13,
                      inputs={"tau": (SAMPLE_T, SAMPLE_U)})
    assert run.success
    power = model.power_input(run.y, p, run.t, inputs=run.inputs)
    work, total = [0.0], 0.0
    for grid in grids:
        sel = np.isin(run.t, grid)
        h = run.t[sel][1] - run.t[sel][0]
        f = power[sel]
        total += h / 3 * (f[0] + f[-1] + 4 * f[1:-1:2].sum() + 2 * f[2:-1:2].sum())
        work.append(total)
    energy = run.energy
    at_cuts = energy[np.isin(run.t, cuts)]
    assert np.ptp(energy) > 1e-3 * np.max(np.abs(energy))  # the motor changes the energy
    assert np.max(np.abs(at_cuts - (energy[0] + np.array(work)))) < 1e-9 * np.max(np.abs(energy))
