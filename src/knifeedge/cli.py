"""Command line: ``knifeedge COMMAND --help``.

Commands: ``demo``, ``simulate``, ``derive``, ``scene``, ``figures``, ``sweep``, ``bench``.
Errors are one line on stderr and a non-zero exit status, not a traceback.
"""
from __future__ import annotations

import argparse
import ast
import math
import operator
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



# -- values on the command line -------------------------------------------------
_OPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
        ast.Pow: operator.pow, ast.USub: operator.neg, ast.UAdd: operator.pos}


def number(text: str) -> float:
    """A float from text: ``0.5``, ``1e-3``, ``pi/4``, ``2*pi`` (numbers, ``pi``, + - * / **)."""
    def ev(node):
        if isinstance(node, ast.Expression):
            return ev(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool):
            return float(node.value)
        if isinstance(node, ast.Name) and node.id == "pi":
            return math.pi
        if isinstance(node, ast.BinOp) and type(node.op) in _OPS:
            return _OPS[type(node.op)](ev(node.left), ev(node.right))
        if isinstance(node, ast.UnaryOp) and type(node.op) in _OPS:
            return _OPS[type(node.op)](ev(node.operand))
        raise ValueError
    try:
        return float(ev(ast.parse(text.strip(), mode="eval")))
    except (SyntaxError, ValueError, ZeroDivisionError, OverflowError, RecursionError):
        raise ValueError(f"{text!r} is not a number (accepted: 0.5, 1e-3, pi/4, 2*pi)") from None


def assignments(items, what: str = "--set") -> dict:
    """``["D=0.5", "phi_dot=pi/30"]`` -> ``{"D": 0.5, "phi_dot": 0.1047...}``."""
    out = {}
    for item in items or ():
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise ValueError(f"`{what}` expects NAME=VALUE, got {item!r}")
        out[name.strip()] = number(value)
    return out


def grid_assignments(items) -> dict:
    """``["phi_dot=0.05,0.1,0.2"]`` -> ``{"phi_dot": [0.05, 0.1, 0.2]}``; also ``NAME=START:STOP:N`` (geometric)."""
    out = {}
    for item in items or ():
        name, sep, values = item.partition("=")
        if not sep or not name.strip() or not values.strip():
            raise ValueError(f"`--grid` expects NAME=V1,V2,... or NAME=START:STOP:N, got {item!r}")
        if ":" in values:
            parts = values.split(":")
            if len(parts) != 3:
                raise ValueError(f"`--grid` range must be START:STOP:N, got {values!r}")
            a, b = number(parts[0]), number(parts[1])
            n = int(number(parts[2]))
            if n < 1 or a <= 0 or b <= 0:
                raise ValueError(f"`--grid` range {values!r}: START, STOP must be positive and N >= 1 (geometric spacing)")
            import numpy as np

            out[name.strip()] = [float(v) for v in np.geomspace(a, b, n)]
        else:
            out[name.strip()] = [number(v) for v in values.split(",")]
    return out


# -- simulate -----------------------------------------------------------------
def default_state(model) -> dict:
    """The model's default initial state (its module's ``DEFAULT_STATE``; the pose, if any, starts at 0)."""
    y0 = dict(model.default_state)
    y0.update({n: 0.0 for n in model.state_names if n not in y0 and n in model.pose_names})
    return y0


def _simulate_args(sub: argparse.ArgumentParser) -> None:
    from .models import FIDELITIES, MODEL_NAMES

    sub.add_argument("--model", default="single_mode",
                     help=f"one of {', '.join(MODEL_NAMES)}, or a model in --path (default: %(default)s)")
    sub.add_argument("--fidelity", default=None,
                     help=f"one of {', '.join(FIDELITIES)} (default: reduced for the knife edges, else full)")
    sub.add_argument("--path", type=Path, default=None,
                     help="folder of models written by `knifeedge derive FILE --out DIR` (default: built-in models)")
    sub.add_argument("--pose", action="store_true", help="also integrate the pose (position on the table)")
    sub.add_argument("--set", nargs="+", action="extend", default=[], metavar="NAME=VALUE",
                     help="parameters and initial state by name, e.g. --set D=0.5 phi_dot=0.2 alpha=pi/4. Defaults: "
                          "the model's own (its module's DEFAULT_PARAMS and DEFAULT_STATE; for the knife edges the "
                          "paper's scenes: tilts 1e-3, rates 0, spin 0.1)")
    sub.add_argument("--t-end", type=number, default=300.0, help="end time in sqrt(ell/g) (default: %(default)s)")
    sub.add_argument("--t-start", type=number, default=0.0, help="start time (default: %(default)s)")
    sub.add_argument("--method", default="DOP853", help="integration method, see knifeedge.METHODS (default: %(default)s)")
    sub.add_argument("--rtol", type=number, default=1e-10, help="relative tolerance (default: %(default)s)")
    sub.add_argument("--atol", type=number, default=1e-12, help="absolute tolerance (default: %(default)s)")
    sub.add_argument("--n-eval", type=int, default=4001, help="output samples, equally spaced (default: %(default)s)")
    sub.add_argument("--out", type=Path, help="write the trajectory: .csv (t and states) or .npz")
    sub.add_argument("--plot", type=Path, help="write a PNG of the tilts and the spin")


