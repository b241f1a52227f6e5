"""The knifeedge command line: --help everywhere, simulate with good and bad arguments, scene, figures, sweep."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from knifeedge.cli import COMMANDS, main, number


def run(capsys, *argv):
    rc = main(list(argv))
    out, err = capsys.readouterr()
    return rc, out, err


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_every_command_has_help(capsys, command):
    with pytest.raises(SystemExit) as exc:
        main([command, "--help"])
    assert exc.value.code == 0
    assert "usage: knifeedge " + command in capsys.readouterr().out


def test_python_dash_m_knifeedge():
    r = subprocess.run([sys.executable, "-m", "knifeedge", "--help"], capture_output=True, text=True)
    assert r.returncode == 0
    for command in ("demo", "simulate", "scene", "figures", "sweep", "bench"):
        assert command in r.stdout


def test_simulate_prints_reversals_and_writes_csv_and_png(capsys, tmp_path):
    """Single-mode default scene (Fig. numerical): one reversal at t = 106.36 (reduced model, FINAL3)."""
    csv, png = tmp_path / "run.csv", tmp_path / "run.png"
    rc, out, err = run(capsys, "simulate", "--t-end", "200", "--out", str(csv), "--plot", str(png))
    assert rc == 0, err
    assert "reversals (1): 106.36" in out and "(zero crossings of phi_dot)" in out
    data = np.loadtxt(csv, delimiter=",", skiprows=1)
    header = csv.read_text().splitlines()[0]
    assert header == "t,theta,theta_dot,phi_dot"
    assert data.shape == (4001, 4) and data[-1, 0] == 200.0
    assert png.stat().st_size > 10_000


def test_simulate_two_mode_by_name_to_npz(capsys, tmp_path):
    out_file = tmp_path / "run.npz"
    rc, out, err = run(capsys, "simulate", "--model", "two_mode", "--set", "alpha=pi/4", "phi_dot=0.2",
                       "--t-end", "1500", "--n-eval", "11", "--out", str(out_file))
    assert rc == 0, err
    z = np.load(out_file)
    assert list(z["state_names"]) == ["theta1", "theta2", "theta1_dot", "theta2_dot", "phi_dot"]
    assert z["y"].shape == (5, 11) and z["y"][4, 0] == 0.2
    assert len(z["reversal_times"]) >= 1


def test_simulate_writes_its_file_whole_or_not_at_all(capsys, tmp_path, monkeypatch):
    """`--out X.NPZ` writes X.NPZ (numpy's savez added ".npz" to a path not ending in lower-case .npz, and the
    command said it wrote X.NPZ); a Ctrl-C while the CSV is written leaves the earlier file as it was."""
    npz = tmp_path / "Run.NPZ"
    rc, out, err = run(capsys, "simulate", "--t-end", "10", "--n-eval", "11", "--out", str(npz))
    assert rc == 0, err
    assert [p.name for p in tmp_path.iterdir()] == ["Run.NPZ"]
    assert np.load(npz)["y"].shape == (3, 11)

    def interrupted(fname, X, **kwargs):  # the first rows written, then Ctrl-C
        if hasattr(fname, "write"):
            fname.write(b"t,theta\n0.0,")
        else:
            Path(fname).write_text("t,theta\n0.0,")
        raise KeyboardInterrupt

    monkeypatch.setattr(np, "savetxt", interrupted)
    csv = tmp_path / "run.csv"
    csv.write_text("an earlier run")
    rc, out, err = run(capsys, "simulate", "--t-end", "10", "--n-eval", "11", "--out", str(csv))
    assert rc == 130 and "interrupted" in err
    assert csv.read_text() == "an earlier run"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["Run.NPZ", "run.csv"]


@pytest.mark.parametrize("argv, needle", [
    (["simulate", "--set", "D=-1"], "`D` must be positive"),
    (["simulate", "--set", "Q=1"], "unknown name(s) ['Q']"),
    (["simulate", "--set", "D"], "NAME=VALUE"),
    (["simulate", "--rtol", "abc"], "--rtol"),
    (["simulate", "--fidelity", "exact"], "`fidelity`"),
    (["simulate", "--model", "three_mode"], "`--model`"),
    (["simulate", "--method", "Euler"], "`method`"),
    (["simulate", "--t-end", "-5"], "`--t-end`"),
    (["simulate", "--out", "x.txt"], "`--out`"),
    (["scene", "nope"], "`name`"),
    (["scene"], "scene NAME"),
    (["sweep", "numerical", "--grid", "D"], "--grid"),
    (["sweep", "numerical", "--grid", "Q=1,2"], "`grid`"),
    (["figures", "--only", "nope"], "`name`"),
    (["frobnicate"], "invalid choice"),
])
def test_bad_arguments_give_one_line_and_a_nonzero_exit(capsys, argv, needle):
    try:
        rc = main(argv)
    except SystemExit as exc:  # argparse's own errors
        rc = exc.code
    out, err = capsys.readouterr()
    assert rc != 0
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert needle in lines[0]
    assert "Traceback" not in err


def test_the_command_line_leaves_its_heap_out_of_the_collector_at_exit(capsys, monkeypatch):
    """``knifeedge ...`` (``main()`` reading ``sys.argv``) freezes its heap when the command ends: the interpreter's
    collector passes at exit then skip it (0.5-1 s of a ``knifeedge figures``); ``main(argv)`` called in a
    process that goes on (these tests) leaves the collector as it was."""
    import gc

    assert gc.get_freeze_count() == 0
    rc, _, _ = run(capsys, "simulate", "--set", "Q=1")
    assert rc == 2 and gc.get_freeze_count() == 0
    monkeypatch.setattr(sys, "argv", ["knifeedge", "simulate", "--set", "Q=1"])
    try:
        rc = main()
        assert rc == 2 and gc.get_freeze_count() > 0
    finally:
        gc.unfreeze()


def test_number_parser():
    assert number("pi/4") == pytest.approx(np.pi / 4)
    assert number("1e-3") == 1e-3 and number("-2*pi") == pytest.approx(-2 * np.pi)
    for bad in ("__import__('os')", "x", "1/0", ""):
        with pytest.raises(ValueError):
            number(bad)


def test_scene_command_writes_its_figure(capsys, tmp_path):
    png = tmp_path / "n.png"
    rc, out, err = run(capsys, "scene", "numerical", "--set", "t_end=150", "--out", str(png))
    assert rc == 0, err
    assert "reversal_times = [106.363]" in out and "[supports]" in out
    assert png.exists()


def test_sweep_command_resumes_from_its_file(capsys, tmp_path):
    out_file = tmp_path / "s.csv"
    argv = ["sweep", "numerical", "--grid", "phi_dot=0.1,0.2", "--set", "t_end=150", "--workers", "1",
            "--out", str(out_file)]
    rc, out, err = run(capsys, *argv)
    assert rc == 0, err
    assert "2 runs: 2 computed, 0 read back" in out
    rc, out, err = run(capsys, *argv)
    assert "2 runs: 0 computed, 2 read back" in out


def test_figures_command_writes_pngs_and_an_index(capsys, tmp_path):
    rc, out, err = run(capsys, "figures", "--out", str(tmp_path), "--only", "numerical", "amplitudes", "--workers", "1")
    assert rc == 0, err
    assert (tmp_path / "numerical.png").exists() and (tmp_path / "amplitudes.png").exists()
    html = (tmp_path / "index.html").read_text()
    md = (tmp_path / "index.md").read_text()
    for text in (html, md):
        assert "Numerical solution of the single mode rattleback" in text  # the paper's caption
        assert "t_R_theory" in text and "supports" in text
    assert "figures: [3/3]" in err  # progress: two scenes and the animation of numerical
    assert (tmp_path / "numerical.gif").exists() and not (tmp_path / "amplitudes.gif").exists()
    for text in (html, md):
        assert "numerical.gif" in text and "tilt angles drawn x4" in text


def test_bench_points_to_make_bench(capsys):
    rc, out, err = run(capsys, "bench")
    assert rc == 0 and "make bench" in out


def test_demo_unchanged(capsys, tmp_path):
    rc, out, err = run(capsys, "demo", "--out", str(tmp_path / "d.png"), "--t-end", "150")
    assert rc == 0
    assert "spin reversals at t = 106.36" in out


