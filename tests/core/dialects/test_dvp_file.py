"""The `.dvp` reader on projects the tests make: key rules, codes, comments, and bad input (every
truncation, byte flips, damaged parts) giving one diagnostic with its byte offset, never a
traceback."""

from __future__ import annotations

import random

import pytest

from ladderworks.core.diagnostics import MESSAGES, Severity
from ladderworks.core.dialects.delta.dvp_codes import END
from ladderworks.core.dialects.delta.dvp_file import (
    PROGRAM_START,
    DvpError,
    read_dvp,
    read_or_diagnostic,
)
from ladderworks.core.dialects.delta.dvp_program import parse_dvp, save_refused
from ladderworks.core.il.reading import parse_bytes
from tests.core.dialects.dvp_samples import cell, make_dvp, row

TIMER = ["LD X0", "TMR T0 K5", "LD T0", "OUT Y0", "LD X1", "RST T0", "END"]


def _texts(data: bytes) -> list[str]:
    return [each.text() for each in read_dvp(data).instructions]


@pytest.mark.parametrize("version", [214, 215, 216])
def test_each_format_version_unscrambles_with_its_own_key(version: int) -> None:
    data = make_dvp(version=version, key=b"\xa7\x13\xee\x42")
    project = read_dvp(data)
    assert [each.text() for each in project.instructions] == TIMER
    assert [each.step for each in project.instructions] == [0, 1, 5, 6, 7, 8, 11]
    assert (project.version, project.capacity, project.steps, project.title) == (
        version, 64, 12, "sample")
    assert project.comments == {"X0": "start"}


def test_the_codes_and_operands_of_each_form() -> None:
    words = (0xABEA, 0x80AE, 0x0000, 0x0000, 0x0001, 0x0000, 0x0200, 0x0000, 0x0001, 0x0000,
             0x8028, 0x0064, 0x0000, 0x0688, 0x0604,  # MOV K100 D580
             0x8039, 0x06E8, 0x0603, 0x0000, 0x0000, 0x0000, 0x0000, 0x0000, 0x0080,
             0x060E, 0x0600, 0x0000, 0x0000,  # DADD D500 K-2147483648 D7
             0x7FFA, 0x81E5, 0x060E, 0x0600, 0x0000, 0x0000, 0x00FF, 0x00FF, 0x00FF, 0x00FF,
             0x8006, 0x03EB, 0x0612, 0x0600, 0x0000, 0x0000,  # DCNT C235 D9
             0x7FFC, 0xA410, 0x8102, 0x0465, 0x0008, 0x8007, 0x06F2, 0x0603,  # RST D505
             0xFEAE, 0x8007, 0x0601, 0x040E, 0x3005, 0x8010, 0x0805, 0x0000,
             0x80F1, 0x0266, 0x0066, 0x0046, 0x0041, 0x0604, 0x0600, 0x0000, 0x0000, END)
    assert _texts(make_dvp(words)) == [
        "LD M1002", "TO K0 K1 H0 K1", "MOV K100 D580", "DADD D500 K-2147483648 D7", "MPS",
        "DAND< D7 K-1", "DCNT C235 D9", "MPP", "LD X20", "LDF M101", "RST D505", "ORI C174",
        "RST C1", "P5", "CJ P5", "DMOVR F12.4 D2", "END"]


def test_bit_devices_are_delta_device_addresses() -> None:
    # S 0x000+n, M0-M1535 0x800+n, M1536.. 0xB000+n (only in an operand), C 0xE00+n
    words = (0xA000, 0xC3FF, 0xECB0, 0xDDFF, 0x4EC8, 0x8107, 0x0400, 0x00B0,
             0x8060, 0x0400, 0x0000, 0x0409, 0x0000, END)
    assert _texts(make_dvp(words)) == [
        "LD S0", "AND S1023", "OR M1200", "ANI M1535", "OUT C200", "PLS M1536",
        "ZRST S0 S9", "END"]


