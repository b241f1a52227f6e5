"""Scene ``knife_edge_rigid``: the paper's two-mode knife edge against the real rigid body it describes.

The rigid body (``two_mode_rigid``, built with ``derivation/rigid.py`` from
the geometry of section III: inverted-U bar, masses M/2 a distance ell below
its ends, contact at the lowest point of a circle of radius D at the chiral
angle alpha) is exact in the tilts; the paper's two-mode model (``two_mode``,
fidelity ``full``) is exact consequences of the paper's Lagrangian and
``Const22``/``Const23``.  The paper's constraints and kinetic energy are the
body's small-tilt limit, but its potential misses ``(1/2) M g D theta_alpha^2``
(``derivation/rigid_knife_edge.py``; ``Twomodes.lagrangian`` in
``derivation/published.py``).

The tilt amplitude of a run is its largest tilt, ``theta_max = phi_dot0
L/sqrt(g ell)`` (the invariant of the averaged flow), set by the initial spin;
both initial tilts are ``theta_max/10`` at rest.  For each amplitude the scene
compares the first reversal time -- the first zero of the vertical spin
``omega . n`` for both models (``phi_dot + theta2_dot sin theta1`` for the
paper's) -- and the period of the fast rocking mode in ``theta1`` (``n_y =
sin theta1`` for the body) over a short run started at tilts ``theta_max``,
for the paper's ``D/ell = 1/2`` and two smaller ones.  The closed-form linear
periods of both potentials are reported beside them.  It also runs the
initial state of Fig. ``Numerical2``.

Both models run at rtol 1e-8, atol 1e-11 (the tilts start at 1e-3 and up): the
scene asks whether two models agree within 1 %, and against runs at rtol 1e-10,
atol 1e-12 its reversal times moved by at most 2e-6 relative, its periods by
2e-5 (the FFT's estimate on the steps), its relative errors by at most 2e-5
(the closest to the 1 % line, -0.984 %, by 3e-7), at two thirds of the CPU.
"""
from __future__ import annotations

import math

import numpy as np

from .base import RunSpec, Scene, SceneResult
from .common import first_reversal, label_log_ticks, layout, require_success, run_to_first_reversal

PARAMS = {"g": 1.0, "ell": 1.0, "L": 2.0, "D": 0.5, "alpha": math.pi / 4}


def rigid_state(theta1: float, theta2: float, phi_dot: float) -> dict:
    """The body's state for the paper's tilts (``R = Rz(phi) Rx(theta1) Ry(theta2)``) at rest, spinning at ``phi_dot``."""
    from ..models import load

    n0 = (-math.sin(theta2) * math.cos(theta1), math.sin(theta1), math.cos(theta2) * math.cos(theta1))
    m = load("two_mode_rigid")
    y = m.initial_state(n0=n0, omega0=tuple(phi_dot * c for c in n0))
    return dict(zip(m.closed_state_names, y.tolist()))


RUN = RunSpec(
    model="two_mode_rigid", fidelity="full", params=PARAMS, y0=rigid_state(1e-3, 1e-3, 0.1),
    t_span=(0.0, 4000.0), method="DOP853", rtol=1e-8, atol=1e-11, n_eval=None,
)


def _period(t, signal, t_max: float, band=(0.0, math.inf)) -> float:
    """Period of the strongest oscillation of ``signal`` on ``t <= t_max`` whose period lies in ``band``.

    Uniform resampling, Hann window, FFT peak, parabolic refinement of the peak.
    """
    keep = t <= t_max
    tt = np.linspace(t[keep][0], t[keep][-1], 8192)
    s = np.interp(tt, t[keep], signal[keep])
    s = (s - s.mean()) * np.hanning(s.size)
    spec = np.abs(np.fft.rfft(s))
    span = tt[-1] - tt[0]
    k_all = np.arange(spec.size)
    ok = (k_all >= 1) & (span / np.maximum(k_all, 1) >= band[0]) & (span / np.maximum(k_all, 1) <= band[1])
    k = int(k_all[ok][np.argmax(spec[ok])])
    if 1 <= k < spec.size - 1:
        a, b, c = np.log(spec[k - 1:k + 2] + 1e-300)
        k = k + 0.5 * (a - c) / (a - 2 * b + c)
    return float(span / k)


