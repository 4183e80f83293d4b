"""Delta DVP binary floating point: FLT/DFLT, INT/DINT, DEMOV, DEADD, DESUB, DEMUL, DEDIV,
DECMP, DEZCP, the functions DRAD ... DTANH, DLOG, DPOW (each with its pulse form), and the
contacts FLD= ... FOR>=.

A floating-point value is an IEEE 754 single in a device pair, low word first (D0 = low 16
bits); a K/H constant where a float is read is that integer as a float. FLT S D: the 16-bit
integer S (DFLT: the 32-bit S) as a float into D, D+1. INT S D: the float S without its
fraction (toward zero) into the 16-bit D (DINT: 32-bit); outside the range: operation error,
D kept. DEADD ... DEDIV: the float result, rounded to single precision; M1020 when it is 0,
M1021 when it is below the smallest normal float (it is kept), M1022 when it overflows (the
largest float is written, with its sign); of two NaNs, the first's; a division by 0:
operation error, D kept. DECMP /
DEZCP: as CMP / ZCP on floats. DSIN ... DTAN take, DASIN ... DATAN give, degrees while M1018
is on (else radians); a value outside a function's domain (DLN of 0, DASIN of 2, DLOG base 1)
is an operation error, D kept. FLD= ... compare two floats as LD= compares words.
docs/dialects.md.
"""

from __future__ import annotations

import math
import operator
import struct
from collections.abc import Callable

from ladderworks.core.dialects.delta import relay
from ladderworks.core.dialects.delta.rows_extra import ACTIONS, FAMILIES
from ladderworks.core.instructions import Combine, Operation, lookup
from ladderworks.core.plc.functions import FunctionContext, function
from ladderworks.core.plc.functions.delta_words32 import (
    Action,
    operation_error,
    register,
    results,
    store32,
    value32,
)
from ladderworks.core.plc.functions.dvp_data import M1020, M1021, M1022, Impl, value
from ladderworks.core.plc.memory import Memory

SMALLEST = 2.0 ** -126  # the smallest normal single
LARGEST = struct.unpack("<f", b"\xff\xff\x7f\x7f")[0]


def to_float(raw: int) -> float:
    """The single whose 32 bits are `raw`."""
    return float(struct.unpack("<f", (raw & 0xFFFF_FFFF).to_bytes(4, "little"))[0])


def bits_of(number: float) -> int:
    """The 32 bits of `number` as a single (too large: the largest single, with its sign)."""
    if math.isinf(number) or abs(number) > LARGEST:
        number = math.copysign(LARGEST, number)
    return int.from_bytes(struct.pack("<f", number), "little")


def read_float(memory: Memory, operand: object) -> float:
    """A float operand: a constant (an integer) or a device pair's bits."""
    if isinstance(operand, int):
        return float(operand)
    return to_float(value32(memory, operand))


def _store_float(memory: Memory, output: object, number: float) -> None:
    store32(memory, output, bits_of(number))  # type: ignore[arg-type]


def _float(memory: Memory, params: tuple) -> None:
    source, output = params
    _store_float(memory, output, float(value(memory, source)))


def _float32(memory: Memory, params: tuple) -> None:
    source, output = params
    _store_float(memory, output, float(value32(memory, source)))


def _integer(memory: Memory, params: tuple, bits: int) -> None:
    source, output = params
    number = read_float(memory, source)
    if not math.isfinite(number) \
            or not -(2.0 ** (bits - 1)) <= math.trunc(number) < 2.0 ** (bits - 1):
        operation_error(memory)
        return
    whole = math.trunc(number)
    memory.set_bit(M1020, whole == 0)
    if bits == 32:
        store32(memory, output, whole)
    else:
        memory.write(output, whole, 2)


def _integer16(memory: Memory, params: tuple) -> None:
    _integer(memory, params, 16)


def _integer32(memory: Memory, params: tuple) -> None:
    _integer(memory, params, 32)


def _fmove(memory: Memory, params: tuple) -> None:
    source, output = params
    _store_float(memory, output, read_float(memory, source))


def _arithmetic(memory: Memory, params: tuple, op: str) -> None:
    s1, s2, output = params
    a, b = read_float(memory, s1), read_float(memory, s2)
    if op == "/" and b == 0:
        operation_error(memory)
        return
    exact = a + b if op == "+" else a - b if op == "-" else a * b if op == "*" else a / b
    if math.isnan(a) and math.isnan(b):  # the first's NaN, as x86 (CPython's own order varies)
        exact = a
    stored = to_float(bits_of(exact))
    memory.set_bit(M1020, stored == 0)
    memory.set_bit(M1021, 0 < abs(stored) < SMALLEST)
    memory.set_bit(M1022, math.isinf(exact) or abs(exact) > LARGEST)
    _store_float(memory, output, stored)


