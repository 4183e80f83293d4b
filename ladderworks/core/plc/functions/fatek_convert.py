"""Fatek FBs conversions: FUN 20 →BCD and FUN 21 →BIN (docs/dialects.md, Fatek; the FBs-PLC
manual's FUN 20 page: FO0 is ERR, set, and D kept, when S is out of the conversion's range), and
the check code FUN 31 CRC16 (its page 7-10)."""

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


def crc16(data: bytes) -> int:
    """The CRC16 of Modbus RTU (start 0xFFFF, polynomial 0xA001 reflected)."""
    crc = 0xFFFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return crc


@function("FBS.CRC16")
def fatek_crc16(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                params: tuple) -> bool:
    """FUN 31 CRC16 (MD, S, N, D): the CRC16 of the low bytes of the N registers from S (MD
    0; MD 1 is reserved: ERR), its high byte in D, its low byte in D + 1. FO0 D=0; FO1 ERR: N
    outside 1-256 or MD not 0, nothing written (FBs manual p. 7-10)."""
    mode, kind, source, count, destination, fo = params
    if not runs(state, mode, inputs[0]):
        return bool(state.get("fo0", False))
    memory = ctx.memory
    n = operand_value(memory, count, 2)
    area = memory.areas[source.area]
    if kind != 0 or not 1 <= n <= 256 or source.byte + 2 * n > len(area):
        write_outputs(memory, fo, False, True)
        state["fo0"] = False
        return False
    crc = crc16(bytes(memory.read(source.offset(2 * k), 1) for k in range(n)))
    memory.write(destination, crc >> 8, 2)
    memory.write(destination.offset(2), crc & 0xFF, 2)
    write_outputs(memory, fo, crc == 0, False)
    state["fo0"] = crc == 0
    return crc == 0
