"""Fatek FBs table functions: FUN 24 SUM, 25 MEAN, 100 R->T, 101 T->R, 103 BT_M, 104 T_SWP,
107 T_FIL (docs/dialects.md, Fatek). A table is L consecutive registers (register pairs in the
D form) from its first; L outside 1-256, or a table running past its area: ERR (FO0, FO1 for
the pointer moves), nothing written."""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import FunctionContext, FunctionImpl, function
from ladderworks.core.plc.functions.fatek_data import runs, width
from ladderworks.core.plc.functions.fatek_timing import operand_value, write_outputs
from ladderworks.core.plc.functions.fatek_words import signed

MAX_LENGTH = 256


def _error(ctx: FunctionContext, state: dict, fo: object, error: bool) -> bool:
    write_outputs(ctx.memory, fo, error)
    state["fo0"] = error
    return error


def _fits(ctx: FunctionContext, table: object, length: int, size: int) -> bool:
    """Whether a table of `length` entries of `size` bytes starts at an address and ends
    inside its area."""
    return (isinstance(table, Address) and 1 <= length <= MAX_LENGTH
            and table.byte + length * size <= len(ctx.memory.areas[table.area]))


def _entries(ctx: FunctionContext, table: Address, length: int, size: int) -> list[int]:
    return [ctx.memory.read(table.offset(k * size), size, signed=True) for k in range(length)]


def _statistic(mean: bool) -> FunctionImpl:
    """FUN 24 SUM (D := the sum, wrapped to D's width) and 25 MEAN (D := the sum divided by
    L, truncated toward 0) of the table Ts of L entries."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """D := the table's sum or mean when the box runs."""
        mode, table, length, destination, fo = params
        if not runs(state, mode, inputs[0]):
            return bool(state.get("fo0", False))
        size = width(mode)
        count = operand_value(ctx.memory, length, 2)
        if not _fits(ctx, table, count, size):
            return _error(ctx, state, fo, True)
        assert isinstance(table, Address)
        total = sum(_entries(ctx, table, count, size))
        if mean:
            total = abs(total) // count * (1 if total >= 0 else -1)
        ctx.memory.write(destination, signed(total, size), size)
        return _error(ctx, state, fo, False)

    return impl


function("FBS.SUM")(_statistic(False))
function("FBS.MEAN")(_statistic(True))


@function("FBS.BT_M")
def fatek_block_move(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                     params: tuple) -> bool:
    """FUN 103 BT_M: the L entries of Ts copied to Td (as read before any is written)."""
    mode, source, target, length, fo = params
    if not runs(state, mode, inputs[0]):
        return bool(state.get("fo0", False))
    size = width(mode)
    count = operand_value(ctx.memory, length, 2)
    if not (_fits(ctx, source, count, size) and _fits(ctx, target, count, size)):
        return _error(ctx, state, fo, True)
    assert isinstance(source, Address) and isinstance(target, Address)
    for k, value in enumerate(_entries(ctx, source, count, size)):
        ctx.memory.write(target.offset(k * size), value, size)
    return _error(ctx, state, fo, False)


@function("FBS.T_SWP")
def fatek_table_swap(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                     params: tuple) -> bool:
    """FUN 104 T_SWP: the L entries of Ta and Tb exchanged."""
    mode, first, second, length, fo = params
    if not runs(state, mode, inputs[0]):
        return bool(state.get("fo0", False))
    size = width(mode)
    count = operand_value(ctx.memory, length, 2)
    if not (_fits(ctx, first, count, size) and _fits(ctx, second, count, size)):
        return _error(ctx, state, fo, True)
    assert isinstance(first, Address) and isinstance(second, Address)
    a = _entries(ctx, first, count, size)
    b = _entries(ctx, second, count, size)
    for k in range(count):
        ctx.memory.write(first.offset(k * size), b[k], size)
        ctx.memory.write(second.offset(k * size), a[k], size)
    return _error(ctx, state, fo, False)


@function("FBS.T_FIL")
def fatek_table_fill(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                     params: tuple) -> bool:
    """FUN 107 T_FIL: every one of the L entries of Td := S."""
    mode, source, target, length, fo = params
    if not runs(state, mode, inputs[0]):
        return bool(state.get("fo0", False))
    size = width(mode)
    count = operand_value(ctx.memory, length, 2)
    if not _fits(ctx, target, count, size):
        return _error(ctx, state, fo, True)
    assert isinstance(target, Address)
    value = operand_value(ctx.memory, source, size)
    for k in range(count):
        ctx.memory.write(target.offset(k * size), value, size)
    return _error(ctx, state, fo, False)


def _pointer_move(to_table: bool) -> FunctionImpl:
    """FUN 100 R→T (Rs, Td, L, Pr: Td[Pr] := Rs) and 101 T→R (Ts, L, Pr, Rd: Rd := Ts[Pr]).
    Inputs EN, PIN, CLR: CLR = 1 sets Pr to 0 and does nothing else; after a move PIN = 1 moves
    Pr on by one, up to L - 1 where it stays. FO0 PEND: the move was at the table's last entry;
    FO1 ERR: Pr outside 0 .. L - 1 or L outside 1-256, nothing moved."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """One pointer move when the box runs."""
        if to_table:
            mode, source, table, length, pointer, fo = params
        else:
            mode, table, length, pointer, source, fo = params
        enable = runs(state, mode, inputs[0])
        memory = ctx.memory
        if len(inputs) > 2 and inputs[2]:
            memory.write(pointer, 0, 2)
            return _outputs(ctx, state, fo, False, False)
        if not enable:
            return bool(state.get("fo0", False))
        size = width(mode)
        count = operand_value(memory, length, 2)
        at = memory.read(pointer, 2, signed=True)
        if not (_fits(ctx, table, count, size) and 0 <= at < count):
            return _outputs(ctx, state, fo, False, True)
        assert isinstance(table, Address)
        entry = table.offset(at * size)
        if to_table:
            memory.write(entry, operand_value(memory, source, size), size)
        else:
            memory.write(source, memory.read(entry, size), size)
        if len(inputs) > 1 and inputs[1] and at < count - 1:
            memory.write(pointer, at + 1, 2)
        return _outputs(ctx, state, fo, at == count - 1, False)

    return impl


def _outputs(ctx: FunctionContext, state: dict, fo: object, *bits: bool) -> bool:
    write_outputs(ctx.memory, fo, *bits)
    state["fo0"] = bits[0]
    return bits[0]


function("FBS.R_T")(_pointer_move(True))
function("FBS.T_R")(_pointer_move(False))
