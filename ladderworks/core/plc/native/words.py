"""Delta DVP's 16-bit data rows as native code (MOV, ADD, SUB, MUL, DIV, INC, DEC, CMP, ZCP:
core/plc/functions/dvp_data.py), each while its input is on, W1 = the input; widths and
addresses known when the IR is made (a counter C200-C255 is 32-bit). Values are worked in i64
(the constants taken are 32-bit: every sum and product fits), stored wrapped to the width as
`Memory.write` does; a pulse form (MOVP ...) runs in the scan its input went on, the input
of its last execution kept in its state block (the dict's "prev")."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.dialects.delta.table import ROWS
from ladderworks.core.instructions import Operation
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.dvp_data import (
    _OPERATIONS,
    M1020,
    M1021,
    M1022,
    M1067,
    M1068,
    bit_after,
    width_of,
)
from ladderworks.core.plc.native.builtins import Emitter, _fits, _load, _store, _when
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import HAS_PREV, PREV, Block

_I32 = (-(1 << 31), (1 << 31) - 1)
Prepare = Callable[[Sequence[object]], Callable[[FunctionText], None]]


class _Refused(Exception):
    """A parameter the native code does not take: the op calls back."""


def _width(operand: object) -> int:
    """The width of a word operand the native code reads or writes."""
    if not isinstance(operand, Address):
        raise _Refused
    width = width_of(operand)
    if width not in (1, 2, 4, 8) or not _fits(operand, width):
        raise _Refused
    return width


def _source(operand: object, measure: Callable[[object], int] | None = None
            ) -> Callable[[FunctionText], str]:
    """`dvp_data.value` as an i64 (checked now, emitted when called); `measure` gives an
    address operand's width (`_width`, else the 32-bit forms' own)."""
    if isinstance(operand, bool) or not isinstance(operand, int | Address):
        raise _Refused
    if isinstance(operand, int):
        if not _I32[0] <= operand <= _I32[1]:
            raise _Refused
        return lambda f: str(operand)
    width = (measure or _width)(operand)
    return lambda f: f.value(f"sext i{8 * width} {_load(f, operand, width)} to i64")


def _place(address: object, width: int) -> Address:
    if not isinstance(address, Address) or not _fits(address, width):
        raise _Refused
    return address


def _write(f: FunctionText, address: Address, value: str, width: int) -> None:
    _store(f, address, width, f.value(f"trunc i64 {value} to i{8 * width}"))


def _bit(f: FunctionText, address: Address, value: str) -> None:
    """`Memory.set_bit` of an i1."""
    if address.bit is None or not _fits(address, 1):
        raise _Refused
    old = _load(f, address, 1)
    cleared = f.value(f"and i8 {old}, {~(1 << address.bit) & 0xFF}")
    bit = f.value(f"shl i8 {f.value(f'zext i1 {value} to i8')}, {address.bit}")
    _store(f, address, 1, f.value(f"or i8 {cleared}, {bit}"))


def _mov(params: Sequence[object]) -> Callable[[FunctionText], None]:
    source, output = params
    read, width = _source(source), _width(output)
    place = _place(output, width)
    return lambda f: _write(f, place, read(f), width)


def _add_sub(operator: str) -> Callable[[Sequence[object]], Callable[[FunctionText], None]]:
    def prepare(params: Sequence[object]) -> Callable[[FunctionText], None]:
        s1, s2, output = params
        first, second, place = _source(s1), _source(s2), _place(output, 2)
        for flag in (M1020, M1021, M1022):
            _place(flag, 1)

        def body(f: FunctionText) -> None:
            exact = f.value(f"{operator} i64 {first(f)}, {second(f)}")
            stored = f.value(f"trunc i64 {exact} to i16")
            _store(f, place, 2, stored)
            _bit(f, M1020, f.value(f"icmp eq i16 {stored}, 0"))
            _bit(f, M1021, f.value(f"icmp slt i64 {exact}, -32768"))
            _bit(f, M1022, f.value(f"icmp sgt i64 {exact}, 32767"))

        return body

    return prepare


def _mul(params: Sequence[object]) -> Callable[[FunctionText], None]:
    s1, s2, output = params
    first, second, place = _source(s1), _source(s2), _place(output, 4)
    return lambda f: _write(f, place, f.value(f"mul i64 {first(f)}, {second(f)}"), 4)


def divided(first: Callable[[FunctionText], str], second: Callable[[FunctionText], str],
            place: Address, word: int) -> Callable[[FunctionText], None]:
    """A division's body: the quotient and the remainder in two `word`-byte halves at `place`;
    by zero an operation error (M1067, M1068) and nothing written."""
    _place(M1067, 1), _place(M1068, 1)

    def body(f: FunctionText) -> None:
        a, c = first(f), second(f)
        zero, divide, after = f.label(), f.label(), f.label()
        f.add(f"br i1 {f.value(f'icmp eq i64 {c}, 0')}, label %{zero}, label %{divide}")
        f.start(zero)  # an operation error: nothing written
        _bit(f, M1067, "true")
        _bit(f, M1068, "true")
        f.add(f"br label %{after}")
        f.start(divide)
        _write(f, place, f.value(f"sdiv i64 {a}, {c}"), word)
        _write(f, place.offset(word), f.value(f"srem i64 {a}, {c}"), word)
        f.join(after)

    return body


def _div(params: Sequence[object]) -> Callable[[FunctionText], None]:
    s1, s2, output = params
    return divided(_source(s1), _source(s2), _place(output, 4), 2)


def _step(amount: int) -> Callable[[Sequence[object]], Callable[[FunctionText], None]]:
    def prepare(params: Sequence[object]) -> Callable[[FunctionText], None]:
        (output,) = params
        read, width = _source(output), _width(output)
        place = _place(output, width)
        return lambda f: _write(f, place, f.value(f"add i64 {read(f)}, {amount}"), width)

    return prepare


def _results(output: object) -> list[Address]:
    if not isinstance(output, Address):
        raise _Refused
    return [_place(bit_after(output, k), 1) for k in range(3)]


def compared(measure: Callable[[object], int] | None = None) -> Prepare:
    """CMP S1 S2 D: D, D+1, D+2 on for S1 > S2, =, <; `measure` the operands' width as
    `_source` takes it (words32's: 32 bits)."""

    def prepare(params: Sequence[object]) -> Callable[[FunctionText], None]:
        s1, s2, output = params
        first, second = _source(s1, measure), _source(s2, measure)
        bits = _results(output)

        def body(f: FunctionText) -> None:
            a, c = first(f), second(f)
            for place, test in zip(bits, ("sgt", "eq", "slt"), strict=True):
                _bit(f, place, f.value(f"icmp {test} i64 {a}, {c}"))

        return body

    return prepare


def zone_compared(measure: Callable[[object], int] | None = None) -> Prepare:
    """ZCP S1 S2 S D: D, D+1, D+2 on for S below S1, within, above S2; `measure` as
    `compared`'s."""

    def prepare(params: Sequence[object]) -> Callable[[FunctionText], None]:
        low, high, source, output = params
        lo, hi, read = (_source(p, measure) for p in (low, high, source))
        bits = _results(output)

        def body(f: FunctionText) -> None:
            lower, upper, s = lo(f), hi(f), read(f)
            below = f.value(f"icmp slt i64 {s}, {lower}")
            above = f.value(f"and i1 {f.value(f'xor i1 {below}, true')}, "
                            f"{f.value(f'icmp sgt i64 {s}, {upper}')}")
            inside = f.value(f"xor i1 {f.value(f'or i1 {below}, {above}')}, true")
            for place, value in zip(bits, (below, inside, above), strict=True):
                _bit(f, place, value)

        return body

    return prepare


_PREPARE: dict[Operation, Callable[[Sequence[object]], Callable[[FunctionText], None]]] = {
    Operation.MOVE: _mov, Operation.ADD: _add_sub("add"), Operation.SUBTRACT: _add_sub("sub"),
    Operation.MULTIPLY: _mul, Operation.DIVIDE: _div, Operation.INCREMENT: _step(1),
    Operation.DECREMENT: _step(-1), Operation.COMPARE: compared(),
    Operation.ZONE_COMPARE: zone_compared(),
}


def _row(prepare: Callable[[Sequence[object]], Callable[[FunctionText], None]]) -> Emitter:
    def emit(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
        if not inputs:
            return None
        try:
            body = prepare(params)
        except (_Refused, ValueError, TypeError, KeyError):
            return None
        _when(f, inputs[-1], lambda: body(f))
        return inputs[-1]

    return emit


def pulse(b: Block, impl: FunctionImpl, params: Sequence[object],
          inputs: list[str]) -> str | None:
    """A pulse form (`dvp_data.rising`): the input stored as "prev" in every execution, the
    row's work done when it went on; W1 = the input."""
    if not inputs:
        return None
    try:
        body = PULSES[impl](params)
    except (_Refused, ValueError, TypeError, KeyError):
        return None
    f = b.f
    flags = b.flags()
    act = f.truth(inputs[-1])
    before = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {PREV}')}, 0")
    kept = f.value(f"or i32 {f.value(f'and i32 {flags}, {~PREV}')}, {HAS_PREV}")
    b.set_flags(flags, f.value(f"select i1 {act}, i32 {f.value(f'or i32 {kept}, {PREV}')}, "
                               f"i32 {kept}"))
    run = f.value(f"and i1 {act}, {f.value(f'xor i1 {before}, true')}")
    _, after = f.branch_if(run)
    body(f)
    f.join(after)
    return inputs[-1]


def _rows(pulse: bool) -> dict[FunctionImpl, Callable[[Sequence[object]],
                                                    Callable[[FunctionText], None]]]:
    """The rows whose implementation is dvp_data's (pulse forms or not), by it."""
    load_all()
    found: dict[FunctionImpl, Callable[[Sequence[object]], Callable[[FunctionText], None]]] = {}
    for row in ROWS:
        impl = REGISTRY.get(row.name)
        action = _OPERATIONS.get(row.operation)
        cells = [cell.cell_contents for cell in getattr(impl, "__closure__", None) or ()]
        if impl is not None and row.operation in _PREPARE and row.pulse == pulse \
                and action in cells:
            found[impl] = _PREPARE[row.operation]
    return found


EMITTERS: dict[FunctionImpl, Emitter] = {impl: _row(prepare)
                                        for impl, prepare in _rows(False).items()}
PULSES = _rows(True)  # the pulse forms: stateful.py gives each a block
