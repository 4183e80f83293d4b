"""Text forms: encodings, BOMs, line ends kept; bad bytes kept with a warning; no `?` on save."""

from __future__ import annotations

import pytest

from ladderworks.core.il import parse, parse_bytes
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.textform import (
    CP1254,
    UTF8,
    UTF16BE,
    UTF16LE,
    EncodeError,
    TextForm,
    decode_text,
    encode_text,
    split_lines,
)
from tests.core.il import cases

TURKISH = "%@3\n// İŞ MİLİ ŞALTER ĞÜÇÖ\nRD X2.1  // ılık\nWRT Y0.0\n%\n"


@pytest.mark.parametrize(("data", "encoding", "bom"), [
    (TURKISH.encode("utf-8"), UTF8, b""),
    (b"\xef\xbb\xbf" + TURKISH.encode("utf-8"), UTF8, b"\xef\xbb\xbf"),
    (TURKISH.encode("cp1254"), CP1254, b""),
    (b"\xff\xfe" + TURKISH.encode("utf-16-le"), UTF16LE, b"\xff\xfe"),
    (b"\xfe\xff" + TURKISH.encode("utf-16-be"), UTF16BE, b"\xfe\xff"),
    (TURKISH.replace("\n", "\r\n").encode("utf-8"), UTF8, b""),
    (TURKISH.replace("\n", "\r").encode("cp1254"), CP1254, b""),
    (TURKISH.rstrip("\n").encode("utf-8"), UTF8, b""),  # no final newline
    (b"%@3\r\nRD X0.0\nWRT Y0.0\r%\n", UTF8, b""),  # mixed line ends
])
def test_every_form_reads_the_same_program_and_saves_the_same_bytes(
        data: bytes, encoding: str, bom: bytes) -> None:
    result = parse_bytes(data)
    assert result.ok, result.diagnostics
    assert (result.form.encoding, result.form.bom) == (encoding, bom)
    assert result.encoding == encoding
    assert encode_program(result.program) == data


def test_newline_of_the_form() -> None:
    assert parse_bytes(b"%@3\r\nRD X0.0\r\nWRT Y0.0\r\n%\r\n").form.newline == "\r\n"
    assert not parse_bytes(b"%@3\nRD X0.0\nWRT Y0.0\n%").form.final_newline


def test_a_few_invalid_bytes_stay_utf8_warned_at_their_line_and_kept() -> None:
    data = "%@3\n// ĞÜŞ\n".encode() + b"RD X0.0  // bad \xff here\nWRT Y0.0\n%\n"
    result = parse_bytes(data)
    assert result.ok and result.form.encoding == UTF8
    assert [(d.code, d.line, d.is_error) for d in result.diagnostics] == [
        ("invalid-bytes", 3, False)]
    assert encode_program(result.program) == data


def test_an_unencodable_character_raises_never_writes_a_question_mark() -> None:
    result = parse_bytes(TURKISH.encode("cp1254"))
    network = result.program.networks[0]
    network.comments.append("snow ☃")
    with pytest.raises(EncodeError) as info:
        encode_program(result.program)
    assert info.value.char == "☃" and info.value.line == 3
    with pytest.raises(EncodeError):
        encode_text("a\nb€☃", TextForm("latin-1"))


def test_lines_end_only_at_lf_crlf_cr() -> None:
    text = "a\x0bb\x0cc\x1cd\x85e\u2028f\u2029g\rh\r\ni\nj"
    assert split_lines(text) == ["a\x0bb\x0cc\x1cd\x85e\u2028f\u2029g", "h", "i", "j"]
    result = parse("%@3\n// odd \u2028 \x85 \x1c breaks\nRD X0.0\nFOO 1\n%\n")
    assert [(d.code, d.line) for d in result.diagnostics] == [("unknown-instruction", 4)]
    _text, form, _diagnostics = decode_text("x\u2028y\n".encode())
    assert form.newline == "\n"


