"""Delta DVP word arithmetic beyond the four operations: CML, RCR/RCL, BON, MEAN, SQR, ABS,
SWAP, GRY/GBIN, each with its 32-bit D form and pulse forms.

CML S D: D = NOT S. RCR/RCL D n: D and the carry M1022 rotated together by n bits (17 or 33
bits). BON S D n: bit D = bit n of S. MEAN S D n: the mean of the n words (pairs) from S,
toward zero. SQR S D: the integer square root; S < 0: operation error, D kept; M1020 when 0.
ABS D: D = |D| (-32768 stays). SWAP D: its high and low bytes exchanged (DSWAP: in each word).
GRY S D: S as Gray code; GBIN S D: Gray code S as binary; S < 0: operation error, D kept.
SMOV S m1 m2 D n: S and D as 4 BCD digits; the m2 digits of S from digit m1 down go to D from
digit n down, D's other digits kept (a value above 9999: operation error). BOUT D n: bit n of
D follows the input; BSET / BRST D n set / reset it while the input is on. SCAL S1 S2 S3 D:
D = S1 x S2 / 1000 + S3 (toward zero). SCLP S T D: D = (S - T+1) x (T+2 - T+3) / (T - T+1)
+ T+3, the table T: source maximum, source minimum, result maximum, result minimum (toward
zero; integers: M1162's floating-point mode not modelled). Out of range: operation error.
docs/dialects.md.
"""

from __future__ import annotations

from collections.abc import Callable
from math import isqrt

from ladderworks.core.address import Address
from ladderworks.core.dialects.delta.rows_extra import ACTIONS, FAMILIES
from ladderworks.core.plc.bcd import bcd_to_int, int_to_bcd
from ladderworks.core.plc.functions import FunctionContext, function
from ladderworks.core.plc.functions.delta_blocks import word_after
from ladderworks.core.plc.functions.delta_words32 import (
    Action,
    operation_error,
    register,
    store32,
    toward_zero,
    value32,
)
from ladderworks.core.plc.functions.dvp_data import M1020, M1022, Impl, value
from ladderworks.core.plc.memory import Memory

Wide = Callable[[Memory, tuple, bool], None]  # an action of both widths (`wide`: 32-bit)


def _reader(wide: bool) -> Callable[[Memory, object], int]:
    return value32 if wide else value


def _store(memory: Memory, output: Address, number: int, wide: bool) -> None:
    if wide:
        store32(memory, output, number)
    else:
        memory.write(output, number, 2)


def _complement(memory: Memory, params: tuple, wide: bool) -> None:
    source, output = params
    _store(memory, output, ~_reader(wide)(memory, source), wide)


def _carry_rotate(memory: Memory, params: tuple, wide: bool, right: bool) -> None:
    output, count = params
    bits = 32 if wide else 16
    n = value(memory, count)
    if not 1 <= n <= bits:
        operation_error(memory)
        return
    word = _reader(wide)(memory, output) & ((1 << bits) - 1)
    carry = memory.bit(M1022)
    for _ in range(n):
        if right:
            word, carry = word >> 1 | carry << (bits - 1), word & 1
        else:
            word, carry = (word << 1 | carry) & ((1 << bits) - 1), word >> (bits - 1) & 1
    _store(memory, output, word, wide)
    memory.set_bit(M1022, bool(carry))


def _bit_on(memory: Memory, params: tuple, wide: bool) -> None:
    source, output, which = params
    n = value(memory, which)
    if not 0 <= n < (32 if wide else 16):
        operation_error(memory)
        return
    memory.set_bit(output, bool(_reader(wide)(memory, source) >> n & 1))


def _mean(memory: Memory, params: tuple, wide: bool) -> None:
    source, output, count = params
    n = value(memory, count)
    if not 1 <= n <= 64:
        operation_error(memory)
        return
    if isinstance(source, int):
        numbers = [source] * n
    else:
        places = [word_after(source, k * (2 if wide else 1)) for k in range(n)]
        numbers = [_reader(wide)(memory, place) for place in places if place is not None]
    if numbers:
        _store(memory, output, toward_zero(sum(numbers), len(numbers)), wide)


def _root(memory: Memory, params: tuple, wide: bool) -> None:
    source, output = params
    number = _reader(wide)(memory, source)
    if number < 0:
        operation_error(memory)
        return
    result = isqrt(number)
    _store(memory, output, result, wide)
    memory.set_bit(M1020, result == 0)


def _absolute(memory: Memory, params: tuple, wide: bool) -> None:
    (output,) = params
    _store(memory, output, abs(_reader(wide)(memory, output)), wide)


