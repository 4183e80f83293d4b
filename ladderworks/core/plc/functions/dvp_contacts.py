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

from ladderworks.core.dialects.delta.instructions import COMPARISONS
from ladderworks.core.plc.functions import FunctionContext, function
from ladderworks.core.plc.functions.dvp_data import Impl, value

_TESTS: dict[str, Callable[[int, int], bool]] = {
    "=": operator.eq, ">": operator.gt, "<": operator.lt, "<>": operator.ne,
    "<=": operator.le, ">=": operator.ge,
}
assert tuple(_TESTS) == COMPARISONS


def _joined(start: str, contact: bool, inputs: tuple[bool, ...]) -> bool:
    if start == "LD":
        return contact
    if start == "AND":
        return bool(inputs[-1]) and contact
    return bool(inputs[-1]) or contact


def _compare(start: str, test: Callable[[int, int], bool]) -> Impl:
    def run(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
        s1, s2 = params
        return _joined(start, test(value(ctx.memory, s1), value(ctx.memory, s2)), inputs)

    return run


def _edge(start: str, falling: bool) -> Impl:
    def run(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
        now = bool(ctx.memory.bit(params[0]))
        before = state.get("prev", False)
        state["prev"] = now
        return _joined(start, (before and not now) if falling else (now and not before), inputs)

    return run


for _op, _test in _TESTS.items():
    for _start in ("LD", "AND", "OR"):
        function(f"DVP.{_start}{_op}")(_compare(_start, _test))
    function(f"DVP.LD{_op}.STK")(_compare("LD", _test))
for _kind in ("P", "F"):
    for _start in ("LD", "AND", "OR"):
        function(f"DVP.{_start}{_kind}")(_edge(_start, _kind == "F"))
    function(f"DVP.LD{_kind}.STK")(_edge("LD", _kind == "F"))
