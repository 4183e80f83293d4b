"""Code and data conversion: COD, CODB (table look-up) and DCNV, DCNVB (binary <-> BCD)."""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.plc.bcd import int_to_bcd
from ladderworks.core.plc.functions import (
    FLAG_NEGATIVE,
    FLAG_OVERFLOW,
    FunctionContext,
    function,
    held_output,
    output,
    result_flags,
)


def _fits_binary(value: int, width: int) -> bool:
    """True when `value` can be stored in `width` bytes, read signed or unsigned."""
    return -(1 << (8 * width - 1)) <= value < (1 << (8 * width))


@function("COD")
def cod(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """output = table[index] in BCD; W1 = 1 when the index is past the table or not BCD."""
    byt, rst, act = inputs
    held = held_output(state, rst, act)
    if held is not None:
        return held
    size, index, out = params[:3]
    table = params[3:]
    assert isinstance(index, Address) and isinstance(out, Address)
    row = ctx.memory.read_bcd(index, 1)
    if row is None or row >= min(size, len(table)):
        return output(state, True)
    return output(state, not ctx.memory.write_bcd(out, table[row], 2 if byt else 1))


@function("CODB")
def codb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """output = table[index] in binary (1/2/4 bytes); W1 = 1 when the index is past the table."""
    rst, act = inputs
    held = held_output(state, rst, act)
    if held is not None:
        return held
    width, size, index, out = params[:4]
    table = params[4:]
    row = ctx.memory.read(index, 1)
    if row >= min(size, len(table)) or not _fits_binary(table[row], width):
        return output(state, True)
    ctx.memory.write(out, table[row], width)
    return output(state, False)


@function("DCNV")
def dcnv(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Binary <-> BCD of 1 (BYT=0) or 2 bytes; W1 = 1 on a bad BCD digit or a too-large value."""
    byt, cnv, rst, act = inputs
    held = held_output(state, rst, act)
    if held is not None:
        return held
    source, target = params
    width = 2 if byt else 1
    if cnv:  # BCD -> binary
        value = ctx.memory.read_bcd(source, width)
        if value is None:
            return output(state, True)
        ctx.memory.write(target, value, width)
        return output(state, False)
    raw = int_to_bcd(ctx.memory.read(source, width), 2 * width)
    if raw is None:
        return output(state, True)
    ctx.memory.write(target, raw, width)
    return output(state, False)


@function("DCNVB")
def dcnvb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Signed binary <-> BCD of 1/2/4 bytes; SIN gives the BCD sign, R9000 gets the flags."""
    sin, cnv, rst, act = inputs
    held = held_output(state, rst, act)
    if held is not None:
        return held
    width, source, target = params
    if cnv:  # BCD (magnitude) with the sign from SIN -> signed binary
        magnitude = ctx.memory.read_bcd(source, width)
        if magnitude is None:
            ctx.set_result_register(FLAG_OVERFLOW, 1)
            return output(state, True)
        value = -magnitude if sin else magnitude
        ctx.memory.write(target, value, width)
        ctx.set_result_register(result_flags(value), 1)
        return output(state, False)
    value = ctx.memory.read(source, width, signed=True)
    raw = int_to_bcd(abs(value), 2 * width)
    if raw is None:
        ctx.set_result_register(FLAG_OVERFLOW | (FLAG_NEGATIVE if value < 0 else 0), 1)
        return output(state, True)
    ctx.memory.write(target, raw, width)
    ctx.set_result_register(result_flags(value), 1)
    return output(state, False)
