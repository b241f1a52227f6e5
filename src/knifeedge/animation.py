"""Animations of a run: the body in 3D, its contact path, its spin rate and the time.

:func:`animate` writes a GIF (pillow) or an MP4 (ffmpeg, when it is on the
``PATH``) of a simulation.  The body is drawn from what the generated module
says about it (``DRAWING``, ``body_points``, ``body_outlines``; written by
``derivation/drawing.py``): this module knows no model by name.

What a frame shows, and how it stays honest:

- the body in perspective (``mplot3d``), the table ``z = 0`` as a grey square,
  the contact point as a red cross, a curved arrow over the body whose length
  is the spin rate (the gauge) and whose head gives its sign;
- the path of the contact point on the table, seen from above at its true
  scale (its own zoom, stated), and the spin rate against time with a cursor;
- the time, the frame rate, and how many time units one second of video
  covers *at this frame*: long runs are compressed, and compressed less around
  the spin reversals, which are sampled more densely (never skipped);
- the tilt angles the drawing declares magnifiable are multiplied by the
  magnification written on the frame; positions and lengths are never scaled,
  so the body stays rigid (the top view shows the true contact path);
- which model drew it: runs without the pose (a scene's closed state) are
  re-run with the pose, at the same fidelity, method and tolerances, the pose
  left out of the error control so that the closed state takes the same steps.
"""
from __future__ import annotations

import math
import shutil
import subprocess
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ._output import replacing, writable

#: file suffixes :func:`animate` writes
FORMATS = (".gif", ".mp4")
#: most pixels of all a GIF's frames together: they are held in memory until the file is written (one byte a
#: pixel; the default 240 frames of 640 x 360 hold 55 million), an MP4's are streamed to ffmpeg
MAX_GIF_PIXELS = 2**31
#: largest tilt (rad) that the automatic magnification aims for (about 23 degrees)
TARGET_TILT = 0.4
_NICE = (1, 2, 3, 4, 5, 10, 20, 30, 50, 100, 200, 300, 500, 1000)
#: a run of at most this many steps is drawn by the model's ``body_points`` as plain Python (``py_func``): ~10 us
#: a call, once a step and twice a frame, so a few thousand calls cost less than compiling it (0.3-1 s of CPU,
#: cold); a longer run (scene numerical2's 28,714 steps) calls the compiled one.  ``body_outlines`` (0.3-0.5 ms
#: a call as Python, 2-3 us compiled) is called once a frame only: always as Python (a few hundred frames cost
#: less than its compile, 0.2-0.9 s)
DRAW_AS_PYTHON_UP_TO = 10_000
_GAP = np.full((1, 3), np.nan)  # between the lines one artist draws


@dataclass
class Motion:
    """The run to draw, sampled at the frame times.

    Attributes
    ----------
    model : Model with the pose (its module has ``DRAWING``).
    p : parameter vector.
    t : ndarray (n_frames,), frame times.
    y : ndarray (n_state, n_frames), pose-extended states at ``t`` (true, not magnified).
    reversal_times : spin reversals of the run.
    t_span : (t0, t1) of the run.
    run_t, run_y : the whole run as integrated (every step, pose-extended), for the gauge and the path.
    drawn_by : one line: which model, fidelity, method drew the body, and whether it is a re-run.
    """

    model: object
    p: np.ndarray
    t: np.ndarray
    y: np.ndarray
    reversal_times: np.ndarray
    t_span: tuple
    run_t: np.ndarray
    run_y: np.ndarray
    drawn_by: str

    @property
    def spin_t(self) -> np.ndarray:
        """Times of :attr:`spin_y` (every step of the run)."""
        return self.run_t

    @property
    def spin_y(self) -> np.ndarray:
        """Spin rate over the whole run."""
        return self.run_y[self.model.index(gauge_name(self.model))]

    @property
    def drawing(self) -> dict:
        return self.model.module.DRAWING

    def _drawing_function(self, name: str):
        """The module's ``body_points`` (compiled for a run of more than :data:`DRAW_AS_PYTHON_UP_TO` steps) or
        ``body_outlines``, else as plain Python."""
        f = getattr(self.model.module, name)
        compiled = name == "body_points" and self.run_t.size > DRAW_AS_PYTHON_UP_TO
        return f if compiled else getattr(f, "py_func", f)

    def points(self, k: int, magnify: float = 1.0) -> np.ndarray:
        """World coordinates of ``DRAWING["points"]`` at frame ``k``, tilts multiplied by ``magnify``; (n_points, 3)."""
        return self._drawing_function("body_points")(self._state(k, magnify), self.p)

    def outlines(self, k: int, u: np.ndarray, magnify: float = 1.0) -> np.ndarray:
        """``DRAWING["outlines"]`` at frame ``k``; shape (n_outlines, len(u), 3)."""
        return self._drawing_function("body_outlines")(self._state(k, magnify), self.p,
                                                       np.ascontiguousarray(u, dtype=float))

    def _state(self, k: int, magnify: float) -> np.ndarray:
        s = np.array(self.y[:, k], dtype=float)
        if magnify != 1.0:
            for name in self.drawing["magnify"]:
                s[self.model.index(name)] *= magnify
        return s

    def contact_path(self, whole_run: bool = False) -> np.ndarray:
        """True (not magnified) position of the contact point at every frame (or every step of the run); (n, 3)."""
        c = self.drawing["points"].index(self.drawing["contact"])
        if not whole_run:
            return np.array([self.points(k)[c] for k in range(self.t.size)])
        f = self._drawing_function("body_points")
        return np.array([f(np.ascontiguousarray(self.run_y[:, j]), self.p)[c] for j in range(self.run_t.size)])

    def max_tilt(self) -> float:
        """Largest absolute value of the magnifiable tilts over the whole run (0 if none)."""
        names = self.drawing["magnify"]
        return max((float(np.max(np.abs(self.run_y[self.model.index(n)]))) for n in names), default=0.0)


