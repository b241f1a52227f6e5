"""Command line: ``knifeedge COMMAND --help``.

Errors are one line on stderr and a non-zero exit status, not a traceback.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

COMMANDS: dict = {}


def command(name: str, help: str):
    def register(fn):
        COMMANDS[name] = (fn, help)
        return fn

    return register


def _demo_args(sub: argparse.ArgumentParser) -> None:
    sub.add_argument("--out", type=Path, default=Path("knifeedge-demo.png"), help="PNG to write (default: %(default)s)")
    sub.add_argument("--t-end", type=float, default=300.0, help="end time in units of sqrt(ell/g) (default: %(default)s)")


@command("demo", "single-mode spin reversal (paper Fig. 'numerical'): print the result, write a plot")
def demo(args) -> int:
    import numpy as np

    from . import load, simulate

    model = load("single_mode", fidelity="full")
    p = model.params(g=1.0, ell=1.0, L=1.0, D=1.0)
    y0 = {"theta": 1e-3, "theta_dot": 0.0, "phi_dot": 0.1}
    r = simulate(model, y0, (0.0, args.t_end), p, method="DOP853", rtol=1e-10, atol=1e-12,
                 t_eval=np.linspace(0.0, args.t_end, 6001))
    if not r.success:
        print(f"knifeedge demo: integration failed: {r.message}", file=sys.stderr)
        return 1
    e = r.energy
    print("single_mode (full), l/L = 1, D/l = 1, phi_dot(0) = 0.1 sqrt(g/l), theta(0) = 1e-3")
    print(f"  spin reversals at t = {', '.join(f'{t:.4f}' for t in r.reversal_times) or 'none'}")
    print(f"  phi_dot: {r['phi_dot'][0]:+.6f} -> {r['phi_dot'][-1]:+.6f}")
    print(f"  max |theta| = {np.max(np.abs(r['theta'])):.5f} rad")
    print(f"  relative energy drift = {np.max(np.abs(e - e[0])) / abs(e[0]):.2e} over {r.nfev} rhs evaluations")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (a1, a2) = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    a1.plot(r.t, r["theta"], lw=0.6)
    a1.set_ylabel(r"$\theta$ [rad]")
    a1.set_title("single mode knife edge: spin reversal (paper Fig. 'numerical')")
    a2.plot(r.t, r["phi_dot"])
    for t in r.reversal_times:
        a2.axvline(t, color="k", ls=":", lw=0.8)
    a2.axhline(0, color="gray", lw=0.5)
    a2.set_ylabel(r"$\dot\phi$ [$\sqrt{g/\ell}$]")
    a2.set_xlabel(r"t [$\sqrt{\ell/g}$]")
    fig.tight_layout()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out, dpi=120)
    print(f"  plot written to {args.out}")
    return 0


_ARGS = {"demo": _demo_args}


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="knifeedge", description="Simulators of the chiral knife-edge rattleback.")
    subs = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, (fn, help) in COMMANDS.items():
        sub = subs.add_parser(name, help=help, description=help)
        _ARGS.get(name, lambda s: None)(sub)
        sub.set_defaults(func=fn)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        return int(args.func(args) or 0)
    except (ValueError, TypeError, KeyError, OSError) as exc:
        print(f"knifeedge {args.command}: error: {exc}", file=sys.stderr)
        return 2