@pytest.mark.parametrize("text", [
    "%@3\nRD X0.0\nTMRB 1 " + "9" * 5000 + "\nWRT Y0.0\n%\n",
    "%@3\nRD X0.0\nSUB 24\n1\n" + "9" * 5000 + "\nWRT Y0.0\n%\n",
    "%@3\nRD X" + "9" * 5000 + ".0\nWRT Y0.0\n%\n",
    "%@3\nRD X1." + "9" * 5000 + "\nWRT Y0.0\n%\n",
    "%@3\nRD X0.0\nSUB " + "9" * 5000 + "\n1\n%\n",
    "%@" + "9" * 5000 + "\n1\n%\n%@3\nRD X0.0\nWRT Y0.0\n%\n",
    "%@3\nN" + "0" * 5000 + "1:\nRD X0.0\nWRT Y0.0\n%\n",
    "%@3\nRD X0.0\nSUB.300 " + "9" * 5000 + "\nWRT Y0.0\n%\n",
    "%@4\nA0.1\t" + "9" * 5000 + " text\n%\n%@3\nRD X0.0\nWRT Y0.0\n%\n",
])
def test_numbers_of_thousands_of_digits_give_diagnostics(text: str) -> None:
    result = parse(text)  # never Python's int-conversion ValueError
    for diagnostic in result.diagnostics:
        assert diagnostic.message() and len(diagnostic.message()) < 300


def test_binary_is_not_a_program() -> None:
    result = parse_bytes(bytes(range(256)) * 4)
    assert [d.code for d in result.diagnostics] == ["not-a-program"]
    garbage = parse("hello world\nthis is a letter, not a ladder\n!!\n")
    assert garbage.diagnostics[0].code == "not-a-program" and len(garbage.diagnostics) <= 3
    assert parse("RD X0.0\nWRT Y0.0\n").diagnostics[0].code == "missing-start"


def test_ladder_iii_sections_views_and_dialect() -> None:
    result = parse(cases.LADDER_III)
    assert result.ok, result.diagnostics
    program = result.program
    assert program.dialect == "fanuc" and program.framed
    assert [n.label for n in program.networks] == ["N00000", "N00001", "N00002"]
    assert program.networks[0].comments == ["--------------- module.lad \t(SIGNALS )"]
    assert program.networks[1].instructions[1].params[1] == -25600
    assert program.symbols is not None
    assert program.symbols.symbol(program.networks[0].instructions[0].operand) == "ESKIP"
    assert program.symbols.program_symbol(3) == "C62297"
    assert program.title == {2: "TEST MACHINE * P001", 7: "19/03/22 11:04"}
    assert next(iter(program.messages.values())).number == 1000
    assert encode_program(program) == cases.LADDER_III.encode()
    again = parse(parse_canonical(program))
    assert again.ok and again.program == program


def parse_canonical(program: object) -> str:
    from ladderworks.core.il import print_program

    return print_program(program)  # type: ignore[arg-type]


def test_unknown_sections_are_kept_with_a_warning() -> None:
    text = "%@A\n%@7\nwhatever\n%\n%@3-D\nRD X0.0\n%\n%@3\nRD X0.0\nWRT Y0.0\n%\n%@E\n"
    result = parse(text)
    assert result.ok
    assert [(d.code, d.is_error) for d in result.diagnostics] == [
        ("bad-section", False), ("bad-section", False)]
    assert [s.title for s in result.program.sections()] == ["%@7", "%@3-D"]
    assert encode_program(result.program) == text.encode()


def test_seed_program_edits_rewrite_only_the_edited_network() -> None:
    from ladderworks.core.il.printer import print_faithful
    from ladderworks.core.il.program import Instruction, Network

    text = "%@3\n// first\nRD   X0.0\nWRT  Y0.0\n\n; second\nRD X0.1\nWRT Y0.1\n%\n"
    program = parse(text).program
    assert print_faithful(program) == text
    program.networks[1].instructions[0] = Instruction("RD", program.networks[0].instructions[0]
                                                      .operand)
    assert print_faithful(program) == (
        "%@3\n// first\nRD   X0.0\nWRT  Y0.0\n\n; second\nRD X0.0\nWRT Y0.1\n%\n")
    program.networks.append(Network(list(program.networks[0].instructions), ["new"]))
    assert print_faithful(program).endswith("WRT Y0.1\n\n//new\nRD X0.0\nWRT Y0.0\n%\n")
    del program.networks[0]
    assert print_faithful(program).startswith("%@3\n\n; second\n")
