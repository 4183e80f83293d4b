"""The parser's fast paths read exactly what its line-by-line paths read: the batch scanner
(one findall over the distinct line texts), the batch address parse, the symbol section's
batch read, and the functions whose parameter lines are all valid (read in one pass)."""

from __future__ import annotations

import pytest

from ladderworks.core.address import AddressError, parse_address_cached, parse_plain_addresses
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il import parse
from ladderworks.core.il.line_scan import Line as _Line
from ladderworks.core.il.line_scan import Made as _Made
from ladderworks.core.il.line_scan import scan_common as _scan_common
from ladderworks.core.il.line_scan import scan_fast as _scan_fast
from ladderworks.core.il.parser import _percent_lines
from ladderworks.core.il.program import Instruction
from ladderworks.core.il.sections import read_symbols
from ladderworks.core.il.textform import split_with_ends
from ladderworks.core.instructions import lookup
from ladderworks.core.symbols import SymbolTable

# texts the batch scanner reads, must leave to the line scanner, or must read the same way
SCAN_TEXTS = [
    "RD X21.7", "RD        X21.7", "RD\tX21.7", "RD X21.7  ", "RD X21.7\t", "RD.NOT    R100.0",
    "WRT Y0.1", "AND.STK", "rd x21.7", "rd X21.7", "RD x21.7", "  RD X21.7", "\tRD X21.7",
    "RD X21.8", "RD X128.0", "RD X1127.7", "RD X0021.7", "RD X1234567.1", "RD R9500.0",
    "RD X21", "RD X21.7 ; comment", "RD X21.7 // comment", "RD X21.7;", "RD X21.7 X1.0",
    "RD X21.7\x0c", "RD\u00a0X21.7", "RD X21.7.1", "RDX X21.7", "FOO X21.7", "TMRB X1.0",
    "SUB 40", "SUB  40", "SUB 1 R100 R102 R104", "MOVB", "NUMEB ; c", "",
    "   ", "\t", "; a comment", "// a comment", ", a comma comment", "R100", "R100  ",
    "r100", "X21.7", "0001", "1000 ", "+5", "-1", "12a", "P5", "L3", "N00012:", "n12:",
    "N00012:  ", " N00012:", "N00012: ; c", "N12:x", "NOT_A_LABEL:", "R100 ; param",
    "1 ; param", "RD.NOT.STK X3.3", "OR.STK", "END1", "\u00b2", "RD X²1.7",
]


def _shape(item: _Line | _Made | None) -> object:
    """What a scan gives, comparable: a _Line by its fields, a made tuple as it is."""
    if isinstance(item, _Line):
        return (item.kind, [(w.text, w.column, w.is_int) for w in item.words], item.comment,
                item.param, item.made)
    return item


def test_batch_scanner_reads_each_text_as_the_line_scanner() -> None:
    batch = _scan_common(SCAN_TEXTS)
    assert len(batch) == len(SCAN_TEXTS)
    read = 0
    for text, item in zip(SCAN_TEXTS, batch, strict=True):
        if item is not None:  # what it reads, it reads as _scan_fast does
            read += 1
            assert _shape(item) == _shape(_scan_fast(text)), text
    assert read > 20  # it reads the common shapes
    left = {text for text, item in zip(SCAN_TEXTS, batch, strict=True) if item is None}
    # odd spacing, case, comments and bad addresses are left to the line scanner
    assert {"  RD X21.7", "rd x21.7", "RD x21.7", "RD X21.7 ; comment", "RD X21.8",
            "RD X128.0", "RD X21.7\x0c", "RD\u00a0X21.7", "SUB 40", " N00012:",
            "N00012: ; c", "R100 ; param", "+5", ""} <= left


def test_batch_scanner_made_instruction_has_the_line_scanner_fields() -> None:
    item = _scan_common(["RD.NOT    R100.0"])[0]
    assert isinstance(item, tuple)
    spec, name, operand, params, comment, column, starts, ends = item
    assert spec is lookup("RD.NOT") and name == "RD.NOT" and str(operand) == "R100.0"
    assert (params, comment, column, starts, ends) == ((), "", 1, True, False)


def test_batch_scanner_leaves_all_texts_when_one_holds_a_line_break() -> None:
    assert _scan_common(["RD X1.0", "RD X1.1\nWRT Y0.0"]) == [None, None]
    assert _scan_common([]) == []


PLAIN_TEXTS = ["X1.0", "X0001.7", "X127", "X128.0", "X199", "X200", "X1127.7", "X1128",
               "R9499.7", "R9500.1", "D10", "D9999", "x1.0", "X1.8", "X1.", "F767", "F768",
               "F1000", "", "A9249", "C5199.1", "E9999", "E10000", "K999.7", "T9500",
               "X999999", "X1000000", "E0000001", "Q1", "P5", " X1.0", "X1.0 ", "X1.07"]


