"""Fatek programs through the dialect framework: sniffed, read, saved byte for byte, checked,
compiled and run (fast and monitored); the examples; bad input at its line."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core import dialects
from ladderworks.core.compiler import compile, compile_program
from ladderworks.core.dialects.fatek import DEVICES
from ladderworks.core.dialects.fatek.ascii_files import load_ascii_files
from ladderworks.core.dialects.fatek.printer import network_lines
from ladderworks.core.dialects.fatek.terminal import AsciiTerminal
from ladderworks.core.il import Program
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.reading import parse_bytes, parse_file
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.session import PlcRun
from tests.core.dialects import conftest as dialects_conftest
from tests.core.dialects.fatek.test_ascii_format import REPORT

EXAMPLES = Path(__file__).resolve().parents[4] / "resources" / "examples" / "fatek"
LISTINGS = sorted(EXAMPLES.glob("*.lst"))


def fatek(text: str) -> Program:
    """A Fatek program read from its text (no diagnostic error)."""
    result = parse_bytes(text.encode("utf-8"), "fatek")
    assert result.ok, [d.located("t") for d in result.diagnostics]
    return result.program


def engine(text: str, monitored: bool = False) -> ScanEngine:
    plc = ScanEngine(compile(fatek(text)), period_ms=10)
    plc.monitored = monitored
    return plc


def get(plc: ScanEngine, text: str) -> int:
    """A Fatek device's value (a bit, or a signed word)."""
    return dialects_conftest.get(plc, text, "fatek")


def put(plc: ScanEngine, text: str, value: int) -> None:
    """Set a Fatek device."""
    dialects_conftest.put(plc, text, value, "fatek")


@pytest.mark.parametrize("path", LISTINGS, ids=lambda p: p.name)
def test_examples_are_recognised_read_saved_byte_for_byte_and_compiled(path: Path) -> None:
    data = path.read_bytes()
    assert dialects.sniff(data.decode("utf-8")) is dialects.get("fatek")
    result = parse_file(path)
    assert result.program.dialect == "fatek"
    assert not [d for d in result.diagnostics if d.is_error]
    assert encode_program(result.program) == data
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    assert not [d for d in compiled.diagnostics if d.is_error]


@pytest.mark.parametrize("path", LISTINGS, ids=lambda p: p.name)
def test_changed_networks_are_written_back_in_fatek_form(path: Path) -> None:
    """Every network printed by the dialect's printer reads back as the same instructions."""
    program = parse_file(path).program
    text = "\n".join(line for network in program.networks
                     for line in network_lines(network, False))
    again = fatek(text)
    assert [n.instructions for n in again.networks] == [n.instructions for n in program.networks]


def test_a_changed_program_keeps_its_other_lines() -> None:
    path = EXAMPLES / "conveyor.lst"
    program = parse_file(path).program
    first = program.networks[0]
    changed = first.instructions[-1]._replace(operand=DEVICES.bit("Y20"))
    first.instructions = [*first.instructions[:-1], changed]
    saved = encode_program(program).decode("utf-8").splitlines()
    original = path.read_text(encoding="utf-8").splitlines()
    assert saved[:2] == original[:2]  # the page header
    assert saved[2:6] == ["ORG      X0", "OR       Y0", "AND NOT  X1", "OUT      Y20"]
    assert saved[6:] == original[6:]


