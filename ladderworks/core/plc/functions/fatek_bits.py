"""Fatek FBs bit and word moves: FUN 9 MOV/, 10 TOGG, 37 ZNCMP, 40 BITRD, 41 BITWR, 42 BITMV,
43 NBMV, 44 BYMV, 45 XCHG, 46 SWAP, 47 UNIT, 48 DIST (docs/dialects.md, Fatek). `mode` bit 0
the P form, bit 1 the D form."""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import FunctionContext, FunctionImpl, function
from ladderworks.core.plc.functions.fatek_data import runs, width
from ladderworks.core.plc.functions.fatek_timing import operand_value
from ladderworks.core.plc.functions.fatek_words import _held, _out, signed


@function("FBS.MOVN")
def fatek_move_inverted(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                        params: tuple) -> bool:
    """FUN 9 MOV/: D := S with every bit inverted."""
    mode, source, destination = params
    if runs(state, mode, inputs[0]):
        size = width(mode)
        ctx.memory.write(destination, ~operand_value(ctx.memory, source, size), size)
    return False


@function("FBS.TOGG")
def fatek_toggle(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                 params: tuple) -> bool:
    """FUN 10 TOGG: the bit D inverted each time the box runs; FO0 OTP its new state."""
    mode, device, fo = params
    if not runs(state, mode, inputs[0]):
        return _held(state)
    assert isinstance(device, Address)
    on = not ctx.memory.bit(device)
    ctx.memory.set_bit(device, on)
    return _out(ctx, state, fo, on)


@function("FBS.ZNCMP")
def fatek_zone_compare(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                       params: tuple) -> bool:
    """FUN 37 ZNCMP: FO0 INZ SL <= S <= SU, FO1 S > SU, FO2 S < SL; SU < SL: FO3 ERR only."""
    mode, source, upper, lower, fo = params
    if not runs(state, mode, inputs[0]):
        return _held(state)
    size = width(mode)
    s, su, sl = (operand_value(ctx.memory, v, size) for v in (source, upper, lower))
    if su < sl:
        return _out(ctx, state, fo, False, False, False, True)
    return _out(ctx, state, fo, sl <= s <= su, s > su, s < sl)


def _bit_in_range(number: int, size: int) -> bool:
    return 0 <= number < 8 * size


@function("FBS.BITRD")
def fatek_bit_read(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                   params: tuple) -> bool:
    """FUN 40 BITRD: FO0 OTB := bit N of S; N outside the width: nothing done."""
    mode, source, number, fo = params
    if not runs(state, mode, inputs[0]):
        return _held(state)
    size = width(mode)
    n = operand_value(ctx.memory, number, 2)
    if not _bit_in_range(n, size):
        return _held(state)
    return _out(ctx, state, fo, bool(operand_value(ctx.memory, source, size) >> n & 1))


def _put_bit(ctx: FunctionContext, destination: Address, size: int, n: int, on: bool) -> None:
    value = ctx.memory.read(destination, size)
    value = value | 1 << n if on else value & ~(1 << n)
    ctx.memory.write(destination, value, size)


@function("FBS.BITWR")
def fatek_bit_write(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                    params: tuple) -> bool:
    """FUN 41 BITWR: bit N of D := the INB input; N outside the width: nothing done."""
    mode, destination, number = params
    if runs(state, mode, inputs[0]):
        size = width(mode)
        n = operand_value(ctx.memory, number, 2)
        if _bit_in_range(n, size):
            _put_bit(ctx, destination, size, n, len(inputs) > 1 and bool(inputs[1]))
    return False


def _part_move(bits: int) -> FunctionImpl:
    """FUN 42 BITMV (a bit), 43 NBMV (a nibble), 44 BYMV (a byte): part Nd of D := part Ns of
    S, the other parts of D kept; a part number outside the width: nothing done."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """Move one part when the box runs."""
        mode, source, ns, destination, nd = params
        if runs(state, mode, inputs[0]):
            size = width(mode)
            parts = 8 * size // bits
            a = operand_value(ctx.memory, ns, 2)
            b = operand_value(ctx.memory, nd, 2)
            if 0 <= a < parts and 0 <= b < parts:
                mask = (1 << bits) - 1
                part = operand_value(ctx.memory, source, size) >> (a * bits) & mask
                value = ctx.memory.read(destination, size)
                value = value & ~(mask << (b * bits)) | part << (b * bits)
                ctx.memory.write(destination, value, size)
        return False

    return impl


function("FBS.BITMV")(_part_move(1))
function("FBS.NBMV")(_part_move(4))
function("FBS.BYMV")(_part_move(8))


@function("FBS.XCHG")
def fatek_exchange(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                   params: tuple) -> bool:
    """FUN 45 XCHG: Da and Db exchanged."""
    mode, first, second = params
    if runs(state, mode, inputs[0]):
        size = width(mode)
        a = ctx.memory.read(first, size)
        ctx.memory.write(first, ctx.memory.read(second, size), size)
        ctx.memory.write(second, a, size)
    return False


@function("FBS.SWAP")
def fatek_swap(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
               params: tuple) -> bool:
    """FUN 46 SWAP: D's high and low bytes exchanged (the D form: its two words)."""
    mode, destination = params
    if runs(state, mode, inputs[0]):
        size = width(mode)
        value = ctx.memory.read(destination, size)
        half = 4 * size
        low = value & ((1 << half) - 1)
        ctx.memory.write(destination, signed(low << half | value >> half, size), size)
    return False


def _nibbles(unite: bool) -> FunctionImpl:
    """FUN 47 UNIT (S, N, D): nibble 0 of the N registers from S into nibbles 0 .. N - 1 of D,
    its other nibbles 0; FUN 48 DIST (S, N, D): nibbles 0 .. N - 1 of S into nibble 0 of the N
    registers from D, their other nibbles 0 (FBs manual p. 7-23). N outside 1-4: FO0 ERR,
    nothing done."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """Unite or distribute N nibbles when the box runs."""
        mode, source, count, destination, fo = params
        if not runs(state, mode, inputs[0]):
            return _held(state)
        n = operand_value(ctx.memory, count, 2)
        if not 1 <= n <= 4:
            return _out(ctx, state, fo, True)
        memory = ctx.memory
        if unite:
            value = 0
            for k in range(n):
                value |= (memory.read(source.offset(2 * k), 2, signed=False) & 0xF) << (4 * k)
            memory.write(destination, signed(value, 2), 2)
        else:
            word = operand_value(memory, source, 2)
            for k in range(n):
                memory.write(destination.offset(2 * k), (word >> (4 * k)) & 0xF, 2)
        return _out(ctx, state, fo, False)

    return impl


function("FBS.UNIT")(_nibbles(True))
function("FBS.DIST")(_nibbles(False))