@dataclass
class AnimationInfo:
    """What :func:`animate` wrote.

    Attributes
    ----------
    path : the file.
    n_frames, fps : frames written and frame rate.
    frame_times : ndarray (n_frames,), simulated time of each frame.
    time_per_second : ndarray (n_frames,), simulated time one second of video covers at each frame.
    magnification : factor applied to the tilt angles.
    drawn_by : which model and run drew the body.
    seconds : wall time spent.
    """

    path: Path
    n_frames: int
    fps: float
    frame_times: np.ndarray = field(repr=False)
    time_per_second: np.ndarray = field(repr=False)
    magnification: float
    drawn_by: str
    seconds: float

    def summary(self) -> str:
        tps = self.time_per_second
        return (f"{self.path}: {self.n_frames} frames at {self.fps:g} fps ({self.n_frames / self.fps:.1f} s), "
                f"t = {self.frame_times[0]:g}..{self.frame_times[-1]:g}; 1 s of video = {tps.min():.3g} to "
                f"{tps.max():.3g} time units; tilts x{self.magnification:g}; drawn by {self.drawn_by}; "
                f"{self.seconds:.1f} s")


# -- input ------------------------------------------------------------------------
def _check_options(out, frames, fps, magnify, size=(8.0, 4.5), dpi=80) -> tuple:
    if not isinstance(out, (str, Path)):
        raise TypeError(f"`out` must be a path ending in .gif or .mp4, got {type(out).__name__}")
    out = Path(out)
    if out.suffix.lower() not in FORMATS:
        raise ValueError(f"`out` must end in .gif or .mp4, got {out.name!r}")
    if isinstance(frames, bool) or not isinstance(frames, (int, np.integer)):
        raise TypeError(f"`frames` must be an integer, got {frames!r}")
    if not 2 <= frames <= 5000:
        raise ValueError(f"`frames` must be between 2 and 5000, got {frames}")
    if isinstance(fps, bool) or not isinstance(fps, (int, float, np.integer, np.floating)) \
            or not (math.isfinite(fps) and 1 <= fps <= 50):
        raise ValueError(f"`fps` must be a number between 1 and 50 (GIF frames last at least 20 ms), got {fps!r}")
    if not (isinstance(magnify, str) and magnify == "auto"):
        if isinstance(magnify, bool) or not isinstance(magnify, (int, float, np.integer, np.floating)) \
                or not (math.isfinite(magnify) and magnify >= 1):
            raise ValueError(f"`magnify` must be 'auto' or a number >= 1, got {magnify!r}")
    if isinstance(dpi, bool) or not isinstance(dpi, (int, np.integer)) or not 10 <= dpi <= 600:
        raise ValueError(f"`dpi` must be an integer between 10 and 600, got {dpi!r}")
    try:
        w, h = (float(v) for v in size)
    except (TypeError, ValueError):
        raise TypeError(f"`size` must be a pair (width, height) in inches, got {size!r}") from None
    if not (0.5 <= w <= 40 and 0.5 <= h <= 40):
        raise ValueError(f"`size` must be between 0.5 and 40 inches each way, got {size!r}")
    pixels = frames * round(w * dpi) * round(h * dpi)
    if out.suffix.lower() == ".gif" and pixels > MAX_GIF_PIXELS:
        raise ValueError(f"a GIF of {frames} frames at {round(w * dpi)} x {round(h * dpi)} pixels holds {pixels:.3g} "
                         f"pixels in memory, more than {MAX_GIF_PIXELS:.3g}: lower `frames`, `dpi` or `size`, or "
                         f"write an .mp4 (streamed to ffmpeg)")
    if out.suffix.lower() == ".mp4" and shutil.which("ffmpeg") is None:
        raise RuntimeError("writing MP4 needs ffmpeg on the PATH, and it was not found: install it "
                           "(apt-get install ffmpeg, conda install ffmpeg, brew install ffmpeg) or write a .gif "
                           "(pillow, no system dependency)")
    return out, int(frames), float(fps)


def _run_spec_of(source):
    """``(RunSpec, label)`` for a scene name, Scene, SceneResult or RunSpec; ``None`` for a SimulationResult."""
    from .scenes import get_scene
    from .scenes.base import RunSpec, Scene, SceneResult
    from .simulate import SimulationResult

    if isinstance(source, str):
        source = get_scene(source)
    if isinstance(source, SceneResult):
        source = source.scene
    if isinstance(source, Scene):
        return source.main_run(), f"scene {source.name}"
    if isinstance(source, RunSpec):
        return source, "run"
    if isinstance(source, SimulationResult):
        return None, "result"
    raise TypeError("`source` must be a scene name, a Scene, a SceneResult, a RunSpec or a SimulationResult, "
                    f"got {type(source).__name__}")


