"""The stages of a step and the interpolant as LLVM IR (written by derivation/stage_ir.py, compiled by irparts).

Each check calls the IR parts of a kernel and compares with the method's loops over the tableau written here in
numpy (an independent implementation of the same method) from one workspace, or checks the IR parts
against the formulas they implement: Hairer, Norsett & Wanner, Solving ODEs I, Sect. II.4 (the error scale
``atol + rtol max(|y|, |y_new|)``) and II.10 (DOP853's error norm), as SciPy's ``solve_ivp`` computes them.
The stand-in model is ``tests/stub_model.py``: q' = v, v' = -w^2 q, s' = -q.
"""
import ctypes
import importlib.util
import math
import os
import subprocess
import sys

import numpy as np
import pytest

from knifeedge.integrators import Status, from_code, load_kernel, methods
import stub_model as _stub

_D = ctypes.c_double
_I = ctypes.c_int64
_P = ctypes.c_void_p
ATTEMPT = ctypes.CFUNCTYPE(_D, _D, _D, _D, _D, _I, _P, _I, _I, _P, _P)
DENSE = ctypes.CFUNCTYPE(None, _D, _D, _P, _I, _I)
RHS = ctypes.CFUNCTYPE(None, _D, _P, _P, _I, _P)


def _ptr(a):
    return a.ctypes.data


class Layout:
    """The offsets of ``y`` and ``q`` in the integrator's workspace on ``n`` states (its one layout,
    ``methods.erk_arrays(method).rows``: K (n_ext x n), y, y_new, work, scale (n each), F (dense_rows x n), q)."""

    def __init__(self, n: int, method: str):
        rows = methods.erk_arrays(method).rows
        self.y, self.q = rows["y"] * n, rows["q"] * n


def _layout(mod):
    return Layout(mod.N, mod.TABLEAU)


def _workspace(mod, y, p):
    """The workspace the integrator gives the parts: y, q = constants(p) and K[0] = f(0, y)."""
    ws = np.zeros(_layout(mod).q + mod.NQ)
    ws[_layout(mod).y:_layout(mod).y + mod.N] = y
    ws[_layout(mod).q:] = mod._constants(p)
    fns = mod.parts()
    RHS(int(fns[0]))(0.0, _ptr(ws[_layout(mod).y:]), _ptr(ws[_layout(mod).q:]), mod.NQ, _ptr(ws))
    return ws


def _step(mod, ws, h, rtol, atol, pair, mode):
    fns = mod.parts()
    err = ATTEMPT(int(fns[1]))(0.0, h, h, rtol, mode, _ptr(ws), mod.N, mod.NQ, _ptr(atol), _ptr(pair))
    DENSE(int(fns[2]))(0.0, h, _ptr(ws), mod.N, mod.NQ)
    return err


def _loops(method, ws, n, h, rtol, atol, pair, mode, rhs):
    """One step and its interpolant from the workspace ``ws`` (K[0], y and q set), as plain loops over the
    tableau (Hairer, Norsett & Wanner I, Sect. II.4-II.6; DOP853's dense output as in SciPy's
    ``Dop853DenseOutput``): ``(K, y_new, scale, err, F)``."""
    t = methods.erk_arrays(method)
    K = np.zeros((t.n_ext, n))
    K[0] = ws[:n]
    lay = Layout(n, method)
    y, q = ws[lay.y:lay.y + n].copy(), ws[lay.q:]
    for s in range(1, t.n_ext):
        K[s] = rhs(0.0 + t.C[s] * h, y + h * (t.A[s, :s] @ K[:s]), q)
        if s == t.n_stages:
            y_new = y + h * (t.A[s, :s] @ K[:s])
    mag = np.maximum(np.abs(y), np.abs(y_new))
    if mode:
        mag = np.maximum(mag, np.where(pair >= 0, np.maximum(np.abs(y[pair]), np.abs(y_new[pair])), 0.0))
    scale = atol + rtol * mag
    e5 = t.E5[:t.n_stages + 1] @ K[:t.n_stages + 1] / scale
    if t.hairer:
        e3 = t.E3[:t.n_stages + 1] @ K[:t.n_stages + 1] / scale
        n5, n3 = np.sum(e5 ** 2), np.sum(e3 ** 2)
        err = abs(h) * n5 / math.sqrt((n5 + 0.01 * n3) * n)
        dy = y_new - y
        F = np.array([dy, h * K[0] - dy, 2 * dy - h * (K[t.n_stages] + K[0])] + [h * (row @ K) for row in t.DD])
    else:
        err = abs(h) * math.sqrt(np.sum(e5 ** 2) / n)
        F = h * (K.T @ t.P).T
    return K, y_new, scale, err, F


