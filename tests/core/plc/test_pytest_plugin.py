"""The pytest plugin: every *.scenario.csv is one test, in process and under pytest-xdist."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import ladderworks
import ladderworks.core.plc.scenario_batch
from tests.core.plc.conftest import EXAMPLES

pytest_plugins = ["pytester"]

ROOT = Path(ladderworks.__file__).resolve().parents[1]
PLUGIN = ("-p", "ladderworks.pytest_plugin")
LATCH = "%@2\nX2.1 START_PB\n%\n%@3\nRD X2.1\nWRT Y0.0\n%\n"
GOOD = "PMC SIGNAL DATA\nPROGRAM,../programs/latch.LAD\nSET,0,START_PB,1\nEXPECT,0,Y0.0,1\n"
BAD = "PMC SIGNAL DATA\nPROGRAM,../programs/latch.LAD\nSET,0,X2.1,1\nEXPECT,8,Y0.0,0\n"


@pytest.fixture
def suite(pytester: pytest.Pytester) -> pytest.Pytester:
    """A machine builder's tests: a program, a passing and a failing scenario, a Python test."""
    (pytester.path / "programs").mkdir()
    (pytester.path / "programs" / "latch.LAD").write_text(LATCH, encoding="utf-8")
    (pytester.path / "tests").mkdir()
    (pytester.path / "tests" / "start.scenario.csv").write_text(GOOD, encoding="utf-8")
    (pytester.path / "tests" / "stop.scenario.csv").write_text(BAD, encoding="utf-8")
    (pytester.path / "tests" / "notes.csv").write_text(BAD, encoding="utf-8")  # not a scenario
    (pytester.path / "tests" / "test_other.py").write_text("def test_x():\n    pass\n")
    return pytester


def test_each_scenario_file_is_one_item_and_a_failure_names_line_and_values(
        suite: pytest.Pytester) -> None:
    result = suite.runpytest(*PLUGIN, "-v")
    result.assert_outcomes(passed=2, failed=1)
    result.stdout.fnmatch_lines([
        "tests/start.scenario.csv::start PASSED*",
        "tests/stop.scenario.csv::stop FAILED*",
    ])
    result.stdout.fnmatch_lines(["tests/stop.scenario.csv:4: expected Y0.0=0, got 1 at 8 ms"])
    assert "Traceback" not in result.stdout.str()


def test_pytest_xdist_spreads_the_scenarios_over_workers(
        suite: pytest.Pytester, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PYTHONPATH", str(ROOT))  # this checkout's ladderworks in the workers
    result = suite.runpytest_subprocess(*PLUGIN, "-n", "2", "-v")
    result.assert_outcomes(passed=2, failed=1)
    result.stdout.fnmatch_lines(["*2 workers*"])
    result.stdout.fnmatch_lines(["tests/stop.scenario.csv:4: expected Y0.0=0, got 1 at 8 ms"])


def test_no_program_is_a_failure_at_the_header_and_collection_can_be_turned_off(
        pytester: pytest.Pytester) -> None:
    pytester.path.joinpath("x.scenario.csv").write_text("PMC SIGNAL DATA\nEXPECT,0,Y0.0,0\n")
    result = pytester.runpytest(*PLUGIN)
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["x.scenario.csv:1:1: scenario-no-program *"])
    pytester.makeini("[pytest]\nladderworks_scenarios = false\n")
    pytester.runpytest(*PLUGIN).assert_outcomes()


def test_the_example_scenarios_pass_as_plugin_items(pytester: pytest.Pytester) -> None:
    for path in EXAMPLES.iterdir():
        if path.suffix in (".LAD", ".csv", ".prm"):
            shutil.copy(path, pytester.path / path.name)
    result = pytester.runpytest(*PLUGIN)
    result.assert_outcomes(passed=len(list(EXAMPLES.glob("*.scenario.csv"))))


def test_the_delta_and_fatek_example_scenarios_name_their_program(
        pytester: pytest.Pytester) -> None:
    """Each dialect example's scenario has its PROGRAM line: the plugin runs them as they are."""
    for family in ("delta", "fatek"):
        shutil.copytree(EXAMPLES / family, pytester.path / family)
    result = pytester.runpytest(*PLUGIN)
    result.assert_outcomes(passed=len(list(EXAMPLES.glob("*/*.scenario.csv"))))


def test_the_project_suite_collects_no_scenario_file() -> None:
    """The plugin is on wherever LadderWorks is installed: the project's own test path holds
    no *.scenario.csv (tests write theirs under tmp_path), so nothing is collected twice or
    by surprise; the examples are run by the two tests above and by the CLI tests."""
    tests = Path(__file__).resolve().parents[2]
    assert not list(tests.rglob("*.scenario.csv"))


def test_the_plugin_imports_no_qt() -> None:
    code = ("import sys, ladderworks.pytest_plugin; "
            "sys.exit(any(m.split('.')[0] in ('PySide6', 'shiboken6', 'pyqtgraph') "
            "for m in sys.modules))")
    assert subprocess.run([sys.executable, "-c", code], cwd=ROOT, check=False).returncode == 0
