"""pytest plugin: each `*.scenario.csv` is one test, run as `ladderworks-cli test` runs it.

Registered as the `pytest11` entry point `ladderworks.pytest_plugin` (pyproject.toml), so an
installed LadderWorks makes `pytest` collect the scenario files under its test paths; the
scenario names its program on a `PROGRAM,path` line (docs/scenarios.md). The ini option
`ladderworks_scenarios = false` (or `-p no:ladderworks.pytest_plugin`) turns collection off.
Each item runs in the process that collected it, so `pytest -n auto` (pytest-xdist) spreads
the scenarios over its workers. No Qt is imported.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from ladderworks.core.plc.scenario import ScenarioResult
from ladderworks.core.plc.scenario_batch import ScenarioJob, run_job

SUFFIX = ".scenario.csv"


def pytest_addoption(parser: pytest.Parser) -> None:
    """The ini switch and the scan period."""
    parser.addini("ladderworks_scenarios", "collect *.scenario.csv files as LadderWorks "
                  "scenario tests (default: true)", type="bool", default=True)
    parser.addini("ladderworks_scan_period", "scan period in ms of the scenario tests "
                  "(default: 8)", default="8")
    parser.addini("ladderworks_every_scan", "run every scan of the scenario tests (default: "
                  "false: the scans of a state that repeats are skipped, with the same results)",
                  type="bool", default=False)
    parser.addini("ladderworks_backend", "the scan's code: python (default) or native "
                  "(llvmlite; Python runs where it cannot)", default="python")


def pytest_collect_file(file_path: Path, parent: pytest.Collector) -> pytest.Collector | None:
    """A scenario file is a collector of one item."""
    if file_path.name.endswith(SUFFIX) and parent.config.getini("ladderworks_scenarios"):
        file: ScenarioFile = ScenarioFile.from_parent(parent, path=file_path)
        return file
    return None


class ScenarioFailed(Exception):
    """A scenario whose file, program or checks failed: the messages to show."""

    def __init__(self, texts: list[str]) -> None:
        super().__init__("\n".join(texts))
        self.texts = texts


class ScenarioFile(pytest.File):
    """A `*.scenario.csv` file."""

    def collect(self) -> Iterator[pytest.Item]:
        """Its one item, named for the file without `.scenario.csv`."""
        yield ScenarioItem.from_parent(self, name=self.path.name[:-len(SUFFIX)])


class ScenarioItem(pytest.Item):
    """One scenario played on a cold start of its program."""

    result: ScenarioResult | None = None

    def runtest(self) -> None:
        """Run it; raise ScenarioFailed with the failures' messages."""
        period = int(self.config.getini("ladderworks_scan_period"))
        backend = str(self.config.getini("ladderworks_backend")).strip() or "python"
        outcome = run_job(ScenarioJob(str(self.path), period_ms=period,
                                      every_scan=self.config.getini("ladderworks_every_scan"),
                                      backend=backend))
        result = self.result = outcome.result
        result.scenario.name = self._shown_name()
        if outcome.messages:
            self.add_report_section("call", "program", "\n".join(outcome.messages))
        if backend == "native" and outcome.backend_reason:
            self.add_report_section("call", "backend",
                                    f"the Python scan ran: {outcome.backend_reason}")
        name = result.scenario.name
        checks = "\n".join(check.message(name) for check in result.checks)
        if checks:
            self.add_report_section("call", "checks", checks)
        if not result.passed:
            raise ScenarioFailed(result.failures())

    def _shown_name(self) -> str:
        """The file as the user named its folder: relative to where pytest was started."""
        start = self.config.invocation_params.dir
        try:
            return str(self.path.relative_to(start))
        except ValueError:
            return str(self.path)

    def repr_failure(self, excinfo: pytest.ExceptionInfo[BaseException],
                     style: str | None = None) -> str:
        """`SCENARIO:LINE: expected ADDR=V, got W at T ms`, one line per failure."""
        if isinstance(excinfo.value, ScenarioFailed):
            return "\n".join(excinfo.value.texts)
        return str(super().repr_failure(excinfo, style))  # type: ignore[arg-type]

    def reportinfo(self) -> tuple[Path, int | None, str]:
        """The file, and the scenario's name."""
        return self.path, None, f"scenario {self.name}"
