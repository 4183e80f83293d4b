"""Delta DVP word logic and conversion: WAND/WOR/WXOR (32-bit DAND/DOR/DXOR), NEG/DNEG,
ROR/ROL (DROR/DROL), BCD/BIN (DBCD/DBIN), each with its pulse form.

WAND S1 S2 D: D = S1 AND S2 bit by bit (OR, XOR alike). NEG D: D = -D (two's complement;
-32768 stays -32768). ROR/ROL D n: D rotated right/left by n bits in 16 (32) bits; the last
bit that went round is M1022 (carry). BCD S D: S (0-9999; DBCD 0-99999999) as BCD digits into
D; BIN S D: S's BCD digits as a binary number into D; a value out of range or a digit above 9
is an operation error (M1067, M1068) and D is kept. docs/dialects.md.
"""

from __future__ import annotations

from ladderworks.core.plc.bcd import bcd_to_int, int_to_bcd
from ladderworks.core.plc.functions.delta_words32 import (
    operation_error,
    register,
    store32,
    value32,
)
from ladderworks.core.plc.functions.dvp_data import M1022, value
from ladderworks.core.plc.memory import Memory


def _logic(memory: Memory, params: tuple, wide: bool, op: str) -> None:
    s1, s2, output = params
    read = value32 if wide else value
    a, b = read(memory, s1), read(memory, s2)
    result = a & b if op == "and" else a | b if op == "or" else a ^ b
    if wide:
        store32(memory, output, result)
    else:
        memory.write(output, result, 2)


def _and(memory: Memory, params: tuple) -> None:
    _logic(memory, params, False, "and")


def _or(memory: Memory, params: tuple) -> None:
    _logic(memory, params, False, "or")


def _xor(memory: Memory, params: tuple) -> None:
    _logic(memory, params, False, "xor")


def _and32(memory: Memory, params: tuple) -> None:
    _logic(memory, params, True, "and")


def _or32(memory: Memory, params: tuple) -> None:
    _logic(memory, params, True, "or")


def _xor32(memory: Memory, params: tuple) -> None:
    _logic(memory, params, True, "xor")


def _negate(memory: Memory, params: tuple) -> None:
    (output,) = params
    memory.write(output, -value(memory, output), 2)


def _negate32(memory: Memory, params: tuple) -> None:
    (output,) = params
    store32(memory, output, -value32(memory, output))


def _rotate(memory: Memory, params: tuple, bits: int, right: bool) -> None:
    output, count = params
    n = value(memory, count)
    if not 1 <= n <= bits:
        operation_error(memory)
        return
    mask = (1 << bits) - 1
    raw = (value32(memory, output) if bits == 32 else value(memory, output)) & mask
    if right:
        rotated = (raw >> n | raw << (bits - n)) & mask
        carry = rotated >> (bits - 1) & 1  # the last bit out of bit 0 went to the top
    else:
        rotated = (raw << n | raw >> (bits - n)) & mask
        carry = rotated & 1  # the last bit out of the top went to bit 0
    if bits == 32:
        store32(memory, output, rotated)
    else:
        memory.write(output, rotated, 2)
    memory.set_bit(M1022, bool(carry))


def _rotate_right(memory: Memory, params: tuple) -> None:
    _rotate(memory, params, 16, True)


def _rotate_left(memory: Memory, params: tuple) -> None:
    _rotate(memory, params, 16, False)


def _rotate_right32(memory: Memory, params: tuple) -> None:
    _rotate(memory, params, 32, True)


def _rotate_left32(memory: Memory, params: tuple) -> None:
    _rotate(memory, params, 32, False)


def _to_bcd(memory: Memory, params: tuple, digits: int) -> None:
    source, output = params
    number = value32(memory, source) if digits == 8 else value(memory, source)
    raw = int_to_bcd(number, digits)
    if raw is None:
        operation_error(memory)
    elif digits == 8:
        store32(memory, output, raw)
    else:
        memory.write(output, raw, 2)


def _to_binary(memory: Memory, params: tuple, digits: int) -> None:
    source, output = params
    raw = (value32(memory, source) if digits == 8 else value(memory, source)) \
        & ((1 << 4 * digits) - 1)
    number = bcd_to_int(raw, digits)
    if number is None:
        operation_error(memory)
    elif digits == 8:
        store32(memory, output, number)
    else:
        memory.write(output, number, 2)


def _bcd(memory: Memory, params: tuple) -> None:
    _to_bcd(memory, params, 4)


def _bcd32(memory: Memory, params: tuple) -> None:
    _to_bcd(memory, params, 8)


def _bin(memory: Memory, params: tuple) -> None:
    _to_binary(memory, params, 4)


def _bin32(memory: Memory, params: tuple) -> None:
    _to_binary(memory, params, 8)


register(__name__, {
    "and": _and, "or": _or, "xor": _xor, "and32": _and32, "or32": _or32, "xor32": _xor32,
    "negate": _negate, "negate32": _negate32, "rotate-right": _rotate_right,
    "rotate-left": _rotate_left, "rotate-right32": _rotate_right32,
    "rotate-left32": _rotate_left32, "to-bcd": _bcd, "to-bcd32": _bcd32,
    "to-binary": _bin, "to-binary32": _bin32})
