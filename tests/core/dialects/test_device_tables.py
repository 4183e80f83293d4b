"""The device tables of a dialect (issues 25/26): the timers, counters and registers a program
uses, their presets and bases, rows read from memory, ranges a user types."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core import dialects
from ladderworks.core.address import AddressError
from ladderworks.core.compiler import compile
from ladderworks.core.dialects.device_tables import (
    MAX_RANGE,
    Table,
    device_range,
    program_devices,
    table_rows,
)
from ladderworks.core.il.reading import parse_bytes, parse_file
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects.conftest import get, put

EXAMPLES = Path(__file__).resolve().parents[3] / "resources" / "examples"


def _engine(text: str, dialect: str) -> ScanEngine:
    result = parse_bytes(text.encode("utf-8"), dialect)
    assert result.ok, [d.located("t") for d in result.diagnostics]
    return ScanEngine(compile(result.program), period_ms=10)


def _rows(plc: ScanEngine, dialect: str, table: Table,
          listed: set[tuple[str, int]] | None = None) -> list[tuple[object, ...]]:
    found = dialects.get(dialect)
    assert found is not None
    tables = found.device_tables()
    assert tables is not None
    used = program_devices(tables, found.devices, plc.program.ops)
    return [(row.device, row.base_ms, row.preset.text if row.preset else None, row.value,
             row.contact, 8 * row.width, row.up_down)
            for row in table_rows(table, tables, found.devices, used, listed or set(),
                                  plc.memory.areas)]


DELTA = """LD X0
TMR T0 K10
LD X1
TMR T64 D5
LD X2
TMR T127 K3
LD X3
CNT C1 D7
LD X4
DCNT C200 K-2
LD M1000
MOV K30 D5
ADD D5 K1 D6000
END
"""


def test_delta_program_devices() -> None:
    plc = _engine(DELTA, "delta")
    plc.scan()
    assert _rows(plc, "delta", Table.TIMERS) == [
        ("T0", 100, "K10", 0, False, 16, False), ("T64", 100, "D5", 0, False, 16, False),
        ("T127", 1, "K3", 0, False, 16, False)]
    assert _rows(plc, "delta", Table.COUNTERS) == [
        ("C1", 0, "D7", 0, True, 16, False), ("C200", 0, "K-2", 0, True, 32, True)]  # 0 >= 0
    assert [row[0] for row in _rows(plc, "delta", Table.REGISTERS)] == ["D5", "D7", "D6000"]
    put(plc, "M1028", 1)
    assert [row[1] for row in _rows(plc, "delta", Table.TIMERS)] == [100, 10, 1]
    assert [row[3] for row in _rows(plc, "delta", Table.REGISTERS)] == [30, 0, 31]


def test_fatek_program_devices() -> None:
    plc = ScanEngine(compile(parse_file(EXAMPLES / "fatek" / "conveyor.lst").program),
                     period_ms=10)
    plc.scan()
    assert _rows(plc, "fatek", Table.TIMERS) == [("T50", 100, "30", 0, False, 16, False)]
    assert _rows(plc, "fatek", Table.COUNTERS) == [("C0", 0, "5", 0, False, 16, False)]
    assert [(row[0], row[3]) for row in _rows(plc, "fatek", Table.REGISTERS)] == [
        ("R0", 0), ("R1", 0), ("R2", 100)]
    listed = {("T", 0), ("T", 200), ("C", 200)}
    assert [(row[0], row[1]) for row in _rows(plc, "fatek", Table.TIMERS, listed)] == [
        ("T0", 10), ("T50", 100), ("T200", 1000)]
    assert [(row[0], row[5]) for row in _rows(plc, "fatek", Table.COUNTERS, listed)] == [
        ("C0", 16), ("C200", 32)]
    listed = {("D", 3), ("R", 9)}
    assert [row[0] for row in _rows(plc, "fatek", Table.REGISTERS, listed)] == [
        "R0", "R1", "R2", "R9", "D3"]


def test_a_fatek_timer_counts_on_from_a_value_written_into_it() -> None:
    plc = _engine("ORG X0\nTMR T50 0.1S 30\nFO 0\nOUT Y0\nEND\n", "fatek")
    put(plc, "X0", 1, "fatek")
    for _ in range(50):
        plc.scan()
    assert get(plc, "T50", "fatek") in (4, 5)
    put(plc, "T50", 28, "fatek")
    for _ in range(25):
        plc.scan()
    assert get(plc, "T50", "fatek") in (30, 31) and get(plc, "Y0", "fatek") == 1


@pytest.mark.parametrize(("dialect", "table", "text", "devices"), [
    ("delta", Table.REGISTERS, "D10", [("D", 10)]),
    ("delta", Table.REGISTERS, "d0-d2", [("D", 0), ("D", 1), ("D", 2)]),
    ("delta", Table.REGISTERS, "D4998..5001", [("D", n) for n in range(4998, 5002)]),
    ("delta", Table.TIMERS, "T5~T6", [("T", 5), ("T", 6)]),
    ("fatek", Table.REGISTERS, "R1-2", [("R", 1), ("R", 2)]),
    ("fatek", Table.COUNTERS, "C199-C200", [("C", 199), ("C", 200)]),
])
def test_ranges_a_user_types(dialect: str, table: Table, text: str,
                             devices: list[tuple[str, int]]) -> None:
    found = dialects.get(dialect)
    assert found is not None and found.device_tables() is not None
    assert device_range(table, found.device_tables(), found.devices, text) == devices


@pytest.mark.parametrize(("dialect", "table", "text", "code"), [
    ("delta", Table.REGISTERS, "T5", "device-not-in-table"),
    ("delta", Table.REGISTERS, "D9-D2", "device-range-order"),
    ("delta", Table.REGISTERS, f"D0-D{MAX_RANGE}", "device-range-order"),
    ("delta", Table.REGISTERS, "D10000", "device-range"),
    ("delta", Table.TIMERS, "T0-C3", "device-not-in-table"),
    ("delta", Table.COUNTERS, "Q1", "device-unknown"),
    ("fatek", Table.REGISTERS, "X0", "device-not-in-table"),
])
def test_bad_ranges_say_why(dialect: str, table: Table, text: str, code: str) -> None:
    found = dialects.get(dialect)
    assert found is not None and found.device_tables() is not None
    with pytest.raises(AddressError) as caught:
        device_range(table, found.device_tables(), found.devices, text)
    assert caught.value.diagnostics[0].code == code


def test_delta_module_registers_of_from_and_to_are_listed() -> None:
    plc = _engine("LD M1000\nFROM K0 K12 D200 K1\nDTO K1 K4 D0 K2\nFROMP K2 D5 D300 K3\n"
                  "TO K7 K98 K5 K4\nEND\n", "delta")
    put(plc, "CR12", 1234)
    plc.scan()
    rows = _rows(plc, "delta", Table.REGISTERS)
    # DTO K1 K4 .. K2: module 1's CR#4-CR#7; FROMP's first register is a D (not known before
    # the run): none; TO K7 K98 .. K4: CR#98, CR#99 (a module has no place past #99)
    assert [row[0] for row in rows] == ["D0", "D5", "D200", "D300", "CR12", "CR104", "CR105",
                                        "CR106", "CR107", "CR798", "CR799"]
    assert [row[3] for row in rows if row[0] in ("D200", "CR12")] == [1234, 1234]
