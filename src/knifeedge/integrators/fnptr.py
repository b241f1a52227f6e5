"""Calls through a function's address inside compiled code: one compiled integrator serves every model.

A model's compiled parts (:class:`.erk.AdaptiveKernel`) are passed to the shared integrator as machine addresses,
plain integers, and called with :func:`call_f8` / :func:`call_void`; so the integrator compiles once per method
and machine.  Arguments are ``float64`` or ``int64`` scalars, by value, and C-contiguous arrays, as the address
of their first element (the callee rebuilds them with ``numba.carray``).  The caller keeps the parts alive.
"""
import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.core import cgutils
from numba.extending import intrinsic


def _lower_args(context, builder, arg_types, values):
    """LLVM values and types of the arguments: scalars as they are, arrays as pointers to their data."""
    out, tys = [], []
    for ty, v in zip(arg_types, values):
        if isinstance(ty, types.Array):
            data = context.make_array(ty)(context, builder, v).data
            out.append(data)
            tys.append(data.type)
        elif isinstance(ty, (types.Float, types.Integer)):
            out.append(v)
            tys.append(context.get_value_type(ty))
        else:
            raise TypeError(f"fnptr: unsupported argument type {ty}")
    return out, tys


def _check(args):
    if not isinstance(args, types.BaseTuple):
        raise TypeError("fnptr: the arguments must be passed as one tuple")
    for ty in args:
        if isinstance(ty, types.Array) and ty.layout != "C":
            raise TypeError(f"fnptr: arrays must be C-contiguous, got {ty}")


def _call_through(args, returns):
    """The codegen of a call through an address, of the LLVM function type returning ``returns``."""
    def codegen(context, builder, signature, llargs):
        addr, tup = llargs
        values = cgutils.unpack_tuple(builder, tup, len(args))
        vals, tys = _lower_args(context, builder, args.types, values)
        fn = builder.inttoptr(addr, ir.FunctionType(returns, tys).as_pointer())
        out = builder.call(fn, vals)
        return out if returns != ir.VoidType() else context.get_dummy_value()

    return codegen


@intrinsic
def call_f8(typingctx, address, args):
    """``call_f8(address, (a, b, ...))``: call the ``double f(...)`` at ``address`` and return its value."""
    _check(args)
    return types.float64(address, args), _call_through(args, ir.DoubleType())


@intrinsic
def call_void(typingctx, address, args):
    """``call_void(address, (a, b, ...))``: call the ``void f(...)`` at ``address``."""
    _check(args)
    return types.none(address, args), _call_through(args, ir.VoidType())


@njit(cache=True, error_model="numpy")
def constants_at(address, p, nq):
    """``q`` (``nq`` values) from the ``void constants(double* p, double* q)`` at ``address``, and whether
    every value is finite (compiled once per machine: one function for every model's ``constants`` part)."""
    q = np.empty(nq)
    call_void(address, (p, q))
    for i in range(nq):
        if not np.isfinite(q[i]):
            return q, False
    return q, True
