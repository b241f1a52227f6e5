"""How an integration ended: an enumeration whose values are the user-facing messages.

The compiled kernels return the integer :attr:`Status.code`; :func:`from_code`
maps it back.  Zero is success, negative codes are failures (the integration
stopped there and its arrays end at the last accepted step).
"""
from __future__ import annotations

import enum


class Status(enum.Enum):
    SUCCESS = "The solver successfully reached the end of the integration interval."
    STEP_SIZE_UNDERFLOW = (
        "The step size fell below the resolution of t (10 ulps): the requested accuracy cannot be met. "
        "Loosen `rtol`/`atol`, or check the state for a singularity."
    )
    MAX_STEPS = "The maximum number of solver steps was reached. Try increasing `max_steps`."
    NON_FINITE = (
        "The state became non-finite (overflow or NaN); the step was not accepted. "
        "For a fixed-step method reduce `h`."
    )
    IMPLICIT_NOT_CONVERGED = (
        "The implicit stage equations did not converge (fixed-point iteration diverged or stalled). Reduce `h`."
    )

    @property
    def code(self) -> int:
        return _CODES[self]

    @property
    def success(self) -> bool:
        return self is Status.SUCCESS


_CODES = {
    Status.SUCCESS: 0,
    Status.STEP_SIZE_UNDERFLOW: -1,
    Status.MAX_STEPS: -2,
    Status.NON_FINITE: -3,
    Status.IMPLICIT_NOT_CONVERGED: -4,
}
_BY_CODE = {v: k for k, v in _CODES.items()}


def from_code(code: int) -> Status:
    """The :class:`Status` of a kernel's integer return code."""
    return _BY_CODE[int(code)]
