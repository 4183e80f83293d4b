"""Tests of AlarmMsg.dat reading and of the active-alarm list."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderworks import paths
from ladderworks.core.address import Address, AddressError, Area
from ladderworks.core.alarms import (
    A_BYTES,
    ALARM_COUNT,
    ActiveAlarms,
    AlarmTable,
    alarm_address,
    alarm_number,
    format_number,
    load_alarm_file,
    parse_alarm_text,
    read_alarm_bytes,
)
from ladderworks.core.diagnostics import MESSAGES, Severity

SAMPLE = paths.RESOURCES / "AlarmMsg.dat"


def _area(*bits: str) -> bytes:
    """The A area with the given bits (`A0.0`, `A21.3`) at 1."""
    data = bytearray(A_BYTES)
    for text in bits:
        number = alarm_number(text)
        data[number // 8] |= 1 << (number % 8)
    return bytes(data)


# ------------------------------------------------------------------ numbers and addresses

def test_numbering_is_byte_times_eight_plus_bit() -> None:
    assert ALARM_COUNT == 800
    assert alarm_number("A00.0") == 0
    assert alarm_number("A0.7") == 7
    assert alarm_number("A21.0") == alarm_number("A021.0") == 168
    assert alarm_number("A99.7") == 799
    assert alarm_number(Address(Area.A, 1, 2)) == 10
    assert alarm_address(168) == Address(Area.A, 21, 0)
    assert str(alarm_address(799)) == "A99.7"
    assert format_number(7) == "007"


@pytest.mark.parametrize("number", [0, 1, 7, 8, 168, 799])
def test_number_and_address_round_trip(number: int) -> None:
    assert alarm_number(alarm_address(number)) == number


def test_bad_alarm_addresses() -> None:
    with pytest.raises(AddressError):
        alarm_number("R0.0")
    with pytest.raises(AddressError):
        alarm_number("A100.0")
    with pytest.raises(AddressError):
        alarm_number("A5")
    with pytest.raises(ValueError):
        alarm_address(800)


# ------------------------------------------------------------------ the message file

def test_sample_file_reads_cleanly() -> None:
    table, diagnostics = load_alarm_file(SAMPLE)
    assert diagnostics == []
    assert sorted(table) == list(range(16))
    assert table.text_for(0).startswith("X EKSENİ HAREKET EDİYOR")  # type: ignore[union-attr]
    assert table.text_for("A00.0") == table.text_for(0)
    assert table.text_for("A1.0") == table.text_for(8)
    assert table.text_for("A99.7") is None


def test_both_line_forms_comments_and_blanks() -> None:
    text = (
        "// header comment\n"
        "; FANUC-style comment\n"
        "\n"
        "000 X EKSENİ HAREKET EDİYOR\n"
        "A21.0 TEXT OF A21.0\n"
        "  A021.1   leading blanks and spaces  \n"
        "7 one digit\n"
        "799 last\n"
    )
    table, diagnostics = parse_alarm_text(text)
    assert diagnostics == []
    assert table.messages == {
        0: "X EKSENİ HAREKET EDİYOR",
        168: "TEXT OF A21.0",
        169: "leading blanks and spaces",
        7: "one digit",
        799: "last",
    }
    assert table.text_for("A021.0") == "TEXT OF A21.0"


def test_bad_lines_become_diagnostics_with_line_numbers() -> None:
    text = (
        "000 ok\n"
        "800 too big\n"
        "A100.0 no such byte\n"
        "A1.8 no such bit\n"
        "hello world\n"
        "000 again\n"
        "005\n"
    )
    table, diagnostics = parse_alarm_text(text)
    found = [(d.code, d.line) for d in diagnostics]
    assert found == [
        ("alarm-number", 2),
        ("alarm-address", 3),
        ("alarm-address", 4),
        ("alarm-line", 5),
        ("alarm-duplicate", 6),
        ("alarm-empty", 7),
    ]
    assert table.text_for(0) == "ok"  # the first line wins
    assert table.text_for(5) == ""
    severities = {d.code: d.severity for d in diagnostics}
    assert severities["alarm-duplicate"] is Severity.WARNING
    assert severities["alarm-number"] is Severity.ERROR
    for diagnostic in diagnostics:
        assert diagnostic.code in MESSAGES
        assert "{" not in diagnostic.message()
    assert "800" in diagnostics[0].message()


def test_column_of_indented_bad_line() -> None:
    _table, diagnostics = parse_alarm_text("   garbage here\n")
    assert diagnostics[0].column == 4


def test_encodings_and_line_endings(tmp_path: Path) -> None:
    text = "000 X EKSENİ HAREKET EDİYOR\r\n001 ŞALTER ĞÜÇÖ\r\n"
    for encoding in ("utf-8", "utf-8-sig", "cp1254"):
        path = tmp_path / f"AlarmMsg-{encoding}.dat"
        path.write_bytes(text.encode(encoding))
        table, diagnostics = load_alarm_file(path)
        assert diagnostics == []
        assert table.messages == {0: "X EKSENİ HAREKET EDİYOR", 1: "ŞALTER ĞÜÇÖ"}


def test_to_text_round_trip() -> None:
    table, _ = load_alarm_file(SAMPLE)
    again, diagnostics = parse_alarm_text(table.to_text())
    assert diagnostics == []
    assert again.messages == table.messages


@given(st.binary(max_size=300))
def test_reader_never_raises_on_bytes(data: bytes) -> None:
    table, diagnostics = read_alarm_bytes(data)
    assert isinstance(table, AlarmTable)
    assert all(0 <= n < ALARM_COUNT for n in table)
    assert all(d.line >= 1 for d in diagnostics)


@given(st.lists(st.text(alphabet="0123456789A.; /xİş \t", max_size=12), max_size=20))
def test_reader_never_raises_on_line_like_text(lines: list[str]) -> None:
    table, diagnostics = parse_alarm_text("\n".join(lines))
    assert all(0 <= n < ALARM_COUNT for n in table)
    for diagnostic in diagnostics:
        assert diagnostic.code in MESSAGES


# ------------------------------------------------------------------ active alarms

def test_rising_bit_raises_with_time() -> None:
    table, _ = load_alarm_file(SAMPLE)
    alarms = ActiveAlarms(table)
    assert alarms.update(bytes(A_BYTES), 0) == []
    raised = alarms.update(_area("A0.0"), 100)
    assert [(a.number, a.raised_ms) for a in raised] == [(0, 100)]
    assert raised[0].text.startswith("X EKSENİ HAREKET EDİYOR")
    assert raised[0].address == Address(Area.A, 0, 0)
    # staying at 1 raises nothing new
    assert alarms.update(_area("A0.0"), 200) == []
    assert [a.raised_ms for a in alarms.alarms] == [100]


def test_newest_first() -> None:
    alarms = ActiveAlarms()
    alarms.update(_area("A0.1"), 10)
    alarms.update(_area("A0.1", "A21.0"), 20)
    alarms.update(_area("A0.1", "A21.0", "A0.3", "A0.2"), 30)
    assert [a.number for a in alarms.alarms] == [2, 3, 168, 1]
    assert alarms.alarms[0].text == ""  # no table: no text


def test_alarm_stays_listed_after_bit_drops_until_reset() -> None:
    alarms = ActiveAlarms()
    alarms.update(_area("A0.0"), 10)
    alarms.update(bytes(A_BYTES), 20)
    assert [(a.number, a.active) for a in alarms.alarms] == [(0, False)]
    alarms.reset()
    assert alarms.alarms == []


def test_reset_keeps_alarms_whose_bit_is_still_one() -> None:
    alarms = ActiveAlarms()
    alarms.update(_area("A0.0", "A0.1"), 10)
    alarms.update(_area("A0.1"), 20)
    alarms.reset()
    assert [(a.number, a.raised_ms, a.active) for a in alarms.alarms] == [(1, 10, True)]
    assert not alarms.is_raised(0)
    # still 1: no new raise, the old entry stays
    assert alarms.update(_area("A0.1"), 30) == []
    # the bit drops: it stays listed (inactive) until the next reset
    alarms.update(bytes(A_BYTES), 40)
    assert [(a.number, a.active) for a in alarms.alarms] == [(1, False)]
    alarms.reset()
    assert len(alarms) == 0
    # and it is raised again only when the bit rises again
    raised = alarms.update(_area("A0.1"), 50)
    assert [(a.number, a.raised_ms) for a in raised] == [(1, 50)]


def test_rise_again_before_reset_moves_to_top() -> None:
    alarms = ActiveAlarms()
    alarms.update(_area("A0.0"), 10)
    alarms.update(_area("A0.1"), 20)  # A0.0 drops, A0.1 rises
    alarms.update(_area("A0.0", "A0.1"), 30)  # A0.0 rises again
    assert [(a.number, a.raised_ms, a.active) for a in alarms.alarms] == [
        (0, 30, True), (1, 20, True)]
    assert len(alarms) == 2


def test_all_800_bits() -> None:
    alarms = ActiveAlarms()
    raised = alarms.update(b"\xff" * A_BYTES, 5)
    assert [a.number for a in raised] == list(range(ALARM_COUNT))
    assert alarms.alarms[-1].number == 799


def test_clear_and_wrong_length() -> None:
    alarms = ActiveAlarms()
    alarms.update(_area("A3.3"), 1)
    alarms.clear()
    assert len(alarms) == 0
    assert [a.number for a in alarms.update(_area("A3.3"), 2)] == [27]
    with pytest.raises(ValueError):
        alarms.update(bytes(10), 3)


# ------------------------------------------------------------------ ladderworks-cli alarms

def test_cli_alarms_lists_the_sample(capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.cli import main

    assert main(["alarms"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == 16
    assert lines[0].startswith("000  A0.0  X EKSENİ HAREKET EDİYOR")
    assert lines[8].startswith("008  A1.0  ")


def test_cli_alarms_reports_bad_lines(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.cli import main

    path = tmp_path / "AlarmMsg.dat"
    path.write_text("000 ok\n900 no\n", encoding="utf-8")
    assert main(["alarms", str(path)]) == 1
    captured = capsys.readouterr()
    assert captured.out == "000  A0.0  ok\n"
    assert f"{path}:2:1: alarm-number" in captured.err
