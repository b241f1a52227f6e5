"""Animations: the drawn body agrees with the pose and the paper's geometry; frames, files, bad input.

Geometry (independent of derivation/drawing.py, from the paper's text):
single mode (section II, Fig. figg1): the bar of half-length L lies on the
table along u_phi = (cos phi, sin phi), masses hang ell below its ends and
swing by ell*theta along v_phi = (-sin phi, cos phi) (the cross term
2 ell theta_dot x_dot . v_phi of its Lagrangian); the contact point is
x + D theta u_phi (vinculo1, vinculo2).  Two modes (section III,
Fig. sketch_2modes): the masses swing by ell (theta1 v_phi - theta2 u_phi)
(cross terms of its Lagrangian) and the bar's ends rise and fall by -+ L theta2
(its term L^2 theta2_dot^2), the contact is x + D theta_alpha u_alpha,
theta_alpha = theta2 cos(alpha) - theta1 sin(alpha) (Const22, Const23).
"""
from __future__ import annotations

import math

import numpy as np
import docs_blocks
import pytest
from PIL import Image

import knifeedge as ke
from knifeedge import animation as an
from knifeedge.cli import main

SINGLE = {"g": 1.0, "ell": 1.0, "L": 1.0, "D": 1.0}
TWO = {"g": 1.0, "ell": 1.0, "L": 2.0, "D": 0.5, "alpha": math.pi / 4}


def _points(m, s, p):
    """The drawn points at one state, by ``body_points`` as Python (compiling it costs 0.4-0.7 s of CPU a model; the
    compiled one draws the runs of test_drawn_masses_move_with_the_lagrangians_kinetic_energy)."""
    names = m.module.DRAWING["points"]
    pts = m.module.body_points.py_func(np.asarray(s, float), np.asarray(p, float))
    return {n: pts[i] for i, n in enumerate(names)}


def _uv(phi):
    return np.array([math.cos(phi), math.sin(phi), 0.0]), np.array([-math.sin(phi), math.cos(phi), 0.0])


@pytest.mark.parametrize("fidelity", ["full", "reduced"])
def test_single_mode_drawing_is_the_papers_geometry(fidelity):
    """Contact x + D theta u_phi on the table (vinculo1/2); masses ell below the bar ends, swung by ell theta v_phi."""
    m = ke.load("single_mode", fidelity, pose=True)
    p = m.params(SINGLE)
    theta, phi, x, y = 0.3, 0.7, 0.2, -0.1
    s = m.state(theta=theta, theta_dot=0.4, phi_dot=0.1, phi=phi, x=x, y=y)
    pt = _points(m, s, p)
    u, v = _uv(phi)
    o = np.array([x, y, 0.0])
    np.testing.assert_allclose(pt[m.module.DRAWING["contact"]], o + SINGLE["D"] * theta * u, atol=1e-14)
    for sign, end, mass in ((-1, "end_minus", "mass_minus"), (1, "end_plus", "mass_plus")):
        np.testing.assert_allclose(pt[end], o + sign * SINGLE["L"] * u, atol=1e-14)
        # the hanging segment keeps its length ell and swings in the plane across the bar
        hang = pt[mass] - pt[end]
        assert np.linalg.norm(hang) == pytest.approx(SINGLE["ell"], rel=1e-14)
        assert hang @ u == pytest.approx(0.0, abs=1e-14)
        assert math.atan2(hang @ v, -hang[2]) == pytest.approx(theta, rel=1e-14)
    assert set(m.module.DRAWING["masses"]) == {"mass_minus", "mass_plus"}
    assert m.module.DRAWING["magnify"] == ("theta",)


def test_two_mode_drawing_agrees_with_the_papers_geometry_to_first_order():
    """Masses at x +- L u_phi - ell z + ell (theta1 v_phi - theta2 u_phi) -+ L theta2 z; contact x + D theta_alpha u_alpha.

    The drawing is an exact rigid placement; its distance from the
    first-order geometry must shrink as the square of the tilts.
    """
    m = ke.load("two_mode", "reduced", pose=True)
    p = m.params(TWO)
    L, ell, D, alpha = TWO["L"], TWO["ell"], TWO["D"], TWO["alpha"]
    phi, x, y = 2.1, 0.3, 0.05
    u, v = _uv(phi)
    ua = np.array([math.cos(phi + alpha), math.sin(phi + alpha), 0.0])
    errors = []
    for eps in (1e-2, 5e-3):
        t1, t2 = 1.3 * eps, -0.7 * eps
        s = m.state(theta1=t1, theta2=t2, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1, phi=phi, x=x, y=y)
        pt = _points(m, s, p)
        o = np.array([x, y, 0.0])
        ta = t2 * math.cos(alpha) - t1 * math.sin(alpha)
        # small rigid tilt: rotation vector w = theta1 u_phi + theta2 v_phi displaces r by w x r; on the masses
        # r = +-L u_phi - ell z this is ell (theta1 v_phi - theta2 u_phi) -+ L theta2 z: the Lagrangian's
        # cross terms and its (L^2 + ell^2) theta2_dot^2
        w = t1 * u + t2 * v
        expect = {"C": o + D * ta * ua}
        for sign, end, mass in ((-1, "end_minus", "mass_minus"), (1, "end_plus", "mass_plus")):
            for name, r in ((end, sign * L * u), (mass, sign * L * u - ell * np.array([0, 0, 1.0]))):
                expect[name] = o + r + np.cross(w, r)
        np.testing.assert_allclose(expect["mass_plus"] - expect["end_plus"] - (expect["mass_minus"] - expect["end_minus"]),
                                   0.0, atol=1e-15)
        errors.append(max(float(np.linalg.norm(pt[k] - e)) for k, e in expect.items()))
        assert pt["C"][2] == 0.0
        assert pt["O"][:2] == pytest.approx([x, y], abs=1e-15)
    assert errors[0] < 10 * 1e-2**2
    assert 3.0 < errors[0] / errors[1] < 5.0  # second order