# -- the run with the pose, sampled at the frame times ------------------------------
def motion(source, frames: int = 240) -> Motion:
    """Sample ``source`` at ``frames`` times chosen by :func:`frame_times`, with the pose.

    A run without the pose (or at a fidelity without one) is integrated again
    with the pose; a :class:`~knifeedge.SimulationResult` with the pose is
    interpolated (cubic spline through its samples).
    """
    from .simulate import simulate

    spec, label = _run_spec_of(source)
    if spec is None:
        return _motion_of_result(source, frames)
    fidelity = spec.fidelity
    note = []
    if not _has_pose(spec.model, fidelity, spec.path):
        fidelity = "reduced" if _has_pose(spec.model, "reduced", spec.path) else "full"
        note.append(f"fidelity {spec.fidelity} has no pose: drawn at {fidelity}")
    if not _has_drawing(spec.model, fidelity, spec.path):
        raise ValueError(f"model {spec.model} has no drawing (DRAWING in its generated module); "
                         "see derivation/drawing.py")
    m = _load(spec.model, fidelity, True, spec.path)
    y0 = dict(spec.y0)
    kw = dict(method=spec.method, rtol=spec.rtol, atol=spec.atol)
    if not spec.pose:
        kw.update(_closed_state_tolerances(m, spec.rtol, spec.atol))
    if spec.max_steps is not None:
        kw["max_steps"] = int(spec.max_steps)
    first = simulate(m, y0, spec.t_span, dict(spec.params), **kw)
    if not first.success:
        raise RuntimeError(f"the run to draw failed: {first.message}")
    times = frame_times(first.t, first.y, m, first.reversal_times, frames)
    r = simulate(m, y0, spec.t_span, dict(spec.params), t_eval=times, **kw)
    if not r.success:
        raise RuntimeError(f"the run to draw failed: {r.message}")
    rerun = "" if spec.pose and fidelity == spec.fidelity else f", a re-run of {label} with the pose on its steps"
    drawn_by = (f"{spec.model} ({fidelity} + pose), {spec.method} rtol {spec.rtol:g}"
                f"{rerun}" + (f"; {'; '.join(note)}" if note else ""))
    return Motion(m, r.p, r.t, r.y, first.reversal_times, spec.t_span, first.t, first.y, drawn_by)


def _closed_state_tolerances(m, rtol: float, atol: float) -> dict:
    """Tolerances that leave the pose out of the error control of a run with the pose.

    The error norm is a root mean square over the state: the pose gets an
    absolute tolerance so loose that its terms vanish, and the closed state's
    tolerances are scaled by ``sqrt(n_closed / n)`` to make up for the longer
    vector.  The closed state then takes the steps of the run without the pose
    (the scene's own), and so has its reversal times, which matters for the
    later two-mode reversals: they are ill-conditioned (docs/integrators.md).
    """
    n_closed = len(m.closed_state_names)
    c = math.sqrt(n_closed / m.n_state)
    tol = np.full(m.n_state, 0.5)
    tol[:n_closed] = atol * c
    return {"rtol": rtol * c, "atol": tol}


def _motion_of_result(result, frames: int) -> Motion:
    from scipy.interpolate import CubicSpline

    from .simulate import simulate

    m = result.model
    path = m.source_path.parent if m.source_path is not None else None  # a user's model: the same module
    if result.t.size < 2:
        raise ValueError("`source` holds fewer than two samples: nothing to animate")
    if not m.pose:
        if not _has_pose(m.name, m.fidelity, path):
            raise ValueError(f"{m.name} at fidelity {m.fidelity!r} has no pose to draw; simulate a fidelity with "
                             "one (reduced or full)")
        mp = _load(m.name, m.fidelity, True, path)
        y0 = np.concatenate([result.y[:, 0], np.zeros(len(mp.pose_names))])
        t_span = (float(result.t[0]), float(result.t[-1]))
        first = simulate(mp, y0, t_span, result.p)
        if not first.success:
            raise RuntimeError(f"the run to draw failed: {first.message}")
        times = frame_times(first.t, first.y, mp, first.reversal_times, frames)
        r = simulate(mp, y0, t_span, result.p, t_eval=times)
        return Motion(mp, r.p, r.t, r.y, first.reversal_times, t_span, first.t, first.y,
                      f"{m.name} ({m.fidelity} + pose), DOP853 at the default tolerances, a re-run of the "
                      "result's initial state with the pose from (phi, x, y) = 0")
    if not _has_drawing(m.name, m.fidelity, path):
        raise ValueError(f"model {m.name} has no drawing (DRAWING in its generated module)")
    times = frame_times(result.t, result.y, m, result.reversal_times, frames)
    y = CubicSpline(result.t, result.y, axis=1)(times)
    return Motion(m, result.p, times, y, result.reversal_times, (float(result.t[0]), float(result.t[-1])),
                  result.t, result.y, f"{m.name} ({m.fidelity} + pose), {result.method}, the given result "
                  f"({result.t.size} samples, cubic interpolation)")


def gauge_name(model) -> str:
    """The state shown as the spin rate: the drawing's ``gauge``, else the model's spin (first reversal event)."""
    drawing = getattr(model.module, "DRAWING", None) or {}
    name = drawing.get("gauge") or model.spin_name
    if name is None:
        raise ValueError(f"model {model.name} names no spin rate to show: give its drawing a `gauge` state "
                         "(derivation/drawing.py) or the model a reversal event")
    return name


def _load(name: str, fidelity: str, pose: bool = False, path=None):
    """The model ``name`` at ``fidelity``: built in, or from the folder ``path`` (a user's model)."""
    from .models import load

    return load(name, fidelity=fidelity, pose=pose) if path is None else load(name, fidelity, pose, path=path)


