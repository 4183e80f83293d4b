"""Fatek FBs conversions: FUN 20 →BCD and FUN 21 →BIN (docs/dialects.md, Fatek; the FBs-PLC
manual's FUN 20 page). FO0 is ERR: set, and D kept, when S is out of the conversion's range."""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext, function
from ladderworks.core.plc.functions.fatek_data import runs, width
from ladderworks.core.plc.functions.fatek_timing import operand_value, write_outputs


def to_bcd(value: int, digits: int) -> int | None:
    """The BCD code of 0 .. 10**digits - 1, None outside it."""
    if not 0 <= value < 10**digits:
        return None
    return int(str(value), 16)


def from_bcd(code: int, digits: int) -> int | None:
    """The value of a BCD code of `digits` nibbles, None when a nibble is above 9."""
    text = f"{code & ((1 << 4 * digits) - 1):0{digits}x}"
    return int(text) if text.isdigit() else None


def _convert(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple,
             to_code: bool) -> bool:
    mode, source, destination, fo = params
    if not runs(state, mode, inputs[0]):
        return bool(state.get("fo0", False))
    size = width(mode)
    value = operand_value(ctx.memory, source, size)
    digits = 2 * size  # 4 digits in 16 bits, 8 in 32
    result = to_bcd(value, digits) if to_code else from_bcd(value, digits)
    error = result is None
    if result is not None:
        ctx.memory.write(destination, result, size)
    write_outputs(ctx.memory, fo, error)
    state["fo0"] = error
    return error


@function("FBS.BCD")
def fatek_to_bcd(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                 params: tuple) -> bool:
    """FUN 20 →BCD: D := the BCD code of S (0-9999, D form 0-99999999); else FO0 ERR, D kept."""
    return _convert(ctx, state, inputs, params, True)


@function("FBS.BIN")
def fatek_to_bin(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                 params: tuple) -> bool:
    """FUN 21 →BIN: D := the value of the BCD code in S; a nibble above 9: FO0 ERR, D kept."""
    return _convert(ctx, state, inputs, params, False)