def test_sniffing_tells_fatek_from_delta_and_the_pmc() -> None:
    assert dialects.sniff("ORG X0\nAND X1\nOUT Y0\n") is dialects.get("fatek")
    assert dialects.sniff("ORG\tX\t0\nLD\tX\t1\nORLD\nOUT\tY\t0\n") is dialects.get("fatek")
    assert dialects.sniff("LD X0\nANI X1\nOUT Y0\nEND\n") is dialects.get("delta")
    assert dialects.sniff("%@3\nRD X0.0\nWRT Y0.0\n%\n") is None
    forced = parse_bytes(b"LD X0\nOUT Y0\n", "fatek")
    assert forced.program.dialect == "fatek"


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_conveyor(monitored: bool) -> None:
    plc = engine((EXAMPLES / "conveyor.lst").read_text(encoding="utf-8"), monitored)
    plc.scan()
    assert get(plc, "R2") == 100 and get(plc, "Y10") == 1  # M1924: MOV; C0 < 3
    put(plc, "X0", 1)
    plc.scan()
    put(plc, "X0", 0)
    for _ in range(298):
        plc.scan()
    assert (get(plc, "Y0"), get(plc, "Y1")) == (1, 0)
    plc.scan()
    plc.scan()
    assert get(plc, "Y1") == 1 and get(plc, "T50") == 30
    for _ in range(5):
        put(plc, "X2", 1)
        plc.scan()
        put(plc, "X2", 0)
        plc.scan()
    assert (get(plc, "C0"), get(plc, "Y2"), get(plc, "M10"), get(plc, "Y3")) == (5, 1, 1, 1)


def test_first_scan_and_clock_relays() -> None:
    plc = engine("ORG M1924\nOUT M0\nORG M1921\nOUT M1\nORG M1924\nFUN 15 (+1)\n D : R0\n"
                 "ORG M1922\nFUN 15P (+1)\n D : R1")
    seen = []
    for _ in range(250):  # 2.5 s at 10 ms
        plc.scan()
        seen.append(get(plc, "M1"))
    assert get(plc, "R0") == 1  # M1924 only in the first scan
    assert get(plc, "R1") == 3  # M1922 (1 s clock) rose at 0, 1 and 2 s
    assert seen[:12] == [1] * 5 + [0] * 5 + [1, 1]  # M1921: 0.1 s clock


def test_production_report_prints_the_seed_report() -> None:
    """004: X0 0 -> 1 with X1, X2 at 0 prints the report through Port 1."""
    path = EXAMPLES / "production_report.lst"
    run = PlcRun(period_ms=10)
    files = load_ascii_files(path)
    assert files.diagnostics == []
    run.use_ascii_files(files.files)
    assert run.load_program(parse_file(path).program).binary is not None
    run.start()
    run.run_scans(2)
    assert run.ascii_terminal.text() == ""
    assert run.engine is not None
    put(run.engine, "X1", 1)  # PAU
    put(run.engine, "X0", 1)
    run.run_scans(2)
    assert run.ascii_terminal.text() == ""
    put(run.engine, "X0", 0)
    put(run.engine, "X1", 0)
    run.run_scans(1)
    put(run.engine, "X0", 1)
    run.run_scans(3)
    assert run.ascii_terminal.text() == REPORT
    assert get(run.engine, "Y0") == 1  # FO2 DN