def _add(memory: Memory, params: tuple) -> None:
    _arithmetic(memory, params, "+")


def _subtract(memory: Memory, params: tuple) -> None:
    _arithmetic(memory, params, "-")


def _multiply(memory: Memory, params: tuple) -> None:
    _arithmetic(memory, params, "*")


def _divide(memory: Memory, params: tuple) -> None:
    _arithmetic(memory, params, "/")


def _compare(memory: Memory, params: tuple) -> None:
    s1, s2, output = params
    a, b = read_float(memory, s1), read_float(memory, s2)
    results(memory, output, 0 if a > b else 1 if a == b else 2)


def _zone(memory: Memory, params: tuple) -> None:
    low, high, source, output = params
    lo, hi, s = (read_float(memory, low), read_float(memory, high),
                 read_float(memory, source))
    results(memory, output, 0 if s < lo else 2 if s > hi else 1)


M1018 = relay(1018)  # on: DSIN ... DTAN, DASIN ... DATAN in degrees (off: radians)


def _function(compute: Callable[[float], float], angle_in: bool = False,
              angle_out: bool = False) -> Action:
    def run(memory: Memory, params: tuple) -> None:
        source, output = params
        number = read_float(memory, source)
        degrees = bool(memory.bit(M1018))
        if angle_in and degrees:
            number = math.radians(number)
        try:
            result = compute(number)
        except (ValueError, OverflowError, ZeroDivisionError):
            operation_error(memory)
            return
        if angle_out and degrees:
            result = math.degrees(result)
        _result(memory, output, result)

    run.__name__ = compute.__name__
    return run


def _result(memory: Memory, output: object, exact: float) -> None:
    if math.isnan(exact):
        operation_error(memory)
        return
    stored = to_float(bits_of(exact))
    memory.set_bit(M1020, stored == 0)
    memory.set_bit(M1021, 0 < abs(stored) < SMALLEST)
    memory.set_bit(M1022, math.isinf(exact) or abs(exact) > LARGEST)
    _store_float(memory, output, stored)


def _log(memory: Memory, params: tuple) -> None:
    base, source, output = params
    b, x = read_float(memory, base), read_float(memory, source)
    if b <= 0 or b == 1 or x <= 0:
        operation_error(memory)
        return
    _result(memory, output, math.log(x, b))


def _power(memory: Memory, params: tuple) -> None:
    base, exponent, output = params
    try:
        exact = math.pow(read_float(memory, base), read_float(memory, exponent))
    except (ValueError, OverflowError, ZeroDivisionError):
        operation_error(memory)
        return
    _result(memory, output, exact)


_FUNCTIONS: dict[str, Action] = {
    "radians": _function(math.radians), "degrees": _function(math.degrees),
    "exp": _function(math.exp), "ln": _function(math.log), "sqrt": _function(math.sqrt),
    "sin": _function(math.sin, angle_in=True), "cos": _function(math.cos, angle_in=True),
    "tan": _function(math.tan, angle_in=True), "asin": _function(math.asin, angle_out=True),
    "acos": _function(math.acos, angle_out=True), "atan": _function(math.atan, angle_out=True),
    "sinh": _function(math.sinh), "cosh": _function(math.cosh), "tanh": _function(math.tanh),
    "log": _log, "power": _power}
_TESTS: dict[Operation, Callable[[float, float], bool]] = {
    Operation.EQUAL: operator.eq, Operation.GREATER: operator.gt, Operation.LESS: operator.lt,
    Operation.NOT_EQUAL: operator.ne, Operation.LESS_EQUAL: operator.le,
    Operation.GREATER_EQUAL: operator.ge}


def _contact(combine: Combine, test: Callable[[float, float], bool]) -> Impl:
    def run(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
        """FLD= ... FOR>=: compares two floats as its row's operation says."""
        f1, f2 = params
        on = test(read_float(ctx.memory, f1), read_float(ctx.memory, f2))
        if combine is Combine.READ:
            return on
        return bool(inputs[-1]) and on if combine is Combine.AND else bool(inputs[-1]) or on

    run.__module__ = __name__
    return run


for _name in FAMILIES["delta_float"]:
    if ACTIONS[_name] == "fcontact":
        _spec = lookup(_name)
        assert _spec is not None
        function(_name)(_contact(_spec.combine, _TESTS[_spec.operation]))


register(__name__, {**_FUNCTIONS,
    "float": _float, "float32": _float32, "integer": _integer16, "integer32": _integer32,
    "fmove": _fmove, "fadd": _add, "fsubtract": _subtract, "fmultiply": _multiply,
    "fdivide": _divide, "fcompare": _compare, "fzone": _zone})