def test_plain_addresses_are_parse_address_cached_of_width_one() -> None:
    found = parse_plain_addresses(PLAIN_TEXTS)
    for text in PLAIN_TEXTS:
        try:
            expected = parse_address_cached(text, None, 1)
        except AddressError:
            assert text not in found, text
            continue
        if text in found:
            assert found[text] == expected and repr(found[text]) == repr(expected)
    assert {"X1.0", "X0001.7", "X1127.7", "R9499.7", "D10", "C5199.1"} <= found.keys()
    assert parse_plain_addresses(["X1.0\nX1.1"]) == {}
    assert parse_plain_addresses([]) == {}


SYMBOLS = """\
D1.0    S41F+D
X21.7   ESKIP  the skip signal
D37.3\tC62196\t
x1.1    LOWER
P5      SUBPROG
p0006   OTHER
X1.0    FIRST
X1.0    SECOND
R10.0   FIRST
Q1.0    BADAREA
X128.0  OUTSIDE
; a comment line

  R11.0   INDENTED
R12.0
G8.4    *ESP
D37.3   AGAIN
"""


def test_symbol_section_fast_lines_keep_order_and_warnings() -> None:
    from ladderworks.core.il.program import Section

    section = Section(2, SYMBOLS.splitlines(), "%@2-C")
    table = SymbolTable()
    out: list[Diagnostic] = []
    read_symbols(section, 10, table, out)
    by_address = [(str(a), s.symbol, s.comments) for a, s in table.by_address.items()]
    assert by_address == [
        ("D1.0", "S41F+D", ()), ("X21.7", "ESKIP", ("the skip signal",)),
        ("D37.3", "AGAIN", ()), ("X1.1", "LOWER", ()), ("X1.0", "SECOND", ()),
        ("R10.0", "FIRST", ()), ("R11.0", "INDENTED", ()), ("G8.4", "*ESP", ())]
    assert [(s, str(a)) for s, a in table.by_symbol.items()] == [
        ("S41F+D", "D1.0"), ("ESKIP", "X21.7"), ("C62196", "D37.3"), ("LOWER", "X1.1"),
        ("FIRST", "X1.0"), ("SECOND", "X1.0"), ("INDENTED", "R11.0"), ("*ESP", "G8.4"),
        ("AGAIN", "D37.3")]
    assert {n: s.symbol for n, s in table.programs.items()} == {5: "SUBPROG", 6: "OTHER"}
    assert [(d.code, d.line, d.args["text"]) for d in out] == [
        ("section-line", 19, "Q1.0    BADAREA"), ("section-line", 20, "X128.0  OUTSIDE"),
        ("section-line", 24, "R12.0")]
    checked: list[Diagnostic] = []  # with build False: the same warnings, nothing added
    read_symbols(section, 10, SymbolTable(), checked, build=False)
    assert checked == out


def _function_text(lines: list[str]) -> str:
    return "%@3\nN00001:\nRD X1.0\n" + "\n".join(lines) + "\nWRT Y0.1\n%\n"


def _read(text: str) -> tuple[list[Instruction], list[tuple[str, dict[str, object], int]]]:
    result = parse(text)
    return ([ins for net in result.program.networks for ins in net.instructions],
            [(d.code, d.args, d.column) for d in result.diagnostics])


# functions written with one parameter a line, valid and not; each is read twice: as written
# (the fast path for its valid parameters) and with its parameters on the name's line (the
# line-by-line path): the same instruction and the same diagnostics
FUNCTIONS = [
    ("TMRB", ["1", "1000"]), ("TMRB", ["0", "1000"]), ("TMRB", ["501", "1000"]),
    ("TMRB", ["1", "R100"]), ("TMRB", ["0001", "0000000000000001000"]),
    ("MOVB", ["R100", "R200"]), ("MOVB", ["R100", "5"]), ("MOVB", ["R100.1", "R200"]),
    ("MOVB", ["R9500", "R200"]), ("MOVW", ["D9998", "D10"]), ("MOVW", ["D9999", "D10"]),
    ("MOVN", ["4", "D100", "D200"]), ("MOVN", ["4", "D9998", "D200"]),
    ("NUMEB", ["2", "1234", "D100"]), ("NUMEB", ["3", "1234", "D100"]),
    ("NUMEB", ["4", "-5", "D9998"]), ("COMPB", ["1001", "D10", "D20"]),
    ("COMPB", ["1", "D10", "D20"]), ("COMPB", ["1", "100", "D20"]),
    ("COMPB", ["1001", "100", "D20"]), ("COMPB", ["5", "100", "D20"]),
    ("CALL", ["P5"]), ("CALL", ["P0"]), ("CALL", ["L5"]), ("CALL", ["p0005"]),
    ("JMPB", ["L3"]), ("JMPB", ["P3"]), ("DIFU", ["1"]), ("DIFU", ["2001"]),
    ("LOGAND", ["1", "R10", "R11", "R12"]), ("LOGAND", ["1001", "R10", "R11", "R12"]),
    ("DECB", ["1", "R10", "12345", "R12"]), ("MOVE", ["1111", "0000", "R10", "R11"]),
    ("MOVE", ["1112", "0000", "R10", "R11"]), ("XMOVB", ["1", "R100", "R10", "R12", "R14"]),
    ("XMOVB", ["1", "100", "R10", "R12", "R14"]),
]


