"""Fatek FBs table functions that search, shift and keep tables: FUN 105 R-T_S, 106 T-T_C,
108 T_SHF, 109 T_ROT, 110 QUEUE, 111 STACK, 112 BKCMP, 113 SORT (docs/dialects.md, Fatek's
FUN table).

Entries are registers (register pairs in the D form); a pointer Pr is a 16-bit register in
both forms (FBs manual p. 7-83). A table that does not fit its area, a length out of range or
a pointer out of range is ERR, and nothing is written but the FO."""

from __future__ import annotations

from collections.abc import Callable

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import FunctionContext, FunctionImpl, function
from ladderworks.core.plc.functions.fatek_data import runs, width
from ladderworks.core.plc.functions.fatek_tables import fits, outputs
from ladderworks.core.plc.functions.fatek_timing import operand_value


def _held(state: dict) -> bool:
    return bool(state.get("fo0", False))


def _read(ctx: FunctionContext, table: Address, at: int, size: int) -> int:
    return ctx.memory.read(table.offset(at * size), size, signed=True)


def _write(ctx: FunctionContext, table: Address, at: int, size: int, value: int) -> None:
    ctx.memory.write(table.offset(at * size), value, size)


Matches = Callable[[FunctionContext, tuple, int, int, bool], bool]


