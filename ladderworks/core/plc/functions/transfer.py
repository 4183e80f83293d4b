"""Data transfer: MOVE (masked), MOVOR (with OR), XMOV and XMOVB (indexed table transfer)."""

from __future__ import annotations

from ladderworks.core.address import AREA_SIZES, Address
from ladderworks.core.plc.functions import FunctionContext, function, held_output, output
from ladderworks.core.plc.memory import Memory


@function("MOVE")
def move(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """output byte = input byte AND the mask (high 4 bits, low 4 bits); ACT = 0 does nothing."""
    (act,) = inputs
    if act:
        high, low, source, target = params
        ctx.memory.write(target, ctx.memory.read(source, 1) & ((high << 4) | low), 1)
    return False


@function("MOVOR")
def movor(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """output byte = input byte OR the OR-data byte; ACT = 0 does nothing."""
    (act,) = inputs
    if act:
        source, or_data, target = params
        ctx.memory.write(target, ctx.memory.read(source, 1) | ctx.memory.read(or_data, 1), 1)
    return False


def _table_entry(table: Address, row: int, width: int) -> Address | None:
    """Address of entry `row` of a table of `width`-byte entries, None if past the area."""
    entry = table.offset(row * width)
    return entry if entry.byte + width <= AREA_SIZES[entry.area] else None


def _transfer(memory: Memory, write: bool, table: Address, row: int | None, size: int,
              data: Address, width: int) -> bool:
    """Copy `width` bytes between table[row] and data; True on an error (bad row)."""
    if row is None or not 0 <= row < size:
        return True
    entry = _table_entry(table, row, width)
    if entry is None:
        return True
    source, target = (data, entry) if write else (entry, data)
    memory.write(target, memory.read(source, width), width)
    return False


@function("XMOV")
def xmov(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """RW = 0: data = table[index]; RW = 1: table[index] = data (BCD index, 2 or 4 digits)."""
    byt, rw, rst, act = inputs
    held = held_output(state, rst, act)
    if held is not None:
        return held
    size, table, data, index = params
    width = 2 if byt else 1
    row = ctx.memory.read_bcd(index, width)
    return output(state, _transfer(ctx.memory, rw, table, row, size, data, width))


@function("XMOVB")
def xmovb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Binary XMOV: entries of 1/2/4 bytes, the index a binary number."""
    rw, rst, act = inputs
    held = held_output(state, rst, act)
    if held is not None:
        return held
    width, size, table, data, index = params
    row = ctx.memory.read(index, 4, signed=True)
    return output(state, _transfer(ctx.memory, rw, table, row, size, data, width))
