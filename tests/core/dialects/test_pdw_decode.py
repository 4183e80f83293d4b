"""A .pdw's code decoded to WinProladder's listing: each code form, the units, the timer bases,
the comments as symbols, and the stop (code + byte offset) at what is not decoded yet."""

from __future__ import annotations

import struct

import pytest

from ladderworks.core.compiler import compile
from ladderworks.core.dialects.fatek.devices import Device, bit_address, word_address
from ladderworks.core.dialects.fatek.pdw_file import read_pdw
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects.pdw_builder import CODE_START, build

PROGRAM_PAYLOAD = 0x100 + 4 + 8 + 11 + 2 + 4  # header, project record, program record head
CODE_AT = PROGRAM_PAYLOAD + CODE_START  # the first code word's file offset


def steps(words: list[int]) -> list[str]:
    """The listing's step and operand lines (without the page header), stripped."""
    result = read_pdw(build(words))
    assert result.error is None, result.error.args_map if result.error else None
    return [line.strip() for line in result.lines[2:]]


@pytest.mark.parametrize(("words", "lines"), [
    ([0x4000, 0xC100], ["00000M ORG X0", "00001M OUT Y0"]),
    ([0x5007, 0xB0FF, 0x9101, 0xA200, 0x8300, 0xC428], [
        "00000M ORG NOT X7", "00001M OR NOT X255", "00002M AND NOT Y1", "00003M OR T0",
        "00004M AND C0", "00005M OUT S0"]),
    ([0x4810, 0x8FE1, 0xCFE1], ["00000M ORG M0", "00001M AND M2001", "00002M OUT M2001"]),
    ([0xE000, 0x4001, 0xE000, 0x9810, 0xE000, 0xA80F], [
        "00000M ORG TU X1", "00001M AND TD M0", "00002M OR TU S999"]),
    ([0x4000, 0xC400, 0x8FE6, 0xC100, 0x6400, 0x9FE7, 0xC101], [
        "00000M ORG X0", "00001M OUT TR 0", "00002M AND SHORT", "00003M OUT Y0",
        "00004M LD TR 0", "00005M AND OPEN", "00006M OUT Y1"]),
    ([0x5FEB], ["00000M ORG OPEN"]),
    ([0x4000, 0xD105], ["00000M ORG X0", "00001M OUT NOT Y5"]),
    ([0x4000, 0xFC82, 0x042B, 0xFCC4, 0x0810, 0xFDC4, 0x0590, 0xFDC4, 0x03A4], [
        "00000M ORG X0", "00001M SET( ) S3", "00002M RST( ) M0", "00003M RST( ) C0",
        "00004M RST( ) T10"]),
])
def test_basic_forms(words: list[int], lines: list[str]) -> None:
    assert steps(words) == lines


def test_function_boxes_and_their_operand_lines() -> None:
    words = [0x4000, 0xF5AC, 0xFFFF - 4, 0x0A02,  # MOV -5 to R1
             0x4001, 0xF4AC, 0x0590, 0x2A5E,  # MOV C0 to R4143
             0x4002, 0xF496, 0x0A00,  # (+1) R0
             0x4003, 0xF51A, 0x1428, 0x15B8,  # HSPSO Ps 1
             0x4004, 0xF1D0, 0x1360, 0x6FFC, 0xC101]  # MPARA Ps 1, FO0
    assert steps(words) == [
        "00000M ORG X0", "00001M FUN 08 _.MOV", "S: -5", "D: R1",
        "00002M ORG X1", "00003M FUN 08 _.MOV", "S: C0", "D: R4143",
        "00004M ORG X2", "00005M FUN 15 _.(+1)", ": R0",
        "00006M ORG X3", "00007M FUN 140.HSPSO", "Ps: 1", "SR: R1300", "WR: R1500",
        "00008M ORG X4", "00009M FUN 141.MPARA", "Ps: 1", "SR: R1200", "00010M FO 0",
        "00011M OUT Y1"]


def test_comparison_contacts_with_constants() -> None:
    words = [0x4000, 0xF47F, 0x0025, 0x0590, 0x0A0C,  # ANDF 174 C0 R6
             0xF67F, 0x0022, 0x0A0C, 0x0000,  # ANDF 171 R6 0
             0xF57F, 0x0021, 0x0007, 0x0A00,  # ANDF 170 7 R0
             0xF47F, 0x0026, 0x0A00, 0x0A02, 0xC100]  # ANDF 175 R0 R1
    assert steps(words) == [
        "00000M ORG X0", "00001M ANDF 174_.>=", "Sa: C0", "Sb: R6",
        "00002M ANDF 171_.>", "Sa: R6", "Sb: 0", "00003M ANDF 170_.=", "Sa: 7", "Sb: R0",
        "00004M ANDF 175_.<=", "Sa: R0", "Sb: R1", "00005M OUT Y0"]


