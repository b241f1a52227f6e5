"""Command line: ``knifeedge COMMAND --help``.

Commands: ``demo``, ``simulate``, ``derive``, ``scene``, ``figures``, ``sweep``, ``animate``, ``bench``.
Errors are one line on stderr and a non-zero exit status, not a traceback.
"""
from __future__ import annotations

import argparse
import ast
import contextlib
import gc
import math
import operator
import os
import sys
from pathlib import Path

from ._output import replacing, writable

COMMANDS: dict = {}


def command(name: str, help: str):
    def register(fn):
        COMMANDS[name] = (fn, help)
        return fn

    return register


def _demo_args(sub: argparse.ArgumentParser) -> None:
    sub.add_argument("--out", type=Path, default=Path("knifeedge-demo.png"), help="PNG to write (default: %(default)s)")
    sub.add_argument("--t-end", type=number, default=300.0, help="end time in units of sqrt(ell/g) (default: %(default)s)")


@command("demo", "single-mode spin reversal (paper Fig. 'numerical'): print the result, write a plot")
def demo(args) -> int:
    import numpy as np

    from . import load, simulate

    if args.out.suffix.lower() != ".png":
        raise ValueError(f"`--out` must end in .png, got {args.out.name!r}")
    writable(args.out, "`--out`")
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
    with replacing(args.out) as tmp:
        fig.savefig(tmp, dpi=120)
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


#: most output samples (``--n-eval``, ``n_eval``) the command line will allocate: 8 MB per state
MAX_N_EVAL = 1_000_000
#: most values one ``--grid`` range may make, and most runs a sweep may start
MAX_GRID_VALUES = 100_000
MAX_SWEEP_RUNS = 1_000_000


def count(text: str, what: str, high: int | None = None) -> int:
    """A positive integer from text (``4001``, ``1e4``, ``2**20``), at most ``high``; errors name ``what``."""
    try:
        v = number(text)
    except ValueError:
        raise ValueError(f"{what} must be a positive integer, got {text!r}") from None
    if not (math.isfinite(v) and v == int(v) and v >= 1):
        raise ValueError(f"{what} must be a positive integer, got {text!r}")
    if high is not None and v > high:
        limit = "2**63 - 1" if high == 2**63 - 1 else str(high)
        raise ValueError(f"{what} must be at most {limit}, got {text!r}")
    return int(v)


def _flag(text: str, what: str) -> bool:
    t = text.strip().lower()
    if t in ("true", "yes", "1", "on"):
        return True
    if t in ("false", "no", "0", "off"):
        return False
    raise ValueError(f"{what} must be true or false, got {text!r}")


def _text(text: str, what: str) -> str:
    t = text.strip()
    if not t:
        raise ValueError(f"{what} needs a value")
    return t


#: run settings that are not real numbers, and how the command line reads them (the others are numbers)
SETTING_READERS = {
    "method": _text,
    "fidelity": _text,
    "pose": _flag,
    "n_eval": lambda text, what: count(text, what, MAX_N_EVAL),
    "max_steps": lambda text, what: count(text, what, 2**63 - 1),
}


def value(name: str, text: str, what: str):
    """The value of ``NAME=TEXT``: a number, or what :data:`SETTING_READERS` reads for a setting."""
    reader = SETTING_READERS.get(name)
    if reader is not None:
        return reader(text, f"`{what} {name}`")
    try:
        return number(text)
    except ValueError as exc:
        raise ValueError(f"`{what} {name}`: {exc}") from None


def assignments(items, what: str = "--set") -> dict:
    """``["D=0.5", "phi_dot=pi/30", "method=DP54"]`` -> ``{"D": 0.5, "phi_dot": 0.1047..., "method": "DP54"}``.

    A name given twice is refused (not silently the last).
    """
    out = {}
    for item in items or ():
        name, sep, text = item.partition("=")
        name = name.strip()
        if not sep or not name:
            raise ValueError(f"`{what}` expects NAME=VALUE, got {item!r}")
        if name in out:
            raise ValueError(f"`{what}` gives {name!r} twice; give each name once")
        out[name] = value(name, text, what)
    return out


