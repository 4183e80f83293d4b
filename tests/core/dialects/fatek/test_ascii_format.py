"""FUN 94 ASCWR's ASCII file format (seed 004): parsing, values, the worked production report."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core.dialects.fatek.ascii_format import (
    Feed,
    Text,
    Variable,
    format_value,
    parse_format,
    render,
)
from ladderworks.core.dialects.fatek.terminal import AsciiTerminal

EXAMPLE = Path(__file__).parents[4] / "resources" / "examples" / "fatek"

# 004:272-276: the register values of the worked report
REPORT_VALUES = {"R4133": 99, "R4132": 1, "R4131": 20, "R0": 1000, "R1": 983, "R2": 17,
                 "R3": 85, "R4": 8500, "R5": 9190, "R6": 9249}

# docs/dialects.md (Fatek, ASCII output): the seed's report as its file data prints it
REPORT = (
    "\n\n\n"
    "                            Uretim Raporu\n"
    "                            ==================\n"
    "                                                    Date: 1/20/99\n"
    "\n"
    "                Toplam Sayı(A) :      1000 PCS\n"
    "\n"
    "                Urun Sayısı (B) :       983 PCS\n"
    "\n"
    "                Tamir Edilecek Sayısı (C) :        17 PCS\n"
    "\n"
    "                Standart Zaman (D) :       8.5 MIN/PCS\n"
    "\n"
    "                TOTAL WORKING    TIME (E) :      8500 MIN\n"
    "\n"
    "                Gercek calısma Zamanı(F) :      9190 MIN\n"
    "\n"
    "                Verimlilik (G) :     92.49 %\n"
    "\n\n\n\n"
    "                      Acıklama: AXD=E, E/F=G"
)


def report_text() -> str:
    """The example's ASCII file (seed 004:228-234, the missing quote restored), without its
    `[R1000]` header line."""
    lines = (EXAMPLE / "production_report.lst.ascii").read_text(encoding="utf-8").splitlines(True)
    assert lines[0].strip() == "[R1000]"
    return "".join(lines[1:])


def test_the_seed_report_renders_as_printed() -> None:
    fmt, diagnostics = parse_format(report_text(), first_line=2)
    assert diagnostics == []
    text = render(fmt, lambda v: REPORT_VALUES[v.name])
    assert text == REPORT
    # the seed's table (004:181-215): the title 28 blanks in, the date 52, the lines 16, 22
    lines = text.split("\n")
    assert lines[3].index("Uretim") == 28
    assert lines[5].index("Date") == 52
    assert lines[-1].index("Acıklama") == 22
    for value in ("1000 PCS", "983 PCS", "17 PCS", "8.5 MIN/PCS", "8500 MIN", "9190 MIN",
                  "92.49 %", "1/20/99"):
        assert value in text


def test_the_seed_text_as_printed_has_a_missing_quote_at_its_line() -> None:
    broken = report_text().replace("'Uretim Raporu',", "'Uretim Raporu,", 1)
    _fmt, diagnostics = parse_format(broken, first_line=10)
    assert diagnostics, "the seed's line 228 is malformed as printed"
    assert diagnostics[0].code == "fatek-ascii-item"
    assert diagnostics[0].line == 10


@pytest.mark.parametrize(("spec", "value", "shown"), [
    ("8.2R0", -32768, " -327.68"),  # 004:155-158
    ("5.1R0", -32768, "276.8"),  # 004:160-165: high digits and the sign cut
    ("10R0", 1000, "      1000"),
    ("2R4132", 1, " 1"),
    ("10.1R3", 85, "       8.5"),
    ("4.2R0", 5, "0.05"),
    ("4R0H", 255, "  FF"),
    ("4R0H", -1, "FFFF"),
    ("8R0B", 5, "     101"),
    ("3DR0", 123456, "456"),
    ("12DR0", -2_000_000_000, " -2000000000"),
    ("6DR0H", -1, "FFFFFF"),
])
def test_variable_values(spec: str, value: int, shown: str) -> None:
    fmt, diagnostics = parse_format(f'"{spec}",END')
    assert diagnostics == []
    (variable,) = fmt.items
    assert isinstance(variable, Variable)
    assert format_value(variable, value) == shown


def test_items() -> None:
    fmt, diagnostics = parse_format("'I''M A BOY',3X'ab',2X0D0A,4X,1B,//,\\,\"8.2DD10D\",END")
    assert diagnostics == []
    assert fmt.items == [Text("I'M A BOY"), Text("ab", 3), Text("\r\n", 2), Text(" ", 4),
                         Text("\x1b"), Feed("\n", 2), Feed("\f", 1),
                         Variable(8, 2, "DD", 10, "D")]
    assert fmt.items[-1].double  # type: ignore[union-attr]
    assert render(fmt, lambda v: 12345) == "I'M A BOYababab\r\n\r\n    \x1b\n\n\f  123.45"


def test_footnote_spellings_are_equal() -> None:
    """004:237: '==================' may be written 18X'=' or 18X3D."""
    texts = ["'==================',END", "18X'=',END", "18X3D,END"]
    shown = {render(parse_format(t)[0], lambda v: 0) for t in texts}
    assert shown == {"=" * 18}


@pytest.mark.parametrize(("text", "code", "line"), [
    ("'abc,\n/,END", "fatek-ascii-quote", 1),
    ("'a',\n1000X'b',END", "fatek-ascii-repeat", 2),
    ("'a',/,\n\n  HELLO,END", "fatek-ascii-item", 3),
    ("'a',\n\"8.2Q0\",END", "fatek-ascii-variable", 2),
    ("'a',\n\"2.2R0\",END", "fatek-ascii-variable", 2),
    ("'a',END\n'b'", "fatek-ascii-after-end", 2),
    ("'a',/\n'b'", "fatek-ascii-no-end", 2),
])
def test_malformed_formats_are_diagnosed_at_their_line(text: str, code: str, line: int) -> None:
    _fmt, diagnostics = parse_format(text)
    assert [d.code for d in diagnostics][:1] == [code]
    assert diagnostics[0].line == line


def test_terminal_wraps_at_its_last_column_and_keeps_pages() -> None:
    terminal = AsciiTerminal(columns=5)
    terminal.write("abcdefg\nxy\fz")
    assert terminal.text() == "abcde\nfg\nxy\fz"
    assert terminal.writes == 1
    terminal.clear()
    assert terminal.text() == ""
