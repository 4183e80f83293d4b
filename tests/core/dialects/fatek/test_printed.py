"""WinProladder's printed mnemonic form: read, drawn, run; an unmodified file saved byte for
byte; a changed network written in the file's own form; each box-input pattern redrawn runs as
printed."""

from __future__ import annotations

import itertools
from dataclasses import replace
from pathlib import Path

import pytest

from ladderworks.core.compiler import compile
from ladderworks.core.dialects.fatek.printed import style_of
from ladderworks.core.dialects.fatek.printer import network_lines
from ladderworks.core.il import Network, Program
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.reading import parse_bytes, parse_file
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects.fatek.test_programs import fatek, get, put

EXAMPLE = Path(__file__).resolve().parents[4] / "resources" / "examples" / "fatek" / \
    "capping_printed.lst"
HEAD = "Printed Item: Mnemonic - Main_unit1\n\n"


def printed(*steps: str) -> str:
    """Step lines numbered as WinProladder prints them (`00003M …`); operand lines as given."""
    out, step = [], 0
    for text in steps:
        if text.startswith((" ", "#")):
            out.append(text)
        else:
            out.append(f"{step:05d}M {text}")
            step += 1
    return HEAD + "\n".join(out) + "\n"


def test_the_example_reads_with_warnings_only_and_saves_byte_for_byte() -> None:
    result = parse_file(EXAMPLE)
    assert [d.code for d in result.diagnostics] == ["fatek-not-simulated"] * 2
    assert encode_program(result.program) == EXAMPLE.read_bytes()


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_the_example_runs(monitored: bool) -> None:
    plc = ScanEngine(compile(parse_file(EXAMPLE).program), period_ms=10)
    plc.monitored = monitored
    plc.scan()
    assert get(plc, "S1") == 1  # ORG NOT X0 / SET( ) S1
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "S1") == 1  # SET holds
    program = "ORG X0\nAND NOT S1\nSET( ) S2"
    assert fatek(printed(*program.split("\n"))).networks  # SET( ) reads as a coil


def test_set_and_reset_with_spaces_and_the_printed_timer_line() -> None:
    plc = ScanEngine(compile(fatek(printed(
        "ORG      X0", "SET( )   S2", "ORG      X1", "RST( )   S2",
        "ORG      S2", "T10 .01 30", "ORG      T10", "OUT      Y0"))), period_ms=10)
    put(plc, "X0", 1)
    plc.scan()
    put(plc, "X0", 0)
    for _ in range(25):
        plc.scan()
    assert (get(plc, "S2"), get(plc, "Y0")) == (1, 0)
    for _ in range(10):
        plc.scan()
    assert get(plc, "Y0") == 1  # 30 x 10 ms (.01 base)
    put(plc, "X1", 1)
    plc.scan()
    plc.scan()
    assert (get(plc, "S2"), get(plc, "Y0")) == (0, 0)


def test_a_timer_line_with_a_wrong_base_is_refused_at_its_line() -> None:
    result = parse_bytes(printed("ORG X0", "T10 .1 30").encode(), "fatek")
    assert [(d.code, d.line) for d in result.diagnostics] == [("fatek-timer-base", 4)]


def test_the_printed_counter_line() -> None:
    plc = ScanEngine(compile(fatek(printed("ORG      X0", "LD       X1", "C5      3",
                                           "FO       0", "OUT      Y0"))))
    for _ in range(3):
        put(plc, "X0", 1)
        plc.scan()
        put(plc, "X0", 0)
        plc.scan()
    assert (get(plc, "C5"), get(plc, "Y0")) == (3, 1)
    put(plc, "X1", 1)  # CLR
    plc.scan()
    assert (get(plc, "C5"), get(plc, "Y0")) == (0, 0)


def test_comment_lines_and_other_printed_items_are_skipped() -> None:
    text = ("Printed Item: Ladder Diagram - Main_unit1\n  X0\nN0000  EN\n0000M  SAFETY\n"
            + printed("# a comment", "ORG      X0", "OUT      Y0")
            + "Printed Item: Element Comment - [Input Contact]\nX0  SAFETY\n")
    program = fatek(text)
    assert [i.name for i in program.networks[0].instructions] == ["RD", "WRT"]
    assert encode_program(program).decode() == text


