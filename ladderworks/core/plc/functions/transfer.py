"""Data transfer: MOVE (masked), MOVOR (with OR), MOVB/MOVW/MOVN/MOVD (1, 2, n, 4 bytes),
XMOV and XMOVB (indexed table transfer)."""

from __future__ import annotations

from ladderworks.core.address import AREA_SIZES, Address
from ladderworks.core.plc.functions import (
    FunctionContext,
    fits,
    function,
    held_output,
    output,
)
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


def copy_bytes(memory: Memory, source: Address, target: Address, count: int) -> None:
    """Copy `count` bytes as if through a buffer (overlap is safe); nothing if either runs
    past the end of its area."""
    if fits(memory, source, count) and fits(memory, target, count):
        memory.write(target, memory.read(source, count), count)


@function("MOVB")
def movb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Copy 1 byte while ACT = 1."""
    if inputs[-1]:
        copy_bytes(ctx.memory, params[0], params[1], 1)
    return False


@function("MOVW")
def movw(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Copy 2 bytes while ACT = 1."""
    if inputs[-1]:
        copy_bytes(ctx.memory, params[0], params[1], 2)
    return False


@function("MOVN")
def movn(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Copy n bytes while ACT = 1 (as through a buffer when the areas overlap)."""
    if inputs[-1]:
        count, source, target = params
        copy_bytes(ctx.memory, source, target, count)
    return False


@function("MOVD")
def movd(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Copy 4 bytes while ACT = 1: the same as MOVN 4."""
    if inputs[-1]:
        copy_bytes(ctx.memory, params[0], params[1], 4)
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
    """Binary XMOV: entries of 1/2/4 bytes, the index a binary number; the table size is a
    constant or read (2 bytes) from an address."""
    rw, rst, act = inputs
    held = held_output(state, rst, act)
    if held is not None:
        return held
    width, size, table, data, index = params
    if isinstance(size, Address):  # the table size at an address: 2 bytes, signed
        size = ctx.memory.read(size, 2, signed=True)
    row = ctx.memory.read(index, 4, signed=True)
    return output(state, _transfer(ctx.memory, rw, table, row, size, data, width))
