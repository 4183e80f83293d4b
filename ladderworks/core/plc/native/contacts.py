"""Delta DVP's comparison and edge contacts as native code (core/plc/functions/dvp_contacts.py):
LD= … OR>= of 16-bit values (a C200-C255 operand 32-bit) and DLD= … DOR>= of 32-bit ones,
joined as the row's `combine` says; LDP/LDF/ANDP/ANDF/ORP/ORF with the bit's last value as
the state's "prev"; PLS/PLF the same way. Each read from its implementation's closure
(its test, join and width)."""

from __future__ import annotations

import operator
from collections.abc import Sequence

from ladderworks.core.address import Address
from ladderworks.core.instructions import Combine
from ladderworks.core.plc.functions import (
    REGISTRY,
    FunctionImpl,
    dvp_contacts,
    dvp_data,
    load_all,
)
from ladderworks.core.plc.functions.delta_words32 import value32
from ladderworks.core.plc.native import words, words32
from ladderworks.core.plc.native.builtins import Emitter, _fits
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import HAS_PREV, PREV, Block

_PREDICATES = {operator.eq: "eq", operator.gt: "sgt", operator.lt: "slt", operator.ne: "ne",
               operator.le: "sle", operator.ge: "sge"}


def _cells(impl: object) -> dict[str, object]:
    code = getattr(impl, "__code__", None)
    closure = getattr(impl, "__closure__", None) or ()
    if code is None:
        return {}
    return {name: cell.cell_contents for name, cell in zip(code.co_freevars, closure,
                                                          strict=False)}


def _join(f: FunctionText, combine: object, contact: str, inputs: list[str]) -> str | None:
    """The contact (i1) joined with the input as `_joined` does, as i8."""
    value = f.value(f"zext i1 {contact} to i8")
    if combine is Combine.READ:
        return value
    if not inputs:
        return None
    return f.value(f"{'and' if combine is Combine.AND else 'or'} i8 {inputs[-1]}, {value}")


def _compare(combine: object, predicate: str, wide: bool) -> Emitter:
    source = words32._source if wide else words._source

    def emit(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
        if len(params) != 2 or (combine is not Combine.READ and not inputs):
            return None
        try:
            first, second = source(params[0]), source(params[1])
        except (words._Refused, ValueError, TypeError, KeyError):
            return None
        contact = f.value(f"icmp {predicate} i64 {first(f)}, {second(f)}")
        return _join(f, combine, contact, inputs)

    return emit


def edge(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    """LDP … ORF: the bit now against its value at the last execution (kept as "prev")."""
    combine, falling = EDGES[impl]
    if len(params) != 1 or (combine is not Combine.READ and not inputs):
        return None
    (address,) = params
    if not (isinstance(address, Address) and address.bit is not None and _fits(address, 1)):
        return None
    f = b.f
    now = f.truth(f.bit(address.area, address.byte, address.bit, False))
    flags = b.flags()
    before = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {PREV}')}, 0")
    kept = f.value(f"or i32 {f.value(f'and i32 {flags}, {~PREV}')}, {HAS_PREV}")
    b.set_flags(flags, f.value(f"select i1 {now}, i32 {f.value(f'or i32 {kept}, {PREV}')}, "
                               f"i32 {kept}"))
    if falling:
        contact = f.value(f"and i1 {before}, {f.value(f'xor i1 {now}, true')}")
    else:
        contact = f.value(f"and i1 {now}, {f.value(f'xor i1 {before}, true')}")
    return _join(f, combine, contact, inputs)


def _rows() -> tuple[dict[FunctionImpl, Emitter], dict[FunctionImpl, tuple[object, bool]]]:
    load_all()
    compares: dict[FunctionImpl, Emitter] = {}
    edges: dict[FunctionImpl, tuple[object, bool]] = {}
    for impl in set(REGISTRY.values()):
        if getattr(impl, "__module__", "") != dvp_contacts.__name__:
            continue
        cells = _cells(impl)
        if "test" in cells and cells["test"] in _PREDICATES and "read" in cells:
            compares[impl] = _compare(cells["combine"], _PREDICATES[cells["test"]],
                                      cells["read"] is value32)
        elif "falling" in cells and isinstance(cells["falling"], bool):
            edges[impl] = (cells["combine"], cells["falling"])
    return compares, edges


EMITTERS, EDGES = _rows()


def pls_plf(b: Block, impl: FunctionImpl, params: Sequence[object],
            inputs: list[str]) -> str | None:
    """PLS / PLF: the output bit on for the scan the input went on / off (its last value kept
    as "prev"); W1 = the input."""
    if len(params) != 1 or not inputs:
        return None
    (address,) = params
    if not (isinstance(address, Address) and address.bit is not None and _fits(address, 1)):
        return None
    f = b.f
    act = f.truth(inputs[-1])
    flags = b.flags()
    before = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {PREV}')}, 0")
    if impl is dvp_data.plf:
        pulse = f.value(f"and i1 {before}, {f.value(f'xor i1 {act}, true')}")
    else:
        pulse = f.value(f"and i1 {act}, {f.value(f'xor i1 {before}, true')}")
    words._bit(f, address, pulse)
    kept = f.value(f"or i32 {f.value(f'and i32 {flags}, {~PREV}')}, {HAS_PREV}")
    b.set_flags(flags, f.value(f"select i1 {act}, i32 {f.value(f'or i32 {kept}, {PREV}')}, "
                               f"i32 {kept}"))
    return inputs[-1]


PULSES = (dvp_data.pls, dvp_data.plf)
