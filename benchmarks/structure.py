"""Structure of the source tree: the numbers issue 25 checks, measured on the files (nothing is imported).

``python -m benchmarks.structure`` prints the lines of ``src/knifeedge/integrators/``, the import cycles of
``derivation/`` (installed as ``knifeedge.derive``) and ``src/knifeedge/``, the functions over
:data:`LONG` lines, whether the integrators parse or write source code, and the README's size.

An import is any ``import``/``from ... import`` statement of the tree, inside functions too.  ``from pkg
import name`` depends on the module ``pkg.name`` when there is one, else on ``pkg`` (its ``__init__``);
importing a submodule is not counted as depending on its parent package's ``__init__``.  A cycle is a
strongly connected set of more than one module.
"""
from __future__ import annotations

import ast
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
#: folder -> the package name it is installed as
PACKAGES = {"src/knifeedge": "knifeedge", "derivation": "knifeedge.derive", "generated": "knifeedge.generated"}
#: the hand-written folders (whose functions are measured; generated/ is only part of the import graph)
SOURCES = ("src/knifeedge", "derivation")
#: a function longer than this (from its ``def`` line to its last line, without its docstring) counts as long
LONG = 80
INTEGRATORS = "src/knifeedge/integrators"


def modules(root: Path = ROOT, folders=tuple(PACKAGES)) -> dict:
    """``{module name: path}`` of every Python file of the ``folders`` of :data:`PACKAGES`."""
    out = {}
    for folder in folders:
        package = PACKAGES[folder]
        for path in sorted((root / folder).rglob("*.py")):
            parts = list(path.relative_to(root / folder).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            out[".".join([package, *parts])] = path
    return out


def _is_package(name: str, paths: dict) -> bool:
    return paths[name].name == "__init__.py"


def imports(name: str, paths: dict) -> set:
    """The modules of ``paths`` that the module ``name`` imports (anywhere in its file)."""
    tree = ast.parse(paths[name].read_text(encoding="utf-8"))
    here = name if _is_package(name, paths) else name.rpartition(".")[0]
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = here.split(".")
                anchor = anchor[:len(anchor) - node.level + 1]
                base = ".".join(anchor + ([base] if base else []))
            for alias in node.names:
                sub = f"{base}.{alias.name}"
                out.add(sub if sub in paths else base)
    return {m for m in out if m in paths and m != name}


def graph(root: Path = ROOT) -> dict:
    """``{module: set of modules it imports}`` over the tree."""
    paths = modules(root)
    return {name: imports(name, paths) for name in paths}


def cycles(edges: dict) -> list:
    """The strongly connected sets of more than one module (Tarjan), each sorted, sorted by their first name."""
    index, low, stack, on_stack, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1:
                out.append(tuple(sorted(group)))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return sorted(out)


#: the layers, lowest first (issue 25: derivation -> generated -> models -> integrators -> simulate ->
#: sweep/scenes/figures/animation -> cli), each a tuple of module-name prefixes; a module imports only modules
#: of its own layer or lower ones.  The first layer holds the runtime's helpers that the derivation shares
#: (the seal of a generated module, the checks of a rigid body's numbers, the registered methods' tables that
#: derivation/stage_ir.py writes the adaptive methods' stages from).
LAYERS = (
    ("knifeedge.modulecheck", "knifeedge.bodies", "knifeedge._validate", "knifeedge._process", "knifeedge._output",
     "knifeedge.integrators.methods"),
    ("knifeedge.derive",),
    ("knifeedge.generated",),
    ("knifeedge.models", "knifeedge.inputs"),
    ("knifeedge.integrators",),
    ("knifeedge.simulate", "knifeedge.runspec", "knifeedge.sections", "knifeedge.reversal", "knifeedge.stability",
     "knifeedge.lyapunov", "knifeedge.magnus", "knifeedge.background", "knifeedge.store"),
    ("knifeedge.sweep", "knifeedge.workers", "knifeedge.scenes", "knifeedge.figures", "knifeedge.animation"),
    ("knifeedge.cli", "knifeedge.__main__", "knifeedge"),
)


def layer(module: str) -> int:
    """The index in :data:`LAYERS` of ``module`` (by its longest matching prefix)."""
    best, found = -1, None
    for i, prefixes in enumerate(LAYERS):
        for p in prefixes:
            below = module.startswith(p + ".") and p != "knifeedge"  # the package's __init__ only, not all
            if (module == p or below) and len(p) > best:
                best, found = len(p), i
    if found is None:
        raise ValueError(f"module {module!r} is in no layer: add it to LAYERS in benchmarks/structure.py")
    return found


def upward_imports(edges: dict) -> list:
    """``(module, imported)`` pairs where a module imports one of a higher layer."""
    return sorted((m, t) for m, ts in edges.items() for t in ts if layer(t) > layer(m))


@dataclass(frozen=True)
class Function:
    path: str  # relative to the root
    name: str  # qualified: Class.method, outer.inner
    lines: int

    def __str__(self) -> str:
        return f"{self.path}:{self.name} ({self.lines} lines)"


def _docstring_lines(node) -> int:
    first = node.body[0]
    if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and isinstance(first.value.value, str):
        return first.end_lineno - first.lineno + 1
    return 0


def _nested_lines(node) -> int:
    """The lines of the functions and classes defined inside ``node`` (each counted once, in itself)."""
    n = 0
    for child in ast.iter_child_nodes(node):
        if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            n += child.end_lineno - child.lineno + 1
        else:
            n += _nested_lines(child)
    return n


def long_functions(root: Path = ROOT, limit: int = LONG) -> list:
    """Every function (methods and nested functions too) over ``limit`` lines, longest first.

    A function's lines: from its ``def`` to its last line, without its docstring (documentation is not length)
    and without the functions defined inside it (a factory's closure is counted once, as itself).
    """
    out = []
    for path in modules(root, SOURCES).values():
        rel = path.relative_to(root).as_posix()

        def walk(node, prefix):
            for child in ast.iter_child_nodes(node):
                if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                    name = prefix + child.name
                    if not isinstance(child, ast.ClassDef):
                        n = child.end_lineno - child.lineno + 1 - _docstring_lines(child) - _nested_lines(child)
                        if n > limit:
                            out.append(Function(rel, name, n))
                    walk(child, name + ".")
                else:
                    walk(child, prefix)

        walk(ast.parse(path.read_text(encoding="utf-8")), "")
    return sorted(out, key=lambda f: (-f.lines, f.path, f.name))


#: calls that import a module from a file or run source text
_LOADERS = ("spec_from_file_location", "exec_module", "module_from_spec", "SourceFileLoader", "import_module")


def writes_or_parses_source(root: Path = ROOT, folder: str = INTEGRATORS) -> list:
    """Files under ``folder`` that import ``ast`` (parse source), build a ``.py`` path and write files, or import
    modules from files (``importlib``'s loaders, ``exec``, ``compile``)."""
    out = []
    for path in sorted((root / folder).rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        rel = path.relative_to(root).as_posix()
        parses = any(isinstance(n, ast.Import) and any(a.name == "ast" for a in n.names)
                     or isinstance(n, ast.ImportFrom) and n.module == "ast" for n in ast.walk(tree))
        docstrings = {id(n.body[0].value) for n in ast.walk(tree)
                      if isinstance(n, (ast.Module, ast.FunctionDef, ast.ClassDef)) and n.body
                      and isinstance(n.body[0], ast.Expr) and isinstance(n.body[0].value, ast.Constant)}
        # a string that ends a path in ".py" (not a glob pattern read, not ".py" inside an f-string: "x.py311")
        inner = {id(v) for n in ast.walk(tree) if isinstance(n, ast.JoinedStr) for v in n.values[:-1]}
        py_path = any(isinstance(n, ast.Constant) and isinstance(n.value, str) and n.value.endswith(".py")
                      and "*" not in n.value and id(n) not in docstrings | inner for n in ast.walk(tree))
        writes = any(isinstance(n, ast.Call) and isinstance(n.func, ast.Attribute)
                     and n.func.attr in ("write_text", "write_bytes", "write") for n in ast.walk(tree))
        loads = any(isinstance(n, ast.Call) and (isinstance(n.func, ast.Attribute) and n.func.attr in _LOADERS
                                                 or isinstance(n.func, ast.Name) and n.func.id in ("exec", "compile"))
                    for n in ast.walk(tree))
        if parses:
            out.append(f"{rel}: imports ast")
        if py_path and writes:
            out.append(f"{rel}: writes .py files")
        if loads:
            out.append(f"{rel}: imports or runs source from a file or a string")
    return out


def lines_of(folder: Path) -> int:
    return sum(len(p.read_text(encoding="utf-8").splitlines()) for p in folder.rglob("*.py"))


def main() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    found = cycles(graph())
    long = long_functions()
    print(f"lines of {INTEGRATORS}/: {lines_of(ROOT / INTEGRATORS)}")
    print(f"import cycles: {len(found)}")
    for group in found:
        print("    " + " <-> ".join(group))
    upward = upward_imports(graph())
    print(f"imports against the layers (LAYERS): {len(upward)}")
    for m, t in upward:
        print(f"    {m} -> {t}")
    print(f"functions over {LONG} lines: {len(long)} "
          f"({sum(1 for f in long if not f.path.startswith(INTEGRATORS + '/'))} outside integrators/)")
    for f in long:
        print(f"    {f}")
    source = writes_or_parses_source()
    print(f"source parsed or written under {INTEGRATORS}: {len(source)}")
    for line in source:
        print(f"    {line}")
    print(f"README.md: {len(readme)} lines, longest {max(map(len, readme), default=0)} characters")


if __name__ == "__main__":
    main()
