"""A generated right-hand side written as LLVM IR at derive time (derivation/ir_emit.py, carried by every
generated module as ``LLVM_IR``) computes what numba's compilation of the same Python computes, bit for bit:
the same operations in the same order, no fast-math flags, numba's square-and-multiply for integer powers
(numba/cpython/numbers.py, ``static_power_impl``)."""
import ctypes
import importlib
import inspect
import math

import llvmlite.binding as ll
import numpy as np
import pytest
from numba import njit

from knifeedge.derive import ir_emit, stage_ir
from knifeedge.generated import MODULES
from knifeedge.integrators import irparts

_P = ctypes.c_void_p
RHS = ctypes.CFUNCTYPE(None, ctypes.c_double, _P, _P, ctypes.c_int64, _P)
_KEEP = []  # compiled libraries stay alive while their functions may be called


#: every generated module; the default tier checks the paper's two-mode model (with its pose), the slow tier
#: all of them (numba compiling each module's right-hand side to compare with costs 0.5-2 s apiece)
KEYS = [key if MODULES[key] == "two_mode_full" else pytest.param(key, marks=pytest.mark.slow)
        for key in sorted(MODULES)]


def _source(func):
    """The parsed source of ``func`` (a Python function or a numba dispatcher)."""
    py = getattr(func, "py_func", func)
    return ir_emit.functions(inspect.getsource(py))[py.__name__]


def _compiled(text, native, name):
    """The C-callable rhs of the IR ``text`` (defining ``native``) compiled, and the library kept: ``text``'s
    function bound to the stages' right-hand-side symbol and called by their C wrapper (derivation/stage_ir.py),
    as the runtime binds it (llvmlite renames; no text written)."""
    module = ll.parse_assembly(stage_ir.c_wrapper_ir()
                               + f'declare i32 @"{stage_ir.RHS}"(ptr, ptr, double, ptr, ptr, i64, ptr)\n')
    rhs = ll.parse_assembly(text)
    function = rhs.get_function(native)
    function.name, function.linkage = stage_ir.RHS, "external"
    module.link_in(rhs)
    module.get_function(stage_ir.RHS).linkage = "internal"
    module.get_function(stage_ir.SYMBOLS[2]).name = f"test.c.{name}"
    lib = irparts.compile_library(module, f"test_ir_emit_{name}", [])
    _KEEP.append(lib)
    return RHS(lib.get_pointer_to_function(f"test.c.{name}"))


def _both(func, name, t, s, q, n_out, text=None):
    """The IR's result (``text``, else ``func`` written as IR now) and numba's, at ``(t, s, q)``."""
    ir = np.full(n_out, np.nan)
    native = func.py_func.__name__ if text is not None else f"test.native.{name}"
    text = text if text is not None else ir_emit.rhs_ir(_source(func), native)
    _compiled(text, native, name)(t, s.ctypes.data, q.ctypes.data, q.size, ir.ctypes.data)
    nb = np.full(n_out, np.nan)
    func(t, s, q, nb)
    return ir, nb


@pytest.mark.parametrize("key", KEYS, ids="_".join)
def test_generated_right_hand_sides_are_written_and_agree_bit_for_bit(key):
    """Every generated module carries the IR of its rhs_q_into (and rhs_pose_q_into): straight-line code the
    writer takes, and at random states and parameters that IR gives numba's result exactly (NaN where numba's
    does); it is the IR written from the module's own text now (not stale)."""
    check_module_ir(importlib.import_module(f"knifeedge.generated.{MODULES[key]}"), MODULES[key])