def test_a_timer_prints_its_base_from_the_projects_allocation() -> None:
    words = [0x4000, 0xFC80, 0x0A10, 0x03CC,  # T30 R8: T0-T49 are 0.01 s
             0x4001, 0xFC80, 0x0A10, 0x03F0,  # T48
             0x4002, 0xFC80, 0x0A10, 0x0404,  # T58: 0.1 s
             0x4003, 0xFC80, 0x0A00, 0x04D0]  # T160: 1 s (T150-T255 here)
    assert [line for line in steps(words) if " T" in line] == [
        "00001M T30 .01 R8", "00003M T48 .01 R8", "00005M T58 .1 R8", "00007M T160 1 R0"]


@pytest.mark.parametrize(("words", "index", "code"), [
    ([0x4000, 0x0123, 0xC100], 1, "pdw-code"),  # top bits 0: not decoded
    ([0x4000, 0xF0AC, 0x0000], 1, "pdw-code"),  # an extended code never seen
    ([0x4000, 0xE000, 0xC100], 1, "pdw-code"),  # TU before a coil
    ([0x4000, 0xCFE6], 1, "pdw-operand"),  # OUT of a drawn line's bit
    ([0x4000, 0xFC82, 0x1FFF], 2, "pdw-operand"),  # SET of no bit device
    ([0x4000, 0xF496, 0x0A01], 2, "pdw-operand"),  # an odd word operand
    ([0x4000, 0xF496, 0x4A00], 2, "pdw-operand"),  # past R4167
    ([0x4000, 0xFC82], 2, "pdw-cut"),  # the code ends inside SET
    ([0x4000, 0xFC7F], 1, "pdw-code"),  # a comparison form never seen (not ANDF's bits)
    ([0x4000, 0xF47F, 0x0027], 1, "pdw-code"),  # a comparison past FUN 175
    ([0x4000, 0xF47F, 0x0021], 3, "pdw-cut"),  # ANDF without its operands
])
def test_what_is_not_decoded_stops_the_listing_there(words: list[int], index: int,
                                                     code: str) -> None:
    result = read_pdw(build(words))
    assert result.error is not None
    assert result.error.code == code
    assert result.error.offset == CODE_AT + 2 * index
    assert result.lines[2] == "00000M ORG X0"  # what came before is kept


def test_a_subroutine_unit_is_listed_after_the_main_one() -> None:
    result = read_pdw(build([0x4000, 0xC100, 0x4001, 0xC101], sub_words=2))
    assert result.error is None
    assert result.lines == [
        "Printed Item: Mnemonic - Main_unit1", "", "00000M ORG X0", "00001M OUT Y0",
        "Printed Item: Mnemonic - Sub_unit1", "", "00000S ORG X1", "00001S OUT Y1"]


def test_the_program_runs_and_its_comments_are_its_symbols() -> None:
    data = build([0x4000, 0x9001, 0xC100], {"X0": "START".encode("cp1250"),
                                            "T5": "Opóźnienie".encode("cp1250"),
                                            "R100": b"Licznik", "Q9": b"not a device"})
    result = parse_bytes(data)
    assert result.ok, [d.located("t") for d in result.diagnostics]
    program = result.program
    assert program.dialect == "fatek"
    symbols = program.symbols
    assert symbols is not None
    assert symbols.lookup(bit_address(Device("X", 0))).symbol == "START"  # type: ignore[union-attr]
    for address in (bit_address(Device("T", 5)), word_address(Device("T", 5))[0]):
        assert symbols.lookup(address).symbol == "Opóźnienie"  # type: ignore[union-attr]
    assert symbols.lookup(word_address(Device("R", 100))[0]).symbol == "Licznik"  # type: ignore[union-attr]
    assert len(symbols.by_address) == 4  # X0, T5 twice, R100; Q9 left out
    plc = ScanEngine(compile(program), period_ms=10)
    x0, y0 = bit_address(Device("X", 0)), bit_address(Device("Y", 0))
    plc.memory.set_bit(x0, True)
    plc.scan()
    assert plc.memory.bit(y0)
    plc.memory.set_bit(bit_address(Device("X", 1)), True)
    plc.scan()
    assert not plc.memory.bit(y0)


def test_the_listing_is_what_the_reader_reads_back() -> None:
    data = build([0x4000, 0xFC82, 0x042B])
    text = read_pdw(data).text
    assert text.endswith("00001M SET( ) S3\r\n")
    assert struct.unpack_from("<H", data, 0x100)[0] == 0x1006


def test_a_program_whose_code_repeats_more_than_the_erased_blocks_still_unmasks() -> None:
    words = [0x4000, 0xC100] * 6592  # 20 identical code blocks, 11 erased ones
    result = read_pdw(build(words))
    assert result.error is None
    assert len(result.units[0][1]) == len(words)
    assert result.lines[-1] == f"{len(words) - 1:05d}M OUT Y0"
