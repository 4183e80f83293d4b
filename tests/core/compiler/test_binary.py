"""The binary format: round trips, the source map, and clear errors for bad files."""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import pytest

from ladderworks.core.compiler import (
    BinaryFormatError,
    compile,
    decode,
    disassemble,
)
from ladderworks.core.compiler.binary import FORMAT_VERSION, HEADER_SIZE, MAGIC
from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.il import parse, parse_file, print_program
from ladderworks.core.plc.engine import ScanEngine

EXAMPLES = sorted((Path(__file__).resolve().parents[3] / "resources" / "examples").glob("*.LAD"))

MIXED = """%@3
RD X0.0
AND.NOT R1.2
RD.STK F3.4
OR.STK
WRT Y0.0
RD R0.0
TMR 7
WRT R0.1
RD R0.0
RD.STK R0.1
RD.STK R0.2
RD.STK R0.3
CTR 20
WRT R0.4
RD R1.0
TMRC 1 D10 D20
WRT R1.1
RD R2.0
RD.STK R2.2
CODB 2 3 D0 D2 -5 0 70000
WRT R2.1
%
"""


def test_examples_exist() -> None:
    assert len(EXAMPLES) >= 9


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_compile_disassemble_compile_gives_identical_bytes(path: Path) -> None:
    program = parse_file(path).program
    binary = compile(program)
    again = compile(disassemble(binary))
    assert again == binary


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_disassembly_is_the_program_without_its_comments(path: Path) -> None:
    program = parse_file(path).program
    back = disassemble(compile(program))
    assert [[(i.name, i.operand, i.params, i.line) for i in n.instructions]
            for n in back.networks] == [
        [(i.name, i.operand, i.params, i.line) for i in n.instructions]
        for n in program.networks]


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_disassembling_a_decoded_binary_equals_disassembling_its_bytes(path: Path) -> None:
    binary = compile(parse_file(path).program)
    assert disassemble(decode(binary)) == disassemble(binary)


def test_functions_and_their_parameters_round_trip() -> None:
    program = parse(MIXED).program
    binary = compile(program)
    back = disassemble(binary)
    assert compile(back) == binary
    text = print_program(back)
    assert "CODB 2 3 D0 D2 -5 0 70000" in text
    assert "TMRC 1 D10 D20" in text


def test_source_map_points_at_network_instruction_and_line() -> None:
    binary = decode(compile(parse(MIXED).program))
    assert [(op.name, op.source.network, op.source.instruction, op.source.line)
            for op in binary.ops[:8]] == [
        ("RD", 0, 0, 2), ("AND.NOT", 0, 1, 3), ("RD.STK", 0, 2, 4), ("OR.STK", 0, 3, 5),
        ("WRT", 0, 4, 6), ("RD", 1, 0, 7), ("TMR", 1, 1, 8), ("WRT", 1, 2, 9)]
    assert binary.op_at_line(8) == 6


def resign(data: bytearray) -> bytes:
    """`data` with its checksum made valid again (CRC-32 of header bytes 0-19, then the body)."""
    head = bytes(data[:HEADER_SIZE - 4])
    data[HEADER_SIZE - 4:HEADER_SIZE] = zlib.crc32(
        bytes(data[HEADER_SIZE:]), zlib.crc32(head)).to_bytes(4, "little")
    return bytes(data)


def test_header_holds_magic_version_flags_and_checksum() -> None:
    data = compile(parse(MIXED).program)
    magic, version, header_size, count, _params, flags, _, crc = struct.unpack_from(
        "<4sHHIIHHI", data)
    assert (magic, version, header_size, count, flags) == (
        MAGIC, FORMAT_VERSION, HEADER_SIZE, 21, 0)
    assert crc == zlib.crc32(data[HEADER_SIZE:], zlib.crc32(data[:HEADER_SIZE - 4]))
    assert resign(bytearray(data)) == data


