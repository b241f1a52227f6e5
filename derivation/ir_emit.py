"""A generated model's right-hand side as LLVM IR, written at derive time from the module's Python.

:func:`with_ir` is the emitter's last step before a module is sealed
(``emit.write_all``): it reads the module text it was given and appends
``LLVM_IR``, the IR of its ``rhs_q_into``, ``rhs_pose_q_into`` and
``constants`` where they can be written so (a function left out is one the
runtime compiles with numba instead), and ``LLVM_IR_READS``, the number of
parameters that ``constants`` reads.  The runtime hands these strings to
LLVM (``knifeedge.integrators.irparts``); it never parses source.

The generated ``rhs_q_into(t, s, q, ds)`` (and ``rhs_pose_q_into``) is
straight-line arithmetic (selects included): names bound once, ``s[i]`` and ``q[i]`` read,
``ds[i]`` written, ``+ - * /``, powers, ``math.sin``, ``math.cos``,
``math.sqrt``.  numba takes 0.1-0.6 s to compile one (its typing and
lowering cost about a millisecond per operation); LLVM, given the same
operations as IR, a few milliseconds.  :func:`rhs_ir` writes that IR with
the operations numba would emit, in the same order and without fast-math
flags, so that the result is the one numba's compilation computes, bit for
bit (checked for every generated module by ``tests/test_ir_emit.py``):

- ``a + b``, ``a - b``, ``a * b``, ``a / b``: one ``fadd``, ``fsub``, ``fmul``,
  ``fdiv`` in double precision; integer literals are converted exactly;
- ``x ** k`` for an integer literal ``k``: numba's unrolled square-and-multiply
  (``res = 1.0``; for each bit of ``|k|``, low first: ``res *= x`` if set, then
  ``x *= x``; ``1.0 / res`` if ``k < 0``); any other power ``llvm.pow.f64``;
- ``-a``: ``fneg``; ``math.sin``, ``math.cos``, ``math.sqrt``, ``math.exp``,
  ``math.log``, ``abs``: the LLVM intrinsics numba uses (``sqrt`` is exact).

- ``a if x < y else b`` (a conditional expression, the pivot choices of a
  numeric elimination's LU, ``derivation/kkt_emit.py``) with one comparison
  ``<``, ``>``, ``<=``, ``>=``, ``==`` or ``!=``: numba's ``fcmp`` (ordered,
  false when either side is NaN, except ``!=``: unordered, true on NaN;
  numba/cpython/numbers.py) and a ``select``.  Both arms are computed, where
  numba computes the one taken: they are pure (names, loads of the inputs,
  arithmetic and intrinsics, nothing that writes or raises here), so the
  result is the same bits.  Two integer constants as arms (numba would type
  the result as an integer) are refused.

A division by zero gives an infinity or NaN here where numba's compilation
would raise (which a compiled callback cannot pass on): the integrator sees
a non-finite error norm and rejects the step.

Anything else (a statement ``if``, a chained comparison or ``and``/``or``
in a condition, a call of another function) raises :class:`Unsupported`;
that function is then left out of ``LLVM_IR``.

Every function is defined ``internal`` under its Python name (``@"rhs_q_into"``, ...): the runtime links it
into a library of its own that calls it (and inlines it), so equal names in several libraries never clash.
"""
from __future__ import annotations

import ast
import math
import struct

#: the functions of a generated module written as IR, when it has them and they are straight-line
FUNCTIONS = ("rhs_q_into", "rhs_pose_q_into", "constants")


def literal(x: float) -> str:
    """``x`` as an exact LLVM IR double literal."""
    return "0x%016X" % struct.unpack("<Q", struct.pack("<d", float(x)))[0]

#: math functions and the LLVM intrinsic that numba's compilation calls for each
_INTRINSICS = {"sin": "llvm.sin.f64", "cos": "llvm.cos.f64", "sqrt": "llvm.sqrt.f64", "exp": "llvm.exp.f64",
               "log": "llvm.log.f64", "fabs": "llvm.fabs.f64"}