def test_two_mode_contact_is_the_lowest_point_of_the_drawn_circle():
    """Fig. sketch_2modes: the contact is the instantaneous lowest point of the circle of radius D."""
    m = ke.load("two_mode", "full", pose=True)
    p = m.params(TWO)
    s = m.state(theta1=0.25, theta2=-0.15, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1, phi=0.4, x=0.0, y=0.0)
    u = np.linspace(0, 2 * math.pi, 20001)
    circle = m.module.body_outlines(s, p, u)[0]
    pt = _points(m, s, p)
    radius = np.linalg.norm(circle - pt["circle_centre"], axis=1)
    np.testing.assert_allclose(radius, TWO["D"], rtol=1e-12)
    low = circle[np.argmin(circle[:, 2])]
    assert np.linalg.norm(low - pt["C"]) < 1e-3 * TWO["D"]
    assert circle[:, 2].min() == pytest.approx(0.0, abs=1e-7)
    # the circle's plane is vertical at the chiral angle alpha from the bar when untilted
    s0 = m.state(theta1=0.0, theta2=0.0, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1, phi=0.0, x=0.0, y=0.0)
    c0 = m.module.body_outlines(s0, p, np.array([0.5 * math.pi]))[0, 0]
    assert math.atan2(c0[1], c0[0]) == pytest.approx(TWO["alpha"], rel=1e-12)


def _drawn_kinetic_energy(m, r):
    """Kinetic energy per unit mass of the drawn point masses, by finite differences of their positions."""
    names = m.module.DRAWING["points"]
    idx = [names.index(n) for n in m.module.DRAWING["masses"]]
    pos = np.array([m.module.body_points(np.ascontiguousarray(r.y[:, j]), r.p)[idx] for j in range(r.t.size)])
    vel = np.gradient(pos, r.t, axis=0, edge_order=2)
    return 0.5 * np.mean(np.sum(vel**2, axis=2), axis=1), pos


@pytest.mark.parametrize("name, params, y0", [
    ("single_mode", SINGLE, {"theta": 1.0, "theta_dot": 0.0, "phi_dot": 1.0}),
    ("two_mode", TWO, {"theta1": 1.0, "theta2": 0.5, "theta1_dot": 0.0, "theta2_dot": 0.0, "phi_dot": 1.0}),
])
def test_drawn_masses_move_with_the_lagrangians_kinetic_energy(name, params, y0):
    """Along a run with the pose, the drawn masses (M/2 each) carry the kinetic energy of the paper's Lagrangian.

    The model's kinetic energy is its energy minus the paper's potential
    (1/2) g ell sum theta_i^2; the paper's Lagrangian is the small-tilt form,
    so the two agree up to a relative O(theta^2): halving the tilts quarters
    the difference.
    """
    m = ke.load(name, "full", pose=True)
    p = m.params(params)
    t = np.linspace(0.0, 20.0, 8001)
    errs = []
    for eps in (0.01, 0.005):
        ys = {k: v * eps if k.startswith("theta") else v * 0.02 for k, v in y0.items()}
        r = ke.simulate(m, ys, (0.0, 20.0), p, t_eval=t)
        kin, _ = _drawn_kinetic_energy(m, r)
        pot = 0.5 * params["g"] * params["ell"] * sum(r[n] ** 2 for n in m.tilt_names)
        model_kin = r.energy - pot
        errs.append(float(np.max(np.abs(kin - model_kin)[3:-3]) / np.max(model_kin)))
    assert errs[0] < 0.01
    assert 3.0 < errs[0] / errs[1] < 5.0


def test_sleigh_drawing_carries_its_energy_exactly():
    """Chaplygin sleigh: centre of mass G at distance a ahead of the contact; E = |v_G|^2/2 + k^2 phi_dot^2/2."""
    m = ke.load("chaplygin_sleigh", "full", pose=True)
    p = m.params(a=0.5, k=0.3)
    t = np.linspace(0.0, 10.0, 4001)
    r = ke.simulate(m, {"v": 0.1, "phi_dot": 0.5}, (0.0, 10.0), p, t_eval=t)
    names = m.module.DRAWING["points"]
    pts = np.array([m.module.body_points(np.ascontiguousarray(r.y[:, j]), r.p) for j in range(t.size)])
    g, c = pts[:, names.index("G")], pts[:, names.index(m.module.DRAWING["contact"])]
    np.testing.assert_allclose(c[:, :2], np.stack([r["x"], r["y"]], 1), atol=1e-15)
    np.testing.assert_allclose(np.linalg.norm((g - c)[:, :2], axis=1), 0.5, rtol=1e-12)
    vg = np.gradient(g, t, axis=0, edge_order=2)
    e = 0.5 * np.sum(vg**2, 1) + 0.5 * 0.3**2 * r["phi_dot"] ** 2
    np.testing.assert_allclose(e[3:-3], r.energy[3:-3], rtol=1e-6)


# -- the runtime ------------------------------------------------------------------------
@pytest.fixture(scope="module")
def single_motion():
    return an.motion("numerical", frames=40)


def test_a_short_run_is_drawn_by_its_drawing_functions_as_python(single_motion, monkeypatch):
    """``knifeedge figures`` cold (issue 25 item 4): a run of a few thousand steps calls ``body_points`` and
    ``body_outlines`` as plain Python (compiling them costs more, 0.2-1 s of CPU each); a longer one calls the
    compiled ``body_points`` (once a step) but still ``body_outlines`` as Python (once a frame)."""
    mo = single_motion
    mod = mo.model.module
    assert mo.run_t.size <= an.DRAW_AS_PYTHON_UP_TO
    assert mo._drawing_function("body_points") is mod.body_points.py_func
    assert mo._drawing_function("body_outlines") is mod.body_outlines.py_func
    monkeypatch.setattr(an, "DRAW_AS_PYTHON_UP_TO", mo.run_t.size - 1)
    assert mo._drawing_function("body_points") is mod.body_points
    assert mo._drawing_function("body_outlines") is mod.body_outlines.py_func