def test_an_unknown_code_is_kept_with_its_operands_and_a_warning() -> None:
    project = read_dvp(make_dvp((0xA400, 0x821C, 0x0600, 0x0200, 0x000A, 0x0000, END)))
    assert [each.text() for each in project.instructions] == ["LD X0", "?821C T0 K10", "END"]
    (warning,) = project.warnings
    assert (warning.code, warning.severity, warning.args["offset"]) == (
        "dvp-unknown-code", Severity.WARNING, PROGRAM_START + 2)
    result = parse_dvp(make_dvp((0xA400, 0x821C, 0x0600, 0x0200, 0x000A, 0x0000, END)))
    assert [d.code for d in result.diagnostics][:1] == ["dvp-unknown-code"]


def test_comments_keep_their_text_and_big5_punctuation() -> None:
    lines = (b"X0$&ba\xfelat\n"  # cp1254: "başlat"
             b"M1007$&Data doesn\xa1\xa6t exist\n"  # WPLSoft's default comments: Big5
             b"D10$&\n")
    assert read_dvp(make_dvp(comments=lines)).comments == {
        "X0": "başlat", "M1007": "Data doesn’t exist", "D10": ""}


def test_an_empty_program_reads_with_a_warning() -> None:
    project = read_dvp(make_dvp(()))
    assert project.instructions == []
    assert [w.code for w in project.warnings] == ["dvp-no-program"]


X, Y, M, D, K = 0x09, 0x0A, 0x05, 0x02, 0x04


def test_an_uncompiled_project_is_read_from_its_ladder_drawing() -> None:
    drawing = (row(cell(0x12, X, 0), cell(0x22, M, 1000), cell(0x32, Y, 0))
               + row(cell(0xE2, 0, 0x0A), cell(0x80, D, 0), cell(0x80, K, 7), cell(0x32, Y, 1))
               + row(cell(0x12, X, 0o12), cell(0x42, 0, 0x0039, 0x10), cell(0x80, K, 0x84D0),
                     cell(0x90, 0, 0), cell(0x80, D, 2), cell(0x90, 0, 0), cell(0x80, D, 4),
                     cell(0x90, 0, 0))
               + row(cell(0x12, X, 1), cell(0x42, 0, 0xD000), cell(0x80, Y, 2))
               + row(cell(0x42, 0, 0x000F, 0x01)))
    project = read_dvp(make_dvp((), drawing=drawing))
    assert [(each.step, each.text()) for each in project.instructions] == [
        (0, "LD X0"), (1, "ANI M1000"), (2, "OUT Y0"), (3, "LD>= D0 K7"), (8, "OUT Y1"),
        (9, "LD X12"), (10, "DADD K34000 D2 D4"), (23, "LD X1"), (24, "SET Y2"), (25, "END")]
    assert project.drawn and [w.code for w in project.warnings] == ["dvp-from-drawing"]


def test_edge_contacts_inv_and_float_constants_in_a_drawing() -> None:
    drawing = (row(cell(0xB2, X, 0), cell(0xC2, M, 3), cell(0xD2, 0), cell(0x32, Y, 0))
               + row(cell(0x12, X, 1), cell(0x42, 0, 0x00F1, 0x10), cell(0x80, 0x03, 0x6666),
                     cell(0x90, 0, 0x4146, 0x10), cell(0x80, D, 2), cell(0x90, 0, 0)))
    assert [each.text() for each in read_dvp(make_dvp((), drawing=drawing)).instructions] == [
        "LDP X0", "ANDF M3", "INV", "OUT Y0", "LD X1", "DMOVR F12.4 D2"]


