"""The alarm panel: the AlarmMsg.dat message of every A bit the program raised, newest first."""

from __future__ import annotations

from datetime import datetime
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QEvent, QLocale, QObject, QRect, QSize, Qt
from PySide6.QtGui import QAction, QBrush, QColor
from PySide6.QtWidgets import (
    QDockWidget,
    QHeaderView,
    QLabel,
    QToolBar,
    QTreeWidget,
    QTreeWidgetItem,
    QVBoxLayout,
    QWidget,
)

from ladderworks import paths
from ladderworks.core.alarms import ActiveAlarm, AlarmTable, format_number, load_alarm_file
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.program import Program
from ladderworks.gui import file_dialogs
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.family_words import family_title, is_pmc
from ladderworks.gui.header_fit import fit_headers
from ladderworks.gui.os_errors import os_error_text
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.retranslate import Retranslating

translate = QCoreApplication.translate

DEFAULT_ALARM_FILE = paths.alarm_file()
COLUMNS = 5  # number, address, PLC time, clock, message
MESSAGE = COLUMNS - 1
NARROW_HIDES = (3, 1)  # a narrow dock drops the clock, then the bit (the number names it)
MESSAGE_CHARS = 24  # the message keeps room for this many characters before a column goes
TEXT_MARGIN = 4  # a cell's text from its edge


def plc_time_text(ms: int) -> str:
    """PLC (virtual clock) time as `m:ss.mmm` (`h:mm:ss.mmm` after an hour), with the UI
    language's decimal sign (`0:01,250` in Turkish)."""
    seconds, millis = divmod(ms, 1000)
    minutes, seconds = divmod(seconds, 60)
    hours, minutes = divmod(minutes, 60)
    point = QLocale().decimalPoint()
    if hours:
        return f"{hours}:{minutes:02d}:{seconds:02d}{point}{millis:03d}"
    return f"{minutes}:{seconds:02d}{point}{millis:03d}"