def check_module_ir(mod, label: str, rounds: int = 3) -> None:
    """The generated module ``mod`` carries the IR of its rhs_q_into (and rhs_pose_q_into) as the writer writes it
    from the module's text now, and at random states and parameters that IR gives numba's result exactly (also
    used by the slow tests of derived numeric-elimination models)."""
    rng = np.random.default_rng(sum(map(ord, label)))
    names = ["rhs_q_into"] + (["rhs_pose_q_into"] if hasattr(mod, "rhs_pose_q_into") else [])
    n, n_pose = len(mod.STATE_NAMES), len(getattr(mod, "POSE_NAMES", ()))
    for name in names:
        func = getattr(mod, name)
        assert mod.LLVM_IR[name] == ir_emit.rhs_ir(_source(func), name)
        size = n + (n_pose if name == "rhs_pose_q_into" else 0)
        for _ in range(rounds):
            p = rng.uniform(0.5, 2.0, len(mod.PARAM_NAMES))
            q = mod.constants(p)
            s = rng.uniform(-0.6, 0.6, size)
            ir, nb = _both(func, f"{label}_{name}", float(rng.uniform(0, 10)), s, q, size, mod.LLVM_IR[name])
            assert np.isfinite(nb).any()
            np.testing.assert_array_equal(ir.view(np.int64), nb.view(np.int64))


CONSTANTS = ctypes.CFUNCTYPE(None, _P, _P)


@pytest.mark.parametrize("key", KEYS, ids="_".join)
def test_generated_constants_are_written_and_agree_bit_for_bit(key):
    """Every generated module carries its constants(p) as IR (reading exactly the model's parameters), which
    gives numba's result exactly at random parameters."""
    mod = importlib.import_module(f"knifeedge.generated.{MODULES[key]}")
    rng = np.random.default_rng(1 + sum(map(ord, MODULES[key])))
    nq = mod.constants(rng.uniform(0.5, 2.0, len(mod.PARAM_NAMES))).size
    assert mod.LLVM_IR_READS == len(mod.PARAM_NAMES)
    assert ir_emit.constants_ir(_source(mod.constants), "constants", nq) == (mod.LLVM_IR["constants"], mod.LLVM_IR_READS)
    text = (mod.LLVM_IR["constants"] + f'define void @"test.constants.{MODULES[key]}"(ptr %p, ptr %q) {{\n'
            'entry:\n  call void @"constants"(ptr %p, ptr %q)\n  ret void\n}\n')
    lib = irparts.compile_library(ll.parse_assembly(text), f"test_ir_emit_constants_{MODULES[key]}", [])
    _KEEP.append(lib)
    fn = CONSTANTS(lib.get_pointer_to_function(f"test.constants.{MODULES[key]}"))
    for _ in range(3):
        p = rng.uniform(0.5, 2.0, len(mod.PARAM_NAMES))
        q = np.full(nq, np.nan)
        fn(p.ctypes.data, q.ctypes.data)
        np.testing.assert_array_equal(q.view(np.int64), mod.constants(p).view(np.int64))
    with pytest.raises(ir_emit.Unsupported):  # another size than the one it allocates
        ir_emit.constants_ir(_source(mod.constants), "x", nq + 1)


def test_a_kernel_checks_the_parameters_its_ir_constants_read():
    """The kernel's constants(p) (IR) refuses a parameter vector shorter than what it reads, where reading
    past its end would give garbage; the stand-in's np.array form is left to numba."""
    from knifeedge.integrators import load_kernel
    import stub_model as _stub

    with pytest.raises(ir_emit.Unsupported):
        ir_emit.constants_ir(_source(_stub.constants), "x", 2)
    mod = importlib.import_module("knifeedge.generated.single_mode_full")
    kernel = load_kernel("erk", "DOP853", mod, "rhs_q_into", len(mod.STATE_NAMES))
    p = np.array([1.0, 1.0, 1.0, 1.0])
    np.testing.assert_array_equal(kernel.constants(p), mod.constants(p))
    with pytest.raises(ValueError, match="reads 4"):
        kernel.constants(p[:3])
    # where the IR divides by zero (an infinite constant), numba's compilation answers: it raises
    celt = importlib.import_module("knifeedge.generated.celt_reduced")
    kernel = load_kernel("erk", "DOP853", celt, "rhs_q_into", len(celt.STATE_NAMES))
    with pytest.raises(ZeroDivisionError):
        kernel.constants(np.ones(len(celt.PARAM_NAMES)))


