"""The one writer of generated modules (derivation/codegen.py): what a module must hold, and its text."""
import importlib.util
import math

import numpy as np
import pytest
import sympy as sp

from knifeedge.derive import codegen
from knifeedge.modulecheck import sealed_ok

x, v, a = sp.symbols("x v a", real=True)


def _parts(constants=None, digest="0" * 64):
    """A small module: the oscillator x'' = -a x^2 - sin(a), with its energy-like function."""
    body = (*codegen.rhs_functions([x, v], [a], [v, -a * x**2 - sp.sin(a)]),
            codegen.expression_function("energy", "s, p", "Energy", [v**2 / 2 + a * x**3 / 3], ["energy"],
                                        {x, v, a}, (codegen.unpack(["x", "v"], "s"), codegen.unpack(["a"], "p")),
                                        "energy"),
            "\n\n#: a text block\nEXTRA = 1\n")
    if constants is None:
        constants = tuple(codegen.Constant(name, "()") for name in codegen.REQUIRED_CONSTANTS
                          if name not in ("INPUT_HASH", "SYMPY_VERSION")) + codegen.provenance(digest)
    return codegen.ModuleParts(title="toy, fidelity full: a test.", hint="Run nothing.", produced="Produced here.",
                               digest=digest, doc="Toy.", constants=constants, body=body)


def test_a_module_without_the_metadata_the_runtime_reads_is_refused():
    with pytest.raises(ValueError, match="STATE_NAMES"):
        _parts(constants=(codegen.const("MODEL", "toy"), *codegen.provenance("0" * 64)))


def test_the_header_hash_and_input_hash_must_agree():
    parts = _parts()
    with pytest.raises(ValueError, match="INPUT_HASH"):
        codegen.ModuleParts(**{**parts.__dict__, "digest": "1" * 64})


def test_module_text_runs_and_computes_the_rates(tmp_path):
    """The written module's right-hand side, with and without the hoisted constants, against the closed form."""
    path = tmp_path / "toy_full.py"
    path.write_text(codegen.module_text(_parts()))
    spec = importlib.util.spec_from_file_location("toy_full", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    space = vars(module)
    s, p = np.array([0.3, -1.2]), np.array([1.7])
    want = [-1.2, -1.7 * 0.3**2 - math.sin(1.7)]
    ds = np.empty(2)
    space["rhs_into"].py_func(0.0, s, p, ds)
    assert ds.tolist() == pytest.approx(want, rel=1e-15)
    q = space["constants"].py_func(p)
    ds[:] = 0
    space["rhs_q_into"].py_func(0.0, s, q, ds)
    assert ds.tolist() == pytest.approx(want, rel=1e-15)
    assert space["energy"].py_func(s, p) == pytest.approx(1.2**2 / 2 + 1.7 * 0.3**3 / 3, rel=1e-15)
    assert space["EXTRA"] == 1


def test_op_counts_follow_the_counted_functions_in_body_order():
    parts = _parts()
    text = codegen.module_text(parts)
    assert list(parts.op_counts()) == ["rhs", "constants", "rhs_q", "energy"]  # rhs() itself is not counted
    assert f"OP_COUNTS = {parts.op_counts()!r}" in text
    assert f'"""Energy ({parts.op_counts()["energy"]} operations)."""' in text


def test_finish_seals_the_text():
    assert sealed_ok(codegen.finish(_parts()).encode())