def test_a_changed_network_is_written_in_the_printed_form() -> None:
    program = parse_file(EXAMPLE).program
    style = style_of(program.source.lines)  # type: ignore[union-attr]
    assert style is not None and style.unit == "M"
    first = program.networks[0]
    first.instructions = [*first.instructions[:-1],
                          first.instructions[-1]._replace(operand=first.instructions[-1].operand)]
    changed = program.networks[4]  # ORG S2 / AND X2 / T10 .01 R7
    changed.instructions = changed.instructions[:1] + changed.instructions[2:]
    saved = encode_program(program).decode().splitlines()
    at = saved.index("00012M AND      X2") if "00012M AND      X2" in saved else -1
    assert at == -1
    assert "00011M ORG      S2" in saved and "00012M T10 .01 R7" in saved
    again = fatek("\n".join(saved))
    assert again.networks[4].instructions == changed.instructions


@pytest.mark.parametrize("network", range(15))  # FO 2 on its box, a TR branch: one network
def test_every_network_of_the_example_prints_in_the_printed_form_and_reads_back(
        network: int) -> None:
    program = parse_file(EXAMPLE).program
    style = style_of(program.source.lines)  # type: ignore[union-attr]
    assert style is not None
    lines = network_lines(program.networks[network], True, style)
    assert all(line[:5].isdigit() or line.startswith("       ") for line in lines)
    before = [line for n in program.networks[:network] for line in network_lines(n, True)]
    again = fatek(HEAD + "\n".join([*before, *lines]))
    assert again.networks[network].instructions == program.networks[network].instructions


# Each pattern of a box's inputs as WinProladder prints them, with the inputs it reads
PATTERNS = {
    "second input a block": ("ORG X0\nLD X1\nC5 3\nFO 0\nOUT Y0", ("X0", "X1")),
    "an input LD OPEN": ("ORG X0\nLD OPEN\nC5 2\nOUT Y0", ("X0",)),
    "a series of contacts": ("ORG X0\nAND X1\nAND NOT X2\nLD X3\nOR X1\nC6 2\nOUT Y0",
                             ("X0", "X1", "X2", "X3")),
    "a TR point read back": ("ORG X0\nLD X1\nOR NOT X2\nOUT TR 0\nAND OPEN\nLD TR 0\n"
                             "FUN 94 ASCWR\n MD: 0\n S : R0\n Pt: R1\nFO 2\nOUT Y0",
                             ("X0", "X1", "X2")),
    "a coil after a box with no output": ("ORG X0\nAND X1\nFUN 08 _.MOV\n S : 7\n D : R5\n"
                                          "RST( ) S3\nSET( ) Y1", ("X0", "X1")),
    "boxes in cascade": ("ORG X0\nAND X1\nFUN 08 _.MOV\n S : 3\n D : R6\nRST( ) C7\n"
                         "RST( ) T12", ("X0", "X1")),
    "a box after coils": ("ORG X0\nOR X1\nSET( ) Y2\nRST( ) S4\nRST( ) C8\nRST( ) T13",
                          ("X0", "X1")),
    "a coil after a box's output": ("ORG X0\nT20 .01 2\nOUT Y3\nOUT Y4", ("X0",)),
}
WATCHED = ("Y0", "Y1", "Y2", "Y3", "Y4", "S3", "S4", "R5", "R6", "C5", "C6", "C7", "C8", "T12",
           "T13", "T20")


def _redrawn(program: Program) -> Program:
    """The program with every network drawn and coded again from the drawing."""
    networks = []
    for network in program.networks:
        net = layout_network(list(network.instructions))
        assert net.listing is None, network.instructions  # it has a ladder picture
        code, problems = network_to_instructions(replace(net, source=None), dialect="fatek")
        assert code is not None and not [d for d in problems if d.is_error], problems
        networks.append(Network(code, network.comments, network.label))
    return Program(networks=networks, dialect=program.dialect)


def _run(program: Program, inputs: tuple[str, ...]) -> list[list[int]]:
    plc = ScanEngine(compile(program), period_ms=10)
    seen = []
    for values in [*itertools.product((0, 1), repeat=len(inputs))] * 2:
        for name, value in zip(inputs, values, strict=True):
            put(plc, name, value)
        for _ in range(3):
            plc.scan()
            seen.append([get(plc, name) for name in WATCHED])
    return seen


@pytest.mark.parametrize("pattern", PATTERNS, ids=list(PATTERNS))
def test_each_box_input_pattern_redrawn_runs_as_printed(pattern: str) -> None:
    text, inputs = PATTERNS[pattern]
    program = fatek(printed(*text.split("\n")))
    assert _run(_redrawn(program), inputs) == _run(program, inputs)