@pytest.mark.parametrize("cells", [
    (cell(0x12, X, 0), cell(0x54, 0x10), cell(0x32, Y, 0)),  # a branch down
    (cell(0x12, X, 1), cell(0x42, 0, 0x0010), cell(0x80, 0x0C, 0)),  # CJ P0: P is not drawn
    (cell(0x42, 0, 0x001C),),  # FEND: the subroutines' pointers are not drawn
])
def test_a_drawing_the_reader_cannot_take_whole_is_not_used(cells: tuple[bytes, ...]) -> None:
    data = make_dvp((), drawing=row(*cells))
    project = read_dvp(data)
    assert project.instructions == []
    (warning,) = project.warnings
    assert warning.code == "dvp-drawing-unread"
    assert data[warning.args["offset"]] in (0x54, 0x80, 0x42)


def test_a_drawing_with_a_branch_is_not_guessed() -> None:
    drawing = (row(cell(0x12, X, 0), cell(0x54, 0x10), cell(0x32, Y, 0))
               + row(cell(0x00), cell(0x59), cell(0x32, Y, 1)))
    data = make_dvp((), drawing=drawing)
    project = read_dvp(data)
    assert project.instructions == []
    (warning,) = project.warnings
    assert warning.code == "dvp-drawing-unread"
    assert data[warning.args["offset"]] == 0x54


@pytest.mark.parametrize(("change", "code", "offset"), [
    (lambda d: b"PK\x03\x04" + d[4:], "dvp-not-dvp", 0),
    (lambda d: d[:0x4C] + b"\xe7\x03" + d[0x4E:], "dvp-version", 0x4C),
    (lambda d: d.replace(b"Function=Initial Value", b"Function=Initial Walue"),
     "dvp-bad-layout", PROGRAM_START),
    (lambda d: d.replace(b"X0$&start", b"X0 start!"), "dvp-bad-comment", None),
    (lambda d: d.replace(b"<DataEnd>\n<TypeBegin>", b"<DataEnd>\n<TypeBegun>", 1),
     None, None),
])
def test_damaged_parts_give_one_diagnostic_at_their_byte(change, code, offset) -> None:
    data = change(make_dvp())
    project, diagnostic = read_or_diagnostic(data)
    if code is None:  # a damaged marker between sections: the comments are still found
        assert project is not None and project.comments == {"X0": "start"}
        return
    assert project is None and diagnostic is not None
    assert diagnostic.code == code
    assert "{" not in diagnostic.message()
    if offset is not None:
        assert diagnostic.args["offset"] == offset
    else:
        assert data[diagnostic.args["offset"]:].startswith(b"X0 start!")


@pytest.mark.parametrize(("words", "code", "at"), [
    ((0x0100, END), "dvp-stray-operand", 0),  # an operand word with no instruction
    ((0xA400, 0x4500), "dvp-no-end", 2),
    ((0xA400, END, 0xA401), "dvp-after-end", 2),
    ((0xA700, END), "dvp-unknown-device", 0),  # device nibble 7: none known
    ((0x8107, 0x0400, 0x00BA, END), "dvp-unknown-device", 1),  # past M4095
    ((0x8028, 0x0A64, 0x0000, 0x0688, 0x0604, END), "dvp-bad-operand", 1),
    ((0x8028, 0x0064, 0x0000, 0x0688, END), "dvp-operand-count", 0),
    ((0x8003, 0x0100, END), "dvp-operand-count", 0),  # TMR without its value
    ((0xA400, 0x4500, 0x1234, END), "dvp-unknown-code", 2),
])
def test_damaged_program_words_give_their_step_and_byte(words, code, at) -> None:
    with pytest.raises(DvpError) as caught:  # 0x1234 is no instruction at all: not kept
        read_dvp(make_dvp(words))
    assert caught.value.code == code
    assert caught.value.offset == PROGRAM_START + 2 * at
    assert "{" not in caught.value.diagnostic().message()


def test_every_truncation_of_a_project_is_cut_short_at_its_length() -> None:
    data = make_dvp()
    for length in range(len(data)):
        project, diagnostic = read_or_diagnostic(data[:length])
        assert project is None and diagnostic is not None, length
        assert diagnostic.code == ("dvp-truncated" if length >= 4 else "dvp-not-dvp"), length
        if length >= 4:
            assert diagnostic.args["offset"] == length
    assert read_or_diagnostic(data)[0] is not None


