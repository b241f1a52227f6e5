"""The stages of a step and the interpolant of every adaptive method as LLVM IR, written at derive time.

The adaptive integrator (``knifeedge.integrators.erk``) calls a model's
``attempt`` (the stages of a step, ``y_new``, the error scale and norm) and
``dense`` (the interpolant's extra stages and rows) through their addresses.
This module writes them once per registered adaptive method
(``knifeedge.integrators.methods``, ``kind = "erk"``), for every model: loops
over the state's ``n`` components (an argument), the tableau's coefficients
as exact literals, and the right-hand side called by the one symbol
:data:`RHS` (numba's calling convention, ``i32 (ptr retptr, ptr excinfo,
double t, ptr y, ptr q, i64 nq, ptr out)``).  ``make derive`` writes the
texts into ``generated/stages.py`` (:func:`write`); the runtime
(``knifeedge.integrators.irparts``) parses one, binds :data:`RHS` to the
model's right-hand side by renaming a symbol (the model's own IR, or numba's
compiled function), links, compiles and caches it: it writes no code.

The state size is read from the constant :data:`SIZE`, which the runtime
binds to ``SIZE.n`` of :func:`sizes_ir` (a renamed declaration, resolved by
LLVM's linker), so that LLVM sees a constant trip count; every loop carries
``llvm.loop.unroll.full``, so that it is unrolled as the straight-line parts
written per state size before were (which also keeps LLVM's choices of fused
multiply-adds, hence the results, bit for bit those of that code).  A loop
left rolled (7 states, DP54) fused the error norm's sum in another order and
changed a step's last bit; with runtime trip counts the small models lost
20-45 % per evaluation.  A state larger than :data:`MAX_SIZE` takes its size
from the argument ``n`` and runs the loops rolled.

Every floating-point operation carries the ``contract`` flag (numba's
``fastmath={"contract"}``), so LLVM fuses multiply-adds.  A stage of a step
is summed as ``y + (h a_0) K_0 + (h a_1) K_1 + ...``, oldest stage first, so
that only the last term waits for the stage just computed (the chain of
dependent operations between two right-hand-side calls is one fused
multiply-add); the error norm and the interpolant sum ``0.0 + (c_0 K_0 +
c_1 K_1 + ...)``; the error norm's sums run over the components in order.
``tests/test_irparts.py`` compares the parts with the same method as plain
loops over the tableau in numpy, on one workspace.

A right-hand side that fails (numba's status nonzero) makes ``attempt``
return NaN, so the step is rejected and the run ends with the step-size
failure instead of going on with garbage.  (``dense`` has no way to say so:
its extra stages lie inside a step whose own stages all succeeded.)

The workspace is the integrator's one array, laid out as
``knifeedge.integrators.methods.erk_arrays(...).rows`` says (its one home).
"""
from __future__ import annotations

from pathlib import Path

from .ir_emit import literal

#: the version of what this module writes (part of the runtime's cache key)
FORMAT = 1
#: the symbol of the right-hand side the stages call (the runtime binds it to the model's)
RHS = "knifeedge.rhs"
#: the symbols of ``attempt``, ``dense`` and the C-callable right-hand side the texts define
SYMBOLS = ("knifeedge.attempt", "knifeedge.dense", "knifeedge.rhs_c")
#: the constant the stages read the state size from (the runtime binds it to one of :func:`sizes_ir`)
SIZE = "knifeedge.n"
#: the largest state size with a constant of its own in :func:`sizes_ir` (a larger state is read from ``n``)
MAX_SIZE = 64
#: the C signatures of the two parts (called by the integrator)
ATTEMPT_ARGS = ("double %t", "double %h", "double %t_new", "double %rtol", "i64 %mode_scaled", "ptr %ws",
                "i64 %n_arg", "i64 %nq", "ptr %ap", "ptr %pairp")
DENSE_ARGS = ("double %t", "double %h", "ptr %ws", "i64 %n_arg", "i64 %nq")
#: the flags of every floating-point operation of the two parts
FLAGS = "contract"
_NAN = "0x7FF8000000000000"
#: the first metadata node of ``dense``'s loops (``attempt``'s start at 1; ``!0`` is the unroll hint)
_DENSE_LOOPS = 100


