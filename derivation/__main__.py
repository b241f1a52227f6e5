"""``python -m knifeedge.derive [--out DIR] [FILE.py ...]``: derive every model and write the generated modules.

Without files: the package's models (:data:`knifeedge.derive.models.MODELS`)
and the example models of the source tree (``cli.EXAMPLE_MODELS``, those
present), with the package registry, into ``generated/`` (``make derive``).
With files: only the models they define (``MODEL``), as ``knifeedge derive``.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from .cli import ROOT, DeriveError, derive_specs, load_specs, project_specs
from .emit import write_all


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m knifeedge.derive", description=__doc__)
    parser.add_argument("--out", type=Path, default=ROOT / "generated",
                        help="output folder (default: the project's generated/)")
    parser.add_argument("files", nargs="*", type=Path, help="model files defining MODEL (default: the package's)")
    args = parser.parse_args(argv)
    start = time.perf_counter()
    if args.files:
        specs = [s for f in args.files for s in load_specs(f)]
    else:
        specs = project_specs()
    systems = derive_specs(specs, check=bool(args.files), log=lambda s: print(s, file=sys.stderr))
    for path in write_all(args.out, systems, registry=not args.files):
        print(f"wrote {path}", file=sys.stderr)
    print(f"done in {time.perf_counter() - start:.1f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    try:
        raise SystemExit(main())
    except DeriveError as exc:
        print(f"python -m knifeedge.derive: error: {exc}", file=sys.stderr)
        raise SystemExit(2) from None
