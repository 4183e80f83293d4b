"""Fatek FBs data functions: FUN 8 MOV, FUN 11-14 (+ - x /), FUN 15-16 (+1 -1), FUN 17 CMP and
the comparison contacts FUN 170-175 (docs/dialects.md, Fatek).

`mode` holds the box's forms: bit 0 the P (pulse) form, run only on EN's 0 -> 1; bit 1 the D
form, 32-bit operands. A box that does not run leaves its destination and its FO as they were.
"""

from __future__ import annotations

import operator
from collections.abc import Callable

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import FunctionContext, FunctionImpl, function
from ladderworks.core.plc.functions.fatek_timing import operand_value, write_outputs

PULSE = 1
DOUBLE = 2


def runs(state: dict, mode: int, enable: bool) -> bool:
    """Whether the box executes this scan: EN = 1, or its 0 -> 1 in the P form."""
    rising = enable and not state.get("en", False)
    state["en"] = bool(enable)
    return rising if mode & PULSE else bool(enable)


def width(mode: int) -> int:
    """Bytes of the operands: 4 in the D form, else 2."""
    return 4 if mode & DOUBLE else 2


def _wrap(value: int, nbytes: int) -> int:
    """The signed value of `nbytes` that `value` wraps to."""
    bits = 8 * nbytes
    value &= (1 << bits) - 1
    return value - (1 << bits) if value >> (bits - 1) else value


def _held(state: dict) -> bool:
    return bool(state.get("fo0", False))


def _result(ctx: FunctionContext, state: dict, fo: object, *bits: bool) -> bool:
    write_outputs(ctx.memory, fo, *bits)
    state["fo0"] = bits[0]
    return bits[0]


@function("FBS.MOV")
def fatek_move(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
               params: tuple) -> bool:
    """FUN 8 MOV: D := S."""
    mode, source, destination = params
    if runs(state, mode, inputs[0]):
        size = width(mode)
        ctx.memory.write(destination, operand_value(ctx.memory, source, size), size)
    return False


def _arithmetic(fun: int) -> FunctionImpl:
    """FUN 11 (+), 12 (-), 13 (x), 14 (/): D := Sa op Sb. FO0 D = 0; (+)/(-) FO1 carry, FO2
    borrow (the result wrapped); (x) the product fills D and the register after it (two
    registers, four in the D form); (/) the quotient in D, the remainder after it, FO1 ERR
    when Sb = 0 (nothing written)."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """D := Sa op Sb when the box runs."""
        mode, sa, sb, destination, fo = params
        if not runs(state, mode, inputs[0]):
            return _held(state)
        size = width(mode)
        memory = ctx.memory
        a = operand_value(memory, sa, size)
        b = operand_value(memory, sb, size)
        assert isinstance(destination, Address)
        if fun == 13:
            product = a * b
            memory.write(destination, product, 2 * size)
            return _result(ctx, state, fo, product == 0)
        if fun == 14:
            if b == 0:
                return _result(ctx, state, fo, False, True)
            quotient = abs(a) // abs(b) * (1 if (a < 0) == (b < 0) else -1)
            remainder = a - quotient * b
            memory.write(destination, quotient, size)
            memory.write(destination.offset(size), remainder, size)
            return _result(ctx, state, fo, quotient == 0)
        exact = a + b if fun == 11 else a - b
        value = _wrap(exact, size)
        memory.write(destination, value, size)
        return _result(ctx, state, fo, value == 0, exact > value, exact < value)

    return impl


def _step(fun: int) -> FunctionImpl:
    """FUN 15 (+1), 16 (-1): D := D + 1 / D - 1; FO0 its one output: on when D wrapped past
    the limit (overflow 32767 -> -32768 / underflow -32768 -> 32767; FBs-PLC manual §5.1,
    "CY Carry(FO0)", and §5.4 OVF/UDF)."""

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """D := D +/- 1 when the box runs."""
        mode, destination, fo = params
        if not runs(state, mode, inputs[0]):
            return _held(state)
        size = width(mode)
        exact = ctx.memory.read(destination, size, signed=True) + (1 if fun == 15 else -1)
        value = _wrap(exact, size)
        ctx.memory.write(destination, value, size)
        return _result(ctx, state, fo, value != exact)

    return impl


function("FBS.ADD")(_arithmetic(11))
function("FBS.SUB")(_arithmetic(12))
function("FBS.MUL")(_arithmetic(13))
function("FBS.DIV")(_arithmetic(14))
function("FBS.INC")(_step(15))
function("FBS.DEC")(_step(16))


@function("FBS.DIV48")
def fatek_divide48(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                   params: tuple) -> bool:
    """FUN 23 DIV48: the 48-bit Sa (three registers, the first the lowest) divided by the
    48-bit Sb, the quotient (truncated toward 0) in D's three registers; U/S = 1 unsigned, 0
    signed. FO0 D=0, FO1 ERR: Sb = 0, D kept (FBs manual p. 7-2)."""
    mode, sa, sb, destination, fo = params
    if not runs(state, mode, inputs[0]):
        return _held(state)
    signed = not (len(inputs) > 1 and inputs[1])
    a = ctx.memory.read(sa, 6, signed=signed)
    b = ctx.memory.read(sb, 6, signed=signed)
    if b == 0:
        return _result(ctx, state, fo, False, True)
    quotient = abs(a) // abs(b) * (1 if (a < 0) == (b < 0) else -1)
    ctx.memory.write(destination, quotient, 6)
    return _result(ctx, state, fo, quotient & (2**48 - 1) == 0, False)


@function("FBS.CMP")
def fatek_compare(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                  params: tuple) -> bool:
    """FUN 17 CMP: FO0 Sa = Sb, FO1 Sa > Sb, FO2 Sa < Sb (001:1081-1095)."""
    mode, sa, sb, fo = params
    if not runs(state, mode, inputs[0]):
        return _held(state)
    size = width(mode)
    a = operand_value(ctx.memory, sa, size)
    b = operand_value(ctx.memory, sb, size)
    return _result(ctx, state, fo, a == b, a > b, a < b)


COMPARISONS = {170: "=", 171: ">", 172: "<", 173: "<>", 174: ">=", 175: "<="}


_OPERATORS: dict[str, Callable[[int, int], bool]] = {
    "=": operator.eq, ">": operator.gt, "<": operator.lt, "<>": operator.ne, ">=": operator.ge,
    "<=": operator.le}


def compare(symbol: str, a: int, b: int) -> bool:
    """`a symbol b` for the six comparison contacts."""
    return _OPERATORS[symbol](a, b)


def _contact(fun: int) -> FunctionImpl:
    """FUN 170-175 as a contact: passes while Sa op Sb, in series with IN."""
    test = _OPERATORS[COMPARISONS[fun]]

    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """IN and the comparison of Sa with Sb."""
        mode, sa, sb = params
        size = width(mode)
        a = operand_value(ctx.memory, sa, size)
        b = operand_value(ctx.memory, sb, size)
        return bool(inputs[0]) and test(a, b)

    return impl


for _fun, _name in ((170, "FBS.EQ"), (171, "FBS.GT"), (172, "FBS.LT"), (173, "FBS.NE"),
                    (174, "FBS.GE"), (175, "FBS.LE")):
    function(_name)(_contact(_fun))
