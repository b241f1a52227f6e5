"""``knifeedge derive FILE.py --out DIR``: a user's models, from their own file to compiled modules.

The file defines ``MODEL``: one :class:`~knifeedge.derive.ModelSpec` or a
list of them.  Each model is derived at every fidelity that applies to it
(:data:`~knifeedge.derive.fidelities.FIDELITIES`), its symmetry is checked
at a random general pose, and the modules are written into ``DIR`` exactly as
``make derive`` writes the package's own (header, input hash, state and
parameter order, operation counts, deterministic bytes).  Load them with
``knifeedge.load(name, fidelity=..., path=DIR)``.

Errors name the user's file and line: a :class:`ModelSpecError` names the
line where the spec was built; an exception raised while running the file or
deriving a model names the deepest line of the user's file involved.
"""
from __future__ import annotations

import hashlib
import importlib.util
import sys
import traceback
from pathlib import Path

from . import emit, engine, models
from .engine import ModelSpec, ModelSpecError

ROOT = Path(__file__).resolve().parent.parent
#: model files of the source tree's examples/ derived into generated/ with the package's models (``make derive``)
EXAMPLE_MODELS = ("examples/rolling_disk.py",)


class DeriveError(ValueError):
    """A user's model file could not be derived; the message names the file and line."""


def _user_line(exc: BaseException, path: Path) -> str:
    """``file:line`` of the deepest frame of ``exc`` in ``path`` (or just the file)."""
    where = str(path)
    for frame in traceback.extract_tb(exc.__traceback__):
        if Path(frame.filename).resolve() == path.resolve():
            where = f"{path}:{frame.lineno}"
    return where


def load_specs(path: str | Path) -> list:
    """Run the file ``path`` and return its ``MODEL`` as a list of :class:`ModelSpec`."""
    path = Path(path)
    if not path.is_file():
        raise DeriveError(f"model file {str(path)!r} does not exist")
    name = f"knifeedge_user_spec_{path.stem}"
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None:
        raise DeriveError(f"{path} is not a Python file")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except ModelSpecError as exc:
        raise DeriveError(str(exc)) from None
    except Exception as exc:  # noqa: BLE001 -- reported with the user's line
        raise DeriveError(f"{_user_line(exc, path)}: running the model file failed: "
                          f"{type(exc).__name__}: {exc}") from None
    finally:
        sys.modules.pop(name, None)
    if not hasattr(module, "MODEL"):
        raise DeriveError(f"{path} defines no `MODEL` (a knifeedge.derive.ModelSpec or RigidBody, or a list of them)")
    models = module.MODEL if isinstance(module.MODEL, (list, tuple)) else [module.MODEL]
    from .rigid import RigidBody

    bad = [type(m).__name__ for m in models if not isinstance(m, (ModelSpec, RigidBody))]
    if bad or not models:
        raise DeriveError(f"{path}: `MODEL` must be a ModelSpec or RigidBody, or a non-empty list of them, got "
                          f"{bad or 'an empty list'}")
    names = [m.name for m in models]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise DeriveError(f"{path}: several models are named {dup}")
    return list(models)


def project_specs() -> list:
    """The package's models (:data:`~knifeedge.derive.models.MODELS`) and the source tree's example models present."""
    from .rigid_models import MODELS as RIGID_MODELS

    specs = list(models.MODELS.values()) + [RIGID_MODELS[k] for k in sorted(RIGID_MODELS)]
    return specs + [s for f in EXAMPLE_MODELS if (ROOT / f).is_file() for s in load_specs(ROOT / f)]


#: the file ``make derive`` writes beside the generated modules: what they were derived from, and what was written
MANIFEST = "MANIFEST.sha256"


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def manifest_text(generated: Path, root: Path = ROOT) -> str:
    """The manifest of the folder ``generated`` derived from the source tree ``root``.

    One line per file, as ``sha256sum`` writes them (``sha256sum -c`` checks it from ``root``): every source
    of the derivation (``derivation/*.py``, the example models of :data:`EXAMPLE_MODELS`), then every generated
    module; the first line names the SymPy version.  A derivation source changed since ``make derive``, or a
    generated module edited by hand, no longer matches its line (:func:`manifest_mismatches`); this check reads
    files only, where the full one (``make check-generated``) derives everything again.
    """
    import sympy

    sources = sorted((root / "derivation").glob("*.py")) + [root / f for f in EXAMPLE_MODELS if (root / f).is_file()]
    written = sorted(generated.glob("*.py"))
    lines = [f"# sympy {sympy.__version__}"]
    lines += [f"{_sha256(f)}  {f.relative_to(root).as_posix()}" for f in sources]
    lines += [f"{_sha256(f)}  generated/{f.name}" for f in written]
    return "\n".join(lines) + "\n"


def manifest_mismatches(generated: Path, root: Path = ROOT) -> list:
    """What differs between ``generated``'s manifest and the files it names now (empty: nothing does)."""
    path = generated / MANIFEST
    if not path.is_file():
        return [f"{path} is missing"]

    def entries(text: str) -> dict:
        out = {}
        for line in text.splitlines():
            digest, _, name = line.partition("  ")
            out[name or digest] = digest if name else ""
        return out

    recorded, now = entries(path.read_text()), entries(manifest_text(generated, root))
    problems = []
    for name in sorted(set(recorded) | set(now)):
        if name not in now:
            problems.append(f"{name}: named by the manifest, absent now")
        elif name not in recorded:
            problems.append(f"{name}: present, not in the manifest")
        elif recorded[name] != now[name]:
            problems.append(f"{name}: changed since the manifest was written")
    return problems


def derive_specs(specs, check: bool = True, log=None) -> dict:
    """Derive ``specs`` at every fidelity: ``{(name, fidelity): system}``; errors name the spec's file and line."""
    out = {}
    for spec in specs:
        if log:
            log(f"deriving {spec.name} ({spec.defined_at if isinstance(spec, ModelSpec) else spec.source})")
        try:
            systems = emit.build(spec)
            if check and isinstance(spec, ModelSpec):
                engine.check_symmetry(systems[(spec.name, "full")])
        except ModelSpecError as exc:
            raise DeriveError(str(exc)) from None
        except Exception as exc:  # noqa: BLE001 -- reported with the spec's line
            if not isinstance(spec, ModelSpec):
                raise DeriveError(f"{spec.name} ({spec.source}): the derivation failed: {type(exc).__name__}: {exc}") \
                    from None
            raise DeriveError(spec.error_message(f"the derivation failed: {type(exc).__name__}: {exc}")) from None
        out.update(systems)
    return out


def derive_files(files, out: str | Path, check: bool = True, log=None) -> list:
    """Derive the models of ``files`` into the folder ``out``; returns the paths written."""
    specs = [s for f in files for s in load_specs(f)]
    names = [s.name for s in specs]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise DeriveError(f"several models are named {dup} across {', '.join(map(str, files))}")
    systems = derive_specs(specs, check=check, log=log)
    return emit.write_all(Path(out), systems, registry=False)
