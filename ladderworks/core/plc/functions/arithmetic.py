"""Arithmetic: ADD/SUB/MUL/DIV (BCD), ADDB/SUBB/MULB/DIVB (signed binary), NUME, NUMEB."""

from __future__ import annotations

from collections.abc import Callable

from ladderworks.core.address import Address
from ladderworks.core.instructions import FUNCTIONS, InstructionSpec, Operation
from ladderworks.core.plc.bcd import bcd_limit
from ladderworks.core.plc.functions import (
    FLAG_OVERFLOW,
    REMAINDER_REGISTER,
    FunctionContext,
    function,
    held_output,
    output,
    result_flags,
    signed_range,
)


def truncated_division(a: int, b: int) -> tuple[int, int]:
    """Quotient rounded toward zero and the remainder with the dividend's sign (b != 0)."""
    quotient = abs(a) // abs(b)
    if (a < 0) != (b < 0):
        quotient = -quotient
    return quotient, a - quotient * b


# (a, b) -> result, or None when the operation is an error (divide by zero).
_OPERATIONS: dict[Operation, Callable[[int, int], int | None]] = {
    Operation.ADD: lambda a, b: a + b,
    Operation.SUBTRACT: lambda a, b: a - b,
    Operation.MULTIPLY: lambda a, b: a * b,
    Operation.DIVIDE: lambda a, b: truncated_division(a, b)[0] if b else None,
}


def _bcd_arithmetic(spec: InstructionSpec) -> None:
    compute = _OPERATIONS[spec.operation]

    @function(spec.name)
    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        byt, rst, act = inputs
        held = held_output(state, rst, act)
        if held is not None:
            return held
        _, a_at, b, result_at = params
        width = 2 if byt else 1
        a = ctx.memory.read_bcd(a_at, width)
        if isinstance(b, Address):
            b = ctx.memory.read_bcd(b, width)
        elif not 0 <= b <= bcd_limit(width):
            b = None
        if a is None or b is None:
            return output(state, True)
        result = compute(a, b)
        if result is None:
            return output(state, True)
        return output(state, not ctx.memory.write_bcd(result_at, result, width))

    impl.__name__ = spec.name.lower()
    impl.__doc__ = f"BCD {spec.name}: 2 (BYT=0) or 4 digits; W1 = 1 on error, result kept."


def _binary_arithmetic(spec: InstructionSpec) -> None:
    compute = _OPERATIONS[spec.operation]
    keeps_remainder = spec.operation is Operation.DIVIDE

    @function(spec.name)
    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        rst, act = inputs
        held = held_output(state, rst, act)
        if held is not None:
            return held
        fmt, a_at, b, result_at = params
        width = fmt % 10
        a = ctx.memory.read(a_at, width, signed=True)
        if isinstance(b, Address):
            b = ctx.memory.read(b, width, signed=True)
        result = compute(a, b)
        lo, hi = signed_range(width)
        if result is None or not lo <= result <= hi:
            ctx.set_result_register(FLAG_OVERFLOW, 1)
            return output(state, True)
        ctx.memory.write(result_at, result, width)
        ctx.set_result_register(result_flags(result), 1)
        if keeps_remainder:
            ctx.memory.write(REMAINDER_REGISTER, truncated_division(a, b)[1], width)
        return output(state, False)

    impl.__name__ = spec.name.lower()
    impl.__doc__ = f"Signed binary {spec.name}: 1/2/4 bytes, R9000 flags; W1 = 1 on error."


for _spec in FUNCTIONS:  # each row with an operation, in its encoding
    if _spec.operation is not Operation.NONE:
        (_binary_arithmetic if _spec.binary else _bcd_arithmetic)(_spec)


@function("NUME")
def nume(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Write a BCD constant (2 digits with BYT=0, 4 with BYT=1); one that does not fit: nothing."""
    byt, act = inputs
    if act:
        constant, target = params
        ctx.memory.write_bcd(target, constant, 2 if byt else 1)
    return False


@function("NUMEB")
def numeb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Write a binary constant of 1/2/4 bytes; one outside the width's range: nothing."""
    (act,) = inputs
    if act:
        width, constant, target = params
        lo, _ = signed_range(width)
        if lo <= constant < 1 << (8 * width):
            ctx.memory.write(target, constant, width)
    return False