def test_frame_times_are_denser_around_the_reversal(single_motion):
    mo = single_motion
    t = mo.t
    assert t[0] == mo.t_span[0] and t[-1] == mo.t_span[1] and np.all(np.diff(t) > 0)
    (rev,) = mo.reversal_times
    dt = np.diff(t)
    mid = 0.5 * (t[1:] + t[:-1])
    near, far = dt[np.abs(mid - rev) < 10].max(), dt[np.abs(mid - rev) > 80].min()
    assert near < 0.5 * far
    assert np.any(np.abs(t - rev) < 1.0)  # a frame within a sixth of a period of the reversal


def test_drawn_frame_shows_the_pose_with_magnified_tilt(single_motion):
    """The renderer's artists hold the independent geometry at the frame's state, with theta magnified."""
    mo = single_motion
    r = an.FrameRenderer(mo, fps=10, magnify=4.0, size=(6.0, 3.4), dpi=50)
    k = int(np.argmin(np.abs(mo.t - mo.reversal_times[0])))
    r.render(k)
    s = dict(zip(mo.model.state_names, mo.y[:, k]))
    u, v = _uv(s["phi"])
    o = np.array([s["x"], s["y"], 0.0])
    th = 4.0 * s["theta"]
    swing = SINGLE["ell"] * (math.sin(th) * v - math.cos(th) * np.array([0, 0, 1.0]))
    expect_masses = np.array([o - SINGLE["L"] * u + swing, o + SINGLE["L"] * u + swing])
    xs, ys, zs = r.mass_dots.get_data_3d()
    np.testing.assert_allclose(np.stack([xs, ys, zs], 1), expect_masses, atol=1e-12)
    cx, cy, cz = r.contact_mark.get_data_3d()
    np.testing.assert_allclose([cx[0], cy[0], cz[0]], o + SINGLE["D"] * th * u, atol=1e-12)
    # the top view shows the true (not magnified) contact point
    tx, ty = r.tv_mark.get_data()
    np.testing.assert_allclose([tx[0], ty[0]], (o + SINGLE["D"] * s["theta"] * u)[:2], atol=1e-12)


def test_frames_differ_where_the_body_moves(single_motion):
    mo = single_motion
    r = an.FrameRenderer(mo, fps=10, magnify=4.0, size=(6.0, 3.4), dpi=50)
    k = int(np.argmin(np.abs(mo.t - mo.reversal_times[0])))
    a, b, a2 = r.render(k), r.render(k + 1), r.render(k)
    np.testing.assert_array_equal(a, a2)  # drawing is a function of the frame
    h, w, _ = a.shape
    body = (slice(int(0.1 * h), int(0.9 * h)), slice(0, int(0.6 * w)))  # the 3D view
    assert np.count_nonzero(np.any(a[body] != b[body], axis=2)) > 50
    # the time and the speed (written by pillow) are in the frame's pixels, below the title, and change with it
    label = (slice(int(0.07 * h), int(0.14 * h)), slice(0, int(0.4 * w)))
    assert np.count_nonzero(np.any(a[label] < 128, axis=2)) > 20
    assert np.count_nonzero(np.any(a[label] != b[label], axis=2)) > 5


def _pieces(artist) -> list:
    """The lines one artist draws: its 3D data split at the NaN rows between them."""
    xyz = np.stack(artist.get_data_3d(), 1)
    gaps = np.nonzero(np.isnan(xyz[:, 0]))[0]
    parts = (part[~np.isnan(part[:, 0])] for part in np.split(xyz, gaps))
    return [part for part in parts if len(part)]


def test_a_frame_draws_each_line_once_on_its_side_of_the_table_and_the_spin_so_far(single_motion):
    """``knifeedge figures`` cold (issue 25 item 4): the body's lines share a few artists (one per style and side
    of the table) and the spin rate's trace so far is copied as pixels.  Every segment of the drawing
    (``DRAWING["segments"]`` at the frame's points, checked against the paper's geometry above) and every
    outline is drawn exactly once, by an artist of the side of the table its mean height is on; the red trace
    of the spin rate fills the gauge from its left edge up to the frame's time and not beyond (the dot's
    radius)."""
    mo = single_motion
    r = an.FrameRenderer(mo, fps=10, magnify=4.0, size=(6.0, 3.4), dpi=50)
    for k in (3, int(np.argmin(np.abs(mo.t - mo.reversal_times[0])))):
        img = r.render(k)
        below, above = r._body_lines(k)
        want = [r.pts[k][[a, b]] for a, b in r.seg] + list(r.outl[k])
        drawn = [(q, side) for side, artists in enumerate((below, above)) for a in artists for q in _pieces(a)]
        assert len(drawn) == len(want)
        for line in want:
            (side,) = [sd for q, sd in drawn if q.shape == line.shape and np.array_equal(q, line)]
            assert side == (0 if line[:, 2].mean() < 0 else 1)
        h = img.shape[0]
        box = r.gauge.bbox
        rgb = img[h - int(box.y1):h - int(box.y0)].astype(int)  # the gauge's rows
        red = (rgb[..., 0] - rgb[..., 1] > 60) & (rgb[..., 0] - rgb[..., 2] > 60)  # C3: the trace so far, the dot
        cols = np.nonzero(red.any(axis=0))[0]
        x_k = float(r.gauge.transData.transform((mo.t[k], 0.0))[0])
        assert cols.min() <= box.x0 + 3 and abs(cols.max() - x_k) <= 4


