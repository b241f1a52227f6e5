"""The rolling disk of ``examples/rolling_disk.py``: a model the engine was not written for.

References
----------
* sympy issue #27631, "Error in the example 'A rolling disk using the Lagrange
  method'" (https://github.com/sympy/sympy/issues/27631): the correct equations
  of motion of a thin disk rolling without slipping, in the coordinates of the
  SymPy rolling-disc tutorials (``q1`` heading, ``q2`` lean, ``q3`` rotation
  about the axle), transcribed below as :func:`issue_27631`.  The same issue shows
  the tutorial's Lagrange example (kept below as :func:`sympy_tutorial`) to be
  wrong: it drops the rolling constraints and flips the potential.
* Stability of straight upright rolling: with per-unit-mass moments of
  inertia ``I1`` about a diameter and ``I3`` about the axle, upright rolling at
  spin rate ``Omega`` is stable for ``Omega**2 > g r I1 / (I3 (I3 + r**2))``
  (Routh, *Advanced Dynamics of a System of Rigid Bodies*, section 244; for a
  hoop, ``I1 = r**2/2, I3 = r**2``, this is the familiar ``g/(4r)``); for a thin
  uniform disk, ``I1 = r**2/4, I3 = r**2/2``, ``Omega_c**2 = g/(3r)``
  (K. T. McDonald and A. J. McDonald, *The rolling motion of a disk on a
  horizontal plane*, arXiv:physics/0008227).
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import knifeedge as ke
from knifeedge.derive import check_symmetry, derive, load_specs

EXAMPLE = Path(__file__).resolve().parent.parent / "examples" / "rolling_disk.py"


def _specs() -> dict:
    return {s.name: s for s in load_specs(EXAMPLE)}


@pytest.fixture(scope="module")
def disk():
    """The example's undamped ModelSpec and its derived reduced system."""
    spec = _specs()["rolling_disk"]
    return spec, derive(spec)


def issue_27631(g, r, q2, q1d, q2d, q3d):
    """(q1'', q2'', q3'') as stated in sympy issue #27631 (transcribed from the issue's text)."""
    q1dd = -2 * q2d * q3d / np.cos(q2)
    q2dd = 4 * g * np.sin(q2) / (5 * r) + np.sin(2 * q2) * q1d**2 / 2 + 6 * np.cos(q2) * q1d * q3d / 5
    q3dd = -(10 * np.cos(q2) * q1d - 12 * np.tan(q2) * q3d) * q2d / 6
    return q1dd, q2dd, q3dd


def sympy_tutorial(g, r, q2, q1d, q2d, q3d):
    """(q1'', q2'', q3'') of the SymPy tutorial 'A rolling disc using Lagrange's Method' (wrong, see #27631)."""
    q1dd = -2 * (2 * np.tan(q2) * q1d + 3 * q3d / np.cos(q2)) * q2d
    q2dd = -4 * g * np.sin(q2) / (5 * r) + np.sin(2 * q2) * q1d**2 / 2 + 6 * np.cos(q2) * q1d * q3d / 5
    q3dd = (-5 * np.cos(q2) * q1d + 6 * np.tan(q2) * q3d + 4 * q1d / np.cos(q2)) * q2d
    return q1dd, q2dd, q3dd


def _numeric_rhs(system):
    """d(state)/dt of the derived system as a NumPy function of (state, g, r)."""
    spec = system.spec
    return sp.lambdify([system.state, spec.params], system.state_rhs(), "numpy")


def _random_states(n, seed=27631):
    rng = np.random.default_rng(seed)
    g = rng.uniform(0.5, 20.0, n)
    r = rng.uniform(0.05, 2.0, n)
    q2 = rng.uniform(-1.4, 1.4, n)          # lean, away from lying flat (|q2| = pi/2)
    q1d, q2d, q3d = rng.uniform(-5.0, 5.0, (3, n))
    return g, r, q2, q1d, q2d, q3d


def test_the_example_is_the_models_own_file():
    """The example lives outside the package and defines MODEL with the issue's names."""
    assert "src" not in EXAMPLE.parts and EXAMPLE.is_file()
    specs = _specs()
    assert sorted(specs) == ["rolling_disk", "rolling_disk_damped"]
    spec = specs["rolling_disk"]
    assert [str(p) for p in spec.params] == ["g", "r"]
    assert [str(s) for s in spec.state] == ["q2", "q1_dot", "q2_dot", "q3_dot"]
    m = ke.load("rolling_disk")             # derived into the package by `make derive`
    assert m.state_names == ("q2", "q1_dot", "q2_dot", "q3_dot") and m.param_names == ("g", "r")


