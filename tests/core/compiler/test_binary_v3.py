"""Binary format v3: area E, SET/RST, P/L parameters, unknown SUB n, dialect flag, v2 refused."""

from __future__ import annotations

import struct
import zlib

import pytest

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import (
    BinaryFormatError,
    compile,
    decode,
    disassemble,
    encode,
    to_ops,
)
from ladderworks.core.compiler.binary import AREA_CODES, FORMAT_VERSION
from ladderworks.core.il.program import FANUC
from tests.core.plc.conftest import build

PROGRAM = """
RD E9999.7
SET E0.0
RST Y0.1
RD X0.0
CALL P5
RD X0.1
JMPB L3
LBL L3
RD X0.1
SUB.250 R0 -7 4294967295
WRT Y0.2
END2
SP P5
RD X0.0
WRT E12.3
SPE
END
"""


def test_version_3_and_the_area_codes_of_version_2_are_kept() -> None:
    assert FORMAT_VERSION == 3
    assert AREA_CODES.startswith("XYFGRADTCK")
    assert "E" in AREA_CODES


def test_round_trip_keeps_every_new_kind_of_op() -> None:
    program = build(PROGRAM)
    program.dialect = FANUC  # the E area is a FANUC 30i program's
    binary = compile(program)
    back = disassemble(binary)
    assert [[(i.name, i.operand, i.params, i.line) for i in n.instructions]
            for n in back.networks] == [
        [(i.name, i.operand, i.params, i.line) for i in n.instructions]
        for n in program.networks]
    assert compile(back) == binary
    names = [op.name for op in decode(binary).ops]
    assert {"SET", "RST", "CALL", "JMPB", "LBL", "SUB.250", "SP", "SPE", "END2"} <= set(names)


def test_the_dialect_is_in_the_header() -> None:
    ops = to_ops(build(PROGRAM))
    assert decode(encode(ops)).dialect == "seed"
    assert decode(encode(ops, "fanuc")).dialect == "fanuc"
    assert encode(ops, "fanuc") != encode(ops)


def test_version_2_is_refused_with_the_reason() -> None:
    body = struct.pack("<BBHI", 1, 0, 0, 0) + struct.pack("<IHIH", 0, 0, 2, 1)
    header = struct.pack("<4sHHIII", b"LWPC", 2, 20, 1, 0, zlib.crc32(body))
    with pytest.raises(BinaryFormatError) as info:
        decode(header + body)
    assert "version 2 is no longer supported" in info.value.reason
    assert "compile the program again" in info.value.reason


def test_big_numbers_and_addresses_fit() -> None:
    program = build("RD R0.0\nNUMEB 4 4294967295 D9996\nRD E0.0\nWRT R1.0")
    program.dialect = FANUC  # the E area is a FANUC 30i program's
    ops = decode(compile(program)).ops
    assert ops[1].params == (4, 4294967295, Address(Area.D, 9996))
    assert ops[2].operand == Address(Area.E, 0, 0)