def _probe(t, s, q, ds):
    a = s[0]
    b = -s[1] / q[0]
    ds[0] = a**5 + b**8 * 3 - 2 * a**7
    ds[1] = a**-3 + abs(b) ** (-3.0 / 2.0)
    ds[2] = math.sqrt(q[1]) * math.sin(a * t) - math.cos(b) / (1 + a * a)
    ds[3] = math.exp(-a) + math.log(q[1]) + +b - (a - b) * (a + b)
    ds[4] = a ** (2 * 3) + b * (1 / 3) + a ** (1 / 2 + 1) - 3**40 * a * 1e-19


def test_powers_negation_and_functions_are_numbas():
    """Powers by integer literals (odd, even, negative), a fractional power, unary minus and plus, abs, sqrt,
    sin, cos, exp, log, integer literals in float arithmetic, and constant expressions (folded by Python's
    compiler before numba sees them: 2 * 3 as an integer power, 3**40 as one integer): numba's bits."""
    jit = njit(_probe)
    rng = np.random.default_rng(7)
    for _ in range(20):
        s, q = rng.uniform(-2, 2, 2), rng.uniform(0.1, 3, 2)
        ir, nb = _both(jit, f"probe_{_}", float(rng.uniform(-3, 3)), s, q, 5)
        np.testing.assert_array_equal(ir.view(np.int64), nb.view(np.int64))


def _selects(t, s, q, ds):
    x = s[0]
    y = s[1]
    a = s[2]
    b = s[3]
    ds[0] = a if x < y else b
    ds[1] = a if x > y else b
    ds[2] = a if x <= y else b
    ds[3] = a if x >= y else b
    ds[4] = a if x == y else b
    ds[5] = a if x != y else b
    ds[6] = ((y) if (abs(x) < abs(y)) else (x))  # a pivot choice as derivation/kkt_emit.py's LU prints it
    ds[7] = (a if x > 0 else b) * 2 + (x if abs(y) >= 1.5 else (y if x <= -1 else a - b))
    ds[8] = (1.0 if 0 < x else -1) * (x / y if y != 0 else 0.0)


#: NaN, infinities, signed zeros, the smallest subnormal, and ordinary values
SPECIAL = [math.nan, -math.nan, math.inf, -math.inf, 0.0, -0.0, 5e-324, 1.0, -1.0, 1.5, -2.5]


def test_selects_are_numbas_on_nan_infinities_and_signed_zeros():
    """``a if x <op> y else b`` for each of ``< > <= >= == !=`` (numba: ordered compares, false on NaN; ``!=``
    unordered, true on NaN), on abs() as the LU's pivot choice prints it, against constants, nested and inside
    arithmetic: numba's bits for every pair of special values.  The arms 0.0 and -0.0 differ only in their bits,
    so an arm taken wrongly shows."""
    jit = njit(_selects)
    native = "test.native.selects"
    text = ir_emit.rhs_ir(_source(_selects), native)
    assert text.count("select i1") == 12 and "fcmp ogt" in text and "fcmp une" in text
    rhs = _compiled(text, native, "selects")
    for x in SPECIAL:
        for y in SPECIAL:
            for a, b in ((0.0, -0.0), (-0.0, 0.0), (2.0, 3.0)):
                s, q = np.array([x, y, a, b]), np.zeros(1)
                ir, nb = np.full(9, 7.0), np.full(9, 7.0)
                rhs(0.0, s.ctypes.data, q.ctypes.data, q.size, ir.ctypes.data)
                jit(0.0, s, q, nb)
                np.testing.assert_array_equal(ir.view(np.int64), nb.view(np.int64), err_msg=f"{x}, {y}, {a}, {b}")


