"""S7-1200 MOVE, ADD, SUB, MUL, DIV, INC, DEC, CONVERT on typed values (core/plc/typed.py).

A box runs when EN is 1; ENO (its result) is 0 when it did not run or when the result does not
fit its type (the wrapped value is still written, as the S7-1200 does for integers) or a
division by 0 (nothing written). Integer DIV truncates toward 0. docs/dialects.md, S7-1200.
"""

from __future__ import annotations

import math

from ladderworks.core.plc import typed
from ladderworks.core.plc.functions import FunctionContext, function

_INTEGER_RESULT = {"S7.ADD": lambda a, b: a + b, "S7.SUB": lambda a, b: a - b,
                   "S7.MUL": lambda a, b: a * b}


@function("S7.MOVE")
def move(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """OUT1 := IN."""
    if not inputs[0]:
        return False
    vtype = typed.ValueType(params[0])
    typed.write(ctx.memory, params[2], vtype, typed.read(ctx.memory, params[1], vtype))
    return True


def _arithmetic(ctx: FunctionContext, name: str, inputs: tuple[bool, ...],
                params: tuple) -> bool:
    if not inputs[0]:
        return False
    vtype = typed.ValueType(params[0])
    a, b = typed.read(ctx.memory, params[1], vtype), typed.read(ctx.memory, params[2], vtype)
    if name == "S7.DIV":
        if b == 0 and vtype not in typed.FLOATS:
            return False
        if vtype in typed.FLOATS:
            result: int | float = a / b if b else math.copysign(math.inf, a) if a else math.nan
        else:
            result = int(a / b) if abs(a) < 2**52 else (abs(int(a)) // abs(int(b))) * (
                1 if (a >= 0) == (b >= 0) else -1)
    else:
        result = _INTEGER_RESULT[name](a, b)
    typed.write(ctx.memory, params[3], vtype, result)
    return typed.fits(result, vtype)


@function("S7.ADD")
def add(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """OUT := IN1 + IN2."""
    return _arithmetic(ctx, "S7.ADD", inputs, params)


@function("S7.SUB")
def sub(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """OUT := IN1 - IN2."""
    return _arithmetic(ctx, "S7.SUB", inputs, params)


@function("S7.MUL")
def mul(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """OUT := IN1 * IN2."""
    return _arithmetic(ctx, "S7.MUL", inputs, params)


@function("S7.DIV")
def div(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """OUT := IN1 / IN2."""
    return _arithmetic(ctx, "S7.DIV", inputs, params)


def _step(ctx: FunctionContext, inputs: tuple[bool, ...], params: tuple, delta: int) -> bool:
    if not inputs[0]:
        return False
    vtype = typed.ValueType(params[0])
    result = typed.read(ctx.memory, params[1], vtype) + delta
    typed.write(ctx.memory, params[1], vtype, result)
    return typed.fits(result, vtype)


@function("S7.INC")
def inc(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """IN/OUT := IN/OUT + 1."""
    return _step(ctx, inputs, params, 1)


@function("S7.DEC")
def dec(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """IN/OUT := IN/OUT - 1."""
    return _step(ctx, inputs, params, -1)


@function("S7.CONVERT")
def convert(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
            params: tuple) -> bool:
    """OUT (type `to`) := IN (type `type`); Real → integer rounds half to even (CONVERT)."""
    if not inputs[0]:
        return False
    source, target = typed.ValueType(params[0]), typed.ValueType(params[1])
    value = typed.read(ctx.memory, params[2], source)
    if target not in typed.FLOATS:
        if not math.isfinite(value):
            return False
        value = round(value)
    typed.write(ctx.memory, params[3], target, value)
    return typed.fits(value, target)
