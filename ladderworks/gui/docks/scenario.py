"""PLC › Run scenario and PLC › Record scenario: check results at their lines, recording."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QCoreApplication, Qt, Signal
from PySide6.QtGui import QAction, QBrush, QColor
from PySide6.QtWidgets import (
    QDockWidget,
    QLabel,
    QToolBar,
    QTreeWidget,
    QTreeWidgetItem,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.plc.recorder import ScenarioRecorder, relative_program
from ladderworks.core.plc.scenario import (
    CheckResult,
    Scenario,
    ScenarioResult,
    parse_scenario,
    read_scenario,
    run_scenario,
)
from ladderworks.core.plc.session import PlcRun
from ladderworks.gui import file_dialogs
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.docks.time_chart import TimeChartDock
from ladderworks.gui.docks.trace_record import TracedSignal, TraceRecord, traced
from ladderworks.gui.error_list import location_text
from ladderworks.gui.files import atomic_write
from ladderworks.gui.header_fit import fit_headers
from ladderworks.gui.live_text import set_live_text
from ladderworks.gui.os_errors import os_error_text
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.retranslate import Retranslating

translate = QCoreApplication.translate
RUN = "action_plc_run_scenario"
RECORD = "action_plc_record_scenario"
_PASS, _FAIL, _WARN = QColor("#1a7f37"), QColor("#c00000"), QColor("#b35c00")


class ScenarioDock(Retranslating, QDockWidget):
    """Runs a scenario on a cold-started copy of the loaded program; records one from the PLC."""

    finished = Signal(object)  # the ScenarioResult

    def __init__(self, session: PlcSession, parent: QWidget | None = None,
                 chart: TimeChartDock | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("scenarioDock")
        self.session = session
        self.chart = chart
        self.result: ScenarioResult | None = None
        self.recorder: ScenarioRecorder | None = None
        self.program_path: Path | None = None  # the file of the program loaded in the PLC
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        self.toolbar = QToolBar(body)
        self.toolbar.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextOnly)
        self.actions_by_name: dict[str, QAction] = {}
        for name, slot in ((RUN, self.run_dialog), (RECORD, self.toggle_recording)):
            action = QAction(self)
            action.setObjectName(name)
            action.triggered.connect(lambda _c=False, s=slot: s())
            self.toolbar.addAction(action)
            self.actions_by_name[name] = action
        self.actions_by_name[RECORD].setCheckable(True)
        layout.addWidget(self.toolbar)
        self.message = QLabel(body)
        self.message.setObjectName("scenarioMessage")
        self.message.setWordWrap(True)
        layout.addWidget(self.message)
        self.checks = QTreeWidget(body)
        self.checks.setObjectName("scenarioChecks")
        self.checks.setRootIsDecorated(False)
        self.checks.itemActivated.connect(self._jump)
        layout.addWidget(self.checks, 1)
        self.setWidget(body)
        self.retranslate()

    # -- running -----------------------------------------------------------------------------

    def run_dialog(self) -> None:
        """Ask for a scenario file and run it."""
        path = file_dialogs.open_file_name(
            self, translate("Scenario", "Run scenario"), "",
            translate("Scenario", "Scenario files (*.csv);;All files (*)"))
        if path:
            self.run_file(path)

    def run_file(self, path: str | Path) -> ScenarioResult | None:
        """Read and run a scenario file."""
        program = self.session.run.program
        try:
            scenario = read_scenario(path, program.symbols if program is not None else None,
                                     self.session.run.program_dialect)
        except OSError as error:
            reason = error  # the except clause's name is gone after it
            self._say(lambda: translate("Scenario", "Cannot read {0}: {1}").format(
                      path, os_error_text(reason)), error=True)
            return None
        return self.run(scenario)

    def run_text(self, text: str, name: str = "scenario") -> ScenarioResult | None:
        """Run scenario text (tests, the recorder's output)."""
        program = self.session.run.program
        return self.run(parse_scenario(text, name,
                                       program.symbols if program is not None else None,
                                       self.session.run.program_dialect))

    def run(self, scenario: Scenario) -> ScenarioResult | None:
        """Run on a cold start of the loaded program with its PMC parameters; the live PLC is
        not touched. Every address of the scenario is traced into the time chart."""
        binary = self.session.run.binary
        if binary is None:
            self._say(lambda: translate("Scenario", "Load (compile) a PLC program first"),
                      error=True)
            return None
        plc = PlcRun(period_ms=self.session.run.period_ms)
        plc.set_parameters(self.session.run.parameters)
        if plc.load(binary, self.session.run.program) or plc.engine is None:
            return None
        self._check_program(scenario)
        signals = _signals(scenario, self.session.run.program_dialect)
        trace = (plc.engine.start_trace([s.address for s in signals], plc.engine.period_ms,
                                        widths=[s.width for s in signals]) if signals else None)
        result = run_scenario(plc, scenario)
        self.result = result
        self._fill(result)
        if trace is not None and self.chart is not None:
            record = TraceRecord(signals)
            record.period_ms = plc.engine.period_ms
            record.extend(trace.take())
            self.chart.show_record(record)
            failing = self.failing_times()
            if failing:  # the first failure at once
                self.chart.set_cursor(failing[0])
        self.finished.emit(result)
        return result

    def _check_program(self, scenario: Scenario) -> None:
        """A warning at the PROGRAM line when it names another file than the PLC's program."""
        named = scenario.program_path()
        if named is None or self.program_path is None:
            return
        try:
            same = named.resolve() == self.program_path.resolve()
        except OSError:
            same = False
        if not same:
            scenario.diagnostics.append(Diagnostic(
                "scenario-other-program", {"path": scenario.program}, scenario.program_line,
                2, Severity.WARNING))

    def _fill(self, result: ScenarioResult) -> None:
        self._fill_checks(result)
        failed = sum(not c.passed for c in result.checks)
        errors = sum(d.is_error for d in result.scenario.diagnostics)
        if result.passed:
            self._say(lambda: translate("Scenario", "{0}: all {1} checks passed").format(
                Path(result.scenario.name).name, len(result.checks)))
        else:
            self._say(lambda: translate("Scenario", "{0}: {1} of {2} checks failed").format(
                Path(result.scenario.name).name, failed + errors,
                len(result.checks) + errors), error=True)

    def _fill_checks(self, result: ScenarioResult) -> None:
        """The checks' rows (made again in the new language after a live switch)."""
        self.checks.clear()
        for diagnostic in result.scenario.diagnostics:  # in the UI language, no codes
            text = f"{location_text(diagnostic)}: {diagnostic_text(diagnostic)}"
            colour = _FAIL if diagnostic.is_error else _WARN
            self._item([text], colour, None).setFirstColumnSpanned(True)  # not a wide Line
        for check in result.checks:
            state = (translate("Scenario", "passed") if check.passed
                     else translate("Scenario", "FAILED"))
            op, expected, got = check.shown or ("", str(check.expected), str(check.got))
            self._item([str(check.line), f"{check.command} {check.target}",
                        f"{'' if op == '=' else op}{expected}", got, str(check.time_ms), state],
                       _PASS if check.passed else _FAIL, check)
        for column in range(self.checks.columnCount() - 1):  # passed / FAILED in view
            self.checks.resizeColumnToContents(column)

    def _item(self, texts: list[str], colour: QColor,
              check: CheckResult | None) -> QTreeWidgetItem:
        item = QTreeWidgetItem(texts)
        item.setForeground(len(texts) - 1, QBrush(colour))
        item.setData(0, Qt.ItemDataRole.UserRole, check)
        self.checks.addTopLevelItem(item)
        return item

    def failing_times(self) -> list[int]:
        """The times (ms) of the failed checks."""
        return [c.time_ms for c in self.result.checks if not c.passed] if self.result else []

    def _jump(self, item: QTreeWidgetItem, _column: int = 0) -> None:
        check = item.data(0, Qt.ItemDataRole.UserRole)
        if isinstance(check, CheckResult) and self.chart is not None:
            self.chart.show()
            self.chart.raise_()
            self.chart.set_cursor(check.time_ms)

    # -- recording ---------------------------------------------------------------------------

    def toggle_recording(self) -> None:
        """Start recording, or stop and ask where to save the scenario."""
        if self.recorder is None:
            self.start_recording()
            return
        text = self.stop_recording()
        path = file_dialogs.save_file_name(
            self, translate("Scenario", "Save the recorded scenario"), "scenario.csv",
            translate("Scenario", "Scenario files (*.csv);;All files (*)"))
        if path:
            self.save(path, text)

    def start_recording(self) -> None:
        """Record the inputs set and the bits forced on the PLC from now on (the file names
        the PLC's program on its PROGRAM line when it has a file)."""
        self.recorder = ScenarioRecorder(self.session.run,
                                         translate("Scenario", "recorded in LadderWorks"),
                                         self.program_path)
        self.recorder.start()
        self.actions_by_name[RECORD].setChecked(True)
        self._say(lambda: translate("Scenario", "Recording inputs and forces..."))

    def stop_recording(self) -> str:
        """Stop recording; the scenario text (empty when not recording)."""
        recorder, self.recorder = self.recorder, None
        self.actions_by_name[RECORD].setChecked(False)
        if recorder is None:
            return ""
        recorder.stop()
        count = len(recorder.events)
        self._say(lambda: translate("Scenario", "Recorded {0} changes").format(count))
        return recorder.text()

    def save(self, path: str | Path, text: str) -> bool:
        """Write a scenario file (its PROGRAM path relative to the file's folder)."""
        try:
            atomic_write(path, relative_program(text, path))
        except OSError as error:
            reason = error  # the except clause's name is gone after it
            self._say(lambda: translate("Scenario", "Cannot write {0}: {1}").format(
                      path, os_error_text(reason)), error=True)
            return False
        self._say(lambda: translate("Scenario", "Saved {0}").format(path))
        return True

    # -- texts -------------------------------------------------------------------------------

    def _say(self, text: Callable[[], str], *, error: bool = False) -> None:
        """Show a message, made again in the new language after a live switch."""
        self.message.setStyleSheet("color:#c00000;" if error else "")
        set_live_text(self.message, text)

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(translate("Scenario", "PLC scenario"))
        self.actions_by_name[RUN].setText(translate("Scenario", "Run scenario..."))
        self.actions_by_name[RECORD].setText(translate("Scenario", "Record scenario"))
        self.checks.setHeaderLabels([
            translate("Scenario", "Line"), translate("Scenario", "Check"),
            translate("Scenario", "Expected"), translate("Scenario", "Got"),
            translate("Scenario", "Time (ms)"), translate("Scenario", "Result")])
        if self.result is not None:  # "passed" / "geçti" in the rows too
            self._fill_checks(self.result)
        fit_headers(self.checks)



def _signals(scenario: Scenario, dialect: str | None) -> list[TracedSignal]:
    """Every address the scenario sets or checks, once, in order of appearance."""
    seen: dict[tuple[object, int], TracedSignal] = {}
    for step in scenario.steps:
        for target, _value in step.items:
            key = (target.address, target.width)
            seen.setdefault(key, traced(target.address, target.width, dialect))
    return list(seen.values())