def test_a_printout_cut_in_a_fun_box_is_an_error_at_its_line() -> None:
    cut = printed("ORG X0", "FUN 08 _.MOV", "       S : 7")
    result = parse_bytes(cut.encode(), "fatek")
    assert [(d.code, d.line) for d in result.diagnostics] == [("fatek-missing-operand", 4)]
    assert "D" in result.diagnostics[0].message()


def test_a_number_of_thousands_of_digits_is_an_error_at_its_line() -> None:
    """Found by tests/fuzz/test_fatek_printed_fuzz.py: int() refuses 4300+ digits."""
    result = parse_bytes(printed("ORG X0", "OUT Y" + "9" * 5000).encode(), "fatek")
    assert [(d.code, d.line, d.column) for d in result.diagnostics] == [
        ("fatek-long-number", 4, 13)]


def _split(text: str) -> str:
    """The printout as `pdftotext` without -layout gives it: a step's operand on a later line
    after a blank one (`00001M SET( )`, ``, `S1`)."""
    out = []
    for line in text.split("\n"):
        head, _, operand = line.partition("   ")
        word = head[7:].strip()
        if line[:5].isdigit() and operand.strip() and word in ("ORG", "LD", "AND", "OR", "OUT",
                                                                 "SET( )", "RST( )", "FO"):
            out += [head.rstrip(), "", operand.strip(), ""]
        else:
            out.append(line)
    return "\n".join(out)


def test_the_text_pdftotext_gives_without_layout_reads_as_the_printout() -> None:
    text = EXAMPLE.read_text(encoding="utf-8")
    split = _split(text)
    assert split != text and "\n00001M SET( )\n\nS1\n" in split
    assert [n.instructions for n in fatek(split).networks] == [
        n.instructions for n in fatek(text).networks]
    # two steps before their operands, as pdftotext printed the real printout's step 125
    both = printed("ORG X0", "OUT TR 0", "AND SHORT", "SET( )", "LD") + "S12\n\nTR 0\n"
    both += "00005M RST( )   S11\n"
    assert [n.instructions for n in fatek(both).networks] == [n.instructions for n in fatek(
        printed("ORG X0", "OUT TR 0", "AND SHORT", "SET( )   S12", "LD      TR 0",
                "RST( )   S11")).networks]


def test_an_unknown_fun_opens_draws_runs_as_nothing_and_prints_back() -> None:
    """Issue 37: nothing a real program holds stops it from opening (FUN 60 is not simulated)."""
    text = printed("ORG      X0", "FUN 60 DP.XYZ", "       S : R0", "       D : R1",
                   "FO       0", "OUT      Y0", "ORG      X1", "OUT      Y1")
    result = parse_bytes(text.encode(), "fatek")
    assert [(d.code, d.line, d.is_error) for d in result.diagnostics] == [
        ("fatek-not-simulated", 4, False)]
    program = result.program
    box = next(i for i in program.networks[0].instructions if i.spec.cnc)
    assert box.name == "FBS.FUN" and box.comment == "FUN 60DP XYZ: S: R0, D: R1"
    assert layout_network(list(program.networks[0].instructions)).listing is None
    plc = ScanEngine(compile(program))
    put(plc, "X0", 1)
    put(plc, "X1", 1)
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "Y1")) == (0, 1)  # FO 0 stays 0; the rest runs
    lines = network_lines(program.networks[0], True)
    assert "FUN 60DP XYZ" in lines and "    S: R0" in lines
    again = fatek(HEAD + "\n".join(lines) + "\n")
    assert again.networks[0].instructions == program.networks[0].instructions
    assert encode_program(program) == text.encode()


def test_the_timer_line_of_each_base() -> None:
    program = fatek(printed("ORG X0", "T10 .01 5", "ORG X0", "T60 .1 R3", "ORG X0", "T200 1 7"))
    presets = [i.params[:2] for n in program.networks for i in n.instructions
               if i.name == "FBS.TMR"]
    assert [p[0] for p in presets] == [10, 60, 200] and presets[0][1] == 5
    style = style_of(printed("ORG X0", "SET( )   S1").split("\n"))
    assert style is not None
    lines = [line for n in program.networks for line in network_lines(n, True, style)]
    assert [line[7:] for line in lines if "T" in line[7:9]] == [
        "T10 .01 5", "T60 .1 R3", "T200 1 7"]
