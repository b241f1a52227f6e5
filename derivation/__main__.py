"""``python -m derivation [--out DIR]``: derive every model and write the generated modules."""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from .emit import build_all, write_all


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m derivation", description=__doc__)
    parser.add_argument("--out", type=Path, default=Path(__file__).resolve().parent.parent / "generated",
                        help="output folder (default: the project's generated/)")
    args = parser.parse_args(argv)
    start = time.perf_counter()
    systems = build_all()
    for (name, fidelity) in sorted(systems):
        print(f"derived {name} ({fidelity})", file=sys.stderr)
    for path in write_all(args.out, systems):
        print(f"wrote {path}", file=sys.stderr)
    print(f"done in {time.perf_counter() - start:.1f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
