"""A model's stages of a step and its interpolant written as LLVM IR, compiled without numba's front end.

The adaptive integrator (:mod:`.erk`) calls four parts of each
model through their addresses (:class:`.erk.AdaptiveKernel`).  Two of them,
``attempt`` (the stages of a step, ``y_new``, the error scale and norm) and
``dense`` (the interpolant's extra stages and rows), are straight-line code
fixed by the tableau and the state size.  Compiled by numba they cost
2.3-2.9 s of CPU per model and method, nearly all of it numba's typing and
lowering in Python; LLVM itself needs about 0.1-0.3 s.  This module writes
their IR text directly from the tableau (:func:`module_ir`), with the
coefficients as exact literals, and calls the model's right-hand side by the
symbol of its compiled ``rhs`` part, whose library is linked in before
optimization so that LLVM inlines it into every stage.

Every floating-point operation carries the ``contract`` flag (numba's
``fastmath={"contract"}``), so LLVM fuses multiply-adds.  A stage of a step
is summed as ``y + (h a_0) K_0 + (h a_1) K_1 + ...``, oldest stage first, so
that only the last term waits for the stage just computed (the chain of
dependent operations between two right-hand-side calls is one fused
multiply-add); the error norm and the interpolant sum ``0.0 + (c_0 K_0 +
c_1 K_1 + ...)``.  ``tests/test_irparts.py`` compares them with the same
method as plain loops over the tableau in numpy, on one workspace.

A right-hand side that fails (numba's status nonzero) makes ``attempt``
return NaN, so the step is rejected and the run ends with the step-size
failure instead of going on with garbage.  (``dense`` has no way to say so:
its extra stages lie inside a step whose own stages all succeeded.)

The compiled parts are kept in one file per kernel and machine
(:func:`cache_file`: numba's serialized object code), so that a second
process loads them in milliseconds (:func:`load_or_compile`).  The file is a
checked cache file, as numba's files of the kernels (:func:`.cache.write_checked`:
a SHA-256 verified before anything in it is read, only files of this user
that no one else may write are read), and no pickle: a JSON line with the
compilers' versions and the machine (:func:`_key`) and the sizes of numba's
two blobs (object code, bitcode), then the blobs; a file of another
key, or one that fails a check, is removed, said in one line and compiled again.
"""
from __future__ import annotations

import hashlib
import json
import struct
from pathlib import Path
from types import SimpleNamespace

from .cache import discard, read_checked, write_checked
from .methods import erk_arrays

#: the C signatures of the two parts (called by the integrator of :mod:`.erk`)
ATTEMPT_ARGS = ("double %t", "double %h", "double %t_new", "double %rtol", "i64 %mode_scaled", "ptr %ws",
                "i64 %nq", "ptr %ap", "ptr %pairp")
DENSE_ARGS = ("double %t", "double %h", "ptr %ws", "i64 %nq")
#: the flags of every floating-point operation of the two parts (numba's ``fastmath={"contract"}``)
FLAGS = "contract"
#: the version of what this module writes (part of the cache key)
FORMAT = 5
_NAN = "0x7FF8000000000000"


def literal(x: float) -> str:
    """``x`` as an exact LLVM IR double literal."""
    return "0x%016X" % struct.unpack("<Q", struct.pack("<d", float(x)))[0]


class _Writer:
    """IR text of one function: numbered SSA values and the instructions the parts need."""

    def __init__(self):
        # the right-hand side's return slot and exception slot (numba's calling convention)
        self.lines: list = ["  %ret = alloca ptr, align 8", "  %exc = alloca ptr, align 8"]
        self.count = 0
        #: the right-hand side's return codes so far, or-ed (0: every call succeeded)
        self.status = "0"

    def value(self, text: str) -> str:
        self.count += 1
        name = f"%v{self.count}"
        self.lines.append(f"  {name} = {text}")
        return name

    def emit(self, text: str) -> None:
        self.lines.append(f"  {text}")

    def ptr(self, base: str, offset: int) -> str:
        return base if offset == 0 else self.value(f"getelementptr inbounds double, ptr {base}, i64 {offset}")

    def load(self, base: str, offset: int) -> str:
        return self.value(f"load double, ptr {self.ptr(base, offset)}, align 8")

    def store(self, value: str, base: str, offset: int) -> None:
        self.emit(f"store double {value}, ptr {self.ptr(base, offset)}, align 8")

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

    def dot(self, coefficients, k: list, i: int) -> str:
        """``0.0 + (c_0 K_0[i] + c_1 K_1[i] + ...)`` over the nonzero coefficients, left to right (the
        template's ``acc = 0.0; acc += ...``)."""
        acc = None
        for j, c in enumerate(coefficients):
            if c != 0.0:
                term = self.mul(literal(c), k[j][i])
                acc = term if acc is None else self.add(acc, term)
        return "0.0" if acc is None else self.add("0.0", acc)