@command("simulate", "integrate one model; print the spin reversals; optionally write CSV/NPZ and a PNG")
def simulate_cmd(args) -> int:
    import numpy as np

    from . import load, simulate
    from .models import MODEL_NAMES, available

    if args.out is not None and args.out.suffix.lower() not in (".csv", ".npz"):
        raise ValueError(f"`--out` must end in .csv or .npz, got {args.out.name!r}")
    if args.plot is not None and args.plot.suffix.lower() != ".png":
        raise ValueError(f"`--plot` must end in .png, got {args.plot.name!r}")
    if args.n_eval < 2:
        raise ValueError(f"`--n-eval` must be at least 2, got {args.n_eval}")
    fidelity = args.fidelity
    if args.path is None:
        if args.model not in MODEL_NAMES:
            raise ValueError(f"unknown `--model` {args.model!r}; accepted: {', '.join(MODEL_NAMES)} "
                             f"(or a model of your own with `--path`)")
        if fidelity is None:
            fidelity = "reduced" if (args.model, "reduced") in available() else "full"
    elif fidelity is None:
        fidelity = "full"
    m = load(args.model, fidelity=fidelity, pose=args.pose, path=args.path)
    values = assignments(args.set)
    unknown = [k for k in values if k not in m.param_names and k not in m.state_names]
    if unknown:
        raise ValueError(f"`--set`: unknown name(s) {unknown}; parameters {m.param_names}, states {m.state_names}")
    p = {**m.default_params, **{k: v for k, v in values.items() if k in m.param_names}}
    y0 = {**default_state(m), **{k: v for k, v in values.items() if k in m.state_names}}
    lacking = [n for n in m.param_names if n not in p] + [n for n in m.state_names if n not in y0]
    if lacking:
        raise ValueError(f"{m.name} declares no default for {lacking}: give them with `--set NAME=VALUE`")
    t_eval = np.linspace(args.t_start, args.t_end, args.n_eval) if args.t_end > args.t_start else None
    r = simulate(m, y0, (args.t_start, args.t_end), p, method=args.method, rtol=args.rtol, atol=args.atol,
                 t_eval=t_eval)
    print(f"{m.name} ({m.fidelity}{', pose' if m.pose else ''}), " + ", ".join(f"{k}={v:g}" for k, v in p.items()))
    print("  y0: " + ", ".join(f"{k}={v:g}" for k, v in y0.items()))
    rev = r.reversal_times
    if m.reversal_events:
        print(f"  reversals ({len(rev)}): {', '.join(f'{t:.6g}' for t in rev) or 'none'} "
              f"(zero crossings of {', '.join(m.reversal_events)})")
    if len(rev) > 1:
        print(f"  intervals between reversals: {', '.join(f'{d:.6g}' for d in np.diff(rev))}")
    if not r.in_validity_domain:
        print(f"  warning: {r.validity_message}")
    print(f"  {r.method}, rtol={args.rtol:g}, atol={args.atol:g}: {r.nfev} rhs evaluations; {r.message}")
    if args.out is not None:
        args.out.parent.mkdir(parents=True, exist_ok=True)
        if args.out.suffix.lower() == ".csv":
            np.savetxt(args.out, np.column_stack([r.t, r.y.T]), delimiter=",", header=",".join(("t",) + r.state_names),
                       comments="")
        else:
            np.savez(args.out, t=r.t, y=r.y, state_names=np.array(r.state_names), reversal_times=rev,
                     params=np.array([p[n] for n in m.param_names]), param_names=np.array(m.param_names))
        print(f"  trajectory written to {args.out}")
    if args.plot is not None and r.t.size:
        _plot_run(r, m, args.plot)
        print(f"  plot written to {args.plot}")
    if not r.success:
        print(f"knifeedge simulate: integration failed: {r.message}", file=sys.stderr)
        return 1
    return 0


