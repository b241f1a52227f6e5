"""What Lyapunov exponents cost against a plain run, at equal accuracy; and the race with jitcode.

``python -m benchmarks.lyapunov_speed [--span 1e4] [--repeats 3] [--no-jitcode] [--out benchmarks/results]``

The celt (Schoemer's set, undamped) from a slightly tilted spin at -2 rad/s (it reverses, as in scene
``celt_schoemer``), over ``--span`` seconds:

* **accuracy**: ``ke.lyapunov`` steps the state and the tangent vectors by fixed-step RK4 (step ``h``).  Its
  accuracy is measured as the state's error after ``--accuracy-span`` seconds against DOP853 at rtol 1e-13, and
  the energy drift over the whole span; the DOP853 tolerance with the same error is "the tolerance the step
  corresponds to".
* **cost**, median CPU time of ``--repeats``, interleaved in one process (warm): a plain RK4 run with the same step (the
  same method and step), plain DP54 and DOP853 runs at ``rtol``, the largest exponent (``k=1``) and
  the full spectrum (5 exponents of the physical phase space), step-controlled (the tangent vectors at their
  default tolerance -- ``rtol`` for Runge-Kutta tangents, ``MAGNUS_TANGENT_RTOL rtol`` for Magnus tangents --, at
  ``rtol`` and at ``--tangent-rtol``, looser; each by the default tangent method -- DOP853 stages with the state for
  the largest, Magnus steps beside the state's DP54 steps for the spectrum -- and by the other one) and fixed-step;
  the steps of each (and the Magnus tangent steps).  The issue's bars: largest <= 3x, full <= 10x a plain run of
  the same span at the same tolerance, each by its state's method (``bars``: the largest against plain DOP853, the
  full spectrum against plain DP54).
* **jitcode** (optional peer, ``pip install jitcode``; skipped with a note when absent): ``jitcode_lyap`` on the
  same equations -- ``M(n) domega/dt = f(n, omega)``, ``dn/dt = n x omega`` from ``derivation.rigid.equations``
  (the derivation the generated module comes from), fed to jitcode as common subexpressions (``helpers``, from
  ``sympy.cse``) and Cramer's rule on the 3 x 3 solve, so that jitcode neither expands nor simplifies them --
  with its DOP853 at the matching tolerance; its set-up (symbolic Jacobian, C code, compile) and run timed apart.

Writes ``lyapunov_speed.json``.
"""
from __future__ import annotations

import argparse
import json
import math
import statistics
import time
from pathlib import Path

import numpy as np

import knifeedge as ke

PRESET, TILT, SPIN = "schoemer", 0.05, -2.0
#: the re-orthonormalization interval (s)
TAU = 1.0


def setup():
    m = ke.load("celt")
    p = m.preset(PRESET, sigma=0.0)
    y0 = m.initial_state(n0=(math.sin(TILT), 0.0, math.cos(TILT)), omega0=(0.0, 0.0, SPIN))
    return m, p, y0


def _run(m, y0, p, span, **kw):
    return ke.simulate(m, y0, (0.0, span), p, t_eval=np.array([span]), max_steps=10**9, **kw)


def _end(m, y0, p, span, **kw):
    return _run(m, y0, p, span, **kw).y[:, -1]


def accuracy(m, p, y0, rtol: float, h: float, span: float) -> dict:
    """State errors after ``span`` (relative to the largest component) against DOP853 at rtol 1e-13: of DP54 at
    ``rtol`` (the state's method and tolerance of the Magnus loop), of RK4 at ``h`` (the fixed-step loop's
    default step) and of DOP853 at several tolerances."""
    ref = _end(m, y0, p, span, rtol=1e-13, atol=1e-15)
    err = lambda y: float(np.abs(y - ref).max() / np.abs(ref).max())  # noqa: E731
    e_dp54 = err(_end(m, y0, p, span, method="DP54", rtol=rtol, atol=rtol * 1e-2))
    e_rk4 = err(_end(m, y0, p, span, method="RK4", h=h))
    dop = {r: err(_end(m, y0, p, span, rtol=r, atol=r * 1e-2)) for r in 10.0 ** -np.arange(5, 13)}
    # the loosest DOP853 tolerance at least as accurate as DP54 at rtol
    matching = max((r for r, e in dop.items() if e <= e_dp54), default=min(dop))
    rk4_matching = max((r for r, e in dop.items() if e <= e_rk4), default=min(dop))
    return {"rtol": rtol, "h_rk4": h, "span": span, "dp54_error": e_dp54, "rk4_error": e_rk4,
            "dop853_error": {f"{r:.0e}": e for r, e in dop.items()}, "dop853_matching_rtol": matching,
            "dop853_rtol_matching_rk4": rk4_matching}


