"""Typed values for functional instructions of any family: Int, DInt, Real, Time … in memory.

A typed parameter is a constant (an int; a Real constant as its IEEE-754 bits, a Time constant
in ms) or an Address whose bytes are read in the memory's byte order (`Memory.byteorder`: the
one place byte order is decided). The type is a `ValueType` number (a NUMBER parameter of the
row), so the binary and the code generator see plain ints. docs/engine.md, "Typed values".
"""

from __future__ import annotations

import math
import struct
from enum import IntEnum

from ladderworks.core.address import Address
from ladderworks.core.plc.memory import Memory


class ValueType(IntEnum):
    """A value's data type (S7's elementary types; numbers are kept in binaries)."""

    BOOL = 0
    SINT = 1
    INT = 2
    DINT = 3
    USINT = 4
    UINT = 5
    UDINT = 6
    REAL = 7
    TIME = 8
    BYTE = 9
    WORD = 10
    DWORD = 11
    LREAL = 12
    CHAR = 13


WIDTH: dict[ValueType, int] = {
    ValueType.BOOL: 1, ValueType.SINT: 1, ValueType.INT: 2, ValueType.DINT: 4,
    ValueType.USINT: 1, ValueType.UINT: 2, ValueType.UDINT: 4, ValueType.REAL: 4,
    ValueType.TIME: 4, ValueType.BYTE: 1, ValueType.WORD: 2, ValueType.DWORD: 4,
    ValueType.LREAL: 8, ValueType.CHAR: 1}
_LARGEST_REAL = 3.4028234663852886e38
FLOATS = frozenset({ValueType.REAL, ValueType.LREAL})
SIGNED = frozenset({ValueType.SINT, ValueType.INT, ValueType.DINT, ValueType.TIME})
# names as TIA writes them (case-insensitive), and the IEC timer/counter types
TYPE_NAMES: dict[str, ValueType] = {t.name.lower(): t for t in ValueType}


def type_of(name: str) -> ValueType | None:
    """The ValueType a type name spells (`Int`, `DINT`, `Time`), None for another type."""
    return TYPE_NAMES.get(name.strip().lower())


def limits(vtype: ValueType) -> tuple[int, int]:
    """The lowest and highest value of an integer type (Time: DInt's)."""
    bits = 8 * WIDTH[vtype]
    if vtype in SIGNED:
        return -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    return 0, (1 << bits) - 1


def real_bits(value: float) -> int:
    """A Real constant as the signed 32-bit int of its IEEE-754 bits (a binary's parameter)."""
    return int.from_bytes(struct.pack(">f", value), "big", signed=True)


def bits_real(bits: int) -> float:
    """The Real whose IEEE-754 bits are `bits`."""
    return float(struct.unpack(">f", (bits & 0xFFFFFFFF).to_bytes(4, "big"))[0])


def to_real(value: float) -> float:
    """A double as a Real stores it: one that rounds past the largest Real is ±infinity
    (C's cast; `struct.pack` would raise)."""
    try:
        struct.pack(">f", value)
    except OverflowError:
        return math.copysign(math.inf, value)
    return value


def quiet(value: float) -> float:
    """A NaN with its quiet bit set (as the FPU returns a NaN operand); another value as is."""
    if value == value:
        return value
    return bits_lreal(lreal_bits(value) | 1 << 51)


def lreal_bits(value: float) -> int:
    """An LReal's IEEE-754 double bits as an unsigned 64-bit int."""
    return int.from_bytes(struct.pack(">d", value), "big")


def bits_lreal(bits: int) -> float:
    """The LReal whose IEEE-754 double bits are `bits`."""
    return float(struct.unpack(">d", (bits & (1 << 64) - 1).to_bytes(8, "big"))[0])


def read(memory: Memory, operand: object, vtype: ValueType) -> int | float:
    """The value of a typed parameter: a constant or the value at an address."""
    if isinstance(operand, Address):
        if operand.bit is not None:
            return memory.bit(operand)
        raw = memory.read(operand, WIDTH[vtype], signed=vtype in SIGNED)
        if vtype is ValueType.LREAL:
            return bits_lreal(raw)
    else:
        assert isinstance(operand, int)
        raw = operand
        if vtype is ValueType.LREAL:  # a constant: a Real's bits (parameters are 32-bit; an
            return bits_real(raw)  # LReal constant a Real does not hold is put in memory)
    return bits_real(raw) if vtype is ValueType.REAL else raw


def wrap(value: int, vtype: ValueType) -> int:
    """An integer wrapped into its type's range (two's complement)."""
    bits = 8 * WIDTH[vtype]
    value &= (1 << bits) - 1
    if vtype in SIGNED and value >> (bits - 1):
        value -= 1 << bits
    return value


def write(memory: Memory, address: object, vtype: ValueType, value: int | float) -> None:
    """Store a value of `vtype` at an address (a bit address: 0 or 1); not an address: nothing."""
    if not isinstance(address, Address):
        return
    if address.bit is not None:
        memory.set_bit(address, bool(value))
        return
    if vtype is ValueType.REAL:
        try:
            raw = real_bits(float(value))
        except OverflowError:  # rounds past the largest Real: C's cast gives ±infinity
            raw = real_bits(math.copysign(math.inf, value))
        memory.write(address, raw, 4)
        return
    if vtype is ValueType.LREAL:
        memory.write(address, lreal_bits(float(value)), 8)
        return
    memory.write(address, wrap(int(value), vtype), WIDTH[vtype])


def fits(value: int | float, vtype: ValueType) -> bool:
    """True when a result is valid for its type (an integer in range, a finite Real as
    written)."""
    if vtype is ValueType.REAL:  # as written: one rounding to the largest Real fits
        return abs(value) <= _LARGEST_REAL or (
            math.isfinite(value) and math.isfinite(to_real(float(value))))
    if vtype is ValueType.LREAL:
        return math.isfinite(value)
    low, high = limits(vtype)
    return low <= value <= high


def valid_real(value: float) -> bool:
    """OK's test: a finite Real that is not denormal (S7-1200 system manual V4.2 p. 252)."""
    return math.isfinite(value) and (value == 0 or abs(value) >= 1.1754943508222875e-38)
