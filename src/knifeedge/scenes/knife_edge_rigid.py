"""Scene ``knife_edge_rigid``: the paper's two-mode knife edge against the real rigid body it describes.

The rigid body (``two_mode_rigid``, built with ``derivation/rigid.py`` from
the geometry of section III: inverted-U bar, masses M/2 a distance ell below
its ends, contact at the lowest point of a circle of radius D at the chiral
angle alpha) is exact in the tilts; the paper's two-mode model (``two_mode``,
fidelity ``full``) is exact consequences of the paper's Lagrangian and
``Const22``/``Const23``.  The paper's constraints and kinetic energy are the
body's small-tilt limit, but its potential misses ``(1/2) M g D theta_alpha^2``
(``derivation/rigid_knife_edge.py``).  For each tilt amplitude (both tilts
equal, at rest, spin ``phi_dot0``) the scene compares the first reversal time
and the dominant oscillation period of ``theta1`` (``n_y = sin theta1`` for
the body), for the paper's ``D/ell`` and for a small one.
"""
from __future__ import annotations

import math

import numpy as np

from .base import RunSpec, Scene, SceneResult
from .common import require_success

PARAMS = {"g": 1.0, "ell": 1.0, "L": 2.0, "D": 0.5, "alpha": math.pi / 4}


def rigid_state(theta1: float, theta2: float, phi_dot: float) -> dict:
    """The body's state for the paper's tilts (``R = Rz(phi) Rx(theta1) Ry(theta2)``) at rest, spinning at ``phi_dot``."""
    from ..models import load

    n0 = (-math.sin(theta2) * math.cos(theta1), math.sin(theta1), math.cos(theta2) * math.cos(theta1))
    m = load("two_mode_rigid")
    y = m.initial_state(n0=n0, omega0=tuple(phi_dot * c for c in n0))
    return dict(zip(m.closed_state_names, y.tolist()))


RUN = RunSpec(
    model="two_mode_rigid", fidelity="full", params=PARAMS, y0=rigid_state(0.05, 0.05, 0.1),
    t_span=(0.0, 12000.0), method="DOP853", rtol=1e-10, atol=1e-12, n_eval=None,
)


def _period(t, signal, t_max: float) -> float:
    """Dominant period of ``signal`` on ``t <= t_max`` (uniform resampling, FFT peak, parabolic refinement)."""
    keep = t <= t_max
    tt = np.linspace(t[keep][0], t[keep][-1], 8192)
    s = np.interp(tt, t[keep], signal[keep])
    s = (s - s.mean()) * np.hanning(s.size)
    spec = np.abs(np.fft.rfft(s))
    k = int(np.argmax(spec[1:])) + 1
    if 1 <= k < spec.size - 1:
        a, b, c = np.log(spec[k - 1:k + 2] + 1e-300)
        k = k + 0.5 * (a - c) / (a - 2 * b + c)
    return float((tt[-1] - tt[0]) / k)


