"""The time chart's trace files: export and import FANUC LADDER-III signal-trace results."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Protocol

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QSpinBox

from ladderworks.core.address import AddressError
from ladderworks.core.plc.trace import TraceSample
from ladderworks.core.plc.trace_file import TraceFileError, TraceTable, ladder3_text, read_trace
from ladderworks.gui import file_dialogs
from ladderworks.gui.button_flow import ButtonFlow
from ladderworks.gui.docks.trace_record import TracedSignal, TraceRecord, parse_traced
from ladderworks.gui.files import atomic_write
from ladderworks.gui.os_errors import os_error_text

translate = QCoreApplication.translate
EXPORT = "action_time_chart_ladder3"
IMPORT = "action_time_chart_import"


class TimeChartDock(Protocol):
    """What the trace files use of the time chart (`time_chart.TimeChartDock`)."""

    record: TraceRecord
    sampling: bool
    period_spin: QSpinBox
    toolbar: ButtonFlow  # the actions' place, and the dialogs' parent
    chart_actions: dict[str, QAction]

    def stop(self) -> None:
        """Stop sampling."""

    def say(self, text: str | Callable[[], str], *, error: bool = False) -> None:
        """A message above the chart."""

    def show_record(self, record: TraceRecord) -> None:
        """Show a finished record instead of live samples."""

    def program_dialect(self) -> str | None:
        """The loaded program's dialect (its devices name the CSV's columns)."""


def table_of(record: TraceRecord) -> TraceTable:
    """The record as a file table."""
    return TraceTable([s.label for s in record.signals], list(record.times),
                      [list(lane) for lane in record.lanes])


def add_actions(dock: TimeChartDock) -> None:
    """Add LADDER-III export and trace import to the chart's toolbar."""
    for name, slot in ((EXPORT, lambda: export_dialog(dock)),
                       (IMPORT, lambda: import_dialog(dock))):
        action = QAction(dock.toolbar)
        action.setObjectName(name)
        action.triggered.connect(lambda _c=False, s=slot: s())
        dock.toolbar.add_action(action)
        dock.chart_actions[name] = action


def retranslate(dock: TimeChartDock) -> None:
    """The actions' texts in the current UI language."""
    actions = dock.chart_actions
    if EXPORT not in actions:
        return
    actions[EXPORT].setText(translate("TraceFiles", "LADDER-III..."))
    actions[EXPORT].setToolTip(
        translate("TraceFiles", "Export the samples as a LADDER-III signal-trace result"))
    actions[IMPORT].setText(translate("TraceFiles", "Import..."))
    actions[IMPORT].setToolTip(
        translate("TraceFiles", "Show a LADDER-III trace result or a CSV trace"))


def export_ladder3(dock: TimeChartDock, path: str | Path) -> bool:
    """Write the record as a LADDER-III trace result (frame 0 = the last sample)."""
    try:
        atomic_write(path, ladder3_text(table_of(dock.record)))
    except OSError as error:
        dock.say(translate("TimeChart", "Cannot write {0}: {1}").format(
                  path, os_error_text(error)), error=True)
        return False
    dock.say(translate("TimeChart", "Saved {0}").format(path))
    return True


def _label_signal(label: str, dialect: str | None) -> TracedSignal:
    """A CSV column's lane: the loaded program's device (`D0`), else a PMC address."""
    try:
        return parse_traced(label, None, dialect)
    except AddressError:
        if dialect is None:
            raise
        return parse_traced(label)


def import_trace(dock: TimeChartDock, path: str | Path) -> bool:
    """Show a LADDER-III trace result (frames at the chosen sampling time) or our CSV."""
    if dock.sampling:
        dock.stop()
    period = dock.period_spin.value()
    try:
        table = read_trace(Path(path).read_text(encoding="utf-8", errors="replace"), period)
        dialect = dock.program_dialect()
        signals = [_label_signal(label, dialect) for label in table.labels]
    except OSError as error:
        dock.say(translate("TimeChart", "Cannot read {0}: {1}").format(
                  path, os_error_text(error)), error=True)
        return False
    except (TraceFileError, AddressError) as error:
        line = getattr(error, "line", 1)
        dock.say(translate("TraceFiles", "{0}, line {1}: not a trace file").format(path, line),
                  error=True)
        return False
    record = TraceRecord(signals)
    record.period_ms = period
    record.extend(TraceSample(index, time_ms, tuple(column[index] for column in table.columns))
                  for index, time_ms in enumerate(table.times))
    dock.show_record(record)
    dock.say(translate("TraceFiles", "Imported {0}: {1} samples").format(path, len(record)))
    return True


def export_dialog(dock: TimeChartDock) -> None:
    """Ask for a file and export the LADDER-III trace result."""
    path = file_dialogs.save_file_name(
        dock.toolbar, translate("TraceFiles", "Export as LADDER-III trace result"), "trace.csv",
        translate("TimeChart", "CSV files (*.csv)"))
    if path:
        export_ladder3(dock, path)


def import_dialog(dock: TimeChartDock) -> None:
    """Ask for a trace file and show it."""
    path = file_dialogs.open_file_name(
        dock.toolbar, translate("TraceFiles", "Import a trace"), "",
        translate("TimeChart", "CSV files (*.csv)"))
    if path:
        import_trace(dock, path)
