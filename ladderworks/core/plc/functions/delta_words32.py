"""Delta DVP 32-bit data instructions: DMOV, DADD, DSUB, DMUL, DDIV, DINC, DDEC, DCMP, DZCP
and their pulse forms (DMOVP ...), and the helpers the other Delta families share.

A 32-bit operand is a device pair, low word first (D0 = low 16 bits, D1 = high): D, T, or a
C200-C255 counter (32-bit itself); a C0-C199 counter is its 16-bit value. K/H constants are
32-bit. DADD/DSUB set M1020 (zero), M1021 (borrow) and M1022 (carry) as ADD does; DMUL writes
its 64-bit product to D..D+3; DDIV its quotient to D, D+1 and remainder to D+2, D+3 (toward
zero); a division by zero writes nothing and sets M1067/M1068. docs/dialects.md.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

from ladderworks.core.address import Address
from ladderworks.core.dialects.delta import DEVICES
from ladderworks.core.dialects.delta.rows_extra import ACTIONS, FAMILIES
from ladderworks.core.instructions import lookup
from ladderworks.core.plc.functions import FunctionContext, fits, function
from ladderworks.core.plc.functions.dvp_data import (
    M1020,
    M1021,
    M1022,
    M1067,
    M1068,
    Impl,
    bit_after,
    rising,
    value,
    wrap,
)
from ladderworks.core.plc.memory import Memory

Action = Callable[[Memory, tuple], None]
LOW32, HIGH32 = -(2**31), 2**31 - 1


@cache
def width32(address: Address) -> int:
    """The bytes a 32-bit operand at `address` has: 4, or 2 for a C0-C199 counter."""
    found = DEVICES.device_of(address)
    if found is not None and found[0].wide_from is not None:  # a counter: its own width
        return found[0].width(found[1])
    return 4


def value32(memory: Memory, operand: object) -> int:
    """A 32-bit source operand's value: a constant, or a device pair (signed)."""
    if isinstance(operand, Address):
        return memory.read(operand, width32(operand), signed=True)
    assert isinstance(operand, int)
    return operand


def store32(memory: Memory, output: Address, number: int) -> None:
    """Write `number` to a 32-bit operand (a C0-C199 counter gets its low 16 bits); a pair
    past the end of its area (D4999 reached by a block's step) is an operation error."""
    width = width32(output)
    if not fits(memory, output, width):
        operation_error(memory)
        return
    memory.write(output, number, width)


def operation_error(memory: Memory) -> None:
    """M1067 and M1068 on: an operation error (a division by zero, a value out of range)."""
    memory.set_bit(M1067, True)
    memory.set_bit(M1068, True)


def flags(memory: Memory, exact: int, low: int, high: int) -> None:
    """M1020 zero, M1021 borrow (below `low`), M1022 carry (above `high`) of a result."""
    memory.set_bit(M1020, wrap(exact, 4 if high > 32767 else 2) == 0)
    memory.set_bit(M1021, exact < low)
    memory.set_bit(M1022, exact > high)


def results(memory: Memory, output: Address, which: int) -> None:
    """CMP-like result bits: bit `which` of output, output+1, output+2 on, the others off."""
    for k in range(3):
        memory.set_bit(bit_after(output, k), k == which)


def toward_zero(a: int, b: int) -> int:
    """a / b rounded toward zero (b != 0)."""
    return abs(a) // abs(b) * (1 if (a < 0) == (b < 0) else -1)


def _move(memory: Memory, params: tuple) -> None:
    source, output = params
    store32(memory, output, value32(memory, source))


def _add(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    exact = value32(memory, s1) + value32(memory, s2)
    store32(memory, output, exact)
    flags(memory, exact, LOW32, HIGH32)


def _subtract(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    exact = value32(memory, s1) - value32(memory, s2)
    store32(memory, output, exact)
    flags(memory, exact, LOW32, HIGH32)


def _multiply(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    memory.write(output, value32(memory, s1) * value32(memory, s2), 8)


def _divide(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    a, b = value32(memory, s1), value32(memory, s2)
    if b == 0:
        operation_error(memory)
        return
    quotient = toward_zero(a, b)
    memory.write(output, quotient, 4)
    memory.write(output.offset(4), a - quotient * b, 4)


def _increment(memory: Memory, params: tuple) -> None:
    (output,) = params
    store32(memory, output, wrap(value32(memory, output) + 1, 4))


def _decrement(memory: Memory, params: tuple) -> None:
    (output,) = params
    store32(memory, output, wrap(value32(memory, output) - 1, 4))


def _compare(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    a, b = value32(memory, s1), value32(memory, s2)
    results(memory, output, 0 if a > b else 1 if a == b else 2)


def _zone(memory: Memory, params: tuple) -> None:
    low, high, source, output = params
    lo, hi, s = value32(memory, low), value32(memory, high), value32(memory, source)
    results(memory, output, 0 if s < lo else 2 if s > hi else 1)


def make(action: Action, pulse: bool, module: str) -> Impl:
    """The implementation (in `module`) of a row doing `action` while its input is on
    (`pulse`: in the scan its input went on); it passes its input on."""
    def run(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
        act = bool(inputs[-1])
        if rising(state, act) if pulse else act:
            action(ctx.memory, params)
        return act

    run.__doc__ = f"Delta {action.__name__.strip('_')}{' (pulse)' if pulse else ''}."
    run.__module__ = module  # the family module that registers it
    return run


def register(module: str, actions: dict[str, Action]) -> None:
    """Register every row of family module `module` (rows_extra.FAMILIES) by its action."""
    for name in FAMILIES[module.rpartition(".")[2]]:
        spec = lookup(name)
        assert spec is not None, name
        if ACTIONS[name] in actions:
            function(name)(make(actions[ACTIONS[name]], spec.pulse, module))


register(__name__, {
    "move": _move, "add": _add, "subtract": _subtract, "multiply": _multiply,
    "divide": _divide, "increment": _increment, "decrement": _decrement,
    "compare": _compare, "zone": _zone})

__all__ = ["store32", "value", "value32", "width32"]