def _stub_rhs(p):
    def rhs(t, y, q):
        out = np.empty(3)
        _stub.rhs_q_into.py_func(t, y, q, out)
        return out
    return rhs


@pytest.mark.parametrize("method,rolled", [("DOP853", False), pytest.param("DP54", False, marks=pytest.mark.slow),
                                           pytest.param("Tsit5", False, marks=pytest.mark.slow),
                                           pytest.param("DOP853", True, marks=pytest.mark.slow)])
def test_ir_parts_compute_the_loops_over_the_tableau(method, rolled, tmp_path, monkeypatch):
    """One step of the stand-in from one workspace: the stages K, y_new, the scale, the error norm and the
    interpolant's rows F agree between the IR parts and the loops over the tableau to round-off (the IR sums a
    stage as y + (h a_0) K_0 + ... with fused multiply-adds, the loops as y + h (a_0 K_0 + ...)); with
    ``mode_scaled`` the scale of a component takes its partner's magnitude too.  ``rolled``: the state size
    taken from the argument, as for a state larger than ``stages.MAX_SIZE`` (here made 2)."""
    if rolled:
        from knifeedge.generated import stages
        from knifeedge.integrators import erk

        monkeypatch.setattr(stages, "MAX_SIZE", 2)
        monkeypatch.setenv("KNIFEEDGE_CACHE_DIR", str(tmp_path))
    ir = erk.AdaptiveKernel(method, _stub, "rhs_q_into", 3) if rolled else load_kernel("erk", method, _stub,
                                                                                        "rhs_q_into", 3)
    y, p = np.array([0.8, -0.3, 0.1]), np.array([2.0, 0.1])
    atol = np.array([1e-9, 2e-9, 3e-9])
    pair = np.array([1, 0, -1], dtype=np.int64)
    for mode in (0, 1):
        wa = _workspace(ir, y, p)
        # a long step (DOP853: error norm 0.03 at rtol 1e-7), so that the estimate is far above round-off
        K, y_new_b, scale, eb, Fb = _loops(method, wa.copy(), 3, 0.3, 1e-7, atol, pair, mode, _stub_rhs(p))
        ea = _step(ir, wa, 0.3, 1e-7, atol, pair, mode)
        assert math.isfinite(ea) and ea > 0.0
        assert math.isclose(ea, eb, rel_tol=1e-6), (ea, eb)  # round-off in the estimate: 1e-9 seen
        np.testing.assert_allclose(wa[:_layout(ir).y], K.ravel(), rtol=1e-13, atol=1e-15)  # the stages K
        y_new = wa[_layout(ir).y + 3:_layout(ir).y + 6]
        np.testing.assert_allclose(y_new, y_new_b, rtol=1e-14)
        # the scale, from its definition (mode_scaled: max over the component and its partner)
        mag = np.maximum(np.abs(y), np.abs(y_new))
        if mode:
            mag = np.array([max(mag[0], mag[1]), max(mag[0], mag[1]), mag[2]])
        np.testing.assert_allclose(wa[_layout(ir).y + 9:_layout(ir).y + 12], atol + 1e-7 * mag, rtol=1e-15)
        np.testing.assert_allclose(scale, atol + 1e-7 * mag, rtol=1e-13)  # from the loops' y_new
        wb = Fb.ravel()
        F = slice(_layout(ir).y + 12, _layout(ir).q)
        np.testing.assert_allclose(wa[F], wb, rtol=0, atol=1e-12 * np.abs(wb).max())  # 2e-13 seen
    # the exact solution q = 0.8 cos(2t) - 0.15 sin(2t): one short step of the 8th (5th) order method is that close
    ws = _workspace(ir, y, p)
    _step(ir, ws, 0.05, 1e-7, atol, pair, 0)
    exact = 0.8 * math.cos(0.1) - 0.15 * math.sin(0.1)
    assert abs(ws[_layout(ir).y + 3] - exact) < (1e-14 if method == "DOP853" else 1e-9), abs(ws[_layout(ir).y + 3] - exact)


def test_the_workspace_has_one_layout_read_by_the_integrator_and_the_stages():
    """The integrator's one array (``methods.erk_arrays(...).rows``, read by the stages' IR and by the
    integrator's ``workspace``): K, y, y_new, work, scale, F, then q, in rows of n, with the published methods'
    sizes: DOP853 12 stages, the step's own (f at t + h) and the 3 extra stages of Hairer's dense output, its
    interpolant 7 rows (SciPy's ``Dop853DenseOutput``); DP54 (SciPy's RK45) and Tsit5 6 + 1 stages, 4 rows."""
    from knifeedge.integrators.erk import _workspace_closure

    n = 3
    for name, (n_k, n_f) in {"DOP853": (16, 7), "DP54": (7, 4), "Tsit5": (7, 4)}.items():
        rows = methods.erk_arrays(name).rows
        assert rows == {"y": n_k, "y_new": n_k + 1, "work": n_k + 2, "scale": n_k + 3, "F": n_k + 4,
                        "q": n_k + 4 + n_f}, name
        ws, K, y, y_new, work, F = _workspace_closure(rows).py_func(np.arange(1.0, n + 1), np.array([7.0, 8.0]))
        assert ws.size == (n_k + 4 + n_f) * n + 2 and list(ws[-2:]) == [7.0, 8.0] and list(y) == [1.0, 2.0, 3.0]
        assert K.shape == (n_k, n) and F.shape == (n_f, n)
        for view, row in ((K, 0), (y, n_k), (y_new, n_k + 1), (work, n_k + 2), (F, n_k + 4)):
            assert view.ctypes.data - ws.ctypes.data == 8 * row * n, name