def _has_pose(name: str, fidelity: str, path=None) -> bool:
    from .models import available

    if (name, fidelity) not in available(path):
        return False
    return bool(_load(name, fidelity, path=path).pose_names)


def _has_drawing(name: str, fidelity: str, path=None) -> bool:
    return getattr(_load(name, fidelity, path=path).module, "DRAWING", None) is not None


def oscillation_period(t: np.ndarray, y: np.ndarray, model, window=None) -> float | None:
    """Period of the fastest-rocking tilt, from the spacing of its zero crossings (``None`` if it does not rock).

    ``window`` (t_lo, t_hi) restricts the estimate; of the magnifiable tilts
    the one with the largest amplitude in the window is used.
    """
    names = getattr(model.module, "DRAWING", None) or {}
    names = names.get("magnify", ()) or model.tilt_names
    sel = slice(None) if window is None else (t >= window[0]) & (t <= window[1])
    best, amp = None, 0.0
    for n in names:
        th = y[model.index(n)][sel]
        tt = t[sel]
        if th.size < 3:
            continue
        a = float(np.max(np.abs(th)))
        z = np.nonzero(np.diff(np.sign(th)) != 0)[0]
        if a > amp and z.size >= 3:
            best, amp = 2.0 * float(np.median(np.diff(tt[z]))), a
    return best


def frame_times(t: np.ndarray, y: np.ndarray, model, reversal_times, frames: int) -> np.ndarray:
    """``frames`` increasing times from ``t[0]`` to ``t[-1]``, denser around the spin reversals.

    Around each reversal two nested windows are sampled more densely: four
    rocking periods each side at up to ten frames per period (the inner
    windows share at most 40 % of the frames), and the spin's turn-around
    (while ``|spin|`` is below half its largest value) at up to three frames
    per period (at most 35 %).  The rest of the run is sampled evenly with
    what is left, at least a quarter of the frames.  The density changes
    smoothly, so the speed written on the frames changes smoothly too.
    """
    t0, t1 = float(t[0]), float(t[-1])
    span = t1 - t0
    grid = np.linspace(t0, t1, 20001)
    spin = np.abs(y[model.index(gauge_name(model))])
    revs = [float(r) for r in reversal_times if t0 < r < t1]
    inner, outer = [], []
    for r in revs:
        period = oscillation_period(t, y, model, (r - 0.05 * span, r + 0.05 * span)) or oscillation_period(t, y, model)
        if period is None:
            continue
        inner.append((r, min(4.0 * period, 0.1 * span), 10.0 / period))
        fast = spin > 0.5 * spin.max()
        before, after = t[fast & (t < r)], t[fast & (t > r)]
        turn = max(r - (before[-1] if before.size else t0), (after[0] if after.size else t1) - r)
        if turn > inner[-1][1]:
            outer.append((r, min(turn, 0.25 * span), 3.0 / period))
    density = np.full_like(grid, 0.25 * frames / span)
    for group, budget in ((inner, 0.4 * frames), (outer, 0.35 * frames)):
        if not group:
            continue
        shapes = [np.exp(-(((grid - r) / half) ** 4)) for r, half, _ in group]
        need = sum(float(np.sum(sh) * (grid[1] - grid[0])) * rate for sh, (_, _, rate) in zip(shapes, group))
        scale = min(1.0, budget / need)
        for sh, (_, _, rate) in zip(shapes, group):
            density = np.maximum(density, scale * rate * sh)
    cum = np.concatenate([[0.0], np.cumsum(0.5 * (density[1:] + density[:-1]) * np.diff(grid))])
    times = np.interp(np.linspace(0.0, cum[-1], frames), cum, grid)
    times[0], times[-1] = t0, t1
    return np.maximum.accumulate(times)


def auto_magnification(max_tilt: float) -> float:
    """The largest of 1, 2, 3, 4, 5, 10, 20, ... that keeps ``max_tilt`` times it at most :data:`TARGET_TILT`."""
    if max_tilt <= 0:
        return 1.0
    return float(max([v for v in _NICE if v * max_tilt <= TARGET_TILT], default=1))