class _Writer:
    """IR text of one function: numbered SSA values, loops over the ``%n`` components, the parts' instructions."""

    def __init__(self, first_loop: int = 1):
        # the right-hand side's return slot and exception slot (numba's calling convention)
        self.lines: list = ["  %ret = alloca ptr, align 8", "  %exc = alloca ptr, align 8",
                            # n: the constant bound to SIZE, or the argument where that constant is 0
                            f'  %n.size = load i64, ptr @"{SIZE}", align 8',
                            "  %n.any = icmp eq i64 %n.size, 0",
                            "  %n = select i1 %n.any, i64 %n_arg, i64 %n.size"]
        self.count = 0
        self.block = "entry"
        #: the loops' metadata nodes (``!k``, each marked ``llvm.loop.unroll.full``: see :func:`module_ir`)
        self.loops = first_loop - 1
        #: the right-hand side's return codes so far, or-ed (0: every call succeeded)
        self.status = "0"

    def value(self, text: str) -> str:
        self.count += 1
        name = f"%v{self.count}"
        self.lines.append(f"  {name} = {text}")
        return name

    def emit(self, text: str) -> None:
        self.lines.append(f"  {text}")

    def at(self, base: str, index: str, kind: str = "double") -> str:
        return self.value(f"getelementptr inbounds {kind}, ptr {base}, i64 {index}")

    def load(self, base: str, index: str) -> str:
        return self.value(f"load double, ptr {self.at(base, index)}, align 8")

    def store(self, value: str, base: str, index: str) -> None:
        self.emit(f"store double {value}, ptr {self.at(base, index)}, align 8")

    def mul(self, a: str, b: str) -> str:
        return self.value(f"fmul {FLAGS} double {a}, {b}")

    def add(self, a: str, b: str) -> str:
        return self.value(f"fadd {FLAGS} double {a}, {b}")

    def sub(self, a: str, b: str) -> str:
        return self.value(f"fsub {FLAGS} double {a}, {b}")

    def div(self, a: str, b: str) -> str:
        return self.value(f"fdiv {FLAGS} double {a}, {b}")

    def fabs(self, a: str) -> str:
        return self.value(f"call {FLAGS} double @llvm.fabs.f64(double {a})")

    def sqrt(self, a: str) -> str:
        return self.value(f"call {FLAGS} double @llvm.sqrt.f64(double {a})")

    def max(self, acc: str, v: str) -> str:
        """Python's ``max(acc, v)`` on floats as numba lowers it: ``v`` if ``v > acc``, else ``acc``."""
        gt = self.value(f"fcmp {FLAGS} ogt double {v}, {acc}")
        return self.value(f"select i1 {gt}, double {v}, double {acc}")

    def dot(self, coefficients, k: list, i: str) -> str:
        """``0.0 + (c_0 K_0[i] + c_1 K_1[i] + ...)`` over the nonzero coefficients, left to right."""
        acc = None
        for j, c in enumerate(coefficients):
            if c != 0.0:
                term = self.mul(literal(c), self.load(k[j], i))
                acc = term if acc is None else self.add(acc, term)
        return "0.0" if acc is None else self.add("0.0", acc)

    def loop(self, body, init: tuple = ()) -> list:
        """``for i in range(n)``: ``body(i, *carried)`` writes one component and returns the carried doubles'
        next values (``init`` their first); returns their last values.  ``n >= 1`` (the kernels refuse an
        empty state)."""
        self.loops += 1
        head, before = f"loop{self.loops}", self.block
        self.emit(f"br label %{head}")
        self.lines.append(f"{head}:")
        self.block = head
        i, carried = f"%{head}.i", [f"%{head}.c{r}" for r in range(len(init))]
        slot = len(self.lines)
        self.lines.extend([""] * (1 + len(init)))
        out = list(body(i, *carried) or ())
        nxt = self.value(f"add nuw nsw i64 {i}, 1")
        done = self.value(f"icmp eq i64 {nxt}, %n")
        self.emit(f"br i1 {done}, label %{head}.end, label %{head}, !llvm.loop !{self.loops}")
        self.lines[slot] = f"  {i} = phi i64 [ 0, %{before} ], [ {nxt}, %{head} ]"
        for r, (c, first, last) in enumerate(zip(carried, init, out)):
            self.lines[slot + 1 + r] = f"  {c} = phi double [ {first}, %{before} ], [ {last}, %{head} ]"
        self.lines.append(f"{head}.end:")
        self.block = f"{head}.end"
        return out