@pytest.mark.parametrize(("text", "code", "line", "error"), [
    ("ORG X0\nOUT Y0\nOUT Y1\n", "", 0, True),
    ("ORG X0\nOUT Y0\n   0  OUT Y1\n", "", 0, True),
    ("ORG X0\nAND X1\nOUT Y0\nOUT Y2\n\nOUT Y3\n", "", 0, True),
    ("ORG X0\nOUT Y0\nOUT Y1\nFUN 999 XYZ\n  D : R0\n", "fatek-not-simulated", 4, False),
    ("ORG X0\nANDF 999 XYZ\n  Sa: R0\n  Sb: R1\nOUT Y0\n", "fatek-unknown-fun", 2, True),
    ("ORG X0\nFUN 11 (+)\n  Sa: R0\n  Sb: R1\nOUT Y0\n", "fatek-missing-operand", 2, True),
    ("ORG X0\nFUN 8 MOV\n  S : R0\n  D : 5\n", "fatek-operand", 4, True),
    ("ORG X0\nFUN 10 TOGG\n  D : R0\n", "fatek-bit-operand", 3, True),
    ("ORG X0\nFUN 24 SUM\n  Ts : R0\n  L : 4\n", "fatek-missing-operand", 2, True),
    ("ORG X0\nFUN 8 MOV\n  S : R0\n  D : R1\n  D : R2\n", "fatek-extra-operand", 5, True),
    ("ORG X0\nFUN 140 HSPSO\n  Ps: 0\n  SR: R0\n  WR: R100\n  : C1\nFO 0\nOUT Y0\n",
     "fatek-not-simulated", 2, False),
    ("ORG X0\nTMR T0 0.1S 100\n", "fatek-timer-base", 2, True),
    ("ORG X0\nTMR T0\n", "fatek-missing-operand", 2, True),
    ("ORG X0\nOUT Y0\nFO 1\nOUT Y1\n", "fatek-fo", 3, True),
    ("ORG X0\nCTR T1 5\n", "fatek-device-kind", 2, True),
])
def test_bad_input_is_diagnosed_at_its_line(text: str, code: str, line: int,
                                            error: bool) -> None:
    result = parse_bytes(("Printed Item: Mnemonic - T\n" + text).encode(), "fatek")
    found = [(d.code, d.line - 1, d.is_error) for d in result.diagnostics]
    if not code:
        assert found == []
        return
    assert found[:1] == [(code, line, error)]


def test_an_output_on_the_left_rail_is_an_error_at_its_line() -> None:
    result = parse_bytes(b"     0  ORG      X0\n     1  OUT      Y0\n     2  OUT      Y1\n"
                         b"     3  ORG      X1\n     4  ANDLD\n", "fatek")
    assert [(d.code, d.line) for d in result.diagnostics] == [("fatek-stack-empty", 5)]
    result = parse_bytes(b"OUT Y0\n", "fatek")
    assert [(d.code, d.line) for d in result.diagnostics] == [("fatek-output-on-rail", 1)]


def test_a_malformed_ascii_file_is_diagnosed_at_its_line(tmp_path: Path) -> None:
    program = tmp_path / "p.lst"
    program.write_text("ORG X0\nFUN 94 ASCWR\n MD: 0\n S : R1000\n Pt: R0\n", encoding="utf-8")
    (tmp_path / "p.lst.ascii").write_text("[R1000]\n'ok',\n'broken,/,END\n[Q5]\n'x',END\n",
                                          encoding="utf-8")
    files = load_ascii_files(program)
    assert [(d.code, d.line) for d in files.diagnostics] == [
        ("fatek-ascii-quote", 3), ("fatek-ascii-section", 4)]
    assert list(files.files.values()) == [None]  # kept as a file with errors: ASCWR ERR


def test_boxes_are_drawn_and_the_not_simulated_keep_their_operand_lines() -> None:
    program = fatek("ORG X0\nFUN 140 HSPSO\n  Ps: 0\n  SR: R0\n  WR: R100\n  : C1\n"
                    "ORG X1\nFUN 8 MOV\n  S : 5\n  D : R3\n")
    hspso, mov = (layout_network(n.instructions) for n in program.networks)
    assert hspso.listing is None and mov.listing is None
    box = next(i for i in program.networks[0].instructions if i.spec.cnc)
    assert box.comment == "Ps: 0, SR: R0, WR: R100, : C1"
    plc = ScanEngine(compile(program))
    put(plc, "X0", 1)
    put(plc, "X1", 1)
    plc.scan()
    assert get(plc, "R3") == 5


def test_terminal_is_a_fresh_one_per_run() -> None:
    assert PlcRun().ascii_terminal is not PlcRun().ascii_terminal
    assert isinstance(PlcRun().ascii_terminal, AsciiTerminal)