def costs(m, p, y0, span: float, rtol: float, h: float, repeats: int, tangent_rtol: float) -> dict:
    """Median CPU times (warm, interleaved) of the plain runs and the variational loops over ``span``."""
    atol = rtol * 1e-2
    runs = {
        "plain_dp54": lambda: _run(m, y0, p, span, method="DP54", rtol=rtol, atol=atol),
        "plain_dop853": lambda: _run(m, y0, p, span, rtol=rtol, atol=atol),
        "plain_rk4": lambda: _run(m, y0, p, span, method="RK4", h=h),
        "largest": lambda: ke.lyapunov(m, y0, p, span, k=1, tau=TAU, rtol=rtol, atol=atol),
        "full": lambda: ke.lyapunov(m, y0, p, span, tau=TAU, rtol=rtol, atol=atol),
        "full_tangents_at_rtol": lambda: ke.lyapunov(m, y0, p, span, tau=TAU, rtol=rtol, atol=atol, tangent_rtol=rtol),
        "largest_loose": lambda: ke.lyapunov(m, y0, p, span, k=1, tau=TAU, rtol=rtol, atol=atol,
                                             tangent_rtol=tangent_rtol),
        "full_loose": lambda: ke.lyapunov(m, y0, p, span, tau=TAU, rtol=rtol, atol=atol, tangent_rtol=tangent_rtol),
        "largest_magnus": lambda: ke.lyapunov(m, y0, p, span, k=1, tau=TAU, rtol=rtol, atol=atol, tangents="magnus"),
        "full_rk_tangents": lambda: ke.lyapunov(m, y0, p, span, tau=TAU, rtol=rtol, atol=atol, tangents="rk"),
        "largest_rk4": lambda: ke.lyapunov(m, y0, p, span, k=1, h=h, tau=TAU),
        "full_rk4": lambda: ke.lyapunov(m, y0, p, span, h=h, tau=TAU),
    }
    # warm: every kernel compiled or loaded before the clock starts
    _end(m, y0, p, 1.0, method="DP54", rtol=rtol, atol=atol)
    _end(m, y0, p, 1.0, rtol=rtol, atol=atol)
    _end(m, y0, p, 1.0, method="RK4", h=h)
    ke.lyapunov(m, y0, p, 1.0, k=1, tau=TAU, rtol=rtol)
    ke.lyapunov(m, y0, p, 1.0, k=1, tau=TAU, rtol=rtol, tangents="magnus")
    ke.lyapunov(m, y0, p, 1.0, tau=TAU, rtol=rtol, tangents="rk")
    ke.lyapunov(m, y0, p, 1.0, k=1, h=h, tau=TAU)
    samples = {k: [] for k in runs}
    out = {}
    for _ in range(repeats):  # interleaved
        for k, fn in runs.items():
            t = time.process_time()
            out[k] = fn()
            samples[k].append(time.process_time() - t)
    med = {k: statistics.median(v) for k, v in samples.items()}
    # the exponents' errors, from a tight reference: the state at 1e-3 rtol, Magnus tangents at 1e-5 rtol (a
    # reference on the state's trajectory at ``rtol`` would count the other state methods' own, smaller, errors);
    # DP54 at 1e-4 rtol with Magnus tangents at 1e-6 rtol, and DOP853 at 1e-4 rtol for both, agree with it to about
    # 1e-11 on the celt over 10^4 s
    ref = ke.lyapunov(m, y0, p, span, tau=TAU, rtol=rtol * 1e-3, atol=atol * 1e-3, tangent_rtol=rtol * 1e-5)
    errors = {k: float(np.abs(r.exponents - ref.exponents).max()) for k, r in out.items()
              if k.startswith("full") and not k.endswith("rk4")}
    errors.update({k: abs(float(out[k].exponents[0] - ref.exponents[0])) for k in ("largest", "largest_magnus")})
    e0 = float(m.energy(y0, p))
    drift = lambda y: abs(float(m.energy(y, p)) - e0) / abs(e0)  # noqa: E731
    steps = {k: (r.nsteps if k.startswith("plain") else r.steps) for k, r in out.items()}
    tangent_steps = {k: r.tangent_steps for k, r in out.items() if not k.startswith("plain") and r.tangent_steps}
    return {
        # the medians of the repeats' own ratios (each pair run within seconds: steadier on a loaded machine than
        # the ratio of the medians, the ratio_* below)
        "bars": {"largest_vs_plain_dop853 (<= 3)": _paired(samples, "largest", "plain_dop853"),
                 "full_vs_plain_dp54 (<= 10)": _paired(samples, "full", "plain_dp54")},
        "seconds": med, "samples": samples, "steps": steps, "tangent_steps": tangent_steps, "tangent_rtol": tangent_rtol,
        "ratio_largest_vs_dp54": med["largest"] / med["plain_dp54"], "ratio_full_vs_dp54": med["full"] / med["plain_dp54"],
        "ratio_largest_loose_vs_dp54": med["largest_loose"] / med["plain_dp54"],
        "ratio_full_loose_vs_dp54": med["full_loose"] / med["plain_dp54"],
        "ratio_full_tangents_at_rtol_vs_dp54": med["full_tangents_at_rtol"] / med["plain_dp54"],
        "ratio_largest_vs_dop853": med["largest"] / med["plain_dop853"],
        "ratio_full_vs_dop853": med["full"] / med["plain_dop853"],
        "ratio_largest_magnus_vs_dp54": med["largest_magnus"] / med["plain_dp54"],
        "ratio_full_rk_tangents_vs_dp54": med["full_rk_tangents"] / med["plain_dp54"],
        "ratio_largest_rk4_vs_rk4": med["largest_rk4"] / med["plain_rk4"],
        "ratio_full_rk4_vs_rk4": med["full_rk4"] / med["plain_rk4"],
        "steps_dp54_loop": out["full"].steps, "rejected_dp54_loop": out["full"].rejected,
        "exponents": [float(x) for x in out["full"].exponents], "uncertainty": [float(x) for x in out["full"].uncertainty],
        "exponents_rk4": [float(x) for x in out["full_rk4"].exponents],
        "exponents_loose": [float(x) for x in out["full_loose"].exponents],
        "exponents_tangents_at_rtol": [float(x) for x in out["full_tangents_at_rtol"].exponents],
        "exponents_rk_tangents": [float(x) for x in out["full_rk_tangents"].exponents],
        "largest": float(out["largest"].exponents[0]),
        "exponents_reference": [float(x) for x in ref.exponents], "exponent_errors": errors,
        "energy_drift": {"dp54_loop": drift(out["full"].y), "plain_dp54": drift(out["plain_dp54"].y[:, -1]),
                         "plain_dop853": drift(out["plain_dop853"].y[:, -1]), "rk4_loop": drift(out["full_rk4"].y)},
    }