#: numba's comparison of two floats as the LLVM ``fcmp`` predicate (numba/cpython/numbers.py: ``fcmp_ordered``
#: for all but ``!=``, which is ``fcmp_unordered``)
_COMPARISONS = {ast.Lt: "olt", ast.Gt: "ogt", ast.LtE: "ole", ast.GtE: "oge", ast.Eq: "oeq", ast.NotEq: "une"}


class Unsupported(ValueError):
    """The function is not straight-line arithmetic this module can write as IR."""


def _constant(node):
    """The value of ``node`` if it is made of numeric constants and arithmetic only (what Python's compiler
    folds into one constant before numba sees the function), else None."""
    for sub in ast.walk(node):
        if not isinstance(sub, (ast.Constant, ast.BinOp, ast.UnaryOp, ast.operator, ast.unaryop)):
            return None
        if isinstance(sub, ast.Constant) and type(sub.value) not in (int, float):
            return None
    try:
        value = eval(compile(ast.Expression(body=node), "<constant>", "eval"), {"__builtins__": {}})  # noqa: S307
    except (ArithmeticError, ValueError, TypeError):
        raise Unsupported(f"constant expression {ast.unparse(node)}") from None
    if type(value) not in (int, float) or not math.isfinite(value):
        raise Unsupported(f"constant expression {ast.unparse(node)} = {value!r}")
    return value


class _Body:
    def __init__(self, arrays: dict, scalars: dict):
        self.lines: list = []
        self.n = 0
        self.names = dict(scalars)  # name -> IR value
        self.arrays = arrays  # name -> IR pointer argument
        self.used: set = set()
        self.extent: dict = {}  # array name -> 1 + its largest index used

    def value(self, text: str) -> str:
        self.n += 1
        self.lines.append(f"  %v{self.n} = {text}")
        return f"%v{self.n}"

    def element(self, node: ast.Subscript) -> str:
        if not (isinstance(node.value, ast.Name) and node.value.id in self.arrays):
            raise Unsupported(f"subscript of {ast.unparse(node.value)}")
        index = node.slice
        if not (isinstance(index, ast.Constant) and type(index.value) is int and index.value >= 0):
            raise Unsupported(f"index {ast.unparse(index)}")
        name = node.value.id
        self.extent[name] = max(self.extent.get(name, 0), index.value + 1)
        return self.value(f"getelementptr inbounds double, ptr {self.arrays[node.value.id]}, i64 {index.value}")

    def expr(self, node) -> str:
        if isinstance(node, (ast.BinOp, ast.UnaryOp)):
            folded = _constant(node)
            if folded is not None:  # Python's compiler folds it: numba sees the value
                return literal(float(folded))
        if isinstance(node, ast.Constant):
            if type(node.value) not in (int, float) or not math.isfinite(node.value):
                raise Unsupported(f"constant {node.value!r}")
            return literal(float(node.value))
        if isinstance(node, ast.Name):
            if node.id not in self.names:
                raise Unsupported(f"name {node.id}")
            return self.names[node.id]
        if isinstance(node, ast.Subscript):
            return self.value(f"load double, ptr {self.element(node)}")
        if isinstance(node, ast.UnaryOp):
            if isinstance(node.op, ast.USub):
                return self.value(f"fneg double {self.expr(node.operand)}")
            if isinstance(node.op, ast.UAdd):
                return self.expr(node.operand)
            raise Unsupported(ast.unparse(node))
        if isinstance(node, ast.BinOp):
            if isinstance(node.op, ast.Pow):
                return self.power(node)
            op = {ast.Add: "fadd", ast.Sub: "fsub", ast.Mult: "fmul", ast.Div: "fdiv"}.get(type(node.op))
            if op is None:
                raise Unsupported(ast.unparse(node))
            a, b = self.expr(node.left), self.expr(node.right)
            return self.value(f"{op} double {a}, {b}")
        if isinstance(node, ast.IfExp):
            return self.select(node)
        if isinstance(node, ast.Call) and not node.keywords and len(node.args) == 1:
            f = node.func
            name = (f.attr if isinstance(f, ast.Attribute) and isinstance(f.value, ast.Name) and f.value.id == "math"
                    else "fabs" if isinstance(f, ast.Name) and f.id == "abs" else None)
            if name in _INTRINSICS:
                self.used.add(_INTRINSICS[name])
                return self.value(f"call double @{_INTRINSICS[name]}(double {self.expr(node.args[0])})")
        raise Unsupported(ast.unparse(node))

    def select(self, node: ast.IfExp) -> str:
        """``a if x <op> y else b``: numba's comparison (:data:`_COMPARISONS`), both arms, a ``select``."""
        test = node.test
        if not (isinstance(test, ast.Compare) and len(test.ops) == 1 and type(test.ops[0]) in _COMPARISONS):
            raise Unsupported(f"condition {ast.unparse(test)}")
        if all(isinstance(arm, ast.Constant) and type(arm.value) is int for arm in (node.body, node.orelse)):
            raise Unsupported(f"integer select {ast.unparse(node)}")
        x, y = self.expr(test.left), self.expr(test.comparators[0])
        chosen = self.value(f"fcmp {_COMPARISONS[type(test.ops[0])]} double {x}, {y}")
        a, b = self.expr(node.body), self.expr(node.orelse)
        return self.value(f"select i1 {chosen}, double {a}, double {b}")

    def power(self, node: ast.BinOp) -> str:
        exponent = node.right
        k = _constant(exponent)
        if type(k) is not int:  # a float exponent: numba's llvm.pow
            self.used.add("llvm.pow.f64")
            return self.value(f"call double @llvm.pow.f64(double {self.expr(node.left)}, double {self.expr(exponent)})")
        if abs(k) > 0x10000:
            raise Unsupported(f"power {k}")
        x = self.expr(node.left)
        res = literal(1.0)
        e = abs(k)
        while e:
            if e & 1:
                res = self.value(f"fmul double {res}, {x}")
            e >>= 1
            if e:  # numba squares once more after the last bit; that value is never used
                x = self.value(f"fmul double {x}, {x}")
        if k < 0:
            res = self.value(f"fdiv double {literal(1.0)}, {res}")
        return res

    def statement(self, node) -> None:
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str):
            return  # the docstring
        if isinstance(node, ast.Assign) and len(node.targets) == 1:
            target = node.targets[0]
            value = self.expr(node.value)
            if isinstance(target, ast.Name):
                if target.id in self.arrays or target.id in self.names:
                    raise Unsupported(f"{target.id} bound twice")
                self.names[target.id] = value
                return
            if isinstance(target, ast.Subscript):
                self.lines.append(f"  store double {value}, ptr {self.element(target)}")
                return
        raise Unsupported(ast.unparse(node))