def test_gif_has_the_stated_frames(tmp_path):
    out = tmp_path / "spin.gif"
    info = ke.animate("numerical", out, frames=12, fps=10, size=(5.0, 2.8), dpi=40)
    theta_max = float(np.abs(ke.scene("numerical").run.simulate()["theta"]).max())
    assert info.n_frames == 12 and info.magnification == an.auto_magnification(theta_max) > 1
    assert "single_mode (reduced + pose)" in info.drawn_by and "re-run of scene numerical" in info.drawn_by
    with Image.open(out) as im:
        assert im.n_frames == 12
        assert im.size == (200, 112)
        assert im.info["duration"] == 100
    np.testing.assert_allclose(info.time_per_second, np.gradient(info.frame_times) * 10)


def test_animate_a_result_with_the_pose(tmp_path):
    """A SimulationResult with the pose is drawn as given (the sleigh: no tilts, no magnification)."""
    m = ke.load("chaplygin_sleigh", "full", pose=True)
    r = ke.simulate(m, {"v": 0.1, "phi_dot": 0.5}, (0.0, 20.0), m.params(a=0.5, k=0.3),
                    t_eval=np.linspace(0, 20, 2001))
    info = an.animate(r, tmp_path / "sleigh.gif", frames=8, size=(5.0, 2.8), dpi=40)
    assert info.magnification == 1.0 and "given result" in info.drawn_by
    with Image.open(tmp_path / "sleigh.gif") as im:
        assert im.n_frames == 8


def test_auto_magnification_rule():
    assert an.auto_magnification(0.0) == 1.0
    assert an.auto_magnification(1.0) == 1.0
    for tilt in (0.0999, 0.2, 1e-3, 3e-6):
        mag = an.auto_magnification(tilt)
        assert mag * tilt <= an.TARGET_TILT
        nxt = [v for v in an._NICE if v > mag]
        assert not nxt or nxt[0] * tilt > an.TARGET_TILT


@pytest.mark.parametrize("kwargs, match", [
    ({"out": "x.png"}, "`out` must end in .gif or .mp4"),
    ({"out": 3}, "`out`"),
    ({"frames": 1}, "`frames`"),
    ({"frames": 2.5}, "`frames`"),
    ({"fps": 0}, "`fps`"),
    ({"fps": float("nan")}, "`fps`"),
    ({"magnify": 0.5}, "`magnify`"),
    ({"magnify": "big"}, "`magnify`"),
    ({"progress": "yes"}, "`progress`"),  # was "'str' object is not callable"
    ({"frames": 5000, "dpi": 600}, "lower `frames`, `dpi` or `size`"),  # 65 GB of frames held until written
])
def test_bad_input_is_refused_before_any_work(tmp_path, kwargs, match, monkeypatch):
    def integrate(*args, **kwargs):
        raise AssertionError("integrated before the arguments were checked")

    monkeypatch.setattr(an, "motion", integrate)
    args = {"out": tmp_path / "a.gif", **kwargs}
    out = args.pop("out")
    with pytest.raises((ValueError, TypeError), match=match):
        an.animate("numerical", out, **args)
    assert not (tmp_path / "a.gif").exists()


def test_an_output_that_cannot_be_written_is_refused_before_any_work(tmp_path, monkeypatch):
    """`out` under a file (not a folder) or naming a folder: a ValueError naming `out` before the run is integrated
    (it was an OSError once the run was integrated and drawn)."""
    def integrate(*args, **kwargs):
        raise AssertionError("integrated before `out` was checked")

    monkeypatch.setattr(an, "motion", integrate)
    (tmp_path / "notes.txt").write_text("a file")
    (tmp_path / "old.gif").mkdir()
    with pytest.raises(ValueError, match="`out` .*notes.txt' is a file, not a folder"):
        an.animate("numerical", tmp_path / "notes.txt" / "a.gif", frames=4)
    with pytest.raises(ValueError, match="`out` .* is a folder"):
        an.animate("numerical", tmp_path / "old.gif", frames=4)


def test_a_drawing_that_fails_leaves_no_half_written_file(single_motion, tmp_path, monkeypatch):
    """An error (or Ctrl-C) while the frames are drawn and streamed to ffmpeg leaves the earlier file of that name
    as it was, and no temporary file (the frames went into it as they were drawn: a truncated video)."""
    import os
    import stat

    fake = tmp_path / "bin" / "ffmpeg"  # stores its input in the file it is given, as ffmpeg writes as it reads
    fake.parent.mkdir()
    fake.write_text('#!/bin/sh\nfor last; do :; done\ncat > "$last"\n')
    fake.chmod(fake.stat().st_mode | stat.S_IEXEC)
    monkeypatch.setenv("PATH", f"{fake.parent}{os.pathsep}{os.environ['PATH']}")
    monkeypatch.setattr(an, "motion", lambda source, frames: single_motion)
    drawn = an.FrameRenderer.render

    def render(self, k):
        if k == 3:
            raise KeyboardInterrupt
        return drawn(self, k)

    monkeypatch.setattr(an.FrameRenderer, "render", render)
    out = tmp_path / "videos" / "spin.mp4"
    out.parent.mkdir()
    out.write_bytes(b"an earlier animation")
    with pytest.raises(KeyboardInterrupt):
        an.animate("numerical", out, frames=6, size=(4.0, 2.5), dpi=40)
    assert out.read_bytes() == b"an earlier animation"
    assert [p.name for p in out.parent.iterdir()] == ["spin.mp4"]


def test_bad_source():
    with pytest.raises(TypeError, match="`source`"):
        an.animate(42, "a.gif")
    with pytest.raises(ValueError, match="unknown scene"):
        an.animate("no_such_scene", "a.gif")


def test_mp4_without_ffmpeg_says_so(tmp_path, monkeypatch):
    monkeypatch.setattr(an.shutil, "which", lambda name: None)
    with pytest.raises(RuntimeError, match="ffmpeg"):
        an.animate("numerical", tmp_path / "a.mp4")
    assert not (tmp_path / "a.mp4").exists()


