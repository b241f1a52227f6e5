"""``python -m knifeedge.derive [--out DIR] [FILE.py ...]``: derive every model and write the generated modules.

Without files: the package's models (:data:`knifeedge.derive.models.MODELS`)
and the example models of the source tree (``cli.EXAMPLE_MODELS``, those
present), with the package registry, into ``generated/`` (``make derive``).
With files: only the models they define (``MODEL``), as ``knifeedge derive``.
"""
from __future__ import annotations

import argparse
import difflib
import sys
import tempfile
import time
from pathlib import Path

from .cli import MANIFEST, ROOT, DeriveError, derive_files, derive_specs, manifest_text, project_specs
from .emit import write_all
from .stage_ir import write as write_stages


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m knifeedge.derive", description=__doc__)
    parser.add_argument("--out", type=Path, default=ROOT / "generated",
                        help="output folder (default: the project's generated/)")
    parser.add_argument("files", nargs="*", type=Path, help="model files defining MODEL (default: the package's)")
    parser.add_argument("--check", action="store_true",
                        help="derive into a temporary folder and compare it with --out (which is never written); "
                             "exit 1 with a diff if they differ")
    args = parser.parse_args(argv)
    if args.check:
        with tempfile.TemporaryDirectory() as tmp:
            status = main([*map(str, args.files), "--out", tmp])
            return status or compare(args.out, Path(tmp))
    start = time.perf_counter()
    log = lambda s: print(s, file=sys.stderr)  # noqa: E731
    if args.files:  # a user's models: as `knifeedge derive` (never into the package's generated/)
        written = derive_files(args.files, args.out, log=log)
    else:
        written = write_all(args.out, derive_specs(project_specs(), check=False, log=log))
        written.append(write_stages(args.out))  # the adaptive methods' stages as IR, for every model
    for path in written:
        print(f"wrote {path}", file=sys.stderr)
    if not args.files:  # the package's models: what they were derived from, checked by the tests without deriving
        manifest = args.out / MANIFEST
        manifest.write_text(manifest_text(args.out))
        print(f"wrote {manifest}", file=sys.stderr)
    print(f"done in {time.perf_counter() - start:.1f} s", file=sys.stderr)
    return 0


def compare(checked_in: Path, fresh: Path) -> int:
    """0 if the ``*.py`` files and the manifest of both folders are identical, else print a diff and the remedy and
    return 1."""
    old = {p.name: p for p in [*checked_in.glob("*.py"), checked_in / MANIFEST] if p.is_file()}
    new = {p.name: p for p in [*fresh.glob("*.py"), fresh / MANIFEST] if p.is_file()}
    problems = [f"only in {checked_in}: {n}" for n in sorted(set(old) - set(new))]
    problems += [f"missing from {checked_in}: {n}" for n in sorted(set(new) - set(old))]
    for name in sorted(set(old) & set(new)):
        a, b = old[name].read_text().splitlines(keepends=True), new[name].read_text().splitlines(keepends=True)
        if a != b:
            problems.append("".join(difflib.unified_diff(a, b, f"{checked_in.name}/{name}", f"fresh/{name}", n=1)))
    if not problems:
        print(f"{checked_in} matches a fresh derivation", file=sys.stderr)
        return 0
    print("\n".join(problems), file=sys.stderr)
    print(f"{checked_in} differs from a fresh derivation (a hand edit, or a stale derivation): "
          f"run make derive and commit", file=sys.stderr)
    return 1


if __name__ == "__main__":
    try:
        raise SystemExit(main())
    except DeriveError as exc:
        print(f"python -m knifeedge.derive: error: {exc}", file=sys.stderr)
        raise SystemExit(2) from None
