"""Delta DVP contacts that are boxes in the table: comparisons (LD= ... OR>=) and edges (LDP,
LDF, ANDP, ANDF, ORP, ORF).

An LD form starts a value (its `.STK` row pushes it, an LD in the middle of a rung); an AND
form is its input AND the contact, an OR form its input OR the contact. A comparison compares
two 16-bit signed values (a C200..C255 operand: 32-bit). An edge contact is on for one
execution when its bit went on (P) or off (F) since the call site's last execution; its memory
is 0 at power-on (a bit already on gives a rising edge in the first scan). docs/dialects.md.
"""

from __future__ import annotations

import operator
from collections.abc import Callable

from ladderworks.core.dialects.delta.rows_extra import ACTIONS
from ladderworks.core.dialects.delta.table import FAMILIES, ROWS
from ladderworks.core.instructions import Combine, Operation
from ladderworks.core.plc.functions import FunctionContext, function
from ladderworks.core.plc.functions.delta_words32 import value32
from ladderworks.core.plc.functions.dvp_data import Impl, value

# A comparison contact's test, by its row's `operation`.
_TESTS: dict[Operation, Callable[[int, int], bool]] = {
    Operation.EQUAL: operator.eq, Operation.GREATER: operator.gt, Operation.LESS: operator.lt,
    Operation.NOT_EQUAL: operator.ne, Operation.LESS_EQUAL: operator.le,
    Operation.GREATER_EQUAL: operator.ge,
}


def _joined(combine: Combine, contact: bool, inputs: tuple[bool, ...]) -> bool:
    """The contact as its row's `combine` says: a new value (READ), or with its input."""
    if combine is Combine.READ:
        return contact
    if combine is Combine.AND:
        return bool(inputs[-1]) and contact
    return bool(inputs[-1]) or contact


def _compare(combine: Combine, test: Callable[[int, int], bool], wide: bool) -> Impl:
    read = value32 if wide else value  # DLD= ...: 32-bit operands (device pairs)

    def run(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
        s1, s2 = params
        return _joined(combine, test(read(ctx.memory, s1), read(ctx.memory, s2)), inputs)

    return run


def _edge(combine: Combine, falling: bool) -> Impl:
    def run(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
        now = bool(ctx.memory.bit(params[0]))
        before = state.get("prev", False)
        state["prev"] = now
        return _joined(combine, (before and not now) if falling else (now and not before),
                       inputs)

    return run


for _row in ROWS:  # each contact row by its fields: how it joins, what it tests
    if _row.name in FAMILIES["dvp_contacts"] and _row.name not in ACTIONS:  # (FLD=: floats)
        test = _TESTS.get(_row.operation)
        function(_row.name)(_compare(_row.combine, test, _row.params[0].width == 4)
                            if test is not None
                            else _edge(_row.combine, _row.operation is Operation.FALLING))
