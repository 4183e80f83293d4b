"""Fatek FBs contacts as native code (core/plc/functions/fatek_contacts.py, fatek_timing.py):
the comparison contacts FUN 170-175 starting a rung or a block (.ORG, .LD: the contact alone)
and in parallel (.OR: IN or the contact), no state; the TU/TD edge contacts in series (IN and
the edge) and in those places, their "before" (the device's bit when the contact last ran) a
bit of the call site's state block."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.dialects.fatek.rows import PLACED, SERIES_OF
from ladderworks.core.instruction_fields import Combine, Operation
from ladderworks.core.plc.functions import REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.fatek_data import DOUBLE
from ladderworks.core.plc.native.builtins import Emitter
from ladderworks.core.plc.native.fatek import _operand
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import BEFORE, HAS_BEFORE, Block, _fits

_PREDICATES = {Operation.EQUAL: "eq", Operation.GREATER: "sgt", Operation.LESS: "slt",
               Operation.NOT_EQUAL: "ne", Operation.GREATER_EQUAL: "sge",
               Operation.LESS_EQUAL: "sle"}
_EDGES = (Operation.RISING, Operation.FALLING)
# a row with its state in a block (stateful.ROWS' emitters)
StatefulEmitter = Callable[[Block, FunctionImpl, Sequence[object], list[str]], str | None]


def _placed(f: FunctionText, combine: Combine, contact: str, inputs: list[str]) -> str:
    """The contact alone (READ), or IN or the contact (OR); i8."""
    if combine is Combine.OR:
        return f.value(f"or i8 {inputs[-1]}, {contact}")
    return contact


def _compare(predicate: str, combine: Combine) -> Emitter:
    """A placed comparison contact: Sa op Sb (signed, 2 or 4 bytes by the mode's D bit)."""

    def emit(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
        if len(params) != 3 or not isinstance(params[0], int) or \
                (combine is Combine.OR and not inputs):
            return None
        size = 4 if params[0] & DOUBLE else 2
        a_of, b_of = _operand(params[1], size), _operand(params[2], size)
        if a_of is None or b_of is None:
            return None
        holds = f.value(f"icmp {predicate} i64 {a_of(f)}, {b_of(f)}")
        return _placed(f, combine, f.value(f"zext i1 {holds} to i8"), inputs)

    return emit


def edge(b: Block, rising: bool, device: object) -> str | None:
    """`fatek_timing.edge`: the device's bit against "before" (False when absent), then
    "before" = the bit; i8 1 on the edge."""
    if not (isinstance(device, Address) and device.bit is not None and _fits(device, 1)):
        return None
    f = b.f
    flags = b.flags()
    now = f.bit(device.area, device.byte, device.bit, False)
    held = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {BEFORE}')}, 0")
    before = f.value(f"zext i1 {held} to i8")
    kept = f.value(f"or i32 {f.value(f'and i32 {flags}, {~BEFORE}')}, {HAS_BEFORE}")
    wide = f.value(f"shl i32 {f.value(f'zext i8 {now} to i32')}, {BEFORE.bit_length() - 1}")
    b.set_flags(flags, f.value(f"or i32 {kept}, {wide}"))
    if rising:
        return f.value(f"and i8 {now}, {f.value(f'xor i8 {before}, 1')}")
    return f.value(f"and i8 {before}, {f.value(f'xor i8 {now}, 1')}")


def _series_edge(rising: bool) -> StatefulEmitter:
    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        if len(params) != 1 or not inputs:
            return None
        contact = edge(b, rising, params[0])
        return None if contact is None else b.f.value(f"and i8 {contact}, {inputs[0]}")

    return emit


def _placed_edge(rising: bool, combine: Combine) -> StatefulEmitter:
    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        if len(params) != 1 or (combine is Combine.OR and not inputs):
            return None
        contact = edge(b, rising, params[0])
        return None if contact is None else _placed(b.f, combine, contact, inputs)

    return emit


def _rows() -> tuple[dict[FunctionImpl, Emitter], dict[FunctionImpl,
                                                       tuple[str, StatefulEmitter]]]:
    """The placed rows' emitters, and the edge rows' (placed and series) with their kind."""
    load_all()
    emitters: dict[FunctionImpl, Emitter] = {}
    stateful: dict[FunctionImpl, tuple[str, StatefulEmitter]] = {}
    for spec in PLACED:
        impl, series = REGISTRY.get(spec.name), SERIES_OF[spec.name]
        rising = spec.operation is Operation.RISING
        if impl is not None and spec.operation in _EDGES:
            stateful[impl] = ("fatek edge", _placed_edge(rising, spec.combine))
        elif impl is not None and spec.operation in _PREDICATES:
            emitters[impl] = _compare(_PREDICATES[spec.operation], spec.combine)
        if spec.operation in _EDGES and series.name in REGISTRY:  # the series row: TU, TD
            stateful[REGISTRY[series.name]] = ("fatek edge", _series_edge(rising))
    return emitters, stateful


EMITTERS, STATEFUL = _rows()
