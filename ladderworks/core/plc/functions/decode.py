"""Decoding: DEC (2-digit BCD code against a number) and DECB (binary code to 8 bits)."""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import FunctionContext, function

_LOW_DIGIT = 1  # spec xx = 01: compare the low digit only
_HIGH_DIGIT = 10  # xx = 10: the high digit only
_BOTH_DIGITS = 11  # xx = 11: both digits


def decode_matches(raw: int, spec: int) -> bool:
    """True when the 2-digit BCD byte `raw` equals the number nn of the spec `nnxx`."""
    number, digits = divmod(spec, 100)
    high_want, low_want = divmod(number, 10)
    high, low = (raw >> 4) & 0xF, raw & 0xF
    if digits == _LOW_DIGIT:
        return low <= 9 and low == low_want
    if digits == _HIGH_DIGIT:
        return high <= 9 and high == high_want
    if digits == _BOTH_DIGITS:
        return high <= 9 and low <= 9 and (high, low) == (high_want, low_want)
    return False  # any other digit spec decodes nothing


@function("DEC")
def dec(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """W1 = 1 while ACT = 1 and the BCD code equals the spec's number; ACT = 0 gives W1 = 0."""
    (act,) = inputs
    if not act:
        return False
    code, spec = params
    assert isinstance(code, Address)
    return decode_matches(ctx.memory.read(code, 1), spec)


@function("DECB")
def decb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Result bit i = 1 when the binary code equals first + i; ACT = 0 clears the result byte."""
    (act,) = inputs
    width, code, first, result = params
    if not act:
        ctx.memory.write(result, 0, 1)
        return False
    value = ctx.memory.read(code, width)
    offset = value - first
    ctx.memory.write(result, 1 << offset if 0 <= offset < 8 else 0, 1)
    return False