class _Layout:
    """Pointers to the workspace's arrays (``tab.rows``), computed from ``%ws`` and ``%n``."""

    def __init__(self, w: _Writer, tab):
        def row(r: int) -> str:
            return "%ws" if r == 0 else w.at("%ws", w.value(f"mul nuw nsw i64 %n, {r}"))

        rows = tab.rows
        self.k = [row(j) for j in range(tab.n_ext)]
        self.y, self.y_new, self.work, self.scale = (row(rows[a]) for a in ("y", "y_new", "work", "scale"))
        self.f = [row(rows["F"] + r) for r in range(tab.dense_rows)]
        self.q = row(rows["q"])


def _stage(w: _Writer, lay: _Layout, row, s: int, time: str, target: str, scaled: bool) -> None:
    """Stage ``s`` from the ``s`` stages before it: its state stored at ``target``, then ``K[s] = f(time,
    state)``.

    ``scaled``: ``y + (h a_0) K_0 + (h a_1) K_1 + ...`` (the stages of a step); else ``y + h (0.0 + (a_0 K_0
    + ...))`` (DOP853's extra stages of the interpolant).
    """
    ha = [None if c == 0.0 else w.mul("%h", literal(c)) for c in row[:s]] if scaled else None

    def body(i):
        if scaled:
            acc = w.load(lay.y, i)
            for j in range(s):
                if ha[j] is not None:
                    acc = w.add(acc, w.mul(ha[j], w.load(lay.k[j], i)))
        else:
            acc = w.add(w.load(lay.y, i), w.mul("%h", w.dot(row[:s], lay.k, i)))
        w.store(acc, target, i)

    w.loop(body)
    code = w.value(f'call i32 @"{RHS}"(ptr %ret, ptr %exc, double {time}, ptr {target}, ptr {lay.q}, i64 %nq, '
                   f"ptr {lay.k[s]}) #0")
    w.status = w.value(f"or i32 {w.status}, {code}")


