"""The text view: a program shown as instruction-list text, with line numbers and its errors."""

from __future__ import annotations

from PySide6.QtGui import QFont, QFontDatabase, QTextCursor
from PySide6.QtWidgets import QWidget

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.gui.docks.mnemonic_editor import MnemonicEditor


class ProgramTextView(MnemonicEditor):
    """The `.LAD` text with a line-number gutter; the error lines tinted, their numbers red."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("text_view")
        font = QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)
        font.setStyleHint(QFont.StyleHint.Monospace)
        self.setFont(font)
        self._update_margin()

    def set_diagnostics(self, diagnostics: list[Diagnostic]) -> None:
        """Mark the diagnostics that point at a line of this text (not at a ladder cell)."""
        super().set_diagnostics([d for d in diagnostics if d.line and d.network is None])

    def setPlainText(self, text: str) -> None:
        """New text; the error list's diagnostics are marked on it again."""
        super().setPlainText(text)
        self._decorate()

    def error_lines(self) -> list[int]:
        """The 1-based lines marked as errors."""
        return sorted({d.line for d in self.diagnostics if d.is_error})

    def go_to(self, line: int, column: int = 1) -> None:
        """Put the cursor at 1-based `line`, `column` and show it."""
        block = self.document().findBlockByNumber(max(line - 1, 0))
        cursor = QTextCursor(block)
        cursor.movePosition(QTextCursor.MoveOperation.Right, QTextCursor.MoveMode.MoveAnchor,
                            max(min(column - 1, block.length() - 1), 0))
        self.setTextCursor(cursor)
        self.centerCursor()
        self.setFocus()

    def cursor_line(self) -> int:
        """1-based line of the cursor."""
        return self.textCursor().blockNumber() + 1