def linear_periods(params, corrected: bool) -> list:
    """Periods of the two linear rocking modes at zero spin, closed form (``sqrt(ell/g)`` units).

    Const22/Const23 give ``x_dot = 0`` at zero spin, so the tilts obey ``M theta'' = -K theta`` with
    ``M = diag(ell^2, L^2 + ell^2)`` and ``K = g ell I`` (the paper's potential) or ``K = g ell I +
    g D a a^T``, ``a = (-sin alpha, cos alpha)`` (the rigid body's: + (1/2) g D theta_alpha^2).
    """
    g, ell, L, D, al = (params[k] for k in ("g", "ell", "L", "D", "alpha"))
    a = np.array([-math.sin(al), math.cos(al)])
    K = g * ell * np.eye(2) + (g * D * np.outer(a, a) if corrected else 0.0)
    w2 = np.linalg.eigvals(np.linalg.solve(np.diag([ell**2, L**2 + ell**2]), K)).real
    return sorted(2 * math.pi / math.sqrt(x) for x in w2)


def _crossings(t, s) -> np.ndarray:
    """Zero crossings of a sampled signal (linear interpolation between samples)."""
    i = np.nonzero(np.sign(s[:-1]) * np.sign(s[1:]) < 0)[0]
    return t[i] - s[i] * (t[i + 1] - t[i]) / (s[i + 1] - s[i])


def first_crossing_paper(spec: RunSpec, scene: Scene) -> float:
    """First zero of the vertical spin ``omega . n = phi_dot + theta2_dot sin(theta1)`` of the paper's model.

    The rigid body's reversal events are the crossings of ``omega . n``; for the paper's model (orientation
    ``Rz(phi) Rx(theta1) Ry(theta2)``) the same quantity is ``phi_dot + theta2_dot sin(theta1)``.  Near a
    reversal it crosses zero several times (the rocking rides on the slow spin), so its first crossing
    precedes the zero of ``phi_dot`` by up to a few rocking periods; it is sampled every 0.05 (a 125th of
    the fast rocking period, 2 pi in these units) from ``0.8 t_phi`` to ``t_phi + 50`` around the zero
    ``t_phi`` of ``phi_dot``, by the run continued from its last step before ``0.8 t_phi`` (the same solution
    to the run's tolerance; integrating again from the start, and on to the span's end, took half of this
    scene's time).  Sampled every 0.01 the crossings were the same to 2.4e-7 relative (the reported errors
    to 6e-6 of themselves) at 1.6 times this scene's cost: the dense output at 10^5-10^6 times was most of it.
    The first run stops a fifth past the amplitude equations' first reversal (:func:`knifeedge.reversal_time`,
    within 0.1 % of the measured one on this scene's scans; the spans are about 3.4 times it):
    :func:`run_to_first_reversal`.
    """
    from ..reversal import reversal_time
    from ..simulate import simulate

    r = run_to_first_reversal(spec, 1.2 * reversal_time(spec.load(), dict(spec.params), dict(spec.y0)).first, scene)
    if not len(r.reversal_times):
        return math.nan
    t_phi = float(r.reversal_times[0])
    t_eval = np.arange(0.8 * t_phi, t_phi + 50.0, 0.05)
    k = max(int(np.searchsorted(r.t, t_eval[0], side="right")) - 1, 0)
    m = spec.load()
    r = require_success(simulate(m, dict(zip(m.state_names, r.y[:, k])), (float(r.t[k]), float(t_eval[-1])),
                                 dict(spec.params), method=spec.method, rtol=spec.rtol, atol=spec.atol,
                                 t_eval=t_eval), scene)
    c = _crossings(r.t, r["phi_dot"] + r["theta2_dot"] * np.sin(r["theta1"]))
    return float(c[0]) if len(c) else math.nan