def _paired(samples: dict, a: str, b: str) -> float:
    """The median over the repeats of ``a``'s time over ``b``'s (same repeat)."""
    return statistics.median(x / y for x, y in zip(samples[a], samples[b]))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.lyapunov_speed", description=__doc__.splitlines()[0])
    ap.add_argument("--span", type=float, default=1e4)
    ap.add_argument("--accuracy-span", type=float, default=100.0)
    ap.add_argument("--rtol", type=float, default=1e-8, help="tolerance of the adaptive loop and the plain DP54 run")
    ap.add_argument("--h", type=float, default=None, help="RK4 step (default: ke.lyapunov's)")
    ap.add_argument("--tangent-rtol", type=float, default=1e-6, help="the looser tolerance of the tangent vectors")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--no-jitcode", action="store_true")
    ap.add_argument("--jitcode-span", type=float, default=None, help="span of the jitcode run (default --span)")
    ap.add_argument("--out", type=Path, default=Path(__file__).resolve().parent / "results")
    args = ap.parse_args(argv)
    m, p, y0 = setup()
    h = args.h or _default_h(m, p, y0)
    res = {"model": f"celt full, {PRESET}, undamped; n0 tilted {TILT} rad, spin {SPIN} rad/s", "span": args.span,
           "tau": TAU}
    res["accuracy"] = acc = accuracy(m, p, y0, args.rtol, h, args.accuracy_span)
    print(f"after {args.accuracy_span:g} s: DP54 rtol {args.rtol:g} error {acc['dp54_error']:.2e}, RK4 h = {h:.3g} "
          f"{acc['rk4_error']:.2e}; DOP853 {acc['dop853_error']}; DOP853 matching DP54: rtol "
          f"{acc['dop853_matching_rtol']:.0e}, matching RK4: {acc['dop853_rtol_matching_rk4']:.0e}", flush=True)
    res["costs"] = c = costs(m, p, y0, args.span, args.rtol, h, args.repeats, args.tangent_rtol)
    print(json.dumps({k: c[k] for k in c if k != "samples"}, indent=1), flush=True)
    if not args.no_jitcode:
        from . import lyapunov_jitcode

        res["jitcode"] = lyapunov_jitcode.race(m, p, y0, args.jitcode_span or args.span, args.rtol, TAU,
                                               c["seconds"]["full"], c["exponents"])
        print(json.dumps(res["jitcode"], indent=1), flush=True)
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "lyapunov_speed.json").write_text(json.dumps(res, indent=1))
    return 0


def _default_h(m, p, y0) -> float:
    """``ke.lyapunov``'s default step: 1/50 of the period of the fastest linear mode at ``y0``."""
    rho = float(np.max(np.abs(np.linalg.eigvals(m.jacobian(y0, p)))))
    return 2 * math.pi / rho / 50


if __name__ == "__main__":
    raise SystemExit(main())