# -- drawing ------------------------------------------------------------------------
class FrameRenderer:
    """Draws the frames of a :class:`Motion` on one matplotlib figure (Agg); ``render(k)`` -> RGB array."""

    def __init__(self, mo: Motion, fps: float, magnify: float, size=(8.0, 4.5), dpi: int = 80, title: str = ""):
        import matplotlib

        matplotlib.use("Agg")
        from matplotlib.figure import Figure
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        self.mo, self.fps, self.mag = mo, fps, magnify
        d = mo.drawing
        self.names = list(d["points"])
        self.contact = self.names.index(d["contact"])
        self.seg = [(self.names.index(a), self.names.index(b)) for a, b in d["segments"]]
        self.mass = [self.names.index(n) for n in d["masses"]]
        self.u = np.linspace(0.0, 2 * math.pi, 73)
        n = mo.t.size
        self.pts = np.array([mo.points(k, magnify) for k in range(n)])          # (n, n_points, 3)
        self.outl = np.array([mo.outlines(k, self.u, magnify) for k in range(n)])  # (n, n_outlines, n_u, 3)
        self.path = mo.contact_path()
        self.run_path = mo.contact_path(whole_run=True)
        # a body that travels far beyond its own size (a rolling disk) is followed by the camera: every frame is
        # drawn relative to its contact point, its recent path drawn on the table (the top view keeps the truth)
        extent = float(np.max(np.ptp(np.concatenate([self.pts[0], self.outl[0].reshape(-1, 3)])[:, :2], axis=0)))
        self.follow = float(np.max(np.ptp(self.run_path[:, :2], axis=0))) > 1.5 * max(extent, 1e-300)
        self.offset = np.zeros((n, 3))
        if self.follow:
            self.offset[:, :2] = self.path[:, :2]
            self.pts = self.pts - self.offset[:, None, :]
            self.outl = self.outl - self.offset[:, None, None, :]
        dt = np.gradient(mo.t) if n > 1 else np.ones(1)
        self.time_per_second = dt * fps
        self.spin = np.interp(mo.t, mo.spin_t, mo.spin_y)
        self.spin_max = float(np.max(np.abs(mo.spin_y))) or 1.0

        self.fig = Figure(figsize=size, dpi=dpi)
        self.canvas = FigureCanvasAgg(self.fig)
        self._setup(title)

    # layout and the artists that stay
    def _setup(self, title: str) -> None:
        self._scene_axes()
        self._top_view()
        self._spin_gauge()
        self._texts(title)
        self.body = [*(a for pair in self.line_groups for a in pair), self.mass_dots, self.contact_mark]
        self.overlay = [self.arc, self.trail, self.tv_mark, self.spin_done, self.spin_dot]
        # the texts that change every frame are set on matplotlib Text artists (their position, size, colour and
        # content) but written into the pixels by pillow: matplotlib's text layout costs ~7 ms a text, 3/4 of a frame
        self.labels = [self.spin_text, self.time_text, self.speed_text]
        self._label_fonts = [self._pil_font(a) for a in self.labels]
        # blitting: the moving artists are drawn over a background drawn once (fixed camera and limits)
        # (the table too: what hangs below it is drawn first, then the translucent table, then the rest)
        self.moving = [self.table, self.table_trail, *self.body, *self.overlay]
        for a in self.moving:
            a.set_animated(True)
        self.canvas.draw()
        self.background = self.canvas.copy_from_bbox(self.fig.bbox)
        # the spin rate's trace so far, red over the grey whole run: drawn once, whole, over the background, and
        # each frame copied as pixels up to two pixels before the frame's time, the rest drawn as a line (a line
        # of every step of the run so far, drawn each frame, was 2.5 ms of numerical2's ~12 ms frames)
        self.gauge.draw_artist(self.spin_done)
        self.spin_drawn = self.canvas.copy_from_bbox(self.fig.bbox)
        self.canvas.restore_region(self.background)

    def _scene_axes(self) -> None:
        """The 3D view: limits around everything drawn, the table, and the body's artists."""
        fig = self.fig
        allp = np.concatenate([self.pts.reshape(-1, 3), self.outl.reshape(-1, 3)]) if self.outl.size else \
            self.pts.reshape(-1, 3)
        centre = 0.5 * (allp.min(0) + allp.max(0))
        half = 0.5 * float(np.max(allp[:, :2].max(0) - allp[:, :2].min(0))) * 1.02
        zlo, zhi = float(allp[:, 2].min()), float(allp[:, 2].max())
        self.arc_z = zhi + 0.15 * half
        self.arc_r = 0.45 * half
        zhi = self.arc_z + 0.05 * half
        ax = fig.add_axes((-0.04, 0.02, 0.7, 0.86), projection="3d")
        ax.set_proj_type("persp", focal_length=0.35)
        ax.set_xlim(centre[0] - half, centre[0] + half)
        ax.set_ylim(centre[1] - half, centre[1] + half)
        ax.set_zlim(zlo, zhi)
        ax.set_box_aspect((1.0, 1.0, (zhi - zlo) / (2 * half)), zoom=1.3)
        ax.view_init(elev=20, azim=-62)
        ax.set_axis_off()
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection

        # the table: the contact path's extent plus half the body's reach (a knife edge's masses hang beside it)
        reach = float(np.max(np.hypot(*(self.pts[0, :, :2] - self.pts[0, self.contact, :2]).T)))
        path = self.run_path[:, :2] if not self.follow else np.zeros((1, 2))
        c0 = 0.5 * (path.min(0) + path.max(0))
        # (at most 0.8 of the view's half-width: a larger square's near corners leave the picture)
        h = half if self.follow else min(0.5 * float(np.max(np.ptp(path, axis=0))) + 0.5 * reach, 0.8 * half)
        table = [[(c0[0] - h, c0[1] - h, 0), (c0[0] + h, c0[1] - h, 0), (c0[0] + h, c0[1] + h, 0),
                  (c0[0] - h, c0[1] + h, 0)]]
        self.table = Poly3DCollection(table, facecolor=(0.55, 0.55, 0.55, 0.55), edgecolor="0.4", lw=0.6)
        ax.add_collection3d(self.table)
        self.ax3 = ax
        # the body's lines in three styles (the main member, the other members, the outlines), each style one
        # artist for its lines below the table and one for those above (NaN between lines): an artist costs
        # ~0.35 ms a frame to draw, a line of its own each made 10-13 artists a frame
        styles = (dict(color="k", lw=2.2, solid_capstyle="round"), dict(color="k", lw=1.4, solid_capstyle="round"),
                  dict(color="C1", lw=1.6))
        self.line_groups = [[ax.plot([], [], [], **style)[0] for _side in ("below", "above")] for style in styles]
        self.mass_dots = ax.plot([], [], [], "o", color="C0", ms=9, mec="k", mew=0.6)[0]
        self.contact_mark = ax.plot([], [], [], "x", color="red", ms=9, mew=2.2)[0]
        self.arc = ax.plot([], [], [], color="C3", lw=2.0)[0]
        self.table_trail = ax.plot([], [], [], color="C3", lw=1.0)[0]  # the recent contact path (camera following)

    def _top_view(self) -> None:
        """The contact path seen from above, true scale."""
        tv = self.fig.add_axes((0.66, 0.55, 0.31, 0.33))
        path = self.run_path
        tv.plot(path[:, 0], path[:, 1], color="0.85", lw=0.5)
        self.trail = tv.plot([], [], color="C3", lw=0.9)[0]
        self.tv_mark = tv.plot([], [], "x", color="red", ms=7, mew=2)[0]
        span = float(max(np.ptp(path[:, 0]), np.ptp(path[:, 1]), 1e-12))
        mid = 0.5 * (path[:, :2].min(0) + path[:, :2].max(0))
        tv.set_xlim(mid[0] - 0.6 * span, mid[0] + 0.6 * span)
        tv.set_ylim(mid[1] - 0.6 * span, mid[1] + 0.6 * span)
        tv.set_aspect("equal", adjustable="box")
        tv.tick_params(labelsize=6)
        tv.ticklabel_format(style="sci", scilimits=(-2, 2))
        tv.xaxis.get_offset_text().set_fontsize(6)
        tv.yaxis.get_offset_text().set_fontsize(6)
        tv.set_title(f"contact point on the table, from above\n(true scale, box {1.2 * span:.2g} wide; red: "
                     "last 8 frames)", fontsize=7)

    def _spin_gauge(self) -> None:
        """The spin rate against time, with a cursor, and the reversals."""
        mo = self.mo
        ga = self.fig.add_axes((0.66, 0.12, 0.31, 0.27))
        ga.plot(mo.spin_t, mo.spin_y, color="0.75", lw=0.8)
        self.spin_done = ga.plot(mo.spin_t, mo.spin_y, color="C3", lw=1.2, animated=True)[0]
        self.gauge = ga
        self.spin_dot = ga.plot([], [], "o", color="C3", ms=5)[0]
        ga.axhline(0.0, color="0.5", lw=0.5)
        for r in mo.reversal_times:
            ga.axvline(r, color="k", ls=":", lw=0.8)
        ga.set_xlim(*mo.t_span)
        ga.tick_params(labelsize=6)
        spin_name = gauge_name(mo.model)
        ga.set_xlabel("t", fontsize=7, labelpad=1)
        ga.set_title(f"spin rate {spin_name} (dotted: reversals)\n", fontsize=7)
        self.spin_text = ga.text(0.5, 1.02, "", transform=ga.transAxes, fontsize=7, color="C3", ha="center",
                                 va="bottom")

    def _texts(self, title: str) -> None:
        """The title, what drew the body, the magnification, and the texts of time and speed."""
        mo, fig = self.mo, self.fig
        fig.text(0.01, 0.975, title or f"{mo.model.name}: the body drawn from its own simulation", fontsize=9,
                 va="top", weight="bold")
        fig.text(0.01, 0.012, f"drawn by {mo.drawn_by}", fontsize=6, color="0.3", va="bottom")
        mag = (f"tilt angles drawn x{self.mag:g} (lengths and positions true)" if self.mag != 1
               else "tilt angles true (not magnified)")
        fig.text(0.01, 0.045, mag, fontsize=7, color="C0" if self.mag != 1 else "0.3", va="bottom")
        self.time_text = fig.text(0.01, 0.92, "", fontsize=9, va="top", family="monospace")
        self.speed_text = fig.text(0.01, 0.875, "", fontsize=7, va="top")
        if self.follow:
            fig.text(0.01, 0.078, "camera follows the body: drawn relative to its contact point, its path of the "
                     "last 8 frames in red on the table", fontsize=6, color="0.3", va="bottom")

    def render(self, k: int) -> np.ndarray:
        """Draw frame ``k``; returns its pixels, shape (height, width, 3), uint8."""
        p = self.pts[k]
        m = p[self.mass]
        self.mass_dots.set_data_3d(m[:, 0], m[:, 1], m[:, 2])
        c = p[self.contact]
        self.contact_mark.set_data_3d([c[0]], [c[1]], [c[2]])
        self._spin_arc(k)
        mo = self.mo
        i = int(np.searchsorted(mo.run_t, mo.t[max(k - 8, 0)], side="left"))
        j = int(np.searchsorted(mo.run_t, mo.t[k], side="right"))
        trail = np.vstack([self.run_path[i:j, :2], self.path[k, :2]])
        self.trail.set_data(trail[:, 0], trail[:, 1])
        if self.follow:
            rel = trail - self.offset[k, :2]
            self.table_trail.set_data_3d(rel[:, 0], rel[:, 1], np.zeros(len(rel)))
        self.tv_mark.set_data([self.path[k, 0]], [self.path[k, 1]])
        self.spin_dot.set_data([mo.t[k]], [self.spin[k]])
        s = self.spin[k]
        sense = "counter-clockwise" if s > 0 else ("clockwise" if s < 0 else "at rest")
        self.spin_text.set_text(f"{s:+.4f}  ({sense} from above)")
        near = [r for r in mo.reversal_times if abs(r - mo.t[k]) <= 3 * self.time_per_second[k] / self.fps]
        self.time_text.set_text(f"t = {mo.t[k]:9.2f}" + (f"   spin reversal at t = {near[0]:.2f}" if near else ""))
        tps = self.time_per_second[k]
        ratio = float(np.max(self.time_per_second)) / tps
        slow = f" ({ratio:.2g}x slower than elsewhere: near a reversal)" if 1.5 < ratio < 10 else (
            f" ({ratio:.0f}x slower than elsewhere: near a reversal)" if ratio >= 10 else "")
        self.speed_text.set_text(f"{self.fps:g} frames/s; 1 s of video = {tps:.3g} time units{slow}")
        self.canvas.restore_region(self.background)
        self._spin_so_far(k)
        below, above = self._body_lines(k)
        (below if bool(self.mass) and float(m[:, 2].mean()) < 0 else above).append(self.mass_dots)
        self.table.do_3d_projection()
        order = below + [self.table, self.table_trail] + above + [self.contact_mark] + self.overlay
        for a in order:
            a.axes.draw_artist(a) if a.axes is not None else self.fig.draw_artist(a)
        return self._with_labels()

    def _body_lines(self, k: int) -> tuple:
        """Set the body's line artists (:attr:`line_groups`) for frame ``k``; returns those holding lines below the
        table (a line is below when its points' mean height is) and those holding lines above, in drawing order:
        the main member, the other members, the outlines."""
        p = self.pts[k]
        lines = [[[], []] for _ in self.line_groups]
        for i, (a, b) in enumerate(self.seg):
            xyz = p[[a, b]]
            lines[min(i, 1)][0 if xyz[:, 2].mean() < 0 else 1].append(xyz)
        for curve in self.outl[k]:
            lines[2][0 if curve[:, 2].mean() < 0 else 1].append(curve)
        sides = ([], [])
        for artists, groups in zip(self.line_groups, lines):
            for side, (artist, group) in enumerate(zip(artists, groups)):
                if group:
                    xyz = np.concatenate([np.vstack([g, _GAP]) for g in group])[:-1]
                    artist.set_data_3d(xyz[:, 0], xyz[:, 1], xyz[:, 2])
                    sides[side].append(artist)
        return sides

    def _spin_so_far(self, k: int) -> None:
        """The red trace of the spin rate up to frame ``k``: pixels of the whole trace (:attr:`spin_drawn`) up to
        two columns before ``t_k``'s (a column holds many times: a steep trace's later part would show), then
        the steps from there to ``t_k`` as a line (:attr:`spin_done`)."""
        mo, ga = self.mo, self.gauge
        done = math.floor(float(ga.transData.transform((mo.t[k], 0.0))[0])) - 1  # columns < done are copied
        left = int(ga.bbox.x0) - 2
        if done > left:
            self.canvas.restore_region(self.spin_drawn, bbox=(left, 0, done, self.canvas.get_width_height()[1]),
                                       xy=(0, 0))
        t_from = float(ga.transData.inverted().transform((done - 1.0, 0.0))[0])
        i = max(int(np.searchsorted(mo.spin_t, t_from)) - 1, 0)
        j = int(np.searchsorted(mo.spin_t, mo.t[k], side="right"))
        self.spin_done.set_data(mo.spin_t[i:j], mo.spin_y[i:j])

    def _pil_font(self, text):
        from matplotlib import font_manager
        from PIL import ImageFont

        path = font_manager.findfont(text.get_fontproperties())
        return ImageFont.truetype(path, size=max(1, round(text.get_fontsize() * self.fig.dpi / 72.0)))

    def _with_labels(self) -> np.ndarray:
        """The canvas's pixels with the per-frame texts (:attr:`labels`) written where matplotlib would put them."""
        from matplotlib.colors import to_rgb
        from PIL import Image, ImageDraw

        rgba = self.canvas.buffer_rgba()
        height, width = rgba.shape[:2]
        # pillow drops the alpha channel (5x faster than numpy's strided copy: 5 ms of a ~20 ms frame)
        img = Image.frombuffer("RGBA", (width, height), rgba, "raw", "RGBA", 0, 1).convert("RGB")
        draw = ImageDraw.Draw(img)
        for text, font in zip(self.labels, self._label_fonts):
            x, y = text.get_transform().transform(text.get_position())
            anchor = {"left": "l", "center": "m", "right": "r"}[text.get_ha()] + \
                {"top": "a", "bottom": "d", "baseline": "s", "center": "m", "center_baseline": "m"}[text.get_va()]
            colour = tuple(int(round(255 * c)) for c in to_rgb(text.get_color()))
            draw.text((float(x), height - float(y)), text.get_text(), font=font, fill=colour, anchor=anchor)
        return np.asarray(img)

    def _spin_arc(self, k: int) -> None:
        """Curved arrow over the body: length proportional to |spin rate|, head in its sense."""
        s = self.spin[k] / self.spin_max
        centre = self.pts[k].mean(0)
        a, b = self.seg[0]  # the arc starts over the body's main member (first segment)
        d = self.pts[k, b, :2] - self.pts[k, a, :2]
        heading = math.atan2(d[1], d[0]) if np.any(d) else 0.0
        if abs(s) < 1e-3:
            self.arc.set_data_3d([], [], [])
            return
        ang = heading + np.sign(s) * np.linspace(0.0, 1.5 * math.pi * abs(s), 40)
        x = centre[0] + self.arc_r * np.cos(ang)
        y = centre[1] + self.arc_r * np.sin(ang)
        z = np.full_like(x, self.arc_z)
        tip, d = ang[-1], np.sign(s)
        back = tip - d * 0.35
        hx = [centre[0] + 0.8 * self.arc_r * math.cos(back), x[-1], centre[0] + 1.2 * self.arc_r * math.cos(back)]
        hy = [centre[1] + 0.8 * self.arc_r * math.sin(back), y[-1], centre[1] + 1.2 * self.arc_r * math.sin(back)]
        # the arc and its head as one artist (NaN between them)
        self.arc.set_data_3d(np.r_[x, np.nan, hx], np.r_[y, np.nan, hy], np.r_[z, np.nan, [self.arc_z] * 3])

    def close(self) -> None:
        self.fig.clear()


