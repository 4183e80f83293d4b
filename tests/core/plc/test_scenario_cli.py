"""ladderworks-cli test: scenarios headless, exit codes, messages and the JUnit XML report."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import xmlschema

from ladderworks.cli import main
from tests.core.plc.conftest import EXAMPLES

SCHEMA = Path(__file__).resolve().parents[2] / "data" / "junit-10.xsd"
PROGRAM = """%@2
X2.1 START_PB
X40 CODE_IN
%
%@3
RD X2.1
WRT Y0.0
RD R9091.1
MOVB X40 G30
%
"""


def cli(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def write(path: Path, text: str) -> str:
    path.write_text(text, encoding="utf-8")
    return str(path)


@pytest.fixture
def program(tmp_path: Path) -> str:
    return write(tmp_path / "prog.LAD", PROGRAM)


def test_symbols_bits_and_bytes_pass(program: str, tmp_path: Path,
                                     capsys: pytest.CaptureFixture[str]) -> None:
    scenario = write(tmp_path / "ok.csv", "PMC SIGNAL DATA\nREMARK,symbols\n"
                     "SET,0,START_PB,1,,CODE_IN,0x2A,BYTE\nEXPECT,0,Y0.0,1\nEXPECT,0,G30,42\n"
                     "SET,3,X2.1,0\nEXPECT,0,Y0.0,0\n")
    code, out, _ = cli(capsys, "test", program, scenario, "-v")
    assert code == 0, out
    assert f"{scenario}:7: Y0.0=0 at 8 ms" in out  # the 3 ms wait rounds up to one scan
    assert out.endswith("1 passed, 0 failed\n")


def test_failing_scenario_message_exit_code_and_junit(
        program: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    good = write(tmp_path / "good.csv", "PMC SIGNAL DATA\nSET,0,X40,7\nEXPECT,8,G30,7\n")
    bad = write(tmp_path / "bad.csv", "PMC SIGNAL DATA\nSET,0,X40,7\nEXPECT,17,G30,8\n")
    broken = write(tmp_path / "broken.csv", "PMC SIGNAL DATA\nSET,-8,X40,7\n")
    report = tmp_path / "junit.xml"
    code, out, _ = cli(capsys, "test", program, good, bad, broken, "--junit", str(report))
    assert code == 1
    assert f"{bad}:3: expected G30=8, got 7 at 24 ms\n" in out
    assert f"{broken}:2:2: scenario-negative negative wait -8 ms\n" in out
    assert out.endswith("1 passed, 2 failed\n")
    xmlschema.XMLSchema(str(SCHEMA)).validate(str(report))
    suite = ET.parse(report).getroot().find("testsuite")
    assert suite is not None
    assert (suite.get("tests"), suite.get("failures"), suite.get("errors")) == ("3", "1", "1")
    cases = {case.get("name"): case for case in suite.iter("testcase")}
    assert list(cases) == ["good.csv", "bad.csv", "broken.csv"]
    assert cases["good.csv"].find("failure") is None
    failure = cases["bad.csv"].find("failure")
    assert failure is not None
    assert failure.get("message") == f"{bad}:3: expected G30=8, got 7 at 24 ms"
    assert cases["broken.csv"].find("error") is not None


def test_program_parameters_are_applied(tmp_path: Path,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    program = write(tmp_path / "timer.LAD", "%@3\nRD R1.4\nTMR 1\nWRT R1.7\n%\n")
    write(tmp_path / "timer.LAD.prm", "T0:4 = 480\n")
    scenario = write(tmp_path / "t.csv", "PMC SIGNAL DATA\nSET,0,R1.4,1\n"
                     "EXPECT,472,R1.7,0\nEXPECT,8,R1.7,1\n")
    code, out, _ = cli(capsys, "test", program, scenario)
    assert code == 0, out


@pytest.mark.parametrize(("program", "scenario"), [
    ("spindle_override.LAD", "spindle_override.scenario.csv"),
    ("timer_relay.LAD", "timer_relay.scenario.csv"),
    ("all_functions.LAD", "all_functions.turret.scenario.csv"),
])
def test_example_scenarios_pass(program: str, scenario: str,
                                capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = cli(capsys, "test", str(EXAMPLES / program), str(EXAMPLES / scenario))
    assert code == 0, out


def test_every_example_scenario_names_its_program() -> None:
    scenarios = sorted(EXAMPLES.glob("*.scenario.csv"))
    assert len(scenarios) >= 3
    for path in scenarios:
        assert (EXAMPLES / (path.name.split(".")[0] + ".LAD")).exists(), path.name
