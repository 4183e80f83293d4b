"""S7-1200 MOVE, ADD, SUB, MUL, DIV, INC, DEC, CONVERT on typed values (core/plc/typed.py).

A box runs when EN is 1; ENO (its result) is 0 when it did not run or when the result does not
fit its type (the wrapped value is still written, as the S7-1200 does for integers) or an
integer division by 0 (nothing written). Integer DIV truncates toward 0. Real/LReal: IEEE-754
in double, never an exception: a NaN operand gives that NaN made quiet (the first one), another
NaN result is `math.nan`, x / ±0 is ±infinity, a Real result too large is written ±infinity;
ENO 0 when the result is not finite (or past the largest Real). docs/dialects.md, S7-1200.
"""

from __future__ import annotations

import math

from ladderworks.core.plc import typed
from ladderworks.core.plc.functions import FunctionContext, function

_INTEGER_RESULT = {"S7.ADD": lambda a, b: a + b, "S7.SUB": lambda a, b: a - b,
                   "S7.MUL": lambda a, b: a * b}


def float_result(name: str, a: float, b: float) -> float:
    """ADD/SUB/MUL/DIV of two doubles, the same on every machine (no exception): a NaN
    operand's NaN made quiet (IN1's first), any other NaN `math.nan`, x / ±0 IEEE's."""
    if a != a or b != b:
        return typed.quiet(a if a != a else b)
    if name != "S7.DIV":
        result = _INTEGER_RESULT[name](a, b)
    elif b:
        result = a / b
    else:
        result = math.copysign(math.inf, a) * math.copysign(1.0, b) if a else math.nan
    return math.nan if result != result else result


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
            result: int | float = float_result(name, float(a), float(b))
        else:
            result = int(a / b) if abs(a) < 2**52 else (abs(int(a)) // abs(int(b))) * (
                1 if (a >= 0) == (b >= 0) else -1)
    elif vtype in typed.FLOATS:
        result = float_result(name, float(a), float(b))
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