class AlarmDock(Retranslating, QDockWidget):
    """The alarms the A area has raised, newest first; RESET clears those whose bit is 0.

    Each row: the message number (A byte × 8 + bit), the A bit, the PLC time it rose, the
    wall-clock time the panel first saw it, and the text from the alarm file. An alarm whose
    bit dropped stays (greyed) until RESET, as on the CNC screen.
    """

    def __init__(self, session: PlcSession, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("alarmDock")
        self.session = session
        self.alarm_file: Path | None = None
        self.file_problems: list[Diagnostic] = []
        self.program_messages = 0  # > 0 while the loaded program's `%@4` messages are used
        self._file_table: AlarmTable | None = None  # the alarm file's table meanwhile
        self._seen: dict[tuple[int, int], datetime] = {}
        self.file_action = QAction(self)
        self.file_action.setObjectName("action_alarm_file")
        self.file_action.triggered.connect(self.open_dialog)
        self.reset_action = QAction(self)
        self.reset_action.setObjectName("action_alarm_reset")
        self.reset_action.triggered.connect(self.reset)
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        toolbar = QToolBar(body)
        toolbar.setObjectName("alarmToolbar")
        toolbar.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextOnly)
        toolbar.addAction(self.reset_action)
        toolbar.addAction(self.file_action)
        self.file_label = QLabel(body)
        self.file_label.setObjectName("alarmFileLabel")
        self.file_label.setWordWrap(True)  # its own line: never hidden in a narrow dock
        layout.addWidget(toolbar)
        layout.addWidget(self.file_label)
        self.tree = QTreeWidget(body)
        self.tree.setObjectName("alarmList")
        self.tree.setColumnCount(COLUMNS)
        self.tree.setRootIsDecorated(False)
        self.tree.setAlternatingRowColors(True)
        self.tree.setWordWrap(True)  # a long message wraps in its column (tooltip: all of it)
        self.tree.setUniformRowHeights(False)
        header = self.tree.header()
        header.setStretchLastSection(True)  # the message takes the room the others leave
        for column in range(MESSAGE):
            header.setSectionResizeMode(column, QHeaderView.ResizeMode.ResizeToContents)
        header.setSectionResizeMode(MESSAGE, QHeaderView.ResizeMode.Stretch)
        layout.addWidget(self.tree, 1)
        self.tree.viewport().installEventFilter(self)  # its width: columns and row heights
        self.setWidget(body)
        self._alarms: list[ActiveAlarm] = []
        session.alarms_changed.connect(self._on_alarms)
        # the texts are the program's in the PLC: they change when another is loaded into it,
        # never when the console opens or starts one (File › New / Open)
        session.program_loaded.connect(self._on_program_loaded)
        session.family_changed.connect(lambda _family: self._show_file())
        if not session.run.alarm_table.messages and DEFAULT_ALARM_FILE.exists():
            self.load_file(DEFAULT_ALARM_FILE)
        self.retranslate()
        self._on_alarms(session.run.alarms())

    # -- the alarm file ----------------------------------------------------------------------

    def load_file(self, path: str | Path) -> bool:
        """Read an AlarmMsg.dat; its messages are used from now on. False if unreadable."""
        try:
            table, problems = load_alarm_file(path)
        except OSError as error:
            self.file_label.setText(
                translate("AlarmPanel", "Cannot read {0}: {1}").format(
                    Path(path).name, os_error_text(error)
                )
            )
            self.file_label.setStyleSheet("color:#c00000;")
            return False
        self.session.run.set_alarm_table(table)
        self.program_messages = 0
        self.alarm_file = Path(path)
        self.file_problems = problems
        self._show_file()
        self._fill()
        return True

    def _on_program_loaded(self, _binary: object) -> None:
        """A program was loaded into the PLC: its messages (or the file's) from now on."""
        self.use_program(self.session.run.program or Program())

    def use_program(self, program: Program) -> None:
        """The PLC's program: its `%@4` messages are the texts; without them, the file's."""
        if program.messages:
            if not self.program_messages:
                self._file_table = self.session.run.alarm_table
            table = AlarmTable.from_messages(program.messages)
            self.session.run.set_alarm_table(table)
            self.program_messages = len(table)
        elif self.program_messages:
            self.session.run.set_alarm_table(self._file_table or AlarmTable())
            self.program_messages = 0
        else:
            return
        self._show_file()
        self._fill()

    def open_dialog(self) -> None:
        """File → Alarm file: choose an AlarmMsg.dat."""
        start = str(self.alarm_file or DEFAULT_ALARM_FILE)
        path = file_dialogs.open_file_name(
            self,
            translate("AlarmPanel", "Alarm message file"),
            start,
            translate("AlarmPanel", "Alarm files (*.dat);;All files (*)"),
        )
        if path:
            self.load_file(path)

    def _show_file(self) -> None:
        if not is_pmc(self.session.family):  # a Delta/Fatek program: no A area, no messages
            self.file_label.setText(translate(
                "AlarmPanel", "A {0} program has no alarm messages (the alarm file is for "
                "PMC programs)").format(family_title(self.session.family)))
            self.file_label.setStyleSheet("")
            self.file_label.setToolTip("")
            return
        if self.program_messages:
            self.file_label.setText(translate(
                "AlarmPanel", "The program's messages (%@4): {0}").format(self.program_messages))
            self.file_label.setStyleSheet("")
            self.file_label.setToolTip(translate(
                "AlarmPanel", "Alarm file... uses an AlarmMsg.dat instead"))
            return
        if self.alarm_file is None:
            self.file_label.setText(translate("AlarmPanel", "No alarm file"))
            return
        text = translate("AlarmPanel", "{0}: {1} messages").format(
            self.alarm_file.name, len(self.session.run.alarm_table)
        )
        if self.file_problems:
            text += " · " + translate("AlarmPanel", "{0} lines with problems").format(
                len(self.file_problems)
            )
        self.file_label.setText(text)
        self.file_label.setStyleSheet("color:#a05000;" if self.file_problems else "")
        self.file_label.setToolTip(
            "\n".join(
                translate("AlarmPanel", "line {0}: {1}").format(d.line, diagnostic_text(d))
                for d in self.file_problems
            )
        )

    # -- the list ------------------------------------------------------------------------------

    def reset(self) -> None:
        """The reset key: alarms whose bit is 0 leave the list (those still on stay)."""
        self.session.reset_alarms()

    def alarms(self) -> list[ActiveAlarm]:
        """The alarms shown, newest first."""
        return list(self._alarms)

    def message_of(self, alarm: ActiveAlarm) -> str:
        """The alarm's text from the file now loaded (or a note that the file has none)."""
        text = self.session.run.alarm_table.text_for(alarm.number) or alarm.text
        return text or translate("AlarmPanel", "(no message {0} in the alarm file)").format(
            format_number(alarm.number)
        )

    def _on_alarms(self, alarms: list[ActiveAlarm]) -> None:
        self._alarms = list(alarms)
        now = datetime.now()
        keys = {(alarm.number, alarm.raised_ms) for alarm in self._alarms}
        self._seen = {key: seen for key, seen in self._seen.items() if key in keys}
        for key in keys:
            self._seen.setdefault(key, now)
        self._fill()

    def _fill(self) -> None:
        self.tree.clear()
        grey = QBrush(QColor("#888888"))
        for alarm in self._alarms:
            seen = self._seen.get((alarm.number, alarm.raised_ms))
            item = QTreeWidgetItem(
                [
                    format_number(alarm.number),
                    str(alarm.address),
                    plc_time_text(alarm.raised_ms),
                    seen.strftime("%H:%M:%S") if seen is not None else "",
                    self.message_of(alarm),
                ]
            )
            item.setToolTip(4, item.text(4))  # the whole message when the column is narrow
            if alarm.active:
                item.setForeground(0, QBrush(QColor("#c00000")))
            else:
                for column in range(COLUMNS):
                    item.setForeground(column, grey)
                item.setToolTip(
                    4, translate("AlarmPanel", "The bit is 0 again: RESET clears this alarm")
                )
            if seen is not None:  # the clock column may be hidden in a narrow dock
                item.setToolTip(2, translate("AlarmPanel", "Seen at {0}").format(
                    seen.strftime("%H:%M:%S")))
            self.tree.addTopLevelItem(item)
        self._fit_columns()

    def _fit_columns(self) -> None:
        """Hide the clock, then the bit, while the message would have too little room; the
        rows grow to the message wrapped in its column (a tree sizes rows unwrapped)."""
        for column in NARROW_HIDES:
            self.tree.setColumnHidden(column, False)
        metrics = self.tree.fontMetrics()
        width = self.tree.viewport().width()
        header = self.tree.header()
        used = sum(max(self.tree.sizeHintForColumn(column), header.sectionSizeHint(column))
                   for column in range(MESSAGE))
        for column in NARROW_HIDES:
            if used <= width - metrics.averageCharWidth() * MESSAGE_CHARS:
                break
            used -= max(self.tree.sizeHintForColumn(column), header.sectionSizeHint(column))
            self.tree.setColumnHidden(column, True)
        text_width = max(width - used - 2 * TEXT_MARGIN, metrics.averageCharWidth())
        room = QRect(0, 0, text_width, 1 << 20)
        for row in range(self.tree.topLevelItemCount()):
            item = self.tree.topLevelItem(row)
            if item is not None:
                lines = metrics.boundingRect(room, Qt.TextFlag.TextWordWrap, item.text(MESSAGE))
                item.setSizeHint(MESSAGE, QSize(text_width, lines.height() + 2))

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """The list's new width: fit the columns and the rows to it."""
        if watched is self.tree.viewport() and event.type() == QEvent.Type.Resize:
            self._fit_columns()
        return super().eventFilter(watched, event)

    def shown_rows(self) -> list[list[str]]:
        """The texts of the list, row by row (for tests and for copying)."""
        items = (self.tree.topLevelItem(row) for row in range(self.tree.topLevelItemCount()))
        return [[item.text(column) for column in range(COLUMNS)] for item in items if item]

    # -- language ------------------------------------------------------------------------------

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(translate("AlarmPanel", "Alarms"))
        self.reset_action.setText(translate("AlarmPanel", "RESET"))
        self.reset_action.setToolTip(
            translate("AlarmPanel", "Clear the alarms whose bit is 0 (the reset key)")
        )
        self.file_action.setText(translate("AlarmPanel", "Alarm file..."))
        self.tree.setHeaderLabels(
            [
                translate("AlarmPanel", "No."),
                translate("AlarmPanel", "Bit"),
                translate("AlarmPanel", "PLC time"),
                translate("AlarmPanel", "Clock"),
                translate("AlarmPanel", "Message"),
            ]
        )
        fit_headers(self.tree)
        self._show_file()
        self._fill()
