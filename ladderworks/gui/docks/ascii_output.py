"""PLC › ASCII output: the simulated printer/terminal a Fatek program's FUN 94 ASCWR writes to."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QFontDatabase
from PySide6.QtWidgets import (
    QDockWidget,
    QHBoxLayout,
    QLabel,
    QPlainTextEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.fatek.ascii_files import ascii_path, load_ascii_files
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.retranslate import Retranslating

translate = QCoreApplication.translate
PAGE_RULE = "\n" + "-" * 40 + "\n"  # a page feed as the dock shows it


class AsciiOutputDock(Retranslating, QDockWidget):
    """What the terminal on Port 1 received, as text (a page feed shown as a rule)."""

    def __init__(self, session: PlcSession, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("asciiOutputDock")
        self.session = session
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        self.view = QPlainTextEdit(body)
        self.view.setObjectName("asciiOutputText")
        self.view.setReadOnly(True)
        self.view.setLineWrapMode(QPlainTextEdit.LineWrapMode.NoWrap)
        self.view.setFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont))
        layout.addWidget(self.view, 1)
        bottom = QHBoxLayout()
        self.summary = QLabel(body)
        self.summary.setObjectName("asciiOutputSummary")
        self.clear_button = QPushButton(body)
        self.clear_button.setObjectName("asciiOutputClear")
        self.clear_button.clicked.connect(self.clear)
        bottom.addWidget(self.summary, 1)
        bottom.addWidget(self.clear_button)
        layout.addLayout(bottom)
        self.setWidget(body)
        self._shown = ""
        self._writes = -1
        self._file: Path | None = None  # the ASCII files read for the open program
        self._problems: list[Diagnostic] = []
        session.snapshot_ready.connect(lambda _snapshot: self.refresh())
        session.status_changed.connect(lambda _status: self.refresh())
        session.program_loaded.connect(lambda _binary: self.refresh())
        self.retranslate()

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.setWindowTitle(translate("AsciiOutput", "ASCII output"))
        self.clear_button.setText(translate("AsciiOutput", "Clear"))
        self.clear_button.setToolTip(translate(
            "AsciiOutput", "Forget what the terminal received"))
        self.view.setPlaceholderText(translate(
            "AsciiOutput", "What FUN 94 ASCWR sends to Port 1 (a Fatek program) shows here."))
        self._writes = -1
        self.refresh()

    def refresh(self) -> None:
        """Show the terminal's text when it changed."""
        terminal = self.session.run.ascii_terminal
        if terminal.writes == self._writes and terminal.text() == self._shown:
            return
        self._writes = terminal.writes
        self._shown = terminal.text()
        self.view.setPlainText(self._shown.replace("\f", PAGE_RULE))
        bar = self.view.verticalScrollBar()
        bar.setValue(bar.maximum())
        text = translate("AsciiOutput", "{0} output(s) received").format(terminal.writes)
        if self._problems and self._file is not None:
            first = self._problems[0]
            text += "  " + translate("AsciiOutput", "{0}, line {1}: {2}").format(
                self._file.name, first.line, diagnostic_text(first))
        self.summary.setText(text)

    def clear(self) -> None:
        """Empty the terminal (and the view)."""
        self.session.run.ascii_terminal.clear()
        self.refresh()

    def use_program(self, path: Path | None) -> None:
        """A program was opened: the ASCII files beside it (`PROGRAM.ascii`) are what its
        FUN 94 sends; their first problem is shown under the text."""
        files = load_ascii_files(path) if path is not None else None
        self._file = ascii_path(path) if path is not None else None
        self._problems = list(files.diagnostics) if files is not None else []
        self.session.run.use_ascii_files(files.files if files is not None else {})
        self._writes = -1
        self.refresh()
