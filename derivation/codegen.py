"""The one writer of generated modules: what a module holds (:class:`ModuleParts`) and its text.

Every kind of model (point masses, :mod:`.emit`; rigid bodies, :mod:`.rigid_emit`; their small-tilt
fidelities, :mod:`.rigid_small_emit`; amplitude equations; numeric elimination, :mod:`.kkt_emit`) only builds
a :class:`ModuleParts`: a header, the constants the runtime reads, and the body, a sequence of jitted
:class:`Function` s (an expression block: CSE'd assignments to targets, with the vectors it reads unpacked)
and blocks of text the block builders write (:mod:`.drawing`, :mod:`.jacobian`, :mod:`.steady`, model
helpers).  :func:`module_text` writes every module; :func:`finish` is where a module's text is finished (sealed,
:func:`knifeedge.modulecheck.seal`) before it is written to a file.

Also here, shared by the builders: the printer of SymPy expressions (:func:`code`), CSE blocks that refuse
undeclared symbols (:func:`cse_block`), the unpacking of vectors (:func:`unpack`) and the right-hand-side
functions every module has (:func:`rhs_functions`).  This module imports no other module of the derivation
but :mod:`.names`, so that every builder can import it.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

from knifeedge.modulecheck import seal

from . import ir_emit, names

#: model files of the source tree's examples/ derived into generated/ with the package's models (``make derive``)
EXAMPLE_MODELS = ("examples/rolling_disk.py",)
#: a user's model file runs as the module ``<prefix><file stem>`` (a RigidBody's ``source=__name__`` names it)
USER_MODULE_PREFIX = "knifeedge_user_spec_"
#: the metadata every module defines (``knifeedge.models.REQUIRED_METADATA`` and the provenance)
REQUIRED_CONSTANTS = ("MODEL", "FIDELITY", "FIDELITY_DOC", "STATE_NAMES", "STATE_UNITS", "POSE_NAMES",
                      "POSE_UNITS", "PARAM_NAMES", "PARAM_UNITS", "PARAM_DOMAINS", "DEFAULT_PARAMS",
                      "DEFAULT_STATE", "RATE_PAIRS", "TILT_NAMES", "REVERSAL_EVENTS", "EVENT_NAMES", "VALIDITY",
                      "MULTIPLIER_NAMES", "HAS_DISSIPATION", "EXPORTS", "INPUT_HASH", "SYMPY_VERSION")


class _Printer(PythonCodePrinter):
    """Python printer with bare ``math`` names and small integer powers as products.

    A power printed as a product is always parenthesized, ``(L*L)``, so that
    it keeps its precedence wherever the printer of the enclosing expression
    places it (``x/(L*L)``, never ``x/L*L``).
    """

    def _print_Pow(self, expr, rational=False):
        b, e = expr.args
        if e.is_Integer and 1 < abs(int(e)) <= 4:
            product = "(" + "*".join([self.parenthesize(b, 100)] * abs(int(e))) + ")"
            return product if int(e) > 0 else f"(1.0/{product})"
        return super()._print_Pow(expr, rational=rational)

    def _print_Rational(self, expr):
        return f"({float(expr.p)!r}/{float(expr.q)!r})"

    def _print_Symbol(self, expr):
        """The emitter's own symbols as they are; a user's through :func:`.names.identifier`."""
        return expr.name if isinstance(expr, names.Own) else names.identifier(expr.name)


def code(e: sp.Expr) -> str:
    """Python source of the SymPy expression ``e``."""
    return _Printer({"fully_qualified_modules": True, "standard": "python3"}).doprint(e)


def cse_block(exprs, targets, allowed, indent="    ", prefix="_c"):
    """CSE ``exprs`` and assign them to ``targets``; returns (code lines, op count).

    Refuses (``ValueError``) an expression with a symbol outside ``allowed``.
    """
    bad = set().union(*(e.free_symbols for e in exprs)) - set(allowed)
    if bad:
        raise ValueError(f"refusing to emit: undeclared symbols {sorted(map(str, bad))}")
    subs, reduced_exprs = sp.cse(exprs, symbols=sp.numbered_symbols(prefix, cls=names.Own), order="canonical")
    lines = [f"{indent}{s} = {code(v)}" for s, v in subs]
    lines += [f"{indent}{t} = {code(v)}" for t, v in zip(targets, reduced_exprs)]
    ops = sum(sp.count_ops(v) for _, v in subs) + sum(sp.count_ops(v) for v in reduced_exprs)
    return lines, int(ops)


def unpack(user_names, array, indent="    ", start=0):
    """Lines binding names to ``array[start]``, ``array[start + 1]``, ...

    A user's name (a string or a symbol) is written as its :func:`.names.identifier`, an emitter's own
    symbol (:class:`.names.Own`, e.g. a hoisted constant) as it is.
    """
    ident = lambda n: n.name if isinstance(n, names.Own) else names.identifier(str(n))  # noqa: E731
    return [f"{indent}{ident(n)} = {array}[{start + i}]" for i, n in enumerate(user_names)]


@dataclass(frozen=True)
class Function:
    """A jitted function of a generated module.

    ``body``: its lines after the docstring (an entry may hold several lines, or none: an empty entry is an
    empty line); ``ops``: the operation count of the body, reported in ``OP_COUNTS`` under ``key`` (default
    the name), ``None`` for a function that is not counted.
    """

    name: str
    args: str
    doc: str
    body: tuple
    ops: int | None = None
    key: str | None = None

    def source(self) -> str:
        return "\n".join(("@njit(cache=True)", f"def {self.name}({self.args}):", f'    """{self.doc}"""',
                          *self.body)) + "\n"


def expression_function(name: str, args: str, doc: str, exprs, targets, allowed, unpacked, ret: str,
                        head: tuple = (), block=None) -> Function:
    """The :class:`Function` ``name(args)`` that assigns ``exprs`` (CSE'd) to ``targets`` and returns ``ret``.

    ``unpacked``: groups of lines binding the names the expressions read (:func:`unpack`), one body entry
    each; ``head``: lines before them (``out = np.empty(n)``); ``doc`` gets the operation count appended;
    ``block``: what writes the lines (default :func:`cse_block`; see :func:`.kkt_emit.function_lines`).
    """
    lines, ops = (block or cse_block)(list(exprs), list(targets), allowed)
    return lines_function(name, args, doc, lines, ops, unpacked, ret, head)


def lines_function(name: str, args: str, doc: str, lines, ops: int, unpacked, ret: str, head: tuple = (),
                   key: str | None = None) -> Function:
    """The :class:`Function` of :func:`expression_function` from its computing ``lines`` and their ``ops``."""
    body = (*head, *("\n".join(group) for group in unpacked), "\n".join(lines), f"    return {ret}")
    return Function(name, args, f"{doc} ({ops} operations).", body, ops, key)


@dataclass(frozen=True)
class Constant:
    """A module-level constant: ``NAME = code``, after its ``#:`` comment lines ``doc`` (may be empty)."""

    name: str
    code: str
    doc: str = ""

    def source(self) -> str:
        comment = "".join(f"#: {line}\n" for line in self.doc.split("\n")) if self.doc else ""
        return f"{comment}{self.name} = {self.code}"


def const(name: str, value, doc: str = "") -> Constant:
    """A :class:`Constant` holding ``repr(value)``."""
    return Constant(name, repr(value), doc)


@dataclass(frozen=True)
class ModuleParts:
    """What a generated module holds, in its order; :func:`module_text` writes it.

    title : the first line of the docstring (``"<model>, fidelity <f>: <what it is>."``).
    hint : how to regenerate the module (:func:`regenerate_hint`).
    produced : the line(s) naming the emitter and the sources the module comes from.
    digest : the input hash (also the constant ``INPUT_HASH`` of ``constants``).
    doc : the rest of the docstring (description, order of the vectors).
    constants : the metadata the runtime reads (:data:`REQUIRED_CONSTANTS` at least), in order; ``OP_COUNTS``
        (of the counted functions of ``body``, in their order) follows them.
    body : :class:`Function` s and blocks of source text (each beginning with its blank lines), in order.
    """

    title: str
    hint: str
    produced: str
    digest: str
    doc: str
    constants: tuple
    body: tuple

    def __post_init__(self):
        defined = [c.name for c in self.constants]
        missing = [n for n in REQUIRED_CONSTANTS if n not in defined]
        if missing or len(set(defined)) != len(defined):
            raise ValueError(f"module {self.title!r}: constants lack {missing} or repeat one of {defined}")
        if dict(zip(defined, (c.code for c in self.constants)))["INPUT_HASH"] != repr(self.digest):
            raise ValueError(f"module {self.title!r}: INPUT_HASH is not the header's digest {self.digest}")

    def op_counts(self) -> dict:
        """``{key: operation count}`` of the counted functions, in the order of the body."""
        return {f.key or f.name: f.ops for f in self.body if isinstance(f, Function) and f.ops is not None}


def provenance(digest: str) -> tuple:
    """The constants ``INPUT_HASH`` and ``SYMPY_VERSION``."""
    return const("INPUT_HASH", digest), const("SYMPY_VERSION", sp.__version__)


_OP_COUNTS_DOC = "floating-point operation counts of each function body (SymPy count_ops after CSE)"


def module_text(parts: ModuleParts) -> str:
    """The source of the module ``parts`` describes (unsealed)."""
    constants = (*parts.constants, const("OP_COUNTS", parts.op_counts(), _OP_COUNTS_DOC))
    header = f'''"""{parts.title}

GENERATED FILE -- DO NOT EDIT BY HAND.  {parts.hint}
{parts.produced}
SymPy {sp.__version__}; input hash sha256:{parts.digest}

{parts.doc}
"""
import math

import numpy as np
from numba import njit

'''
    body = "".join("\n\n" + b.source() if isinstance(b, Function) else b for b in parts.body)
    return header + "\n".join(c.source() for c in constants) + "\n" + body


def finish(parts: ModuleParts) -> str:
    """The finished text of a module: :func:`module_text` with the LLVM IR of its right-hand side appended
    (:func:`.ir_emit.with_ir`), sealed (its last line the SHA-256 of the rest)."""
    return seal(ir_emit.with_ir(module_text(parts)))


def regenerate_hint(label: str) -> str:
    """How to regenerate a module from the file ``label`` (as its header names it): ``make derive`` for the
    package's models, ``knifeedge derive`` for a user's."""
    if label.startswith("derivation/") or label in EXAMPLE_MODELS:
        return "Run ``make derive`` to regenerate."
    return f"Run ``knifeedge derive {label} --out DIR`` to regenerate."


def hoist_parameters(exprs, params):
    """Replace the parameter-only subexpressions of ``exprs`` by symbols ``_k0, _k1, ...``.

    A subexpression is hoisted when it depends on parameters only and is
    more than a bare symbol or number; inside a sum or a product the
    parameter-only terms or factors are grouped and hoisted together
    (``4*D*g*theta/L**2`` -> ``_k0*theta``).  Returns ``(constants, new)``:
    the ``(symbol, expression)`` pairs in order of first appearance
    (a deterministic preorder walk of SymPy's canonical argument order) and
    the rewritten expressions.  Evaluating the constants once per
    integration and the rewritten expressions at every step gives the same
    values, computed with fewer operations per step.  Symbols whose
    ``hoistable`` is false (an input's slots) are never hoisted.
    """
    params = {x for x in params if getattr(x, "hoistable", True)}  # an input's slots vary in a run (input_slots)
    memo: dict = {}

    def const_symbol(e):
        if e.is_Atom:
            return e
        if e not in memo:
            memo[e] = names.Own(f"_k{len(memo)}")
        return memo[e]

    def walk(e):
        if e.is_Atom:
            return e
        if e.free_symbols <= params:
            return const_symbol(e)
        if e.is_Add or e.is_Mul:
            fixed = [a for a in e.args if a.free_symbols <= params]
            rest = [walk(a) for a in e.args if not a.free_symbols <= params]
            if len(fixed) > 1 or (fixed and not fixed[0].is_Atom):
                fixed = [const_symbol(e.func(*fixed))]
            return e.func(*fixed, *rest)
        return e.func(*[walk(a) for a in e.args])

    new = [walk(e) for e in exprs]
    return [(symbol, e) for e, symbol in memo.items()], new


def _wrapper(name: str, into: str, n: int, what: str) -> Function:
    """``name(t, s, p)``: ``into(t, s, p, ds)`` into a new array of length ``n``."""
    return Function(name, "t, s, p", f"Return {what} as a new array of length {n}.",
                    (f"    ds = np.empty({n})", f"    {into}(t, s, p, ds)", "    return ds"))


def rhs_functions(syms_state, syms_par, rates, syms_pose=(), pose_rates=(), solve=((), 0),
                  known=frozenset(), pose_solve=((), 0)) -> tuple:
    """The right-hand-side functions every generated module has, as :class:`Function` s.

    ``rhs_into(t, s, p, ds)`` and ``rhs(t, s, p)`` take the parameters;
    ``constants(p)`` returns ``q``: the parameters followed by the
    parameter-only subexpressions (:func:`hoist_parameters`), and
    ``rhs_q_into(t, s, q, ds)`` is the same right-hand side reading them
    from ``q``, which the compiled integrators call at every stage.  With a
    pose, ``rhs_pose_into``/``rhs_pose``/``rhs_pose_q_into`` likewise.
    ``solve``: lines (and their op count) that open every ``*_into`` body after its unpacking, binding the
    symbols ``known`` that ``rates`` may hold (the numeric elimination, :mod:`.kkt_emit`); ``pose_solve``, lines
    that follow them in the pose functions (binding the symbols of ``pose_rates``).
    """
    pre, pre_ops = list(solve[0]), solve[1]
    state, pose, params = [str(x) for x in syms_state], [str(x) for x in syms_pose], [str(x) for x in syms_par]
    n, npose = len(state), len(pose)
    allowed = set(syms_state) | set(syms_par) | {names.t} | set(known)
    constants, hoisted = hoist_parameters(list(rates) + list(pose_rates), syms_par)
    q_names = list(params) + [k for k, _ in constants]
    const_lines, const_ops = cse_block([v for _, v in constants], [f"q[{len(params) + i}]" for i in
                                                                   range(len(constants))], set(syms_par))
    allowed_q = set(syms_state) | set(syms_par) | {k for k, _ in constants} | {names.t} | set(known)
    nl = "\n"

    def into(name, key, what, exprs, ok, reads, arg, solved=((), 0)):
        lines, ops = cse_block(list(exprs), [f"ds[{i}]" for i in range(len(exprs))], ok)
        body = tuple(nl.join(group) for group in reads) + (nl.join(pre + list(solved[0]) + lines),)
        ops += pre_ops + solved[1]
        return Function(name, f"t, s, {arg}, ds", f"{what} ({ops} operations).", body, ops, key)

    s_lines, p_lines, q_lines = unpack(state, "s"), unpack(params, "p"), unpack(q_names, "q")
    out = [
        into("rhs_into", "rhs", "Write d(state)/dt into ``ds``", rates, allowed, (s_lines, p_lines), "p"),
        _wrapper("rhs", "rhs_into", n, "d(state)/dt"),
        Function("constants", "p", f"``q``: the parameters, then the {len(constants)} parameter-only "
                 f"subexpressions of the right-hand side ({const_ops} operations).",
                 (f"    q = np.empty({len(q_names)})", nl.join(p_lines),
                  nl.join(f"    q[{i}] = {names.identifier(x)}" for i, x in enumerate(params)),
                  nl.join(const_lines), "    return q"), const_ops),
        into("rhs_q_into", "rhs_q", "``rhs_into`` with ``q = constants(p)`` in place of ``p``", hoisted[:n],
             allowed_q, (s_lines, q_lines), "q"),
    ]
    if not npose:
        return tuple(out)
    pose_lines = unpack(pose, "s", start=n)
    return (*out,
            into("rhs_pose_into", "rhs_pose", "Write d(state, pose)/dt into ``ds``", list(rates) + list(pose_rates),
                 allowed | set(syms_pose), (s_lines, pose_lines, p_lines), "p", pose_solve),
            _wrapper("rhs_pose", "rhs_pose_into", n + npose, "d(state, pose)/dt"),
            into("rhs_pose_q_into", "rhs_pose_q", "``rhs_pose_into`` with ``q = constants(p)`` in place of ``p``",
                 hoisted, allowed_q | set(syms_pose), (s_lines, pose_lines, q_lines), "q", pose_solve))
