"""Data search: DSCH (BCD table) and DSCHB (binary table) find the first matching entry."""

from __future__ import annotations

from ladderworks.core.address import AREA_SIZES, Address
from ladderworks.core.plc.functions import FunctionContext, function, held_output, output
from ladderworks.core.plc.memory import Memory


def find(memory: Memory, table: Address, size: int, width: int, wanted: int) -> int | None:
    """Index of the first of `size` raw `width`-byte entries equal to `wanted`, or None.

    Entries past the end of the area are not searched.
    """
    room = (AREA_SIZES[table.area] - table.byte) // width
    for row in range(max(0, min(size, room))):
        if memory.read(table.offset(row * width), width) == wanted:
            return row
    return None


@function("DSCH")
def dsch(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """result = BCD index of the first entry equal to the search data; W1 = 1 if not found."""
    byt, rst, act = inputs
    held = held_output(state, rst, act)
    if held is not None:
        return held
    size, table, search, result = params
    width = 2 if byt else 1
    if ctx.memory.read_bcd(search, width) is None:
        return output(state, True)
    row = find(ctx.memory, table, size, width, ctx.memory.read(search, width))
    if row is None or not ctx.memory.write_bcd(result, row, width):
        return output(state, True)
    return output(state, False)


@function("DSCHB")
def dschb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Binary DSCH: the table size at an address (4 bytes); result a 4-byte binary index."""
    rst, act = inputs
    held = held_output(state, rst, act)
    if held is not None:
        return held
    width, size_at, table, search, result = params
    size = ctx.memory.read(size_at, 4, signed=True)
    row = find(ctx.memory, table, size, width, ctx.memory.read(search, width))
    if row is None:
        return output(state, True)
    ctx.memory.write(result, row, 4)
    return output(state, False)
