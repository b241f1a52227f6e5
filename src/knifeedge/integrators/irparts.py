"""A model's stages of a step and its interpolant: the method's LLVM IR written at derive time, compiled here.

``attempt`` and ``dense`` (:class:`.erk.AdaptiveKernel`) are the IR that ``make derive`` wrote into
``generated/stages.py`` (``derivation/stage_ir.py``, which documents it).  :func:`bound_module` binds its
right-hand side to the model's by renaming symbols with llvmlite (no text is written here): the model's
``LLVM_IR``, linked in so that LLVM inlines it into every stage, or else numba's compiled ``rhs`` part (a
right-hand side that writes a function input first, ``simulate.driven_model``).  LLVM alone compiles the result
(:func:`compile_library`: 0.1-0.3 s for the built-in models, 5-6 s for the Whipple bicycle's ~3,900 operations),
kept in one checked cache file per kernel and machine (:func:`cache_file`, :func:`write_parts`: a JSON line and
numba's two blobs, no pickle).
"""
from __future__ import annotations

import hashlib
import json
from pathlib import Path

import llvmlite
import llvmlite.binding as ll
import numba
from numba.core.compiler_lock import global_compiler_lock
from numba.core.registry import cpu_target

from .cache import discard, read_checked, write_checked
from .methods import erk_fingerprint

#: the version of the parts files (part of the cache key)
FORMAT = 6


def stages_ir(tableau: str) -> str:
    """The IR of the stages of the registered adaptive method ``tableau``, as ``make derive`` wrote it."""
    from ..generated import stages

    if tableau not in stages.IR:
        raise ValueError(f"the adaptive method {tableau!r} has no stages in generated/stages.py: register its tableau "
                         f"in knifeedge/integrators/methods.py and run make derive")
    if stages.TABLES[tableau] != erk_fingerprint(tableau):
        raise ValueError(f"generated/stages.py holds the stages of other tables than the registered {tableau!r}: "
                         f"run make derive")
    return stages.IR[tableau]


def _parsed(text: str, name: str):
    module = ll.parse_assembly(text)
    module.name = name
    return module


def bound_module(tableau: str, n: int, model, rhs_name: str, rhs_cfunc, names: tuple) -> tuple:
    """``(module, libraries)``: the stages of ``tableau`` with their right-hand side bound to ``model``'s
    ``rhs_name`` (its ``LLVM_IR`` linked in, else the symbol of ``rhs_cfunc()``, a ``numba.cfunc``, whose library
    is returned to be linked), the state size to the constant ``n`` (``stages.SIZES``; above
    ``stages.MAX_SIZE`` read from the argument), and their symbols renamed to ``names`` (:func:`symbols`).
    """
    from ..generated import stages

    module = _parsed(stages_ir(tableau), f"knifeedge_parts_{names[0]}")
    ir, libraries = getattr(model, "LLVM_IR", {}), []
    if rhs_name in ir:
        _link(module, ir[rhs_name], rhs_name, stages.RHS)
        module.get_function(stages.RHS).linkage = "internal"  # inlined, then dropped: no clash between libraries
    else:
        compiled = rhs_cfunc()
        native = compiled.native_name
        if not native.startswith("cfunc."):
            raise RuntimeError(f"unexpected symbol of a compiled C callback: {native!r}") from None
        module.get_function(stages.RHS).name = native[len("cfunc."):]
        libraries.append(compiled._library)
    if "constants" in ir:
        _link(module, ir["constants"], "constants", names[3])
    module.get_global_variable(stages.SIZE).name = f"{stages.SIZE}.{n if n <= stages.MAX_SIZE else 0}"
    module.link_in(_parsed(stages.SIZES, "sizes"))
    for variable in module.global_variables:
        if variable.name.startswith(stages.SIZE + "."):
            variable.linkage = "internal"
    for old, new in zip(stages.SYMBOLS, names):
        module.get_function(old).name = new
    module.verify()
    return module, libraries


def _link(module, text: str, name: str, symbol: str) -> None:
    """Link the IR ``text`` (a generated module's function ``name``, defined internal) into ``module`` as the
    external ``symbol``."""
    other = _parsed(text, symbol)
    function = other.get_function(name)
    function.name, function.linkage = symbol, "external"
    module.link_in(other)


def compile_library(module, name: str, link):
    """numba's code library of the parsed IR ``module`` with the libraries ``link`` (linked before optimization,
    so that their functions inline), finalized, its object code kept to be saved."""
    with global_compiler_lock:
        lib = _codegen().create_library(name)
        lib.enable_object_caching()
        lib.add_llvm_module(module)
        for other in link:
            lib.add_linking_library(other)
        lib.finalize()
    return lib


def _codegen():
    return cpu_target.target_context.codegen()


def _key() -> tuple:
    """What compiled parts depend on beside their IR: this module's format, numba, llvmlite and the machine."""
    return (FORMAT, numba.__version__, llvmlite.__version__, _codegen().magic_tuple())


def cache_file(kernel_path) -> Path:
    """Where the compiled parts of the kernel ``kernel_path`` (``AdaptiveKernel.path``) are kept on this
    machine: named after it and a hash of :func:`_key`."""
    path = Path(kernel_path)
    return path.with_name(f"{path.stem}.parts-{hashlib.sha256(repr(_key()).encode()).hexdigest()[:16]}.nbo")


def symbols(kernel_path) -> tuple:
    """The symbols of ``attempt``, ``dense``, ``rhs`` and ``constants`` (where the model carries its IR) in the
    parts of the kernel ``kernel_path``, unique per kernel."""
    stem = Path(kernel_path).stem
    return (f"knifeedge.attempt.{stem}", f"knifeedge.dense.{stem}", f"knifeedge.rhs.{stem}",
            f"knifeedge.constants.{stem}")


def _load(path: Path, names: tuple):
    """``(library, addresses)`` kept in ``path``, or None (a file that cannot be used is discarded)."""
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


def load_or_compile(kernel_path, tableau: str, n: int, model, rhs_name: str, rhs_cfunc) -> tuple:
    """``(library, addresses)`` of the parts of the kernel ``kernel_path``, loaded from :func:`cache_file`, or
    compiled from :func:`bound_module` and saved there; ``addresses`` are those of :func:`symbols` (0 for
    ``constants`` where the model has no IR of it).  A file that cannot be read is discarded and compiled again.
    """
    path = cache_file(kernel_path)
    names = symbols(kernel_path)
    loaded = _load(path, names)
    if loaded is not None:
        return loaded
    with global_compiler_lock:
        module, link = bound_module(tableau, n, model, rhs_name, rhs_cfunc, names)
        lib = compile_library(module, f"knifeedge_parts_{Path(kernel_path).stem}", link)
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
