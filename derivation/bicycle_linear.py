"""The Whipple bicycle's lean/steer equations about straight running, by machine from the nonlinear bicycle.

``make bicycle-linear`` (``python -m knifeedge.derive.bicycle_linear``) writes ``generated/linear/whipple_bicycle.py``:
the matrices ``A0, A1, A2`` of

    d/dt (lean, steer, lean rate, steer rate) = (A0 + v A1 + v^2 A2) (lean, steer, lean rate, steer rate)

at the benchmark's parameters.  They are not typed in: the nonlinear bicycle of ``tests/models/whipple_bicycle.py``
(SymPy's test_kane3 bicycle through :func:`~.mechanics.from_mechanics`, numeric elimination of the multipliers)
is derived, and its generated exact Jacobian is evaluated at straight running (``STEADY_FAMILIES``,
``straight_running``) at the speeds :data:`SPEEDS`; the lean/steer block of each is ``A(v)``.  The benchmark's
linearized equations ``M q'' + v C1 q' + (g K0 + v^2 K2) q = 0`` (Meijaard, Papadopoulos, Ruina & Schwab 2007,
*Proc. R. Soc. A* 463, eq. (A 1)) make ``A(v)`` a quadratic polynomial in ``v``, so three speeds give the
coefficients exactly (to rounding); the module records how far ``A(v)`` at :data:`CHECK_SPEEDS` is from the
polynomial (``FIT_RESIDUAL``), and the writer refuses a fit worse than :data:`FIT_TOLERANCE`.

The Jacobian is evaluated in a child process with numba's JIT off (``NUMBA_DISABLE_JIT=1``): its first
compilation costs about two minutes, a few evaluations in Python a fraction of a second.  The bicycle's
derivation takes about 25 s of CPU, so this is a target of its own and not part of ``make derive``;
``python -m knifeedge.derive.bicycle_linear --check`` (``make check-bicycle-linear``) derives into a temporary
folder and fails with a diff if the checked-in module differs.  The module's ``INPUT_HASH`` is the SHA-256 of the
model file, of this file and of the derivation's sources that make the Jacobian (:data:`PIPELINE`; the tests
compare it without deriving).
"""
from __future__ import annotations

import argparse
import difflib
import hashlib
import json
import os
import subprocess
import sys
import tempfile
from fractions import Fraction
from pathlib import Path

import sympy as sp

from knifeedge.modulecheck import seal

from .codegen import const

ROOT = Path(__file__).resolve().parents[1]
#: the nonlinear bicycle (SymPy's test_kane3 bicycle with the coordinates a Lagrangian needs)
MODEL_FILE = "tests/models/whipple_bicycle.py"
#: where the module is written (the package ``knifeedge.generated.linear``)
OUT = ROOT / "generated" / "linear" / "whipple_bicycle.py"
#: the lean/steer states of the nonlinear bicycle, in the order of the linear state
LEAN_STEER = ("q2", "q5", "q2_dot", "q5_dot")
#: forward speeds [m/s] whose Jacobians give the three coefficients
SPEEDS = (0.0, 1.0, 2.0)
#: forward speeds [m/s] where the polynomial is compared with the Jacobian
CHECK_SPEEDS = (5.0, 10.0)
#: the largest accepted difference between ``A(v)`` and the polynomial at :data:`CHECK_SPEEDS`
FIT_TOLERANCE = 1e-10

PACKAGE_DOC = '''"""Linear models obtained by machine from derived nonlinear ones (``derivation/bicycle_linear.py``).

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make bicycle-linear`` to regenerate.
"""
'''

_EVALUATE = r"""
import importlib.util, json, sys
import numpy as np
path, names, speeds = sys.argv[1], json.loads(sys.argv[2]), json.loads(sys.argv[3])
spec = importlib.util.spec_from_file_location("whipple_bicycle_full", path)
m = importlib.util.module_from_spec(spec)
spec.loader.exec_module(m)
p = np.array([m.DEFAULT_PARAMS[n] for n in m.PARAM_NAMES], dtype=float)
k = list(m.STEADY_FAMILIES).index("straight_running")
keep = [list(m.STATE_NAMES).index(n) for n in names]
out = []
for v in speeds:
    y = np.asarray(m.steady_state(k, v, p)[0], dtype=float)
    out.append(np.asarray(m.jacobian(y, p), dtype=float)[np.ix_(keep, keep)].tolist())
print(json.dumps(out))
"""


#: the derivation's sources that make the bicycle's generated Jacobian and its steady state, beside this file (a
#: change in any of them may move the coefficients' last bits: the half-integer powers of kkt_emit did)
PIPELINE = ("mechanics.py", "engine.py", "kkt_emit.py", "jacobian.py", "codegen.py", "steady.py", "emit.py")


def input_hash(root: Path = ROOT) -> str:
    """SHA-256 of the model file, of this module's source and of the :data:`PIPELINE` sources (what the
    coefficients are made from)."""
    h = hashlib.sha256()
    for path in (root / MODEL_FILE, root / "derivation" / "bicycle_linear.py",
                 *(root / "derivation" / name for name in PIPELINE)):
        h.update(path.read_bytes())
    return h.hexdigest()