def input_assignments(items, model) -> dict | None:
    """``["tau=0.5", "f=samples.csv"]`` -> ``{"tau": 0.5, "f": (t, u)}`` (``None`` for a model without inputs
    given none): a number, or a CSV file of samples read by :func:`knifeedge.inputs.read_samples`."""
    from .inputs import read_samples

    if not items and not model.input_names:
        return None
    out = {}
    for item in items:
        name, sep, text = item.partition("=")
        name, text = name.strip(), text.strip()
        if not sep or not name:
            raise ValueError(f"`--input` expects NAME=VALUE or NAME=FILE.csv, got {item!r}")
        if name in out:
            raise ValueError(f"`--input` gives {name!r} twice; give each input once")
        if text.lower().endswith(".csv"):
            out[name] = read_samples(Path(text), name)
        else:
            try:
                out[name] = number(text)
            except ValueError as exc:
                raise ValueError(f"`--input {name}`: {exc} (or give a samples file NAME=FILE.csv)") from None
    return out


def grid_assignments(items) -> dict:
    """``["phi_dot=0.05,0.1,0.2"]`` -> ``{"phi_dot": [0.05, 0.1, 0.2]}``; also ``NAME=START:STOP:N`` (geometric).

    ``N`` must be a whole number (at most :data:`MAX_GRID_VALUES`); a name given twice is refused.
    """
    out = {}
    for item in items or ():
        name, sep, values = item.partition("=")
        name = name.strip()
        if not sep or not name or not values.strip():
            raise ValueError(f"`--grid` expects NAME=V1,V2,... or NAME=START:STOP:N, got {item!r}")
        if name in out:
            raise ValueError(f"`--grid` gives {name!r} twice; list all its values in one --grid {name}=V1,V2,...")
        if ":" in values:
            parts = values.split(":")
            if len(parts) != 3:
                raise ValueError(f"`--grid {name}` range must be START:STOP:N, got {values!r}")
            if name in SETTING_READERS:
                raise ValueError(f"`--grid {name}` takes a list of values ({name}=V1,V2,...), not a range")
            a, b = value(name, parts[0], "--grid"), value(name, parts[1], "--grid")
            n = count(parts[2], f"`--grid {name}` range's N", MAX_GRID_VALUES)
            if a <= 0 or b <= 0:
                raise ValueError(f"`--grid {name}` range {values!r}: START and STOP must be positive (geometric spacing)")
            import numpy as np

            out[name] = [float(v) for v in np.geomspace(a, b, n)]
        else:
            out[name] = [value(name, v, "--grid") for v in values.split(",")]
    return out


# -- simulate -----------------------------------------------------------------
def default_state(model) -> dict:
    """The model's default initial state (its module's ``DEFAULT_STATE``; the pose, if any, starts at 0)."""
    y0 = dict(model.default_state)
    y0.update({n: 0.0 for n in model.state_names if n not in y0 and n in model.pose_names})
    return y0


def _n_eval(text: str) -> int:
    try:
        n = count(text, "`--n-eval`", MAX_N_EVAL)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None
    if n < 2:
        raise argparse.ArgumentTypeError(f"`--n-eval` must be at least 2, got {text!r}")
    return n


def _max_steps(text: str) -> int:
    try:
        return count(text, "`--max-steps`", 2**63 - 1)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


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
    sub.add_argument("--input", nargs="+", action="extend", default=[], metavar="NAME=VALUE|NAME=FILE.csv",
                     help="a run-time input of the model (model.input_names): a number, or a CSV file of samples "
                          "(columns t, value; interpolated piecewise linearly)")
    sub.add_argument("--t-end", type=number, default=300.0, help="end time in sqrt(ell/g) (default: %(default)s)")
    sub.add_argument("--t-start", type=number, default=0.0, help="start time (default: %(default)s)")
    sub.add_argument("--method", default="DOP853", help="integration method, see knifeedge.METHODS (default: %(default)s)")
    sub.add_argument("--rtol", type=number, default=1e-10, help="relative tolerance (default: %(default)s)")
    sub.add_argument("--atol", type=number, default=1e-12, help="absolute tolerance (default: %(default)s)")
    sub.add_argument("--n-eval", type=_n_eval, default=4001,
                     help=f"output samples, equally spaced, 2 to {MAX_N_EVAL} (default: %(default)s)")
    sub.add_argument("--h", type=number, help="step of a fixed-step method (RK4, implicit_midpoint, gauss4, gauss6)")
    sub.add_argument("--max-steps", type=_max_steps, default=1_000_000,
                     help="steps allowed before the run stops and reports a failure (default: %(default)s)")
    sub.add_argument("--max-step", type=number, default=math.inf,
                     help="largest step of an adaptive method (default: unbounded)")
    sub.add_argument("--error-control", default="component", choices=("component", "mode"),
                     help="compiled adaptive methods: 'component' (as SciPy) or 'mode' (default: %(default)s)")
    sub.add_argument("--out", type=Path, help="write the trajectory: .csv (t and states) or .npz")
    sub.add_argument("--plot", type=Path, help="write a PNG of the tilts and the spin")