# -- writers ------------------------------------------------------------------------
def _write_gif(frames, path: Path, fps: float) -> int:
    from PIL import Image

    images = []
    palette = None
    for rgb in frames:
        im = Image.fromarray(rgb)
        if palette is None:
            palette = im.quantize(colors=128, method=Image.Quantize.MEDIANCUT)
        images.append(im.quantize(palette=palette, dither=Image.Dither.NONE))
    duration = 10 * max(2, round(100.0 / fps))
    images[0].save(path, save_all=True, append_images=images[1:], duration=duration, loop=0, optimize=False,
                   disposal=1)
    return len(images)


def _write_mp4(frames, path: Path, fps: float) -> int:
    exe = shutil.which("ffmpeg")
    if exe is None:
        raise RuntimeError("writing MP4 needs ffmpeg on the PATH, and it was not found")
    proc, n = None, 0
    try:
        for rgb in frames:
            if proc is None:
                h, w = rgb.shape[:2]
                proc = subprocess.Popen(
                    [exe, "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", f"{w}x{h}",
                     "-r", f"{fps:g}", "-i", "-", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p",
                     "-c:v", "libx264", str(path)], stdin=subprocess.PIPE)
            proc.stdin.write(np.ascontiguousarray(rgb).tobytes())
            n += 1
    finally:
        if proc is not None:
            proc.stdin.close()
            if proc.wait() != 0:
                raise RuntimeError(f"ffmpeg failed writing {path} (exit status {proc.returncode})")
    return n