def _within(amplitudes, errors, tol=0.01) -> float:
    """Largest amplitude up to which every amplitude of the scan is within ``tol`` (NaN: not even the smallest)."""
    upto = math.nan
    for a, e in zip(amplitudes, errors):
        if not abs(e) < tol:
            break
        upto = a
    return upto


def compute(scene: Scene, progress) -> SceneResult:
    st = scene.settings
    res = SceneResult(scene)
    rows = []
    frac = st["initial_fraction"]
    for D, amplitudes in st["scans"].items():
        params = {**dict(scene.run.params), "D": D}
        w = math.sqrt(params["g"] / params["ell"])
        fast = linear_periods(params, corrected=False)[0]
        for amp in amplitudes:
            spin = amp * params["ell"] * w / params["L"]  # largest tilt phi_dot0 L/sqrt(g ell) = amp
            t_end = st["t_end_factor"] * params["ell"] / (D * spin)
            progress(f"D/ell = {D:g}, largest tilt {amp:g} rad (spin {spin:.4g})")
            y_paper = {"theta1": frac * amp, "theta2": frac * amp, "theta1_dot": 0.0, "theta2_dot": 0.0,
                       "phi_dot": spin}
            paper = RunSpec(model="two_mode", fidelity="full", params=params, y0=y_paper, t_span=(0.0, t_end),
                            rtol=scene.run.rtol, atol=scene.run.atol, n_eval=None)
            t_p = first_crossing_paper(paper, scene)
            # the rigid body runs a fifth past the paper's reversal (they differ by at most 6 % here), or over the
            # whole span if it has not reversed by then
            rigid = scene.run.with_(D=D, t_end=t_end, **rigid_state(frac * amp, frac * amp, spin))
            r = run_to_first_reversal(rigid, 1.2 * t_p if math.isfinite(t_p) else t_end, scene)
            t_r = first_reversal(r)
            window = st["period_window"]
            rp = require_success(paper.with_(t_end=window, theta1=amp, theta2=amp).simulate(), scene)
            rr = require_success(rigid.with_(t_end=window, **rigid_state(amp, amp, spin)).simulate(), scene)
            T_p = _period(rp.t, rp["theta1"], window, band=(0.6 * fast, 1.4 * fast))
            T_r = _period(rr.t, rr["n_y"], window, band=(0.6 * fast, 1.4 * fast))
            rows.append((D, amp, t_p, t_r, T_p, T_r))
    res.data["rows"] = rows
    for D in st["scans"]:
        sel = [r for r in rows if r[0] == D]
        amps = [r[1] for r in sel]
        rev_err = [r[2] / r[3] - 1 for r in sel]
        per_err = [r[4] / r[5] - 1 for r in sel]
        params = {**dict(scene.run.params), "D": D}
        res.numbers[f"reversal_time_paper_D{D:g}"] = [r[2] for r in sel]
        res.numbers[f"reversal_time_rigid_D{D:g}"] = [r[3] for r in sel]
        res.numbers[f"reversal_time_error_D{D:g}"] = rev_err
        res.numbers[f"period_paper_D{D:g}"] = [r[4] for r in sel]
        res.numbers[f"period_rigid_D{D:g}"] = [r[5] for r in sel]
        res.numbers[f"period_error_D{D:g}"] = per_err
        res.numbers[f"linear_periods_paper_D{D:g}"] = linear_periods(params, corrected=False)
        res.numbers[f"linear_periods_corrected_D{D:g}"] = linear_periods(params, corrected=True)
        for what, errs in (("reversal_time", rev_err), ("period", per_err)):
            upto = _within(amps, errs)
            res.numbers[f"{what}_within_1pct_up_to_D{D:g}"] = upto
            res.claim(f"D/ell = {D:g}: the paper's model gives the rigid body's {what.replace('_', ' ')} within 1 %",
                      not math.isnan(upto),
                      (f"up to a largest tilt of {upto:g} rad" if not math.isnan(upto) else "at none of the tilts")
                      + f"; errors at largest tilts {amps}: " + ", ".join(f"{e:+.1%}" for e in errs))
    # the paper's own run (Fig. Numerical2: tilts 1e-3, phi_dot0 = 0.1, D/ell = 1/2)
    progress("the scene of Fig. Numerical2, paper and rigid body")
    y = st["numerical2_state"]
    paper = RunSpec(model="two_mode", fidelity="full", params=dict(scene.run.params), y0=y,
                    t_span=(0.0, 4000.0), rtol=scene.run.rtol, atol=scene.run.atol, n_eval=None)
    rigid = scene.run.with_(t_end=4000.0, **rigid_state(y["theta1"], y["theta2"], y["phi_dot"]))
    r = require_success(rigid.simulate(), scene)
    t_p, t_r = first_crossing_paper(paper, scene), float(r.reversal_times[0])
    res.numbers["numerical2_first_reversal_paper"] = t_p
    res.numbers["numerical2_first_reversal_rigid"] = t_r
    res.claim("at the tilts of Fig. Numerical2 the missing potential term leaves the first reversal time within 1 %",
              abs(t_p / t_r - 1) < 0.01, f"paper {t_p:.2f}, rigid body {t_r:.2f} ({t_p / t_r - 1:+.1%})")
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
    a1.set_xlabel("largest tilt phi_dot0 L/sqrt(g ell) [rad]")
    a1.set_ylabel(r"first reversal time [$\sqrt{\ell/g}$]")
    a1.legend(fontsize=7)
    a2.axhspan(-1, 1, color="0.9")
    a2.set_xlabel("tilt amplitude [rad]")
    a2.set_ylabel("period of theta1: paper / rigid - 1 [%]")
    a2.legend(fontsize=7)
    for ax in (a1, a2):  # the scanned tilts only: matplotlib labels every minor tick of this short log axis
        label_log_ticks(ax, sorted({r[1] for r in rows}))
    fig.suptitle("two-mode knife edge: the paper's model against the rigid body of section III", fontsize=10)
    layout(fig, res.scene is SCENE, dict(left=0.0998, right=0.9800, bottom=0.1011, top=0.9202, wspace=0.2086))