def test_rhs_matches_sympy_issue_27631_at_random_states(disk):
    """The derived right-hand side equals the equations of sympy #27631 to 1e-10 relative,
    and is far from the tutorial's equations that the issue shows wrong."""
    spec, system = disk
    f = _numeric_rhs(system)
    names = [str(s) for s in system.state]
    g, r, q2, q1d, q2d, q3d = _random_states(200)
    values = {"q2": q2, "q1_dot": q1d, "q2_dot": q2d, "q3_dot": q3d}
    rates = np.array(f([values[n] for n in names], [g, r]))
    derived = dict(zip(names, rates))       # d(name)/dt
    q1dd, q2dd, q3dd = issue_27631(g, r, q2, q1d, q2d, q3d)
    np.testing.assert_allclose(derived["q2"], q2d, rtol=1e-14)
    for got, want in ((derived["q1_dot"], q1dd), (derived["q2_dot"], q2dd), (derived["q3_dot"], q3dd)):
        np.testing.assert_allclose(got, want, rtol=1e-10, atol=1e-10 * np.max(np.abs(want)))
    wrong = sympy_tutorial(g, r, q2, q1d, q2d, q3d)
    for got, bad in zip((derived["q1_dot"], derived["q2_dot"], derived["q3_dot"]), wrong):
        assert np.max(np.abs(got - bad)) > 1.0


def test_reduction_holds_at_a_general_pose(disk):
    """Heading, rotation and contact point are cyclic: the equations derived at x = y = q1 = q3 = 0
    equal the unreduced DAE (five coordinates, two multipliers) at a random pose."""
    _, system = disk
    assert check_symmetry(system, seed=1) < 1e-20


def _critical_spin_squared(system):
    """Omega_c**2 from the linearization of the reduced equations about upright rolling at spin Omega."""
    spec = system.spec
    state = sp.Matrix(system.state)
    names = {str(s): s for s in system.state}
    Omega, lam = sp.Symbol("Omega", positive=True), sp.Symbol("lambda")
    upright = {names["q2"]: 0, names["q2_dot"]: 0, names["q1_dot"]: 0, names["q3_dot"]: Omega}
    rhs = sp.Matrix(system.state_rhs())
    assert rhs.subs(upright).applyfunc(sp.simplify) == sp.zeros(4, 1)   # steady upright rolling
    J = rhs.jacobian(state).subs(upright).applyfunc(sp.simplify)
    # lambda**2 (lambda**2 + k(Omega)): two neutral directions (the family of steady motions)
    # and the lean mode, oscillating for k > 0 and growing for k < 0.
    c4, c3, c2, c1, c0 = (sp.simplify(c) for c in J.charpoly(lam).all_coeffs())
    assert c4 == 1 and c3 == c1 == c0 == 0
    k = c2
    (root,) = sp.solve(k, Omega)          # the one positive root
    return root**2, k, Omega


def test_upright_rolling_threshold_is_the_literature_value(disk):
    """Linearized by machine, upright rolling loses stability at Omega_c**2 = g/(3r) (thin disk),
    Routh's g r I1 / (I3 (I3 + r**2)) with I1 = r**2/4, I3 = r**2/2."""
    spec, system = disk
    g, r = spec.params
    crit, k, Omega = _critical_spin_squared(system)
    I1, I3 = r**2 / 4, r**2 / 2
    assert sp.simplify(crit - g * r * I1 / (I3 * (I3 + r**2))) == 0
    assert sp.simplify(crit - g / (3 * r)) == 0
    # stable (oscillating lean) above the threshold, unstable below
    assert k.subs(Omega, sp.sqrt(2 * crit)).subs({g: 1, r: 1}) > 0
    assert k.subs(Omega, sp.sqrt(crit / 2)).subs({g: 1, r: 1}) < 0


def _issue_rhs(t, y, g, r):
    """d(q2, q1_dot, q2_dot, q3_dot)/dt from the equations of sympy #27631."""
    q2, q1d, q2d, q3d = y
    q1dd, q2dd, q3dd = issue_27631(g, r, q2, q1d, q2d, q3d)
    return [q2d, q1dd, q2dd, q3dd]