#: settings that ``simulate`` takes as options rather than through ``--set``
_SIMULATE_OPTIONS = ("method", "fidelity", "model", "pose", "rtol", "atol", "t_end", "t_start", "n_eval", "h",
                     "max_steps", "max_step", "error_control")


@command("simulate", "integrate one model; print the spin reversals; optionally write CSV/NPZ and a PNG")
def simulate_cmd(args) -> int:
    import numpy as np

    from . import load, simulate
    from .models import MODEL_NAMES, available

    if args.out is not None and args.out.suffix.lower() not in (".csv", ".npz"):
        raise ValueError(f"`--out` must end in .csv or .npz, got {args.out.name!r}")
    if args.plot is not None and args.plot.suffix.lower() != ".png":
        raise ValueError(f"`--plot` must end in .png, got {args.plot.name!r}")
    for path, flag in ((args.out, "`--out`"), (args.plot, "`--plot`")):
        if path is not None:
            writable(path, flag)
    if not args.t_end > args.t_start:
        raise ValueError(f"`--t-end` must exceed `--t-start` ({args.t_start:g}), got {args.t_end:g}")
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
    settings = [k for k in (item.partition("=")[0].strip() for item in args.set) if k in _SIMULATE_OPTIONS]
    if settings:
        k = settings[0]
        raise ValueError(f"`--set {k}`: {k} is an option of simulate here, give it as --{k.replace('_', '-')} VALUE")
    values = assignments(args.set)
    unknown = [k for k in values if k not in m.param_names and k not in m.state_names]
    if unknown:
        given = [k for k in unknown if k in m.input_names]
        hint = f"; give the inputs {given} with `--input NAME=VALUE` or `--input NAME=FILE.csv`" if given else ""
        raise ValueError(f"`--set`: unknown name(s) {unknown}; parameters {m.param_names}, states {m.state_names}"
                         + hint)
    p = {**m.default_params, **{k: v for k, v in values.items() if k in m.param_names}}
    y0 = {**default_state(m), **{k: v for k, v in values.items() if k in m.state_names}}
    lacking = [n for n in m.param_names if n not in p] + [n for n in m.state_names if n not in y0]
    if lacking:
        raise ValueError(f"{m.name} declares no default for {lacking}: give them with `--set NAME=VALUE`")
    t_eval = np.linspace(args.t_start, args.t_end, args.n_eval)
    r = simulate(m, y0, (args.t_start, args.t_end), p, method=args.method, rtol=args.rtol, atol=args.atol,
                 t_eval=t_eval, max_step=args.max_step, h=args.h, max_steps=args.max_steps,
                 error_control=args.error_control, inputs=input_assignments(args.input, m))
    print(f"{m.name} ({m.fidelity}{', pose' if m.pose else ''}), " + ", ".join(f"{k}={v:g}" for k, v in p.items()))
    print("  y0: " + ", ".join(f"{k}={v:g}" for k, v in y0.items()))
    if r.inputs is not None:
        print("  inputs: " + ", ".join(
            f"{n}={d:g}" if kind == "constant" else f"{n}: {d[0].size} samples (piecewise linear)"
            for n, kind, d in zip(r.inputs.names, r.inputs.kinds, r.inputs.data)))
    rev = r.reversal_times
    if m.reversal_events:
        print(f"  reversals ({len(rev)}): {', '.join(f'{t:.6g}' for t in rev) or 'none'} "
              f"(zero crossings of {', '.join(m.reversal_events)})")
    if len(rev) > 1:
        print(f"  intervals between reversals: {', '.join(f'{d:.6g}' for d in np.diff(rev))}")
    if not r.in_validity_domain:
        print(f"  warning: {r.validity_message}")
    control = f"h={args.h:g}" if args.h is not None else f"rtol={args.rtol:g}, atol={args.atol:g}"
    print(f"  {r.method}, {control}: {r.nsteps} steps, {r.nfev} rhs evaluations; {r.message}")
    if args.out is not None:
        with replacing(args.out) as tmp, open(tmp, "wb") as f:  # a file object: savez adds no ".npz" to ".NPZ"
            if args.out.suffix.lower() == ".csv":
                np.savetxt(f, np.column_stack([r.t, r.y.T]), delimiter=",", header=",".join(("t",) + r.state_names),
                           comments="")
            else:
                np.savez(f, t=r.t, y=r.y, state_names=np.array(r.state_names), reversal_times=rev,
                         params=np.array([p[n] for n in m.param_names]), param_names=np.array(m.param_names))
        print(f"  trajectory written to {args.out}")
    if args.plot is not None and r.t.size:
        with replacing(args.plot) as tmp:
            _plot_run(r, m, tmp)
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
            print(f"{n:15s} {s.title}\n{'':15s} model: {s.describe_model()}\n{'':15s} why: {s.why}")
        return 0
    if not args.name:
        raise ValueError(f"give a scene NAME ({', '.join(SCENE_NAMES)}) or --list")
    if args.out is not None and args.out.suffix.lower() != ".png":
        raise ValueError(f"`--out` must end in .png, got {args.out.name!r}")
    scene = get_scene(args.name, **assignments(args.set))
    out = writable(args.out or Path(f"{scene.name}.png"), "`--out`")
    result = scene(progress=lambda msg: print(f"scene {scene.name}: {msg}", file=sys.stderr, flush=True))
    print(result.summary())
    with replacing(out) as tmp:
        result.savefig(tmp)
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
    writable(args.out / "index.html", "`--out`")  # the folder, made if needed
    records = make_figures(args.out, names=args.only, max_workers=args.workers)
    failed = [r["name"] for r in records if not r["ok"]]
    print(f"{len(records) - len(failed)} figure(s) written to {args.out}/ (index: {args.out / 'index.html'})")
    if failed:
        print(f"knifeedge figures: scene(s) failed: {', '.join(failed)} (see the index)", file=sys.stderr)
        return 1
    return 0