def _swap(memory: Memory, params: tuple, wide: bool) -> None:
    (output,) = params
    raw = _reader(wide)(memory, output)
    swapped = ((raw & 0x00FF_00FF) << 8) | ((raw >> 8) & 0x00FF_00FF)
    _store(memory, output, swapped, wide)


def _gray(memory: Memory, params: tuple, wide: bool, encode: bool) -> None:
    source, output = params
    number = _reader(wide)(memory, source)
    if number < 0:
        operation_error(memory)
        return
    if encode:
        result = number ^ (number >> 1)
    else:
        result, shift = number, number >> 1
        while shift:
            result ^= shift
            shift >>= 1
    _store(memory, output, result, wide)


def _digit_move(memory: Memory, params: tuple) -> None:
    source, first, digits, output, to = params
    m1, m2, n = value(memory, first), value(memory, digits), value(memory, to)
    moved, kept = int_to_bcd(value(memory, source), 4), int_to_bcd(value(memory, output), 4)
    if moved is None or kept is None or not (1 <= m2 <= m1 <= 4 and m2 <= n <= 4):
        operation_error(memory)
        return
    for k in range(m2):
        digit = moved >> 4 * (m1 - 1 - k) & 0xF
        place = 4 * (n - 1 - k)
        kept = kept & ~(0xF << place) | digit << place
    memory.write(output, bcd_to_int(kept, 4) or 0, 2)


def _scale(memory: Memory, params: tuple) -> None:
    source, slope, offset, output = params
    exact = toward_zero(value(memory, source) * value(memory, slope), 1000) \
        + value(memory, offset)
    if not -32768 <= exact <= 32767:
        operation_error(memory)
        return
    memory.write(output, exact, 2)


def _scale_table(memory: Memory, params: tuple, wide: bool) -> None:
    source, table, output = params
    step = 2 if wide else 1
    places = [word_after(table, k * step) for k in range(4)]
    if any(place is None for place in places):
        operation_error(memory)
        return
    read = _reader(wide)
    top, bottom, high, low = (read(memory, place) for place in places)
    if top == bottom:
        operation_error(memory)
        return
    exact = toward_zero((read(memory, source) - bottom) * (high - low), top - bottom) + low
    lo, hi = (-(2**31), 2**31 - 1) if wide else (-32768, 32767)
    if not lo <= exact <= hi:
        operation_error(memory)
        return
    _store(memory, output, exact, wide)


def _bit_change(memory: Memory, params: tuple, wide: bool, on: bool) -> None:
    output, which = params
    n = value(memory, which)
    if not 0 <= n < (32 if wide else 16):
        operation_error(memory)
        return
    word = _reader(wide)(memory, output)
    _store(memory, output, word | 1 << n if on else word & ~(1 << n), wide)


def bit_out(wide: bool) -> Impl:
    """BOUT D n: bit n of D follows the input, on or off (as OUT); passes its input on."""
    def run(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
        act = bool(inputs[-1])
        _bit_change(ctx.memory, params, wide, act)
        return act

    run.__module__ = __name__
    return run


def _forms(action: Wide) -> tuple[Action, Action]:
    def narrow(memory: Memory, params: tuple) -> None:
        action(memory, params, False)

    def wide(memory: Memory, params: tuple) -> None:
        action(memory, params, True)

    narrow.__name__ = wide.__name__ = action.__name__
    return narrow, wide


def _actions() -> dict[str, Action]:
    found: dict[str, Action] = {}
    pairs: tuple[tuple[str, Wide], ...] = (
        ("complement", _complement), ("bit-on", _bit_on), ("mean", _mean), ("root", _root),
        ("absolute", _absolute), ("swap", _swap),
        ("carry-right", lambda m, p, w: _carry_rotate(m, p, w, True)),
        ("carry-left", lambda m, p, w: _carry_rotate(m, p, w, False)),
        ("to-gray", lambda m, p, w: _gray(m, p, w, True)),
        ("from-gray", lambda m, p, w: _gray(m, p, w, False)),
        ("bit-set", lambda m, p, w: _bit_change(m, p, w, True)),
        ("bit-reset", lambda m, p, w: _bit_change(m, p, w, False)),
        ("scale-table", _scale_table))
    for key, action in pairs:
        found[key], found[key + "32"] = _forms(action)
    found["digit-move"] = _digit_move
    found["scale"] = _scale
    return found


register(__name__, _actions())
for _name in FAMILIES["delta_math"]:
    if ACTIONS[_name].startswith("bit-out"):
        function(_name)(bit_out(ACTIONS[_name].endswith("32")))