SCENE = Scene(
    name="knife_edge_rigid",
    title="paper's two-mode model vs the rigid knife edge",
    caption=("The chiral knife edge of section III built as the real rigid body (exact in the tilts) against the "
             "paper's two-mode model (full fidelity): first reversal time (first zero of omega.n) and rocking period "
             "against the largest tilt phi_dot0 L/sqrt(g ell) (initial tilts a tenth of it), at the paper's "
             "D/ell = 0.5 and at D/ell = 0.05 and 0.02 (L = 2 ell, alpha = pi/4); and the run of Fig. Numerical2."),
    why=("two_mode_rigid (derivation/rigid.py) is the body the paper's Lagrangian describes; two_mode full isolates "
         "the paper's modelling from its small-angle truncation"),
    run=RUN,
    plots="first reversal time against the tilt amplitude for both models; relative period difference",
    reports=tuple(f"{q}_D{D:g}" for D in (0.5, 0.05, 0.02) for q in (
        "reversal_time_paper", "reversal_time_rigid", "reversal_time_error", "period_paper", "period_rigid",
        "period_error", "linear_periods_paper", "linear_periods_corrected", "reversal_time_within_1pct_up_to",
        "period_within_1pct_up_to")) + ("numerical2_first_reversal_paper", "numerical2_first_reversal_rigid"),
    compute=compute,
    draw=draw,
    settings={"scans": {0.5: (0.02, 0.05, 0.1, 0.2, 0.3), 0.05: (0.02, 0.05, 0.1, 0.2, 0.3),
                        0.02: (0.05, 0.1, 0.2, 0.3)}, "initial_fraction": 0.1,
              "t_end_factor": 200.0, "period_window": 100.0,
              "numerical2_state": {"theta1": 1e-3, "theta2": 1e-3, "theta1_dot": 0.0, "theta2_dot": 0.0,
                                   "phi_dot": 0.1}},
    uses=(("two_mode_rigid", "full", False), ("two_mode", "full", False)),
)
