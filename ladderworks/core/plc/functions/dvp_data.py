"""Delta DVP data instructions: MOV, ADD, SUB, MUL, DIV, INC, DEC, CMP, ZCP (and their pulse
forms MOVP ... ZCPP, run on the rising edge of their input only), PLS and PLF.

Every one runs while its input is on (a pulse form: in the scan the input went on) and passes
its input on (the rung may go on to another output). 16-bit signed values; MUL writes its
32-bit product to D and D+1, DIV its quotient to D and remainder to D+1; ADD/SUB set M1020
(zero), M1021 (borrow) and M1022 (carry) as Delta's manual describes. Division by zero writes
nothing and sets M1067/M1068 (operation error). docs/dialects.md.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

from ladderworks.core.address import Address
from ladderworks.core.dialects.delta import DEVICES, relay
from ladderworks.core.dialects.delta.table import ROWS
from ladderworks.core.instructions import Operation
from ladderworks.core.plc.functions import FunctionContext, function
from ladderworks.core.plc.memory import Memory

M1020, M1021, M1022 = relay(1020), relay(1021), relay(1022)  # zero, borrow, carry
M1067, M1068 = relay(1067), relay(1068)  # operation error, and it latched

Impl = Callable[[FunctionContext, dict, tuple[bool, ...], tuple], bool]


@cache
def width_of(address: Address) -> int:
    """The byte width of the word device at `address` (kept: the device map never changes)."""
    return DEVICES.width_at(address)


def value(memory: Memory, operand: object) -> int:
    """A source operand's value: a constant, or a word device (32-bit for C200..C255)."""
    if isinstance(operand, Address):
        return memory.read(operand, width_of(operand), signed=True)
    assert isinstance(operand, int)
    return operand


def wrap(number: int, width: int = 2) -> int:
    """`number` wrapped to a signed value of `width` bytes."""
    bits = 8 * width
    number &= (1 << bits) - 1
    return number - (1 << bits) if number >> (bits - 1) else number


def bit_after(address: Address, count: int) -> Address:
    """The bit `count` places after bit `address` (CMP's D, D+1, D+2: M0, M1, M2 or Y6, Y7, Y10)."""
    index = address.byte * 8 + (address.bit or 0) + count
    return Address(address.area, index // 8, index % 8)


def rising(state: dict, act: bool) -> bool:
    """True when `act` went on since the call site's last execution (off at power-on)."""
    before = state.get("prev", False)
    state["prev"] = bool(act)
    return bool(act) and not before


def _add_flags(memory: Memory, exact: int, stored: int) -> None:
    memory.set_bit(M1020, stored == 0)
    memory.set_bit(M1021, exact < -32768)
    memory.set_bit(M1022, exact > 32767)


def _mov(memory: Memory, params: tuple) -> None:
    source, output = params
    memory.write(output, value(memory, source), DEVICES.width_at(output))


def _add(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    exact = value(memory, s1) + value(memory, s2)
    memory.write(output, exact, 2)
    _add_flags(memory, exact, wrap(exact))


def _sub(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    exact = value(memory, s1) - value(memory, s2)
    memory.write(output, exact, 2)
    _add_flags(memory, exact, wrap(exact))


def _mul(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    memory.write(output, value(memory, s1) * value(memory, s2), 4)


def _div(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    a, b = value(memory, s1), value(memory, s2)
    if b == 0:
        memory.set_bit(M1067, True)
        memory.set_bit(M1068, True)
        return
    quotient = abs(a) // abs(b) * (1 if (a < 0) == (b < 0) else -1)  # toward zero
    memory.write(output, quotient, 2)
    memory.write(output.offset(2), a - quotient * b, 2)


def _inc(memory: Memory, params: tuple) -> None:
    (output,) = params
    memory.write(output, value(memory, output) + 1, DEVICES.width_at(output))


def _dec(memory: Memory, params: tuple) -> None:
    (output,) = params
    memory.write(output, value(memory, output) - 1, DEVICES.width_at(output))


def _results(memory: Memory, output: Address, which: int) -> None:
    for k in range(3):
        memory.set_bit(bit_after(output, k), k == which)


def _cmp(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    a, b = value(memory, s1), value(memory, s2)
    _results(memory, output, 0 if a > b else 1 if a == b else 2)


def _zcp(memory: Memory, params: tuple) -> None:
    low, high, source, output = params
    lo, hi, s = value(memory, low), value(memory, high), value(memory, source)
    _results(memory, output, 0 if s < lo else 2 if s > hi else 1)


# What a data row does, by its row's `operation` (its P form: `pulse`).
_OPERATIONS: dict[Operation, Callable[[Memory, tuple], None]] = {
    Operation.MOVE: _mov, Operation.ADD: _add, Operation.SUBTRACT: _sub,
    Operation.MULTIPLY: _mul, Operation.DIVIDE: _div, Operation.INCREMENT: _inc,
    Operation.DECREMENT: _dec, Operation.COMPARE: _cmp, Operation.ZONE_COMPARE: _zcp,
}


def _make(operation: Callable[[Memory, tuple], None], pulse: bool) -> Impl:
    def run(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
        act = bool(inputs[-1])
        if rising(state, act) if pulse else act:
            operation(ctx.memory, params)
        return act

    run.__doc__ = f"Delta {operation.__name__[1:].upper()}{'P' if pulse else ''}."
    return run


for _row in ROWS:
    if _row.operation in _OPERATIONS:
        function(_row.name)(_make(_OPERATIONS[_row.operation], _row.pulse))


@function("DVP.PLS")
def pls(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """The output bit is on for the one scan in which the input went on."""
    act = bool(inputs[-1])
    ctx.memory.set_bit(params[0], rising(state, act))
    return act


@function("DVP.PLF")
def plf(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """The output bit is on for the one scan in which the input went off."""
    act = bool(inputs[-1])
    before = state.get("prev", False)
    state["prev"] = act
    ctx.memory.set_bit(params[0], before and not act)
    return act
