"""Tests for the instruction-list parser and printer."""

from pathlib import Path

import pytest

from ladderworks.core.address import Address, Area
from ladderworks.core.il import parse, parse_bytes, print_program
from ladderworks.paths import EXAMPLES
from tests.core.il import cases

EXAMPLE_FILES = sorted(EXAMPLES.glob("*.LAD"))


def test_examples_exist() -> None:
    names = {p.stem for p in EXAMPLE_FILES}
    assert {"or_single", "or_double", "or_triple", "or_triple_and", "rising_edge",
            "timer_relay", "mcode_decoder", "spindle_override"} <= names


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.name)
def test_example_round_trip(path: Path) -> None:
    first = parse_bytes(path.read_bytes())
    assert first.ok, first.diagnostics
    text = print_program(first.program)
    second = parse(text)
    assert second.ok
    assert second.program == first.program
    assert print_program(second.program) == text  # canonical is a fixed point


def test_spindle_override_structure() -> None:
    program = parse((EXAMPLES / "spindle_override.LAD").read_text("utf-8")).program
    assert len(program.networks) == 16
    first = program.networks[0]
    assert first.comments[-1].strip().startswith("****")
    assert [i.name for i in first.instructions] == ["RD.NOT", "AND.NOT", "AND.NOT", "WRT"]
    assert first.instructions[-1].operand == Address(Area.R, 102, 0)


def test_fanuc_and_one_line_forms_are_the_same_program() -> None:
    fanuc = parse(cases.FANUC_FORM)
    one = parse(cases.ONE_LINE_FORM)
    assert fanuc.ok and one.ok
    assert fanuc.program == one.program
    tmrb = fanuc.program.networks[0].instructions[1]
    assert tmrb.name == "TMRB" and tmrb.params == (1, 1000)
    assert print_program(fanuc.program) == print_program(one.program)


def test_subtraction_one_line_is_not_fanuc_sub() -> None:
    result = parse("%@3\nRD X0.0\nSUB 1 R100 R102 R104\nWRT R0.0\n%\n")
    assert result.ok, result.diagnostics
    ins = result.program.networks[0].instructions[1]
    assert ins.name == "SUB" and ins.params[0] == 1


def test_other_sections_kept_verbatim() -> None:
    result = parse(cases.SECTIONS)
    assert result.ok, result.diagnostics
    program = result.program
    assert [s.number for s in program.before] == [0, 1]
    assert program.before[0].lines == [" system parameters: anything here is kept verbatim"]
    assert [s.number for s in program.after] == [4]
    assert program.header == [" a FANUC listing with other sections"]
    again = parse(print_program(program)).program
    assert again == program


def test_a_csv_symbol_section_gives_symbols_and_comments() -> None:
    result = parse('%@A\n%@2-E(SYM=1,ADR=2,CM1=3)\nESKIP,X21.7,"skip, signal"\n'
                   "BAD,Q1,x\n%\n%@3\nRD X21.7\nWRT Y0.1\n%\n%@E\n")
    symbol = result.program.symbols.lookup(Address(Area.X, 21, 7))
    assert symbol is not None and (symbol.symbol, symbol.comments) == ("ESKIP", ("skip, signal",))
    assert [(d.code, d.line) for d in result.diagnostics] == [("section-line", 4)]


def test_comments_survive() -> None:
    result = parse(cases.COMMENTS)
    assert result.ok, result.diagnostics
    net1, net2 = result.program.networks
    assert net1.comments == [" a comma comment line", " network 1 comment", " FANUC comment"]
    assert net1.instructions[0].comment == "trailing, Türkçe: İŞ MİLİ"
    assert net1.instructions[1].lead == (" inside the network",)
    assert net2.instructions[0].operand == Address(Area.X, 2, 5)
    assert result.program.trailer == [" trailing comment at the end"]
    assert parse(print_program(result.program)).program == result.program


def test_cp1254_and_crlf() -> None:
    text = "%@3\r\nRD X2.1  // İŞ MİLİ ŞALTER ĞÜÇÖ\r\nWRT Y0.0\r\n%\r\n"
    result = parse_bytes(text.encode("cp1254"))
    assert result.ok and result.encoding == "cp1254"
    assert result.program.networks[0].instructions[0].comment == "İŞ MİLİ ŞALTER ĞÜÇÖ"
    utf = parse_bytes(("\ufeff" + text).encode("utf-8"))
    assert utf.encoding == "utf-8" and utf.program == result.program


def test_missing_start_and_end() -> None:
    no_start = parse("RD X0.0\nWRT Y0.0\n")
    assert [d.code for d in no_start.diagnostics] == ["missing-start"]
    assert no_start.program.step_count() == 2  # the program is still read
    no_end = parse("%@3\nRD X0.0\nWRT Y0.0\n")
    assert [d.code for d in no_end.diagnostics] == ["missing-end"]


def test_section_errors() -> None:
    result = parse("%@3\nRD X0.0\nWRT Y0.0\n%\n%@3\n%\n%@9\n%\ngarbage\n")
    codes = {d.code for d in result.diagnostics}
    assert codes == {"duplicate-section", "bad-section", "text-outside-section"}


def test_bad_input_diagnostics_with_positions() -> None:
    result = parse(cases.BAD)
    found = [(d.code, d.line, d.column) for d in result.diagnostics]
    assert found == [
        ("unknown-area", 2, 4),
        ("bit-range", 3, 4),
        ("unknown-instruction", 4, 1),
        ("param-range", 5, 5),
        ("syntax", 6, 9),
        ("unknown-sub", 7, 5),
        ("param-count", 8, 6),
        ("missing-operand", 9, 1),
        ("extra-operand", 10, 9),
        ("stray-parameter", 11, 1),
        ("param-mask", 12, 6),
        ("param-choice", 13, 6),
        ("param-kind-number", 14, 12),
    ]
    for diagnostic in result.diagnostics:
        assert diagnostic.message()  # every code has an English text
        assert "{" not in diagnostic.message()


def test_param_kind_address_expected() -> None:
    result = parse("%@3\nRD X0.0\nDECB 1 5 1 R11\n%\n")
    assert [d.code for d in result.diagnostics] == ["param-kind-address"]


def test_lowercase_and_spacing_are_normalised() -> None:
    result = parse("%@3\n   rd   x2.1\n\twrt.not\tG8.5   \n%\n")
    assert result.ok
    assert print_program(result.program) == "%@3\nRD X2.1\nWRT.NOT G8.5\n%\n"


def test_move_masks_print_as_binary_digits() -> None:
    result = parse("%@3\nRD X0.0\nMOVE 1111 11 R10 R11\n%\n")
    assert result.ok
    assert "MOVE 1111 0011 R10 R11" in print_program(result.program)


def test_functions_and_ends_split_networks() -> None:
    text = "%@3\nRD X0.0\nJMP 0\nRD X0.1\nWRT Y0.0\nJMPE\nRD X0.2\nWRT Y0.1\nEND1\n%\n"
    result = parse(text)
    assert result.ok, result.diagnostics
    names = [[i.name for i in n.instructions] for n in result.program.networks]
    assert names == [["RD", "JMP"], ["RD", "WRT"], ["JMPE"], ["RD", "WRT"], ["END1"]]