class Layout:
    """The offsets of the integrator's workspace, as the integrator of :mod:`.erk` lays it out: K (n_ext x n), y, y_new,
    work, scale (n each), F (dense_rows x n), then q."""

    def __init__(self, n: int, n_ext: int, dense_rows: int):
        self.n = n
        self.k = [j * n for j in range(n_ext)]
        o = n_ext * n
        self.y, self.y_new, self.work, self.scale, self.f = o, o + n, o + 2 * n, o + 3 * n, o + 4 * n
        self.q = o + (4 + dense_rows) * n


def _stage(w: _Writer, lay: Layout, rhs: str, nq: int, y: list, k: list, row, time: str, target: int,
           scaled: bool) -> list:
    """One stage from the ``len(k)`` stages so far: its state stored at ``target``, then ``K[len(k)] = f(time,
    state)``, whose values are loaded and appended to ``k``; returns the state's values.

    ``scaled``: ``y + (h a_0) K_0 + (h a_1) K_1 + ...`` (the stages of a step); else ``y + h (0.0 + (a_0 K_0
    + ...))`` (DOP853's extra stages of the interpolant, as the template's ``dense``).
    """
    s = len(k)
    values = []
    ha = [None if c == 0.0 else w.mul("%h", literal(c)) for c in row[:s]] if scaled else None
    for i in range(lay.n):
        if scaled:
            acc = y[i]
            for j in range(s):
                if ha[j] is not None:
                    acc = w.add(acc, w.mul(ha[j], k[j][i]))
        else:
            acc = w.add(y[i], w.mul("%h", w.dot(row[:s], k, i)))
        w.store(acc, "%ws", target + i)
        values.append(acc)
    code = w.value(f"call i32 @\"{rhs}\"(ptr %ret, ptr %exc, double {time}, ptr {w.ptr('%ws', target)}, "
                   f"ptr {w.ptr('%ws', lay.q)}, i64 {nq}, ptr {w.ptr('%ws', lay.k[s])}) #0")
    w.status = w.value(f"or i32 {w.status}, {code}")
    k.append([w.load("%ws", lay.k[s] + i) for i in range(lay.n)])
    return values


