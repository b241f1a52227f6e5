"""Scene ``celt_chaos``: a high-energy celt, its Lyapunov spectrum and a Poincaré section.

Borisov & Mamaev (Physics-Uspekhi 46 (2003) 393) and Gonchenko, Gonchenko & Kazakov (Regul. Chaotic Dyn. 18 (2013)
521) found strange attractors in the undamped celt: its energy is conserved but its phase volume is not, so a
conservative-looking body can have attractors ("mixed dynamics"), and chaos needs energy well above the steady
spins.  Their body is a paraboloid (the "BM model") with their own parameters; this scene takes the project's
ellipsoid with Schoemer's set (scene ``celt_schoemer``), undamped, and gives it an energy of about 20 J (three
times that of the upright spin at 10 rad/s): tilted by 0.6 rad and spun at 10 rad/s with a wobble, it rolls over
its whole surface (``n_z`` reaches -1).  The full Lyapunov spectrum (:func:`knifeedge.lyapunov`, Benettin/QR on
the emitted variational equations) is computed at two steps ``h`` (its convergence in the step) with its running
estimates (its convergence in time), and the section ``n_x = 0`` upward (:func:`knifeedge.poincare`) shows what
the motion fills.  The scene says what it finds: chaos if the largest exponent stands clear of its spread and of
the ``ln T / T`` of a regular motion, contraction of the phase volume if the sum of the exponents (the average
divergence) is clearly negative, and whether the upright spin of the same energy is an attractor beside it.

Found (docs/stability.md): lambda_1 = 1.16 +- 0.03 1/s, two exponents zero, sum -0.079 1/s, a section that fills
a band; the upright spin of the same energy (17.41 rad/s) is asymptotically stable, and the chaos is a transient:
RK4 orbits of this state (h = 0.005, 0.0025) fell onto that spin after about 400 s and 2600 s, a DOP853 orbit
(rtol 1e-11) was still chaotic at 3000 s.  The scene's span (1000 s) lies inside the chaotic phase of its run.
"""
from __future__ import annotations

import math

import numpy as np

from ..lyapunov import lyapunov
from ..sections import poincare
from .base import RunSpec, Scene, SceneResult
from .common import layout

#: Schoemer's set (the ``schoemer`` preset of the celt), undamped
PARAMS = {"a": 1.618033988749895, "b": 1.0, "c": 1.0, "h": 0.1875, "m": 0.2, "g": 9.81, "I_xx": 0.05796875,
          "I_yy": 0.09032943, "I_zz": 0.12236068, "I_xy": -0.025, "I_xz": 0.0, "I_yz": 0.0, "sigma": 0.0}
_TILT, _AZIMUTH, _OMEGA = 0.6, 0.5, (1.0, -1.0, 10.0)
_N = (math.sin(_TILT) * math.cos(_AZIMUTH), math.sin(_TILT) * math.sin(_AZIMUTH), math.cos(_TILT))

RUN = RunSpec(
    model="celt", fidelity="full", params=PARAMS,
    y0={"n_x": _N[0], "n_y": _N[1], "n_z": _N[2], "omega_x": _OMEGA[0], "omega_y": _OMEGA[1],
        "omega_z": _OMEGA[2], "omega_n": sum(a * b for a, b in zip(_N, _OMEGA))},
    t_span=(0.0, 1000.0), n_eval=None,
)


def compute(scene: Scene, progress) -> SceneResult:
    s, run = scene.settings, scene.run
    m = run.load()
    p, y0 = m.params(**dict(run.params)), m.state(**dict(run.y0))
    t1 = run.t_span[1]
    progress(f"Lyapunov spectrum (Benettin/QR), h = {s['h']:g}")
    fine = lyapunov(m, y0, p, t1, h=s["h"], tau=s["tau"])
    progress("Poincaré section n_x = 0 (upward)")
    sec = poincare(m, y0, p, t1, "n_x", direction=1, rtol=run.rtol, atol=run.atol)
    # two energies: the generated function as plain Python (compiling it cost 0.3-0.4 s of CPU; same arithmetic)
    energy = m.module.energy.py_func
    e0, e1 = float(energy(y0, p)), float(energy(np.ascontiguousarray(fine.y), p))
    res = SceneResult(scene)
    lam = fine.exponents
    res.numbers.update({
        "exponents": [float(x) for x in lam], "uncertainty": [float(x) for x in fine.uncertainty],
        "h": fine.h,
        "sum_of_exponents": float(lam.sum()), "log_t_over_t": math.log(t1) / t1,
        "energy": e0, "energy_drift_lyapunov_run": abs(e1 - e0) / abs(e0),
        "crossings": int(sec.t.size), "n_z_min_on_section": float(sec["n_z"].min()) if sec.t.size else float("nan"),
    })
    res.numbers.update(_steady_spin_with_the_same_energy(m, p, e0))
    _claims(res, fine, t1)
    res.data.update(history_t=fine.history_t, history=fine.history, sec_n_y=sec["n_y"], sec_omega_z=sec["omega_z"],
                    sec_omega_y=sec["omega_y"])
    return res


