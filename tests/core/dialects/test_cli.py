"""The command line on Delta programs: check, run --set/--print, test, --dialect."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.cli import main
from tests.core.dialects.conftest import EXAMPLES


def _write(tmp_path: Path, text: str, name: str = "prog.txt") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_run_sets_and_prints_in_delta_spelling(tmp_path: Path, capsys) -> None:
    path = _write(tmp_path, "LD X0\nMOV K7 D0\nLD X0\nTMR T0 K10\nLD T0\nOUT Y0\nEND\n")
    assert main(["run", str(path), "--set", "X0=1", "--ms", "1200",
                 "--print", "Y0,D0,T0,X0"]) == 0
    assert capsys.readouterr().out.split("\n")[:4] == ["Y0 = 1", "D0 = 7", "T0 = 10", "X0 = 1"]


def test_run_refuses_a_device_that_does_not_exist(tmp_path: Path, capsys) -> None:
    path = _write(tmp_path, "LD X0\nOUT Y0\nEND\n")
    assert main(["run", str(path), "--print", "X8"]) == 2
    assert "octal" in capsys.readouterr().err


def test_check_reports_file_line_col(tmp_path: Path, capsys) -> None:
    path = _write(tmp_path, "LD X0\nOUT X1\nLD X8\nOUT Y0\nFOO Y1\nEND\n")
    assert main(["check", str(path)]) == 1
    lines = capsys.readouterr().out.splitlines()
    assert lines == [
        f"{path}:2:5: dialect-operand OUT: operand 1 must be one of Y, M, S, found 'X1'",
        f"{path}:3:4: device-octal 'X8': X is numbered in octal (digits 0 to 7)"]
    # FOO (line 5) is kept and drawn; its not-simulated warning comes with the checks, which
    # run on a program without errors


def test_check_runs_the_compiler_checks_in_delta_spelling(tmp_path: Path, capsys) -> None:
    path = _write(tmp_path, "LD X0\nOUT Y0\nLD X1\nOUT Y0\nLD X2\nCALL P5\nFEND\nEND\n")
    assert main(["check", str(path)]) == 1
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].startswith(f"{path}:4:1: coil-twice ") and "Y0" in lines[0]
    assert "Y0.0" not in lines[0]
    assert lines[1] == f"{path}:6:1: dvp-call-missing no subroutine P5 after FEND for this CALL"
    assert len(lines) == 2


def test_dialect_option_forces_the_reader(tmp_path: Path, capsys) -> None:
    path = _write(tmp_path, "LD X0\nOUT Y0\nEND\n")
    assert main(["check", str(path)]) == 0
    assert main(["check", "--dialect", "delta", str(path)]) == 0
    capsys.readouterr()
    assert main(["check", "--dialect", "pmc", str(path)]) == 1
    assert "missing-start" in capsys.readouterr().out


@pytest.mark.parametrize("program", sorted(EXAMPLES.glob("*.txt")), ids=lambda p: p.name)
def test_every_example_passes_its_scenario(program: Path, capsys) -> None:
    scenario = program.with_suffix(".scenario.csv")
    assert main(["test", str(program), str(scenario)]) == 0, capsys.readouterr()
    assert "1 passed, 0 failed" in capsys.readouterr().out


def test_the_example_scenarios_run_alone_on_the_program_they_name(capsys) -> None:
    """`ladderworks-cli test delta/*.scenario.csv fatek/*.scenario.csv`: each names its PROGRAM."""
    scenarios = sorted(EXAMPLES.glob("*.scenario.csv")) + sorted(
        EXAMPLES.parent.joinpath("fatek").glob("*.scenario.csv"))
    assert main(["test", *map(str, scenarios)]) == 0, capsys.readouterr()
    assert f"{len(scenarios)} passed, 0 failed" in capsys.readouterr().out


def test_ladder_art_in_delta_spelling(capsys) -> None:
    assert main(["ladder", str(EXAMPLES / "compare_contacts.txt")]) == 0
    out = capsys.readouterr().out
    assert "|    X0 " in out and "T0 K100" in out and "---|=|---" in out and "T0 K5" in out
    assert "LD< C1 C2" not in out and "---|<|---" in out and "C1 C2" in out  # now ladder
    assert "X0.0" not in out and "RD" not in out


def test_xref_in_delta_spelling(capsys) -> None:
    assert main(["xref", str(EXAMPLES / "motor_flip_flop.txt"), "D500", "Y0"]) == 0
    rows = capsys.readouterr().out.splitlines()[1:]
    assert [row.split()[0] for row in rows] == ["D500", "D500", "D500", "Y0"]
    assert [row.split()[6] for row in rows] == ["MOV", "MOV", "TMR", "OUT"]
    assert [row.split()[-1] for row in rows] == ["write", "write", "read", "write"]
    capsys.readouterr()
    assert main(["xref", str(EXAMPLES / "counter_reset.txt"), "C0"]) == 0
    rows = capsys.readouterr().out.splitlines()[1:]
    assert [(row.split()[6], row.split()[-1]) for row in rows] == [  # LD C0: its contact
        ("CNT", "read+write"), ("LD", "read"), ("RST", "write")]


def test_find_and_replace_take_delta_devices() -> None:
    from ladderworks.core.il import parse_file
    from ladderworks.core.ladder.convert import program_to_ladder
    from ladderworks.core.ladder.find_replace import find, parse_query, replacement_address

    program = parse_file(EXAMPLES / "motor_flip_flop.txt").program
    networks = program_to_ladder(program).networks
    query = parse_query("X0", program.symbols, "delta")
    assert query is not None
    assert len(find(networks, query, program.symbols)) == 3
    d500 = parse_query("D500", program.symbols, "delta")
    assert d500 is not None and len(find(networks, d500, program.symbols)) == 3
    new = replacement_address("M7", query, program.symbols, "delta")
    assert program.dialect == "delta" and new.bit == 7


def test_a_recorded_scenario_of_a_delta_program_replays() -> None:
    from ladderworks.core.plc.recorder import ScenarioRecorder
    from ladderworks.core.plc.scenario import parse_scenario, run_scenario
    from ladderworks.core.plc.session import PlcRun
    from tests.core.dialects.conftest import bit_of, delta

    program = delta("LD X0\nOR Y0\nANI X1\nOUT Y0\nLD X2\nOUT Y10\nEND\n")
    plc = PlcRun()
    assert not plc.load_program(program).diagnostics
    plc.start()
    recorder = ScenarioRecorder(plc, "recorded")
    recorder.start()
    plc.run_scans(2)
    plc.set_bit(bit_of("X0"), 1)
    plc.run_scans(2)
    plc.set_bit(bit_of("X0"), 0)
    plc.force(bit_of("X2"), 1)
    plc.run_scans(3)
    recorder.stop()
    written = recorder.text()
    assert written.splitlines()[2:] == ["SET,16,X0,1", "SET,16,X0,0", "FORCE,0,X2,1",
                                        "EXPECT,16,Y0,1,BIT", "EXPECT,0,Y10,1,BIT"]
    again = PlcRun()
    again.load_program(program)
    scenario = parse_scenario(written, "again", None, "delta")
    assert scenario.ok, scenario.diagnostics
    assert run_scenario(again, scenario).passed