def test_cli_animate(tmp_path, capsys):
    out = tmp_path / "two.gif"
    assert main(["animate", "numerical", "--out", str(out), "--frames", "6", "--dpi", "40"]) == 0
    printed = capsys.readouterr().out
    assert "6 frames" in printed and str(out) in printed
    with Image.open(out) as im:
        assert im.n_frames == 6
    assert main(["animate", "numerical", "--out", str(tmp_path / "a.avi")]) == 2
    assert "`out` must end in .gif or .mp4" in capsys.readouterr().err


def test_docs_animation_code_runs(tmp_path, monkeypatch):
    """The Python block of docs/animation.md works when pasted."""
    import re
    from pathlib import Path

    text = (Path(__file__).resolve().parent.parent / "docs" / "animation.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks
    monkeypatch.chdir(tmp_path)
    for code in blocks:
        docs_blocks.run(code.replace("frames=120", "frames=12"), "docs/animation.md", notes=True)
    assert (tmp_path / "spin.gif").exists() and (tmp_path / "sleigh.gif").exists()


def test_animate_a_result_without_the_pose_reruns_it(tmp_path):
    m = ke.load("single_mode", "reduced")
    r = ke.simulate(m, {"theta": 1e-3, "theta_dot": 0.0, "phi_dot": 0.1}, (0.0, 150.0), m.params(SINGLE))
    info = ke.animate(r, tmp_path / "a.gif", frames=6, size=(4.0, 2.4), dpi=40)
    assert "re-run" in info.drawn_by and "single_mode (reduced + pose)" in info.drawn_by
    assert info.frame_times[0] == 0.0 and info.frame_times[-1] == 150.0


def test_mp4_frames_are_piped_to_ffmpeg(tmp_path, monkeypatch):
    """With an ``ffmpeg`` on the PATH every frame goes to it as raw RGB (a stand-in that stores its input)."""
    import os
    import stat

    fake = tmp_path / "bin" / "ffmpeg"
    fake.parent.mkdir()
    fake.write_text('#!/bin/sh\nfor last; do :; done\ncat > "$last"\n')
    fake.chmod(fake.stat().st_mode | stat.S_IEXEC)
    monkeypatch.setenv("PATH", f"{fake.parent}{os.pathsep}{os.environ['PATH']}")
    info = ke.animate("numerical", tmp_path / "a.mp4", frames=5, size=(4.0, 2.5), dpi=40)
    assert info.n_frames == 5 and info.fps == 20
    assert (tmp_path / "a.mp4").stat().st_size == 5 * 160 * 100 * 3


def test_drawing_refuses_inconsistent_descriptions():
    """A drawing naming undefined points, undeclared symbols or unknown tilt states is refused before emitting."""
    sp = pytest.importorskip("sympy")
    from knifeedge.derive import drawing, models

    with pytest.raises(ValueError, match="undefined point"):
        drawing.Drawing(points={"A": (0, 0, 0)}, segments=(("A", "B"),), contact="A")
    bad = drawing.Drawing(points={"A": (sp.Symbol("zeta"), 0, 0)}, segments=(), contact="A")
    with pytest.raises(ValueError, match="undeclared symbols"):
        drawing.block_source(bad, (models.theta, models.phi), (models.L,))
    tilt = drawing.Drawing(points={"A": (models.L, 0, 0)}, segments=(), contact="A", magnify=("psi",))
    with pytest.raises(ValueError, match="`magnify`"):
        drawing.block_source(tilt, (models.theta, models.phi), (models.L,))
    src = drawing.block_source(drawing.DRAWINGS["single_mode"], (models.theta, models.theta_dot, models.phi_dot,
                                                                 models.phi, models.x, models.y),
                               (models.g, models.ell, models.L, models.D))
    assert "def body_points(s, p)" in src and "def body_outlines(s, p, uu)" in src and "DRAWING = {" in src


@pytest.mark.slow
def test_rerun_with_the_pose_keeps_the_scenes_reversal_times():
    """The pose is left out of the error control, so even the ill-conditioned later two-mode reversals of the
    drawn run are those of the scene's own run."""
    run = ke.scene("numerical2").run
    own = run.simulate().reversal_times
    drawn = an.motion("numerical2", frames=10).reversal_times
    assert len(own) == len(drawn) == 3
    np.testing.assert_allclose(drawn, own, rtol=1e-9)
    # (a plain re-run with the pose in the error norm puts the second reversal ~0.2 % later)


# -- rigid bodies and the rolling disk: drawn points against the pose, computed independently ----------------------
def _rotation_from_vertical_and_heading(n, psi, axis=(1.0, 0.0, 0.0)):
    """Body -> world rotation with the world vertical along ``n`` (body axes) and the body ``axis`` heading ``psi``.

    Found by SciPy's Wahba solver (``Rotation.align_vectors``, the vertical held exactly), not by the drawing's
    construction.
    """
    from scipy.spatial.transform import Rotation

    n = np.asarray(n, float) / np.linalg.norm(n)
    rot, _ = Rotation.align_vectors([[0.0, 0.0, 1.0], [math.cos(psi), math.sin(psi), 0.0]],
                                    [n, np.asarray(axis, float)], weights=[np.inf, 1.0])
    return rot.as_matrix()


def test_celt_drawing_is_the_ellipsoid_at_its_pose():
    """Celt (derivation/celt.py): centre of mass at the height of the ellipsoid's support function, the contact
    point the ellipsoid's lowest point, the sections on the ellipsoid, the axes the inertia's eigenvectors."""
    m = ke.load("celt", "full", pose=True)
    p = m.preset("kane_levinson_1982")
    par = dict(zip(m.param_names, p))
    a, b, c, h = par["a"], par["b"], par["c"], par["h"]
    inertia = np.array([[par["I_xx"], par["I_xy"], par["I_xz"]], [par["I_xy"], par["I_yy"], par["I_yz"]],
                        [par["I_xz"], par["I_yz"], par["I_zz"]]])
    E = np.diag([a * a, b * b, c * c])
    for n0, psi, x, y in (((0.1, 0.05, 1.0), 0.3, 0.01, 0.02), ((-0.3, 0.2, 0.9), -2.0, -0.5, 0.7)):
        s = m.initial_state(n0=n0, omega0=(0.0, 0.0, 5.0), pose=(psi, x, y))
        pt = _points(m, s, p)
        R = _rotation_from_vertical_and_heading(n0, psi)
        ez = np.array([0.0, 0.0, 1.0])
        nh = np.asarray(n0) / np.linalg.norm(n0)
        # centre of the ellipsoid at the height of its support function in the vertical, G h below it along body z
        centre = np.array([x, y, 0.0]) + R @ [0.0, 0.0, h]
        centre[2] = math.sqrt(nh @ E @ nh)
        G = centre - R @ [0.0, 0.0, h]
        np.testing.assert_allclose(pt["G"], G, atol=1e-14)
        np.testing.assert_allclose(G[:2], [x, y], atol=1e-14)
        Ew = R @ E @ R.T
        np.testing.assert_allclose(pt["C"], centre - Ew @ ez / math.sqrt(ez @ Ew @ ez), atol=1e-14)
        u = np.linspace(0, 2 * math.pi, 721)
        curves = m.module.body_outlines.py_func(s, p, u)  # 721 points: as Python, no compile
        for curve in curves:  # every drawn section lies on the ellipsoid and above the table
            body = (curve - centre) @ R  # rows R^T (P - centre)
            np.testing.assert_allclose(np.sum(body**2 / np.array([a, b, c]) ** 2, axis=1), 1.0, rtol=1e-12)
            assert curve[:, 2].min() > -1e-15
        w, v = np.linalg.eigh(inertia)
        for name, k in (("axis1", 0), ("axis2", 1), ("axis3", 2)):
            d = pt[f"{name}_plus"] - pt[f"{name}_minus"]
            expect = R @ v[:, np.argsort(w)[k] if k < 2 else int(np.argmax(np.abs(v[2])))]
            assert abs(d @ expect) / np.linalg.norm(d) == pytest.approx(1.0, abs=1e-12)
    assert m.module.DRAWING["magnify"] == ("n_x", "n_y")


def test_two_mode_rigid_drawing_is_the_inverted_u_at_its_pose():
    """Rigid knife edge (derivation/rigid_knife_edge.py, Fig. sketch_2modes): masses at G +- L x_body, bar ends
    ell above them, the contact circle of radius D in the plane at the chiral angle alpha, touching the table."""
    m = ke.load("two_mode_rigid", "full", pose=True)
    par = {"g": 1.0, "ell": 1.0, "L": 2.0, "D": 0.5, "alpha": math.pi / 4}
    p = m.params(par)
    L, ell, D, alpha = par["L"], par["ell"], par["D"], par["alpha"]
    n0, psi, x, y = (0.2, -0.1, 1.0), 0.8, 0.3, -0.2
    s = m.initial_state(n0=n0, omega0=(0.0, 0.0, 0.1), pose=(psi, x, y))
    pt = _points(m, s, p)
    R = _rotation_from_vertical_and_heading(n0, psi)
    k_w = R @ [-math.sin(alpha), math.cos(alpha), 0.0]  # normal of the circle's plane
    cz = D * math.sqrt(1.0 - k_w[2] ** 2)  # height of the circle's centre above the table: it touches it
    G = np.array([x, y, cz - (R @ [0.0, 0.0, ell + D])[2]])
    np.testing.assert_allclose(pt["mass_minus"], G - L * R[:, 0], atol=1e-14)
    np.testing.assert_allclose(pt["mass_plus"], G + L * R[:, 0], atol=1e-14)
    for end, mass in (("end_minus", "mass_minus"), ("end_plus", "mass_plus")):
        np.testing.assert_allclose(pt[end] - pt[mass], ell * R[:, 2], atol=1e-14)
    circle = m.module.body_outlines(s, p, np.linspace(0, 2 * math.pi, 20001))[0]
    np.testing.assert_allclose(np.linalg.norm(circle - pt["circle_centre"], axis=1), D, rtol=1e-12)
    np.testing.assert_allclose((circle - pt["circle_centre"]) @ k_w, 0.0, atol=1e-14)
    assert circle[:, 2].min() == pytest.approx(0.0, abs=1e-8)
    assert np.linalg.norm(circle[np.argmin(circle[:, 2])] - pt["C"]) < 1e-3 * D
    assert pt["C"][2] == pytest.approx(0.0, abs=1e-15)


def _disk_points(m, s, p):
    return _points(m, np.asarray(s, float), np.asarray(p, float))


def test_rolling_disk_drawing_is_the_disk_at_its_pose():
    """Rolling disk (examples/rolling_disk.py): contact (x, y, 0), centre r cos(q2) high, the rim a circle of
    radius r normal to the axle (heading q1, lean q2: axle (-sin q1 cos q2, cos q1 cos q2, sin q2)), through C."""
    m = ke.load("rolling_disk", "full", pose=True)
    r_ = 0.1
    p = m.params(g=9.81, r=r_)
    q1, q2, q3, x, y = 0.7, 0.3, 1.1, 0.4, -0.2
    s = m.state(q2=q2, q1_dot=0.0, q2_dot=0.0, q3_dot=8.0, q1=q1, q3=q3, x=x, y=y)
    pt = _disk_points(m, s, p)
    axle = np.array([-math.sin(q1) * math.cos(q2), math.cos(q1) * math.cos(q2), math.sin(q2)])
    np.testing.assert_allclose(pt["C"], [x, y, 0.0], atol=1e-15)
    assert pt["centre"][2] == pytest.approx(r_ * math.cos(q2), rel=1e-14)
    assert np.linalg.norm(pt["centre"] - pt["C"]) == pytest.approx(r_, rel=1e-14)
    assert (pt["centre"] - pt["C"]) @ axle == pytest.approx(0.0, abs=1e-15)
    np.testing.assert_allclose(pt["axle_a"] - pt["axle_b"], 2 * r_ / 3 * axle, atol=1e-15)
    rim = m.module.body_outlines(s, p, np.linspace(0, 2 * math.pi, 3601))[0]
    np.testing.assert_allclose(np.linalg.norm(rim - pt["centre"], axis=1), r_, rtol=1e-13)
    np.testing.assert_allclose((rim - pt["centre"]) @ axle, 0.0, atol=1e-15)
    assert rim[:, 2].min() == pytest.approx(0.0, abs=1e-6)
    assert m.module.DRAWING["gauge"] == "q1_dot" and m.module.DRAWING["magnify"] == ("q2",)


@pytest.mark.slow
def test_drawn_rigid_bodies_roll_without_slipping():
    """Along runs with the pose, the drawn points move as a rigid body about the contact at rest: the velocity of
    any drawn point (finite differences) is omega x (P - C).  Disk: omega = q1_dot z + q2_dot u_q1 + q3_dot axle
    (its spokes turn by q3); celt: omega = R omega_body with R found from n and psi as in the test above."""
    t = np.linspace(0.0, 0.5, 2001)
    m = ke.load("rolling_disk", "full", pose=True)
    r = ke.simulate(m, m.state(q2=0.2, q1_dot=0.5, q2_dot=0.3, q3_dot=8.0, q1=0.0, q3=0.0, x=0.0, y=0.0), (0.0, 0.5),
                    m.params(g=9.81, r=0.1), t_eval=t, rtol=1e-12, atol=1e-14)
    names = m.module.DRAWING["points"]
    pts = np.array([m.module.body_points(np.ascontiguousarray(r.y[:, j]), r.p) for j in range(t.size)])
    vel = np.gradient(pts, t, axis=0, edge_order=2)
    q1, q2 = r["q1"], r["q2"]
    heading = np.stack([np.cos(q1), np.sin(q1), 0 * q1], 1)
    axle = np.stack([-np.sin(q1) * np.cos(q2), np.cos(q1) * np.cos(q2), np.sin(q2)], 1)
    omega = (r["q1_dot"][:, None] * [0.0, 0.0, 1.0] + r["q2_dot"][:, None] * heading + r["q3_dot"][:, None] * axle)
    c = pts[:, names.index("C")]
    for k in ("spoke_a", "spoke_c", "centre"):
        expect = np.cross(omega, pts[:, names.index(k)] - c)
        np.testing.assert_allclose(vel[5:-5, names.index(k)], expect[5:-5], atol=1e-5 * np.abs(expect).max())

    m = ke.load("celt", "full", pose=True)
    p = m.preset("kane_levinson_1982")
    y0 = m.initial_state(n0=(0.05, 0.03, 1.0), omega0=(0.3, -0.2, 5.0), pose=(0.4, 0.0, 0.0))
    t = np.linspace(0.0, 0.05, 5001)  # it rocks at up to ~30 rad/s: a fine grid for the finite differences
    r = ke.simulate(m, y0, (0.0, 0.05), p, t_eval=t, rtol=1e-12, atol=1e-14)
    names = m.module.DRAWING["points"]
    pts = np.array([m.module.body_points(np.ascontiguousarray(r.y[:, j]), r.p) for j in range(t.size)])
    vel = np.gradient(pts, t, axis=0, edge_order=2)
    for j in range(10, t.size - 10, 249):
        R = _rotation_from_vertical_and_heading(r.y[:3, j], r["psi"][j])
        w = R @ r.y[3:6, j]
        c = pts[j, names.index("C")]
        for k in ("G", "axis1_plus", "axis2_minus", "axis3_plus"):
            expect = np.cross(w, pts[j, names.index(k)] - c)
            np.testing.assert_allclose(vel[j, names.index(k)], expect, atol=1e-5 * np.linalg.norm(w) * 0.2)  # finite differences: O(dt^2 |w|^3)


def test_a_rigid_body_without_its_own_drawing_gets_one():
    """examples/rolling_disk_rigid.py (front end, no drawing of its own): its rim, its centre of mass at height
    r cos(lean), lean = asin(|n_y|) (axle along body y), and the contact on the table r from it."""
    sp = pytest.importorskip("sympy")
    import importlib.util
    from pathlib import Path

    from knifeedge.derive import drawing, rigid

    path = Path(__file__).resolve().parent.parent / "examples" / "rolling_disk_rigid.py"
    spec = importlib.util.spec_from_file_location("rolling_disk_rigid_example", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    d = drawing.rigid_body(mod.BODY)
    syms = (*rigid.STATE, *rigid.POSE)
    n = np.array([0.3, -0.4, 0.8])
    vals = (*n, 0.0, 0.0, 0.0, 0.0, 0.5, 0.1, 0.2)
    sub = {**dict(zip(syms, vals)), mod.r: 0.1, mod.g: 9.81, mod.m: 1.0}
    pt = {k: np.array([float(c.subs(sub)) for c in v]) for k, v in d.points.items()}
    lean = math.asin(abs(n[1]) / np.linalg.norm(n))
    np.testing.assert_allclose(pt["G"], [0.1, 0.2, 0.1 * math.cos(lean)], atol=1e-14)
    assert pt["C"][2] == pytest.approx(0.0, abs=1e-15)
    assert np.linalg.norm(pt["C"] - pt["G"]) == pytest.approx(0.1, rel=1e-14)
    rim = sp.lambdify(drawing.u, sp.Matrix(d.outlines["rim"]).subs(sub), "numpy")
    ring = np.array([np.ravel(rim(v)) for v in np.linspace(0, 2 * math.pi, 721)])
    np.testing.assert_allclose(np.linalg.norm(ring - pt["G"], axis=1), 0.1, rtol=1e-13)
    assert ring[:, 2].min() == pytest.approx(0.0, abs=1e-5)


def test_celt_frames_differ_where_it_rocks():
    """The celt drawn from the scene's run: the 3D view changes between frames while it rocks."""
    mo = an.motion("celt", frames=30)
    r = an.FrameRenderer(mo, fps=10, magnify=1.0, size=(6.0, 3.4), dpi=50)
    k = int(np.argmin(np.abs(mo.t - mo.reversal_times[0])))
    a, b = r.render(k), r.render(k + 1)
    h, w, _ = a.shape
    body = (slice(int(0.1 * h), int(0.9 * h)), slice(0, int(0.6 * w)))
    assert np.count_nonzero(np.any(a[body] != b[body], axis=2)) > 50


def test_mp4_with_the_real_ffmpeg_opens_with_the_stated_frames(tmp_path):
    """With ffmpeg installed (never required: skipped without it), the MP4 opens (ffprobe) with every frame."""
    import json
    import shutil
    import subprocess

    if shutil.which("ffmpeg") is None or shutil.which("ffprobe") is None:
        _missing("ffmpeg/ffprobe not on the PATH: MP4 output not checked (GIF needs no system dependency)",
                 "KNIFEEDGE_REQUIRE_FFMPEG")
    out = tmp_path / "spin.mp4"
    info = ke.animate("numerical", out, frames=9, fps=10, size=(4.0, 2.5), dpi=42)
    probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                            "stream=codec_name,width,height,nb_read_frames,avg_frame_rate", "-of", "json", str(out)],
                           capture_output=True, text=True, check=True)
    (stream,) = json.loads(probe.stdout)["streams"]
    assert info.n_frames == 9 and int(stream["nb_read_frames"]) == 9
    assert stream["codec_name"] == "h264" and stream["avg_frame_rate"] == "10/1"
    assert (int(stream["width"]), int(stream["height"])) == (168, 106)  # 4 x 2.5 in at 42 dpi: 168 x 105, padded to even (yuv420p)