def _steady_spin_with_the_same_energy(m, p, energy: float) -> dict:
    """The upright spin ``Omega > 0`` with the run's energy (``E = I_zz Omega^2 / 2 + m g (c - h)``) and its
    largest physical growth rate, from the full body's linearization (its Jacobian is the Lyapunov loop's
    ``jvp_into``: nothing more to compile)."""
    from ..stability import linearize, steady_state

    q = dict(zip(m.param_names, p))
    spin = math.sqrt(2 * (energy - q["m"] * q["g"] * (q["c"] - q["h"])) / q["I_zz"])
    lin = linearize(m, steady_state(m, p, "steady_spin", spin), p)
    return {"steady_spin_same_energy": spin, "steady_spin_growth_rate": lin.max_growth_rate}


def _claims(res: SceneResult, fine, t1: float) -> None:
    n = res.numbers
    lam, unc = fine.exponents, fine.uncertainty
    res.claim("the running estimates have settled (spread over the last quarter of the run below 0.05/s; RK4 "
              "conserves the energy to 1e-4)",
              bool(np.all(unc < 0.05) and n["energy_drift_lyapunov_run"] < 1e-4),
              f"h = {fine.h:g}: {', '.join(f'{x:.3g}' for x in lam)}; spread over the last quarter "
              f"{', '.join(f'{x:.2g}' for x in unc)}; energy drift {n['energy_drift_lyapunov_run']:.1e}")
    floor = 10 * n["log_t_over_t"]
    res.claim("the motion is chaotic: the largest exponent is positive, clear of its spread and of the ln T / T "
              "of a regular motion", bool(lam[0] > max(5 * unc[0], floor)),
              f"lambda_1 = {lam[0]:.3g} +- {unc[0]:.2g} 1/s against 10 ln T / T = {floor:.2g} at T = {t1:g} s")
    res.claim("two exponents are zero (the direction of the flow and the conserved energy)",
              bool(np.sum(np.abs(lam) < np.maximum(3 * unc, 0.05)) >= 2),
              f"the exponents closest to zero: {', '.join(f'{x:.2g}' for x in sorted(lam, key=abs)[:2])}")
    res.claim("along the chaotic motion the phase volume contracts on average although the energy is conserved "
              "(a non-holonomic body: Borisov-Mamaev's mixed dynamics)",
              bool(n["sum_of_exponents"] < -max(float(np.sum(unc)), 0.02)),
              f"sum of the exponents (the average divergence) {n['sum_of_exponents']:.3g} 1/s, total spread "
              f"{float(np.sum(unc)):.2g}; the section's {n['crossings']} points fill a band, not curves (figure)")
    res.claim("the chaotic motion is not the only attractor: the upright spin with the same energy is asymptotically "
              "stable, so the chaos can be a transient (orbits that reach that spin's basin stay there)",
              bool(n["steady_spin_growth_rate"] < 0),
              f"Omega = {n['steady_spin_same_energy']:.4g} rad/s, largest physical growth rate "
              f"{n['steady_spin_growth_rate']:.3g} 1/s")


def draw(res: SceneResult, fig) -> None:
    d, n = res.data, res.numbers
    a1, a2 = fig.subplots(1, 2)
    t, hist = d["history_t"], d["history"]
    for j in range(hist.shape[1]):
        a1.semilogx(t, hist[:, j], lw=0.8, label=f"$\\lambda_{j + 1}$ = {n['exponents'][j]:.3g}")
    a1.axhline(0, color="gray", lw=0.5)
    a1.set_xlabel("T [s]")
    a1.set_ylabel("running estimate [1/s]")
    a1.legend(fontsize=7, loc="upper right")
    a1.set_title(f"Lyapunov spectrum, sum {n['sum_of_exponents']:.3g} 1/s", fontsize=9)
    a2.plot(d["sec_n_y"], d["sec_omega_z"], ",", color="k")
    a2.set_xlabel("$n_y$")
    a2.set_ylabel(r"$\omega_z$ [rad/s]")
    a2.set_title(f"section $n_x$ = 0 (upward), {n['crossings']} crossings", fontsize=9)
    layout(fig, res.scene is SCENE, dict(left=0.0651, right=0.9850, bottom=0.1359, top=0.9259, wspace=0.1763))


SCENE = Scene(
    name="celt_chaos",
    title="A high-energy celt: Lyapunov spectrum and Poincaré section",
    caption=("The undamped celt (Schoemer's set) at about 20 J, rolling over its whole surface: the running "
             "estimates of its five Lyapunov exponents and the section n_x = 0 (upward) in (n_y, omega_z)."),
    why=("the full rigid body (large tilts: the small-tilt fidelities do not hold), undamped so that the energy is "
         "conserved and any attraction is the non-holonomic constraint's, not friction's; the upright spin's "
         "linearization from the same body"),
    run=RUN,
    plots="running Lyapunov exponents against T; Poincaré section n_x = 0 in (n_y, omega_z)",
    reports=("exponents", "uncertainty", "h", "sum_of_exponents", "energy", "energy_drift_lyapunov_run",
             "crossings", "n_z_min_on_section", "steady_spin_same_energy", "steady_spin_growth_rate"),
    compute=compute,
    draw=draw,
    settings={"h": 0.0025, "tau": 0.5},
    figsize=(10.0, 4.5),
    lyapunov=(("celt", "full"),),
)