def attempt_ir(tab) -> str:
    """The IR of ``attempt`` for the tables ``tab`` (``knifeedge.integrators.methods.erk_arrays``): the stages,
    ``y_new``, the error scale ``atol_i + rtol max(|y_i|, |y_new_i|)`` (with ``mode_scaled`` also over the
    partner ``pair[i] >= 0``) and the scaled error norm (DOP853: its 5th- and 3rd-order estimates combined as
    Hairer's), NaN if a right-hand side failed."""
    w = _Writer()
    lay = _Layout(w, tab)
    for s in range(1, tab.n_stages + 1):
        last = s == tab.n_stages
        time = "%t_new" if last else w.add("%t", w.mul(literal(tab.C[s]), "%h"))
        _stage(w, lay, tab.A[s], s, time, lay.y_new if last else lay.work, True)
    scaled = w.value("icmp ne i64 %mode_scaled, 0")

    def body(i, n5, n3=None):
        m = w.max(w.fabs(w.load(lay.y, i)), w.fabs(w.load(lay.y_new, i)))
        pair = w.value(f"load i64, ptr {w.at('%pairp', i, 'i64')}, align 8")
        has = w.value(f"and i1 {scaled}, {w.value(f'icmp sge i64 {pair}, 0')}")
        j = w.value(f"select i1 {has}, i64 {pair}, i64 {i}")
        a, b = w.fabs(w.load(lay.y, j)), w.fabs(w.load(lay.y_new, j))
        m = w.value(f"select i1 {has}, double {w.max(w.max(m, a), b)}, double {m}")
        sc = w.add(w.load("%ap", i), w.mul("%rtol", m))
        w.store(sc, lay.scale, i)
        e5 = w.div(w.dot(tab.E5, lay.k, i), sc)
        if not tab.hairer:
            return [w.add(n5, w.mul(e5, e5))]
        e3 = w.div(w.dot(tab.E3, lay.k, i), sc)
        return [w.add(n5, w.mul(e5, e5)), w.add(n3, w.mul(e3, e3))]

    sums = w.loop(body, ("0.0", "0.0") if tab.hairer else ("0.0",))
    habs, n = w.fabs("%h"), w.value("sitofp i64 %n to double")
    if tab.hairer:
        n5, n3 = sums
        norm = w.div(w.mul(habs, n5), w.sqrt(w.mul(w.add(n5, w.mul(literal(0.01), n3)), n)))
        zero = w.value(f"and i1 {w.value(f'fcmp oeq double {n5}, 0.0')}, {w.value(f'fcmp oeq double {n3}, 0.0')}")
        err = w.value(f"select i1 {zero}, double 0.0, double {norm}")
    else:
        err = w.mul(habs, w.sqrt(w.div(sums[0], n)))
    failed = w.value(f"icmp ne i32 {w.status}, 0")
    w.emit(f"ret double {w.value(f'select i1 {failed}, double {_NAN}, double {err}')}")
    return _function("double", SYMBOLS[0], ATTEMPT_ARGS, w)


def dense_ir(tab) -> str:
    """The IR of ``dense`` for the tables ``tab``: the interpolant's rows ``F`` (DOP853: its extra stages
    first)."""
    w = _Writer(first_loop=_DENSE_LOOPS)
    lay = _Layout(w, tab)
    s = tab.n_stages
    if tab.hairer:
        for st in range(s + 1, tab.n_ext):
            time = w.add("%t", w.mul(literal(tab.C[st]), "%h"))
            _stage(w, lay, tab.A[st], st, time, lay.work, False)

        def body(i):
            dy = w.sub(w.load(lay.y_new, i), w.load(lay.y, i))
            k0 = w.load(lay.k[0], i)
            w.store(dy, lay.f[0], i)
            w.store(w.sub(w.mul("%h", k0), dy), lay.f[1], i)
            w.store(w.sub(w.mul(literal(2.0), dy), w.mul("%h", w.add(w.load(lay.k[s], i), k0))), lay.f[2], i)
            for r, row in enumerate(tab.DD):
                w.store(w.mul("%h", w.dot(row, lay.k, i)), lay.f[3 + r], i)
    else:
        def body(i):
            for r, col in enumerate(tab.P.T):
                w.store(w.mul("%h", w.dot(col, lay.k, i)), lay.f[r], i)
    w.loop(body)
    w.emit("ret void")
    return _function("void", SYMBOLS[1], DENSE_ARGS, w)


def _function(returns: str, name: str, args, w: _Writer) -> str:
    return f'define {returns} @"{name}"({", ".join(args)}) {{\nentry:\n' + "\n".join(w.lines) + "\n}\n"


def c_wrapper_ir() -> str:
    """``void knifeedge.rhs_c(double t, double* y, double* q, int64 nq, double* out)`` calling :data:`RHS`
    (the integrator's own calls of the right-hand side: the initial step)."""
    return (f'define void @"{SYMBOLS[2]}"(double %t, ptr %y, ptr %q, i64 %nq, ptr %out) {{\nentry:\n'
            f"  %ret = alloca ptr\n  %exc = alloca ptr\n"
            f'  %status = call i32 @"{RHS}"(ptr %ret, ptr %exc, double %t, ptr %y, ptr %q, i64 %nq, ptr %out)\n'
            f"  ret void\n}}\n")