def jacobian_blocks(module_file: Path, speeds) -> list:
    """The lean/steer block of the generated Jacobian of the derived bicycle at straight running at each speed."""
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    done = subprocess.run([sys.executable, "-c", _EVALUATE, str(module_file), json.dumps(LEAN_STEER),
                           json.dumps(list(speeds))], check=True, capture_output=True, text=True, env=env)
    return json.loads(done.stdout)


def coefficients(blocks) -> tuple:
    """``(A0, A1, A2)`` from ``A(0), A(1), A(2)`` (lists of rows): ``A2 = (A(2) - 2 A(1) + A(0)) / 2``,
    ``A1 = A(1) - A0 - A2``."""
    a, b, c = ([[Fraction(x) for x in row] for row in m] for m in blocks)  # exact: one rounding, at the end
    a2 = [[(c[i][j] - 2 * b[i][j] + a[i][j]) / 2 for j in range(4)] for i in range(4)]
    a1 = [[b[i][j] - a[i][j] - a2[i][j] for j in range(4)] for i in range(4)]
    return tuple(tuple(tuple(float(x) for x in row) for row in m) for m in (a, a1, a2))


def fit_residual(coeffs, blocks, speeds) -> float:
    """Largest ``|A(v) - (A0 + v A1 + v^2 A2)|`` over ``speeds``."""
    a0, a1, a2 = coeffs
    return max(abs(blocks[k][i][j] - (a0[i][j] + v * a1[i][j] + v * v * a2[i][j]))
               for k, v in enumerate(speeds) for i in range(4) for j in range(4))


def derive_bicycle(out: Path) -> Path:
    """Derive the nonlinear bicycle into ``out``; returns its module's path."""
    from .cli import derive_files

    derive_files([ROOT / MODEL_FILE], out, log=lambda s: print(s, file=sys.stderr))
    return out / "whipple_bicycle_full.py"


def module_text(coeffs, residual: float, digest: str) -> str:
    """The sealed source of the linear module."""
    constants = (
        const("STATE_NAMES", LEAN_STEER, "the linear state: lean q2, steer q5 [rad], their rates [rad/s]"),
        const("SPEEDS", SPEEDS, "forward speeds [m/s] whose Jacobians gave the coefficients"),
        const("A0", coeffs[0], "A(v) = A0 + v A1 + v^2 A2 (rows: rates of STATE_NAMES; columns: STATE_NAMES)"),
        const("A1", coeffs[1]),
        const("A2", coeffs[2]),
        const("CHECK_SPEEDS", CHECK_SPEEDS),
        const("FIT_RESIDUAL", residual, "largest |A(v) - polynomial| at CHECK_SPEEDS (the polynomial is exact)"),
        const("INPUT_HASH", digest, f"SHA-256 of {MODEL_FILE}, derivation/bicycle_linear.py and its PIPELINE"),
        const("SYMPY_VERSION", sp.__version__),
    )
    text = f'''"""whipple_bicycle: the lean/steer equations about straight running, A(v) = A0 + v A1 + v^2 A2.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make bicycle-linear`` to regenerate.
Produced by derivation/bicycle_linear.py from {MODEL_FILE}: the lean/steer block of the derived bicycle's
generated Jacobian at straight running at v = {", ".join(f"{v:g}" for v in SPEEDS)} m/s, at the benchmark's
parameters (Meijaard et al. 2007, Table 1).  SymPy {sp.__version__}; input hash sha256:{digest}
"""
'''
    return seal(text + "\n".join(c.source() for c in constants) + "\n")


def build(work: Path) -> str:
    """Derive the bicycle in ``work``, evaluate its Jacobians and return the module's text."""
    blocks = jacobian_blocks(derive_bicycle(work), SPEEDS + CHECK_SPEEDS)
    coeffs = coefficients(blocks[:3])
    residual = fit_residual(coeffs, blocks[3:], CHECK_SPEEDS)
    if not residual <= FIT_TOLERANCE:
        raise RuntimeError(f"the bicycle's lean/steer Jacobian is not quadratic in the speed: it differs from the "
                           f"polynomial by {residual:.3g} at {CHECK_SPEEDS} m/s (tolerance {FIT_TOLERANCE:g})")
    return module_text(coeffs, residual, input_hash())


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m knifeedge.derive.bicycle_linear",
                                     description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true",
                        help=f"derive in a temporary folder and compare with {OUT.relative_to(ROOT)} (never written)")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        text = build(Path(tmp))
    if args.check:
        old = OUT.read_text() if OUT.is_file() else ""
        if old == text:
            print(f"{OUT.relative_to(ROOT)} matches a fresh derivation", file=sys.stderr)
            return 0
        sys.stderr.writelines(difflib.unified_diff(old.splitlines(True), text.splitlines(True), "checked in", "fresh"))
        print(f"{OUT.relative_to(ROOT)} is stale: run make bicycle-linear and commit", file=sys.stderr)
        return 1
    OUT.parent.mkdir(parents=True, exist_ok=True)
    (OUT.parent / "__init__.py").write_text(PACKAGE_DOC, encoding="utf-8")
    OUT.write_text(text, encoding="utf-8")
    print(f"wrote {OUT}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
