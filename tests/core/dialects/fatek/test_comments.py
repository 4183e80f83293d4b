"""WinProladder's comment export as a program's symbols: the real export (cp1250), the project's
own in several code pages, a guess that is not sure warned at its line, bad input diagnosed."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.dialects.fatek import DEVICES
from ladderworks.core.dialects.fatek.comments import decode, read_comment_file, read_comments
from ladderworks.core.il.reading import parse_file
from tests.hypothesis_profiles import examples
from tests.real_programs import real_programs_dir

EXAMPLES = Path(__file__).resolve().parents[4] / "resources" / "examples" / "fatek"
OWN = ("REF\tCOMMENT\tDESCRIPTION\r\nX0\tStart button\tgreen, on the door\r\n"
       "Y1\tCapper motor\t\r\nM10\tCap present\t\r\nR100\tCaps counted\tshift total\r\n"
       "T10\tCap settle\t\r\nC5\tCap counter\t\r\n")


def test_the_real_export_reads_as_cp1250_symbols() -> None:
    path = real_programs_dir() / "fatek" / "VERTINO_export_comment.txt"
    assert decode(path.read_bytes())[1] == "cp1250"
    table, diagnostics = read_comment_file(path)
    # 112 devices; a timer's or counter's name is on its contact and its value (8 T, 2 C)
    assert diagnostics == [] and table is not None and len(table) == 122
    assert table.lookup(DEVICES.bit("M80")).symbol == "Żądanie HOME"  # type: ignore[union-attr]
    assert table.lookup(DEVICES.bit("X0")).symbol == "SAFETY_STATUS"  # type: ignore[union-attr]


def test_the_projects_own_export_gives_names_and_descriptions() -> None:
    table, diagnostics = read_comments(OWN.encode("ascii"))
    assert diagnostics == [] and table is not None
    start = table.lookup(DEVICES.bit("X0"))
    assert start is not None and (start.symbol, start.comment) == ("Start button",
                                                                   "green, on the door")
    assert table.lookup(DEVICES.word("R100")[0]).symbol == "Caps counted"  # type: ignore
    assert table.by_symbol["Cap counter"] == DEVICES.bit("C5")


def test_polish_in_cp1250_and_utf8_read_alike() -> None:
    text = "REF\tCOMMENT\tDESCRIPTION\nM1\tŻądanie ręczne\tpołożenie\nM2\tObrót\t\n"
    for data in (text.encode("cp1250"), text.encode("utf-8"), text.encode("utf-8-sig")):
        table, diagnostics = read_comments(data)
        assert diagnostics == [] and table is not None
        assert table.lookup(DEVICES.bit("M1")).symbol == "Żądanie ręczne"  # type: ignore


def test_a_turkish_export_in_cp1254_reads_as_turkish() -> None:
    text = "REF\tCOMMENT\tDESCRIPTION\nM1\tKapı açık\t\nM2\tŞişe yok\tğ\n"
    table, diagnostics = read_comments(text.encode("cp1254"))
    assert diagnostics == [] and table is not None
    assert table.lookup(DEVICES.bit("M1")).symbol == "Kapı açık"  # type: ignore[union-attr]


def test_a_code_page_guess_that_is_not_sure_is_warned_at_its_line() -> None:
    data = b"REF\tCOMMENT\tDESCRIPTION\nX0\tStart\t\nM1\tMo\xe8\t\n"  # Moč? Moè?
    table, diagnostics = read_comments(data)
    assert table is not None
    assert [(d.code, d.line, d.is_error) for d in diagnostics] == [
        ("fatek-comment-codepage", 3, False)]
    assert "cp1250" in diagnostics[0].message() and "cp1252" in diagnostics[0].message()


def test_a_truncated_utf16_export_is_an_error_at_its_byte() -> None:
    data = "REF\tCOMMENT\tDESCRIPTION\nX0\tStart\t\n".encode("utf-16")[:-1]
    table, diagnostics = read_comments(data)
    assert table is None and [(d.code, d.line) for d in diagnostics] == [
        ("fatek-comment-bytes", 2)]
    assert "byte" in diagnostics[0].message()


def test_not_an_export_and_bad_references() -> None:
    assert [d.code for d in read_comments(b"ORG X0\nOUT Y0\n")[1]] == ["fatek-comment-header"]
    table, diagnostics = read_comments(b"REF\tCOMMENT\tDESCRIPTION\nQ7\tno such\t\nX1\tok\t\n")
    assert table is not None and len(table) == 1
    assert [(d.code, d.line, d.is_error) for d in diagnostics] == [("fatek-comment-ref", 2, False)]


def test_a_reference_of_thousands_of_digits_is_skipped_at_its_line() -> None:
    table, diagnostics = read_comments(b"REF\tCOMMENT\tDESCRIPTION\nX" + b"9" * 5000 + b"\tx\t\n")
    assert table is not None and len(table) == 0
    assert [(d.code, d.line, len(str(d.args["text"]))) for d in diagnostics] == [
        ("fatek-comment-ref", 2, 24)]


def test_an_export_beside_the_program_becomes_its_symbols(tmp_path: Path) -> None:
    program = tmp_path / "capping.lst"
    program.write_bytes((EXAMPLES / "capping_printed.lst").read_bytes())
    assert parse_file(program).program.symbols is None
    (tmp_path / "comment.txt").write_bytes(OWN.encode("cp1250"))
    symbols = parse_file(program).program.symbols
    assert symbols is not None and symbols.lookup(DEVICES.bit("Y1")).symbol == "Capper motor"  # type: ignore
    (tmp_path / "comment.txt").write_bytes(b"not an export\n")  # one that does not read: none
    assert parse_file(program).program.symbols is None


@settings(max_examples=examples(300), deadline=None)
@given(st.binary(max_size=300), st.booleans())
def test_random_bytes_never_raise(data: bytes, with_header: bool) -> None:
    if with_header:
        data = b"REF\tCOMMENT\tDESCRIPTION\r\n" + data
    table, diagnostics = read_comments(data)
    lines = data.count(b"\n") + 1
    for diagnostic in diagnostics:
        assert 1 <= diagnostic.line <= lines and diagnostic.message()
    assert table is not None or any(d.is_error for d in diagnostics)


def test_the_ladder_names_the_devices_in_fatek_spelling(tmp_path: Path,
                                                        capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.cli import main

    program = tmp_path / "capping.lst"
    program.write_bytes((EXAMPLES / "capping_printed.lst").read_bytes())
    (tmp_path / "capping_comment.txt").write_bytes(
        "REF\tCOMMENT\tDESCRIPTION\nS1\tPołożenie\t\nX0\tStart\t\n".encode("cp1250"))
    assert main(["ladder", str(program)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert "   X0 Start" in out and "   S1 Położenie" in out