def test_random_byte_flips_never_raise() -> None:
    rng = random.Random(36)
    data = make_dvp()
    outcomes: set[str] = set()
    for _ in range(1500):
        flipped = bytearray(data)
        for _ in range(rng.randrange(1, 4)):
            flipped[rng.randrange(len(flipped))] ^= 1 << rng.randrange(8)
        project, diagnostic = read_or_diagnostic(bytes(flipped))
        assert (project is None) != (diagnostic is None)
        outcomes.add(diagnostic.code if diagnostic is not None else "read")
        parse_bytes(bytes(flipped))  # and the Program reading of it: no traceback either
    assert {"read", "dvp-truncated", "dvp-not-dvp", "dvp-version"} <= outcomes
    assert any(code in outcomes for code in ("dvp-stray-operand", "dvp-bad-operand",
                                             "dvp-unknown-device", "dvp-no-end"))


READER_CODES = ("dvp-not-dvp", "dvp-truncated", "dvp-version", "dvp-bad-layout",
                "dvp-unknown-code", "dvp-unknown-device", "dvp-bad-operand", "dvp-operand-count",
                "dvp-stray-operand", "dvp-no-end", "dvp-after-end", "dvp-bad-section",
                "dvp-bad-comment", "dvp-no-program", "dvp-save-refused", "dvp-from-drawing",
                "dvp-drawing-unread")


def test_every_dvp_message_reads_with_the_arguments_the_reader_gives() -> None:
    for code in READER_CODES:
        MESSAGES[code].format(offset=1, step=2, word="8FFE", version=300, path="x.dvp")


def test_parse_bytes_reads_a_project_as_a_delta_program_with_its_comments() -> None:
    result = parse_bytes(make_dvp(comments=b"X0$&start\nT0$&delay\nD10$&speed\n"))
    assert result.ok, [d.message() for d in result.diagnostics]
    program = result.program
    assert program.dialect == "delta"
    assert program.symbols is not None
    from ladderworks.core.dialects.delta import DEVICES
    assert program.symbols.lookup(DEVICES.bit("X0")).comment == "start"
    assert program.symbols.lookup(DEVICES.bit("T0")).comment == "delay"
    assert program.symbols.lookup(DEVICES.word("T0")[0]).comment == "delay"
    assert program.symbols.lookup(DEVICES.word("D10")[0]).comment == "speed"


def test_a_damaged_project_is_one_error_and_an_empty_program() -> None:
    data = make_dvp()
    result = parse_bytes(data[:-3])
    assert [d.code for d in result.diagnostics] == ["dvp-truncated"]
    assert not result.ok and result.program.networks == []


def test_damaged_program_words_show_what_was_read_before_them() -> None:
    result = parse_bytes(make_dvp((0xA400, 0x4500, 0xA401, 0xA700, 0x4501, END)))
    assert [(d.code, d.line) for d in result.diagnostics] == [("dvp-unknown-device", 4)]
    assert result.program.source is not None
    assert [line.split() for line in result.program.source.lines] == [
        ["LD", "X0"], ["OUT", "Y0"], ["LD", "X1"]]
    assert not result.ok


def test_saving_over_a_project_is_refused(tmp_path) -> None:
    project = tmp_path / "machine.dvp"
    project.write_bytes(make_dvp())
    refused = save_refused(project)
    assert refused is not None and refused.code == "dvp-save-refused"
    assert save_refused(tmp_path / "machine.il", read_from_dvp=True) is None
    assert save_refused(tmp_path / "new.DVP", read_from_dvp=True) is not None
    assert save_refused(tmp_path / "new.dvp") is None  # a Delta text list may be named .dvp
    text = tmp_path / "list.dvp"
    text.write_text("LD X0\nOUT Y0\nEND\n")
    assert save_refused(text) is None