def attempt_ir(tab: SimpleNamespace, n: int, nq: int, name: str, rhs: str) -> str:
    """The IR of ``attempt`` (called by the integrator of :mod:`.erk`) for ``tab`` on ``n`` states and ``nq`` constants,
    defining the symbol ``name`` and calling the right-hand side ``rhs`` (numba's native function of the
    model's ``rhs`` part)."""
    lay = Layout(n, tab.n_ext, tab.dense_rows)
    w = _Writer()
    y = [w.load("%ws", lay.y + i) for i in range(n)]
    k = [[w.load("%ws", lay.k[0] + i) for i in range(n)]]
    for s in range(1, tab.n_stages + 1):
        last = s == tab.n_stages
        time = "%t_new" if last else w.add("%t", w.mul(literal(tab.C[s]), "%h"))
        y_new = _stage(w, lay, rhs, nq, y, k, tab.A[s], time, lay.y_new if last else lay.work, True)
    # scale_i = atol_i + rtol max(|y_i|, |y_new_i|), with mode_scaled also over the partner pair[i] >= 0
    scale = []
    scaled = w.value("icmp ne i64 %mode_scaled, 0")
    for i in range(n):
        m = w.max(w.fabs(y[i]), w.fabs(y_new[i]))
        pair = w.value(f"load i64, ptr {w.value(f'getelementptr inbounds i64, ptr %pairp, i64 {i}')}, align 8")
        has = w.value(f"and i1 {scaled}, {w.value(f'icmp sge i64 {pair}, 0')}")
        j = w.value(f"select i1 {has}, i64 {pair}, i64 {i}")
        yj = w.value(f"getelementptr inbounds double, ptr %ws, i64 {j}")
        a = w.fabs(w.load(yj, lay.y))
        b = w.fabs(w.load(yj, lay.y_new))
        m = w.value(f"select i1 {has}, double {w.max(w.max(m, a), b)}, double {m}")
        sc = w.add(w.value(f"load double, ptr {w.ptr('%ap', i)}, align 8"), w.mul("%rtol", m))
        w.store(sc, "%ws", lay.scale + i)
        scale.append(sc)
    # the scaled norm of the embedded estimate (DOP853: its 5th- and 3rd-order ones combined as Hairer's)
    n5, n3 = "0.0", "0.0"
    for i in range(n):
        e5 = w.div(w.dot(tab.E5, k, i), scale[i])
        n5 = w.add(n5, w.mul(e5, e5))
        if tab.hairer:
            e3 = w.div(w.dot(tab.E3, k, i), scale[i])
            n3 = w.add(n3, w.mul(e3, e3))
    habs = w.fabs("%h")
    if tab.hairer:
        norm = w.div(w.mul(habs, n5), w.sqrt(w.mul(w.add(n5, w.mul(literal(0.01), n3)), literal(n))))
        zero = w.value(f"and i1 {w.value(f'fcmp oeq double {n5}, 0.0')}, {w.value(f'fcmp oeq double {n3}, 0.0')}")
        err = w.value(f"select i1 {zero}, double 0.0, double {norm}")
    else:
        err = w.mul(habs, w.sqrt(w.div(n5, literal(n))))
    failed = w.value(f"icmp ne i32 {w.status}, 0")
    w.emit(f"ret double {w.value(f'select i1 {failed}, double {_NAN}, double {err}')}")
    return _function("double", name, ATTEMPT_ARGS, w)


def dense_ir(tab: SimpleNamespace, n: int, nq: int, name: str, rhs: str) -> str:
    """The IR of ``dense`` (called by the integrator of :mod:`.erk`): the interpolant's rows ``F`` (DOP853:
    its extra stages first) for ``tab`` on ``n`` states, defining ``name`` and calling the right-hand side ``rhs``."""
    lay = Layout(n, tab.n_ext, tab.dense_rows)
    w = _Writer()
    s = tab.n_stages
    k = [[w.load("%ws", lay.k[j] + i) for i in range(n)] for j in range(s + 1)]
    if tab.hairer:
        y = [w.load("%ws", lay.y + i) for i in range(n)]
        y_new = [w.load("%ws", lay.y_new + i) for i in range(n)]
        for st in range(s + 1, tab.n_ext):
            time = w.add("%t", w.mul(literal(tab.C[st]), "%h"))
            _stage(w, lay, rhs, nq, y, k, tab.A[st], time, lay.work, False)
        for i in range(n):
            dy = w.sub(y_new[i], y[i])
            w.store(dy, "%ws", lay.f + i)
            w.store(w.sub(w.mul("%h", k[0][i]), dy), "%ws", lay.f + n + i)
            f2 = w.sub(w.mul(literal(2.0), dy), w.mul("%h", w.add(k[s][i], k[0][i])))
            w.store(f2, "%ws", lay.f + 2 * n + i)
            for r, row in enumerate(tab.DD):
                w.store(w.mul("%h", w.dot(row, k, i)), "%ws", lay.f + (3 + r) * n + i)
    else:
        for i in range(n):
            for r, col in enumerate(tab.P.T):
                w.store(w.mul("%h", w.dot(col, k, i)), "%ws", lay.f + r * n + i)
    w.emit("ret void")
    return _function("void", name, DENSE_ARGS, w)


def _function(returns: str, name: str, args, w: _Writer) -> str:
    return f'define {returns} @"{name}"({", ".join(args)}) {{\nentry:\n' + "\n".join(w.lines) + "\n}\n"