@pytest.mark.slow  # compiles the module's rhs (~1.5 s); the compiled module against #27631: the trajectory check below
def test_compiled_rhs_matches_sympy_issue_27631_at_random_states():
    """The generated, numba-compiled module (what ke.load gives) against #27631, 1e-10 relative."""
    m = ke.load("rolling_disk")
    g, r, q2, q1d, q2d, q3d = _random_states(200, seed=7)
    for k in range(g.size):
        got = m.rhs(0.0, np.array([q2[k], q1d[k], q2d[k], q3d[k]]), np.array([g[k], r[k]]))
        want = np.array(_issue_rhs(0.0, (q2[k], q1d[k], q2d[k], q3d[k]), g[k], r[k]))
        np.testing.assert_allclose(got, want, rtol=1e-10, atol=1e-10 * np.max(np.abs(want)))


def test_trajectory_matches_the_issue_equations_integrated_by_scipy():
    """ke.simulate on the compiled model and SciPy's DOP853 on the transcribed equations of #27631
    follow the same wobbling, turning motion (both at rtol 1e-12)."""
    m = ke.load("rolling_disk")
    y0 = {"q2": 0.4, "q1_dot": 0.3, "q2_dot": -0.2, "q3_dot": 2.0}
    t = np.linspace(0.0, 20.0, 201)
    run = ke.simulate(m, y0, (0.0, 20.0), {"g": 1.0, "r": 1.0}, rtol=1e-12, atol=1e-14, t_eval=t)
    ref = solve_ivp(_issue_rhs, (0.0, 20.0), list(y0.values()), method="DOP853", rtol=1e-12, atol=1e-14,
                    t_eval=t, args=(1.0, 1.0))
    assert run.success and ref.success
    np.testing.assert_allclose(run.y, ref.y, rtol=0, atol=1e-8)


def test_energy_is_conserved_along_a_run():
    """The generated energy (the Jacobi integral) stays constant along a wobbling, turning run."""
    m = ke.load("rolling_disk")
    run = ke.simulate(m, {"q2": 0.4, "q1_dot": 0.3, "q2_dot": -0.2, "q3_dot": 2.0}, (0.0, 40.0),
                      {"g": 1.0, "r": 1.0}, rtol=1e-12, atol=1e-14)
    assert run.success
    e = run.energy
    assert np.max(np.abs(e - e[0])) < 1e-10 * abs(e[0])
    # and it is the energy of a thin disk, written here independently (per unit mass; rolling gives
    # |v_centre| = r |omega x e_z|, omega = (q2_dot, q1_dot sin q2 + q3_dot, q1_dot cos q2) in the lean frame):
    # g r cos q2 + (r^2/8)(5 q2_dot^2 + (1 + 5 sin^2 q2) q1_dot^2 + 12 sin q2 q1_dot q3_dot + 6 q3_dot^2)
    q2, q1d, q2d, q3d = run.y
    independent = np.cos(q2) + (5 * q2d**2 + (1 + 5 * np.sin(q2)**2) * q1d**2
                                + 12 * np.sin(q2) * q1d * q3d + 6 * q3d**2) / 8
    np.testing.assert_allclose(e, independent, rtol=1e-13)


@pytest.mark.parametrize("factor", [0.95, 1.05])
def test_threshold_confirmed_by_simulation(factor):
    """5 % on either side of Omega_c, a disk leaned by q2_0 = 1e-5 follows the linear theory of the
    equations of #27631: with q1_dot(0) = q2_dot(0) = 0, q1_dot = -2 Omega (q2 - q2_0) and
    q2'' = -(12/5) (Omega**2 - Omega_c**2) q2 + (12/5) Omega**2 q2_0 (g = r = 1), so the lean
    oscillates about s = q2_0 Omega**2 / (Omega**2 - Omega_c**2) with amplitude |s - q2_0| above the
    threshold, and grows as s + (q2_0 - s) cosh(sigma t) below it.  Above: bounded by |2 s - q2_0|
    over 200 time units.  Below: reaches 100 q2_0 when the linear theory says, then an O(1) lean."""
    m = ke.load("rolling_disk")
    g = r = 1.0
    omega_c = math.sqrt(g / (3 * r))
    Omega, q20 = factor * omega_c, 1e-5
    t = np.linspace(0.0, 200.0, 20001)
    run = ke.simulate(m, {"q2": q20, "q1_dot": 0.0, "q2_dot": 0.0, "q3_dot": Omega}, (0.0, 200.0),
                      {"g": g, "r": r}, rtol=1e-12, atol=1e-16, t_eval=t)
    assert run.success
    lean = np.abs(run["q2"])
    s = q20 * Omega**2 / (Omega**2 - omega_c**2)
    if factor > 1:
        bound = abs(2 * s - q20)
        assert bound < 5e-4
        assert 0.99 * bound < lean.max() < 1.01 * bound
    else:
        sigma = math.sqrt(12 / 5 * (omega_c**2 - Omega**2))
        t_linear = math.acosh((100 * q20 - s) / (q20 - s)) / sigma
        t_sim = run.t[np.argmax(lean > 100 * q20)]
        assert t_sim == pytest.approx(t_linear, rel=0.01, abs=0.01)    # 0.01: spacing of the samples
        assert lean.max() > 0.1


