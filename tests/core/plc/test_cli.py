"""ladderworks-cli compile, disasm and run."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.cli import main
from tests.core.plc.conftest import EXAMPLES

TIMER = "%@3\nRD R1.4\nTMR 1\nWRT R1.7\n%\n"


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_compile_then_disasm_then_run_the_binary(tmp_path: Path,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "spindle.bin"
    assert run(capsys, "compile", str(EXAMPLES / "spindle_override.LAD"), "-o", str(out))[0] == 0
    code, text, _ = run(capsys, "disasm", str(out))
    assert code == 0
    assert text.startswith("%@3\nRD.NOT X2.1\nAND.NOT X2.3\n")
    code, text, _ = run(capsys, "run", str(out), "--set", "X2.1=1", "--set", "X2.5=1",
                        "--print", "G30", "--print", "R102")
    assert (code, text) == (0, "G30 = 100\nR102 = 32\n")


@pytest.mark.parametrize(("position", "percent"), [(0, 10), (3, 60), (6, 125), (7, 150)])
def test_run_text_directly(capsys: pytest.CaptureFixture[str], position: int,
                           percent: int) -> None:
    sets = [f"X2.{bit}={position >> k & 1}" for k, bit in enumerate((1, 3, 5))]
    argv = ["run", str(EXAMPLES / "spindle_override.LAD")]
    for item in sets:
        argv += ["--set", item]
    code, text, _ = run(capsys, *argv, "--print", "G30")
    assert (code, text) == (0, f"G30 = {percent}\n")


def test_run_with_timer_preset_timed_set_and_trace(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    source = tmp_path / "timer.LAD"
    source.write_text(TIMER)
    code, text, _ = run(capsys, "run", str(source), "--ms", "160", "--timer", "1=100",
                        "--set", "R1.4=1@16", "--trace", "R1.4,R1.7", "--period", "16",
                        "--print", "R1.7")
    assert code == 0
    lines = text.splitlines()
    assert lines[0] == "time_ms,R1.4,R1.7"
    assert lines[1:4] == ["0,0,0", "16,1,0", "32,1,0"]
    assert lines[7] == "96,1,0"
    assert lines[8] == "112,1,1"  # 16 ms + 96 ms (100 rounded down to 48 ms ticks)
    assert len(lines) == 1 + 10 + 1
    assert lines[-1] == "R1.7 = 1"


def test_run_wide_values_and_counter_preset(tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    source = tmp_path / "ctr.LAD"
    source.write_text("%@3\nRD R0.0\nRD.STK R0.1\nRD.STK R0.2\nRD.STK R0.3\nCTR 2\n"
                      "WRT R1.0\n%\n")
    code, text, _ = run(capsys, "run", str(source), "--scans", "4", "--counter", "2=1",
                        "--set", "R0.3=1@8", "--set", "D10:4=70000", "--set", "D20:2=0x1234",
                        "--set", "D30=007",
                        "--print", "C4:2,C6:2,R1.0,D10:4,D20:2,D20,D30")
    assert code == 0
    assert text.splitlines() == ["C4:2 = 1", "C6:2 = 1", "R1.0 = 1", "D10:4 = 70000",
                                 "D20:2 = 4660", "D20 = 52", "D30 = 7"]


def test_compile_reports_errors_with_positions(tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    source = tmp_path / "bad.LAD"
    source.write_text("%@3\nRD R0.0\nWRT X0.0\n%\n")
    code, _, err = run(capsys, "compile", str(source), "-o", str(tmp_path / "bad.bin"))
    assert code == 1
    assert err == f"{source}:3:1: write-input WRT writes to X0.0, an input area\n"
    assert not (tmp_path / "bad.bin").exists()


def test_disasm_of_a_foreign_file_is_a_clear_error(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    foreign = tmp_path / "x.bin"
    foreign.write_bytes(b"\x7fELF" + bytes(40))
    code, out, err = run(capsys, "disasm", str(foreign))
    assert (code, out) == (1, "")
    assert "bad-binary" in err and "magic" in err


@pytest.mark.parametrize("argv", [
    ["--set", "Q1=1"], ["--set", "X1.0"], ["--print", "D10:3"], ["--timer", "101=5"],
    ["--set", "X1.0:2=1"], ["--set", "D1=twelve"]])
def test_bad_options_are_reported(capsys: pytest.CaptureFixture[str], argv: list[str]) -> None:
    code, _, err = run(capsys, "run", str(EXAMPLES / "alarm.LAD"), *argv)
    assert code == 2
    assert err.startswith("ladderworks-cli: ")


def test_run_reads_the_parameter_file_beside_the_program(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    source = tmp_path / "timer.LAD"
    source.write_text(TIMER)
    argv = ["run", str(source), "--ms", "400", "--set", "R1.4=1", "--trace", "R1.7",
            "--period", "48"]

    def first_on() -> int:
        code, text, err = run(capsys, *argv)
        assert code == 0, err
        return next(int(line.split(",")[0]) for line in text.splitlines()[1:]
                    if line.endswith(",1"))

    assert first_on() == 0  # no parameter file: preset 0
    (tmp_path / "timer.LAD.prm").write_text("T0:4 = 200  # TMR 1\nT0:9 = 1\n")
    assert first_on() == 192  # 200 ms rounded down to 48 ms ticks
    _code, _, err = run(capsys, *argv)
    assert err == (f"{tmp_path / 'timer.LAD.prm'}:2:1: prm-value '1' is not a value for 9 "
                   "byte(s)\n")
    other = tmp_path / "other.prm"
    other.write_text("T0:4 = 100\n")
    argv += ["--params", str(other)]
    assert first_on() == 96
    argv += ["--timer", "1=300"]  # an option wins over the file
    assert first_on() == 288


def test_run_with_a_missing_named_parameter_file(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, "run", str(EXAMPLES / "alarm.LAD"), "--params",
                       str(tmp_path / "none.prm"))
    assert code == 2 and err.startswith("ladderworks-cli: ")


def test_run_with_level_2_divisions(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.core.compiler import compile
    from tests.core.plc.conftest import build

    out = tmp_path / "levels.bin"
    out.write_bytes(compile(build("RD.NOT R0.1\nWRT R0.1\nEND1\nRD.NOT R0.0\nWRT R0.0\nEND2")))
    code, text, _ = run(capsys, "run", str(out), "--scans", "4", "--divisions", "2",
                        "--trace", "R0.1,R0.0")
    assert code == 0
    assert text == "time_ms,R0.1,R0.0\n0,1,1\n8,0,1\n16,1,0\n24,0,0\n"
    assert run(capsys, "run", str(out), "--divisions", "0")[0] == 2


def test_an_endless_label_loop_stops_run_with_exit_1(tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.core.compiler import compile
    from tests.core.plc.conftest import build

    out = tmp_path / "loop.bin"
    out.write_bytes(compile(build("RD X0.0\nWRT Y0.0\nLBL L1\nRD R9091.1\nJMPB L1")))
    code, _, err = run(capsys, "run", str(out), "--scans", "3")
    assert code == 1
    assert "endless-loop" in err and ":3:" in err


@pytest.mark.parametrize("argv", [
    ["run", "--print", "G30", "--scans", "3", "--set", "X2.1=1", "--set", "X2.3=1", "{FILE}"],
    ["run", "{FILE}", "--print", "G30", "--scans", "3", "--set", "X2.1=1", "--set", "X2.3=1"],
    ["run", "--scans", "3", "{FILE}", "--set", "X2.1=1", "--set", "X2.3=1", "--print", "G30"],
])
def test_options_before_or_after_the_file(argv: list[str],
                                          capsys: pytest.CaptureFixture[str]) -> None:
    spindle = str(EXAMPLES / "spindle_override.LAD")
    code, text, err = run(capsys, *[spindle if a == "{FILE}" else a for a in argv])
    assert (code, text, err) == (0, "G30 = 60\n", "")


@pytest.mark.parametrize("command", ["compile", "check", "format", "ladder", "mnemonic"])
def test_every_command_takes_options_before_the_file(
        command: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    spindle = str(EXAMPLES / "spindle_override.LAD")
    options = ["-o", str(tmp_path / "out.bin")] if command == "compile" else []
    assert run(capsys, command, *options, spindle)[0] == 0
    assert run(capsys, command, spindle, *options)[0] == 0