def compute(scene: Scene, progress) -> SceneResult:
    st = scene.settings
    res = SceneResult(scene)
    rows = []
    for D in st["D_values"]:
        params = {**dict(scene.run.params), "D": D}
        for amp in st["amplitudes"]:
            progress(f"D = {D:g}, tilt amplitude {amp:g} rad")
            rigid = scene.run.with_(D=D, **rigid_state(amp, amp, st["phi_dot0"])).simulate()
            paper = RunSpec(model="two_mode", fidelity="full", params=params,
                            y0={"theta1": amp, "theta2": amp, "theta1_dot": 0.0, "theta2_dot": 0.0,
                                "phi_dot": st["phi_dot0"]},
                            t_span=scene.run.t_span, rtol=scene.run.rtol, atol=scene.run.atol, n_eval=None).simulate()
            require_success(rigid, scene)
            require_success(paper, scene)
            t_r = float(rigid.reversal_times[0]) if len(rigid.reversal_times) else math.nan
            t_p = float(paper.reversal_times[0]) if len(paper.reversal_times) else math.nan
            T_r = _period(rigid.t, rigid["n_y"], st["period_window"])
            T_p = _period(paper.t, paper["theta1"], st["period_window"])
            rows.append((D, amp, t_p, t_r, T_p, T_r))
    res.data["rows"] = rows
    for D in st["D_values"]:
        sel = [r for r in rows if r[0] == D]
        rev_err = [abs(r[2] / r[3] - 1) for r in sel]
        per_err = [abs(r[4] / r[5] - 1) for r in sel]
        res.numbers[f"reversal_time_paper_D{D:g}"] = [r[2] for r in sel]
        res.numbers[f"reversal_time_rigid_D{D:g}"] = [r[3] for r in sel]
        res.numbers[f"period_paper_D{D:g}"] = [r[4] for r in sel]
        res.numbers[f"period_rigid_D{D:g}"] = [r[5] for r in sel]
        for what, errs in (("reversal_time", rev_err), ("period", per_err)):
            upto = math.nan  # largest amplitude up to which every amplitude of the scan is within 1 %
            for r, e in zip(sel, errs):
                if not e < 0.01:
                    break
                upto = r[1]
            res.numbers[f"{what}_within_1pct_up_to_D{D:g}"] = upto
            res.claim(f"D/ell = {D:g}: the paper's model gives the rigid body's {what.replace('_', ' ')} within 1 %",
                      not math.isnan(upto), f"up to tilt {upto:g} rad; errors at tilts {[r[1] for r in sel]}: "
                      + ", ".join(f"{e:.1%}" for e in errs))
    return res


def draw(res: SceneResult, fig) -> None:
    rows = res.data["rows"]
    a1, a2 = fig.subplots(1, 2)
    for i, D in enumerate(sorted({r[0] for r in rows})):
        sel = [r for r in rows if r[0] == D]
        amp = [r[1] for r in sel]
        a1.loglog(amp, [r[2] for r in sel], "o--", color=f"C{i}", label=f"paper, D/ell={D:g}")
        a1.loglog(amp, [r[3] for r in sel], "s-", color=f"C{i}", mfc="none", label=f"rigid body, D/ell={D:g}")
        a2.semilogx(amp, [100 * (r[4] / r[5] - 1) for r in sel], "o-", color=f"C{i}", label=f"D/ell={D:g}")
    a1.set_xlabel("initial tilts theta1 = theta2 [rad]")
    a1.set_ylabel(r"first reversal time [$\sqrt{\ell/g}$]")
    a1.legend(fontsize=7)
    a2.axhspan(-1, 1, color="0.9")
    a2.set_xlabel("initial tilts [rad]")
    a2.set_ylabel("period of theta1: paper / rigid - 1 [%]")
    a2.legend(fontsize=7)
    fig.suptitle("two-mode knife edge: the paper's model against the rigid body of section III", fontsize=10)
    fig.tight_layout()


SCENE = Scene(
    name="knife_edge_rigid",
    title="paper's two-mode model vs the rigid knife edge",
    caption=("The chiral knife edge of section III built as the real rigid body (exact in the tilts) against the "
             "paper's two-mode model (full fidelity), for growing tilt amplitudes, at the paper's D/ell = 0.5 "
             "and at D/ell = 0.05 (L = 2 ell, alpha = pi/4, phi_dot0 = 0.1 sqrt(g/ell))."),
    why=("two_mode_rigid (derivation/rigid.py) is the body the paper's Lagrangian describes; two_mode full isolates "
         "the paper's modelling from its small-angle truncation"),
    run=RUN,
    plots="first reversal time against the tilt amplitude for both models; relative period difference",
    reports=tuple(f"{q}_D{D:g}" for D in (0.5, 0.05) for q in (
        "reversal_time_paper", "reversal_time_rigid", "period_paper", "period_rigid", "reversal_time_within_1pct_up_to",
        "period_within_1pct_up_to")),
    compute=compute,
    draw=draw,
    settings={"D_values": (0.5, 0.05), "amplitudes": (0.05, 0.1, 0.2, 0.3), "phi_dot0": 0.1, "period_window": 100.0},
    uses=(("two_mode_rigid", "full", False), ("two_mode", "full", False)),
)
