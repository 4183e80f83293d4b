"""The command line on Fatek programs: run --set/--print/--ascii-out, test, check, --dialect."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.cli import main
from tests.core.dialects.fatek.test_ascii_format import REPORT

EXAMPLES = Path(__file__).resolve().parents[4] / "resources" / "examples" / "fatek"


def test_run_sets_and_prints_in_fatek_spelling(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["run", str(EXAMPLES / "conveyor.lst"), "--set", "X0=1", "--ms", "3110",
                 "--print", "Y0,Y1,T50,R2", "--scan-period", "10"]) == 0
    assert capsys.readouterr().out.splitlines() == ["Y0 = 1", "Y1 = 1", "T50 = 31", "R2 = 100"]


def test_run_writes_the_report_to_the_ascii_out_file(tmp_path: Path) -> None:
    out = tmp_path / "terminal.txt"
    assert main(["run", str(EXAMPLES / "production_report.lst"), "--set", "X0=1@20",
                 "--ms", "100", "--ascii-out", str(out)]) == 0
    assert out.read_bytes() == REPORT.encode("utf-8")


def test_the_conveyor_scenario_passes(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["test", str(EXAMPLES / "conveyor.lst"),
                 str(EXAMPLES / "conveyor.scenario.csv")]) == 0
    assert "1 passed, 0 failed" in capsys.readouterr().out


def test_check_reports_file_line_col(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "bad.lst"
    path.write_text("Printed Item: Mnemonic - BAD\n     0  OUT      Y0\n     1  ORG      X0\n"
                    "     2  FUN 999  XYZ\n     3  ORG      X1\n     4  FUN 8    MOV\n"
                    "             S : 1\n", encoding="utf-8")
    assert main(["check", str(path)]) == 1
    out = capsys.readouterr().out.splitlines()
    assert [line.split(": ")[0] for line in out] == [
        f"{path}:2:9", f"{path}:4:9", f"{path}:6:9"]
    # an unknown FUN opens (a box run as nothing), with a warning at its line
    assert "fatek-output-on-rail" in out[0] and "fatek-not-simulated" in out[1]
    assert "fatek-missing-operand" in out[2]


def test_dialect_option_forces_fatek(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "plain.txt"
    path.write_text("LD X0\nOUT Y0\n", encoding="utf-8")  # Delta-looking, read as Fatek
    assert main(["run", str(path), "--dialect", "fatek", "--set", "X0=1", "--print", "Y0"]) == 0
    assert capsys.readouterr().out.splitlines() == ["Y0 = 1"]
