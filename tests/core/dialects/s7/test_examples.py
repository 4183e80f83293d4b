"""The S7 example programs (seeds 001 and 003 in SIMATIC SD) pass their scenarios, with the
engine skipping scans and running every scan alike; the CLI takes their tag names."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.cli import main
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.reading import parse_file

EXAMPLES = Path(__file__).resolve().parents[4] / "resources" / "examples" / "s7"
NAMES = ("timers", "counters", "compare", "jumps", "jump_list", "switch", "calls")


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("every", [False, True])
def test_the_example_passes_its_scenario(name: str, every: bool,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    folder = EXAMPLES / name
    args = ["test", *(["--every-scan"] if every else []), str(folder / "Main.s7dcl"),
            str(folder / "Main.scenario.csv")]
    assert main(args) == 0, capsys.readouterr().out
    assert "1 passed, 0 failed" in capsys.readouterr().out


@pytest.mark.parametrize("name", NAMES)
def test_the_example_reads_without_diagnostics_and_saves_byte_for_byte(name: str) -> None:
    path = EXAMPLES / name / "Main.s7dcl"
    result = parse_file(path)
    assert result.diagnostics == []
    assert result.program.dialect == "s7"
    assert encode_program(result.program) == path.read_bytes()


def test_run_sets_and_prints_by_tag_name(capsys: pytest.CaptureFixture[str]) -> None:
    path = EXAMPLES / "timers" / "Main.s7dcl"
    assert main(["run", str(path), "--set", "Start=1", "--ms", "5010", "--scan-period", "10",
                 "--print", "Lamba 1,Lamba 2,%MD0:4,Geçen Süre:4"]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "Lamba 1 = 0", "Lamba 2 = 1", "%MD0:4 = 5000", "Geçen Süre:4 = 5000"]


def test_check_of_a_folder_opens_it_as_one_program(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", str(EXAMPLES / "counters")]) == 0


def test_network_titles_come_from_the_s7res_texts() -> None:
    program = parse_file(EXAMPLES / "jumps" / "Main.s7dcl").program
    titles = [net.comments[0] for net in program.networks if net.comments]
    assert titles[:2] == ["Jump condition: skip network 2",
                          "Skipped when jumping (keeps its output)"]


def test_first_scan_always_true_and_the_clock_memory(tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "Main.s7dcl"
    path.write_text('ORGANIZATION_BLOCK "Main"\n NETWORK\n  RUNG wire#powerrail\n'
                    '   Contact( %M1.0 )\n   Move( in := 7, out1 => %MW10 )\n  END_RUNG\n'
                    ' END_NETWORK\n NETWORK\n  RUNG wire#powerrail\n   Contact( %M1.2 )\n'
                    '   I_Contact( %M1.3 )\n   Inc( %MW12 )\n  END_RUNG\n END_NETWORK\n'
                    ' NETWORK\n  RUNG wire#powerrail\n   Contact( %M0.5 )\n   Coil( %Q0.0 )\n'
                    '  END_RUNG\n END_NETWORK\nEND_ORGANIZATION_BLOCK\n', encoding="utf-8")
    assert main(["run", str(path), "--ms", "490", "--scan-period", "10", "--every-scan",
                 "--set", "%MW10:2=0@20", "--print", "%MW10:2,%MW12:2,%Q0.0"]) == 0
    # FirstScan only in the first scan (MW10 cleared at 20 stays 0); AlwaysTRUE counts 49
    # scans; %M0.5 (1 Hz) is on for the first half second
    assert capsys.readouterr().out.splitlines() == ["%MW10:2 = 0", "%MW12:2 = 49", "%Q0.0 = 1"]


def test_an_fc_is_tested_alone_with_its_interface(capsys: pytest.CaptureFixture[str]) -> None:
    folder = EXAMPLES / "calls"
    assert main(["test", str(folder / "Kilit.s7dcl"), str(folder / "Kilit.scenario.csv")]) == 0
    assert "1 passed, 0 failed" in capsys.readouterr().out


def test_a_call_of_a_block_that_is_not_there(tmp_path: Path) -> None:
    path = tmp_path / "Main.s7dcl"
    path.write_text('ORGANIZATION_BLOCK "Main"\n NETWORK\n  RUNG wire#powerrail\n'
                    '   "Nowhere_DB"( a := 1 )\n  END_RUNG\n END_NETWORK\n'
                    'END_ORGANIZATION_BLOCK\n', encoding="utf-8")
    result = parse_file(path)
    assert [(d.code, d.line, d.args["block"]) for d in result.diagnostics] == [
        ("s7-call-unknown", 4, "Nowhere_DB")]


pytest_plugins = ["pytester"]


def test_the_pytest_plugin_runs_an_fc_alone(pytester: pytest.Pytester) -> None:
    """A technician's unit test of one block: the scenario names the FC (PROGRAM line)."""
    for path in (EXAMPLES / "calls").iterdir():
        if path.name.startswith("Kilit") or path.suffix in (".s7res", ".xml"):
            (pytester.path / path.name).write_bytes(path.read_bytes())
    result = pytester.runpytest_inprocess("-p", "ladderworks.pytest_plugin", "-q")
    result.assert_outcomes(passed=1)
