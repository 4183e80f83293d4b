"""Comparison: COMP (BCD <=), COIN (BCD =), COMPB (binary, flags in R9000) and RNGB/RNGW/RNGD
(signed range check of 1/2/4 bytes)."""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.plc.bcd import bcd_limit
from ladderworks.core.plc.functions import (
    FLAG_NEGATIVE,
    FLAG_ZERO,
    FunctionContext,
    fits,
    function,
)
from ladderworks.core.plc.memory import Memory


def _bcd_operands(memory: Memory, byt: bool, value: int | Address,
                  compare: Address) -> tuple[int, int] | None:
    """The input (constant or BCD at an address) and the BCD comparison data; None if invalid."""
    width = 2 if byt else 1
    if isinstance(value, Address):
        first = memory.read_bcd(value, width)
    else:
        first = value if 0 <= value <= bcd_limit(width) else None
    second = memory.read_bcd(compare, width)
    if first is None or second is None:
        return None
    return first, second


@function("COMP")
def comp(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """W1 = 1 while ACT = 1 and input <= comparison data (BCD, 2 or 4 digits)."""
    byt, act = inputs
    if not act:
        return False
    _, value, compare = params
    operands = _bcd_operands(ctx.memory, byt, value, compare)
    return operands is not None and operands[0] <= operands[1]


@function("COIN")
def coin(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """W1 = 1 while ACT = 1 and input = comparison data (BCD, 2 or 4 digits)."""
    byt, act = inputs
    if not act:
        return False
    _, value, compare = params
    operands = _bcd_operands(ctx.memory, byt, value, compare)
    return operands is not None and operands[0] == operands[1]


@function("COMPB")
def compb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Signed binary compare: R9000.0 = (input = data), R9000.1 = (input < data)."""
    (act,) = inputs
    if act:
        fmt, value, compare = params
        width = fmt % 10
        first = ctx.memory.read(value, width, signed=True) if isinstance(value, Address) \
            else value
        second = ctx.memory.read(compare, width, signed=True)
        flags = (FLAG_ZERO if first == second else 0) | (FLAG_NEGATIVE if first < second else 0)
        ctx.set_result_register(flags, 1)
    return False


def _signed(memory: Memory, value: int | Address, width: int) -> int | None:
    """A signed value of `width` bytes: read from an address (None past the area's end) or a
    constant wrapped to the width (65535 in 2 bytes is -1)."""
    if isinstance(value, Address):
        return memory.read(value, width, signed=True) if fits(memory, value, width) else None
    bits = 8 * width
    value &= (1 << bits) - 1
    return value - (1 << bits) if value >> (bits - 1) else value


def _in_range(ctx: FunctionContext, inputs: tuple[bool, ...], params: tuple, width: int) -> bool:
    """W1 of RNGB/RNGW/RNGD: ACT = 1 and the input lies between the limits (either order)."""
    if not inputs[-1]:
        return False
    values = [_signed(ctx.memory, p, width) for p in params]
    if None in values:
        return False
    first, second, data = values
    assert first is not None and second is not None and data is not None
    return min(first, second) <= data <= max(first, second)


@function("RNGB")
def rngb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """W1 = 1 while ACT = 1 and limit1 <= input <= limit2 (or the reverse), 1 byte signed."""
    return _in_range(ctx, inputs, params, 1)


@function("RNGW")
def rngw(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """As RNGB with 2-byte data (SUB 219)."""
    return _in_range(ctx, inputs, params, 2)


@function("RNGD")
def rngd(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """As RNGB with 4-byte data (SUB 220)."""
    return _in_range(ctx, inputs, params, 4)