def _search(first: int, matches: Matches, control: int) -> FunctionImpl:
    """FUN 105 R-T_S (Rs, Ts, L, Pr) and 106 T-T_C (Ta, Tb, L, Pr): from the table's head (FHD
    = 1, or Pr at L - 1) or from the entry after Pr, the first entry that `matches` stops the
    search: Pr := it, FO0 FND. Reaching the last entry, found or not, sets FO1 END and leaves
    Pr at L - 1. Pr outside 0 .. L - 1, L outside 2-256: FO2 ERR, nothing done (FBs manual
    p. 7-90). `first` is the index of the first table parameter, `control` that of the input
    passed to `matches` (T-T_C's D/S; -1: none)."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """One search when the box runs."""
        mode, length, pointer, fo = params[0], params[-3], params[-2], params[-1]
        if not runs(state, mode, inputs[0]):
            return _held(state)
        size = width(mode)
        count = operand_value(ctx.memory, length, 2)
        at = ctx.memory.read(pointer, 2, signed=True)
        tables = params[first:-3]
        if not (all(fits(ctx, t, count, size, 2) for t in tables) and 0 <= at < count):
            return outputs(ctx, state, fo, False, False, True)
        head = len(inputs) > 1 and inputs[1]
        start = 0 if head or at == count - 1 else at + 1
        flag = control >= 0 and len(inputs) > control and inputs[control]
        for k in range(start, count):
            if matches(ctx, params, k, size, flag):
                ctx.memory.write(pointer, k, 2)
                return outputs(ctx, state, fo, True, k == count - 1, False)
        ctx.memory.write(pointer, count - 1, 2)
        return outputs(ctx, state, fo, False, True, False)

    return impl


def _equal_to_rs(ctx: FunctionContext, params: tuple, k: int, size: int, _flag: bool) -> bool:
    """R-T_S: Ts[k] = Rs."""
    _mode, source, table = params[:3]
    return _read(ctx, table, k, size) == operand_value(ctx.memory, source, size)


def _pair(ctx: FunctionContext, params: tuple, k: int, size: int, different: bool) -> bool:
    """T-T_C: Ta[k] ≠ Tb[k] when D/S = 1, Ta[k] = Tb[k] when D/S = 0."""
    _mode, first, second = params[:3]
    return (_read(ctx, first, k, size) != _read(ctx, second, k, size)) == different


function("FBS.R_T_S")(_search(2, _equal_to_rs, -1))
function("FBS.T_T_C")(_search(1, _pair, 2))


def _moving(shift: bool) -> FunctionImpl:
    """FUN 108 T_SHF (IW, Ts, L, OW) and 109 T_ROT (Ts, L): the L entries of Ts moved one
    entry left (toward the higher registers, L/R = 1) or right (L/R = 0, FBs manual p. 7-83).
    T_SHF: the entry moved out goes to OW, IW comes in at the freed end; T_ROT: the entry
    moved out comes in at the other end. FO0 ERR: L outside 2-256, nothing moved."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """Move the table by one entry when the box runs."""
        if shift:
            mode, incoming, table, length, outgoing, fo = params
        else:
            mode, table, length, fo = params
        if not runs(state, mode, inputs[0]):
            return _held(state)
        size = width(mode)
        count = operand_value(ctx.memory, length, 2)
        if not fits(ctx, table, count, size, 2):
            return outputs(ctx, state, fo, True)
        entries = [_read(ctx, table, k, size) for k in range(count)]
        left = len(inputs) > 1 and inputs[1]
        out = entries[-1] if left else entries[0]
        rest = entries[:-1] if left else entries[1:]
        fill = operand_value(ctx.memory, incoming, size) if shift else out
        moved = [fill, *rest] if left else [*rest, fill]
        for k, entry in enumerate(moved):
            _write(ctx, table, k, size, entry)
        if shift:
            ctx.memory.write(outgoing, out, size)
        return outputs(ctx, state, fo, False)

    return impl


function("FBS.T_SHF")(_moving(True))
function("FBS.T_ROT")(_moving(False))


def _keeper(queue: bool) -> FunctionImpl:
    """FUN 110 QUEUE and 111 STACK (IW, QU/ST, L, Pr, OW; inputs EN, I/O). Pr = 0 is empty,
    1 .. L the entries QU1/ST1 .. QUL/STL. I/O = 1 pushes IW: the queue moves its Pr entries
    one up and takes IW as QU1, the stack takes it as ST(Pr + 1); Pr + 1. I/O = 0 pops the
    entry at Pr (the queue's oldest, the stack's newest) into OW; Pr - 1. A push on a full one
    or a pop on an empty one is not done. FO0 EPT Pr = 0, FO1 FUL Pr = L, FO2 ERR: Pr outside
    0 .. L or L outside 2-256, nothing done (FBs manual pp. 7-94 - 7-97)."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """One push or pop when the box runs."""
        mode, incoming, table, length, pointer, outgoing, fo = params
        if not runs(state, mode, inputs[0]):
            return _held(state)
        size = width(mode)
        count = operand_value(ctx.memory, length, 2)
        at = ctx.memory.read(pointer, 2, signed=True)
        if not (fits(ctx, table, count, size, 2) and 0 <= at <= count):
            return outputs(ctx, state, fo, False, False, True)
        if len(inputs) > 1 and inputs[1]:
            if at < count:
                if queue:
                    for k in range(at, 0, -1):
                        _write(ctx, table, k, size, _read(ctx, table, k - 1, size))
                _write(ctx, table, 0 if queue else at, size,
                       operand_value(ctx.memory, incoming, size))
                at += 1
        elif at > 0:
            ctx.memory.write(outgoing, _read(ctx, table, at - 1, size), size)
            at -= 1
        ctx.memory.write(pointer, at, 2)
        return outputs(ctx, state, fo, at == 0, at == count, False)

    return impl


function("FBS.QUEUE")(_keeper(True))
function("FBS.STACK")(_keeper(False))


@function("FBS.BKCMP")
def fatek_block_compare(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                        params: tuple) -> bool:
    """FUN 112 BKCMP (Rs, Ts, L, D) [chosen]: L zones, zone k's lower limit Ts[2k] and upper
    limit Ts[2k + 1]; bit k of the 16-bit registers from D := lower ≤ Rs ≤ upper (0 when
    lower > upper). FO0 ERR: L outside 1-128, nothing written."""
    mode, reference, table, length, target, fo = params
    if not runs(state, mode, inputs[0]):
        return _held(state)
    size = width(mode)
    count = operand_value(ctx.memory, length, 2)
    registers = (count + 15) // 16
    if not (1 <= count <= 128 and fits(ctx, table, 2 * count, size, 2)
            and fits(ctx, target, registers, 2, 1)):
        return outputs(ctx, state, fo, True)
    value = operand_value(ctx.memory, reference, size)
    words = [0] * registers
    for k in range(count):
        if _read(ctx, table, 2 * k, size) <= value <= _read(ctx, table, 2 * k + 1, size):
            words[k // 16] |= 1 << (k % 16)
    for k, word in enumerate(words):
        ctx.memory.write(target.offset(2 * k), word, 2)
    return outputs(ctx, state, fo, False)


@function("FBS.SORT")
def fatek_sort(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
               params: tuple) -> bool:
    """FUN 113 SORT (S, D, L; inputs EN, A/D): the L entries from S, sorted ascending (A/D =
    1) or descending (A/D = 0), written from D; S is read whole before D is written. FO0 ERR:
    L outside 2-127, nothing written (FBs manual p. 7-100)."""
    mode, source, target, length, fo = params
    if not runs(state, mode, inputs[0]):
        return _held(state)
    size = width(mode)
    count = operand_value(ctx.memory, length, 2)
    if not all(fits(ctx, t, count, size, 2, 127) for t in (source, target)):
        return outputs(ctx, state, fo, True)
    ascending = len(inputs) > 1 and inputs[1]
    entries = sorted((_read(ctx, source, k, size) for k in range(count)),
                     reverse=not ascending)
    for k, entry in enumerate(entries):
        _write(ctx, target, k, size, entry)
    return outputs(ctx, state, fo, False)
