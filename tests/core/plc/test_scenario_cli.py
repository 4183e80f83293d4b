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
        program = path.name.split(".")[0] + ".LAD"
        assert (EXAMPLES / program).exists(), path.name
        assert path.read_text(encoding="utf-8").splitlines()[1] == f"PROGRAM,{program}"


def test_example_scenarios_run_on_their_program_lines_in_processes(
        capsys: pytest.CaptureFixture[str]) -> None:
    names = [str(EXAMPLES / s) for s in ("timer_relay.scenario.csv",
                                         "all_functions.turret.scenario.csv",
                                         "spindle_override.scenario.csv")]
    code, out, _ = cli(capsys, "test", *names, "-j", "2")
    assert code == 0, out
    assert [line.split(":")[0] for line in out.splitlines()[:3]] == names


OTHER = "%@3\nRD X2.1\nWRT.NOT Y0.0\n%\n"


def test_program_lines_relative_absolute_and_two_programs_in_one_call(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "progs").mkdir()
    (tmp_path / "tests").mkdir()
    write(tmp_path / "progs" / "prog.LAD", PROGRAM)
    other = write(tmp_path / "progs" / "other.LAD", OTHER)
    relative = write(tmp_path / "tests" / "a.scenario.csv",
                     "PMC SIGNAL DATA\nPROGRAM,../progs/prog.LAD\nSET,0,START_PB,1\n"
                     "EXPECT,0,Y0.0,1\n")  # a symbol of the program named
    absolute = write(tmp_path / "tests" / "b.scenario.csv",
                     f"PMC SIGNAL DATA\nPROGRAM,{other}\nSET,0,X2.1,1\nEXPECT,0,Y0.0,0\n")
    report = tmp_path / "junit.xml"
    code, out, _ = cli(capsys, "test", relative, absolute, "-j", "1", "--junit", str(report))
    assert code == 0, out
    suites = [s.get("name") for s in ET.parse(report).getroot().iter("testsuite")]
    assert suites == ["prog.LAD", "other.LAD"]
    # a PROGRAM argument wins over the PROGRAM line: other.LAD inverts Y0.0
    code, out, _ = cli(capsys, "test", other, relative)
    assert code == 1
    assert f"{relative}:3:3: scenario-address" in out  # START_PB is no symbol of other.LAD


def test_scenario_without_program_and_unloadable_program_are_errors_at_their_line(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    none = write(tmp_path / "none.csv", "\nPMC SIGNAL DATA\nEXPECT,0,Y0.0,0\n")
    missing = write(tmp_path / "missing.csv",
                    "PMC SIGNAL DATA\nREMARK,x\nPROGRAM,nowhere.LAD\nEXPECT,0,Y0.0,0\n")
    broken = write(tmp_path / "broken.csv", "PMC SIGNAL DATA\nPROGRAM,bad.LAD\n")
    write(tmp_path / "bad.LAD", "%@3\nRD X2.1\nFOO Y0.0\n%\n")
    twice = write(tmp_path / "twice.csv",
                  "PMC SIGNAL DATA\nPROGRAM,bad.LAD\nPROGRAM,bad.LAD\n")
    good = write(tmp_path / "good.csv", "PMC SIGNAL DATA\nPROGRAM,p.LAD\nEXPECT,0,Y0.0,0\n")
    write(tmp_path / "p.LAD", PROGRAM)
    code, out, err = cli(capsys, "test", none, missing, broken, twice, good, "-j", "1")
    assert code == 1
    assert f"{none}:2:1: scenario-no-program the scenario names no program" in out
    assert (f"{missing}:3:2: scenario-program the program '{tmp_path / 'nowhere.LAD'}' "
            "cannot be loaded: ") in out
    assert (f"{broken}:2:2: scenario-program the program '{tmp_path / 'bad.LAD'}' cannot be "
            "loaded: it does not parse") in out
    assert f"{twice}:3:1: scenario-program-twice" in out
    assert err.count(f"{tmp_path / 'bad.LAD'}:3:") == 1  # the program's own errors, once
    assert out.endswith("1 passed, 4 failed\n")


def test_parallel_results_keep_the_order_given_and_a_failure_stops_nothing(
        program: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    long = "PMC SIGNAL DATA\nSET,0,X40,7\nEXPECT,20000,G30,7\n"  # the slowest runs first
    names = [write(tmp_path / "slow.csv", long),
             write(tmp_path / "fail.csv", "PMC SIGNAL DATA\nSET,0,X40,7\nEXPECT,8,G30,9\n"),
             write(tmp_path / "ok1.csv", "PMC SIGNAL DATA\nSET,0,X40,3\nEXPECT,8,G30,3\n"),
             write(tmp_path / "ok2.csv", "PMC SIGNAL DATA\nSET,0,X2.1,1\nEXPECT,8,Y0.0,1\n")]
    report = tmp_path / "junit.xml"
    code, out, _ = cli(capsys, "test", program, *names, "-j", "2", "--junit", str(report))
    assert code == 1
    summaries = [line.split(":")[0] for line in out.splitlines() if " passed (" in line
                 or " FAILED (" in line]
    assert summaries == names
    assert f"{names[1]}:3: expected G30=9, got 7 at 8 ms" in out
    assert out.endswith("3 passed, 1 failed\n")
    xmlschema.XMLSchema(str(SCHEMA)).validate(str(report))
    cases = [c.get("name") for c in ET.parse(report).getroot().iter("testcase")]
    assert cases == ["slow.csv", "fail.csv", "ok1.csv", "ok2.csv"]


def test_program_alone_or_bad_jobs_are_usage_errors(
        program: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert cli(capsys, "test", program)[0] == 2
    assert cli(capsys, "test", program, program, "-j", "0")[0] == 2