@pytest.mark.parametrize(("name", "params"), FUNCTIONS, ids=lambda v: str(v))
def test_function_parameter_lines_read_as_one_line(name: str, params: list[str]) -> None:
    sub = lookup(name)
    assert sub is not None and sub.sub is not None
    one_line = _read(_function_text([" ".join([sub.text_name, *params])]))
    heads = [f"SUB {sub.sub}"] + ([name] if name == sub.text_name else [])  # AND: basic
    for head in heads:
        lines = _read(_function_text([head, *params]))
        assert [(i.name, i.params) for i in lines[0]] == [
            (i.name, i.params) for i in one_line[0]]
        assert [(c, a) for c, a, _ in lines[1]] == [(c, a) for c, a, _ in one_line[1]]


def test_repeated_function_lines_make_equal_instructions_at_their_lines() -> None:
    group = ["SUB 43", "R100", "R200"]
    text = "%@3\nN00001:\nRD X1.0\n" + "\n".join(group) + "\nRD X1.1\n" + "\n".join(
        group) + "\nWRT Y0.1\n%\n"
    result = parse(text)
    assert result.ok, result.diagnostics
    moves = [i for i in result.program.instructions() if i.name == "MOVB"]
    assert len(moves) == 2 and moves[0] == moves[1]
    assert [(i.line, i.column, str(i.params[1])) for i in moves] == [(4, 1, "R200"),
                                                                     (8, 1, "R200")]
    assert result.program.source is not None
    assert result.program.source.spans == [(1, 6), (6, 11)]  # a function ends a network


@pytest.mark.parametrize("between", ["", ";c", "SUB 43", "R300"])
def test_repeated_function_with_other_lines_reads_them(between: str) -> None:
    """The second SUB 43 is read again when its lines differ from the first one's."""
    first = ["SUB 43", "R100", "R200"]
    second = ["SUB 43", "R100", between, "R200"]
    text = "%@3\nRD X1.0\n" + "\n".join(first) + "\nRD X1.1\n" + "\n".join(
        second) + "\nWRT Y0.1\n%\n"
    expected = {
        "": [],  # a blank line between parameters is skipped
        ";c": [("param-count", 7), ("stray-parameter", 10)],
        "SUB 43": [("param-count", 7), ("param-count", 9)],
        "R300": [("stray-parameter", 10)],
    }[between]
    result = parse(text)
    assert [(d.code, d.line) for d in result.diagnostics] == expected
    moves = [i for i in result.program.instructions() if i.name == "MOVB"]
    assert len(moves) == (2 if between in ("", "R300") else 1)


def test_repeated_table_function_takes_its_own_table_size() -> None:
    text = ("%@3\nRD X1.0\nSUB 27\n1\n2\nR10\nR12\n5\n6\nRD X1.1\nSUB 27\n1\n3\nR10\nR12\n5\n"
            "6\n7\nWRT Y0.1\n%\n")
    result = parse(text)
    assert result.ok, result.diagnostics
    codb = [i for i in result.program.instructions() if i.name == "CODB"]
    assert [i.params[4:] for i in codb] == [(5, 6), (5, 6, 7)]


def test_repeated_function_with_a_bad_parameter_reports_at_its_line() -> None:
    text = "%@3\nRD X1.0\nSUB 24\n1\n1000\nRD X1.1\nSUB 24\n1\nR100\nWRT Y0.1\n%\n"
    result = parse(text)
    # reported at the function's line, as the first SUB 24's would be
    assert [(d.code, d.line) for d in result.diagnostics] == [("param-kind-number", 7)]
    assert [i.name for i in result.program.instructions()] == ["RD", "TMRB", "RD", "WRT"]


def test_repeated_function_lines_give_the_same_check_diagnostics(tmp_path: object) -> None:
    from pathlib import Path

    from ladderworks.core.il import parse_for_check

    text = ("%@3\nRD X1.0\nSUB 24\n1\n1000\nRD X1.1\nSUB 24\n1\n1000\nRD X1.2\nSUB 24\n1\n"
            "R5\nWRT Y0.1\n%\n")
    path = Path(str(tmp_path)) / "p.LAD"
    path.write_text(text)
    assert parse_for_check(path).diagnostics == parse(text).diagnostics


def test_crlf_and_tabs_read_as_lf_and_spaces() -> None:
    text = "%@3\nN00001:\nRD\tX1.0\nSUB 43\nR100\nR200\nWRT  Y0.1\n%\n"
    lf = parse(text)
    crlf = parse(text.replace("\n", "\r\n"))
    assert lf.ok and crlf.ok
    assert lf.program == crlf.program
    assert lf.program.networks[0].label == "N00001"


@pytest.mark.parametrize("text", ["", "%", "%\n", "a\n%\n%@3\nx%y%z\n\n%", "\n\n%\n", "abc",
                                  "%%\n%\n", "a\r\n%\r\nb%", "a\rb%\r%", "%@3\nRD X1.0\n%\n"])
def test_percent_lines_are_the_lines_holding_a_percent_sign(text: str) -> None:
    lines = split_with_ends(text)[0]
    assert _percent_lines(text, lines) == [i for i, line in enumerate(lines) if "%" in line]