def test_the_error_norm_is_hairers_from_the_stages():
    """DOP853's norm (Hairer's code, SciPy's ``DOP853._estimate_error_norm``): err = |h| n5 / sqrt((n5 + 0.01
    n3) N) with n5, n3 the squared scaled 5th- and 3rd-order estimates, recomputed here in numpy from the
    stages the IR part left in the workspace."""
    mod = load_kernel("erk", "DOP853", _stub, "rhs_q_into", 3)
    t = methods.erk_arrays("DOP853")
    y, p = np.array([0.8, -0.3, 0.1]), np.array([2.0, 0.1])
    ws = _workspace(mod, y, p)
    h = 0.2
    err = _step(mod, ws, h, 1e-8, np.full(3, 1e-10), np.full(3, -1, dtype=np.int64), 0)
    K = ws[:t.n_ext * 3].reshape(t.n_ext, 3)[:t.n_stages + 1]
    scale = ws[_layout(mod).y + 9:_layout(mod).y + 12]
    n5 = np.sum((t.E5 @ K / scale) ** 2)
    n3 = np.sum((t.E3 @ K / scale) ** 2)
    assert math.isclose(err, h * n5 / math.sqrt((n5 + 0.01 * n3) * 3), rel_tol=1e-9)


def test_a_right_hand_side_that_raises_fails_the_run_instead_of_going_on(tmp_path, monkeypatch):
    """A right-hand side whose compiled code raises (here once q > 0.9) makes the step's error norm NaN: the
    step is rejected until the step size underflows, and the run reports failure; the numba parts' wrapper
    would have printed the exception and gone on."""
    src = (tmp_path / "raising_rhs.py")
    src.write_text(
        "import numpy as np\nfrom numba import njit\n\n"
        "@njit(cache=True)\ndef constants(p):\n    return np.array([p[0], p[0] * p[0]])\n\n"
        "@njit(cache=True)\ndef rhs_q_into(t, s, q, ds):\n"
        "    if s[0] > 0.9:\n        raise ValueError('q left the domain')\n"
        "    ds[0] = s[1]\n    ds[1] = -q[1] * s[0]\n    ds[2] = -s[0]\n")
    spec = importlib.util.spec_from_file_location("raising_rhs", src)
    module = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, "raising_rhs", module)
    spec.loader.exec_module(module)
    solve = load_kernel("erk", "DOP853", module, "rhs_q_into", 3).solve
    # q = 0.5 cos 2t + sin 2t = R sin(2t + phi) first reaches 0.9 at t* (R = sqrt(1.25), phi = atan2(0.5, 1))
    y0, p = np.array([0.5, 2.0, 0.0]), np.array([2.0])
    t_star = (math.asin(0.9 / math.sqrt(1.25)) - math.atan2(0.5, 1.0)) / 2
    ts, ys, ev_t, ev_k = np.empty(2), np.empty((2, 3)), np.empty(64), np.empty(64, dtype=np.int64)
    out = solve(0.0, 10.0, y0, y0, p, (1e-8, np.full(3, 1e-11), 0.0, np.inf, np.full(3, -1), False),
                (np.array([5.0, 10.0]), False, np.array([0]), 10**6, 10**6), (ts, ys, ev_t, ev_k))
    n_out, status, t_end = out[0], out[2], out[6]
    assert from_code(status) == Status.STEP_SIZE_UNDERFLOW and n_out == 0
    assert 0.99 * t_star < t_end < t_star + 1e-8  # the last accepted step ends where q reaches 0.9


