"""PyDy's Kane-Levinson rattleback example through ``from_mechanics`` against knifeedge's own ``celt`` (issue 23).

tests/models/pydy_rattleback.py is the model of pydy/pydy ``examples/rattleback/ellipsoid_no_slip.py`` (Euler angles
yaw q0, lean q1, pitch q2 and the contact point (q3, q4); body-frame angular velocity as speeds; its z axis down)
converted by ``from_mechanics``.  knifeedge's ``celt`` (``derivation/celt.py``: the unit vertical ``n`` and the
angular velocity ``omega`` in a body frame whose z axis points up, from the rigid-body front end) is an independent
formulation of the same body.  With Kane & Levinson's parameters (Int. J. Non-Linear Mech. 17 (1982) 175-186;
celt's preset ``kane_levinson_1982``) and the initial state of PyDy's own simulation of the example
(``examples/rattleback/cpp/ellipsoid_sim.cc``: lean and pitch 0.5 degrees, spin 5 rad/s), the two runs agree to the
tolerance of the integration, through the spin's reversal.  Slow tier: the derivation (about 30 s of CPU) and the
first compilation of its integrator (about 30 s).
"""
from pathlib import Path

import numpy as np
import pytest

import knifeedge as ke
from knifeedge import cli

MODELS = Path(__file__).resolve().parent / "models"
TILT = np.radians(0.5)  # PyDy's ellipsoid_sim.cc: "Roll" and "Pitch" 0.5 degrees
SPIN = 5.0              # and u2 = -5 rad/s about the body's downward z axis


@pytest.fixture(scope="module")
def rattleback(tmp_path_factory):
    out = tmp_path_factory.mktemp("pydy_rattleback")
    assert cli.main(["derive", str(MODELS / "pydy_rattleback.py"), "--out", str(out)]) == 0
    return ke.load("pydy_rattleback", path=out)


def euler_rates(q1, q2, u):
    """The example's kinematic differential equations (its ``qd_rhs[:3]``): yaw, lean and pitch rates from the
    body-frame angular velocity ``u``."""
    return ((u[2] * np.cos(q2) - u[0] * np.sin(q2)) / np.cos(q1), u[0] * np.cos(q2) + u[2] * np.sin(q2),
            u[1] + np.tan(q1) * (u[0] * np.sin(q2) - u[2] * np.cos(q2)))


def as_celt(q1, q2, q0_dot, q1_dot, q2_dot):
    """``(n, omega)`` of celt's frame from the example's angles and rates.  In the example's body frame R (yaw about
    N.z, lean about Y.x, pitch about L.y; z down) the downward vertical is mu = (-sin q2 cos q1, sin q1,
    cos q2 cos q1) (Kane & Levinson 1982, eq. 37) and omega = q0' mu + q1' (cos q2, 0, sin q2) + q2' (0, 1, 0);
    celt's frame is R turned half a turn about x (z up): (x, y, z) -> (x, -y, -z), and its n the upward vertical."""
    mu = np.array([-np.sin(q2) * np.cos(q1), np.sin(q1), np.cos(q2) * np.cos(q1)])
    zero = np.zeros_like(q2)
    w = q0_dot * mu + q1_dot * np.array([np.cos(q2), zero, np.sin(q2)]) + q2_dot * np.array([zero, 1 + zero, zero])
    return np.array([-mu[0], mu[1], mu[2]]), np.array([w[0], -w[1], -w[2]])


@pytest.mark.slow
@pytest.mark.parametrize("damping", [0.0, 1e-4])  # 1e-4 N m s: the example's own simulation's sigma
def test_pydy_rattleback_runs_as_celt(rattleback, damping):
    """5 s from PyDy's own initial state at the classic spin of 5 rad/s: the Euler-angle formulation (PyDy's model
    through from_mechanics) and the (n, omega) one (celt) agree along the run to the integration's tolerance."""
    q0_dot, q1_dot, q2_dot = euler_rates(TILT, TILT, np.array([0.0, 0.0, -SPIN]))
    y0 = rattleback.state(dict(q1=TILT, q2=TILT, q0_dot=q0_dot, q1_dot=q1_dot, q2_dot=q2_dot))
    p = rattleback.params({**rattleback.default_params, "s": damping})
    celt = ke.load("celt")
    pc = celt.params({**dict(zip(celt.param_names, celt.preset("kane_levinson_1982"))), "sigma": damping})
    n0, w0 = as_celt(TILT, TILT, q0_dot, q1_dot, q2_dot)
    t = np.linspace(0.0, 5.0, 201)
    ours = ke.simulate(rattleback, y0, (0.0, 5.0), p, rtol=1e-12, atol=1e-14, t_eval=t)
    theirs = ke.simulate(celt, celt.initial_state(n0=n0, omega0=w0), (0.0, 5.0), pc, rtol=1e-12, atol=1e-14,
                         t_eval=t)
    assert ours.success and theirs.success
    n, w = as_celt(ours["q1"], ours["q2"], ours["q0_dot"], ours["q1_dot"], ours["q2_dot"])
    np.testing.assert_allclose(n, theirs.y[:3], rtol=0, atol=1e-9)
    np.testing.assert_allclose(w, theirs.y[3:6], rtol=0, atol=1e-8)
    spin = (theirs.y[:3] * theirs.y[3:6]).sum(axis=0)
    assert spin[0] > 4.99 and spin.min() < -3.0  # it reverses (Kane & Levinson 1982): not a trivial run
    e = ours.energy
    if damping == 0.0:
        assert np.abs(e - e[0]).max() < 1e-10 * abs(e[0])
    else:
        assert np.all(np.diff(e) < 0)
