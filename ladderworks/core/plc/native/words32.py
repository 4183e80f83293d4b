"""Delta DVP's 32-bit data rows as native code (DMOV, DADD, DSUB, DMUL, DDIV, DINC, DDEC,
DCMP, DZCP and their pulse forms: core/plc/functions/delta_words32.py), made as words.py makes
the 16-bit ones: a 32-bit operand is a device pair or a C200-C255 counter (a C0-C199 counter
its 16 bits); an output pair past its area's end (an operation error in Python) calls back."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.dialects.delta.rows_extra import ACTIONS
from ladderworks.core.instructions import lookup
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, delta_words32, load_all
from ladderworks.core.plc.functions.dvp_data import M1020, M1021, M1022
from ladderworks.core.plc.native import words
from ladderworks.core.plc.native.builtins import _fits, _store
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.words import (
    Prepare,
    _bit,
    _place,
    _Refused,
    _row,
    _write,
    divided,
)

_I32 = (-(1 << 31), (1 << 31) - 1)
Body = Callable[[FunctionText], None]


def _width(operand: object) -> int:
    if not isinstance(operand, Address):
        raise _Refused
    width = delta_words32.width32(operand)
    if width not in (2, 4) or not _fits(operand, width):
        raise _Refused
    return width


def _source(operand: object) -> Callable[[FunctionText], str]:
    """`value32` as an i64 (checked now, emitted when called)."""
    return words._source(operand, _width)


def _output(operand: object) -> tuple[Address, int]:
    width = _width(operand)
    assert isinstance(operand, Address)
    return operand, width


def _move(params: Sequence[object]) -> Body:
    source, output = params
    read, (place, width) = _source(source), _output(output)
    return lambda f: _write(f, place, read(f), width)


def _add_sub(operator: str) -> Prepare:
    def prepare(params: Sequence[object]) -> Body:
        s1, s2, output = params
        first, second, (place, width) = _source(s1), _source(s2), _output(output)
        for flag in (M1020, M1021, M1022):
            _place(flag, 1)

        def body(f: FunctionText) -> None:
            exact = f.value(f"{operator} i64 {first(f)}, {second(f)}")
            _write(f, place, exact, width)
            low = f.value(f"trunc i64 {exact} to i32")
            _bit(f, M1020, f.value(f"icmp eq i32 {low}, 0"))
            _bit(f, M1021, f.value(f"icmp slt i64 {exact}, {_I32[0]}"))
            _bit(f, M1022, f.value(f"icmp sgt i64 {exact}, {_I32[1]}"))

        return body

    return prepare


def _mul(params: Sequence[object]) -> Body:
    s1, s2, output = params
    first, second, place = _source(s1), _source(s2), _place(output, 8)
    return lambda f: _store(f, place, 8, f.value(f"mul i64 {first(f)}, {second(f)}"))


def _div(params: Sequence[object]) -> Body:
    s1, s2, output = params
    return divided(_source(s1), _source(s2), _place(output, 8), 4)


def _step(amount: int) -> Prepare:
    def prepare(params: Sequence[object]) -> Body:
        (output,) = params
        read, (place, width) = _source(output), _output(output)
        return lambda f: _write(f, place, f.value(f"add i64 {read(f)}, {amount}"), width)

    return prepare


_PREPARE: dict[str, Prepare] = {
    "move": _move, "add": _add_sub("add"), "subtract": _add_sub("sub"), "multiply": _mul,
    "divide": _div, "increment": _step(1), "decrement": _step(-1),
    "compare": words.compared(_width), "zone": words.zone_compared(_width),
}


def _rows(pulse: bool) -> dict[FunctionImpl, Prepare]:
    """delta_words32's rows (pulse forms or not), by their implementation."""
    load_all()
    found: dict[FunctionImpl, Prepare] = {}
    for name, action in ACTIONS.items():
        impl, spec = REGISTRY.get(name), lookup(name)
        if impl is None or spec is None or spec.pulse != pulse or action not in _PREPARE \
                or getattr(impl, "__module__", "") != delta_words32.__name__:
            continue
        found[impl] = _PREPARE[action]
    return found


EMITTERS = {impl: _row(prepare) for impl, prepare in _rows(False).items()}
PULSES = _rows(True)