@pytest.mark.slow
def test_compiled_parts_are_loaded_by_a_second_process_and_a_damaged_file_is_compiled_again(tmp_path):
    """The IR parts are compiled once and kept beside the kernel (irparts.cache_file): a second process loads
    them, says nothing and gets the same answer; a truncated file is removed, said in one line, compiled
    again."""
    code = (
        "import numpy as np, knifeedge as ke\n"
        "m = ke.load('single_mode', 'reduced')\n"
        "r = ke.simulate(m, {'theta': 1e-3, 'theta_dot': 0.0, 'phi_dot': 0.1}, (0.0, 150.0),"
        " m.params(g=1.0, ell=1.0, L=1.0, D=1.0), rtol=1e-10)\n"
        "print(r.success, repr(float(r.reversal_times[0])), r.nfev)\n"
    )
    env = dict(os.environ, KNIFEEDGE_CACHE_DIR=str(tmp_path / "k"), NUMBA_CACHE_DIR=str(tmp_path / "n"))
    first = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert "compiling DOP853 for single_mode (reduced); once" in first.stderr
    assert first.stdout.startswith("True 106.3")  # the paper's Fig. 'numerical': reversal at t = 106.36
    parts = list((tmp_path / "k" / "kernels").glob("erk-DOP853-single_mode_reduced-*.parts-*.nbo"))
    assert len(parts) == 1
    quiet = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert quiet.stdout == first.stdout and quiet.stderr == ""
    with open(parts[0], "r+b") as f:
        f.truncate(100)
    again = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert again.stdout == first.stdout
    lines = [ln for ln in again.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and "discarded a damaged compiled-parts cache file" in lines[0], again.stderr
    assert parts[0].stat().st_size > 1000


def test_the_stages_are_written_at_derive_time_and_are_not_stale():
    """generated/stages.py is what derivation/stage_ir.py writes now from the registered adaptive methods (a
    changed writer or tableau without `make derive` fails here), sealed as every generated module, and holds
    every registered adaptive method with the fingerprint of its tables."""
    from pathlib import Path

    from knifeedge.derive import stage_ir
    from knifeedge.generated import stages
    from knifeedge.modulecheck import seal

    path = Path(stages.__file__)
    assert path.read_text(encoding="utf-8") == seal(stage_ir.module_source()), "run make derive"
    erk = [name for name, m in methods.COMPILED_METHODS.items() if m.kind == "erk"]
    assert set(erk) <= set(stages.IR)
    assert all(stages.TABLES[name] == methods.erk_fingerprint(name) for name in erk)


def test_the_runtime_writes_no_ir_it_parses_only_what_derive_time_wrote(tmp_path, monkeypatch):
    """Compiling a model's parts (a fresh cache) parses only IR texts written at derive time: the method's
    stages and the sizes of generated/stages.py, the model's own ``LLVM_IR``; and no string under
    src/knifeedge/integrators holds an IR definition (the runtime writes none)."""
    import ast
    from pathlib import Path

    import llvmlite.binding as ll

    from knifeedge.generated import single_mode_full, stages
    from knifeedge.integrators import erk

    parsed, original, folder = [], ll.parse_assembly, Path(erk.__file__).parent

    def parse(text, *args):
        if Path(sys._getframe(1).f_code.co_filename).parent == folder:  # (numba parses IR of its own too)
            parsed.append(text)
        return original(text, *args)

    monkeypatch.setattr(ll, "parse_assembly", parse)
    monkeypatch.setenv("KNIFEEDGE_CACHE_DIR", str(tmp_path))
    kernel = erk.AdaptiveKernel("DP54", single_mode_full, "rhs_q_into", 3)
    assert kernel.parts()[1] != 0 and list(tmp_path.glob("kernels/*.parts-*.nbo"))
    allowed = {stages.IR["DP54"], stages.SIZES, *single_mode_full.LLVM_IR.values()}
    assert parsed and all(text in allowed for text in parsed)
    for path in sorted(folder.glob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        strings = [n.value for n in ast.walk(tree) if isinstance(n, ast.Constant) and isinstance(n.value, str)]
        strings += ["".join(v.value for v in n.values if isinstance(v, ast.Constant)) for n in ast.walk(tree)
                    if isinstance(n, ast.JoinedStr)]  # an f-string's text around its fields
        assert not [s for s in strings if "define " in s and "@" in s], path


def test_an_adaptive_method_without_derived_stages_is_refused(monkeypatch):
    """A tableau registered at run time has no stages written at derive time: its kernel is refused with what
    to do (the runtime writes no code)."""
    tab = methods.ExplicitTableau(name="heun_euler", c=[0.0, 1.0], A=[[0.0, 0.0], [1.0, 0.0]], b=[0.5, 0.5],
                                  e=[-0.5, 0.5, 0.0], order=2, error_order=1, P=[[1.0, -0.5], [0.0, 0.5], [0.0, 0.0]],
                                  description="", reference="")
    monkeypatch.setitem(methods.COMPILED_METHODS, "heun_euler", tab)
    with pytest.raises(ValueError, match="no stages in generated/stages.py.*run make derive"):
        load_kernel("erk", "heun_euler", _stub, "rhs_q_into", 3)