# -- the damped variant ----------------------------------------------------------
def test_damped_power_is_the_rayleigh_function_written_independently():
    """power_dissipated = 2 R = c r^2 |omega|^2, with |omega|^2 = q2_dot^2 + (q1_dot sin q2 + q3_dot)^2
    + (q1_dot cos q2)^2 (the disk's angular velocity in the lean frame)."""
    md = ke.load("rolling_disk_damped")
    assert md.has_dissipation and md.param_names == ("g", "r", "c")
    g, r, q2, q1d, q2d, q3d = _random_states(50, seed=11)
    c = np.linspace(0.01, 2.0, g.size)
    for k in range(g.size):
        want = c[k] * r[k]**2 * (q2d[k]**2 + (q1d[k] * np.sin(q2[k]) + q3d[k])**2 + (q1d[k] * np.cos(q2[k]))**2)
        got = md.power_dissipated(np.array([q2[k], q1d[k], q2d[k], q3d[k]]), np.array([g[k], r[k], c[k]]))
        assert got == pytest.approx(want, rel=1e-12)


def test_damped_energy_plus_dissipated_work_is_constant():
    """Integrating the dissipated work alongside the state (SciPy, on the module's compiled functions):
    energy + work stays at its initial value to 1e-10; with ke.simulate and Model.dissipated_work
    (trapezoidal rule on 8001 samples) to 1e-8.  Without the work the energy falls by half."""
    md = ke.load("rolling_disk_damped")
    p = md.params(md.default_params)
    y0 = md.state(md.default_state)
    mod = md.module

    def augmented(t, z):
        return np.append(mod.rhs(t, z[:4], p), mod.power_dissipated(z[:4], p))

    sol = solve_ivp(augmented, (0.0, 10.0), np.append(y0, 0.0), method="DOP853", rtol=1e-12, atol=1e-14)
    assert sol.success
    e = np.array([md.energy(sol.y[:4, k], p) for k in range(sol.y.shape[1])])
    balance = e + sol.y[4]
    assert np.max(np.abs(balance - balance[0])) < 1e-10 * balance[0]
    assert e[-1] < 0.6 * e[0]

    t = np.linspace(0.0, 10.0, 8001)
    run = ke.simulate(md, y0, (0.0, 10.0), p, t_eval=t)
    balance = run.energy + md.dissipated_work(run.t, run.y, run.p)
    assert np.max(np.abs(balance - balance[0])) < 1e-8 * balance[0]


# -- the scene --------------------------------------------------------------------
def test_rolling_disk_scene_agrees_with_the_linear_theory():
    """The scene's numbers against the linear theory (scene module docstring and test_threshold_... above)."""
    res = ke.scene("rolling_disk")()
    n = res.numbers
    run = res.scene.run
    g, r = run.params["g"], run.params["r"]
    omega, q20 = run.y0["q3_dot"], run.y0["q2"]
    omega_c = math.sqrt(g / (3 * r))
    s = q20 * omega**2 / (omega**2 - omega_c**2)
    assert n["omega_c"] == pytest.approx(omega_c, rel=1e-14)
    assert n["predicted_stable"] is True
    # q2_0 = 0.05 is not infinitesimal: the linear theory holds to a few percent
    assert n["max_lean"] == pytest.approx(abs(2 * s - q20), rel=0.03)
    assert n["lean_period"] == pytest.approx(2 * math.pi / math.sqrt(12 / 5 * (omega**2 - omega_c**2)), rel=0.03)
    assert n["max_lean_slow"] > 10 * q20
    assert all(verdict == "supports" for _, verdict, _ in res.claims), res.claims