def module_ir(tab: SimpleNamespace, n: int, nq: int, names: tuple, rhs: str, rhs_definition: str = "",
              extra: str = "") -> str:
    """The IR module of both parts (``names``: the symbols of ``attempt`` and ``dense``, and optionally of a
    C-callable ``rhs`` part) for ``tab`` on ``n`` states and ``nq`` constants, calling the right-hand side
    ``rhs`` (numba's calling convention): defined by ``rhs_definition`` (its IR, from the generated module), or
    else declared (numba's compiled ``rhs`` part, linked in).  Every call of it is inlined (``alwaysinline``:
    measured on the two-mode model, a call left in costs 7-9 % per evaluation).  ``extra``: more
    definitions (their declarations of intrinsics merged with the parts')."""
    lines = rhs_definition.splitlines()
    more = extra.splitlines()
    declarations = sorted({x for x in lines + more if x.startswith("declare ")}
                          | {"declare double @llvm.fabs.f64(double)", "declare double @llvm.sqrt.f64(double)"})
    return "\n".join([
        f"; knifeedge parts of {tab.name}, {n} states, format {FORMAT}",
        "\n".join(x for x in lines if not x.startswith("declare "))
        or f'declare i32 @"{rhs}"(ptr, ptr, double, ptr, ptr, i64, ptr)',
        *declarations,
        *[x for x in more if not x.startswith("declare ")],
        attempt_ir(tab, n, nq, names[0], rhs),
        dense_ir(tab, n, nq, names[1], rhs),
        *([c_wrapper_ir(rhs, names[2])] if len(names) > 2 else []),
        "attributes #0 = { alwaysinline }",
        "",
    ])


def compile_library(ir_text: str, name: str, link):
    """numba's code library of ``ir_text``, the libraries ``link`` linked in before optimization (so that
    their functions inline), optimized by numba's pipeline, finalized, its object code kept to be saved."""
    import llvmlite.binding as ll
    from numba.core.compiler_lock import global_compiler_lock

    with global_compiler_lock:
        lib = _codegen().create_library(name)
        lib.enable_object_caching()
        module = ll.parse_assembly(ir_text)
        module.name = name
        module.verify()
        lib.add_llvm_module(module)
        for other in link:
            lib.add_linking_library(other)
        lib.finalize()
    return lib


def _codegen():
    from numba.core.registry import cpu_target

    return cpu_target.target_context.codegen()


def _key() -> tuple:
    """What compiled parts depend on beside their IR: this module's format, numba, llvmlite and the machine."""
    import llvmlite
    import numba

    return (FORMAT, numba.__version__, llvmlite.__version__, _codegen().magic_tuple())


def cache_file(kernel_path) -> Path:
    """Where the compiled parts of the kernel ``kernel_path`` (``AdaptiveKernel.path``, a name in the cache
    folder) are kept on this machine: named after it and a hash of :func:`_key`."""
    path = Path(kernel_path)
    return path.with_name(f"{path.stem}.parts-{hashlib.sha256(repr(_key()).encode()).hexdigest()[:16]}.nbo")


def symbols(kernel_path) -> tuple:
    """The symbols of ``attempt``, ``dense``, the C-callable ``rhs`` and ``constants`` for the kernel
    ``kernel_path`` (unique per module; the first three are in every parts library, ``constants`` where the
    model carries its IR)."""
    stem = Path(kernel_path).stem
    return (f"knifeedge.attempt.{stem}", f"knifeedge.dense.{stem}", f"knifeedge.rhs.{stem}",
            f"knifeedge.constants.{stem}")


def _constants_ir(name: str, constants: str) -> str:
    """The model's ``constants`` (its IR from the generated module, or "") exported as ``name``."""
    if not constants:
        return ""
    return (constants + f'define void @"{name}"(ptr %p, ptr %q) {{\nentry:\n'
            f'  call void @"constants"(ptr %p, ptr %q)\n  ret void\n}}\n')


def c_wrapper_ir(native: str, symbol: str) -> str:
    """A C-callable ``void symbol(double t, double* y, double* q, int64 nq, double* out)`` calling ``native``
    (the ``rhs`` part's address for the integrator's own calls: the initial step)."""
    return (f'define void @"{symbol}"(double %t, ptr %y, ptr %q, i64 %nq, ptr %out) {{\nentry:\n'
            f"  %ret = alloca ptr\n  %exc = alloca ptr\n"
            f'  %status = call i32 @"{native}"(ptr %ret, ptr %exc, double %t, ptr %y, ptr %q, i64 %nq, ptr %out)\n'
            f"  ret void\n}}\n")


