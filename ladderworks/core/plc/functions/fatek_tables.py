"""Fatek FBs table functions: FUN 24 SUM, 25 MEAN, 100 R->T, 101 T->R, 102 T->T, 103 BT_M,
104 T_SWP, 107 T_FIL (docs/dialects.md, Fatek). A table is L consecutive registers (register
pairs in the D form) from its first; L outside 2-256 (SUM, MEAN: 1-256), or a table running
past its area: ERR (FO0, FO1 for the pointer moves), nothing written."""

from __future__ import annotations

from collections.abc import Callable

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import FunctionContext, FunctionImpl, function
from ladderworks.core.plc.functions.fatek_data import runs, width
from ladderworks.core.plc.functions.fatek_timing import operand_value, write_outputs
from ladderworks.core.plc.functions.fatek_words import signed

MAX_LENGTH = 256


def outputs(ctx: FunctionContext, state: dict, fo: object, *bits: bool) -> bool:
    """Write the box's FO0, FO1 …; FO0 is also its W1 (kept for a scan it does not run)."""
    write_outputs(ctx.memory, fo, *bits)
    state["fo0"] = bits[0]
    return bits[0]


def fits(ctx: FunctionContext, table: object, length: int, size: int, low: int = 2,
         high: int = MAX_LENGTH) -> bool:
    """Whether a table of `length` entries (`low` .. `high`: a table instruction's table has
    2 or more, FBs manual p. 7-83) of `size` bytes starts at an address and ends inside its
    area."""
    return (isinstance(table, Address) and low <= length <= high
            and table.byte + length * size <= len(ctx.memory.areas[table.area]))


def _entries(ctx: FunctionContext, table: Address, length: int, size: int) -> list[int]:
    return [ctx.memory.read(table.offset(k * size), size, signed=True) for k in range(length)]


TableBody = Callable[[FunctionContext, tuple, int, int], None]


def _table_box(length_at: int, tables: tuple[int, ...], body: TableBody, low: int = 2
               ) -> FunctionImpl:
    """A table FUN: when the box runs (its mode's plain or pulse form), the parameter at
    `length_at` gives L; every table parameter in `tables` must fit L entries, else ERR and
    nothing written; `body(ctx, params, L, entry size)` does the work."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """The table function when the box runs; FO0 its ERR."""
        mode, fo = params[0], params[-1]
        if not runs(state, mode, inputs[0]):
            return bool(state.get("fo0", False))
        size = width(mode)
        count = operand_value(ctx.memory, params[length_at], 2)
        if not all(fits(ctx, params[k], count, size, low) for k in tables):
            return outputs(ctx, state, fo, True)
        body(ctx, params, count, size)
        return outputs(ctx, state, fo, False)

    return impl


def _sum(ctx: FunctionContext, params: tuple, count: int, size: int) -> None:
    """FUN 24 SUM: D := the sum of the table Ts of L entries, wrapped to D's width."""
    _mode, table, _length, destination, _fo = params
    ctx.memory.write(destination, signed(sum(_entries(ctx, table, count, size)), size), size)


def _mean(ctx: FunctionContext, params: tuple, count: int, size: int) -> None:
    """FUN 25 MEAN: D := the sum of the table Ts divided by L, truncated toward 0."""
    _mode, table, _length, destination, _fo = params
    total = sum(_entries(ctx, table, count, size))
    total = abs(total) // count * (1 if total >= 0 else -1)
    ctx.memory.write(destination, signed(total, size), size)


def _block_move(ctx: FunctionContext, params: tuple, count: int, size: int) -> None:
    """FUN 103 BT_M: the L entries of Ts copied to Td (as read before any is written)."""
    _mode, source, target, _length, _fo = params
    for k, value in enumerate(_entries(ctx, source, count, size)):
        ctx.memory.write(target.offset(k * size), value, size)


def _table_swap(ctx: FunctionContext, params: tuple, count: int, size: int) -> None:
    """FUN 104 T_SWP: the L entries of Ta and Tb exchanged."""
    _mode, first, second, _length, _fo = params
    a = _entries(ctx, first, count, size)
    b = _entries(ctx, second, count, size)
    for k in range(count):
        ctx.memory.write(first.offset(k * size), b[k], size)
        ctx.memory.write(second.offset(k * size), a[k], size)


def _table_fill(ctx: FunctionContext, params: tuple, count: int, size: int) -> None:
    """FUN 107 T_FIL: every one of the L entries of Td := S."""
    _mode, source, target, _length, _fo = params
    value = operand_value(ctx.memory, source, size)
    for k in range(count):
        ctx.memory.write(target.offset(k * size), value, size)


function("FBS.SUM")(_table_box(2, (1,), _sum, 1))
function("FBS.MEAN")(_table_box(2, (1,), _mean, 1))
function("FBS.BT_M")(_table_box(3, (1, 2), _block_move))
function("FBS.T_SWP")(_table_box(3, (1, 2), _table_swap))
function("FBS.T_FIL")(_table_box(3, (2,), _table_fill))


def _pointer_move(kind: str) -> FunctionImpl:
    """FUN 100 R→T (Rs, Td, L, Pr: Td[Pr] := Rs), 101 T→R (Ts, L, Pr, Rd: Rd := Ts[Pr]) and
    102 T→T (Ts, Td, L, Pr: Td[Pr] := Ts[Pr]). Inputs EN, PIN, CLR: CLR = 1 sets Pr to 0 and
    does nothing else; after a move PIN = 1 moves Pr on by one, up to L - 1 where it stays.
    FO0 PEND: the move was at the tables' last entry; FO1 ERR: Pr outside 0 .. L - 1 or L
    outside 1-256, nothing moved. Pr is a 16-bit register in the D form too (FBs manual 7-83)."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """One pointer move when the box runs."""
        mode, fo = params[0], params[-1]
        tables: tuple[object, ...]
        if kind == "R->T":
            _m, source, table, length, pointer, _fo = params
            tables = (table,)
        elif kind == "T->R":
            _m, table, length, pointer, source, _fo = params
            tables = (table,)
        else:
            _m, source, table, length, pointer, _fo = params
            tables = (source, table)
        enable = runs(state, mode, inputs[0])
        memory = ctx.memory
        if len(inputs) > 2 and inputs[2]:
            memory.write(pointer, 0, 2)
            return outputs(ctx, state, fo, False, False)
        if not enable:
            return bool(state.get("fo0", False))
        size = width(mode)
        count = operand_value(memory, length, 2)
        at = memory.read(pointer, 2, signed=True)
        if not (all(fits(ctx, t, count, size) for t in tables) and 0 <= at < count):
            return outputs(ctx, state, fo, False, True)
        assert isinstance(table, Address)
        entry = table.offset(at * size)
        if kind == "R->T":
            memory.write(entry, operand_value(memory, source, size), size)
        elif kind == "T->R":
            memory.write(source, memory.read(entry, size), size)
        else:
            memory.write(entry, memory.read(source.offset(at * size), size), size)
        if len(inputs) > 1 and inputs[1] and at < count - 1:
            memory.write(pointer, at + 1, 2)
        return outputs(ctx, state, fo, at == count - 1, False)

    return impl


function("FBS.R_T")(_pointer_move("R->T"))
function("FBS.T_R")(_pointer_move("T->R"))
function("FBS.T_T")(_pointer_move("T->T"))