def _plot_run(r, m, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (a1, a2) = plt.subplots(2, 1, sharex=True, figsize=(7.5, 5))
    # top: the coordinates of the closed state (the tilts); bottom: the reversal state, else the rates
    top = [a for a, _ in m.rate_pairs] or list(m.tilt_names) or [m.closed_state_names[0]]
    bottom = [m.spin_name] if m.spin_name else [n for n in m.closed_state_names if n not in top]
    unit = dict(zip(m.state_names, m.state_units))
    for name in top:
        a1.plot(r.t, r[name], lw=0.5, label=name)
    a1.set_ylabel(" ".join(sorted({f"[{unit[n]}]" for n in top})))
    a1.legend(fontsize=8, loc="upper right")
    for k, name in enumerate(bottom):
        a2.plot(r.t, r[name], color=f"C{k + 1}", label=name)
    for t in r.reversal_times:
        a2.axvline(t, color="k", ls=":", lw=0.8)
    a2.axhline(0, color="gray", lw=0.5)
    a2.set_ylabel(" ".join(sorted({f"[{unit[n]}]" for n in bottom})))
    a2.legend(fontsize=8, loc="upper right")
    a2.set_xlabel("t [time]")
    a1.set_title(f"{m.name} ({m.fidelity})", fontsize=10)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


# -- scene ----------------------------------------------------------------------
def _scene_args(sub: argparse.ArgumentParser) -> None:
    from .scenes import SCENE_NAMES

    sub.add_argument("name", nargs="?", help=f"one of {', '.join(SCENE_NAMES)}")
    sub.add_argument("--list", action="store_true", help="list the scenes with their models and exit")
    sub.add_argument("--set", nargs="+", action="extend", default=[], metavar="NAME=VALUE",
                     help="change the scene's main run: parameters, initial state, or rtol/atol/t_end/method")
    sub.add_argument("--out", type=Path, help="PNG to write (default: NAME.png)")


@command("scene", "run one figure's scene: print its model, numbers and verdicts; write its PNG")
def scene_cmd(args) -> int:
    from .scenes import SCENE_NAMES, get_scene

    if args.list:
        for n in SCENE_NAMES:
            s = get_scene(n)
            print(f"{n:15s} {s.title}\n{'':15s} model: {s.run.describe()}\n{'':15s} why: {s.why}")
        return 0
    if not args.name:
        raise ValueError(f"give a scene NAME ({', '.join(SCENE_NAMES)}) or --list")
    if args.out is not None and args.out.suffix.lower() != ".png":
        raise ValueError(f"`--out` must end in .png, got {args.out.name!r}")
    scene = get_scene(args.name, **assignments(args.set))
    result = scene(progress=lambda msg: print(f"scene {scene.name}: {msg}", file=sys.stderr, flush=True))
    print(result.summary())
    out = args.out or Path(f"{scene.name}.png")
    result.savefig(out)
    print(f"  plot written to {out}")
    return 0


# -- figures --------------------------------------------------------------------
def _figures_args(sub: argparse.ArgumentParser) -> None:
    sub.add_argument("--out", type=Path, default=Path("figures"), help="output folder (default: %(default)s)")
    sub.add_argument("--only", nargs="+", metavar="NAME", help="only these scenes")
    sub.add_argument("--workers", type=int, help="processes (default: all cores)")


@command("figures", "every figure of the paper: one PNG per scene and index.html / index.md with captions and numbers")
def figures_cmd(args) -> int:
    from .figures import make_figures

    if args.workers is not None and args.workers < 1:
        raise ValueError(f"`--workers` must be at least 1, got {args.workers}")
    records = make_figures(args.out, names=args.only, max_workers=args.workers)
    failed = [r["name"] for r in records if not r["ok"]]
    print(f"{len(records) - len(failed)} figure(s) written to {args.out}/ (index: {args.out / 'index.html'})")
    if failed:
        print(f"knifeedge figures: scene(s) failed: {', '.join(failed)} (see the index)", file=sys.stderr)
        return 1
    return 0


# -- sweep ----------------------------------------------------------------------
def _sweep_args(sub: argparse.ArgumentParser) -> None:
    from .scenes import SCENE_NAMES

    sub.add_argument("scene", help=f"the base run: a scene name ({', '.join(SCENE_NAMES)})")
    sub.add_argument("--grid", nargs="+", action="extend", default=[], metavar="NAME=V1,V2,...", required=True,
                     help="values of a parameter, an initial state or rtol/atol/t_end; several --grid give their "
                          "Cartesian product; NAME=START:STOP:N is N geometrically spaced values")
    sub.add_argument("--set", nargs="+", action="extend", default=[], metavar="NAME=VALUE",
                     help="change the base run (parameters, initial state, rtol, atol, t_end)")
    sub.add_argument("--out", type=Path, help="results file (.csv or .jsonl), appended run by run; resumed if it exists")
    sub.add_argument("--fresh", action="store_true", help="overwrite --out instead of resuming from it")
    sub.add_argument("--workers", type=int, help="local processes (default: all cores)")
    sub.add_argument("--dask", metavar="ADDRESS",
                     help="run on a Dask cluster: a scheduler address (tcp://host:8786), or 'local' for a LocalCluster")


@command("sweep", "run a scene over a grid of parameters / initial states; a tidy table, resumable, local or on Dask")
def sweep_cmd(args) -> int:
    from .scenes import get_scene
    from .sweep import sweep

    if args.workers is not None and args.workers < 1:
        raise ValueError(f"`--workers` must be at least 1, got {args.workers}")
    if args.out is not None and args.out.suffix.lower() not in (".csv", ".jsonl"):
        raise ValueError(f"`--out` must end in .csv or .jsonl, got {args.out.name!r}")
    scene = get_scene(args.scene, **assignments(args.set))
    grid = grid_assignments(args.grid)
    client = None
    try:
        executor = None
        if args.dask:
            try:
                from distributed import Client, LocalCluster
            except ImportError:
                raise OSError("`--dask` needs the distributed package: pip install 'dask[distributed]'") from None
            if args.dask == "local":
                client = Client(LocalCluster(n_workers=args.workers or None, threads_per_worker=1))
            else:
                client = Client(args.dask)
            executor = client.get_executor()
        table = sweep(scene, grid, executor=executor, max_workers=args.workers, out=args.out, resume=not args.fresh)
    finally:
        if client is not None:
            client.close()
    print(table)
    failed = table.failures()
    print(f"{len(table)} runs ({table.n_computed} computed, {table.n_reused} read back from {args.out}), "
          f"{len(failed)} failed" if args.out else f"{len(table)} runs, {len(failed)} failed")
    for row in failed:
        print(f"  failed run {row['run_id']}: {row['message']}")
    return 0


# -- derive ---------------------------------------------------------------------
def _derive_args(sub: argparse.ArgumentParser) -> None:
    sub.add_argument("files", nargs="+", type=Path, metavar="FILE.py",
                     help="Python files that each define MODEL: a knifeedge.derive.ModelSpec or a list of them")
    sub.add_argument("--out", type=Path, required=True, help="folder to write the generated modules into")
    sub.add_argument("--no-check", action="store_true",
                     help="skip the numerical check of the symmetry at a random general pose")


@command("derive", "derive your own models (files defining MODEL) into compiled modules: load them with path=OUT")
def derive_cmd(args) -> int:
    try:
        from .derive.cli import derive_files
    except ImportError as exc:
        if "sympy" not in str(exc).lower():
            raise
        raise OSError("`knifeedge derive` needs SymPy: pip install 'knifeedge[derive]'") from None
    for path in derive_files(args.files, args.out, check=not args.no_check, log=lambda s: print(s, file=sys.stderr)):
        print(path)
    return 0


# -- bench ----------------------------------------------------------------------
@command("bench", "speed and accuracy benchmarks: run `make bench` (python -m benchmarks) in a source checkout")
def bench_cmd(args) -> int:
    print("The benchmarks live in the source tree, not in the installed package: in a checkout of knifeedge run\n"
          "    make bench        (same as: python -m benchmarks)\n"
          "They report work-precision and speed ratios measured in one run (median of repeats).")
    return 0


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (``knifeedge CMD: error: ...``) and exit status 2."""

    def error(self, message: str):
        print(f"{self.prog}: error: {message} (see {self.prog} --help)", file=sys.stderr)
        raise SystemExit(2)


_ARGS = {"demo": _demo_args, "simulate": _simulate_args, "scene": _scene_args, "figures": _figures_args,
         "sweep": _sweep_args, "derive": _derive_args}


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="knifeedge", description="Simulators of the chiral knife-edge rattleback.")
    subs = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
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
        msg = exc.args[0] if isinstance(exc, KeyError) and exc.args else exc
        print(f"knifeedge {args.command}: error: {msg}", file=sys.stderr)
        return 2
    except RuntimeError as exc:
        print(f"knifeedge {args.command}: error: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print(f"knifeedge {args.command}: interrupted", file=sys.stderr)
        return 130
