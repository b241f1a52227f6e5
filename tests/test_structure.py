"""The structure issue 25 asks for: one-way imports, short functions, no source written under integrators/.

Measured on the files by ``benchmarks/structure.py`` (``python -m benchmarks.structure`` prints the numbers).
The allow-lists below only shrink: an entry that no longer applies fails its test, so that it is removed.
"""
import pytest

from benchmarks import structure

#: imports of the integrators that still close a cycle: none since the integrators' rework (issue 25 item 1);
#: not to be added to.
INTEGRATOR_CYCLE_IMPORTS: set = set()

#: functions over 80 lines still allowed (``path:qualified name``): shrink this list, never grow it
LONG_FUNCTIONS_ALLOWED = {
    # the two kernels' loops, written out (their per-step blocks as functions cost 1.5-4x per evaluation:
    # numba counts the references of every array passed at every step)
    "src/knifeedge/integrators/erk.py:_driver_closure.solve",
    "src/knifeedge/integrators/fixed.py:_solve_closure.solve",
}


#: one worker parses the tree for the checks that read the import graph or the long functions (~2 s of CPU each
#: time); six checks, no more than the groups that compile DOP853 and the Lyapunov loop (xdist sends the largest
#: groups first, ties in the order collected)
STRUCTURE = pytest.mark.xdist_group("structure")


@pytest.fixture(scope="module")
def graph():
    return structure.graph()


@pytest.fixture(scope="module")
def long_functions():
    """The long functions, measured once per worker for the two checks that read them."""
    return {f"{f.path}:{f.name}" for f in structure.long_functions()}


def test_the_checker_sees_imports_inside_functions_and_cycles(tmp_path):
    """A cycle closed by an import inside a function, a relative import and a name of a package's __init__."""
    pkg = tmp_path / "derivation"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("from .a import f\n")
    (pkg / "a.py").write_text("def f():\n    from . import b\n    return b\n")
    (pkg / "b.py").write_text("from .c import g\n")
    (pkg / "c.py").write_text("from . import f\n")  # the package's __init__, which imports a
    (tmp_path / "src" / "knifeedge").mkdir(parents=True)
    (tmp_path / "generated").mkdir()
    edges = structure.graph(tmp_path)
    assert edges["knifeedge.derive.a"] == {"knifeedge.derive.b"}
    assert edges["knifeedge.derive.c"] == {"knifeedge.derive"}
    assert structure.cycles(edges) == [("knifeedge.derive", "knifeedge.derive.a", "knifeedge.derive.b",
                                        "knifeedge.derive.c")]
    (pkg / "c.py").write_text("import math\n")
    assert structure.cycles(structure.graph(tmp_path)) == []


@STRUCTURE
def test_no_import_cycles_but_the_integrators_listed(graph):
    """derivation -> generated -> models -> integrators -> simulate -> sweep/scenes/... -> cli: no cycle anywhere
    (imports inside functions count), once the integrators' listed imports are left out."""
    rest = {m: {t for t in targets if (m, t) not in INTEGRATOR_CYCLE_IMPORTS} for m, targets in graph.items()}
    assert structure.cycles(rest) == []


@STRUCTURE
def test_imports_follow_the_layers(graph):
    """derivation -> generated -> models -> integrators -> simulate -> sweep/scenes/figures/animation -> cli: a
    module imports nothing of a higher layer (but the integrators' listed imports)."""
    assert [e for e in structure.upward_imports(graph) if e not in INTEGRATOR_CYCLE_IMPORTS] == []
    assert structure.upward_imports({"knifeedge.models": {"knifeedge.simulate", "knifeedge.generated.x"}}) == [
        ("knifeedge.models", "knifeedge.simulate")]
    with pytest.raises(ValueError, match="no layer"):
        structure.layer("knifeedge.newcomer")


@STRUCTURE
def test_the_listed_integrator_imports_still_exist(graph):
    """An import of INTEGRATOR_CYCLE_IMPORTS that is gone is removed from the list (the list only shrinks)."""
    gone = [edge for edge in sorted(INTEGRATOR_CYCLE_IMPORTS) if edge[1] not in graph.get(edge[0], ())]
    assert gone == [], f"remove {gone} from INTEGRATOR_CYCLE_IMPORTS"


@STRUCTURE
def test_the_derivation_has_no_import_cycle(graph):
    derive = {m: {t for t in ts if t.startswith("knifeedge.derive")} for m, ts in graph.items()
              if m.startswith("knifeedge.derive")}
    assert structure.cycles(derive) == []
    runtime = [(m, t) for m, ts in graph.items() if not m.startswith(("knifeedge.derive", "knifeedge.cli"))
               for t in ts if t.startswith("knifeedge.derive")]
    assert runtime == [], "the runtime imports the derivation (SymPy)"


@STRUCTURE
def test_no_new_function_over_80_lines(long_functions):
    assert sorted(long_functions - LONG_FUNCTIONS_ALLOWED) == [], "split them by meaning (or keep them under 80 lines)"


@STRUCTURE
def test_the_long_functions_allowed_are_still_long(long_functions):
    """A function of LONG_FUNCTIONS_ALLOWED that was shortened (or removed) leaves the list."""
    assert sorted(LONG_FUNCTIONS_ALLOWED - long_functions) == [], "remove them from LONG_FUNCTIONS_ALLOWED"


def test_the_checker_counts_nested_functions_and_methods(tmp_path):
    (tmp_path / "derivation").mkdir()
    (tmp_path / "src" / "knifeedge").mkdir(parents=True)
    body = "".join(f"        x{i} = {i}\n" for i in range(85))  # 85 lines in a nested block
    doc = "    lines\n" * 80
    (tmp_path / "derivation" / "m.py").write_text(
        f"def short():\n    return 1\n\n\nclass A:\n    def long(self):\n{body}\n\n"
        f"def outer():\n    def inner():\n{body}    return inner\n\n\n"
        f"def documented():\n    \"\"\"Many\n{doc}    \"\"\"\n    return 1\n")
    found = {f"{f.name}": f.lines for f in structure.long_functions(tmp_path)}
    # a docstring does not count, nor a nested function in the function that defines it (counted once, itself)
    assert found == {"A.long": 86, "outer.inner": 86}


def test_the_integrators_neither_parse_nor_write_source():
    """Issue 25 item 2: the kernels are numba closures over a method's and a model's constants; nothing under
    integrators/ writes, imports or parses source (only numba's compiled code is cached)."""
    assert structure.writes_or_parses_source() == []


def test_the_source_check_sees_ast_and_written_modules(tmp_path):
    folder = tmp_path / "src" / "knifeedge" / "integrators"
    folder.mkdir(parents=True)
    (folder / "a.py").write_text('"""Reads x.py."""\nimport ast\n')
    (folder / "b.py").write_text('def w(p, stem):\n    (p / f"{stem}.py").write_text("x = 1")\n')
    (folder / "c.py").write_text('"""Mentions erk.py only."""\ndef r(p):\n    return p.read_text()\n')
    (folder / "d.py").write_text("import importlib.util\ndef load(path):\n"
                                 "    spec = importlib.util.spec_from_file_location('k', path)\n"
                                 "    return importlib.util.module_from_spec(spec)\n")
    (folder / "e.py").write_text("def run(text):\n    exec(text, {})\n")
    assert structure.writes_or_parses_source(tmp_path) == [
        "src/knifeedge/integrators/a.py: imports ast", "src/knifeedge/integrators/b.py: writes .py files",
        "src/knifeedge/integrators/d.py: imports or runs source from a file or a string",
        "src/knifeedge/integrators/e.py: imports or runs source from a file or a string"]
