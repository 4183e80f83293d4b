"""The PMC parameter file: values, overlaps, text round trip, diagnostics at lines, timers."""

from __future__ import annotations

from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

from ladderworks.core.address import Address, Area, parse_address
from ladderworks.core.plc.memory import Memory
from ladderworks.core.plc.parameters import (
    KEPT_HEADER,
    PmcParameters,
    format_parameters,
    parameter_path,
    parameters_beside,
    parse_parameters,
)
from ladderworks.core.plc.timer_table import FANUC, SEED, dialect_of, timer_layout

TEXT = """# presets
T4:4 = 1000     ; TMR 2
C0:2 = 12
K5.1 = 1
K5.0 = 1
D100 = 0x12
D20:2 = -2
"""


def test_reads_values_bits_and_comments() -> None:
    read = parse_parameters(TEXT)
    assert read.diagnostics == []
    p = read.parameters
    assert p.get(Address(Area.T, 4), 4) == 1000
    assert p.get(Address(Area.C, 0), 2) == 12
    assert p.get(Address(Area.K, 5)) == 0b11
    assert p.get(Address(Area.D, 100)) == 0x12
    assert p.get(Address(Area.D, 20), 2) == 0xFFFE


def test_written_sorted_one_line_per_value_and_read_back() -> None:
    p = parse_parameters(TEXT).parameters
    text = format_parameters(p)
    lines = [line for line in text.splitlines() if not line.startswith("#")]
    assert lines == ["T4:4 = 1000          # TMR 2 preset (ms)",
                     "C0:2 = 12            # CTR 1 preset",
                     "K5 = 0b00000011",
                     "D20:2 = 0xFFFE",
                     "D100 = 0x12"]
    assert parse_parameters(text).parameters == p


def test_fanuc_timer_comments_name_ticks() -> None:
    p = PmcParameters()
    p.set(timer_layout(FANUC).preset_address(3), 25, 2)
    assert "T4:2 = 25            # TMR 3 preset (ticks)" in format_parameters(p, FANUC)


def test_bad_lines_give_diagnostics_at_their_line_and_are_kept() -> None:
    text = "T0:4 = 100\nhello\nX0 = 1\nD0:3 = 1\nK1 = 300\nR0 = 1\nQ9 = 1\nK1.2 = 5\n"
    read = parse_parameters(text)
    assert [(d.line, d.code) for d in read.diagnostics] == [
        (2, "prm-line"), (3, "prm-area"), (4, "prm-value"), (5, "prm-value"),
        (6, "prm-area"), (7, "unknown-area"), (8, "prm-value")]
    assert read.parameters.get(Address(Area.T, 0), 4) == 100
    written = format_parameters(read.parameters)
    assert written.splitlines()[-8:] == [KEPT_HEADER, "hello", "X0 = 1", "D0:3 = 1",
                                         "K1 = 300", "R0 = 1", "Q9 = 1", "K1.2 = 5"]
    again = parse_parameters(written)
    assert again.parameters == read.parameters and len(again.diagnostics) == 7


def test_overlapping_values_keep_the_other_bytes() -> None:
    p = PmcParameters()
    p.set(Address(Area.D, 10), 0x44332211, 4)
    p.set(Address(Area.D, 11), 0, 2)
    assert p.get(Address(Area.D, 10), 4) == 0x44000011
    p.set(Address(Area.D, 10), 0, 4)
    assert not p


def test_apply_writes_only_the_values() -> None:
    memory = Memory()
    memory.write(Address(Area.D, 0), 7)
    p = parse_parameters("D1 = 5\n").parameters
    p.apply(memory)
    assert memory.read(Address(Area.D, 0), 2) == 0x0507


def test_file_beside_the_program(tmp_path: Path) -> None:
    program = tmp_path / "A.LAD"
    assert parameter_path(program) == tmp_path / "A.LAD.prm"
    assert not parameters_beside(program).parameters
    parameter_path(program).write_bytes("K1 = 1 # açıklama\n".encode("cp1254"))
    found = parameters_beside(program)
    assert found.path == parameter_path(program) and found.diagnostics == []
    assert found.parameters.get(parse_address("K1")) == 1


def test_dialect_and_timer_layout() -> None:
    class Fanuc:
        dialect = "fanuc"

    assert dialect_of(None) == SEED and dialect_of(Fanuc()) == FANUC
    seed = timer_layout(SEED)
    assert seed.preset_address(2) == Address(Area.T, 4) and seed.width == 4
    assert seed.delay_ms(1, 1000) == 960 and seed.delay_ms(12, 38) == 32
    fanuc = timer_layout(FANUC)
    assert fanuc.preset_address(2) == Address(Area.T, 2) and fanuc.width == 2
    assert fanuc.delay_ms(1, 10) == 480 and fanuc.delay_ms(9, 10, precision=3) == 1000


@given(st.lists(st.tuples(st.sampled_from([Area.T, Area.C, Area.K, Area.D]),
                          st.integers(0, 60), st.sampled_from([1, 2, 4]),
                          st.integers(0, 2**32 - 1)), max_size=12))
def test_text_round_trip_and_memory_image(values: list[tuple[Area, int, int, int]]) -> None:
    p = PmcParameters()
    memory = Memory()
    for area, byte, width, value in values:
        p.set(Address(area, byte), value, width)
        memory.write(Address(area, byte), value, width)
    again = parse_parameters(format_parameters(p))
    assert again.diagnostics == [] and again.parameters == p
    image = Memory()
    again.parameters.apply(image)
    assert image.snapshot() == memory.snapshot()