def _missing(reason: str, required_by: str):
    """Skip for want of a system program, unless ``required_by`` is set in the environment (CI installs them)."""
    import os

    if os.environ.get(required_by):
        pytest.fail(f"{reason}; {required_by} is set, so it must be installed")
    pytest.skip(reason)


def _chromium():
    import shutil

    return next((p for p in (shutil.which("chromium"), shutil.which("chromium-browser"), shutil.which("google-chrome"))
                 if p), None)


def test_figures_page_loads_its_figures_and_animations_in_a_browser(tmp_path, monkeypatch):
    """The figures page, served over HTTP and opened in headless Chromium (skipped without it): every image
    (figure PNG and animation GIF) loads, at the pixel size of its file."""
    import functools
    import http.server
    import json
    import re
    import subprocess
    import threading

    from knifeedge import figures

    exe = _chromium()
    if exe is None:
        _missing("chromium not found: the figures page was not opened in a browser", "KNIFEEDGE_REQUIRE_BROWSER")
    monkeypatch.setattr(figures, "ANIMATIONS", {"numerical": {"frames": 6, "fps": 10, "size": (4.0, 2.5), "dpi": 40}})
    site = tmp_path / "figures"
    recs = figures.make_figures(site, names=["numerical"], max_workers=1, progress=False)
    assert recs[0]["ok"] and recs[0]["animation"]["ok"]
    probe = ("<script>window.addEventListener('load', function () {"
             "var out = document.createElement('pre'); out.id = 'loaded';"
             "out.textContent = JSON.stringify(Array.from(document.images).map(function (i) {"
             "return [i.getAttribute('src'), i.complete, i.naturalWidth, i.naturalHeight]; }));"
             "document.body.appendChild(out); });</script></body>")
    (site / "check.html").write_text((site / "index.html").read_text().replace("</body>", probe))
    handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=str(site))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    server.RequestHandlerClass.log_message = lambda *a: None
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        url = f"http://127.0.0.1:{server.server_address[1]}/check.html"
        dom = subprocess.run([exe, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                              "--disable-component-update", "--no-first-run", f"--user-data-dir={tmp_path / 'profile'}",
                              "--virtual-time-budget=10000", "--dump-dom", url],
                             capture_output=True, text=True, timeout=600).stdout
    finally:
        server.shutdown()
        server.server_close()
    found = re.search(r"<pre id=\"loaded\">(.*?)</pre>", dom, re.S)
    assert found, "the page's load event never fired"
    images = json.loads(html_unescape(found.group(1)))
    assert sorted(src for src, *_ in images) == ["numerical.gif", "numerical.png"]
    for src, complete, width, height in images:
        with Image.open(site / src) as im:
            assert complete and (width, height) == im.size, src