def test_the_ror_registers_and_the_last_d_register_are_program_devices() -> None:
    """R5000-R8071 and D0-D4095 (FBs manual; docs/dialects.md): written and read by a program,
    kept apart from R0-R4167 and the counters' values; R4168 is refused at its line."""
    plc = engine("ORG M1924\nFUN 8 MOV\n S : 1234\n D : R5000\n"
                 "ORG M1924\nFUN 11 (+)\n Sa: R5000\n Sb: 1\n D : R8071\n"
                 "ORG M1924\nFUN 8 MOV\n S : R8071\n D : D4095\n")
    plc.scan()
    assert (get(plc, "R5000"), get(plc, "R8071"), get(plc, "D4095")) == (1234, 1235, 1235)
    assert get(plc, "R0") == 0 and get(plc, "R4167") == 0 and get(plc, "C200") == 0
    result = parse_bytes(b"ORG X0\nFUN 8 MOV\n S : 1\n D : R4168\n", "fatek")
    assert [(d.code, d.line) for d in result.diagnostics] == [("fatek-operand", 4)]


# The mnemonic column of the FBs/FB-PLC manuals' examples (FBs manual §5.1, FB-PLC manual §6.1:
# the FP-07/FP-08 key-in form): `FUN n` without its name and operand lines `D: R 0`, a space
# between the device letter and its number. Written here in that form, not copied.
MANUAL_FORM = ("ORG X0\nFUN 15P\n D: R 0\nFO 0\nOUT Y0\n"
               "ORG X1\nFUN 11D\n Sa: R 0\n Sb: R 2\n D: R 4\n")


def test_the_manuals_key_in_form_reads_runs_and_saves_as_it_was() -> None:
    result = parse_bytes(MANUAL_FORM.encode(), "fatek")
    assert result.ok, [d.located("t") for d in result.diagnostics]
    assert encode_program(result.program) == MANUAL_FORM.encode()
    plc = ScanEngine(compile(result.program), period_ms=10)
    put(plc, "R0", 32766)
    for x0 in (1, 0, 1):  # two rising edges of X0: R0 32766 -> 32767 -> -32768 (overflow)
        put(plc, "X0", x0)
        plc.scan()
    assert get(plc, "R0") == -32768 and get(plc, "Y0") == 1  # FO0: the overflow
    put(plc, "R0:4", 100_000)
    put(plc, "R2:4", 23)
    put(plc, "X1", 1)
    plc.scan()
    assert get(plc, "R4:4") == 100_023  # FUN 11D: R1-R0 + R3-R2 -> R5-R4


def test_the_manuals_up_down_counter_on_a_register_runs() -> None:
    """FUN 7 with `CV: R 0` (FBs manual §5.1; it was refused: LadderWorks took only C)."""
    plc = engine("ORG X0\nLD X1\nLD X2\nFUN 7\n CV: R 0\n PV: 3\nFO 0\nOUT Y0\n")
    put(plc, "X1", 1)  # U/D: up
    for x0 in (1, 0, 1, 0, 1):  # three rising edges of CK
        put(plc, "X0", x0)
        plc.scan()
    assert get(plc, "R0") == 3 and get(plc, "Y0") == 1
    put(plc, "X2", 1)  # CLR
    plc.scan()
    assert get(plc, "R0") == 0 and get(plc, "Y0") == 0


def test_a_changed_up_down_counter_is_written_so_that_it_reads_back() -> None:
    """FUN 7's preset is written `PV:` (the manuals' label), not the row's name `preset:`,
    which the reader refused: a changed network with UDCTR could not be opened again."""
    for cv in ("C200", "R7"):
        program = fatek(f"ORG X0\nLD X3\nLD X1\nFUN 7 UDCTR\n  CV: {cv}\n  PV: 2\nFO 0\nOUT Y1\n")
        lines = [line for network in program.networks
                 for line in network_lines(network, False)]
        assert "    PV: 2" in lines and f"    CV: {cv}" in lines
        again = fatek("\n".join(lines))
        assert [n.instructions for n in again.networks] == [
            n.instructions for n in program.networks]