def _function_def(fn: ast.FunctionDef, args: list) -> ast.FunctionDef:
    """``fn`` (a parsed function), whose parameters must be exactly ``args``."""
    if not isinstance(fn, ast.FunctionDef) or [a.arg for a in fn.args.args] != args \
            or fn.args.vararg or fn.args.kwarg or fn.args.kwonlyargs or fn.args.defaults:
        raise Unsupported(f"not a function of ({', '.join(args)})")
    return fn


def functions(source: str) -> dict:
    """The top-level functions of the module text ``source``, by name (parsed, not run)."""
    return {node.name: node for node in ast.parse(source).body if isinstance(node, ast.FunctionDef)}


def _text(head: str, body: _Body, ret: str) -> str:
    """The function ``head`` with ``body``'s instructions and ``ret``, then the intrinsics it calls declared."""
    declarations = [f"declare double @{name}(double{', double' if name == 'llvm.pow.f64' else ''})"
                    for name in sorted(body.used)]
    return head + "\n".join(body.lines + [f"  {ret}", "}"]) + "\n" + "\n".join(declarations) + "\n"


def rhs_ir(func: ast.FunctionDef, symbol: str) -> str:
    """The IR of ``func(t, s, q, ds)`` (a generated ``rhs_q_into``, parsed: :func:`functions`),
    as the internal function ``symbol`` with numba's native calling convention for the arguments ``(t, s, q, nq, ds)``
    (``i32 (ptr retptr, ptr excinfo, double, ptr, ptr, i64, ptr)``, returning 0), followed by the declarations
    of the intrinsics it calls.  Raises :class:`Unsupported` for what it cannot write."""
    fn = _function_def(func, ["t", "s", "q", "ds"])
    body = _Body(arrays={"s": "%s", "q": "%q", "ds": "%ds"}, scalars={"t": "%t"})
    for node in fn.body:
        if isinstance(node, ast.Return) and node.value is None:
            continue
        body.statement(node)
    head = (f'define internal i32 @"{symbol}"(ptr nocapture %ret, ptr nocapture %exc, double %t, '
            f"ptr nocapture %s, ptr nocapture %q, i64 %nq, ptr nocapture %ds) {{\nentry:\n")
    return _text(head, body, "ret i32 0")