def html_unescape(text: str) -> str:
    import html

    return html.unescape(text)


def test_a_travelling_body_is_followed_by_the_camera():
    """The rolling disk travels ~20 radii: its 3D view is drawn relative to the contact point (which stays at the
    origin), the recent true path is drawn on the table relative to it, and the top view keeps the true path."""
    mo = an.motion("rolling_disk", frames=12)
    r = an.FrameRenderer(mo, fps=10, magnify=1.0, size=(6.0, 3.4), dpi=40)
    assert r.follow
    k = 7
    r.render(k)
    s = dict(zip(mo.model.state_names, mo.y[:, k]))
    cx, cy, cz = r.contact_mark.get_data_3d()
    np.testing.assert_allclose([cx[0], cy[0], cz[0]], 0.0, atol=1e-15)
    tx, ty = r.tv_mark.get_data()
    np.testing.assert_allclose([tx[0], ty[0]], [s["x"], s["y"]], atol=1e-15)  # the contact is (x, y) on the table
    lx, ly, _ = r.table_trail.get_data_3d()
    np.testing.assert_allclose([lx[-1], ly[-1]], 0.0, atol=1e-15)
    assert np.hypot(lx[0], ly[0]) > 0.1 * float(np.max(np.ptp(r.run_path[:, :2], axis=0))) / 12
    # the knife edge stays near its place: no camera following
    assert not an.FrameRenderer(an.motion("numerical", frames=6), fps=10, magnify=1.0, size=(3.0, 2.0), dpi=30).follow