# -- animate --------------------------------------------------------------------
def _animate_args(sub: argparse.ArgumentParser) -> None:
    from .scenes import SCENE_NAMES

    sub.add_argument("name", help=f"the scene to draw: one of {', '.join(SCENE_NAMES)}")
    sub.add_argument("--out", type=Path, help="file to write, .gif (pillow) or .mp4 (needs ffmpeg); default NAME.gif")
    sub.add_argument("--frames", type=int, default=240, help="number of frames (default: %(default)s)")
    sub.add_argument("--fps", type=float, default=20.0, help="frames per second (default: %(default)s)")
    sub.add_argument("--magnify", default="auto",
                     help="factor for the tilt angles, or 'auto' (largest tilt drawn at ~23 degrees; default)")
    sub.add_argument("--dpi", type=int, default=80, help="pixels per inch of the 8 x 4.5 inch frame (default: %(default)s)")
    sub.add_argument("--set", nargs="+", action="extend", default=[], metavar="NAME=VALUE",
                     help="change the scene's main run: parameters, initial state, or rtol/atol/t_end/method")


@command("animate", "GIF or MP4 of a scene's run: the body in 3D, its contact path, its spin rate, the time")
def animate_cmd(args) -> int:
    from .animation import animate
    from .scenes import get_scene

    try:
        magnify = args.magnify if args.magnify == "auto" else number(args.magnify)
    except ValueError as exc:
        raise ValueError(f"`--magnify`: {exc} or auto") from None
    scene = get_scene(args.name, **assignments(args.set))
    out = args.out or Path(f"{scene.name}.gif")
    info = animate(scene, out, frames=args.frames, fps=args.fps, magnify=magnify, dpi=args.dpi,
                   title=f"scene {scene.name}: {scene.title}",
                   progress=lambda msg: print(f"animate {scene.name}: {msg}", file=sys.stderr, flush=True))
    print(info.summary())
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
    sub.add_argument("--out", type=Path,
                     help="results store: NAME.sqlite (SQLite, one row per run, committed as runs finish), or "
                          "NAME.csv / NAME.jsonl (a text export of the rows, kept in NAME.sqlite); an existing store "
                          "is resumed, and sweeps running at once on one store share the work")
    sub.add_argument("--fresh", action="store_true", help="recompute the runs already in --out (and replace them)")
    sub.add_argument("--workers", type=int, help="local processes (default: all cores)")
    sub.add_argument("--dask", metavar="ADDRESS",
                     help="run on a Dask cluster: a scheduler address (tcp://host:8786), or 'local' for a LocalCluster")