def animate(source, out, *, frames: int = 240, fps: float = 20, magnify="auto", size=(8.0, 4.5), dpi: int = 80,
            title: str | None = None, progress=None) -> AnimationInfo:
    """Write a GIF or MP4 of a run: the body in 3D, its contact path, its spin rate, the time.

    Parameters
    ----------
    source : a scene name (``"numerical"``), a :class:`~knifeedge.Scene` or its
        result, a :class:`~knifeedge.RunSpec`, or a
        :class:`~knifeedge.SimulationResult`.  Runs without the pose are
        integrated again with it (same model, fidelity, method, tolerances);
        the frame says which run drew the body.
    out : path ending in ``.gif`` (pillow) or ``.mp4`` (needs ``ffmpeg``).
    frames : number of frames (2 to 5000); the run is compressed in time to fit,
        less around the spin reversals.
    fps : frames per second of the video (1 to 50); a GIF plays at
        100 / round(100 / fps) (its frame durations are whole centiseconds),
        and that is the rate written on the frames.
    magnify : ``"auto"`` (largest tilt drawn at about 23 degrees, by a factor
        1, 2, 3, 4, 5, 10, 20, ...) or a factor >= 1 for the tilt angles.
    size, dpi : figure size in inches and resolution (pixels = size * dpi).
    title : text on top of every frame (default: the model's name).
    progress : optional callable receiving short messages.

    Returns
    -------
    AnimationInfo

    Examples
    --------
    >>> import knifeedge as ke
    >>> info = ke.animate("numerical", "spin.gif", frames=60)   # doctest: +SKIP
    >>> info.n_frames                                           # doctest: +SKIP
    60
    """
    start = time.perf_counter()
    out, frames, fps = _check_options(out, frames, fps, magnify, size, dpi)
    if progress is not None and not callable(progress):
        raise TypeError(f"`progress` must be None or a callable(message), got {progress!r}")
    writable(out, "`out`")
    if out.suffix.lower() == ".gif":  # GIF frame durations are whole centiseconds: state the rate it plays at
        fps = 100.0 / max(2, round(100.0 / fps))
    say = progress or (lambda msg: None)
    say("integrating the run with the pose")
    mo = motion(source, frames)
    mag = auto_magnification(mo.max_tilt()) if magnify == "auto" else float(magnify)
    say(f"drawing {frames} frames (tilts x{mag:g})")
    if title is None and isinstance(source, str):
        title = f"scene {source}: {mo.model.name}, drawn from its own simulation"
    title = title if title is not None else f"{mo.model.name}: the body drawn from its own simulation"
    renderer = FrameRenderer(mo, fps, mag, size=size, dpi=dpi, title=title or "")
    gen = (renderer.render(k) for k in range(frames))
    with replacing(out) as tmp:  # an error or Ctrl-C while drawing leaves no half-written video
        n = _write_gif(gen, tmp, fps) if out.suffix.lower() == ".gif" else _write_mp4(gen, tmp, fps)
    renderer.close()
    info = AnimationInfo(out, n, fps, mo.t, renderer.time_per_second, mag, mo.drawn_by, time.perf_counter() - start)
    say(info.summary())
    return info
