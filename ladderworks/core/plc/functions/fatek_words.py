"""Fatek FBs word functions: FUN 18 AND, 19 OR, 35 XOR, 36 XNR, 26 SQRT, 27 NEG, 28 ABS, 29 EXT,
the shifts FUN 51 SHFL, 52 SHFR and rotations FUN 53 ROTL, 54 ROTR (docs/dialects.md, Fatek).

`mode` bit 0 is the P form (run on EN 0 -> 1), bit 1 the D form (32-bit). A box that does not
run keeps its destination and FO."""

from __future__ import annotations

import math
from collections.abc import Callable

from ladderworks.core.plc.functions import FunctionContext, FunctionImpl, function
from ladderworks.core.plc.functions.fatek_data import runs, width
from ladderworks.core.plc.functions.fatek_timing import operand_value, write_outputs


def signed(value: int, nbytes: int) -> int:
    """The signed value of `nbytes` that `value` wraps to."""
    bits = 8 * nbytes
    value &= (1 << bits) - 1
    return value - (1 << bits) if value >> (bits - 1) else value


def _out(ctx: FunctionContext, state: dict, fo: object, *bits: bool) -> bool:
    write_outputs(ctx.memory, fo, *bits)
    state["fo0"] = bits[0]
    return bits[0]


def _held(state: dict) -> bool:
    return bool(state.get("fo0", False))


_LOGIC: dict[int, Callable[[int, int], int]] = {
    18: lambda a, b: a & b, 19: lambda a, b: a | b, 35: lambda a, b: a ^ b,
    36: lambda a, b: ~(a ^ b)}


def _logic(fun: int) -> FunctionImpl:
    """FUN 18 AND, 19 OR, 35 XOR, 36 XNR: D := Sa op Sb bit by bit; FO0 D = 0."""
    op = _LOGIC[fun]

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """D := Sa op Sb when the box runs."""
        mode, sa, sb, destination, fo = params
        if not runs(state, mode, inputs[0]):
            return _held(state)
        size = width(mode)
        value = signed(op(operand_value(ctx.memory, sa, size),
                          operand_value(ctx.memory, sb, size)), size)
        ctx.memory.write(destination, value, size)
        return _out(ctx, state, fo, value == 0)

    return impl


for _fun, _name in ((18, "FBS.AND"), (19, "FBS.OR"), (35, "FBS.XOR"), (36, "FBS.XNR")):
    function(_name)(_logic(_fun))


@function("FBS.SQRT")
def fatek_sqrt(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
               params: tuple) -> bool:
    """FUN 26 SQRT: D := the integer square root of S (truncated); S < 0: FO0 ERR, D kept."""
    mode, source, destination, fo = params
    if not runs(state, mode, inputs[0]):
        return _held(state)
    size = width(mode)
    value = operand_value(ctx.memory, source, size)
    if value < 0:
        return _out(ctx, state, fo, True)
    ctx.memory.write(destination, math.isqrt(value), size)
    return _out(ctx, state, fo, False)


def _unary(negate: bool) -> FunctionImpl:
    """FUN 27 NEG (D := -D), FUN 28 ABS (D := |D|); the one value with no opposite
    (-32768, -2147483648) stays as it is (wrapped)."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """D := -D or |D| when the box runs."""
        mode, destination = params
        if runs(state, mode, inputs[0]):
            size = width(mode)
            value = ctx.memory.read(destination, size, signed=True)
            ctx.memory.write(destination, signed(-value if negate else abs(value), size), size)
        return False

    return impl


function("FBS.NEG")(_unary(True))
function("FBS.ABS")(_unary(False))


@function("FBS.EXT")
def fatek_extend(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                 params: tuple) -> bool:
    """FUN 29 EXT: the 16-bit D sign-extended into the 32-bit D + 1, D (FBs manual p. 7-8);
    the D form does the same [chosen]."""
    mode, destination = params
    if runs(state, mode, inputs[0]):
        ctx.memory.write(destination, ctx.memory.read(destination, 2, signed=True), 4)
    return False


def _moved(value: int, count: int, bits: int, left: bool, rotate: bool, fill: bool
           ) -> tuple[int, bool]:
    """`value` (unsigned, `bits` wide) moved `count` places: the new value and the last bit
    that left it (0 when count is 0)."""
    mask = (1 << bits) - 1
    out = False
    for _ in range(count):
        if left:
            out = bool(value >> (bits - 1) & 1)
            value = ((value << 1) & mask) | (int(out) if rotate else int(fill))
        else:
            out = bool(value & 1)
            value = (value >> 1) | ((int(out) if rotate else int(fill)) << (bits - 1))
    return value, out


def _mover(left: bool, rotate: bool) -> FunctionImpl:
    """FUN 51 SHFL / 52 SHFR (the INB input shifted in) and 53 ROTL / 54 ROTR: D moved N
    bits; FO0 OTB the last bit moved out; N outside 1-16 (1-32 in the D form): FO1 ERR and
    nothing done (FBs manual pp. 7-26, 7-29)."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """Move D by N bits when the box runs."""
        mode, destination, count, fo = params
        if not runs(state, mode, inputs[0]):
            return _held(state)
        size = width(mode)
        bits = 8 * size
        n = operand_value(ctx.memory, count, 2)
        if not 1 <= n <= bits:
            return _out(ctx, state, fo, False, True)
        fill = not rotate and len(inputs) > 1 and bool(inputs[1])
        value = ctx.memory.read(destination, size, signed=False)
        value, out = _moved(value, n, bits, left, rotate, fill)
        ctx.memory.write(destination, signed(value, size), size)
        return _out(ctx, state, fo, out, False)

    return impl


function("FBS.SHFL")(_mover(True, False))
function("FBS.SHFR")(_mover(False, False))
function("FBS.ROTL")(_mover(True, True))
function("FBS.ROTR")(_mover(False, True))