def module_ir(tab) -> str:
    """The IR module of the method whose tables are ``tab``: ``attempt``, ``dense`` and the C-callable right-hand
    side (:data:`SYMBOLS`), :data:`RHS` declared (every call of it inlined: ``alwaysinline``; measured on the
    two-mode model, a call left in costs 7-9 % per evaluation)."""
    attempt, dense = attempt_ir(tab), dense_ir(tab)
    return "\n".join([
        f"; knifeedge stages of {tab.name}, format {FORMAT}, written by derivation/stage_ir.py",
        f'declare i32 @"{RHS}"(ptr, ptr, double, ptr, ptr, i64, ptr)',
        f'@"{SIZE}" = external constant i64',
        "declare double @llvm.fabs.f64(double)",
        "declare double @llvm.sqrt.f64(double)",
        attempt,
        dense,
        c_wrapper_ir(),
        "attributes #0 = { alwaysinline }",
        '!0 = !{!"llvm.loop.unroll.full"}',
        *[f"!{k} = distinct !{{!{k}, !0}}" for k in _loop_ids(attempt) + _loop_ids(dense)],
        "",
    ])


def _loop_ids(text: str) -> list:
    return [int(x.rsplit("!", 1)[1]) for x in text.splitlines() if "!llvm.loop !" in x]


def sizes_ir() -> str:
    """The constants ``SIZE.k = k`` for ``k`` in ``0 .. MAX_SIZE``: the runtime binds the stages' :data:`SIZE` to
    ``SIZE.n`` for a state of ``n <= MAX_SIZE`` components (a constant trip count: the loops unroll), else to
    ``SIZE.0`` (the size is the argument ``n``)."""
    return "".join(f'@"{SIZE}.{k}" = constant i64 {k}\n' for k in range(MAX_SIZE + 1))


def module_source() -> str:
    """The text of ``generated/stages.py``: :func:`module_ir` of every registered adaptive method, with the
    fingerprint of the tables it was written from (the runtime refuses IR written from other tables)."""
    from knifeedge.integrators.methods import COMPILED_METHODS, erk_arrays, erk_fingerprint

    names = [name for name, m in COMPILED_METHODS.items() if m.kind == "erk"]
    entries = "".join(f"    {name!r}: {_lines(module_ir(erk_arrays(name)), 8)},\n" for name in names)
    return (
        '"""stages: the stages of a step and the interpolant of every adaptive method as LLVM IR.\n\n'
        "GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make derive`` to regenerate.\n"
        "Written by derivation/stage_ir.py from the registered tables (knifeedge.integrators.methods); the runtime\n"
        "(knifeedge.integrators.irparts) parses, links and compiles them with a model's right-hand side.\n"
        '"""\n'
        f"#: the version of the writer\nFORMAT = {FORMAT}\n"
        f"#: the symbol of the right-hand side the stages call, and those they define (attempt, dense, C rhs)\n"
        f"RHS = {RHS!r}\nSYMBOLS = {SYMBOLS!r}\n"
        "#: the constant the stages read the state size from, and the module defining SIZE.k = k for k <= MAX_SIZE\n"
        f"SIZE = {SIZE!r}\nMAX_SIZE = {MAX_SIZE}\nSIZES = {_lines(sizes_ir(), 4)}\n"
        "#: method -> the fingerprint of the tables the IR was written from (methods.erk_fingerprint)\n"
        f"TABLES = {{{', '.join(f'{n!r}: {erk_fingerprint(n)!r}' for n in names)}}}\n"
        f"#: method -> its IR module (symbols {', '.join(SYMBOLS)}; calls {RHS})\n"
        f"IR = {{\n{entries}}}\n")


def _lines(text: str, indent: int) -> str:
    """``text`` as a parenthesized Python literal of one string per line."""
    pad = " " * indent
    return "(\n" + "".join(f"{pad}{line + chr(10)!r}\n" for line in text.splitlines()) + " " * (indent - 4) + ")"


def write(out_dir: Path) -> Path:
    """Write ``stages.py`` (:func:`module_source`, sealed as every generated module) into ``out_dir``."""
    from knifeedge.modulecheck import seal

    path = Path(out_dir) / "stages.py"
    path.write_text(seal(module_source()), encoding="utf-8")
    return path
