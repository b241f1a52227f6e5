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

from knifeedge import modulecheck

from . import emit, engine, models
from .codegen import EXAMPLE_MODELS, USER_MODULE_PREFIX  # the example models of make derive; a user file's module
from .engine import ModelSpec, ModelSpecError

ROOT = Path(__file__).resolve().parent.parent


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
    name = f"{USER_MODULE_PREFIX}{path.stem}"
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None:
        raise DeriveError(f"{path} is not a Python file")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except ModelSpecError as exc:
        raise DeriveError(str(exc)) from None
    except SystemExit as exc:  # the file's own exit is not the end of `knifeedge derive`, nor a success
        raise DeriveError(f"{_user_line(exc, path)}: the model file called sys.exit({exc.code!r}) while it ran: "
                          f"nothing was derived; a model file defines MODEL and must not exit") from None
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


def _package_folders() -> set:
    """The package's own folders (``knifeedge``, its ``generated/`` and ``derive/``, as installed and in the source
    tree), resolved."""
    folders = {ROOT / "generated", ROOT / "derivation", ROOT / "src" / "knifeedge"}
    for name in ("knifeedge", "knifeedge.generated", "knifeedge.derive"):
        found = importlib.util.find_spec(name)
        folders |= {Path(f) for f in (found.submodule_search_locations or ())} if found is not None else set()
    return {f.resolve() for f in folders}


def written_by_knifeedge(path: Path) -> bool:
    """True if the file ``path`` is a module knifeedge wrote and nobody changed since (or one an older knifeedge
    wrote, before modules carried ``MODULE_SHA256``)."""
    data = path.read_bytes()
    if modulecheck.sealed_ok(data):
        return True
    head = data[:600]
    return (head.startswith(b'"""') and b"GENERATED FILE -- DO NOT EDIT BY HAND." in head
            and b"\nINPUT_HASH = " in data and b"\nMODULE_SHA256 = " not in data)


def check_out(out: Path, keys) -> None:
    """Refuse to write the modules ``keys`` ((name, fidelity) pairs) into the package's own ``generated/`` or over
    a file knifeedge did not write; nothing is written when one of them is refused."""
    out, package = Path(out), _package_folders()
    if any(f == out.resolve() or f in out.resolve().parents for f in package):
        raise DeriveError(f"--out {out} is inside the package's own folders (its generated/ folder holds the "
                          f"built-in models, which only `make derive` writes); choose a folder of your own "
                          f"(e.g. --out my_models)")
    for key in keys:
        try:
            path = emit.module_path(out, *key)
        except ValueError as exc:
            raise DeriveError(str(exc)) from None
        if path.is_symlink() or (path.exists() and not (path.is_file() and written_by_knifeedge(path))):
            raise DeriveError(f"{path} exists and is not a module knifeedge wrote (or it was edited since): not "
                              f"overwritten. Move it away or delete it, or choose another --out")


def derive_files(files, out: str | Path, check: bool = True, log=None) -> list:
    """Derive the models of ``files`` into the folder ``out``; returns the paths written.

    Refuses (:func:`check_out`) the package's own ``generated/`` and files of ``out`` knifeedge did not write.
    """
    specs = [s for f in files for s in load_specs(f)]
    names = [s.name for s in specs]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise DeriveError(f"several models are named {dup} across {', '.join(map(str, files))}")
    check_out(Path(out), [])
    systems = derive_specs(specs, check=check, log=log)
    check_out(Path(out), systems)
    return emit.write_all(Path(out), systems, registry=False)