def _lu_text(m: int) -> str:
    """``rhs_q_into`` writing ``x`` with ``A x = b`` (``A`` m x m in ``s[:m*m]``, ``b`` after it), the LU with
    partial pivoting of a numeric elimination (derivation/kkt_emit.py's ``lu_solve``) printed as the emitter
    prints a program."""
    import sympy as sp

    from knifeedge.derive import kkt_emit

    symbols = sp.symbols(f"e0:{m * m + m}", real=True)
    prog = kkt_emit.Program()
    A = [list(symbols[r * m:(r + 1) * m]) for r in range(m)]
    (x,) = kkt_emit.lu_solve(prog, A, [list(symbols[m * m:])])
    lines, _ = kkt_emit._lines(prog, {f"ds[{i}]": xi for i, xi in enumerate(x)})
    return ("def rhs_q_into(t, s, q, ds):\n" + "".join(f"    {e} = s[{i}]\n" for i, e in enumerate(symbols))
            + "\n".join(lines) + "\n")


def test_the_pivoting_lu_of_a_numeric_elimination_is_numbas():
    """The LU with partial pivoting that a numeric elimination writes (selects choosing the larger |pivot|) as IR:
    numba's bits at random systems (and the solution numpy's to 1e-12), at ties of |pivot| (+-, equal), at a
    zero and a NaN pivot candidate."""
    m = 3
    text = _lu_text(m)
    assert " if " in text
    namespace = {"math": math}
    exec(compile(text, "<lu>", "exec"), namespace)  # noqa: S102
    jit = njit(namespace["rhs_q_into"])
    native = "test.native.lu"
    rhs = _compiled(ir_emit.rhs_ir(ir_emit.functions(text)["rhs_q_into"], native), native, "lu")
    rng = np.random.default_rng(3)
    cases = [rng.standard_normal(m * m + m) for _ in range(20)]
    tie = np.array([1.0, 2.0, 3.0, -1.0, 5.0, 1.0, 1.0, -4.0, 2.0, 1.0, 2.0, 3.0])
    cases += [tie, np.where(np.arange(12) == 0, 0.0, tie), np.where(np.arange(12) == 3, np.nan, tie)]
    for k, s in enumerate(cases):
        q, ir, nb = np.zeros(1), np.full(m, 7.0), np.full(m, 7.0)
        rhs(0.0, s.ctypes.data, q.ctypes.data, q.size, ir.ctypes.data)
        jit(0.0, s, q, nb)
        np.testing.assert_array_equal(ir.view(np.int64), nb.view(np.int64), err_msg=f"case {k}")
        if k < 20:
            np.testing.assert_allclose(ir, np.linalg.solve(s[:m * m].reshape(m, m), s[m * m:]), rtol=1e-12, atol=1e-12)


def _chained(t, s, q, ds):
    ds[0] = s[0] if s[1] < s[0] < s[2] else s[1]


def _either(t, s, q, ds):
    ds[0] = s[0] if s[1] > 0 and s[2] > 0 else s[1]


def _truthy(t, s, q, ds):
    ds[0] = s[0] if s[1] else s[2]


def _integers(t, s, q, ds):
    ds[0] = s[0] ** (2 if s[1] > 0 else 3)


def _branching(t, s, q, ds):
    if s[0] > 0.9:
        raise ValueError("out of the domain")
    ds[0] = s[0]


def _calling(t, s, q, ds):
    ds[0] = np.tanh(s[0])


def _rebinding(t, s, q, ds):
    a = s[0]
    a = a * a
    ds[0] = a


@pytest.mark.parametrize("func", [_branching, _calling, _rebinding, _chained, _either, _truthy, _integers])
def test_what_is_not_straight_line_arithmetic_is_refused(func):
    """A branch (a statement ``if``), a function the writer does not know, a name bound twice, a select on a
    chained comparison, on ``and``, on a value's truth, or between two integers (numba's result an integer):
    Unsupported, so that the kernel
    uses numba's compilation of the right-hand side instead (tests/test_irparts.py runs a model whose
    right-hand side raises through that path)."""
    with pytest.raises(ir_emit.Unsupported):
        ir_emit.rhs_ir(_source(func), "x")