def reason(data: bytes) -> str:
    with pytest.raises(BinaryFormatError) as info:
        disassemble(data)
    diagnostic = info.value.diagnostics[0]
    assert diagnostic.code == "bad-binary"
    return str(diagnostic.args["reason"])


def test_a_flipped_byte_is_caught_by_the_checksum() -> None:
    data = bytearray(compile(parse(MIXED).program))
    data[HEADER_SIZE + 5] ^= 0x40
    assert "checksum" in reason(bytes(data))


def test_foreign_files_are_refused_clearly() -> None:
    assert "magic" in reason(b"%@3\nRD X0.0\nWRT Y0.0\n%\n" + bytes(20))
    assert "too short" in reason(b"LWP")
    assert "too short" in reason(b"")


def test_truncated_file_is_refused() -> None:
    data = compile(parse(MIXED).program)
    assert "length" in reason(data[:-3])


def test_newer_version_is_refused() -> None:
    data = bytearray(compile(parse(MIXED).program))
    data[4:6] = (FORMAT_VERSION + 1).to_bytes(2, "little")
    assert f"version {FORMAT_VERSION + 1} is not supported" in reason(bytes(data))


def test_version_1_binary_with_a_bare_jmp_is_refused_with_the_reason() -> None:
    # version 1 wrote JMP (SUB 10) with no parameter: op record a = 0
    op = struct.pack("<BBHI", 0x80, 0, 10, 0)
    body = struct.pack("<BBHI", 1, 0, 0, 0) + op + struct.pack("<IHIH", 0, 0, 2, 1) * 2
    header = struct.pack("<4sHHIII", MAGIC, 1, 20, 2, 0, zlib.crc32(body))
    text = reason(header + body)
    assert "version 1 is no longer supported" in text
    assert "JMP" in text and "compile the program again" in text
    with pytest.raises(DiagnosticError) as info:
        ScanEngine(header + body)
    assert [d.code for d in info.value.diagnostics] == ["bad-binary"]


def test_jmp_keeps_its_coil_count_in_the_binary() -> None:
    program = parse("%@3\nRD X0.0\nJMP 2\nRD X0.1\nWRT Y0.1\nRD X0.0\nJMP 0\nJMPE\n%\n")
    assert program.ok
    jumps = [op for op in decode(compile(program.program)).ops if op.name == "JMP"]
    assert [op.params for op in jumps] == [(2,), (0,)]


def test_bad_opcode_with_a_valid_checksum_is_refused() -> None:
    data = bytearray(compile(parse(MIXED).program))
    data[HEADER_SIZE] = 0x55
    assert "unknown opcode 85" in reason(resign(data))


def test_random_damage_with_a_valid_checksum_never_crashes_the_engine() -> None:
    import random

    rng = random.Random(4)
    good = compile(parse(MIXED).program)
    for _ in range(300):
        data = bytearray(good)
        for _ in range(rng.randint(1, 4)):
            data[rng.randrange(len(data))] = rng.randrange(256)
        try:
            ScanEngine(resign(data)).run_scans(3)
        except DiagnosticError as error:  # BinaryFormatError or a failed check
            assert error.diagnostics


def test_random_programs_round_trip_to_identical_bytes() -> None:
    import random

    from tests.core.plc.test_engine import random_program

    rng = random.Random(11)
    for _ in range(40):
        ops = random_program(rng, rng.randint(1, 8))
        text = "\n".join(n if a is None else f"{n} {a}" for n, a in ops)
        extra = f"\nRD R9.0\nTMRB {rng.randint(1, 100)} {rng.randint(0, 99_999_999)}\nWRT R9.1"
        binary = compile(parse("%@3\n" + text + extra + "\n%\n").program)
        assert compile(disassemble(binary)) == binary
        reprinted = decode(compile(parse(print_program(disassemble(binary))).program))
        assert [(op.name, op.operand, op.params) for op in reprinted.ops] == [
            (op.name, op.operand, op.params) for op in decode(binary).ops]
