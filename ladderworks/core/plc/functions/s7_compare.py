"""S7-1200 comparisons ==, <>, >, <, >=, <= on integers, Real and Time; IN_RANGE / OUT_RANGE
(bounds inclusive); OK / NOT_OK (a valid Real: finite, not denormal). A comparison is a contact:
its result is its input AND the test (001:1097-1458; system manual V4.2 p. 252)."""

from __future__ import annotations

import operator
from collections.abc import Callable
from typing import Any

from ladderworks.core.plc import typed
from ladderworks.core.plc.functions import FunctionContext, FunctionImpl, function

_TESTS: dict[str, Callable[[Any, Any], Any]] = {
    "S7.EQ": operator.eq, "S7.NE": operator.ne, "S7.GT": operator.gt, "S7.LT": operator.lt,
    "S7.GE": operator.ge, "S7.LE": operator.le}


def _comparison(name: str, test: Callable[[Any, Any], Any]) -> FunctionImpl:
    def compare(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                params: tuple) -> bool:
        vtype = typed.ValueType(params[0])
        if not inputs[0]:
            return False
        return bool(test(typed.read(ctx.memory, params[1], vtype),
                         typed.read(ctx.memory, params[2], vtype)))

    compare.__name__ = compare.__qualname__ = name.replace(".", "_").lower()
    compare.__doc__ = f"{name}: IN AND (IN1 {name[3:]} IN2)."
    return compare


for _name, _test in _TESTS.items():
    function(_name)(_comparison(_name, _test))


def _range(ctx: FunctionContext, params: tuple) -> bool:
    vtype = typed.ValueType(params[0])
    low, value, high = (typed.read(ctx.memory, p, vtype) for p in params[1:4])
    return bool(low <= value <= high)


@function("S7.IN_RANGE")
def in_range(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """IN AND MIN ≤ VAL ≤ MAX."""
    return bool(inputs[0]) and _range(ctx, params)


@function("S7.OUT_RANGE")
def out_range(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
              params: tuple) -> bool:
    """IN AND (VAL < MIN OR VAL > MAX)."""
    return bool(inputs[0]) and not _range(ctx, params)


@function("S7.OK")
def ok(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """IN AND the Real is valid."""
    return bool(inputs[0]) and typed.valid_real(
        float(typed.read(ctx.memory, params[0], typed.ValueType.REAL)))


@function("S7.NOT_OK")
def not_ok(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """IN AND the Real is invalid (±INF, NaN, denormal)."""
    return bool(inputs[0]) and not typed.valid_real(
        float(typed.read(ctx.memory, params[0], typed.ValueType.REAL)))