def _load(path: Path, names: tuple):
    """``(library, addresses)`` kept in ``path``, or None (a file that cannot be used is discarded)."""
    from numba.core.compiler_lock import global_compiler_lock

    if not path.exists():
        return None
    try:
        serialized = read_parts(path)
        with global_compiler_lock:
            lib = _codegen().unserialize_library(serialized)
            addresses = [lib.get_pointer_to_function(x) for x in names]
        if all(addresses[:3]):
            return lib, addresses
        raise ValueError("it lacks the parts' symbols")
    except Exception as exc:  # noqa: BLE001 - any unreadable file is compiled again
        discard([path], exc, "compiled-parts cache file")
    return None


def load_or_compile(kernel_path, tableau: str, n: int, nq: int, model, rhs_name: str, rhs_cfunc) -> tuple:
    """``(library, addresses)`` of the parts of the kernel ``kernel_path`` (``AdaptiveKernel.path``, a name in
    the cache folder), loaded from :func:`cache_file`, or compiled from :func:`module_ir` and saved there;
    ``addresses`` are those of :func:`symbols` (0 for ``constants`` where the model has no IR of it).

    The right-hand side ``rhs_name`` and ``constants`` are the IR the generated ``model`` carries
    (``model.LLVM_IR``, written at derive time by ``derivation/ir_emit.py``); a right-hand side it does not
    carry is numba's compiled ``rhs`` part (``rhs_cfunc()``, a ``numba.cfunc``) linked in.  A cache file that
    cannot be read is removed, said in one line on stderr, and compiled again.
    """
    path = cache_file(kernel_path)
    names = symbols(kernel_path)
    loaded = _load(path, names)
    if loaded is not None:
        return loaded
    ir = getattr(model, "LLVM_IR", {})
    if rhs_name in ir:
        native, definition, link = rhs_name, ir[rhs_name], []
    else:
        compiled = rhs_cfunc()
        native = compiled.native_name
        if not native.startswith("cfunc."):
            raise RuntimeError(f"unexpected symbol of a compiled C callback: {native!r}") from None
        native, definition, link = native[len("cfunc."):], "", [compiled._library]
    extras = _constants_ir(names[3], ir.get("constants", ""))
    text = module_ir(erk_arrays(tableau), n, nq, names[:3], native, definition, extras)
    lib = compile_library(text, f"knifeedge_parts_{Path(kernel_path).stem}", link)
    addresses = [lib.get_pointer_to_function(x) for x in names]
    write_parts(path, lib.serialize_using_object_code())
    return lib, addresses


def write_parts(path: Path, serialized: tuple) -> None:
    """Keep numba's ``serialize_using_object_code()`` of the parts, ``(name, "object", (object code, bitcode))``,
    in ``path``: a checked cache file (:func:`.cache.write_checked`) holding a JSON line (:func:`_key`, the name,
    the two blobs' sizes) and the blobs, no pickle."""
    name, kind, (code, bitcode) = serialized
    head = {"key": _key(), "name": name, "kind": kind, "sizes": [len(code), len(bitcode)]}
    write_checked(path, json.dumps(head).encode() + b"\n" + code + bitcode, "the compiled parts")


def read_parts(path: Path) -> tuple:
    """numba's serialized parts kept in ``path`` by :func:`write_parts` (:func:`.cache.read_checked`); ValueError
    if they were compiled with another :func:`_key` or the sizes do not add up."""
    data = read_checked(path)
    line, _, blobs = data.partition(b"\n")
    try:
        head = json.loads(line)
        key, sizes = head["key"], head["sizes"]
    except (ValueError, KeyError, TypeError):
        raise ValueError(f"{path}: its header is not the parts' header") from None
    if key != json.loads(json.dumps(_key())):
        raise ValueError(f"{path}: compiled by another compiler or for another machine ({key!r})")
    if sum(sizes) != len(blobs):
        raise ValueError(f"{path}: its blobs are not the sizes its header says")
    return head["name"], head["kind"], (blobs[:sizes[0]], blobs[sizes[0]:])
