"""Fatek's edge (TU/TD) and comparison (FUN 170-175) contacts in their other places: starting a
rung or a block (`ORG TU X2`, `LDF 170`: the contact alone) and in parallel (`OR TU`, `ORF`:
IN OR the contact). The series place is the rows' own (fatek_timing, fatek_data)."""

from __future__ import annotations

from collections.abc import Callable

from ladderworks.core.dialects.fatek.rows import PLACED
from ladderworks.core.instructions import Combine, InstructionSpec, Operation
from ladderworks.core.plc.functions import FunctionContext, FunctionImpl, function
from ladderworks.core.plc.functions.fatek_data import compare, width
from ladderworks.core.plc.functions.fatek_timing import edge, operand_value

Test = Callable[[FunctionContext, dict, tuple], bool]


def _edge_test(rising: bool) -> Test:
    def test(ctx: FunctionContext, state: dict, params: tuple) -> bool:
        return edge(ctx, state, params[0], rising)

    return test


def _compare_test(symbol: str) -> Test:
    def test(ctx: FunctionContext, state: dict, params: tuple) -> bool:
        mode, sa, sb = params
        size = width(mode)
        return compare(symbol, operand_value(ctx.memory, sa, size),
                       operand_value(ctx.memory, sb, size))

    return test


def _placed(spec: InstructionSpec, test: Test) -> FunctionImpl:
    def impl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
             params: tuple) -> bool:
        """The contact alone (READ), or IN OR the contact (OR)."""
        contact = test(ctx, state, params)  # an edge's memory follows every execution
        return bool(inputs[-1]) or contact if spec.combine is Combine.OR else contact

    return impl


for _spec in PLACED:
    if _spec.operation in (Operation.RISING, Operation.FALLING):
        _test = _edge_test(_spec.operation is Operation.RISING)
    else:
        _test = _compare_test(_spec.operation.value)
    function(_spec.name)(_placed(_spec, _test))
