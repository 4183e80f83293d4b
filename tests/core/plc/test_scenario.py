"""Scenario files: reading (FANUC signal-operation lines, EXPECT, WAITFOR) and running."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import parse_address
from ladderworks.core.compiler import compile_program
from ladderworks.core.il import parse, parse_file
from ladderworks.core.plc.scenario import Step, parse_scenario, rounded, run_scenario
from ladderworks.core.plc.session import PlcRun
from ladderworks.core.symbols import Symbol, SymbolTable
from tests.core.plc.conftest import EXAMPLES
from tests.hypothesis_profiles import examples

TIMER = "%@3\nRD R1.4\nTMR 1\nWRT R1.7\n%\n"


def loaded(text: str | None = None, example: str | None = None, period_ms: int = 8) -> PlcRun:
    """A cold-started PlcRun of program text or an example."""
    program = (parse_file(EXAMPLES / example) if example else parse(text or "")).program
    plc = PlcRun(period_ms=period_ms)
    assert plc.load_program(program).binary is not None
    return plc


def test_reads_header_remark_sets_with_types_and_checks() -> None:
    scenario = parse_scenario(
        "PMC SIGNAL DATA\nREMARK,first\nREMARK,second is ignored\n"
        "SET,0,X2.1,1,,X40,0x12,BYTE,D10,-2,WORD\nS,5,X2.3,1\n"
        "EXPECT,16,G30,100\nWAITFOR,1000,R1.7,1\n")
    assert scenario.ok, scenario.error_texts()
    assert scenario.remark == "first"
    first, second, expect, wait = scenario.steps
    assert [(t.text, t.width, v) for t, v in first.items] == [
        ("X2.1", 1, 1), ("X40", 1, 0x12), ("D10", 2, 0xFFFE)]
    assert (second.line, second.wait_ms, second.command) == (5, 5, "SET")
    assert (expect.command, expect.items[0][1]) == ("EXPECT", 100)
    assert (wait.command, wait.wait_ms, wait.line) == ("WAITFOR", 1000, 7)


def test_pairs_without_type_column_and_symbols() -> None:
    symbols = SymbolTable()
    symbols.add(parse_address("X2.1"), Symbol("SW1"))
    scenario = parse_scenario("PMC SIGNAL DATA\nSET,0,SW1,1,X2.3,1\n", symbols=symbols)
    assert scenario.ok, scenario.error_texts()
    assert [(t.address, v) for t, v in scenario.steps[0].items] == [
        (parse_address("X2.1"), 1), (parse_address("X2.3"), 1)]


@pytest.mark.parametrize(("line", "code", "column"), [
    ("SET,-8,X2.1,1", "scenario-negative", 2),
    ("SET,abc,X2.1,1", "scenario-wait", 2),
    ("SET,0,NOSUCH,1", "scenario-address", 3),
    ("SET,0,X2.1,2", "scenario-value", 4),
    ("SET,0,X40,256", "scenario-value", 4),
    ("SET,0,X40,1,BYTE,X41", "scenario-fields", 3),
    ("SET,0,X40,1,QWORD,1", "scenario-address", 5),
    ("EXPECT,0,X40", "scenario-fields", 1),
    ("JUMP,0,X40,1", "scenario-command", 1),
])
def test_errors_at_their_line(line: str, code: str, column: int) -> None:
    scenario = parse_scenario(f"PMC SIGNAL DATA\nREMARK,x\n{line}\n", "s.csv")
    assert not scenario.ok
    assert [(d.code, d.line, d.column) for d in scenario.diagnostics] == [(code, 3, column)]
    assert scenario.error_texts()[0].startswith(f"s.csv:3:{column}: {code} ")


def test_header_is_required() -> None:
    scenario = parse_scenario("SET,0,X2.1,1\n")
    assert [d.code for d in scenario.diagnostics] == ["scenario-header"]


def test_waits_round_up_to_the_scan_period() -> None:
    assert [rounded(w, 8) for w in (0, 1, 8, 9, 960)] == [0, 8, 8, 16, 960]
    plc = loaded(TIMER)
    plc.set_timer_preset(1, 1000)  # 48 ms ticks: 960 ms
    result = run_scenario(plc, parse_scenario(
        "PMC SIGNAL DATA\nSET,1,R1.4,1\nEXPECT,945,R1.7,0\nEXPECT,1,R1.7,1\n"))
    assert [(c.time_ms, c.got) for c in result.checks] == [(960, 0), (968, 1)]
    assert result.passed


def test_failed_expect_message_and_waitfor() -> None:
    plc = loaded(TIMER)
    plc.set_timer_preset(1, 1000)
    result = run_scenario(plc, parse_scenario(
        "PMC SIGNAL DATA\nSET,0,R1.4,1\nWAITFOR,2000,R1.7,1\nEXPECT,0,R1.7,0\n"
        "SET,0,R1.4,0\nWAITFOR,100,R1.7,0\nWAITFOR,100,R1.7,1\n", "t.csv"))
    # the SET after a check at 960 ms acts at the next scan (968 ms); 100 ms round up to 104
    assert [(c.line, c.passed, c.time_ms) for c in result.checks] == [
        (3, True, 960), (4, False, 960), (6, True, 968), (7, False, 1072)]
    assert result.failures() == ["t.csv:4: expected R1.7=0, got 1 at 960 ms",
                                 "t.csv:7: expected R1.7=1, got 0 at 1072 ms"]
    assert not result.passed


def test_set_bytes_and_bits_on_the_spindle_override() -> None:
    plc = loaded(example="spindle_override.LAD")
    result = run_scenario(plc, parse_scenario(
        "PMC SIGNAL DATA\nSET,0,X2,0x2A\nEXPECT,0,G30,150\nSET,8,X2.5,0\nEXPECT,0,G30,60\n"))
    assert result.passed, result.failures()


def test_parse_errors_do_not_run() -> None:
    plc = loaded(TIMER)
    result = run_scenario(plc, parse_scenario("PMC SIGNAL DATA\nSET,-1,R1.4,1\n", "x"))
    assert not result.passed and result.checks == [] and result.virtual_ms == 0


def test_compiled_binary_loads() -> None:
    assert compile_program(parse(TIMER).program).binary is not None


def test_force_and_release_lines() -> None:
    plc = loaded("%@3\nRD X2.1\nWRT Y0.0\n%\n")
    result = run_scenario(plc, parse_scenario(
        "PMC SIGNAL DATA\nSET,0,X2.1,1\nFORCE,8,X2.1,0\nEXPECT,0,Y0.0,0\nRELEASE,8,X2.1\n"
        "EXPECT,0,Y0.0,1\n"))
    assert result.passed, result.failures()
    bad = parse_scenario("PMC SIGNAL DATA\nFORCE,0,X2,1\n")
    assert [d.code for d in bad.diagnostics] == ["scenario-bit"]


def test_recorder_writes_changes_and_forces_that_replay_the_same() -> None:
    from ladderworks.core.plc.recorder import ScenarioRecorder

    text = "%@3\nRD X2.1\nOR Y0.0\nAND.NOT X2.2\nWRT Y0.0\nRD X2.3\nWRT Y0.1\nMOVB X40 Y1\n%\n"
    plc = loaded(text)
    plc.start()
    recorder = ScenarioRecorder(plc, "recorded")
    recorder.start()
    plc.run_scans(3)
    plc.set_bit(parse_address("X2.1"), 1)
    plc.run_scans(2)
    plc.set_bit(parse_address("X2.1"), 0)
    plc.force(parse_address("X2.3"), 1)
    plc.write(parse_address("X40"), 0x5A)
    plc.run_scans(4)
    plc.release(parse_address("X2.3"))
    plc.run_scans(1)
    recorder.stop()
    written = recorder.text()
    assert written.splitlines() == [
        "PMC SIGNAL DATA", "REMARK,recorded", "SET,24,X2.1,1", "SET,16,X2.1,0",
        "FORCE,0,X2.3,1", "SET,0,X40,0x5A,BYTE", "RELEASE,32,X2.3",
        "EXPECT,0,Y0,1,BYTE", "EXPECT,0,Y1,90,BYTE"]
    again = loaded(text)
    result = run_scenario(again, parse_scenario(written))
    assert result.passed, result.failures()
    assert again.memory.areas == plc.memory.areas


def test_a_real_time_plc_is_refused() -> None:
    program = parse(TIMER).program
    plc = PlcRun(realtime=True)
    assert plc.load_program(program).binary is not None
    try:
        with pytest.raises(ValueError, match="virtual clock"):
            run_scenario(plc, parse_scenario("PMC SIGNAL DATA\nEXPECT,8,R1.7,0\n"))
    finally:
        plc.stop()


_FIELDS = st.one_of(
    st.sampled_from(["SET", "S", "EXPECT", "WAITFOR", "FORCE", "RELEASE", "REMARK", "R", "BYTE",
                     "WORD", "DWORD", "BIT", "X2.1", "R1.7", "D10", "T0", "Q9", "X2.9", "",
                     "0x", "0xFF", "-", "İŞ", "9" * 400]),
    st.integers(-10**6, 10**6).map(str),
    st.text(max_size=8),
)
_LINES = st.lists(st.lists(_FIELDS, max_size=8).map(",".join), max_size=12)


@settings(max_examples=examples(150))
@given(_LINES)
def test_any_text_reads_and_runs_without_a_crash(lines: list[str]) -> None:
    scenario = parse_scenario("\n".join(["PMC SIGNAL DATA", *lines]))
    for step in scenario.steps:
        assert step.wait_ms >= 0 and step.items
    capped = [Step(s.line, s.command, min(s.wait_ms, 80), s.items) for s in scenario.steps]
    scenario.steps = capped
    result = run_scenario(loaded(TIMER), scenario)
    assert result.passed in (True, False)


def test_program_line_names_the_program_relative_to_the_file(tmp_path: Path) -> None:
    scenario = parse_scenario("PMC SIGNAL DATA\nREMARK,x\nPROGRAM,../p/prog.LAD\n"
                              "EXPECT,0,Y0.0,0\n", str(tmp_path / "s" / "a.scenario.csv"))
    assert scenario.ok and (scenario.program, scenario.program_line) == ("../p/prog.LAD", 3)
    assert scenario.program_path() == tmp_path / "s" / ".." / "p" / "prog.LAD"
    absolute = parse_scenario(f"PMC SIGNAL DATA\nPROGRAM,{tmp_path / 'x.LAD'}\n", "b.csv")
    assert absolute.program_path() == tmp_path / "x.LAD"
    none = parse_scenario("\nPMC SIGNAL DATA\nEXPECT,0,Y0.0,0\n")
    assert none.program_path() is None and none.program_line == 2  # the header's line
    empty = parse_scenario("PMC SIGNAL DATA\nPROGRAM,\n")
    assert [(d.code, d.line) for d in empty.diagnostics] == [("scenario-fields", 2)]


def test_recorder_writes_the_program_line_relative_to_where_it_is_saved(
        tmp_path: Path) -> None:
    from ladderworks.core.plc.recorder import ScenarioRecorder, relative_program

    plc = loaded("%@3\nRD X2.1\nWRT Y0.0\n%\n")
    plc.start()
    recorder = ScenarioRecorder(plc, "r", tmp_path / "progs" / "m.LAD")
    recorder.start()
    plc.set_bit(parse_address("X2.1"), 1)
    plc.run_scans(2)
    recorder.stop()
    text = recorder.text()
    assert text.splitlines()[:2] == ["PMC SIGNAL DATA",
                                     f"PROGRAM,{(tmp_path / 'progs' / 'm.LAD').as_posix()}"]
    moved = relative_program(text, tmp_path / "tests" / "m.scenario.csv")
    assert moved.splitlines()[1] == "PROGRAM,../progs/m.LAD"
    assert moved.splitlines()[2:] == text.splitlines()[2:]
    read = parse_scenario(moved, str(tmp_path / "tests" / "m.scenario.csv"))
    assert read.program_path() is not None
    assert read.program_path().resolve() == tmp_path / "progs" / "m.LAD"