@command("sweep", "run a scene over a grid of parameters / initial states; a tidy table, resumable, local or on Dask")
def sweep_cmd(args) -> int:
    import warnings

    from .scenes import get_scene
    from .sweep import sweep

    if args.workers is not None and args.workers < 1:
        raise ValueError(f"`--workers` must be at least 1, got {args.workers}")
    changes = assignments(args.set)
    scene = get_scene(args.scene, **changes)
    grid = grid_assignments(args.grid)
    both = [k for k in grid if k in changes]
    if both:
        raise ValueError(f"`--set` and `--grid` both give {both[0]!r}: give it in one of them")
    n_runs = math.prod(len(v) for v in grid.values())
    if n_runs > MAX_SWEEP_RUNS:
        raise ValueError(f"`--grid` makes {n_runs:.3g} runs, more than the {MAX_SWEEP_RUNS} one sweep may start")
    client = cluster = None
    try:
        executor = None
        if args.dask:
            try:
                from distributed import Client, LocalCluster
            except ImportError:
                raise OSError("`--dask` needs the distributed package: pip install 'dask[distributed]'") from None
            if args.dask == "local":
                cluster = LocalCluster(n_workers=args.workers or None, threads_per_worker=1, dashboard_address=None)
                client = Client(cluster)
            else:
                client = Client(args.dask)
            executor = client.get_executor()
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", RuntimeWarning)
            table = sweep(scene, grid, executor=executor, max_workers=args.workers, out=args.out,
                          resume=not args.fresh)
    finally:
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
    for w in caught:
        if "have no result" not in str(w.message):  # said below
            print(f"knifeedge sweep: warning: {w.message}", file=sys.stderr)
    print(table)
    print(table.summary())
    for row in table.failures():
        print(f"  failed run {row['run_id']}: {row['message']}")
    for row in table.missing():
        print(f"  no result for run {row['run_id']}: {row['message']}")
    if table.n_missing:
        print(f"knifeedge sweep: {table.n_missing} run(s) have no result (their worker died); run the same "
              "command again to compute them", file=sys.stderr)
        return 1
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
         "sweep": _sweep_args, "animate": _animate_args, "derive": _derive_args}


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="knifeedge", description="Simulators of the chiral knife-edge rattleback.")
    subs = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for name, (fn, help) in COMMANDS.items():
        sub = subs.add_parser(name, help=help, description=help)
        _ARGS.get(name, lambda s: None)(sub)
        sub.set_defaults(func=fn)
    return parser


#: commands of one run, whose first run does not wait for a kernel to compile (see
#: ``knifeedge.integrators.set_compile_mode``; ``KNIFEEDGE_COMPILE=wait`` makes them wait): the commands of many
#: runs compile each kernel once, first, in parallel processes
BACKGROUND_COMPILE = ("demo", "simulate", "scene")


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    from .integrators.compiler import compile_mode_set

    background = args.command in BACKGROUND_COMPILE and not os.environ.get("KNIFEEDGE_COMPILE")
    try:
        with compile_mode_set("background") if background else contextlib.nullcontext():
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
    except MemoryError:
        print(f"knifeedge {args.command}: error: out of memory (ask for fewer samples, runs or steps)", file=sys.stderr)
        return 1
    except Exception as exc:  # a defect of knifeedge, not of the input: one line, and the traceback on request
        if os.environ.get("KNIFEEDGE_TRACEBACK"):
            raise
        print(f"knifeedge {args.command}: internal error: {type(exc).__name__}: {exc} (please report it; "
              f"set KNIFEEDGE_TRACEBACK=1 to see the traceback)", file=sys.stderr)
        return 1
    finally:
        if argv is None:  # the command line's process ends next: its collector passes at exit (0.5-1 s) skip the heap
            gc.freeze()