def constants_ir(func: ast.FunctionDef, symbol: str, nq: int) -> tuple:
    """The IR of a generated ``constants(p)`` (parsed; ``q = np.empty(nq)``, ``q[i] = ...``, ``return q``) as
    the internal ``void symbol(double* p, double* q)`` writing into ``q``, and the number of parameters it
    reads (``p`` must hold at least that many).  Raises :class:`Unsupported` for anything else."""
    fn = _function_def(func, ["p"])
    body = _Body(arrays={"p": "%p"}, scalars={})
    out = None
    statements = list(fn.body)
    last = statements.pop() if statements else None
    if not (isinstance(last, ast.Return) and isinstance(last.value, ast.Name)):
        raise Unsupported("does not end by returning its array")
    for node in statements:
        if (isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name)
                and out is None and ast.unparse(node.value) == f"np.empty({nq})"):
            out = node.targets[0].id
            body.arrays[out] = "%q"
            continue
        body.statement(node)
    if out is None or last.value.id != out:
        raise Unsupported(f"does not return its np.empty({nq})")
    if body.extent.get(out, 0) > nq:
        raise Unsupported(f"writes beyond its np.empty({nq})")
    head = f'define internal void @"{symbol}"(ptr nocapture readonly %p, ptr nocapture %q) {{\nentry:\n'
    return _text(head, body, "ret void"), body.extent.get("p", 0)


def _size(fn: ast.FunctionDef):
    """``nq`` of a ``constants`` that starts with ``q = np.empty(nq)`` (an integer literal), else None."""
    for node in fn.body:
        value = getattr(node, "value", None)
        if (isinstance(node, ast.Assign) and isinstance(value, ast.Call) and ast.unparse(value.func) == "np.empty"
                and len(value.args) == 1 and isinstance(value.args[0], ast.Constant)
                and type(value.args[0].value) is int):
            return value.args[0].value
    return None


def module_ir(source: str) -> tuple:
    """``({name: IR}, reads)``: the IR of the functions :data:`FUNCTIONS` of the module text ``source`` that
    can be written so, and the number of parameters its ``constants`` reads (0 if it is not written)."""
    found = functions(source)
    out, reads = {}, 0
    for name in FUNCTIONS:
        if name not in found:
            continue
        try:
            if name == "constants":
                nq = _size(found[name])
                if nq is None:
                    raise Unsupported("does not start with q = np.empty(<size>)")
                out[name], reads = constants_ir(found[name], name, nq)
            else:
                out[name] = rhs_ir(found[name], name)
        except Unsupported:
            continue
    return out, reads


def with_ir(source: str) -> str:
    """The module text ``source`` with ``LLVM_IR`` and ``LLVM_IR_READS`` appended (see the module's doc)."""
    ir, reads = module_ir(source)
    entries = "".join(f"    {name!r}: (\n" + "".join(f"        {line + chr(10)!r}\n" for line in text.splitlines())
                      + "    ),\n" for name, text in ir.items())
    return (source.rstrip("\n") + "\n\n\n"
            "#: LLVM IR of the functions above that are straight-line arithmetic, written by derivation/ir_emit.py\n"
            "#: (the operations numba emits for them, in its order: the same bits); the runtime compiles it\n"
            f"LLVM_IR = {{\n{entries}}}\n"
            "#: how many parameters the IR of ``constants`` reads\n"
            f"LLVM_IR_READS = {reads}\n")
