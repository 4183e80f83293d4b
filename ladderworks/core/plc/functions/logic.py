"""Byte-wise logic on 1, 2 or 4 bytes: LOGAND (`AND`), LOGOR (`OR`), EOR and NOT.

Format 1/2/4: the operand is a constant; 1001/1002/1004: the operand is an address. A constant
is taken modulo 2^(8w), so -1 is all ones and 65295 in 2 bytes is 0xFF0F. ACT = 0 writes
nothing; no W1; R9000 is not touched. An unknown format or an operand past the end of its
area does nothing.
"""

from __future__ import annotations

import operator
from collections.abc import Callable

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import FunctionContext, fits, function
from ladderworks.core.plc.memory import Memory

WIDTHS = (1, 2, 4)


def _width(fmt: int) -> int | None:
    """Bytes of data for a format (1/2/4, or 1001/1002/1004), None for any other."""
    width = fmt % 1000 if fmt in (1, 2, 4, 1001, 1002, 1004) else 0
    return width if width in WIDTHS else None


def _operand(memory: Memory, value: int | Address, width: int) -> int | None:
    """The operand's bits: a constant wrapped to the width, or the data at an address."""
    if isinstance(value, Address):
        return memory.read(value, width) if fits(memory, value, width) else None
    return value & ((1 << (8 * width)) - 1)


def _binary(ctx: FunctionContext, inputs: tuple[bool, ...], params: tuple,
            op: Callable[[int, int], int]) -> bool:
    """out = in `op` operand, for the three two-operand instructions."""
    if not inputs[-1]:
        return False
    fmt, source, value, target = params
    width = _width(fmt)
    if width is None or not (fits(ctx.memory, source, width) and fits(ctx.memory, target, width)):
        return False
    operand = _operand(ctx.memory, value, width)
    if operand is not None:
        ctx.memory.write(target, op(ctx.memory.read(source, width), operand), width)
    return False


@function("LOGAND")
def logand(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """out = in AND operand (SUB 60, written `AND` with four parameters)."""
    return _binary(ctx, inputs, params, operator.and_)


@function("LOGOR")
def logor(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """out = in OR operand (SUB 61, written `OR` with four parameters)."""
    return _binary(ctx, inputs, params, operator.or_)


@function("EOR")
def eor(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """out = in XOR operand (SUB 59)."""
    return _binary(ctx, inputs, params, operator.xor)


@function("NOT")
def lognot(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """out = every bit of in inverted (SUB 62; format 1/2/4)."""
    if inputs[-1]:
        fmt, source, target = params
        width = fmt if fmt in WIDTHS else None
        if width and fits(ctx.memory, source, width) and fits(ctx.memory, target, width):
            ctx.memory.write(target, ~ctx.memory.read(source, width), width)
    return False
